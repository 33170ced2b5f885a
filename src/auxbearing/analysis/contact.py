"""Ball-raceway Hertz contact of a bearing, its sweeps and the four-point/angular comparison.

Source paper Sec. II.B read as docs/paper_notes.md explains: the 1000 N "radial external
load" is the radial load on one ball; a four-point ball touches each race at +alpha and -alpha
so each contact carries Q / (2 cos alpha), an angular-contact ball carries Q / cos alpha on
its single contact.
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr

from auxbearing import __version__
from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.common.errors import InputError
from auxbearing.core import hertz

RACES = ("inner", "outer")

#: Values printed in the source paper, Sec. II.B (Fig. 4 discussion), at 1000 N ball load.
PAPER_CONTACT = {
    "theory_four_point_MPa": 2616.0,
    "fe_four_point_MPa": 2346.2,
    "fe_angular_contact_MPa": 3043.9,
    "claimed_reduction_percent": 22.9,
}

_VARIABLES = {
    "contact_load": ("N", "Load on one ball-raceway contact"),
    "semi_major": ("m", "Semi-major axis a of the contact ellipse"),
    "semi_minor": ("m", "Semi-minor axis b of the contact ellipse"),
    "approach": ("m", "Elastic approach delta of ball and raceway"),
    "max_stress": ("Pa", "Maximum Hertz contact stress 3Q/(2 pi a b)"),
    "ellipticity": ("1", "Ellipticity kappa = a/b"),
    "stiffness": ("N/m^1.5", "Load-deflection constant K, Q = K delta^1.5"),
}


def compliance(bearing: BearingGeometry) -> float:
    """Eta = (1 - nu_ball^2)/E_ball + (1 - nu_ring^2)/E_ring [1/Pa], source paper Eq. 3."""
    return bearing.contact_compliance


def contact_load(bearing: BearingGeometry, ball_load: float, contact_angle: float | None = None) -> float:
    """Load on each contact of a ball under radial ball load Q [N]: Q / (pairs cos alpha).

    Statics of one ball pressed radially with all its pairs loaded equally (docs/paper_notes.md on Sec. II.B).
    """
    alpha = bearing.contact_angle if contact_angle is None else contact_angle
    return ball_load / (bearing.pairs_per_ball * math.cos(alpha))


def raceway_contact(
    bearing: BearingGeometry,
    load: np.ndarray | float,
    race: str,
    contact_angle: np.ndarray | float | None = None,
    groove_ratio: np.ndarray | float | None = None,
    method: str = "exact",
) -> hertz.PointContact:
    """Hertz contact of one ball on the inner or outer raceway (source paper Eq. 4-8).

    Parameters
    ----------
    bearing : BearingGeometry
    load : float or array
        Contact load [N].
    race : {"inner", "outer"}
    contact_angle : float or array, optional
        [rad]; default the bearing's.
    groove_ratio : float or array, optional
        Groove ratio of that race [-]; default the bearing's.
    method : {"exact", "hamrock_brewe"}
    """
    alpha = bearing.contact_angle if contact_angle is None else contact_angle
    if groove_ratio is None:
        groove_ratio = bearing.inner_groove_ratio if race == "inner" else bearing.outer_groove_ratio
    sum_rho, f_rho = hertz.ball_raceway_curvature(
        bearing.ball_diameter, bearing.pitch_diameter, groove_ratio, alpha, race
    )
    return hertz.point_contact(load, sum_rho, f_rho, compliance(bearing), method)


def ball_constant(bearing: BearingGeometry, contact_angle: float | np.ndarray | None = None) -> np.ndarray:
    """K_b of one ball between the races [N/m^1.5], source paper Eq. 15 from Hertz K_i, K_o."""
    k_inner = raceway_contact(bearing, 0.0, "inner", contact_angle).stiffness
    k_outer = raceway_contact(bearing, 0.0, "outer", contact_angle).stiffness
    return hertz.series_constant(k_inner, k_outer)


def ball_contact(
    bearing: BearingGeometry,
    ball_load: float,
    contact_angle: float | None = None,
    groove_ratio: float | None = None,
    method: str = "exact",
) -> dict:
    """Inner and outer contact of one ball under a radial ball load, in display units.

    Returns the mapping printed by ``auxbearing contact --json``.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> r = ball_contact(get_bearing("QJ202"), 1000.0)
    >>> round(r["inner"]["max_stress_MPa"])
    2610
    """
    if not (isinstance(ball_load, (int, float)) and math.isfinite(ball_load)) or ball_load < 0.0:
        raise InputError.for_field("ball_load", ball_load, "must be >= 0 N and finite")
    if contact_angle is not None:
        bearing = bearing.with_changes(contact_angle=contact_angle)
    if groove_ratio is not None:
        bearing = bearing.with_changes(inner_groove_ratio=groove_ratio, outer_groove_ratio=groove_ratio)
    q = contact_load(bearing, ball_load)
    out: dict = {
        "bearing": bearing.name,
        "type": bearing.type,
        "ball_load_N": ball_load,
        "contact_angle_deg": math.degrees(bearing.contact_angle),
        "contacts_per_race": bearing.pairs_per_ball,
        "ball_constant_N_per_m1_5": float(ball_constant(bearing)),
    }
    for race in RACES:
        c = raceway_contact(bearing, q, race, method=method)
        out[race] = {
            "contact_load_N": q,
            "groove_ratio": bearing.inner_groove_ratio if race == "inner" else bearing.outer_groove_ratio,
            "semi_major_mm": float(c.semi_major) * 1e3,
            "semi_minor_mm": float(c.semi_minor) * 1e3,
            "approach_um": float(c.approach) * 1e6,
            "max_stress_MPa": float(c.max_stress) / 1e6,
            "ellipticity": float(c.ellipticity),
            "stiffness_N_per_m1_5": float(c.stiffness),
        }
    return out


def ellipse_checks(bearing: BearingGeometry, result: dict) -> tuple[list[str], str | None]:
    """Where a contact of :func:`ball_contact` leaves Hertz theory: warnings, and a reason no result follows.

    Hertz's solution holds for a contact small against the bodies' radii (Johnson, *Contact Mechanics*,
    1985, Sec. 4.1); a semi-major axis as large as the ball's radius is outside it altogether (the
    reason returned). Short of that, an ellipse whose half-length, added to the contact angle, reaches
    past the groove shoulder is cut by the shoulder's edge, which carries a stress Hertz does not give
    (a warning). The shoulder is the one the machine model assumes
    (:data:`auxbearing.machine.model.SHOULDER_FRACTION` of the ball diameter above the groove bottom), and the
    test is the one its observer applies during a drop.

    Parameters
    ----------
    bearing : BearingGeometry
    result : dict
        What :func:`ball_contact` returned for it.

    Returns
    -------
    warnings : list of str
    refusal : str or None
        Why the numbers mean nothing, or None.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> b = get_bearing("QJ202")
    >>> ellipse_checks(b, ball_contact(b, 1000.0))
    ([], None)
    >>> conformal = b.with_changes(inner_groove_ratio=0.5000001, outer_groove_ratio=0.5000001)
    >>> ellipse_checks(conformal, ball_contact(conformal, 1000.0))[1][:45]
    'the inner contact ellipse (semi-major axis 89'
    """
    from auxbearing.machine.model import SHOULDER_FRACTION

    radius = 0.5 * bearing.ball_diameter
    alpha = math.radians(result["contact_angle_deg"])
    warnings = []
    for race in RACES:
        c = result[race]
        a = c["semi_major_mm"] * 1e-3
        if a >= radius:
            return [], (f"the {race} contact ellipse (semi-major axis {a * 1e3:.4g} mm) is as large as the ball "
                        f"(radius {radius * 1e3:.4g} mm) at a contact load of {c['contact_load_N']:.4g} N: Hertz "
                        "theory needs a contact small against the ball, so no result follows")
        groove = c["groove_ratio"] * bearing.ball_diameter
        shoulder = math.acos(max(-1.0, 1.0 - SHOULDER_FRACTION * bearing.ball_diameter / groove))
        reach = alpha + a / groove
        if reach > shoulder:
            warnings.append(f"the {race} contact ellipse runs over the groove shoulder: contact angle "
                            f"{math.degrees(alpha):.3g} deg plus half the ellipse ({math.degrees(a / groove):.3g} "
                            f"deg of groove arc) reach {math.degrees(reach):.3g} deg, past the shoulder at "
                            f"{math.degrees(shoulder):.3g} deg (shoulder height {SHOULDER_FRACTION:g} D assumed); the "
                            "edge carries a stress Hertz does not give")
    return warnings, None


def sweep_grid(start: float, stop: float, step: float) -> np.ndarray:
    """START, START + STEP, ... up to STOP, never past it (a float error of 1e-9 steps is forgiven).

    >>> sweep_grid(10.0, 89.9, 5.0)[-1]
    np.float64(85.0)
    >>> len(sweep_grid(0.505, 0.6, 0.0025))
    39
    """
    count = math.floor((stop - start) / step + 1e-9) + 1
    return start + step * np.arange(count)


def contact_map(
    bearing: BearingGeometry,
    ball_load: float,
    contact_angles_deg: np.ndarray,
    groove_ratios: np.ndarray,
    method: str = "exact",
) -> xr.Dataset:
    """Contact of one ball over a grid of contact angle x groove ratio (Fig. 2-3 and beyond).

    Both grooves take the swept ratio, as the paper's "radius coefficient of race". The
    bearing's own angle and ratio are added to the grids so that Fig. 2 and Fig. 3 are exact
    slices of the map.
    """
    if ball_load < 0.0 or not math.isfinite(ball_load):
        raise InputError.for_field("ball_load", ball_load, "must be >= 0 N and finite")
    # rounded so that a grid point and the bearing's own value do not sit 1e-16 apart
    angles = np.unique(np.round(np.r_[np.asarray(contact_angles_deg, float), math.degrees(bearing.contact_angle)], 9))
    ratios = np.unique(np.round(np.r_[np.asarray(groove_ratios, float), bearing.inner_groove_ratio], 9))
    if np.any(angles < 0.0) or np.any(angles >= 90.0):
        raise InputError.for_field("contact_angle", float(angles.max()), "must lie in [0, 90) deg")
    if np.any(ratios <= 0.5):
        raise InputError.for_field("groove_ratio", float(ratios.min()), "must be > 0.5")
    alpha = np.radians(angles)[:, None]
    f = ratios[None, :]
    q = ball_load / (bearing.pairs_per_ball * np.cos(alpha)) * np.ones_like(f)
    data = {name: (("race", "contact_angle", "groove_ratio"), np.empty((2, *q.shape))) for name in _VARIABLES}
    for i, race in enumerate(RACES):
        c = raceway_contact(bearing, q, race, contact_angle=alpha, groove_ratio=f, method=method)
        data["contact_load"][1][i] = q
        for name in _VARIABLES:
            if name != "contact_load":
                data[name][1][i] = getattr(c, name)
    ds = xr.Dataset(
        data,
        coords={
            "race": list(RACES),
            "contact_angle": ("contact_angle", angles, {"units": "deg", "long_name": "Contact angle"}),
            "groove_ratio": ("groove_ratio", ratios, {"units": "1", "long_name": "Groove radius coefficient f"}),
        },
    )
    for name, (unit, long_name) in _VARIABLES.items():
        ds[name].attrs.update(units=unit, long_name=long_name)
    ds.attrs.update(
        title=f"Hertz contact of one ball, {bearing.name} ({bearing.label})",
        ball_load_N=float(ball_load),
        load_split="radial ball load / (contact pairs * cos(alpha)) per contact",
        ellipticity_method=method,
        bearing=str(bearing.describe()),
        auxbearing_version=__version__,
        source="source paper Sec. II.B, Eq. 4-8, Fig. 2-3",
    )
    return ds


def type_comparison(bearing: BearingGeometry, ball_load: float = 1000.0) -> dict:
    """Four-point versus angular-contact max stress at the same geometry (source paper Fig. 4)."""
    four = bearing.with_changes(type="four_point", diametral_clearance=0.0)
    angular = bearing.with_changes(type="angular_contact", diametral_clearance=0.0)
    s4 = ball_contact(four, ball_load)["inner"]["max_stress_MPa"]
    sa = ball_contact(angular, ball_load)["inner"]["max_stress_MPa"]
    return {
        "ball_load_N": ball_load,
        "four_point_max_stress_MPa": s4,
        "angular_contact_max_stress_MPa": sa,
        "reduction_percent": 100.0 * (1.0 - s4 / sa),
        "paper": dict(PAPER_CONTACT),
        "paper_fe_reduction_percent": 100.0
        * (1.0 - PAPER_CONTACT["fe_four_point_MPa"] / PAPER_CONTACT["fe_angular_contact_MPa"]),
    }
