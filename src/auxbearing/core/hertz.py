"""Hertz point and line contact on SI floats and numpy arrays (no units, no I/O).

Notation follows Harris & Kotzalas, *Rolling Bearing Analysis*, 5th ed. (2007), Essential
Concepts, Ch. 2 (curvature) and Ch. 6 (contact stress and deformation), which is also the
reading of Eq. 1-8 of the source paper:

* curvature sum and difference ``sum_rho``, ``F(rho)`` (Harris Eq. 2.2-2.3),
* ellipticity ``kappa = a/b`` from F(rho) through the complete elliptic integrals K and E
  (Harris Eq. 6.22 in the form F = [(kappa^2+1)E - 2K] / [(kappa^2-1)E]),
* semi-axes a, b (source paper Eq. 4-5; Harris Eq. 6.38-6.39), elastic approach delta (source
  paper Eq. 6 with the compliance squared, see :func:`point_contact`; Harris Eq. 6.40-6.43),
* max stress 3Q/(2 pi a b) (source paper Eq. 8; Harris Eq. 6.47),
* load-deflection constant K with Q = K delta^1.5 (Harris Eq. 7.1-7.2).

``compliance`` below is eta = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 [1/Pa] (source paper Eq. 3).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit, prange

_HALF_PI = 0.5 * np.pi
_EPS = np.finfo(float).eps

# Maclaurin coefficients of K(m) and E(m) in the parameter m (Abramowitz & Stegun 17.3.11-12):
# K = pi/2 sum a_n m^n, E = pi/2 sum a_n m^n / (1 - 2n), a_n = ((2n-1)!!/(2n)!!)^2.
_N_SERIES = 80
_A = np.cumprod(np.r_[1.0, ((2.0 * np.arange(1, _N_SERIES) - 1.0) / (2.0 * np.arange(1, _N_SERIES))) ** 2])
_E = _A / (1.0 - 2.0 * np.arange(_N_SERIES))
# numerator (2-m)E - 2(1-m)K = pi/2 sum c_n m^n with c_0 = c_1 = 0 exactly; dividing by m
# gives the series of F(rho) * E(m) * 2/pi, free of the cancellation of the closed form at small m.
_C = 2.0 * _E - 2.0 * _A
_C[1:] += -_E[:-1] + 2.0 * _A[:-1]
_S = _C[1:].copy()  # coefficients of N(m)/m, starting at m^0 (which is 0)
_SERIES_LIMIT = 0.5  # below this m the series converges as 0.5^80 and beats the closed form


class PointContact(NamedTuple):
    """Hertz point contact results (arrays broadcast over the inputs)."""

    semi_major: np.ndarray  #: a [m]
    semi_minor: np.ndarray  #: b [m]
    approach: np.ndarray  #: elastic approach delta [m]
    max_stress: np.ndarray  #: sigma_max [Pa]
    ellipticity: np.ndarray  #: kappa = a/b [-]
    stiffness: np.ndarray  #: K with Q = K delta^1.5 [N/m^1.5]


def curvature_sum_difference(rho_11, rho_12, rho_21, rho_22, plane_angle=0.0):
    """Curvature sum and curvature difference F(rho) of two bodies in contact.

    Harris & Kotzalas (2007) Eq. 2.2-2.3, generalised to principal planes at an angle
    ``plane_angle`` (Johnson, *Contact Mechanics*, 1985, Eq. 4.9); zero is the bearing case.

    Parameters
    ----------
    rho_11, rho_12 : float or array
        Principal curvatures of body I [1/m] (convex positive, concave negative).
    rho_21, rho_22 : float or array
        Principal curvatures of body II [1/m].
    plane_angle : float or array
        Angle between the principal planes [rad].

    Returns
    -------
    sum_rho : array
        Curvature sum [1/m].
    f_rho : array
        Curvature difference [-], in [0, 1).

    Examples
    --------
    >>> s, f = curvature_sum_difference(1.0, 1.0, 0.0, 0.0)
    >>> float(s), float(f)
    (2.0, 0.0)
    """
    d1 = np.asarray(rho_11, float) - rho_12
    d2 = np.asarray(rho_21, float) - rho_22
    total = np.asarray(rho_11, float) + rho_12 + rho_21 + rho_22
    diff = np.sqrt(np.maximum(d1**2 + d2**2 + 2.0 * d1 * d2 * np.cos(2.0 * np.asarray(plane_angle)), 0.0))
    return total, diff / total


def ball_raceway_curvature(ball_diameter, pitch_diameter, groove_ratio, contact_angle, race):
    """Curvature sum and difference of a ball on the inner or outer raceway.

    Harris & Kotzalas (2007) Eq. 2.27-2.33 (ball: rho = 2/D in both planes; raceway:
    rho_II1 = +-(2/D) gamma/(1 -+ gamma) in the rolling plane, rho_II2 = -1/(f D) across the
    groove; gamma = D cos(alpha)/dm, upper signs inner race).

    Parameters
    ----------
    ball_diameter : float or array
        D [m].
    pitch_diameter : float or array
        dm [m].
    groove_ratio : float or array
        f = r/D [-], > 0.5.
    contact_angle : float or array
        alpha [rad].
    race : {"inner", "outer"}

    Returns
    -------
    sum_rho, f_rho : arrays
        [1/m], [-].

    Examples
    --------
    >>> s, f = ball_raceway_curvature(6e-3, 25.5e-3, 0.52, 0.0, "inner")
    >>> round(float(s), 2), round(float(f), 5)
    (448.72, 0.94286)
    """
    d = np.asarray(ball_diameter, float)
    gamma = d * np.cos(contact_angle) / pitch_diameter
    if race == "inner":
        rho_rolling = 2.0 / d * gamma / (1.0 - gamma)
    elif race == "outer":
        rho_rolling = -2.0 / d * gamma / (1.0 + gamma)
    else:
        raise ValueError(f"race = {race!r}: must be 'inner' or 'outer'")
    rho_groove = -1.0 / (np.asarray(groove_ratio, float) * d)
    return curvature_sum_difference(2.0 / d, 2.0 / d, rho_rolling, rho_groove)


@njit(cache=True)
def _elliptic_k_e(p):
    """K(m) and E(m) at m = 1 - p by the arithmetic-geometric mean.

    Abramowitz & Stegun 17.6: K = pi / (2 AGM(1, sqrt(p))) and
    E = K (1 - sum_n 2^(n-1) c_n^2), c_0^2 = m. Fed the complementary parameter p directly, so
    elongated contacts (p -> 0) lose no digits forming 1 - m.
    """
    a = 1.0
    b = np.sqrt(p)
    total = 0.5 * (1.0 - p)
    weight = 0.5
    for _ in range(60):
        c = 0.5 * (a - b)
        a, b = 0.5 * (a + b), np.sqrt(a * b)
        weight *= 2.0
        total += weight * c * c
        # the next c is about c^2/(4a): below 1e-8 a it no longer changes a, b or the sum
        if c <= 1e-8 * a:
            c = 0.5 * (a - b)
            a = 0.5 * (a + b)
            total += 2.0 * weight * c * c
            break
    k = np.pi / (2.0 * a)
    return k, k * (1.0 - total)


@njit(cache=True)
def _curvature_difference_of(p):
    """F(rho) for kappa = p^(-1/2), its slope dF/dp, and K, E (Harris Eq. 6.22 in p = 1/kappa^2).

    F = [(1 + p) E - 2 p K] / [(1 - p) E]. Below m = 1 - p = 0.5 the closed form cancels
    (F ~ 3m/8), so a Maclaurin series with exact cancellation-free coefficients is used there.
    """
    k, e = _elliptic_k_e(p)
    m = 1.0 - p
    if m < _SERIES_LIMIT:
        series = 0.0
        dseries = 0.0
        e_series = 0.0
        de_series = 0.0
        power = 1.0
        for j in range(_N_SERIES - 1):
            series += _S[j] * power
            e_series += _E[j] * power
            if j + 1 < _N_SERIES - 1:
                dseries += (j + 1) * _S[j + 1] * power
            de_series += (j + 1) * _E[j + 1] * power
            power *= m
        f = series / e_series
        slope_m = (dseries * e_series - series * de_series) / e_series**2
        return f, -slope_m, k, e
    num = (1.0 + p) * e - 2.0 * p * k
    den = m * e
    dk = (e - p * k) / (2.0 * m * p)  # dK/dm
    de = (e - k) / (2.0 * m)  # dE/dm
    dnum = -e + (1.0 + p) * de + 2.0 * k - 2.0 * p * dk
    dden = e + m * de
    return num / den, -(dnum * den - num * dden) / den**2, k, e


@njit(cache=True)
def _solve_p(target, max_iter):
    """Safeguarded Newton for p = 1/kappa^2 with F(p) = target, started from Hamrock-Brewe."""
    if target == 0.0:
        return 1.0, 0.5 * np.pi, 0.5 * np.pi
    ratio = (1.0 + target) / (1.0 - target)
    p = ratio ** (-4.0 / np.pi)  # kappa_HB^-2 with kappa_HB = ratio^(2/pi)
    lo, hi = 0.0, 1.0  # F falls monotonically from 1 at p = 0 to 0 at p = 1
    k = e = 0.0
    for _ in range(max_iter):
        f, slope, k, e = _curvature_difference_of(p)
        resid = f - target
        if abs(resid) <= _EPS * target:
            return p, k, e
        if resid > 0.0:
            lo = max(lo, p)
        else:
            hi = min(hi, p)
        p_new = p - resid / slope
        if not (lo < p_new < hi):
            p_new = 0.5 * (lo + hi)
        if abs(p_new - p) <= 2.0 * _EPS * p:
            p = p_new
            break
        p = p_new
    k, e = _elliptic_k_e(p)
    return p, k, e


@njit(cache=True, parallel=True)
def _ellipticity_exact(targets, max_iter):
    n = targets.size
    kappa = np.empty(n)
    k_int = np.empty(n)
    e_int = np.empty(n)
    for i in prange(n):
        p, k_int[i], e_int[i] = _solve_p(targets[i], max_iter)
        kappa[i] = 1.0 / np.sqrt(p)
    return kappa, k_int, e_int


def ellipticity(f_rho, method="exact", max_iter=60):
    """Ellipticity kappa = a/b of the contact ellipse from the curvature difference.

    ``exact`` solves F(rho) = [(kappa^2+1) E - 2K] / [(kappa^2-1) E] (Harris & Kotzalas 2007,
    Eq. 6.22; source paper Sec. II.A) for kappa to machine precision: compiled, per-contact
    safeguarded Newton on p = 1/kappa^2 started from the Hamrock-Brewe estimate and bracketed
    by bisection; K and E by the arithmetic-geometric mean. ``hamrock_brewe`` returns the
    approximation of :func:`hamrock_brewe`.

    Parameters
    ----------
    f_rho : float or array
        Curvature difference [-], in [0, 1).
    method : {"exact", "hamrock_brewe"}
    max_iter : int
        Iteration cap of the exact solve.

    Returns
    -------
    kappa, K, E : arrays
        Ellipticity [-] and the complete elliptic integrals of the first and second kind.

    Examples
    --------
    >>> kappa, k, e = ellipticity(0.9)
    >>> round(float(kappa), 4)
    6.7133
    """
    f_target = np.asarray(f_rho, dtype=float)
    if np.any(~np.isfinite(f_target)) or np.any(f_target < 0.0) or np.any(f_target >= 1.0):
        bad = f_target[~((f_target >= 0.0) & (f_target < 1.0))].ravel()[0]
        raise ValueError(f"curvature difference F(rho) = {float(bad)!r}: must lie in [0, 1)")
    if method == "hamrock_brewe":
        return hamrock_brewe(f_target)
    if method != "exact":
        raise ValueError(f"method = {method!r}: must be 'exact' or 'hamrock_brewe'")
    kappa, k_int, e_int = _ellipticity_exact(np.ascontiguousarray(f_target.ravel()), max_iter)
    shape = f_target.shape
    return kappa.reshape(shape), k_int.reshape(shape), e_int.reshape(shape)


def hamrock_brewe(f_rho):
    """Hamrock-Brewe approximation of kappa, K and E (an approximation, not exact).

    Hamrock & Brewe, "Simplified solution for stresses and deformations", J. Lubr. Technol.
    105 (1983) 171-177: with alpha_r = Ry/Rx = (1 + F)/(1 - F),
    kappa = alpha_r^(2/pi), E = 1 + (pi/2 - 1)/alpha_r, K = pi/2 + (pi/2 - 1) ln(alpha_r).

    Examples
    --------
    >>> kappa, k, e = hamrock_brewe(0.9)
    >>> round(float(kappa), 3)
    6.517
    """
    f = np.asarray(f_rho, dtype=float)
    ratio = (1.0 + f) / (1.0 - f)
    q = _HALF_PI - 1.0
    return ratio ** (2.0 / np.pi), _HALF_PI + q * np.log(ratio), 1.0 + q / ratio


def point_contact(load, sum_rho, f_rho, compliance, method="exact"):
    """Hertz point contact: semi-axes, approach, max stress and load-deflection constant.

    With s = (3 Q eta / (2 sum_rho))^(1/3) (source paper Eq. 4-5; Harris Eq. 6.38-6.39):
    a = a* s, b = b* s, a* = (2 kappa^2 E / pi)^(1/3), b* = (2 E / (pi kappa))^(1/3);
    delta = (delta*/2) s^2 sum_rho with delta* = 2K/(pi a*) (Harris Eq. 6.40-6.43; the source
    paper's Eq. 6 prints the compliance unsquared inside the cube root, a misprint: its own
    Eq. 7, the steel form 2.79e-4 delta* Q^(2/3) sum_rho^(1/3), needs it squared);
    sigma_max = 3Q/(2 pi a b) (Eq. 8); K = Q / delta^1.5.

    Parameters
    ----------
    load : float or array
        Contact load Q [N], >= 0. Zero gives a zero ellipse, zero approach and zero stress.
    sum_rho : float or array
        Curvature sum [1/m], > 0.
    f_rho : float or array
        Curvature difference [-].
    compliance : float or array
        eta = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 [1/Pa].
    method : {"exact", "hamrock_brewe"}
        How the ellipticity and elliptic integrals are found.

    Returns
    -------
    PointContact

    Examples
    --------
    >>> s, f = ball_raceway_curvature(6e-3, 25.5e-3, 0.52, 0.0, "inner")
    >>> c = point_contact(1000.0, s, f, 2 * (1 - 0.3**2) / 207e9)
    >>> round(float(c.max_stress) / 1e6, 1)
    3154.2
    """
    q = np.asarray(load, dtype=float)
    if np.any(q < 0.0) or np.any(~np.isfinite(q)):
        bad = q[~(q >= 0.0) | ~np.isfinite(q)].ravel()[0]
        raise ValueError(f"contact load = {float(bad)!r} N: must be >= 0 and finite")
    kappa, k_int, e_int = ellipticity(f_rho, method)
    a_star = np.cbrt(2.0 * kappa**2 * e_int / np.pi)
    b_star = np.cbrt(2.0 * e_int / (np.pi * kappa))
    delta_star = 2.0 * k_int / (np.pi * a_star)
    scale = np.cbrt(1.5 * q * compliance / sum_rho)
    a = a_star * scale
    b = b_star * scale
    approach = 0.5 * delta_star * scale**2 * sum_rho
    area = a * b
    with np.errstate(invalid="ignore", divide="ignore"):
        stress = np.where(area > 0.0, 1.5 * q / (np.pi * np.where(area > 0.0, area, 1.0)), 0.0)
    stiffness = load_deflection_constant(sum_rho, compliance, kappa, k_int, e_int)
    return PointContact(a, b, approach, stress, kappa * np.ones_like(a), stiffness * np.ones_like(a))


def load_deflection_constant(sum_rho, compliance, kappa, k_int, e_int):
    """K in Q = K delta^1.5 for a point contact [N/m^1.5] (Harris & Kotzalas 2007, Eq. 7.2).

    From delta = (delta*/2) (3 Q eta / (2 sum_rho))^(2/3) sum_rho:
    K = [(delta*/2)^(3/2) (3 eta / 2) sum_rho^(1/2)]^(-1).
    """
    a_star = np.cbrt(2.0 * kappa**2 * e_int / np.pi)
    delta_star = 2.0 * k_int / (np.pi * a_star)
    return 1.0 / ((0.5 * delta_star) ** 1.5 * 1.5 * compliance * np.sqrt(sum_rho))


def stress_coefficient(sum_rho, f_rho, compliance, method="exact"):
    """C in sigma_max = C Q^(1/3) [Pa/N^(1/3)]: Eq. 8 with Eq. 4-5, since a, b ~ Q^(1/3)."""
    kappa, _, e_int = ellipticity(f_rho, method)
    a_star = np.cbrt(2.0 * kappa**2 * e_int / np.pi)
    b_star = np.cbrt(2.0 * e_int / (np.pi * kappa))
    return 1.5 / (np.pi * a_star * b_star * np.cbrt(1.5 * compliance / sum_rho) ** 2)


def series_constant(k_inner, k_outer):
    """Combined constant of two contacts in series, Q = K_b delta^1.5 (source paper Eq. 15).

    K_b = K_i K_o / (K_i^(2/3) + K_o^(2/3))^(3/2), since the approaches add
    (Harris & Kotzalas 2007, Eq. 7.4).

    Examples
    --------
    >>> round(float(series_constant(1.0, 1.0)), 6)
    0.353553
    """
    k_i = np.asarray(k_inner, float)
    k_o = np.asarray(k_outer, float)
    return k_i * k_o / (k_i ** (2.0 / 3.0) + k_o ** (2.0 / 3.0)) ** 1.5


#: Palmgren's line-contact approach for steel, delta = 3.84e-5 Q^0.9 / l^0.8 (delta, l in mm,
#: Q in N): Palmgren, *Ball and Roller Bearing Engineering*, 3rd ed. (1959); Harris & Kotzalas
#: (2007) Eq. 6.51 and Eq. 7.3. Its steel has E = 207 GPa, nu = 0.3 for both bodies.
PALMGREN_COEFFICIENT_MM = 3.84e-5
PALMGREN_REFERENCE_COMPLIANCE = 2.0 * (1.0 - 0.3**2) / 207e9


def line_contact_constant(length, compliance=PALMGREN_REFERENCE_COMPLIANCE):
    """K_l in Q = K_l delta^(10/9) for a line contact of length ``length`` [N/m^(10/9)].

    Inverts Palmgren's delta = 3.84e-5 Q^0.9 / l^0.8 (mm, N; Harris & Kotzalas 2007 Eq. 6.51)
    in SI. Other materials scale with the compliance as (eta/eta_steel)^0.9, the dependence
    that Palmgren's form delta ~ (Q / (E' l))^0.9 l^0.1 implies dimensionally.

    Parameters
    ----------
    length : float or array
        Effective contact length l [m].
    compliance : float or array
        eta = (1 - nu1^2)/E1 + (1 - nu2^2)/E2 [1/Pa].

    Examples
    --------
    >>> f"{float(line_contact_constant(11e-3)):.4g}"  # the source paper's K_l is 1.468e9
    '1.463e+09'
    """
    ratio = np.asarray(compliance, float) / PALMGREN_REFERENCE_COMPLIANCE
    # delta [m] = 1e-3 * c (Q^0.9) (1e3 l)^-0.8 ratio^0.9
    coefficient = 1e-3 * PALMGREN_COEFFICIENT_MM * 1e3**-0.8 * ratio**0.9
    return (np.asarray(length, float) ** 0.8 / coefficient) ** (10.0 / 9.0)


# ----------------------------------------------------------------------------- a journal in its bore
# A journal of radius R1 in a bore of radius R2 = R1 + dR (plane strain, frictionless, both bodies of one
# material) is a conformal contact: past a few degrees of contact the Hertz half-space law (Johnson 1985,
# Eq. 4.43 with the conformal radius R1 R2 / dR) over-predicts the contact width and under-predicts the peak
# pressure. The problem is Persson's (A. Persson, PhD thesis, Chalmers, 1964); Ciavarella & Decuzzi,
# Int. J. Solids Struct. 38 (2001) 4507-4523, give its elementary closed form for elastic similarity. Our
# closed forms below follow that route (the pressure expanded in Fourier modes around the bore, mode n >= 2
# of radial compliance (2R/E*) n/(n^2 - 1) and mode 0 of R/E*, the contact condition reduced with
# x = tan(theta/2) to a Cauchy singular integral equation and inverted); they reduce to Hertz at small
# angles and are checked against a direct numerical solution of the mode equations
# (tests/consistency/test_conformal_contact.py). With b = tan(eps/2), eps the contact half-angle:
#
#   P / (E* dR) = pi b^2 (1 + b^2) / (1 - b^4 - ln(1 + b^2) / 2)                                  (C1)
#   p_max R / (E* dR) = [cos^4(eps/2) artanh(sin(eps/2)) + 2 sin^3(eps/2)] / D(eps),
#   D(eps) = cos(eps) + cos^4(eps/2) ln cos(eps/2)                                                  (C2)
#
# with P the load per unit length and 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2. The contact never passes
# eps_lim = 84.83 deg (D = 0): as the load grows the peak pressure tends to 0.5996 P / R, linear in P where
# Hertz's grows as sqrt(P).

#: tan(eps_lim / 2), where the denominator of (C1) vanishes: the contact half-angle's limit at infinite load.
CONFORMAL_LIMIT_B = 0.9135733


@njit(cache=True)
def conformal_load(half_angle):
    """Load per unit length over E* dR of a journal in its bore at contact half-angle eps, Eq. (C1) above [-].

    Parameters
    ----------
    half_angle : float
        eps [rad], in [0, 84.83 deg).

    Examples
    --------
    >>> round(conformal_load(math.radians(60.0)), 6)  # (4 pi / 9) / (8/9 - ln(4/3) / 2)
    1.874059
    >>> round(conformal_load(0.01) / (math.pi * 0.01**2 / 4.0), 3)  # Hertz at small angles
    1.0
    """
    b2 = math.tan(0.5 * half_angle) ** 2
    return math.pi * b2 * (1.0 + b2) / (1.0 - b2 * b2 - 0.5 * math.log1p(b2))


@njit(cache=True)
def conformal_peak_pressure(half_angle):
    """Peak contact pressure times R over E* dR at contact half-angle eps, Eq. (C2) above [-].

    Examples
    --------
    >>> round(conformal_peak_pressure(math.radians(60.0)), 5)
    1.33381
    >>> round(conformal_peak_pressure(0.01) / 0.005, 3)  # Hertz p0 = E* dR eps / (2 R) at small angles
    1.0
    """
    c = math.cos(0.5 * half_angle)
    sn = math.sin(0.5 * half_angle)
    c4 = c**4
    return (c4 * math.atanh(sn) + 2.0 * sn**3) / (math.cos(half_angle) + c4 * math.log(c))


@njit(cache=True)
def conformal_half_angle(load_ratio):
    """Contact half-angle eps [rad] at a load per unit length P = load_ratio E* dR (inverts Eq. C1).

    Bisection on b = tan(eps/2) in (0, :data:`CONFORMAL_LIMIT_B`), where (C1) rises monotonically from 0 to
    infinity; 80 halvings.

    Examples
    --------
    >>> round(math.degrees(conformal_half_angle(1.0)), 3)
    50.424
    """
    if load_ratio <= 0.0:
        return 0.0
    lo, hi = 0.0, CONFORMAL_LIMIT_B
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        if conformal_load(2.0 * math.atan(mid)) < load_ratio:
            lo = mid
        else:
            hi = mid
    return 2.0 * math.atan(0.5 * (lo + hi))


@njit(cache=True)
def journal_contact(force, length, compliance, clearance, radius):
    """Contact half-angle [rad] and peak pressure [Pa] of a journal pressed into its bore (Eq. C1, C2 above).

    Parameters
    ----------
    force : float
        Contact force [N], spread evenly over ``length`` [m].
    compliance : float
        (1 - nu1^2)/E1 + (1 - nu2^2)/E2 [1/Pa].
    clearance, radius : float
        Radial clearance dR and journal radius R [m].

    Examples
    --------
    >>> eps, p = journal_contact(21.7e3, 18e-3, 2 * (1 - 0.3**2) / 207e9, 0.15e-3, 19.85e-3)
    >>> round(math.degrees(eps), 1), round(p / 1e6)  # the heavy example rotor's journal at 21.7 kN
    (16.8, 133)
    """
    if force <= 0.0:
        return 0.0, 0.0
    scale = clearance / compliance  # E* dR [N/m]
    eps = conformal_half_angle(force / length / scale)
    return eps, conformal_peak_pressure(eps) * scale / radius


@njit(cache=True)
def journal_force_at_pressure(pressure, length, compliance, clearance, radius):
    """Contact force [N] at which the journal contact's peak pressure reaches ``pressure`` [Pa] (Eq. C1, C2).

    The peak pressure rises monotonically with the load (to infinity as eps tends to its limit), so the
    force is found by bisection on b = tan(eps/2).

    Examples
    --------
    >>> c = 2 * (1 - 0.3**2) / 207e9
    >>> f = journal_force_at_pressure(4000e6, 18e-3, c, 0.15e-3, 19.85e-3)
    >>> round(journal_contact(f, 18e-3, c, 0.15e-3, 19.85e-3)[1] / 1e6, 3)
    4000.0
    """
    scale = clearance / compliance
    target = pressure * radius / scale
    lo, hi = 0.0, CONFORMAL_LIMIT_B
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        if conformal_peak_pressure(2.0 * math.atan(mid)) < target:
            lo = mid
        else:
            hi = mid
    return conformal_load(2.0 * math.atan(0.5 * (lo + hi))) * scale * length
