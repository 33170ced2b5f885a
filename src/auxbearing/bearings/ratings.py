"""Basic load ratings of a ball bearing from its geometry: ISO 281 C, ISO 76 C0, hybrids and matched sets.

* Dynamic rating C (ISO 281:2007, 6.1.1) through :func:`auxbearing.core.fatigue.dynamic_load_rating`,
  times the bearing's ``rating_factor`` (a maker's adjustment of b_m; 1 for the plain standard).
* Static rating C0 (ISO 76:2006, 6.1.1): C0 = f0 i Z D_w^2 cos(alpha). The factor f0 is not typed
  from ISO 76's Table 1 but computed the way that table was made (ISO 76:2006, Introduction and
  6.1.1): the ball load Q0 that gives 4200 MPa at the centre of the most stressed contact, with the
  groove radii the standard assumes (0.52 D_w inner, 0.53 D_w outer) and steel on steel (E = 207 GPa,
  nu = 0.3), spread over the balls as Q_max = 5 F_r / (i Z cos alpha) (Stribeck's static factor 5 of
  ISO 76), so f0 = Q0 / (5 D_w^2) in N and mm. tests/consistency checks it against the Hertz
  closed form and against the f0 of the SKF bearings whose ball sets are published.
* Hybrids (silicon-nitride balls): C as the all-steel bearing's (DIN ISO 281 Beiblatt 5, superseded
  by DIN ISO 20056-1:2019: "a reduction of the dynamic load rating for hybrid bearings is not
  necessary"); C0 at the same 4200 MPa with the ceramic ball's compliance, which lowers it by the
  square of the compliance ratio (Q ~ sigma^3 eta^2 in Hertz point contact). ISO 20056-2:2017
  allows a slightly higher permissible stress for hybrids; its value was not retrievable here, so
  this C0 is on the safe side.
* Matched sets (ISO 281:2007 6.1.2-6.1.3; ISO 76:2006 6.1.2): two identical single-row
  angular-contact bearings side by side working as one unit (back-to-back, face-to-face or in
  tandem) have C_pair = 2^0.7 C and C0_pair = 2 C0.
"""

from __future__ import annotations

import contextlib
import math

import numpy as np

from auxbearing.common.errors import InputError
from auxbearing.core import fatigue as cf
from auxbearing.core import hertz

#: ISO 76:2006 6.1.1: permissible contact stress at C0 for ball bearings other than self-aligning [Pa].
ISO76_STRESS = 4200e6
#: Groove radii that ISO 76's f0 assumes for radial ball bearings (inner 0.52 D_w, outer 0.53 D_w).
ISO76_INNER_GROOVE, ISO76_OUTER_GROOVE = 0.52, 0.53
#: Steel on steel, the elastic constants behind ISO 76's f0 (E = 207 GPa, nu = 0.3).
ISO76_MODULUS, ISO76_POISSON = 207e9, 0.3
#: ISO 76's static load distribution: Q_max = 5 F_r / (i Z cos alpha).
ISO76_DISTRIBUTION = 5.0
#: ISO 281:2007 6.1.2-6.1.3: a matched set of n identical rows is rated n^0.7 times one row.
ROW_EXPONENT = 0.7
#: ISO 76 works in N and mm.
_MM = 1e3
#: f0 of steel radial ball bearings at gamma = 0, 0.01, ..., 0.42, computed by :func:`f0_exact` and read by
#: linear interpolation as ISO 76 reads its own Table 1 (tests/consistency recompute it; the values
#: agree with the ISO 76 table as makers reprint it, 14.7 at 0 and 16.4 at 0.10).
ISO76_F0 = (14.7341, 14.9320, 15.1305, 15.3296, 15.5292, 15.7294, 15.9302, 16.1315, 16.3334, 16.5358, 16.3952,
            16.1468, 15.8993, 15.6528, 15.4072, 15.1625, 14.9189, 14.6762, 14.4345, 14.1938, 13.9541, 13.7154,
            13.4778, 13.2412, 13.0056, 12.7712, 12.5378, 12.3054, 12.0742, 11.8441, 11.6151, 11.3873, 11.1606,
            10.9351, 10.7107, 10.4876, 10.2656, 10.0449, 9.8254, 9.6072, 9.3902, 9.1746, 8.9602)
ISO76_F0_STEP = 0.01


def _steel_compliance() -> float:
    return 2.0 * (1.0 - ISO76_POISSON**2) / ISO76_MODULUS


def f0_exact(gamma, compliance: float | None = None):
    """ISO 76 factor f0 [-] at gamma = D_w cos(alpha) / D_pw, from Hertz at 4200 MPa (arrays too).

    Parameters
    ----------
    gamma : float or array
        D_w cos(alpha)/D_pw [-], 0 to 0.42.
    compliance : float, optional
        Sum (1 - nu1^2)/E1 + (1 - nu2^2)/E2 [1/Pa]; default steel on steel (ISO 76's).

    Examples
    --------
    >>> [round(float(f0_exact(g)), 2) for g in (0.0, 0.1, 0.2)]
    [14.73, 16.4, 13.95]
    """
    eta = _steel_compliance() if compliance is None else compliance
    g = np.maximum(np.asarray(gamma, float), 1e-9)
    dm = 1.0 / g  # D_w = 1 m; the factor depends on gamma only
    loads = []
    for race, ratio in (("inner", ISO76_INNER_GROOVE), ("outer", ISO76_OUTER_GROOVE)):
        sum_rho, f_rho = hertz.ball_raceway_curvature(1.0, dm, ratio, 0.0, race)
        coefficient = np.asarray(hertz.stress_coefficient(np.atleast_1d(sum_rho), np.atleast_1d(f_rho), eta))
        loads.append((ISO76_STRESS / coefficient) ** 3)
    out = np.minimum(*loads) / (ISO76_DISTRIBUTION * _MM**2)
    return out.reshape(np.shape(gamma)) if np.ndim(gamma) else float(out[0])


@contextlib.contextmanager
def _within_the_standards(bearing):
    """Say a missing load rating as bad input on the ball diameter, where the kernels raise a plain ValueError.

    A ball set whose D_w cos(alpha) / D_pw lies outside ISO 281's and ISO 76's tables has no load rating.
    """
    try:
        yield
    except ValueError:
        gamma = bearing.ball_diameter * math.cos(bearing.contact_angle) / bearing.pitch_diameter
        raise InputError.for_field(
            "ball_diameter", f"{bearing.ball_diameter * 1e3:g} mm",
            f"with a pitch diameter of {bearing.pitch_diameter * 1e3:g} mm and a contact angle of "
            f"{math.degrees(bearing.contact_angle):g} deg, D_w cos(alpha)/D_pw = {gamma:.3g} lies outside the "
            f"tables of ISO 281 ({cf.ISO281_FC_GAMMA[0]:g}-{cf.ISO281_FC_GAMMA[-1]:g}) or ISO 76 (0-"
            f"{ISO76_F0_STEP * (len(ISO76_F0) - 1):g}), so {bearing.name} has no load rating") from None


def nearest_angle(table: dict, contact_angle: float) -> int:
    """The key of an ISO table by contact angle [deg] nearest ``contact_angle`` [rad].

    On a tie the smaller angle, whose axial factor is the larger (the safe side).

    >>> nearest_angle({30: 0.33, 35: 0.29, 40: 0.26}, math.radians(37.5))
    35
    """
    return min(sorted(table), key=lambda a: abs(a - math.degrees(contact_angle)))


def iso76_f0(gamma: float) -> float:
    """f0 [-] of ISO 76 for steel bearings: :data:`ISO76_F0` read by linear interpolation.

    Examples
    --------
    >>> round(iso76_f0(0.2034), 2)
    13.87
    """
    top = ISO76_F0_STEP * (len(ISO76_F0) - 1)
    if not 0.0 <= gamma <= top:
        raise ValueError(f"D_w cos(alpha)/D_pw = {gamma:.4g}: outside 0 to {top:g}")
    x = gamma / ISO76_F0_STEP
    i = min(int(x), len(ISO76_F0) - 2)
    return ISO76_F0[i] + (x - i) * (ISO76_F0[i + 1] - ISO76_F0[i])


def static_load_rating_si(ball_diameter: float, pitch_diameter: float, ball_count: int, contact_angle: float,
                          rows: int = 1, compliance_ratio: float = 1.0) -> float:
    """Basic static radial load rating C0 [N] (ISO 76:2006 6.1.1), C0 = f0 i Z D_w^2 cos(alpha).

    Parameters
    ----------
    ball_diameter, pitch_diameter : float
        D_w, D_pw [m].
    ball_count : int
        Z per row.
    contact_angle : float
        alpha [rad].
    rows : int
        i.
    compliance_ratio : float
        Contact compliance of the bearing's materials over steel on steel's; C0 scales with its
        square (hybrid bearings, see the module notes).

    Examples
    --------
    >>> round(static_load_rating_si(7.94e-3, 39.04e-3, 9, 0.0))  # CWRU's SKF 6205 ball set
    7872
    """
    gamma = ball_diameter * math.cos(contact_angle) / pitch_diameter
    c0 = iso76_f0(gamma) * rows * ball_count * (ball_diameter * _MM) ** 2 * math.cos(contact_angle)
    return c0 * compliance_ratio**2


def compliance_ratio(bearing) -> float:
    """The bearing's contact compliance over ISO 76's steel on steel [-] (< 1 for ceramic balls).

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> round(compliance_ratio(get_bearing("6205")), 4), round(compliance_ratio(get_bearing("6205 hybrid")), 4)
    (1.0, 0.8421)
    """
    return bearing.contact_compliance / _steel_compliance()


def rating_rows(bearing) -> int:
    """Rows i of the ISO 281 / ISO 76 rating: 2 for a four-point bearing (makers' practice), else 1."""
    return 2 if bearing.type == "four_point" else 1


def static_load_rating(bearing) -> float:
    """Basic static radial load rating C0 [N] of a bearing (ISO 76; hybrids see the module notes).

    A four-point bearing is rated as a double-row 35 deg bearing (i = 2), as for C.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> round(static_load_rating(get_bearing("6205")) / 1e3, 2)   # SKF: 7.8 kN
    7.85
    """
    with _within_the_standards(bearing):
        return static_load_rating_si(bearing.ball_diameter, bearing.pitch_diameter, bearing.ball_count,
                                     bearing.contact_angle, rating_rows(bearing), compliance_ratio(bearing))


def dynamic_load_rating(bearing) -> float:
    """Basic dynamic radial load rating C [N] of one bearing: ISO 281 times its ``rating_factor``.

    The ball material does not enter (DIN ISO 281 Bbl. 5 / ISO 20056-1 for hybrids).

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> round(dynamic_load_rating(get_bearing("209")))
    32687
    """
    with _within_the_standards(bearing):
        base = cf.dynamic_load_rating(bearing.ball_diameter, bearing.pitch_diameter, bearing.ball_count,
                                      bearing.contact_angle, rating_rows(bearing))
    return base * getattr(bearing, "rating_factor", 1.0)


def set_factor(rows: int) -> float:
    """C of n identical rows as one unit over C of one row, n^0.7 (ISO 281:2007 6.1.2-6.1.3).

    Examples
    --------
    >>> round(set_factor(2), 4)
    1.6245
    """
    return rows**ROW_EXPONENT


#: ISO 76:2006 permissible contact stress at C0 for ball bearings (not self-aligning) [Pa].
ISO76_BALL_STRESS = 4200e6


def safety_factor(max_stress: np.ndarray | float) -> np.ndarray:
    """Static safety factor s0 = (4200 MPa / sigma_max)^3 (ISO 76:2006 with Hertz sigma ~ Q^(1/3)).

    Parameters
    ----------
    max_stress : float or array
        Largest Hertz contact stress [Pa]; zero gives infinity.

    Examples
    --------
    >>> float(safety_factor(4200e6)), float(safety_factor(2100e6))
    (1.0, 8.0)
    """
    sigma = np.asarray(max_stress, float)
    with np.errstate(divide="ignore", over="ignore"):  # a vanishing stress gives an infinite s0, not a warning
        return np.where(sigma > 0.0, (ISO76_BALL_STRESS / np.where(sigma > 0.0, sigma, 1.0)) ** 3, np.inf)
