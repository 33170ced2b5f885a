"""The drops a touchdown bearing survives: fatigue damage of a drop and its coast-down, and the dent.

Per plane and drop (:func:`plane_life`):

* the drop itself: the Hertz stress history of every ball/raceway contact (inner and outer race, each pair)
  from the drop's full dynamics, with the over-rolling while the race turns, rainflow-counted and summed
  by Palmgren-Miner (:func:`auxbearing.analysis.life.drop_damage`: Lundberg-Palmgren / ISO 281 stress-life law);
* the coast-down: its settled stretches over-roll the raceways under loads that barely change, so each
  stretch adds revolutions / L10(P) with the ISO 281 basic rating life L10 = (C/P)^3 10^6 revolutions at
  its equivalent load P (ISO 281:2007 Eq. 1; the constant-load case of the same law, which the helper's
  consistency test checks against the stress-history path). Within a full-dynamics window the load varies (a
  rattle's impacts, a swing, a whirl beating against the unbalance), so its radial part is the window's mean load
  of a varying load, F_m = (integral of F^3 dN / N)^(1/3) with p = 3 for ball bearings (Mott, *Machine Elements
  in Mechanical Design*, 4th ed., 2004, Eq. 14-11; NSK's "average of fluctuating load"), F the ball set's
  radial reaction on the race at every step and the revolutions counted as time at the window's nearly constant
  race speed; its axial part is the window's mean face force (the process thrust, nearly steady). The damage then
  no longer depends on the window's length: the blower over 30 s of full dynamics with windows of 10 and 30 ms,
  drive end -0.6 %, non-drive end +0.2 %; the windows' plain mean forces, taken before, moved it by -1.6 and
  -4.2 % and left a rattle's damage far short, its impacts averaged before the cube: over the same 30 s the
  coast-down part of the damage was 1.9 times (drive end) and 6.6 times (the rattling non-drive end) smaller;
* the permanent dent of the drop's largest ball load (Palmgren, ISO 76's 1e-4 D limit;
  :func:`auxbearing.analysis.life.dent_per_drop`), the same spot dented every drop;
* which of the two governs against ``life.required_drops`` (:func:`auxbearing.analysis.life.governing`).
"""

from __future__ import annotations

import functools
import math

import numpy as np
import xarray as xr

from auxbearing.analysis.drop import plane_ball_arrays
from auxbearing.analysis.life import dent_per_drop, drop_damage, dynamic_load_rating, governing
from auxbearing.bearings.ratings import nearest_angle
from auxbearing.core import fatigue as cf


def _factors(bearing, axial: float = 0.0) -> tuple:
    """Equivalent-load factors (e, X1, Y1, X2, Y2) by bearing type (ISO 281:2007 6.2).

    Four-point and angular contact as the makers give them, a deep-groove bearing by ISO 281 Table 3 at its
    f0 Fa / C0 (:mod:`auxbearing.core.fatigue`).
    """
    row = getattr(bearing, "row", None)
    if row is not None:  # a matched pair: DB/DF as a double row, DT as its rows
        table = cf.ANGULAR_CONTACT_FACTORS if bearing.arrangement == "DT" else cf.ANGULAR_CONTACT_PAIR_FACTORS
        return table[nearest_angle(table, row.contact_angle)]
    if bearing.type == "four_point":
        return cf.FOUR_POINT_FACTORS
    if bearing.type == "angular_contact":
        return cf.ANGULAR_CONTACT_FACTORS[nearest_angle(cf.ANGULAR_CONTACT_FACTORS, bearing.contact_angle)]
    # deep groove: the thrust it carries loads its balls at an angle the table's e and Y follow (ISO 281 Table 3)
    return cf.deep_groove_factors(abs(axial) * _f0_over_c0(bearing))


@functools.lru_cache(maxsize=64)
def _f0_over_c0(bearing) -> float:
    """f0 / C0 of a deep-groove bearing [1/N] (ISO 76), once per bearing: a coast-down asks it every window.

    Table 3's f0 Fa / C0 is Fa over Z D_w^2 (N and mm): how far the thrust turns the balls' contact angle, a matter
    of the geometry alone. A hybrid's C0 is lowered for its stiffer balls (the square of the compliance ratio,
    :func:`auxbearing.bearings.ratings.static_load_rating_si`), which the table does not mean: it is taken out again.
    """
    from auxbearing.bearings.ratings import compliance_ratio, iso76_f0, static_load_rating

    steel_c0 = static_load_rating(bearing) / compliance_ratio(bearing) ** 2
    return iso76_f0(bearing.ball_diameter / bearing.pitch_diameter) / steel_c0


def equivalent_load(bearing, radial: float, axial: float) -> float:
    """ISO 281 dynamic equivalent load P = X Fr + Y Fa [N] of a bearing type or a matched pair."""
    return float(cf.equivalent_dynamic_load(abs(radial), abs(axial), _factors(bearing, axial)))


def _drop_fatigue(plane, drop_ds: xr.Dataset, k: int) -> dict:
    """The drop's rainflow damage of plane k; a matched pair's rows as a series system of two bearings.

    Each row is counted on its own rings; the set fails with its first row, so the rows' damages combine as
    Lundberg-Palmgren ring damages do, D = (D_1^e + D_2^e)^(1/e) (:func:`auxbearing.core.fatigue.bearing_damage`).
    """
    t, speed = drop_ds.time.values, drop_ds.race_speed.isel(plane=k).values
    bearing = plane.bearing
    arrays = plane_ball_arrays(drop_ds, k, bearing.ball_count, bearing.pairs_per_ball * plane.rows)
    inner, outer = arrays["stress_inner"], arrays["stress_outer"]
    if plane.rows == 1:
        return drop_damage(t, speed, inner, outer, bearing)
    per = inner.shape[2] // plane.rows
    rows = [drop_damage(t, speed, inner[:, :, j * per:(j + 1) * per], outer[:, :, j * per:(j + 1) * per], bearing)
            for j in range(plane.rows)]
    worst = max(range(plane.rows), key=lambda j: rows[j]["worst_contact"]["damage"])
    contact = dict(rows[worst]["worst_contact"], pair=rows[worst]["worst_contact"]["pair"] + worst * per, row=worst)
    return {"damage": float(cf.bearing_damage(rows[0]["damage"], rows[1]["damage"])), "worst_contact": contact,
            "rows": rows}


def plane_life(machine, k: int, drop_ds: xr.Dataset, drop_plane: dict, overrolling: list[tuple[float, float]]) -> dict:
    """Damage per drop (drop + coast-down), drops to failure and to the dent limit, and which governs.

    Parameters
    ----------
    machine : Machine
    k : int
        Plane index.
    drop_ds : xarray.Dataset
        The drop's time series (:func:`auxbearing.analysis.drop.run_machine`), with ``stress_inner`` and
        ``stress_outer`` over (time, plane, ball, pair).
    drop_plane : dict
        The drop summary's entry of the plane (its ``peak_ball_load_N``).
    overrolling : list of (revolutions, equivalent load [N])
        The coast-down's stretches and windows after the drop.
    """
    plane = machine.planes[k]
    bearing = plane.bearing
    out: dict = {}
    if plane_ball_arrays(drop_ds, k, 1, 1) is not None:
        fatigue = _drop_fatigue(plane, drop_ds, k)
        out["drop_damage"] = float(fatigue["damage"])
        out["worst_contact"] = fatigue["worst_contact"]
    else:  # a drop too long to keep its ball arrays: count it as the coast-down counts a window
        fatigue = None
        revolutions, load = _drop_overrolling(plane, drop_ds, k)
        out["drop_damage"] = (revolutions / (float(cf.rating_life(dynamic_load_rating(plane.unit), load)) * 1e6)
                              if load > 0.0 and revolutions > 0.0 else 0.0)
        out["drop_damage_method"] = ("over-rolling at the drop's mean load (its ball stresses were too many to keep): "
                                     "the ISO 281 rating life, as for the coast-down's windows")
    rating = dynamic_load_rating(plane.unit)
    coast = 0.0
    for revolutions, load in overrolling:
        if load > 0.0 and revolutions > 0.0:
            coast += revolutions / (float(cf.rating_life(rating, load)) * 1e6)
    out["coastdown_damage"] = coast
    damage = out["drop_damage"] + coast
    out["damage_per_drop"] = damage
    out["drops_to_failure"] = 1.0 / damage if damage > 0.0 else math.inf
    peak = drop_plane.get("peak_ball_load_N") or 0.0
    dent = dent_per_drop(peak, bearing, machine.life.dent_accumulation)
    out["drops_to_dent_limit"] = float(dent["drops_to_dent_limit"])
    out["dent_depth_um"] = max(dent["inner"]["depth"], dent["outer"]["depth"]) * 1e6
    out["dent_assumption"] = dent["assumption"]
    out["dynamic_load_rating_N"] = rating
    out["governing"] = governing(out["drops_to_failure"], out["drops_to_dent_limit"], machine.life.required_drops)
    out["fatigue"] = fatigue
    return out


def _drop_overrolling(plane, drop_ds: xr.Dataset, k: int) -> tuple[float, float]:
    """Race revolutions of the drop and its ISO 281 equivalent load [N], as a coast-down window is counted.

    The radial part is the mean of the ball set's varying reaction weighted by the revolutions,
    F_m = (integral of F^3 dN / N)^(1/3) (Mott, Machine Elements in Mechanical Design, 4th ed., 2004,
    Eq. 14-11), the axial part the mean thrust on the balls.
    """
    t = drop_ds.time.values
    turns = np.abs(drop_ds.race_speed.isel(plane=k).values) / (2.0 * math.pi)
    radial = np.hypot(drop_ds.ball_force_x.isel(plane=k).values, drop_ds.ball_force_y.isel(plane=k).values)
    axial = np.abs(drop_ds.ball_force_axial.isel(plane=k).values)
    dn = 0.5 * (turns[1:] + turns[:-1]) * np.diff(t)
    revolutions = float(dn.sum())
    if revolutions <= 0.0:
        return 0.0, 0.0
    f3 = 0.5 * (radial[1:] ** 3 + radial[:-1] ** 3)
    mean_radial = float((f3 * dn).sum() / revolutions) ** (1.0 / 3.0)
    mean_axial = float((0.5 * (axial[1:] + axial[:-1]) * dn).sum() / revolutions)
    return revolutions, equivalent_load(plane.unit, mean_radial, mean_axial)


def cycles_of_worst_contact(life: dict) -> dict | None:
    """The counted stress cycles of the most damaged contact of the drop (ranges, means, counts), for a figure."""
    fatigue = life.get("fatigue")
    if not fatigue:
        return None
    worst = fatigue["worst_contact"]
    return {key: np.asarray(worst[key]) for key in ("ranges", "means", "counts") if key in worst} | {
        "race": worst.get("race"), "ball": worst.get("ball"), "pair": worst.get("pair")}
