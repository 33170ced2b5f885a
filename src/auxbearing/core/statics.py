"""Batched Newton-Raphson equilibrium of the inner ring on the ball set (SI kernels).

Solves ``load + F_ballset(u) = 0`` for the 5-DOF ring displacement ``u`` of every load case
(source paper Eq. 14 for four-point and Eq. 16 for angular-contact bearings, which the
paper solves "by Newton-Raphson"; Harris & Kotzalas 2007, Advanced Concepts, Ch. 1) with the
analytic Jacobian of :func:`auxbearing.core.ballset.accumulate`. Load vector and DOF
conventions are those of :mod:`auxbearing.core.ballset`.

Robustness, per case, compiled:

* Cold start from a rigid-ring estimate: the ring is moved along each load direction alone
  (axial, radial, tilt) until the ball set balances that load component to 1 % (1-D
  safeguarded false position on G^(2/3), which Hertz makes nearly linear); the estimates are
  summed. A start, not an answer: Newton polishes it.
  This also handles the zero-stiffness start at zero clearance and zero displacement.
* Newton step on the scaled system (moments divided by the moment arm r_ic, tilts times
  r_ic, so every row is in N and every unknown in m), with Levenberg regularisation
  ``K + mu k_ref I`` when K is singular or a step fails, a step cap of one curvature-centre
  distance A, and a backtracking (Armijo) line search on the residual 2-norm.
* Cases that still fail are retried by load continuation (:func:`continuation`).
* Converged: max scaled residual <= ``tol`` times the largest applied load component, and
  the next Newton step <= 1e-6 of the displacement. Otherwise the case gets a nonzero status.
  A residual that double precision cannot resolve counts as converged at that round-off floor,
  16 ulp x ||K|| x |u|: it exceeds ``tol`` only for micro-newton loads on a ring that has
  crossed a clearance (u ~ Pd, compression ~ 1e-12 m; relative residual up to ~1e-7 there)
  and for loads below ~1e-20 N; ``relative_residual`` reports what was reached.

Fixed DOFs (e.g. an axially located ring) are removed from the system; their residual is the
reaction the support must supply.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numba
import numpy as np

from auxbearing.core.ballset import K_B, accumulate, table

#: Status codes of :func:`solve_cases`.
CONVERGED, MAX_ITERATIONS, LINE_SEARCH_FAILED = 0, 1, 2
STATUS_TEXT = {CONVERGED: "converged", MAX_ITERATIONS: "iteration limit reached",
               LINE_SEARCH_FAILED: "no descent direction (line search failed)"}
DEFAULT_TOL = 1e-9
DEFAULT_MAX_ITER = 100
_STEP_TOL = 1e-6  # converged step, relative to the displacement
_ULP = 2.220446049250313e-16


@numba.njit(cache=True)
def _scales(params):
    ric = params.moment_arm
    w = np.array([1.0, 1.0, 1.0, 1.0 / ric, 1.0 / ric])  # residual rows -> N
    xs = np.array([1.0, 1.0, 1.0, ric, ric])  # unknowns -> m
    return w, xs


@numba.njit(cache=True)
def _along(tau, direction, goal, params, u, force, jac):
    """G(tau)^(2/3) - goal with G the ball-set reaction along ``direction`` at u = tau direction."""
    for i in range(5):
        u[i] = tau * direction[i]
        force[i] = 0.0
    accumulate(u, params, params.clearance, force, jac, False, False)
    g = 0.0
    for i in range(5):
        g -= direction[i] * force[i]
    return (g if g > 0.0 else 0.0) ** (2.0 / 3.0) - goal


@numba.njit(cache=True)
def _directional(direction, target, params):
    """Distance tau >= 0 along the unit ``direction`` where the ball set balances ``target``.

    Returns (tau, evaluations); tau = 0 if the ball set cannot carry the load that way alone.
    """
    force = np.zeros(5)
    jac = np.zeros((1, 1))
    u = np.zeros(5)
    big_a = params.curvature_distance
    goal = target ** (2.0 / 3.0)
    lo, f_lo = 0.0, -goal
    # start near the Hertz compression of Z balls sharing the load, then widen by 2x
    k_b, _ = table(params, K_B, params.free_angle)
    hi = min(max((target / (params.cos_azimuth.size * k_b)) ** (2.0 / 3.0), 1e-12 * big_a), big_a)
    f_hi = _along(hi, direction, goal, params, u, force, jac)
    count = 1
    while f_hi < 0.0:
        lo, f_lo = hi, f_hi
        hi *= 2.0
        if hi > 4.0 * big_a:
            return 0.0, count
        f_hi = _along(hi, direction, goal, params, u, force, jac)
        count += 1
    side = 0
    tau = hi
    for _ in range(60):
        tau = (lo * f_hi - hi * f_lo) / (f_hi - f_lo)
        f = _along(tau, direction, goal, params, u, force, jac)
        count += 1
        if abs(f) <= 1e-2 * goal or hi - lo <= 1e-12 * hi:
            break
        if f < 0.0:
            lo, f_lo = tau, f
            if side == -1:
                f_hi *= 0.5  # Illinois modification: keep the stale end from stalling
            side = -1
        else:
            hi, f_hi = tau, f
            if side == 1:
                f_lo *= 0.5
            side = 1
    return tau, count


@numba.njit(cache=True)
def initial_guess(load, free, params):
    """Rigid-ring estimate of the displacement carrying ``load`` (sum of 1-D solves).

    Parameters
    ----------
    load : ndarray, shape (5,)
        (Fa, Fx, Fy, Mx, My) applied to the inner ring [N, N m].
    free : ndarray of bool, shape (5,)
        DOFs the ring may move in.
    params : ndarray
        :class:`auxbearing.core.ballset.BallSet`.
    """
    w, xs = _scales(params)
    guess = np.zeros(5)
    groups = ((0, 0), (1, 2), (3, 4))
    for g in range(3):
        i0, i1 = groups[g]
        direction = np.zeros(5)
        for i in (i0, i1):
            if free[i]:
                direction[i] = load[i] * w[i]
        norm = math.hypot(direction[i0], direction[i1]) if i0 != i1 else abs(direction[i0])
        if norm == 0.0:
            continue
        for i in range(5):
            direction[i] /= norm
        # unknowns in m: direction in scaled space -> physical via 1/xs
        phys = np.zeros(5)
        for i in range(5):
            phys[i] = direction[i] / xs[i]
        tau, _ = _directional(phys, norm, params)
        for i in range(5):
            guess[i] += tau * phys[i]
    return guess


@numba.njit(cache=True)
def _solve_linear(mat, rhs, out):
    """Gaussian elimination with partial pivoting on a 5x5 copy; False if singular."""
    a = mat.copy()
    b = rhs.copy()
    n = 5
    scale = 0.0
    for i in range(n):
        for j in range(n):
            scale = max(scale, abs(a[i, j]))
    if scale == 0.0:
        return False
    for c in range(n):
        p = c
        for r in range(c + 1, n):
            if abs(a[r, c]) > abs(a[p, c]):
                p = r
        if abs(a[p, c]) <= 1e-13 * scale:
            return False
        if p != c:
            for j in range(n):
                a[c, j], a[p, j] = a[p, j], a[c, j]
            b[c], b[p] = b[p], b[c]
        for r in range(c + 1, n):
            f = a[r, c] / a[c, c]
            for j in range(c, n):
                a[r, j] -= f * a[c, j]
            b[r] -= f * b[c]
    for c in range(n - 1, -1, -1):
        s = b[c]
        for j in range(c + 1, n):
            s -= a[c, j] * out[j]
        out[c] = s / a[c, c]
    return True


@numba.njit(cache=True)
def _residual(u, load, free, params, w, force, jac, with_jac):
    """Scaled residual rows [N] (zero in fixed DOFs), its 2-norm and max norm."""
    force[:] = 0.0
    if with_jac:
        jac[:, :] = 0.0
    accumulate(u, params, params.clearance, force, jac, with_jac, False)
    r = np.zeros(5)
    for i in range(5):
        if free[i]:
            r[i] = (load[i] + force[i]) * w[i]
    two = math.sqrt(np.sum(r * r))
    return r, two, np.max(np.abs(r))


@numba.njit(cache=True)
def newton(load, free, params, u0, tol, max_iter):
    """Damped Newton-Raphson for one load case (see the module docstring).

    Returns
    -------
    u : ndarray, shape (5,)
        Displacement [m, m, m, rad, rad].
    residual : float
        Max scaled residual [N] (moments divided by r_ic).
    iterations : int
    status : int
        :data:`CONVERGED`, :data:`MAX_ITERATIONS` or :data:`LINE_SEARCH_FAILED`.
    """
    w, xs = _scales(params)
    ref = 0.0
    for i in range(5):
        ref = max(ref, abs(load[i]) * w[i])
    u = u0.copy()
    for i in range(5):
        if not free[i]:
            u[i] = 0.0
    force = np.zeros(5)
    jac = np.zeros((5, 5))
    r, merit, res = _residual(u, load, free, params, w, force, jac, True)
    if ref == 0.0:
        return u, res, 0, CONVERGED if res == 0.0 else MAX_ITERATIONS
    z = params.cos_azimuth.size
    k_b, _ = table(params, K_B, params.free_angle)
    k_ref = 1.5 * z * k_b ** (2.0 / 3.0) * (ref / z) ** (1.0 / 3.0)
    big_a = params.curvature_distance
    # force of Z balls compressed by a few ulp of A: below it the displacement cannot resolve
    # the load in double precision (loads of ~1e-20 N and less), so it is a round-off floor
    floor = z * k_b * (4.0 * _ULP * big_a) ** 1.5
    goal = max(tol * ref, floor)
    mu = 0.0
    mat = np.zeros((5, 5))
    y = np.zeros(5)
    trial = np.zeros(5)
    jac_t = np.zeros((5, 5))
    force_t = np.zeros(5)
    for it in range(max_iter):
        # stiffness d(-r)/d(y) in scaled units: rows in N, unknowns y = u * xs in m
        k_scale = k_ref
        for n in range(5):
            for m in range(5):
                if free[n] and free[m]:
                    mat[n, m] = -jac[n, m] * w[n] / xs[m]
                    k_scale = max(k_scale, abs(mat[n, m]))
                else:
                    mat[n, m] = 0.0
        # fixed DOFs and the Levenberg term sized to the matrix, so neither looks singular
        for n in range(5):
            if not free[n]:
                mat[n, n] = k_scale
            elif mu > 0.0:
                mat[n, n] += mu * k_scale
        if not _solve_linear(mat, r, y):
            mu = max(10.0 * mu, 1e-6)
            continue
        step_len = np.max(np.abs(y))
        size = 0.0
        for i in range(5):
            size = max(size, abs(u[i] * xs[i]))
        # round-off floor: a residual the last bits of the displacement cannot resolve (matters
        # only when the ring sits far across a clearance and carries a micro-newton load)
        goal_now = max(goal, 16.0 * _ULP * k_scale * size)
        if res <= goal_now and step_len <= _STEP_TOL * size + 1e-300:
            return u, res, it, CONVERGED
        cap = 1.0 if step_len <= big_a else big_a / step_len
        t = cap
        accepted = False
        for _ in range(40):
            for i in range(5):
                trial[i] = u[i] + t * y[i] / xs[i]
            r_t, merit_t, res_t = _residual(trial, load, free, params, w, force_t, jac_t, True)
            if merit_t <= (1.0 - 1e-4 * t) * merit:
                accepted = True
                break
            t *= 0.5
        if not accepted:
            if res <= goal_now:
                return u, res, it, CONVERGED  # at the round-off floor: no further descent exists
            if mu >= 1e6:
                return u, res, it, LINE_SEARCH_FAILED
            mu = max(10.0 * mu, 1e-6)
            continue
        u[:] = trial
        r, merit, res = r_t, merit_t, res_t
        jac[:, :] = jac_t
        if t == cap:
            mu = 0.0 if mu < 1e-9 else 0.1 * mu
    return u, res, max_iter, MAX_ITERATIONS


@numba.njit(cache=True)
def continuation(load, free, params, tol, max_iter):
    """Fallback: walk the load down from a well-conditioned level in steps of 1/4 (warm starts).

    Small loads with clearance touch only a few balls, where K is nearly singular and contacts
    switch on and off between Newton steps. At load level F_big = Z K_b (0.05 A)^1.5 most balls
    carry load; each smaller level starts from the solution of the one before it, from above
    (over-compressed), where Newton on Hertz contacts converges monotonically.
    """
    w, _ = _scales(params)
    size = 0.0
    for i in range(5):
        size = max(size, abs(load[i]) * w[i])
    k_b, _ = table(params, K_B, params.free_angle)
    big = params.cos_azimuth.size * k_b * (0.05 * params.curvature_distance) ** 1.5
    lam = max(1.0, big / size) if size > 0.0 else 1.0
    if lam == 1.0:
        lam = 0.125  # a large load: come up to it from below instead
    u = initial_guess(load * lam, free, params)
    total = 0
    res = 0.0
    status = CONVERGED
    while True:
        u, res, its, status = newton(load * lam, free, params, u, tol, max_iter)
        total += its
        if status != CONVERGED or lam == 1.0:
            break
        lam = max(0.25 * lam, 1.0) if lam > 1.0 else min(2.0 * lam, 1.0)
    return u, res, total, status


@numba.njit(cache=True)
def solve_batch(loads, free, params, guesses, use_guess, tol, max_iter):
    """Equilibrium of every load case: Newton from the rigid-ring start (or ``guesses``), then continuation.

    Solves load + F(u) = 0 with F the ball-set resultant (source paper Eq. 14 and 16 in 5 DOF,
    Harris & Kotzalas 2007 Advanced Concepts Eq. 1.35-1.39) for each row of ``loads`` (n, 5)
    [N, N m]; ``free`` (5,) bool; returns displacement (n, 5), max scaled residual (n,) [N],
    iterations (n,) and status (n,) (:data:`CONVERGED` or the failure code).

    Examples
    --------
    >>> import numpy as np
    >>> from auxbearing import get_bearing
    >>> from auxbearing.bearings.ballset import ballset_params
    >>> u, res, its, status = solve_batch(np.array([[500.0, 1000.0, 0.0, 0.0, 0.0]]), np.ones(5, np.bool_),
    ...                                   ballset_params(get_bearing("QJ202")), np.zeros((1, 5)), False, 1e-9, 100)
    >>> int(status[0]), round(float(u[0, 1]) * 1e6, 2)
    (0, 12.5)
    """
    n = loads.shape[0]
    u = np.zeros((n, 5))
    res = np.zeros(n)
    its = np.zeros(n, dtype=np.int64)
    status = np.zeros(n, dtype=np.int64)
    for c in range(n):
        if use_guess:
            u0 = guesses[c].copy()
        else:
            u0 = initial_guess(loads[c], free, params)
        u[c], res[c], its[c], status[c] = newton(loads[c], free, params, u0, tol, max_iter)
        if status[c] != CONVERGED:
            u1, r1, i1, s1 = continuation(loads[c], free, params, tol, max_iter)
            u[c], res[c], its[c], status[c] = u1, r1, its[c] + i1, s1
    return u, res, its, status


class StaticSolution(NamedTuple):
    """Equilibrium of many load cases (SI)."""

    displacement: np.ndarray  #: (n, 5) [m, m, m, rad, rad]
    residual: np.ndarray  #: (n,) max residual [N], moments divided by r_ic
    relative_residual: np.ndarray  #: (n,) residual / largest applied load component
    iterations: np.ndarray  #: (n,) Newton iterations
    status: np.ndarray  #: (n,) 0 converged
