"""Ball-raceway Hertz contact of a bearing, its sweeps and the four-point/angular comparison.

Source paper Sec. II.B read as docs/paper_notes.md explains: the 1000 N "radial external
load" is the radial load on one ball; a four-point ball touches each race at +alpha and -alpha
so each contact carries Q / (2 cos alpha), an angular-contact ball carries Q / cos alpha on
its single contact.
"""

from __future__ import annotations

import json
import math

import numpy as np
import xarray as xr

from auxbearing import __version__
from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.common.errors import InputError
from auxbearing.common.io import to_jsonable
from auxbearing.common.units import to_si
from auxbearing.core import hertz

RACES = ("inner", "outer")
#: Ellipticity from exact elliptic integrals, or the Hamrock-Brewe approximation (core.hertz.point_contact).
METHODS = ("exact", "hamrock_brewe")

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


class OutsideHertz(InputError):
    """A contact so large that Hertz theory gives no result for it.

    ``reason`` is the sentence without the ``field = value`` head, so that a caller who knows the input by
    another name (a command-line option) can name it its own way.
    """

    def __init__(self, field: str, value: object, reason: str) -> None:
        super().__init__(f"{field} = {value!r}: {reason}")
        self.reason = reason


def ball_load_si(value: object, field: str = "ball_load") -> float:
    """A radial ball load as the user gave it ("1 kN", 1000, a Quantity) in N, refused when negative.

    >>> ball_load_si("1 kN")
    1000.0
    >>> ball_load_si(-5)
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: ball_load = -5: must be >= 0 N
    """
    load = to_si(field, value, "force", "N")
    if load < 0.0:
        raise InputError.for_field(field, value, "must be >= 0 N")
    return load


def check_method(method: object, field: str = "method") -> str:
    """The ellipticity method, refused with its name when it is none of :data:`METHODS`."""
    if not isinstance(method, str) or method not in METHODS:
        raise InputError.for_field(field, method, "must be one of " + ", ".join(METHODS))
    return method


def with_overrides(bearing: BearingGeometry, contact_angle: object = None, groove_ratio: object = None,
                   names: tuple[str, str] = ("contact_angle", "groove_ratio"), angle_unit: str = "rad"
                   ) -> BearingGeometry:
    """``bearing`` with its contact angle and both groove ratios replaced; errors name the value as given.

    ``names`` are the two inputs as the caller's user knows them (the API's arguments, or the command line's
    ``--contact-angle`` and ``--groove-ratio``); a plain number for the angle is in ``angle_unit`` (radians in
    the API, as every angle of a :class:`~auxbearing.bearings.geometry.BearingGeometry`; degrees on the command
    line); a string carries its own unit ("35 deg").

    >>> from auxbearing import get_bearing
    >>> with_overrides(get_bearing("QJ202"), contact_angle=35)
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: contact_angle = 35: must lie in [0, 90) deg; a plain number is in rad (35...
    """
    angle_name, ratio_name = names
    changes: dict = {}
    typed: dict = {}
    if contact_angle is not None:
        angle = to_si(angle_name, contact_angle, "angle", angle_unit)
        if not 0.0 <= angle < 0.5 * math.pi:
            rule = "must lie in [0, 90) deg"
            if angle_unit == "rad" and isinstance(contact_angle, (int, float)):  # degrees meant: the likely slip
                rule += (f"; a plain number is in rad ({contact_angle:g} rad = {math.degrees(angle):.0f} deg), "
                         f"write '{contact_angle:g} deg' for degrees")
            raise InputError.for_field(angle_name, contact_angle, f"{rule} (bearing {bearing.name})")
        changes["contact_angle"] = angle
        typed["contact_angle"] = (angle_name, contact_angle)
    if groove_ratio is not None:
        ratio = to_si(ratio_name, groove_ratio, "dimensionless")
        changes.update(inner_groove_ratio=ratio, outer_groove_ratio=ratio)
        typed["inner_groove_ratio"] = typed["outer_groove_ratio"] = (ratio_name, groove_ratio)
    if not changes:
        return bearing
    try:
        return bearing.with_changes(**changes)
    except InputError as err:  # the geometry names its own fields ("inner_groove_ratio = 0.4")
        head, _, rule = str(err).partition(": ")
        key = head.split(" = ")[0]
        if key in typed:
            raise InputError.for_field(*typed[key], f"{rule} (bearing {bearing.name})") from None
        raise


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
    ball_load: object,
    contact_angle: object = None,
    groove_ratio: object = None,
    method: str = "exact",
) -> dict:
    """Inner and outer contact of one ball under a radial ball load, in display units.

    Returns the mapping printed by ``auxbearing contact --json``.

    Parameters
    ----------
    bearing : BearingGeometry
    ball_load : float, str or pint.Quantity
        Radial load on the ball: a number in N or with a unit ("1 kN").
    contact_angle : float, str or pint.Quantity, optional
        Override of the contact angle: a number in rad or with a unit ("35 deg").
    groove_ratio : float or str, optional
        Override of both groove radius coefficients (> 0.5).
    method : {"exact", "hamrock_brewe"}

    Raises
    ------
    InputError
        A value that is malformed or out of range, named as given; :class:`OutsideHertz` (naming the
        override given, else ``ball_load``) when an ellipse is as large as the ball (:func:`ellipse_checks`),
        where Hertz theory gives no result. Ellipses cut by the groove shoulder are only flagged, by
        :func:`ellipse_checks`.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> b = get_bearing("QJ202")
    >>> r = ball_contact(b, 1000.0)
    >>> round(r["inner"]["max_stress_MPa"])
    2610
    >>> round(ball_contact(b, "1 kN", contact_angle="35 deg")["inner"]["max_stress_MPa"])
    2610
    >>> ball_contact(b, 1000.0, groove_ratio=0.5001)
    Traceback (most recent call last):
    ...
    auxbearing.analysis.contact.OutsideHertz: groove_ratio = 0.5001: the inner contact ellipse (semi-major axis 7.558...
    """
    load = ball_load_si(ball_load)
    check_method(method)
    bearing = with_overrides(bearing, contact_angle, groove_ratio)
    out = _ball_contact(bearing, load, method)
    refusal = ellipse_checks(bearing, out)[1]
    if refusal is not None:
        # the override given is what moved the contact out of Hertz theory; without one, the load did
        field, value = next((n, v) for n, v in (("groove_ratio", groove_ratio), ("contact_angle", contact_angle),
                                                ("ball_load", ball_load)) if v is not None)
        raise OutsideHertz(field, value, refusal)
    return out


def _ball_contact(bearing: BearingGeometry, ball_load: float, method: str) -> dict:
    """:func:`ball_contact` of checked inputs, before its validity check."""
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
    >>> ellipse_checks(b, ball_contact(b, "5 kN"))[0][0][:48]
    'the inner contact ellipse runs over the groove s'
    """
    alpha = math.radians(result["contact_angle_deg"])
    warnings = []
    for race in RACES:
        c = result[race]
        a = c["semi_major_mm"] * 1e-3
        too_large, over_shoulder = outside_hertz(bearing, a, alpha, c["groove_ratio"])
        if too_large:
            return [], too_large_reason(bearing, race, a, c["contact_load_N"])
        if over_shoulder:
            from auxbearing.machine.model import SHOULDER_FRACTION

            groove = c["groove_ratio"] * bearing.ball_diameter
            reach = alpha + a / groove
            warnings.append(f"the {race} contact ellipse runs over the groove shoulder: contact angle "
                            f"{math.degrees(alpha):.3g} deg plus half the ellipse ({math.degrees(a / groove):.3g} "
                            f"deg of groove arc) reach {math.degrees(reach):.3g} deg, past the shoulder at "
                            f"{math.degrees(float(shoulder_angle(bearing, c['groove_ratio']))):.3g} deg (shoulder "
                            f"height {SHOULDER_FRACTION:g} D assumed); the edge carries a stress Hertz does not give")
    return warnings, None


def shoulder_angle(bearing: BearingGeometry, groove_ratio: np.ndarray | float) -> np.ndarray:
    """Groove arc [rad] from the groove bottom to the shoulder edge the machine model assumes.

    The shoulder stands :data:`auxbearing.machine.model.SHOULDER_FRACTION` of the ball diameter above the
    groove bottom, on a groove of radius f D.
    """
    from auxbearing.machine.model import SHOULDER_FRACTION

    groove = np.asarray(groove_ratio, float) * bearing.ball_diameter
    return np.arccos(np.maximum(-1.0, 1.0 - SHOULDER_FRACTION * bearing.ball_diameter / groove))


def outside_hertz(bearing: BearingGeometry, semi_major, contact_angle, groove_ratio) -> tuple:
    """Where contacts leave Hertz theory, elementwise: (ellipse as large as the ball, ellipse past the shoulder).

    The two tests of :func:`ellipse_checks`; ``semi_major`` [m], ``contact_angle`` [rad] and ``groove_ratio``
    broadcast against each other (a contact map's grid).
    """
    a = np.asarray(semi_major, float)
    groove = np.asarray(groove_ratio, float) * bearing.ball_diameter
    too_large = a >= 0.5 * bearing.ball_diameter
    over_shoulder = np.asarray(contact_angle, float) + a / groove > shoulder_angle(bearing, groove_ratio)
    return too_large, over_shoulder


def too_large_reason(bearing: BearingGeometry, race: str, semi_major: float, contact_load: float) -> str:
    """Why no result follows from a contact whose semi-major axis [m] reaches the ball's radius."""
    radius = 0.5 * bearing.ball_diameter
    return (f"the {race} contact ellipse (semi-major axis {semi_major * 1e3:.4g} mm) is as large as the ball "
            f"(radius {radius * 1e3:.4g} mm) at a contact load of {contact_load:.4g} N: Hertz theory needs a "
            "contact small against the ball, so no result follows")


def grid_refusal(bearing: BearingGeometry, ball_load: float, contact_angles_deg, groove_ratios) -> str | None:
    """Why a contact map of ``bearing`` over these grids would hold no Hertz result somewhere, or None.

    The refusal of :func:`ellipse_checks` at the grid's largest ellipse. The semi-major axis grows with the
    contact angle (the load on each contact, Q / (pairs cos alpha), grows) and with the conformity (the
    groove ratio falling to 0.5); swept at 1000 N over 0-89.9 deg and 0.5005-0.95 (300 x 300 points) for
    QJ202, 7202, 218 and QJ208 it never falls along either. So the largest ellipse sits at the largest angle
    and the smallest ratio.

    >>> from auxbearing import get_bearing
    >>> grid_refusal(get_bearing("QJ202"), 1000.0, [10.0, 75.0], [0.505, 0.6]) is None
    True
    >>> grid_refusal(get_bearing("QJ202"), 1000.0, [10.0, 89.5], [0.505, 0.6])[:52]
    'at a contact angle of 89.5 deg and a groove ratio of'
    """
    angle = math.radians(max(float(np.max(contact_angles_deg)), math.degrees(bearing.contact_angle)))
    ratio = min(float(np.min(groove_ratios)), bearing.inner_groove_ratio)
    load = ball_load / (bearing.pairs_per_ball * math.cos(angle))
    for race in RACES:
        c = raceway_contact(bearing, load, race, contact_angle=angle, groove_ratio=ratio)
        if outside_hertz(bearing, float(c.semi_major), angle, ratio)[0]:
            return (f"at a contact angle of {math.degrees(angle):.4g} deg and a groove ratio of {ratio:.4g}, "
                    + too_large_reason(bearing, race, float(c.semi_major), load))
    return None


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
    ball_load: object,
    contact_angles_deg: np.ndarray,
    groove_ratios: np.ndarray,
    method: str = "exact",
) -> xr.Dataset:
    """Contact of one ball over a grid of contact angle x groove ratio (Fig. 2-3 and beyond).

    Both grooves take the swept ratio, as the paper's "radius coefficient of race". The
    bearing's own angle and ratio are added to the grids so that Fig. 2 and Fig. 3 are exact
    slices of the map. ``ball_load`` is a number in N or has a unit ("1 kN"). Grid points outside Hertz
    theory are kept; :func:`outside_hertz` finds them and :func:`grid_refusal` says whether any would be.
    """
    ball_load = ball_load_si(ball_load)
    check_method(method)
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
        # JSON, as every other file stores it: through the shared encoder, so an infinity is "inf"
        bearing=json.dumps(to_jsonable(bearing.describe()), default=str, allow_nan=False),
        auxbearing_version=__version__,
        source="source paper Sec. II.B, Eq. 4-8, Fig. 2-3",
    )
    return ds


def type_comparison(bearing: BearingGeometry, ball_load: object = 1000.0) -> dict:
    """Four-point versus angular-contact max stress at the same geometry (source paper Fig. 4)."""
    ball_load = ball_load_si(ball_load)
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
