"""THE ball-set model: one compiled kernel per contact pair, and the ball-set sum built on it.

Statics (:mod:`auxbearing.core.statics`), the machine drop (:mod:`auxbearing.core.machine`), the
experiment pipeline and the array API all call :func:`pair`; nothing else evaluates the contact
law. The model is the source paper's Sec. II.C (Eq. 9-16), which is Harris & Kotzalas, *Rolling
Bearing Analysis*, 5th ed. (2007), Advanced Concepts, Ch. 1 (ball bearings under combined load,
Eq. 1.27-1.39 in the rigid-ring, no-centrifugal form), in 5 DOF:

* displacement ``u = (delta_a, dx, dy, theta_x, theta_y)`` [m, m, m, rad, rad] of the inner ring
  relative to the outer ring: axial (+z), radial, small tilts about +x and +y (right hand);
* load ``(Fa, Fx, Fy, Mx, My)`` [N, N, N, N m, N m], energy-conjugate to ``u``;
* ball j at azimuth phi_j = 2 pi j / Z from +x; contact pair k on the groove side s_k
  (four-point (+1, -1), angular contact (+1,), deep groove (0,));
* curvature-centre offsets of pair k of ball j (source paper Eq. 10-11 with clearance Pd):
  ``a = s_k A sin(alpha0) + delta_a + r_ic (theta_x sin phi - theta_y cos phi)``,
  ``r = A cos(alpha0) - Pd/2 + dx cos phi + dy sin phi``, ``S = sqrt(a^2 + r^2)``, A = (fi + fo - 1) D
  (Eq. 9). The compression delta = S - A is formed as (S^2 - A^2)/(S + A) with S^2 - A^2 expanded
  in the displacements, so a compression of femtometres keeps its relative precision;
* pair load Q = K_b(alpha) delta^1.5 for delta > 0, else 0 (a pair never pulls; Eq. 14-16), loaded
  contact angle alpha = atan2(sigma_k a, r) with sigma_k = s_k (+1 for s_k = 0) so both four-point
  pairs read positive at rest, like alpha_1, alpha_2 of Eq. 12-13;
* force of the pair ON the inner ring: -Q (a/S) along z and -Q (r/S) along the ball's radial line;
  moment arm r_ic (Harris's inner groove curvature-centre radius; the paper's 0.5 dm differs by
  about 1 %) in both the tilt kinematics and the moments, so force and displacement are conjugate.

K_b(alpha) (Eq. 15 from the Hertz K_i, K_o of :mod:`auxbearing.core.hertz`), the stress
coefficients with sigma_max = C(alpha) Q^(1/3) (Eq. 4-8) and the semi-major-axis coefficients with
a = c_a(alpha) Q^(1/3) (Eq. 4) depend on the loaded contact angle. They are tabulated on |alpha| in
[0, 90] deg with their slopes and read by cubic Hermite interpolation (:func:`table`), so the
Newton Jacobian is continuous. They depend on the angle through cos(alpha) alone (the rolling-plane
curvature of each raceway through gamma = D cos(alpha) / d_m, Harris & Kotzalas Eq. 2.27-2.33), so the
load, which needs K_b only, reads it from a second table on cos(alpha) = r/S in [0, 1]
(:func:`ball_constant`) and needs no arc tangent: the right-hand side of a drop evaluates some 10^6
loaded pairs. The tables are built outside the core (:func:`auxbearing.bearings.ballset.ballset_params`).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

#: Rows of :attr:`BallSet.tables`: ball constant, inner and outer stress coefficient, inner and
#: outer semi-major-axis coefficient.
K_B, STRESS_INNER, STRESS_OUTER, AXIS_INNER, AXIS_OUTER = range(5)
TABLE_NAMES = ("ball_constant", "stress_inner", "stress_outer", "semi_major_inner", "semi_major_outer")

DOF_NAMES = ("axial", "x", "y", "tilt_x", "tilt_y")
LOAD_NAMES = ("Fa", "Fx", "Fy", "Mx", "My")


class BallSet(NamedTuple):
    """One bearing's ball set, as the kernels see it (SI)."""

    signs: np.ndarray  #: (P,) groove side of each contact pair
    cos_azimuth: np.ndarray  #: (Z,) cos(phi_j)
    sin_azimuth: np.ndarray  #: (Z,) sin(phi_j)
    curvature_distance: float  #: A = (fi + fo - 1) D [m] (Eq. 9)
    free_angle: float  #: alpha0 [rad]
    cos_free_angle: float  #: cos(alpha0)
    sin_free_angle: float  #: sin(alpha0)
    clearance: float  #: diametral clearance Pd [m] at the reference temperature
    moment_arm: float  #: r_ic [m]
    table_step: float  #: node spacing of the tables [rad]
    tables: np.ndarray  #: (5, 2, n): value and slope d/d|alpha| of each table row on its nodes
    constant_step: float  #: node spacing of the K_b table on cos(alpha) [-]
    constant_table: np.ndarray  #: (2, n): K_b [N/m^1.5] and its slope d/d cos(alpha) on nodes 0, step, ..., 1


@njit(cache=True, inline="always")
def _interval(n, h, x):
    """Node interval i of ``x`` on the nodes 0, h, ..., (n - 1) h and its place t in [0, 1) there.

    Below 0, ``x`` reads the first node; at or beyond the last node, i = n - 1 (the tables are constant there).
    """
    if x <= 0.0:
        x = 0.0
    if x >= (n - 1) * h:
        return n - 1, 0.0
    i = min(int(x / h), n - 2)
    return i, (x - i * h) / h


@njit(cache=True, inline="always")
def _basis(t):
    """The cubic Hermite basis h00, h10, h01, h11 at the place t in [0, 1] of a node interval.

    Burden & Faires, *Numerical Analysis*, Sec. 3.4: p(t) = h00 y0 + h10 h m0 + h01 y1 + h11 h m1.
    """
    t2 = t * t
    t3 = t2 * t
    return 2.0 * t3 - 3.0 * t2 + 1.0, t3 - 2.0 * t2 + t, 3.0 * t2 - 2.0 * t3, t3 - t2


@njit(cache=True, inline="always")
def _combine(values, slopes, h, i, weights):
    """The Hermite interpolant on node interval i with the basis ``weights`` (:func:`_basis`)."""
    w0, w1, w2, w3 = weights
    return w0 * values[i] + w1 * (slopes[i] * h) + w2 * values[i + 1] + w3 * (slopes[i + 1] * h)


@njit(cache=True, inline="always")
def _hermite(values, slopes, h, x):
    """Cubic Hermite value and slope on nodes 0, h, 2h, ... at ``x``; constant beyond the last node and below 0."""
    n = values.size
    i, t = _interval(n, h, x)
    if i == n - 1:
        return values[n - 1], 0.0
    y0, y1 = values[i], values[i + 1]
    m0, m1 = slopes[i] * h, slopes[i + 1] * h
    t2 = t * t
    slope = ((6.0 * t2 - 6.0 * t) * y0 + (3.0 * t2 - 4.0 * t + 1.0) * m0 + (6.0 * t - 6.0 * t2) * y1
             + (3.0 * t2 - 2.0 * t) * m1) / h
    return _combine(values, slopes, h, i, _basis(t)), slope


@njit(cache=True, inline="always")
def table(bs, row, x):
    """Cubic Hermite value and slope of table ``row`` at |alpha| = ``x`` [rad]; constant beyond the last node.

    Examples
    --------
    >>> import numpy as np
    >>> nodes = np.linspace(0.0, 1.0, 3)
    >>> tab = np.zeros((5, 2, 3)); tab[0, 0] = nodes ** 2; tab[0, 1] = 2.0 * nodes
    >>> bs = BallSet(np.ones(1), np.ones(3), np.zeros(3), 1.0, 0.0, 1.0, 0.0, 0.0, 1.0, 0.5, tab, 0.5, tab[0])
    >>> [round(v, 12) for v in table(bs, 0, 0.3)]  # x^2 is reproduced exactly
    [0.09, 0.6]
    """
    return _hermite(bs.tables[row, 0], bs.tables[row, 1], bs.table_step, x)


@njit(cache=True, inline="always")
def ball_constant(bs, c):
    """K_b [N/m^1.5] and dK_b/d cos(alpha) at cos(alpha) = ``c`` (source paper Eq. 15; module docstring).

    A contact angle beyond 90 deg (c < 0) reads the value at 90 deg, as :func:`table` does.
    """
    return _hermite(bs.constant_table[0], bs.constant_table[1], bs.constant_step, c)


@njit(cache=True, inline="always")
def pair(sign, axial, radial, bs, pd, need_angle, with_angle):
    """THE contact-pair kernel: load and its derivatives for one ball's pair (Eq. 10-16).

    Parameters
    ----------
    sign : float
        Groove side s_k of the pair (+1, -1, or 0 for a single-arc deep groove).
    axial, radial : float
        Inner-ring displacement at the ball, along z and along the ball's radial line [m].
    bs : BallSet
    pd : float
        Diametral clearance [m] (the reference value plus any thermal change).
    need_angle : bool
        Also return the geometry of an open pair (arrays of contact angles); when False an open
        pair returns at once, before any square root.
    with_angle : bool
        Compute the contact angle of a loaded pair; the load and its derivatives do not need it, and a
        right-hand side that only sums forces saves the arc tangent (alpha is then 0). ``need_angle``
        implies it.

    Returns
    -------
    q : float
        Pair load Q = K_b(alpha) delta^1.5 [N], 0 when open.
    alpha : float
        Loaded contact angle [rad] (0 for an open pair when ``need_angle`` is False, and whenever neither
        ``need_angle`` nor ``with_angle`` is set).
    dq_da, dq_dr : float
        dQ/d(axial), dQ/d(radial) [N/m].
    a, r, s_len, delta : float
        Curvature-centre offsets, their distance S [m] and the compression S - A [m].

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> from auxbearing.bearings.ballset import ballset_params
    >>> bs = ballset_params(get_bearing("QJ202"))
    >>> q, alpha, *_ = pair(1.0, 0.0, 5e-6, bs, 0.0, False, True)
    >>> round(q, 3), round(math.degrees(alpha), 3)
    (67.147, 34.327)
    """
    big_a = bs.curvature_distance
    cos0 = bs.cos_free_angle
    a0 = sign * big_a * bs.sin_free_angle
    r0 = big_a * cos0 - 0.5 * pd
    # (s a0)^2 + r0^2 - A^2 = Pd (Pd/4 - A cos(alpha0)) exactly, so S^2 - A^2 needs no cancellation
    excess = pd * (0.25 * pd - big_a * cos0) + axial * (2.0 * a0 + axial) + radial * (2.0 * r0 + radial)
    if excess <= 0.0 and not need_angle:
        return 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, excess
    a = a0 + axial
    r = r0 + radial
    s_len = math.sqrt(a * a + r * r)
    delta = excess / (s_len + big_a)
    alpha = 0.0
    if need_angle or with_angle:
        alpha = math.atan2((sign if sign != 0.0 else 1.0) * a, r)
    if delta <= 0.0:
        return 0.0, alpha, 0.0, 0.0, a, r, s_len, delta
    k, dk = ball_constant(bs, r / s_len)
    root = math.sqrt(delta)
    q = k * delta * root
    inv3 = 1.0 / (s_len * s_len * s_len)
    # Q depends on (a, r) through delta (d delta/da = a/S) and through K_b(cos alpha), cos alpha = r/S with
    # d(r/S)/da = -a r / S^3 and d(r/S)/dr = a^2 / S^3
    dq_da = -dk * a * r * inv3 * delta * root + 1.5 * k * root * a / s_len
    dq_dr = dk * a * a * inv3 * delta * root + 1.5 * k * root * r / s_len
    return q, alpha, dq_da, dq_dr, a, r, s_len, delta


@njit(cache=True, inline="always")
def hermite_weights(bs, x):
    """Node interval i and the cubic Hermite basis (:func:`_basis`) of :func:`table` at |alpha| = ``x`` [rad].

    The weights depend on the angle only, so the rows read at one angle share them (:func:`pair_extents`).
    i = n - 1 marks an angle beyond the last node, where every row is constant.
    """
    n = bs.tables.shape[2]
    i, t = _interval(n, bs.table_step, x)
    if i == n - 1:
        return i, (1.0, 0.0, 0.0, 0.0)
    return i, _basis(t)


@njit(cache=True, inline="always")
def table_value(bs, row, weights):
    """Value of table ``row`` with the weights of :func:`hermite_weights` (the same number :func:`table` gives)."""
    i, basis = weights
    values = bs.tables[row, 0]
    if i == values.size - 1:
        return values[i]
    return _combine(values, bs.tables[row, 1], bs.table_step, i, basis)


@njit(cache=True, inline="always")
def pair_extents(q, alpha, bs):
    """Hertz max stress and semi-major axis at the inner and outer raceway of a loaded pair [Pa, Pa, m, m].

    Eq. 4-8 (sigma_max = C(alpha) Q^(1/3), a = c_a(alpha) Q^(1/3)) with one cube root and one set of table
    weights for the four coefficients.
    """
    if q <= 0.0:
        return 0.0, 0.0, 0.0, 0.0
    cube = q ** (1.0 / 3.0)
    weights = hermite_weights(bs, abs(alpha))
    return (table_value(bs, STRESS_INNER, weights) * cube, table_value(bs, STRESS_OUTER, weights) * cube,
            table_value(bs, AXIS_INNER, weights) * cube, table_value(bs, AXIS_OUTER, weights) * cube)


@njit(cache=True, inline="always")
def pair_stress(q, alpha, bs):
    """Hertz max stress at the inner and outer raceway of a loaded pair [Pa] (Eq. 4-8, sigma ~ Q^(1/3)).

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> from auxbearing.bearings.ballset import ballset_params
    >>> s_i, s_o = pair_stress(610.4, math.radians(35.0), ballset_params(get_bearing("QJ202")))
    >>> round(s_i / 1e6, 1), round(s_o / 1e6, 1)
    (2610.2, 2186.2)
    """
    s_i, s_o, _, _ = pair_extents(q, alpha, bs)
    return s_i, s_o


@njit(cache=True, inline="always")
def accumulate(disp, bs, pd, force, jac, with_jac, with_stress):
    """Add the ball-set resultant ON the inner ring (and its Jacobian) at ``disp`` into the outputs.

    Source paper Eq. 14 (four-point) and Eq. 16 (angular contact) in 5 DOF, with the sign of a
    reaction; allocation-free for solvers and right-hand sides (zero the outputs first).

    Parameters
    ----------
    disp : ndarray, shape (5,)
        (delta_a, dx, dy, theta_x, theta_y) [m, m, m, rad, rad].
    bs : BallSet
    pd : float
        Diametral clearance [m].
    force : ndarray, shape (5,)
        (Fa, Fx, Fy, Mx, My) [N, N m]; the resultant is added.
    jac : ndarray, shape (5, 5)
        d force / d disp (minus the stiffness matrix); added when ``with_jac``.
    with_jac, with_stress : bool

    Returns
    -------
    max_load : float
        Largest pair load [N].
    max_stress : float
        Largest Hertz max stress of any contact, inner or outer race [Pa] (0 unless ``with_stress``).
    """
    ric = bs.moment_arm
    max_load = 0.0
    max_stress = 0.0
    for j in range(bs.cos_azimuth.size):
        cphi = bs.cos_azimuth[j]
        sphi = bs.sin_azimuth[j]
        ga3 = ric * sphi  # d(axial)/d(theta_x), d(axial)/d(theta_y)
        ga4 = -ric * cphi
        axial = disp[0] + ga3 * disp[3] + ga4 * disp[4]
        radial = disp[1] * cphi + disp[2] * sphi
        for k in range(bs.signs.size):
            q, alpha, dq_da, dq_dr, a, r, s_len, _ = pair(bs.signs[k], axial, radial, bs, pd, False, with_stress)
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
            max_load = max(max_load, q)
            if with_stress:
                s_i, s_o = pair_stress(q, alpha, bs)
                max_stress = max(max_stress, s_i, s_o)
    return max_load, max_stress


@njit(cache=True)
def pair_states(disp, bs, pd, load, angle, compression, distance, stress_inner, stress_outer, force, jac,
                with_resultant=True):
    """Per-ball, per-pair state over many displacements: the array face of :func:`pair`.

    ``disp`` is (n, 5); the per-pair outputs are (n, Z, P), ``force`` (n, 5), ``jac`` (n, 5, 5),
    all overwritten (``force`` and ``jac`` only ``with_resultant``: the Jacobian is most of the cost).
    Every number comes from :func:`pair`, :func:`pair_stress` and :func:`accumulate`, so the arrays
    agree with the solvers to the last bit.
    """
    ric = bs.moment_arm
    for i in range(disp.shape[0]):
        u = disp[i]
        for j in range(bs.cos_azimuth.size):
            axial = u[0] + ric * (bs.sin_azimuth[j] * u[3] - bs.cos_azimuth[j] * u[4])
            radial = u[1] * bs.cos_azimuth[j] + u[2] * bs.sin_azimuth[j]
            for k in range(bs.signs.size):
                q, alpha, _, _, _, _, s_len, delta = pair(bs.signs[k], axial, radial, bs, pd, True, True)
                load[i, j, k] = q
                angle[i, j, k] = alpha
                compression[i, j, k] = delta
                distance[i, j, k] = s_len
                stress_inner[i, j, k], stress_outer[i, j, k] = pair_stress(q, alpha, bs)
        if with_resultant:
            force[i, :] = 0.0
            jac[i, :, :] = 0.0
            accumulate(u, bs, pd, force[i], jac[i], True, False)
