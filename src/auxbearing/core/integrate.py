"""Dormand-Prince 5(4) building blocks for compiled adaptive integration (SI, no units).

The method is the embedded pair of Dormand & Prince, "A family of embedded Runge-Kutta
formulae", J. Comput. Appl. Math. 6 (1980) 19-26, with the fourth-order continuous extension
of Hairer, Norsett & Wanner, *Solving Ordinary Differential Equations I*, 2nd ed. (1993),
Sec. II.6 (dense output of DOPRI5), and the PI step-size controller of Hairer & Wanner,
*Solving Ordinary Differential Equations II* (1996), Sec. IV.2, Eq. 2.43c (Gustafsson's
controller in the form used by DOPRI5, beta = 0.04).

Only the pieces that do not depend on the right-hand side live here: the tableau, the error
norm, the step-size controller and the dense-output polynomial. The stepping loop lives next
to its right-hand side (:mod:`auxbearing.core.drop`) so that numba can inline the call.
"""

from __future__ import annotations

import math

from numba import njit

# Butcher tableau of DOPRI5 (Dormand & Prince 1980, Table 2); the seventh stage is the FSAL
# evaluation at the new point, so the fifth-order weights equal its row.
C2, C3, C4, C5 = 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0
A21 = 1.0 / 5.0
A31, A32 = 3.0 / 40.0, 9.0 / 40.0
A41, A42, A43 = 44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0
A51, A52, A53, A54 = 19372.0 / 6561.0, -25360.0 / 2187.0, 64448.0 / 6561.0, -212.0 / 729.0
A61, A62, A63, A64, A65 = 9017.0 / 3168.0, -355.0 / 33.0, 46732.0 / 5247.0, 49.0 / 176.0, -5103.0 / 18656.0
B1, B3, B4, B5, B6 = 35.0 / 384.0, 500.0 / 1113.0, 125.0 / 192.0, -2187.0 / 6784.0, 11.0 / 84.0
# difference of the fifth- and fourth-order weights: the local error estimate
E1, E3, E4, E5, E6, E7 = (71.0 / 57600.0, -71.0 / 16695.0, 71.0 / 1920.0, -17253.0 / 339200.0,
                          22.0 / 525.0, -1.0 / 40.0)
# continuous extension (Hairer, Norsett & Wanner 1993, Sec. II.6, the DOPRI5 dense output)
D1, D3, D4 = -12715105075.0 / 11282082432.0, 87487479700.0 / 32700410799.0, -10690763975.0 / 1880347072.0
D5, D6, D7 = 701980252875.0 / 199316789632.0, -1453857185.0 / 822651844.0, 69997945.0 / 29380423.0

#: Controller constants (Hairer & Wanner's DOPRI5 defaults): safety factor, the largest
#: shrink and growth of the step per attempt, and the PI exponents.
SAFETY = 0.9
MIN_FACTOR = 0.2
MAX_FACTOR = 10.0
BETA = 0.04
ALPHA = 0.2 - 0.75 * BETA


@njit(cache=True)
def error_norm(err, y0, y1, rtol, atol):
    """Root-mean-square scaled local error (Hairer, Norsett & Wanner 1993, Eq. II.4.11).

    Parameters
    ----------
    err : ndarray
        Local error estimate of each component.
    y0, y1 : ndarray
        States at the start and end of the step.
    rtol : float
        Relative tolerance [-].
    atol : ndarray
        Absolute tolerance of each component (same units as the state).

    Returns
    -------
    float
        ``sqrt(mean((err_i / (atol_i + rtol max(|y0_i|, |y1_i|)))^2))``; <= 1 accepts the step.

    Examples
    --------
    >>> import numpy as np
    >>> float(error_norm(np.array([1e-6]), np.array([1.0]), np.array([1.0]), 1e-6, np.array([0.0])))
    1.0
    """
    total = 0.0
    for i in range(err.size):
        scale = atol[i] + rtol * max(abs(y0[i]), abs(y1[i]))
        total += (err[i] / scale) ** 2
    return math.sqrt(total / err.size)


@njit(cache=True)
def next_step_factor(err, err_previous, rejected_last):
    """Step-size factor of the PI controller (Hairer & Wanner 1996, Eq. IV.2.43c).

    Parameters
    ----------
    err : float
        Scaled error norm of the step just attempted.
    err_previous : float
        Scaled error norm of the last accepted step (>= 1e-4).
    rejected_last : bool
        Whether the previous attempt was rejected; a step never grows right after a rejection.

    Returns
    -------
    float
        h_new / h. Below 1 when ``err > 1`` (the step is retried with the smaller size).

    Examples
    --------
    >>> round(next_step_factor(1.0, 1.0, False), 3)
    0.9
    """
    if err == 0.0:
        return MAX_FACTOR
    if err <= 1.0:
        factor = SAFETY * err ** (-ALPHA) * err_previous ** BETA
        factor = min(MAX_FACTOR, max(MIN_FACTOR, factor))
        if rejected_last:
            factor = min(1.0, factor)
        return factor
    # a rejected step uses the pure I-controller: the PI memory is about accepted steps
    return max(MIN_FACTOR, SAFETY * err ** -0.2)


@njit(cache=True)
def dense_coefficients(y0, y1, h, k1, k3, k4, k5, k6, k7, out):
    """Coefficients of the DOPRI5 continuous extension of one step (Hairer et al. 1993, II.6).

    Parameters
    ----------
    y0, y1 : ndarray
        States at the start and the end of the accepted step.
    h : float
        Step size [s].
    k1, k3, k4, k5, k6, k7 : ndarray
        Stage derivatives (k7 is the derivative at the new point).
    out : ndarray, shape (5, n)
        Filled with the five coefficient rows used by :func:`dense_eval`.
    """
    for i in range(y0.size):
        diff = y1[i] - y0[i]
        bspl = h * k1[i] - diff
        out[0, i] = y0[i]
        out[1, i] = diff
        out[2, i] = bspl
        out[3, i] = diff - h * k7[i] - bspl
        out[4, i] = h * (D1 * k1[i] + D3 * k3[i] + D4 * k4[i] + D5 * k5[i] + D6 * k6[i] + D7 * k7[i])


@njit(cache=True)
def dense_eval(coeff, theta, out):
    """State at the fraction ``theta`` in [0, 1] of an accepted step (fourth order accurate).

    y(t0 + theta h) = r0 + theta (r1 + (1 - theta)(r2 + theta (r3 + (1 - theta) r4))).

    Examples
    --------
    >>> import numpy as np
    >>> c = np.zeros((5, 1)); c[0, 0] = 1.0; c[1, 0] = 2.0
    >>> y = np.zeros(1); dense_eval(c, 0.5, y); float(y[0])
    2.0
    """
    one_minus = 1.0 - theta
    for i in range(coeff.shape[1]):
        out[i] = coeff[0, i] + theta * (coeff[1, i] + one_minus * (
            coeff[2, i] + theta * (coeff[3, i] + one_minus * coeff[4, i])))
