"""The classical fourth-order Runge-Kutta method with an embedded third-order estimate (SI, no units).

For a right-hand side whose step is set by stability rather than by accuracy. The coast-down's full-dynamics
windows are such a case: a race rings on its contacts at 10-50 kHz and the Dormand-Prince steps of
:mod:`auxbearing.core.integrate` sit on their stability bound there (``benchmarks/bench_step_floor.py``). Per
right-hand-side evaluation the classical method reaches further along that bound: its stability region crosses
the imaginary axis at 2.83 and the negative real axis at 2.79 with four evaluations a step, against the
Dormand-Prince pair's (propagated solution) 3.31 on the real axis and about 2.3 at the blower's ringing mode
(92 deg from the real axis) with six (the regions: Hairer & Wanner, *Solving Ordinary Differential Equations
II*, 2nd ed. (1996), Sec. IV.2; the Dormand-Prince figures as ``benchmarks/bench_step_floor.py`` computes them).

* **The method**: Kutta's classical scheme (Kutta 1901; Hairer, Norsett & Wanner, *Solving Ordinary
  Differential Equations I*, 2nd ed. (1993), Sec. II.1): c = (0, 1/2, 1/2, 1), a21 = a32 = 1/2, a43 = 1,
  b = (1/6, 1/3, 1/3, 1/6).
* **The error estimate**: the derivative at the new point, f(t + h, y1), is a fifth stage that the next step
  reuses (first same as last). With it the weights b^ = (1/6, 1/3, 1/3, 0, 1/6) satisfy the four third-order
  conditions (sum b^ = 1, b^.c = 1/2, b^.c^2 = 1/3, b^ A c = 1/6; Hairer et al. 1993, Sec. II.2; checked in
  ``tests/unit/test_rk4.py``), so y1 - y^1 = h (k4 - k5) / 6 is the local error estimate of order four.
* **The step control**: Gustafsson's PI controller, h_new = h s err^(-alpha) err_prev^beta with alpha = 0.7 / k
  and beta = 0.4 / k for an estimate of order k = 4 (Gustafsson, "Control-theoretic techniques for stepsize
  selection in explicit Runge-Kutta methods", ACM TOMS 17 (1991) 533-554; Hairer & Wanner 1996, Eq. IV.2.43c).
  Its stronger proportional part keeps a stability-bound step from the reject-and-grow cycle the weak
  Dormand-Prince default (beta = 0.04) falls into; s = 0.95 keeps the error it settles on where an accuracy-bound
  step settles with the Dormand-Prince controller (err^(alpha - beta) = s at equilibrium: 0.95^(1 / 0.075) =
  0.50 against 0.9^(1 / 0.18) = 0.56).
* **The dense output**: the cubic Hermite interpolant of y0, y1 and the derivatives at both ends, third-order
  accurate, written in the five-row form of :func:`auxbearing.core.integrate.dense_eval` (its last row zero), so
  an observer reads it as it reads Dormand-Prince's.

Measured on a 10 ms coast-down window of the shipped examples (the compiled drivers from the same state, same
tolerances; right-hand-side evaluations, this method against Dormand-Prince with its own controller): the blower
at 20 s 5228 against 8796, the compressor at 20 s 5232 against 8886, the vertical rotor at 6 s 14 740 against
16 836, the paper rig at 5 s 8016 against 8850. Against a run with tolerances a thousand times tighter the state a
window ends on is as close as Dormand-Prince's or closer on the blower, the vertical rotor and the paper rig, and
four times further on the compressor's elastic modes (16 against 3.7 tolerances), within what the tolerances
allow a chaotic contact motion over 10 ms. In a drop's first impacts, where the steps are set by accuracy, it
gains nothing (blower 9701 against 9577): the drops keep Dormand-Prince.

:func:`rk4` takes and returns what :func:`auxbearing.core.integrate.dopri5` does (the same
:class:`~auxbearing.core.integrate.Settings` and :class:`~auxbearing.core.integrate.Memory`, the same
right-hand side and observer), so a run can change method between two calls.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from auxbearing.core.integrate import (
    FINISHED,
    MAX_FACTOR,
    MIN_FACTOR,
    STOPPED,
    accepted,
    attempt,
    begin,
    error_norm,
    leave,
    rejected,
)

#: Order of the error estimate plus one (the exponent's k of the step control).
ESTIMATE_ORDER = 4
#: Gustafsson's PI gains for an estimate of order k (module docstring).
ALPHA = 0.7 / ESTIMATE_ORDER
BETA = 0.4 / ESTIMATE_ORDER
#: Safety factor of the step control (module docstring).
SAFETY = 0.95


@njit(cache=True)
def step_factor(err, err_previous, rejected_last):
    """h_new / h after a step with scaled error ``err`` (Gustafsson's PI control; module docstring).

    Examples
    --------
    >>> round(step_factor(1.0, 1.0, False), 3)
    0.95
    >>> step_factor(4.0, 1.0, False) < 1.0
    True
    """
    if err == 0.0:
        return MAX_FACTOR
    if err <= 1.0:
        factor = SAFETY * err ** (-ALPHA) * err_previous ** BETA
        factor = min(MAX_FACTOR, max(MIN_FACTOR, factor))
        if rejected_last:
            factor = min(1.0, factor)
        return factor
    # a rejected step: the pure I-controller (the PI memory is about accepted steps)
    return max(MIN_FACTOR, SAFETY * err ** (-1.0 / ESTIMATE_ORDER))


@njit(cache=True)
def hermite_coefficients(y0, y1, h, f0, f1, out):
    """The cubic Hermite interpolant of one step in :func:`~auxbearing.core.integrate.dense_eval`'s five rows.

    y(t0 + theta h) = y0 + theta (d + (1 - theta)(h f0 - d + theta (2 d - h f0 - h f1))) with d = y1 - y0: the
    values and derivatives at both ends (Hairer et al. 1993, Sec. II.6); the fifth row is zero.

    Examples
    --------
    >>> import numpy as np
    >>> from auxbearing.core.integrate import dense_eval
    >>> c = np.empty((5, 1)); y = np.empty(1)
    >>> hermite_coefficients(np.zeros(1), np.ones(1), 1.0, np.zeros(1), 3.0 * np.ones(1), c)  # y = t^3
    >>> dense_eval(c, 0.5, y); float(y[0])
    0.125
    """
    for i in range(y0.size):
        diff = y1[i] - y0[i]
        start = h * f0[i] - diff
        out[0, i] = y0[i]
        out[1, i] = diff
        out[2, i] = start
        out[3, i] = diff - h * f1[i] - start
        out[4, i] = 0.0


@njit(inline="always")  # inlined into its driver, as integrate.dopri5 (compiled once there, not twice)
def rk4(rhs, observe, model, obs, y, t_end, settings, memory, grid):
    """Advance ``y`` from ``memory.t`` towards ``t_end`` with the classical RK4 and its embedded estimate.

    Arguments, return value and contract as :func:`auxbearing.core.integrate.dopri5` (error control on the
    components of finite ``atol``, a step that lands on ``t_end``, the observer after every accepted step with
    the step's dense output, the right-hand side's last call at the accepted new point).
    """
    n = y.size
    k1 = memory.derivative
    k2 = np.empty(n)
    k3 = np.empty(n)
    k4 = np.empty(n)
    k5 = np.empty(n)
    yt = np.empty(n)
    y1 = np.empty(n)
    err = np.empty(n)
    tmp = np.empty(n)
    coeff = np.empty((5, n))
    t = memory.t[0]
    h = memory.h[0]
    begin(rhs, t, y, model, memory)
    dt_out = settings.output_step
    k_next = memory.next_output[0]
    attempts = 0
    status = FINISHED
    while t < t_end:
        ending, t, h, h_proposed, last = attempt(t, h, t_end, attempts, settings)
        if ending >= 0:
            status = ending
            break
        attempts += 1
        half = 0.5 * h
        for i in range(n):
            yt[i] = y[i] + half * k1[i]
        rhs(t + half, yt, model, k2)
        for i in range(n):
            yt[i] = y[i] + half * k2[i]
        rhs(t + half, yt, model, k3)
        for i in range(n):
            yt[i] = y[i] + h * k3[i]
        rhs(t + h, yt, model, k4)
        sixth = h / 6.0
        for i in range(n):
            y1[i] = y[i] + sixth * (k1[i] + 2.0 * (k2[i] + k3[i]) + k4[i])
        rhs(t + h, y1, model, k5)
        memory.evaluations[0] += 4
        for i in range(n):
            err[i] = sixth * (k4[i] - k5[i])
        e_norm = error_norm(err, y, y1, settings.rtol, settings.atol)
        if not (e_norm <= 1.0):
            h = rejected(step_factor, h, e_norm, memory)
            continue
        hermite_coefficients(y, y1, h, k1, k5, coeff)
        factor = step_factor(e_norm, memory.err_prev[0], memory.rejected_last[0] > 0.5)
        t, h, k_next, code = accepted(observe, model, obs, t, h, h_proposed, last, t_end, y, y1, k1, k5, coeff, grid,
                                      k_next, dt_out, tmp, memory, e_norm, factor)
        if code != 0:
            status = STOPPED
            break
    leave(memory, t, h, k_next)
    return status
