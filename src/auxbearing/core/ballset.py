"""THE ball-set force model: inner-ring displacement -> pair loads, contact angles, resultant.

One model serves the static load distribution (:mod:`auxbearing.core.static`) and the rotor
drop. It is the source paper's Sec. II.C (Eq. 9-16), which is Harris & Kotzalas, *Rolling
Bearing Analysis*, 5th ed. (2007), Advanced Concepts, Ch. 1 ("ball bearings under combined
load", Eq. 1.27-1.39 in the rigid-ring, no-centrifugal form), generalised to 5 DOF:

* DOF vector ``u = (delta_a, dx, dy, theta_x, theta_y)`` [m, m, m, rad, rad]: inner ring
  relative to outer ring, axial (+z), radial, and small tilts about +x and +y (right hand).
* Load vector ``(Fa, Fx, Fy, Mx, My)`` [N, N, N, N m, N m], energy-conjugate to ``u``.
* Ball j sits at azimuth phi_j = 2 pi j / Z from +x. Contact pair k has the axial sign s_k of
  :attr:`BearingGeometry.axial_signs` (four-point (+1, -1), angular contact (+1,), deep groove (0,)).
* Curvature-centre offset of pair k of ball j (source paper Eq. 10-11 with clearance):
  ``a = s_k A sin(alpha0) + delta_a + r_ic (theta_x sin phi - theta_y cos phi)``,
  ``r = A cos(alpha0) - Pd/2 + dx cos phi + dy sin phi``, ``S = sqrt(a^2 + r^2)``,
  A = (fi + fo - 1) D (Eq. 9). Compression delta = S - A, evaluated as (S^2 - A^2)/(S + A)
  without cancellation; Q = K_b(alpha) delta^1.5 for
  delta > 0, else 0 (a pair never pulls). Loaded contact angle alpha = atan2(sigma_k a, r)
  with sigma_k = s_k (or +1 for s_k = 0), so both four-point pairs read positive at rest like
  alpha_1, alpha_2 of Eq. 12-13.
* Force of the pair ON the inner ring: -Q (a/S) along z, -Q (r/S) along the ball's radial
  direction. Moment arm: **r_ic = bearing.inner_curvature_centre_radius** (Harris's choice,
  dm/2 + (fi - 1/2) D cos(alpha0)), used both in the tilt kinematics and in the moments, so
  forces and displacements are energy-conjugate. The source paper's 0.5 dm differs by
  about 1 %.
* The paper's planar (Fa, Fr, M) case is Fx = Fr, Fy = Mx = 0, My = -M: its Eq. 10 adds
  r_ic theta cos(phi) to pair 1, which is theta = -theta_y here.

K_b(alpha) (source paper Eq. 15 from Hertz K_i, K_o of :mod:`auxbearing.core.hertz`) and the
stress coefficients C_i(alpha), C_o(alpha) with sigma_max = C Q^(1/3) (source paper Eq. 4-8)
depend on the loaded contact angle through gamma = D cos(alpha) / dm. They are tabulated at
build time on |alpha| in [0, 90] deg, :data:`TABLE_POINTS` nodes, and read with cubic Hermite
interpolation (values and slopes at the nodes; slopes by central differences of the exact
Hertz solution), so the kernels have a continuous derivative for the Newton Jacobian. Measured
interpolation error against the exact Hertz solution at the mid-points between nodes
(QJ202): below 1e-13 relative for K_b and the stress coefficients (tests/unit/test_ballset.py
asserts < 1e-9).

All kernels take SI floats; ``params`` is the packed array of :func:`kernel_params`.
"""

from __future__ import annotations

import math
from functools import lru_cache
from typing import NamedTuple

import numba
import numpy as np

from auxbearing.bearing import BearingGeometry
from auxbearing.core import hertz

#: Nodes of the Hertz tables over |alpha| in [0, pi/2] (0.125 deg spacing).
TABLE_POINTS = 721
_TABLE_MAX = 0.5 * math.pi
_FD_STEP = 1e-5  # [rad] central-difference step for the node slopes (error ~ h^2 ~ 1e-10)

# Header layout of the packed parameter array (append new slots at the end: compiled callers
# cached by numba elsewhere keep reading the old slots).
_Z, _NP, _A, _ALPHA0, _PD, _RIC, _NT, _H, _SIGNS, _AZIM, _TAB, _COS, _SIN, _HEADER = range(14)
#: Order of the six tables after the header: K_b, dK_b, C_i, dC_i, C_o, dC_o.
_N_TABLES = 6

DOF_NAMES = ("axial", "x", "y", "tilt_x", "tilt_y")
LOAD_NAMES = ("Fa", "Fx", "Fy", "Mx", "My")


def _exact_tables(bearing: BearingGeometry, alpha: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """K_b, C_i, C_o at contact angles ``alpha`` from the exact Hertz solution."""
    eta = bearing.contact_compliance
    d, dm = bearing.ball_diameter, bearing.pitch_diameter
    s_i, f_i = hertz.ball_raceway_curvature(d, dm, bearing.inner_groove_ratio, alpha, "inner")
    s_o, f_o = hertz.ball_raceway_curvature(d, dm, bearing.outer_groove_ratio, alpha, "outer")
    k_i = hertz.point_contact(0.0, s_i, f_i, eta).stiffness
    k_o = hertz.point_contact(0.0, s_o, f_o, eta).stiffness
    k_b = hertz.series_constant(k_i, k_o)
    c_i = hertz.stress_coefficient(s_i, f_i, eta)
    c_o = hertz.stress_coefficient(s_o, f_o, eta)
    return np.asarray(k_b, float), np.asarray(c_i, float), np.asarray(c_o, float)


def hertz_tables(bearing: BearingGeometry) -> tuple[np.ndarray, ...]:
    """Tables of K_b and the stress coefficients against contact angle, with their slopes.

    Parameters
    ----------
    bearing : BearingGeometry

    Returns
    -------
    alpha, k_b, dk_b, c_i, dc_i, c_o, dc_o : arrays
        Node angles [rad]; K_b [N/m^1.5] (source paper Eq. 15) and d K_b / d alpha; inner and
        outer stress coefficients C [Pa/N^(1/3)] with sigma_max = C Q^(1/3) (Eq. 4-8) and slopes.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> alpha, kb, *_ = hertz_tables(get_bearing("QJ202"))
    >>> f"{np.interp(np.radians(35.0), alpha, kb):.4e}"
    '8.0514e+09'
    """
    alpha = np.linspace(0.0, _TABLE_MAX, TABLE_POINTS)
    mid = _exact_tables(bearing, alpha)
    plus = _exact_tables(bearing, alpha + _FD_STEP)
    minus = _exact_tables(bearing, alpha - _FD_STEP)
    out = [alpha]
    for value, hi, lo in zip(mid, plus, minus, strict=True):
        out += [value, (hi - lo) / (2.0 * _FD_STEP)]
    return tuple(out)


@lru_cache(maxsize=64)
def _cached_params(bearing: BearingGeometry, ball_constant: float | None) -> np.ndarray:
    _, k_b, dk_b, c_i, dc_i, c_o, dc_o = hertz_tables(bearing)
    if ball_constant is not None:
        k_b = np.full_like(k_b, ball_constant)
        dk_b = np.zeros_like(dk_b)
    z = bearing.ball_count
    signs = np.asarray(bearing.axial_signs, float)
    header = np.zeros(_HEADER)
    header[_Z] = z
    header[_NP] = signs.size
    header[_A] = bearing.curvature_centre_distance
    header[_ALPHA0] = bearing.contact_angle
    header[_PD] = bearing.diametral_clearance
    header[_RIC] = bearing.inner_curvature_centre_radius
    header[_NT] = TABLE_POINTS
    header[_H] = _TABLE_MAX / (TABLE_POINTS - 1)
    header[_SIGNS] = _HEADER
    header[_AZIM] = _HEADER + signs.size
    header[_COS] = _HEADER + signs.size + z
    header[_SIN] = _HEADER + signs.size + 2 * z
    header[_TAB] = _HEADER + signs.size + 3 * z
    azimuths = 2.0 * np.pi * np.arange(z) / z
    params = np.concatenate([header, signs, azimuths, np.cos(azimuths), np.sin(azimuths),
                             k_b, dk_b, c_i, dc_i, c_o, dc_o])
    params.setflags(write=False)
    return params


def kernel_params(bearing: BearingGeometry, ball_constant: float | None = None) -> np.ndarray:
    """Float64 1-D array packing everything the compiled ball-set kernels need.

    Layout: a header (Z, pairs per ball, A [m], alpha0 [rad], Pd [m], r_ic [m], table size,
    table step [rad], offsets), the pair axial signs, the ball azimuths [rad] with their
    cosines and sines (so the kernels need no trigonometry per ball), then six
    tables over |alpha| in [0, 90] deg: K_b (source paper Eq. 15 via Hertz Eq. 6) and the
    inner and outer stress coefficients of sigma_max = C(alpha) Q^(1/3) (Eq. 4-8), each
    followed by its slope d/d alpha.

    Parameters
    ----------
    bearing : BearingGeometry
    ball_constant : float, optional
        K_b [N/m^1.5] to use at every contact angle instead of the Hertz value (stresses
        still come from Hertz).

    Returns
    -------
    numpy.ndarray
        Read-only packed parameters (cached per bearing).

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> p = kernel_params(get_bearing("QJ202"))
    >>> int(p[0]), int(p[1]), round(float(p[2]) * 1e3, 4)
    (11, 2, 0.24)
    """
    if ball_constant is not None:
        ball_constant = float(ball_constant)
        if not math.isfinite(ball_constant) or ball_constant <= 0.0:
            raise ValueError(f"ball_constant = {ball_constant!r} N/m^1.5: must be > 0 and finite")
    return _cached_params(bearing, ball_constant)


# --------------------------------------------------------------------------- compiled kernels
@numba.njit(cache=True)
def _table(params, which, x):
    """Cubic Hermite value and slope of table ``which`` (0 K_b, 1 C_i, 2 C_o) at |alpha| = x."""
    n = int(params[_NT])
    h = params[_H]
    base = int(params[_TAB]) + 2 * which * n
    if x <= 0.0:
        x = 0.0
    top = (n - 1) * h
    if x >= top:
        return params[base + n - 1], 0.0
    i = int(x / h)
    if i > n - 2:
        i = n - 2
    t = (x - i * h) / h
    y0 = params[base + i]
    y1 = params[base + i + 1]
    m0 = params[base + n + i] * h
    m1 = params[base + n + i + 1] * h
    t2 = t * t
    t3 = t2 * t
    value = (2.0 * t3 - 3.0 * t2 + 1.0) * y0 + (t3 - 2.0 * t2 + t) * m0 + (3.0 * t2 - 2.0 * t3) * y1 + (t3 - t2) * m1
    slope = ((6.0 * t2 - 6.0 * t) * y0 + (3.0 * t2 - 4.0 * t + 1.0) * m0 + (6.0 * t - 6.0 * t2) * y1
             + (3.0 * t2 - 2.0 * t) * m1) / h
    return value, slope


@numba.njit(cache=True)
def _pair(sign, axial, radial, params, with_stress=True):
    """One contact pair: (a, r, S, delta, Q, alpha, dQ/da, dQ/dr, sigma_inner, sigma_outer).

    ``axial`` and ``radial`` are the ring's displacement at the ball [m]. S - A is formed as
    (S^2 - A^2) / (S + A) with S^2 - A^2 expanded in the displacements, so a compression of
    a few femtometres keeps full relative precision (S - A itself would cancel to ulp(A)).
    """
    big_a = params[_A]
    cos0 = math.cos(params[_ALPHA0])
    pd = params[_PD]
    a0 = sign * big_a * math.sin(params[_ALPHA0])
    r0 = big_a * cos0 - 0.5 * pd
    a = a0 + axial
    r = r0 + radial
    s_len = math.sqrt(a * a + r * r)
    # (s a0)^2 + r0^2 - A^2 = Pd (Pd/4 - A cos(alpha0)) exactly (a0 = 0 only when alpha0 = 0)
    excess = pd * (0.25 * pd - big_a * cos0) + axial * (2.0 * a0 + axial) + radial * (2.0 * r0 + radial)
    delta = excess / (s_len + big_a)
    sigma = sign if sign != 0.0 else 1.0
    alpha = math.atan2(sigma * a, r)
    if delta <= 0.0:
        return a, r, s_len, delta, 0.0, alpha, 0.0, 0.0, 0.0, 0.0
    x = abs(alpha)
    k, dk = _table(params, 0, x)
    if alpha < 0.0:
        dk = -dk
    root = math.sqrt(delta)
    q = k * delta * root
    inv2 = 1.0 / (s_len * s_len)
    dalpha_da = sigma * r * inv2
    dalpha_dr = -sigma * a * inv2
    dq_da = dk * dalpha_da * delta * root + 1.5 * k * root * a / s_len
    dq_dr = dk * dalpha_dr * delta * root + 1.5 * k * root * r / s_len
    if not with_stress:
        return a, r, s_len, delta, q, alpha, dq_da, dq_dr, 0.0, 0.0
    cube = q ** (1.0 / 3.0)
    c_i, _ = _table(params, 1, x)
    c_o, _ = _table(params, 2, x)
    return a, r, s_len, delta, q, alpha, dq_da, dq_dr, c_i * cube, c_o * cube


@numba.njit(cache=True)
def accumulate(disp, params, force, jac, with_jac, with_stress=True):
    """Add the ball-set resultant (and its Jacobian) at ``disp`` into ``force`` and ``jac``.

    Allocation-free core of :func:`ballset_forces` for solvers (zero the outputs first).
    Returns (max_load [N], max_stress [Pa]); max_stress is 0 when ``with_stress`` is False.
    """
    z = int(params[_Z])
    n_pairs = int(params[_NP])
    ric = params[_RIC]
    max_load = 0.0
    max_stress = 0.0
    for j in range(z):
        cphi = params[int(params[_COS]) + j]
        sphi = params[int(params[_SIN]) + j]
        # d(axial)/d(disp) = ga, d(radial)/d(disp) = gr
        ga3 = ric * sphi
        ga4 = -ric * cphi
        axial = disp[0] + ga3 * disp[3] + ga4 * disp[4]
        radial = disp[1] * cphi + disp[2] * sphi
        for k in range(n_pairs):
            sign = params[int(params[_SIGNS]) + k]
            a, r, s_len, _, q, _, dq_da, dq_dr, sig_i, sig_o = _pair(sign, axial, radial, params, with_stress)
            if q <= 0.0:
                continue
            sn = a / s_len
            cs = r / s_len
            fz = -q * sn
            fr = -q * cs
            force[0] += fz
            force[1] += fr * cphi
            force[2] += fr * sphi
            force[3] += fz * ga3
            force[4] += fz * ga4
            if with_jac:
                dfz_da = -(dq_da * sn + q * cs * cs / s_len)
                dfz_dr = -(dq_dr * sn - q * sn * cs / s_len)
                dfr_da = -(dq_da * cs - q * sn * cs / s_len)
                dfr_dr = -(dq_dr * cs + q * sn * sn / s_len)
                ga = (1.0, 0.0, 0.0, ga3, ga4)
                gr = (0.0, cphi, sphi, 0.0, 0.0)
                for m in range(5):
                    wz = dfz_da * ga[m] + dfz_dr * gr[m]
                    wr = dfr_da * ga[m] + dfr_dr * gr[m]
                    for n in range(5):
                        jac[n, m] += ga[n] * wz + gr[n] * wr
            if q > max_load:
                max_load = q
            if sig_i > max_stress:
                max_stress = sig_i
            if sig_o > max_stress:
                max_stress = sig_o
    return max_load, max_stress


@numba.njit(cache=True)
def ballset_forces(disp, params):
    """Compiled 5-DOF scalar form: resultant on the inner ring, its Jacobian, max load and stress.

    Source paper Eq. 10-16 generalised to 5 DOF (module docstring); same numbers as the
    vectorised :func:`ballset_state`.

    Parameters
    ----------
    disp : ndarray, shape (5,)
        (delta_a, dx, dy, theta_x, theta_y) [m, m, m, rad, rad] of the inner ring.
    params : ndarray
        :func:`kernel_params`.

    Returns
    -------
    force : ndarray, shape (5,)
        (Fa, Fx, Fy, Mx, My) the ball set exerts ON the inner ring [N, N m] (source paper
        Eq. 14/16 with the sign of a reaction).
    jac : ndarray, shape (5, 5)
        d force / d disp (analytic; minus the stiffness matrix).
    max_load : float
        Largest contact-pair load [N].
    max_stress : float
        Largest Hertz max stress of any contact, inner or outer race [Pa].
    """
    force = np.zeros(5)
    jac = np.zeros((5, 5))
    max_load, max_stress = accumulate(disp, params, force, jac, True)
    return force, jac, max_load, max_stress


@numba.njit(cache=True)
def radial_support(dx: float, dy: float, params: np.ndarray) -> tuple[float, float, float, float]:
    """Radial force of the ball set on an axially located, untilted inner ring (drop model).

    The same pair model as :func:`ballset_forces` with delta_a = theta_x = theta_y = 0
    (source paper Eq. 22 read as NOTES.md item 4: the radial force of the ball set).

    Parameters
    ----------
    dx, dy : float
        Inner ring displacement relative to the outer ring [m].
    params : ndarray
        :func:`kernel_params`.

    Returns
    -------
    fx, fy : float
        Force the ball set exerts ON the inner ring [N]; restoring.
    max_ball_load : float
        Largest contact-pair load [N].
    max_stress : float
        Largest Hertz max stress of any ball contact, inner or outer race [Pa].

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> fx, fy, q, s = radial_support(10e-6, 0.0, kernel_params(get_bearing("QJ202")))
    >>> fx < 0.0, abs(fy) < 1e-9 * abs(fx)
    (True, True)
    """
    z = int(params[_Z])
    n_pairs = int(params[_NP])
    fx = 0.0
    fy = 0.0
    max_load = 0.0
    max_stress = 0.0
    for j in range(z):
        cphi = params[int(params[_COS]) + j]
        sphi = params[int(params[_SIN]) + j]
        radial = dx * cphi + dy * sphi
        for k in range(n_pairs):
            sign = params[int(params[_SIGNS]) + k]
            _, r, s_len, _, q, _, _, _, sig_i, sig_o = _pair(sign, 0.0, radial, params)
            if q <= 0.0:
                continue
            fr = -q * r / s_len
            fx += fr * cphi
            fy += fr * sphi
            if q > max_load:
                max_load = q
            if sig_i > max_stress:
                max_stress = sig_i
            if sig_o > max_stress:
                max_stress = sig_o
    return fx, fy, max_load, max_stress


@numba.njit(cache=True)
def radial_force(dx: float, dy: float, params: np.ndarray) -> tuple[float, float, float]:
    """Force-only form of :func:`radial_support` for the drop right-hand side.

    Same pair model and same numbers (source paper Eq. 10-13 and 22 at zero axial and tilt
    displacement), but no stresses and no derivatives, and the contact angle and K_b(alpha)
    are evaluated only for compressed pairs: in a drop most balls are unloaded, and the
    right-hand side is called some 10^5 times per drop.

    Returns
    -------
    fx, fy : float
        Force the ball set exerts ON the inner ring [N].
    max_ball_load : float
        Largest contact-pair load [N].

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> p = kernel_params(get_bearing("QJ202"))
    >>> fx, fy, q = radial_force(10e-6, 3e-6, p)
    >>> fx2, fy2, q2, _ = radial_support(10e-6, 3e-6, p)
    >>> abs(fx - fx2) <= 1e-12 * abs(fx2), abs(fy - fy2) <= 1e-12 * abs(fy2), q == q2
    (True, True, True)
    """
    z = int(params[_Z])
    n_pairs = int(params[_NP])
    big_a = params[_A]
    cos0 = math.cos(params[_ALPHA0])
    sin0 = math.sin(params[_ALPHA0])
    pd = params[_PD]
    r0 = big_a * cos0 - 0.5 * pd
    base_excess = pd * (0.25 * pd - big_a * cos0)  # (s a0)^2 + r0^2 - A^2, as in _pair
    cos_at = int(params[_COS])
    sin_at = int(params[_SIN])
    signs_at = int(params[_SIGNS])
    fx = 0.0
    fy = 0.0
    max_load = 0.0
    for j in range(z):
        cphi = params[cos_at + j]
        sphi = params[sin_at + j]
        radial = dx * cphi + dy * sphi
        excess = base_excess + radial * (2.0 * r0 + radial)
        if excess <= 0.0:  # the radial move alone decides: no pair of this ball is compressed
            continue
        r = r0 + radial
        for k in range(n_pairs):
            sign = params[signs_at + k]
            a = sign * big_a * sin0
            s_len = math.sqrt(a * a + r * r)
            delta = excess / (s_len + big_a)
            sigma = sign if sign != 0.0 else 1.0
            k_b, _ = _table(params, 0, abs(math.atan2(sigma * a, r)))
            q = k_b * delta * math.sqrt(delta)
            fr = -q * r / s_len
            fx += fr * cphi
            fy += fr * sphi
            if q > max_load:
                max_load = q
    return fx, fy, max_load


# --------------------------------------------------------------------------- numpy form
class BallSetState(NamedTuple):
    """Ball-set state over displacement states ``(...)``, balls ``ball`` and pairs ``pair``."""

    distance: np.ndarray  #: S, loaded curvature-centre distance [m], (..., Z, P)
    compression: np.ndarray  #: S - A [m] (negative: pair open), (..., Z, P)
    load: np.ndarray  #: contact-pair load Q [N], (..., Z, P)
    contact_angle: np.ndarray  #: loaded contact angle [rad], (..., Z, P)
    stress_inner: np.ndarray  #: Hertz max stress at the inner race [Pa], (..., Z, P)
    stress_outer: np.ndarray  #: Hertz max stress at the outer race [Pa], (..., Z, P)
    force: np.ndarray  #: (Fa, Fx, Fy, Mx, My) ON the inner ring [N, N m], (..., 5)
    jacobian: np.ndarray  #: d force / d displacement, (..., 5, 5)


def unpack(params: np.ndarray) -> dict:
    """Header of :func:`kernel_params` as a mapping (SI): Z, signs, azimuths, A, alpha0, Pd, r_ic."""
    z = int(params[_Z])
    n_pairs = int(params[_NP])
    return {
        "ball_count": z,
        "signs": np.array(params[int(params[_SIGNS]): int(params[_SIGNS]) + n_pairs]),
        "azimuths": np.array(params[int(params[_AZIM]): int(params[_AZIM]) + z]),
        "curvature_centre_distance": float(params[_A]),
        "contact_angle": float(params[_ALPHA0]),
        "diametral_clearance": float(params[_PD]),
        "moment_arm": float(params[_RIC]),
    }


def _table_np(params: np.ndarray, which: int, x: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    n = int(params[_NT])
    h = params[_H]
    base = int(params[_TAB]) + 2 * which * n
    values = params[base: base + n]
    slopes = params[base + n: base + 2 * n]
    x = np.clip(x, 0.0, None)
    top = x >= (n - 1) * h
    i = np.minimum((x / h).astype(np.int64), n - 2)
    t = (x - i * h) / h
    y0, y1 = values[i], values[i + 1]
    m0, m1 = slopes[i] * h, slopes[i + 1] * h
    t2 = t * t
    t3 = t2 * t
    value = (2.0 * t3 - 3.0 * t2 + 1.0) * y0 + (t3 - 2.0 * t2 + t) * m0 + (3.0 * t2 - 2.0 * t3) * y1 + (t3 - t2) * m1
    slope = ((6.0 * t2 - 6.0 * t) * y0 + (3.0 * t2 - 4.0 * t + 1.0) * m0 + (6.0 * t - 6.0 * t2) * y1
             + (3.0 * t2 - 2.0 * t) * m1) / h
    return np.where(top, values[-1], value), np.where(top, 0.0, slope)


def ballset_state(displacement: np.ndarray, params: np.ndarray) -> BallSetState:
    """Vectorised ball-set model over many 5-DOF displacement states (source paper Eq. 10-16).

    Parameters
    ----------
    displacement : array_like, shape (..., 5)
        (delta_a, dx, dy, theta_x, theta_y) [m, m, m, rad, rad] of the inner ring.
    params : ndarray
        :func:`kernel_params`.

    Returns
    -------
    BallSetState
        Per ball and pair: S, compression, load, contact angle, inner/outer max stress;
        resultant on the ring and its analytic Jacobian. Same numbers as :func:`ballset_forces`.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> p = kernel_params(get_bearing("QJ202"))
    >>> st = ballset_state([0.0, 10e-6, 0.0, 0.0, 0.0], p)
    >>> st.load.shape, bool(np.allclose(st.load[0, 0], st.load[0, 1]))
    ((11, 2), True)
    """
    u = np.asarray(displacement, float)
    head = unpack(params)
    signs, phi, ric = head["signs"], head["azimuths"], head["moment_arm"]
    big_a = head["curvature_centre_distance"]
    a0 = big_a * math.sin(head["contact_angle"])
    r0 = big_a * math.cos(head["contact_angle"]) - 0.5 * head["diametral_clearance"]
    cphi, sphi = np.cos(phi), np.sin(phi)
    ud = u[..., None, :]
    axial = ud[..., 0] + ric * (ud[..., 3] * sphi - ud[..., 4] * cphi)
    d_radial = ud[..., 1] * cphi + ud[..., 2] * sphi
    radial = r0 + d_radial
    a = signs * a0 + axial[..., None]
    r = np.broadcast_to(radial[..., None], a.shape)
    s_len = np.sqrt(a * a + r * r)
    pd, cos0 = head["diametral_clearance"], math.cos(head["contact_angle"])
    excess = (pd * (0.25 * pd - big_a * cos0) + axial[..., None] * (2.0 * signs * a0 + axial[..., None])
              + (d_radial * (2.0 * r0 + d_radial))[..., None])
    delta = excess / (s_len + big_a)
    sigma = np.where(signs != 0.0, signs, 1.0)
    alpha = np.arctan2(sigma * a, r)
    x = np.abs(alpha)
    k, dk = _table_np(params, 0, x)
    dk = np.where(alpha < 0.0, -dk, dk)
    loaded = delta > 0.0
    root = np.sqrt(np.where(loaded, delta, 0.0))
    q = np.where(loaded, k * np.where(loaded, delta, 0.0) * root, 0.0)
    inv2 = 1.0 / (s_len * s_len)
    dq_da = np.where(loaded, dk * sigma * r * inv2 * delta * root + 1.5 * k * root * a / s_len, 0.0)
    dq_dr = np.where(loaded, -dk * sigma * a * inv2 * delta * root + 1.5 * k * root * r / s_len, 0.0)
    cube = np.cbrt(q)
    stress_i = _table_np(params, 1, x)[0] * cube
    stress_o = _table_np(params, 2, x)[0] * cube
    sn, cs = a / s_len, r / s_len
    fz, fr = -q * sn, -q * cs
    dfz_da = -(dq_da * sn + q * cs * cs / s_len)
    dfz_dr = -(dq_dr * sn - q * sn * cs / s_len)
    dfr_da = -(dq_da * cs - q * sn * cs / s_len)
    dfr_dr = -(dq_dr * cs + q * sn * sn / s_len)
    zero, one = np.zeros_like(phi), np.ones_like(phi)
    ga = np.stack([one, zero, zero, ric * sphi, -ric * cphi], axis=-1)  # (Z, 5)
    gr = np.stack([zero, cphi, sphi, zero, zero], axis=-1)
    fz_ball, fr_ball = fz.sum(-1), fr.sum(-1)  # (..., Z)
    force = fz_ball @ ga + fr_ball @ gr
    jac = (np.einsum("zn,...z,zm->...nm", ga, dfz_da.sum(-1), ga)
           + np.einsum("zn,...z,zm->...nm", ga, dfz_dr.sum(-1), gr)
           + np.einsum("zn,...z,zm->...nm", gr, dfr_da.sum(-1), ga)
           + np.einsum("zn,...z,zm->...nm", gr, dfr_dr.sum(-1), gr))
    return BallSetState(s_len, delta, q, alpha, stress_i, stress_o, force, jac)
