"""Dormand-Prince 5(4) building blocks for compiled adaptive integration (SI, no units).

The method is the embedded pair of Dormand & Prince, "A family of embedded Runge-Kutta
formulae", J. Comput. Appl. Math. 6 (1980) 19-26, with the fourth-order continuous extension
of Hairer, Norsett & Wanner, *Solving Ordinary Differential Equations I*, 2nd ed. (1993),
Sec. II.6 (dense output of DOPRI5), and the PI step-size controller of Hairer & Wanner,
*Solving Ordinary Differential Equations II* (1996), Sec. IV.2, Eq. 2.43c (Gustafsson's
controller in the form used by DOPRI5, beta = 0.04).

The stepping loop :func:`dopri5` knows nothing of bearings: it takes the right-hand side and an
observer as arguments (compiled functions; numba specialises the loop for each pair and inlines
them), so one integrator serves every model and can be tested on problems with exact answers.

* ``rhs(t, y, model, out)`` writes dy/dt into ``out``;
* ``observe(t, h, y0, y1, coeff, model, obs)`` is called after every accepted step from t to t + h
  (``coeff`` the step's dense-output polynomial, :func:`dense_eval`); it locates events, refines
  peaks (:func:`dense_root`, :func:`dense_max`), checks ranges and returns 0 to go on or a
  positive code to stop.

A caller that wants its specialisation cached on disk wraps the call in its own
``njit(cache=True)`` function that names ``rhs`` and ``observe`` as globals (numba cannot cache a
function that receives other functions as arguments from Python).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
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


#: Status codes of :func:`dopri5`.
FINISHED, PAUSED, STEP_UNDERFLOW, STOPPED = 0, 1, 2, 3
STATUS_TEXT = {FINISHED: "reached the end time", PAUSED: "step budget of this call used (call again to go on)",
               STEP_UNDERFLOW: "step size underflow (non-finite or exploding state)",
               STOPPED: "stopped by the observer"}


class Settings(NamedTuple):
    """What the integrator is asked to do (SI)."""

    rtol: float  #: relative tolerance [-]
    atol: np.ndarray  #: absolute tolerance per state; ``inf`` leaves a component out of the error norm
    max_step: float  #: largest step [s]
    min_step: float  #: a step below this means the solution cannot be resolved [s]
    step_budget: int  #: attempted steps allowed in one call before it returns PAUSED
    output_step: float  #: interval of the uniform output grid [s] (row k is t = k * output_step)


class Memory(NamedTuple):
    """What the integrator carries from one call to the next (1-element arrays, updated in place)."""

    t: np.ndarray  #: time reached [s]
    h: np.ndarray  #: step size to try next [s]
    err_prev: np.ndarray  #: error norm of the last accepted step (PI controller memory)
    rejected_last: np.ndarray  #: 1 if the last attempt was rejected
    steps: np.ndarray  #: accepted steps (int64)
    rejected: np.ndarray  #: rejected steps (int64)
    evaluations: np.ndarray  #: right-hand-side evaluations (int64)
    next_output: np.ndarray  #: next grid row to fill (int64)
    derivative: np.ndarray  #: dy/dt at t (first-same-as-last stage), valid when ``evaluations`` > 0


def new_memory(t0: float, h0: float, n_states: int) -> Memory:
    """Fresh :class:`Memory` at time ``t0`` [s] with first trial step ``h0`` [s]."""
    def one(value, dtype=float):
        return np.full(1, value, dtype=dtype)
    return Memory(one(t0), one(h0), one(1e-4), one(0.0), one(0, np.int64), one(0, np.int64), one(0, np.int64),
                  one(0, np.int64), np.zeros(n_states))


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
        ``sqrt(mean((err_i / (atol_i + rtol max(|y0_i|, |y1_i|)))^2))`` over the components with a
    finite ``atol``; <= 1 accepts the step.

    Examples
    --------
    >>> import numpy as np
    >>> float(error_norm(np.array([1e-6]), np.array([1.0]), np.array([1.0]), 1e-6, np.array([0.0])))
    1.0
    """
    total = 0.0
    counted = 0
    for i in range(err.size):
        if math.isinf(atol[i]):  # a bookkeeping component (work, energy) that must not steer the step
            continue
        scale = atol[i] + rtol * max(abs(y0[i]), abs(y1[i]))
        total += (err[i] / scale) ** 2
        counted += 1
    return math.sqrt(total / max(counted, 1))


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


@njit(inline="always")
def dense_root(g, coeff, model, tmp, arg):
    """Fraction theta in (0, 1] of a step where ``g(y, model, arg)`` turns positive (bisection, 60 halvings).

    ``g`` must be <= 0 at the start of the step and > 0 at its end; ``tmp`` is a work array of the
    state's size. Accurate to 2^-60 of the step on the dense output (fourth order).
    """
    lo = 0.0
    hi = 1.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        dense_eval(coeff, mid, tmp)
        if g(tmp, model, arg) > 0.0:
            hi = mid
        else:
            lo = mid
    return hi


@njit(inline="always")
def dense_max(f, coeff, model, tmp, arg):
    """Golden-section search of the largest ``f(y, model, arg)`` inside one step (dense output).

    Returns (theta, value). Kiefer's golden-section search (Press et al., *Numerical Recipes*,
    3rd ed., Sec. 10.2), 40 reductions: the bracket shrinks to 4e-9 of the step.
    """
    g = 0.5 * (math.sqrt(5.0) - 1.0)
    lo = 0.0
    hi = 1.0
    a = hi - g
    b = g
    dense_eval(coeff, a, tmp)
    fa = f(tmp, model, arg)
    dense_eval(coeff, b, tmp)
    fb = f(tmp, model, arg)
    for _ in range(40):
        if fa >= fb:
            hi = b
            b = a
            fb = fa
            a = hi - g * (hi - lo)
            dense_eval(coeff, a, tmp)
            fa = f(tmp, model, arg)
        else:
            lo = a
            a = b
            fa = fb
            b = lo + g * (hi - lo)
            dense_eval(coeff, b, tmp)
            fb = f(tmp, model, arg)
    best = 0.5 * (lo + hi)
    dense_eval(coeff, best, tmp)
    return best, f(tmp, model, arg)


@njit(cache=True)
def output_rows(coeff, t, h, grid, k_next, dt_out, tmp):
    """Fill the output grid's rows that fall inside the accepted step from t to t + h; the next row to fill.

    Row k holds the state at k * ``dt_out``, read off the step's dense output (``coeff``, :func:`dense_eval`);
    ``tmp`` is a work array of the state's size.
    """
    while k_next < grid.shape[0] and k_next * dt_out <= t + h + 1e-9 * dt_out:
        theta = (k_next * dt_out - t) / h
        dense_eval(coeff, min(1.0, max(0.0, theta)), tmp)
        for i in range(tmp.size):
            grid[k_next, i] = tmp[i]
        k_next += 1
    return k_next


@njit(cache=True, inline="always")
def attempt(t, h, t_end, attempts, settings):
    """What a stepping loop does next at ``t`` with the step ``h`` to try: (status, t, h, h_proposed, last).

    ``status`` -1: try a step of ``h``, capped at ``settings.max_step`` and shortened to land on ``t_end`` when it
    would pass it (``last``; ``h_proposed`` is the step before that). Otherwise the loop ends with ``status``:
    :data:`FINISHED` with ``t`` set to ``t_end`` when only round-off is left, :data:`PAUSED` once the call's step
    budget is used, :data:`STEP_UNDERFLOW` for a step below ``settings.min_step`` or not finite.
    """
    end_slack = 1e-13 * max(1.0, abs(t_end))  # a remainder below this is round-off, not a step
    if t_end - t <= end_slack:
        return FINISHED, t_end, h, h, True
    if attempts >= settings.step_budget:
        return PAUSED, t, h, h, False
    if h < settings.min_step * max(1.0, abs(t_end)) or not math.isfinite(h):
        return STEP_UNDERFLOW, t, h, h, False
    h = min(h, settings.max_step)
    h_proposed = h
    last = t + h >= t_end - end_slack
    if last:
        h = t_end - t
    return -1, t, h, h_proposed, last


@njit(cache=True, inline="always")
def remember(memory, accepted, e_norm):
    """Book an attempted step in ``memory``: the PI controller's memory and the step counts."""
    if accepted:
        memory.err_prev[0] = max(e_norm, 1e-4)
        memory.rejected_last[0] = 0.0
        memory.steps[0] += 1
    else:
        memory.rejected_last[0] = 1.0
        memory.rejected[0] += 1


@njit(cache=True, inline="always")
def leave(memory, t, h, k_next):
    """Keep where a stepping loop stopped in ``memory``, for the next call to go on from."""
    memory.t[0] = t
    memory.h[0] = h
    memory.next_output[0] = k_next


@njit(inline="always")
def begin(rhs, t, y, model, memory):
    """The first stage's dy/dt at ``t`` into ``memory.derivative``, unless the call before left it there."""
    if memory.evaluations[0] == 0:
        rhs(t, y, model, memory.derivative)
        memory.evaluations[0] += 1


@njit(inline="always")
def rejected(step_factor, h, e_norm, memory):
    """The step to try after a rejected one of ``h`` (``step_factor``: the method's controller); booked."""
    if not math.isfinite(e_norm):
        h *= MIN_FACTOR
    else:
        h *= step_factor(e_norm, memory.err_prev[0], True)
    remember(memory, False, e_norm)
    return h


@njit(inline="always")
def accepted(observe, model, obs, t, h, h_proposed, last, t_end, y, y1, k1, k_end, coeff, grid, k_next, dt_out,
             tmp, memory, e_norm, factor):
    """Take an accepted step from t to t + h: (t, h, next grid row, observer code) to go on with.

    Fills the grid rows the step passes (``coeff``: its dense output), asks the observer, books the step,
    moves ``y`` to ``y1`` and the first stage to the step's last one (``k_end``, first same as last), and
    proposes the next step as ``factor`` times this one.
    """
    k_next = output_rows(coeff, t, h, grid, k_next, dt_out, tmp)
    code = observe(t, h, y, y1, coeff, model, obs)
    remember(memory, True, e_norm)
    t = t_end if last else t + h
    for i in range(y.size):
        y[i] = y1[i]
        k1[i] = k_end[i]
    # a step shortened to land on t_end says nothing about the step size the solution allows
    h = max(h * factor, h_proposed) if last else h * factor
    return t, h, k_next, code


# Inlined into each driver (core/drive.py): numba links a called kernel into its caller and optimises the linked
# code again, so a separate integrator made the right-hand side and the observer be optimised twice more.
@njit(inline="always")
def dopri5(rhs, observe, model, obs, y, t_end, settings, memory, grid):
    """Advance ``y`` from ``memory.t`` towards ``t_end`` with DOPRI5 and PI step control.

    Dormand & Prince (1980) with error control on the components of finite ``atol``, the PI
    controller (Hairer & Wanner 1996, Eq. IV.2.43c) and dense output (Hairer et al. 1993, II.6)
    for the uniform output grid and the observer. A discontinuity in the right-hand side (a
    contact that closes) makes the error test fail; the step shrinks until it ends just before
    the jump and the next step starts past it, so no event handling is needed for correctness.

    Parameters
    ----------
    rhs, observe : compiled functions
        See the module docstring.
    model : any numba-typed value
        Passed to ``rhs`` and ``observe`` unchanged (parameters).
    obs : any numba-typed value
        Passed to ``observe`` (its mutable state: arrays).
    y : ndarray
        State at ``memory.t``; overwritten with the state reached.
    t_end : float
        End time [s]; the last step lands on it.
    settings : Settings
    memory : Memory
        Updated in place; call again with the same memory to go on after PAUSED.
    grid : ndarray, shape (n_out, n)
        Uniform output: row k holds the state at k * ``settings.output_step`` (rows from
        ``memory.next_output`` on are filled as the solution passes them).

    Returns
    -------
    int
        :data:`FINISHED`, :data:`PAUSED`, :data:`STEP_UNDERFLOW` or :data:`STOPPED`.
    """
    n = y.size
    k1 = memory.derivative
    k2 = np.empty(n)
    k3 = np.empty(n)
    k4 = np.empty(n)
    k5 = np.empty(n)
    k6 = np.empty(n)
    k7 = np.empty(n)
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
        for i in range(n):
            yt[i] = y[i] + h * A21 * k1[i]
        rhs(t + C2 * h, yt, model, k2)
        for i in range(n):
            yt[i] = y[i] + h * (A31 * k1[i] + A32 * k2[i])
        rhs(t + C3 * h, yt, model, k3)
        for i in range(n):
            yt[i] = y[i] + h * (A41 * k1[i] + A42 * k2[i] + A43 * k3[i])
        rhs(t + C4 * h, yt, model, k4)
        for i in range(n):
            yt[i] = y[i] + h * (A51 * k1[i] + A52 * k2[i] + A53 * k3[i] + A54 * k4[i])
        rhs(t + C5 * h, yt, model, k5)
        for i in range(n):
            yt[i] = y[i] + h * (A61 * k1[i] + A62 * k2[i] + A63 * k3[i] + A64 * k4[i] + A65 * k5[i])
        rhs(t + h, yt, model, k6)
        for i in range(n):
            y1[i] = y[i] + h * (B1 * k1[i] + B3 * k3[i] + B4 * k4[i] + B5 * k5[i] + B6 * k6[i])
        rhs(t + h, y1, model, k7)
        memory.evaluations[0] += 6
        for i in range(n):
            err[i] = h * (E1 * k1[i] + E3 * k3[i] + E4 * k4[i] + E5 * k5[i] + E6 * k6[i] + E7 * k7[i])
        e_norm = error_norm(err, y, y1, settings.rtol, settings.atol)
        if not (e_norm <= 1.0):
            h = rejected(next_step_factor, h, e_norm, memory)
            continue
        dense_coefficients(y, y1, h, k1, k3, k4, k5, k6, k7, coeff)
        factor = next_step_factor(e_norm, memory.err_prev[0], memory.rejected_last[0] > 0.5)
        t, h, k_next, code = accepted(observe, model, obs, t, h, h_proposed, last, t_end, y, y1, k1, k7, coeff, grid,
                                      k_next, dt_out, tmp, memory, e_norm, factor)
        if code != 0:
            status = STOPPED
            break
    leave(memory, t, h, k_next)
    return status
