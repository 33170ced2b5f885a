"""Fatigue damage and permanent deformation of a touchdown bearing, per drop and over many drops.

Fatigue (:func:`drop_damage`): the raceway of each race and contact pair is a track of points,
one per strip that a standing peak-load contact damages
(:func:`auxbearing.core.fatigue.dwell_width_ratio`). Each point's stress history is built from the
ball stresses of a drop: a point carries the stress of the ball whose contact centre is nearest to
it, so the turning race makes every ball pass every inner-raceway point (at the ball-pass rate
relative to the race), the cage carries the balls over the outer raceway, and a ball that bounces
while the race stands still loads the same point again and again. An over-rolling is charged the
largest stress seen within half a point pitch, which raises the damage of a smoothly varying load zone by under 1 %
at the default pitch (tests/consistency). The histories are cycle-counted by ASTM E1049-85's rainflow rule (5.4.4)
in a compiled loop that gives what the maintained ``rainflow`` package gives, cycle for cycle (tests/consistency;
the package's Python loop over the 1.3 million cycles of the blower's drop window took 3 of its coast-down's 36 s),
each cycle is charged 1/N_f from the stress-life law of :mod:`auxbearing.core.fatigue` (exponent 9, calibrated on
ISO 281's C), Miner's sum gives each point's damage, and Lundberg-Palmgren's Weibull sums give rings and bearing. A
bearing run at a constant load for N revolutions so gets N/L10 (tests/consistency). Lee & Palazzolo, "Catcher
bearing life prediction using a rainflow counting approach", J. Tribol. 134 (2012) apply rainflow counting and
Miner's rule to touchdown-bearing contact stresses; their paper was not retrievable here, so nothing below is taken
from it.

Assumptions, all stated in the results: ball kinematics of the cage without slip unless the cage
speed is given; drops repeat on the same raceway points (damage per drop adds); a cycle is charged
by its stress range (``cycle_stress="peak"`` charges its maximum, more severe for bounces that do
not unload); stress histories at fixed ball stations (the ball-set model's azimuths) are carried by
the moving balls that are nearest to each station, which turns the over-rolling sums into
Lundberg-Palmgren's own sums over the Z ball loads (Harris & Kotzalas 2007, Ch. 11).

Dent (:func:`dent_per_drop`): Palmgren's permanent set at the largest contact load of a drop,
against ISO 76's 1e-4 D; depths of successive drops are added, by default as if every drop dented the
same spot (conservative: a repeated equal load mostly shakes down elastically), or, with
``life.dent_accumulation = "spread"``, with the rotating race's dents spread round it
(:data:`DENT_ACCUMULATION`). Palmgren's formula has no yield threshold, so under either rule even drops far
below 4200 MPa reach the limit after enough drops.
"""

from __future__ import annotations

import math

import numpy as np

from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.common.errors import InputError
from auxbearing.core import fatigue as cf
from auxbearing.core.hertz import ball_raceway_curvature, ellipticity, stress_coefficient
from auxbearing.machine.params import DENT_ACCUMULATION

RACES = ("inner", "outer")
#: Bounds on the raceway points per track (by default one point per dwell width of the peak contact).
MIN_ELEMENTS, MAX_ELEMENTS = 64, 4096
CYCLE_STRESSES = ("range", "peak")
ASSUMPTIONS = (
    "ball positions from the kinematic cage speed (no cage slip) unless cage_speed or ball_angles are given",
    "each drop loads the same raceway points (damage per drop adds linearly)",
    "stress-life exponent 9 and ISO 281 C: only the L10 (90 % reliability) life, no a_ISO factors",
)


def rating_rows(bearing: BearingGeometry) -> int:
    """Rows i of the ISO 281 rating: 2 for a four-point bearing (makers' practice), else 1."""
    return 2 if bearing.type == "four_point" else 1


def dynamic_load_rating(bearing) -> float:
    """ISO 281:2007 basic dynamic radial load rating C_r [N] of a bearing or a matched set.

    One bearing: ISO 281 6.1.1 from its ball set, times its ``rating_factor`` (a maker's b_m
    adjustment, 1 unless the catalogue says otherwise); a four-point contact bearing is rated as a
    double-row 35 deg bearing (i = 2; ISO 281 does not cover the type, see
    :mod:`auxbearing.core.fatigue`); ceramic balls do not change C (DIN ISO 281 Bbl. 5, now ISO 20056-1).
    A duplex set (DB, DF, DT) of two identical rows: 2^0.7 times one row (ISO 281:2007 6.1.2-6.1.3).
    A name is looked up in the catalogue first.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> round(dynamic_load_rating(get_bearing("209")))
    32687
    >>> round(dynamic_load_rating("7208")), round(dynamic_load_rating("7208 DB"))
    (34370, 55834)
    """
    from auxbearing.bearings import ratings

    if isinstance(bearing, str):
        from auxbearing.bearings.catalogue import get_bearing

        bearing = get_bearing(bearing)
    row = getattr(bearing, "row", None)
    if row is not None:
        return ratings.set_factor(bearing.row_count) * ratings.dynamic_load_rating(row)
    return ratings.dynamic_load_rating(bearing)


def static_load_rating(bearing) -> float:
    """ISO 76:2006 basic static radial load rating C0 [N] of a bearing or a matched set (2 C0 for a pair).

    Hybrids: at 4200 MPa with the ceramic contact (:mod:`auxbearing.bearings.ratings`).

    Examples
    --------
    >>> round(static_load_rating("7208")), round(static_load_rating("7208 DB"))
    (24091, 48182)
    """
    from auxbearing.bearings import ratings

    if isinstance(bearing, str):
        from auxbearing.bearings.catalogue import get_bearing

        bearing = get_bearing(bearing)
    row = getattr(bearing, "row", None)
    if row is not None:
        return bearing.row_count * ratings.static_load_rating(row)
    return ratings.static_load_rating(bearing)


def race_constants(bearing: BearingGeometry) -> dict:
    """Per race: Hertz stress coefficient, contact half-width coefficient, track radius, capacity.

    ``stress_coefficient`` C_s gives sigma = C_s Q^(1/3) [Pa/N^(1/3)]; ``half_width_coefficient`` k_b
    gives the semi-minor axis b = k_b sigma [m/Pa] (from sigma = 3Q/(2 pi a b) with a, b ~ Q^(1/3):
    b = pi eta a* b*^2 sigma / sum_rho, Harris & Kotzalas 2007 Eq. 6.38-6.39); ``radius`` [m] of the
    contact track; ``capacity_load`` Q_c [N], ``capacity_stress`` sigma_c [Pa] and ``capacity_cycles``
    N_c [-] of the stress-life law, all at the nominal contact angle.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> c = race_constants(get_bearing("209"))
    >>> round(c["inner"]["capacity_stress"] / 1e6), round(c["outer"]["capacity_stress"] / 1e6)
    (3922, 4112)
    """
    d, dm, alpha = bearing.ball_diameter, bearing.pitch_diameter, bearing.contact_angle
    gamma = d * math.cos(alpha) / dm
    row_rating = dynamic_load_rating(bearing) / rating_rows(bearing) ** 0.7
    q_c = cf.raceway_capacity_loads(row_rating, bearing.ball_count, alpha, gamma, bearing.inner_groove_ratio,
                                    bearing.outer_groove_ratio)
    cycles = cf.overrolls_per_revolution(bearing.ball_count, gamma)
    eta = bearing.contact_compliance
    out = {}
    for k, (race, ratio, sign) in enumerate(zip(RACES, (bearing.inner_groove_ratio, bearing.outer_groove_ratio),
                                                (-1.0, 1.0), strict=True)):
        sum_rho, f_rho = ball_raceway_curvature(d, dm, ratio, alpha, race)
        kappa, _, e_int = ellipticity(f_rho)
        a_star = np.cbrt(2.0 * kappa**2 * e_int / np.pi)
        b_star = np.cbrt(2.0 * e_int / (np.pi * kappa))
        c_s = float(stress_coefficient(sum_rho, f_rho, eta))
        out[race] = {
            "stress_coefficient": c_s,
            "half_width_coefficient": float(np.pi * eta * a_star * b_star**2 / sum_rho),
            "radius": 0.5 * (dm + sign * d * math.cos(alpha)),
            "capacity_load": q_c[k],
            "capacity_stress": c_s * q_c[k] ** (1.0 / 3.0),
            "capacity_cycles": cf.RATING_REVOLUTIONS * cycles[k],
            "gamma": gamma,
        }
    return out


def count_cycles(series) -> dict:
    """Rainflow cycles of a history (ASTM E1049-85 5.4.4, :func:`auxbearing.core.fatigue.rainflow_turning_points`).

    The history is first cut to its turning points (which leaves the count unchanged), then
    counted; ``start``/``end`` index the input.

    Returns
    -------
    dict
        ``ranges``, ``means`` [input units], ``counts`` (1 or 0.5), ``start``, ``end``.

    Examples
    --------
    >>> c = count_cycles([-2, 1, -3, 5, -1, 3, -4, 4, -2])
    >>> c["ranges"].tolist(), c["counts"].tolist()
    ([3.0, 4.0, 4.0, 8.0, 9.0, 8.0, 6.0], [0.5, 0.5, 1.0, 0.5, 0.5, 0.5, 0.5])
    """
    x = np.asarray(series, dtype=float)
    empty = {key: np.empty(0) for key in ("ranges", "means", "counts")}
    if x.size < 2:
        return {**empty, "start": np.empty(0, int), "end": np.empty(0, int)}
    index = np.flatnonzero(np.r_[True, np.diff(x) != 0.0])
    step = np.diff(x[index])
    index = index[np.r_[True, step[:-1] * step[1:] < 0.0, True]] if step.size else index
    cycles = cf.rainflow_turning_points(np.ascontiguousarray(x[index]))
    return {"ranges": cycles[:, 0], "means": cycles[:, 1], "counts": cycles[:, 2],
            "start": index[cycles[:, 3].astype(int)], "end": index[cycles[:, 4].astype(int)]}


def _cumulative_angle(t, speed):
    increments = 0.5 * (speed[1:] + speed[:-1]) * np.diff(t)
    return np.r_[0.0, np.cumsum(increments)]


def _ball_tracks(t, race_speed, stress_inner, stress_outer, z, gamma, ball_angles, cage_speed):
    """Fixed-frame ball angles (time, ball) and the stress each physical ball carries."""
    race_angle = _cumulative_angle(t, race_speed)
    if isinstance(ball_angles, str):
        speed = race_speed * 0.5 * (1.0 - gamma) if cage_speed is None else np.asarray(cage_speed, float)
        cage = _cumulative_angle(t, speed)
        angles = 2.0 * np.pi * np.arange(z)[None, :] / z + cage[:, None]
        if ball_angles == "stations":
            nearest = (np.arange(z)[None, :] + np.rint(cage * z / (2.0 * np.pi)).astype(int)[:, None]) % z
            rows = np.arange(t.size)[:, None]
            stress_inner, stress_outer = stress_inner[rows, nearest], stress_outer[rows, nearest]
        elif ball_angles != "cage":
            raise ValueError(f"ball_angles = {ball_angles!r}: 'stations', 'cage' or an array (time, ball)")
    else:
        angles = np.unwrap(np.asarray(ball_angles, dtype=float), axis=0)
        if angles.shape != stress_inner.shape[:2]:
            raise ValueError(f"ball_angles shape {angles.shape} must be (time, ball) = {stress_inner.shape[:2]}")
    return {"inner": angles - race_angle[:, None], "outer": angles}, {"inner": stress_inner, "outer": stress_outer}


#: Over-rolling stresses below this fraction of a track's largest are counted as zero: it removes the
#: countless tiny cycles of the unloaded zone (a rattle leaves millions) and moves any counted range by at
#: most this fraction of the largest stress, so a cycle's damage (~ range^9) by under 1 %.
NEGLIGIBLE_STRESS = 1e-3


def _track_cycles(position, stress, n_elements, const, exponent, cycle_stress):
    """Cycles of every raceway point of one track, each with its damage, point and ball."""
    element, ball, value = cf.overrolling_events(position, stress, n_elements)
    # numpy sorts 16-bit integers stably by radix, in linear time (4.7x faster on 3e6 events than the 64-bit timsort)
    keys = element.astype(np.int16) if n_elements <= np.iinfo(np.int16).max else element
    order = np.argsort(keys, kind="stable")
    element, ball, value = element[order], ball[order], value[order]
    if value.size:
        value = np.where(value < NEGLIGIBLE_STRESS * value.max(), 0.0, value)
    c = count_cycles(value)
    peak = np.where(value[c["start"]] >= value[c["end"]], c["start"], c["end"])
    amplitude = c["ranges"] if cycle_stress == "range" else c["means"] + 0.5 * c["ranges"]
    damage = c["counts"] * cf.cycle_damage(amplitude, const["capacity_stress"], const["capacity_cycles"], exponent)
    return {"ranges": c["ranges"], "means": c["means"], "counts": c["counts"], "damage": damage,
            "element": element[peak], "ball": ball[peak]}


def drop_damage(t, race_speed, stress_inner, stress_outer, bearing: BearingGeometry, *, ball_angles="stations",
                cage_speed=None, elements=None, cycle_stress="range",
                exponent=cf.STRESS_LIFE_EXPONENT) -> dict:
    """Rolling-contact fatigue damage of one drop from the contact stress histories.

    Parameters
    ----------
    t : array (time,)
        Time [s], increasing.
    race_speed : array (time,)
        Inner-race spin speed [rad/s]; the outer ring is fixed.
    stress_inner, stress_outer : arrays (time, ball, pair)
        Hertz max stress of each ball/raceway contact [Pa] (2 pairs for a four-point bearing).
    bearing : BearingGeometry
    ball_angles : "stations", "cage" or array (time, ball)
        Where the stresses are: at the fixed azimuths 2 pi j / Z of the ball-set model
        ("stations", each carried by the ball nearest to it), on balls moving with the cage ("cage",
        ball j at 2 pi j / Z + cage angle), or on balls at the given fixed-frame angles [rad].
    cage_speed : array (time,), optional
        Cage speed [rad/s]; default the kinematic omega_i (1 - gamma)/2.
    elements : int, optional
        Raceway points per track; default one point per dwell width of the drop's peak contact
        (:func:`auxbearing.core.fatigue.dwell_width_ratio` times its semi-minor axis), 64 to 4096.
    cycle_stress : "range" or "peak"
        What a counted cycle is charged by.
    exponent : float
        Stress-life exponent; 9 reproduces ISO 281 (NASA/TM-2008-214265 gives 12 for modern steel).

    Returns
    -------
    dict
        ``damage`` (per drop) and ``drops_to_failure`` = 1/damage, ``damage_inner``/``damage_outer``,
        ``contact_damage`` {race: (ball, pair)} (each contact's share of its track's mean damage),
        ``point_damage`` {race: (pair, point)}, ``worst_contact`` and ``worst_point`` with their
        counted cycles (``ranges``, ``means`` [Pa], ``counts``), ``race_revolutions``, ``elements``,
        ``capacity`` and ``assumptions``.
    """
    t = np.asarray(t, dtype=float)
    speed = np.broadcast_to(np.asarray(race_speed, dtype=float), t.shape)
    stress = {"inner": np.asarray(stress_inner, dtype=float), "outer": np.asarray(stress_outer, dtype=float)}
    z, pairs = bearing.ball_count, bearing.pairs_per_ball
    for race, s in stress.items():
        if s.ndim != 3 or s.shape != (t.size, z, pairs):
            raise ValueError(f"stress_{race} shape {s.shape}: must be (time, ball, pair) = {(t.size, z, pairs)}")
        if np.any(~np.isfinite(s)) or np.any(s < 0.0):
            raise ValueError(f"stress_{race}: must be finite and >= 0 Pa")
    if t.size < 2 or np.any(np.diff(t) <= 0.0):
        raise ValueError("t: needs at least two strictly increasing times")
    if cycle_stress not in CYCLE_STRESSES:
        raise ValueError(f"cycle_stress = {cycle_stress!r}: must be 'range' or 'peak'")
    const = race_constants(bearing)
    angles, stress = _ball_tracks(t, speed, stress["inner"], stress["outer"], z, const["inner"]["gamma"],
                                  ball_angles, cage_speed)
    out = {"contact_damage": {}, "point_damage": {}, "elements": {}, "capacity": const}
    cycles = {}
    for race in RACES:
        c, s = const[race], stress[race]
        strip = cf.dwell_width_ratio(exponent) * c["half_width_coefficient"] * float(s.max()) / c["radius"]
        n_el = elements or (int(np.clip(math.ceil(2.0 * np.pi / strip), MIN_ELEMENTS, MAX_ELEMENTS))
                            if strip > 0.0 else MIN_ELEMENTS)
        position = angles[race] * (n_el / (2.0 * np.pi))
        if np.max(np.abs(np.diff(position, axis=0)), initial=0.0) > 0.5 * n_el / z:
            raise ValueError("time step too coarse: a ball moves more than half the ball spacing per sample")
        cycles[race] = [_track_cycles(position, s[:, :, p], n_el, c, exponent, cycle_stress) for p in range(pairs)]
        out["elements"][race] = n_el
        out["point_damage"][race] = np.array([np.bincount(k["element"], k["damage"], n_el) for k in cycles[race]])
        out["contact_damage"][race] = np.array([np.bincount(k["ball"], k["damage"], z) / n_el
                                                for k in cycles[race]]).T
    rings = {race: float(cf.ring_damage(out["point_damage"][race])) for race in RACES}
    where = f"given at {ball_angles}" if isinstance(ball_angles, str) else "on the given ball angles"
    total = float(cf.bearing_damage(rings["inner"], rings["outer"]))
    out.update(damage=total, damage_inner=rings["inner"], damage_outer=rings["outer"],
               drops_to_failure=1.0 / total if total > 0.0 else math.inf,
               race_revolutions=float(_cumulative_angle(t, speed)[-1] / (2.0 * np.pi)),
               assumptions=(*ASSUMPTIONS, f"cycles charged by their {cycle_stress}; stresses " + where))
    out["worst_contact"] = _worst(out["contact_damage"], cycles, "ball")
    out["worst_point"] = _worst(out["point_damage"], cycles, "element", pair_first=True)
    for race in RACES:
        if out["worst_point"]["race"] == race:
            out["worst_point"]["angle"] = 2.0 * np.pi * out["worst_point"]["element"] / out["elements"][race]
    return out


def _worst(damage, cycles, key, pair_first=False):
    """The race, index and pair of the largest damage, with the cycles charged to it."""
    race = max(RACES, key=lambda r: float(damage[r].max(initial=0.0)))
    flat = int(np.argmax(damage[race]))
    first, second = np.unravel_index(flat, damage[race].shape)
    pair, index = (first, second) if pair_first else (second, first)
    track = cycles[race][pair]
    mine = track[key] == index
    return {"race": race, key: int(index), "pair": int(pair), "damage": float(damage[race][first, second]),
            "ranges": track["ranges"][mine], "means": track["means"][mine], "counts": track["counts"][mine]}




def _drops_until_a_spot_fills(hits: float, spots: float) -> float:
    """Drops, placed uniformly at random on ``spots`` spots, after which some spot is expected to hold ``hits``.

    The occupancy of one spot after n drops is Poisson with mean n / spots (many spots); the expected number of
    spots holding ``hits`` or more is spots P(N >= hits), and the limit is reached where it is one. Bisection
    in n (the expected count rises with n).

    >>> round(_drops_until_a_spot_fills(1.0, 100.0))
    1
    >>> 20 < _drops_until_a_spot_fills(5.0, 200.0) < 5 * 200
    True
    """
    from scipy.stats import poisson

    need = max(1, math.ceil(hits))
    if need == 1 or spots <= 1.0:
        return float(need)
    lo, hi = float(need - 1), float(need) * spots
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        if spots * poisson.sf(need - 1, mid / spots) >= 1.0:
            hi = mid
        else:
            lo = mid
    return hi


def dent_per_drop(peak_load, bearing: BearingGeometry, accumulation: str = "same_spot") -> dict:
    """Permanent dent of the most loaded contacts of a drop and the drops to ISO 76's limit.

    Parameters
    ----------
    peak_load : float or (float, float)
        Largest ball/raceway contact load of the drop [N], one value or (inner, outer).
    bearing : BearingGeometry
    accumulation : {"same_spot", "spread"}
        How successive drops' dents add up (:data:`DENT_ACCUMULATION`).

    Returns
    -------
    dict
        Per race ``depth`` [m] (Palmgren, ball and raceway together, at the nominal contact angle),
        ``stress`` [Pa] and ``drops_to_dent_limit``; ``limit`` = 1e-4 D [m] (ISO 76:2006); the smaller race's
        ``drops_to_dent_limit``, and the ``assumption`` behind it in words.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> r = dent_per_drop(1000.0, get_bearing("QJ202"))
    >>> f"{r['inner']['depth'] * 1e9:.1f} nm", round(r["drops_to_dent_limit"])
    ('114.7 nm', 5)
    """
    if accumulation not in DENT_ACCUMULATION:
        raise ValueError(f"accumulation = {accumulation!r}: must be one of {', '.join(DENT_ACCUMULATION)}")
    if isinstance(bearing, str):  # a catalogue name, as dynamic_load_rating takes it
        from auxbearing.bearings.catalogue import get_bearing

        bearing = get_bearing(bearing)
    if isinstance(peak_load, str):  # "1 kN", as everywhere in the API
        from auxbearing.common.params import convert

        peak_load = convert("peak_load", peak_load, "force")
    loads = np.broadcast_to(np.asarray(peak_load, dtype=float), (2,))
    if np.any(~np.isfinite(loads)) or np.any(loads < 0.0):
        raise ValueError(f"peak_load = {peak_load!r}: must be finite and >= 0 N")
    d, alpha = bearing.ball_diameter, bearing.contact_angle
    gamma = d * math.cos(alpha) / bearing.pitch_diameter
    const = race_constants(bearing)
    limit = cf.ISO76_DENT_RATIO * d
    out = {"limit": limit}
    drops = []
    for race, load, ratio, rolling in zip(RACES, loads, (bearing.inner_groove_ratio, bearing.outer_groove_ratio),
                                          (gamma / (1.0 - gamma), -gamma / (1.0 + gamma)), strict=True):
        depth = float(cf.palmgren_dent_depth(load, d, 2.0 / d * (1.0 + rolling), 2.0 / d - 1.0 / (ratio * d)))
        stress = const[race]["stress_coefficient"] * float(load) ** (1.0 / 3.0)
        hits = limit / depth if depth > 0.0 else math.inf
        if accumulation == "spread" and race == "inner" and math.isfinite(hits):
            width = 2.0 * const[race]["half_width_coefficient"] * stress  # the ellipse's extent along the raceway
            spots = 2.0 * math.pi * const[race]["radius"] / max(width, 1e-12)
            hits = _drops_until_a_spot_fills(hits, spots)
        drops.append(hits)
        out[race] = {"load": float(load), "depth": depth, "stress": stress, "drops_to_dent_limit": hits}
    out["drops_to_dent_limit"] = min(drops)
    out["assumption"] = ("every drop dents the same spot of each race and the depths add (Palmgren's set is for one "
                         "loading; conservative)" if accumulation == "same_spot" else
                         "the rotating inner race's dents spread uniformly round it, one spot an ellipse width long, "
                         "a spot reaching the limit when enough drops land on it; the stationary outer race is "
                         "dented on one spot every drop")
    return out


def governing(fatigue, dent, required_drops=None) -> dict:
    """Which of rolling-contact fatigue and permanent dent limits the number of drops.

    Parameters
    ----------
    fatigue, dent : dict or float
        Results of :func:`drop_damage` and :func:`dent_per_drop`, or their drop counts.
    required_drops : float, optional
        Drops the machine must survive; with it, ``margin`` = allowed / required - 1 (the share of drops to spare,
        as every margin of a verification) and ``ok``.

    Examples
    --------
    >>> g = governing(5000.0, 800.0, required_drops=200)
    >>> g["limit"], g["allowed_drops"], g["margin"], g["ok"]
    ('dent', 800.0, 3.0, True)
    """
    counts = []
    for name, value, key in (("fatigue", fatigue, "drops_to_failure"), ("dent", dent, "drops_to_dent_limit")):
        value = value[key] if isinstance(value, dict) else value
        if isinstance(value, bool) or not isinstance(value, (int, float, np.floating)) or not value >= 0.0:
            raise InputError.for_field(name, value, "must be a number of drops >= 0 (inf where nothing limits)")
        counts.append(float(value))
    n_fatigue, n_dent = counts
    if required_drops is not None and (isinstance(required_drops, bool)
                                       or not isinstance(required_drops, (int, float, np.floating))
                                       or not 0.0 < required_drops < math.inf):
        raise InputError.for_field("required_drops", required_drops, "must be a finite number of drops > 0")
    allowed = min(n_fatigue, n_dent)
    # neither limits a plane that carries no load in the drop (an upper plane of a vertical machine, say)
    limit = "none" if math.isinf(allowed) else "fatigue" if n_fatigue <= n_dent else "dent"
    out = {"limit": limit, "allowed_drops": allowed, "fatigue_drops": n_fatigue, "dent_drops": n_dent}
    if required_drops is not None:
        out.update(required_drops=float(required_drops), margin=allowed / float(required_drops) - 1.0,
                   ok=bool(allowed >= required_drops))
    return out
