"""The coast-down windows' integrator (auxbearing.core.rk4) on problems with exact answers.

The tableau's order conditions, the order of the method and of its embedded estimate with the step held fixed,
the cubic Hermite dense output, the harmonic oscillator and the Prothero-Robinson problem (Hairer & Wanner,
Solving ODEs II, Sec. IV.15) under the step control, resuming after a paused call, and what the method is for:
on a stiff, lightly damped oscillation whose step is bound by stability it needs fewer right-hand-side
evaluations than Dormand-Prince for the same tolerance, and stays as accurate.
"""

import math
import sys
from fractions import Fraction as F

import numba
import numpy as np
import pytest
from numba import njit

from auxbearing.core import cache_folder
from auxbearing.core import integrate as ig
from auxbearing.core import rk4 as rk
from tests.unit.test_integrate import nothing, oscillator, prothero_robinson  # noqa: F401 (named as here.*)

_numba_cache_dir = numba.config.CACHE_DIR
numba.config.CACHE_DIR = cache_folder()  # as tests/unit/test_integrate.py: cached with the core's kernels
here = sys.modules[__name__]


@njit(cache=True)
def stiff_oscillation(t, y, model, out):
    """A slow unit oscillator (y0, y1) driving a fast, lightly damped one (y2, y3) of angular frequency model[0]."""
    w = model[0]
    out[0] = y[1]
    out[1] = -y[0]
    out[2] = y[3]
    out[3] = -w * w * (y[2] - y[0]) - 2.0 * 0.02 * w * y[3]


@njit(cache=True)
def run(rhs_id, method, model, obs, y, t_end, settings, memory, grid):
    if method == 0:
        if rhs_id == 0:
            return rk.rk4(here.oscillator, here.nothing, model, obs, y, t_end, settings, memory, grid)
        if rhs_id == 1:
            return rk.rk4(here.prothero_robinson, here.nothing, model, obs, y, t_end, settings, memory, grid)
        return rk.rk4(here.stiff_oscillation, here.nothing, model, obs, y, t_end, settings, memory, grid)
    return ig.dopri5(here.stiff_oscillation, here.nothing, model, obs, y, t_end, settings, memory, grid)


numba.config.CACHE_DIR = _numba_cache_dir


def _solve(rhs_id, y0, t_end, rtol, model=None, method=0, n_out=0, output_step=1.0, max_step=1e9, budget=10**7,
           memory=None, y=None):
    model = np.zeros(1) if model is None else model
    y = np.array(y0, float) if y is None else y
    settings = ig.Settings(rtol, np.full(y.size, rtol), max_step, 1e-14, budget, output_step)
    memory = ig.new_memory(0.0, 1e-3, y.size) if memory is None else memory
    grid = np.empty((n_out, y.size))
    if n_out:
        grid[0] = y
        memory.next_output[0] = 1
    status = run(rhs_id, method, model, np.zeros(1), y, t_end, settings, memory, grid)
    return y, status, memory, grid


def test_the_tableau_meets_the_order_conditions_of_both_solutions():
    """Fourth order for b (eight conditions), third order for the embedded b^ with the first-same-as-last stage
    (Hairer, Norsett & Wanner, Solving ODEs I, Sec. II.2), in exact fractions."""
    a = [[0] * 5 for _ in range(5)]
    a[1][0] = a[2][1] = F(1, 2)
    a[3][2] = F(1)
    a[4][:4] = [F(1, 6), F(1, 3), F(1, 3), F(1, 6)]
    c = [sum(row) for row in a]
    b = [F(1, 6), F(1, 3), F(1, 3), F(1, 6), F(0)]
    b_hat = [F(1, 6), F(1, 3), F(1, 3), F(0), F(1, 6)]
    ac = [sum(a[i][j] * c[j] for j in range(5)) for i in range(5)]
    aac = [sum(a[i][j] * ac[j] for j in range(5)) for i in range(5)]
    ac2 = [sum(a[i][j] * c[j] ** 2 for j in range(5)) for i in range(5)]

    def dot(w, v):
        return sum(x * y for x, y in zip(w, v, strict=True))

    for w in (b, b_hat):  # up to third order: both solutions
        assert sum(w) == 1
        assert dot(w, c) == F(1, 2)
        assert dot(w, [x * x for x in c]) == F(1, 3)
        assert dot(w, ac) == F(1, 6)
    fourth = [(dot(b, [x ** 3 for x in c]), F(1, 4)), (dot(b, [x * y for x, y in zip(c, ac, strict=True)]), F(1, 8)),
              (dot(b, ac2), F(1, 12)), (dot(b, aac), F(1, 24))]
    assert all(value == exact for value, exact in fourth)
    # the embedded solution is not fourth order (else its difference would estimate nothing): it misses b^ A c^2
    assert dot(b_hat, ac2) == F(7, 72) != F(1, 12)


def test_fixed_step_order_is_four():
    """With the step held fixed (huge rtol, max_step = h), halving h divides the global error by about 2^4."""
    errors = []
    for h in (0.2, 0.1, 0.05):
        y, *_ = _solve(0, [1.0, 0.0], 2.0 * math.pi, 1e-1, max_step=h)
        errors.append(math.hypot(y[0] - 1.0, y[1]))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(orders > 3.7) and np.all(orders < 4.3)


def test_the_dense_output_is_the_cubic_hermite_interpolant():
    """Exact for a cubic; third order on the oscillator (halving h divides the midpoint error by about 2^4,
    the interpolation error of a cubic Hermite being O(h^4) locally)."""
    coeff = np.empty((5, 1))
    out = np.empty(1)
    t = np.linspace(0.0, 1.0, 7)
    p = 2.0 * t ** 3 - t ** 2 + 0.5 * t + 1.0
    rk.hermite_coefficients(np.array([p[0]]), np.array([p[-1]]), 1.0, np.array([0.5]), np.array([6.0 - 2.0 + 0.5]),
                            coeff)
    for theta, value in zip(t, p, strict=True):
        ig.dense_eval(coeff, theta, out)
        assert out[0] == pytest.approx(value, abs=1e-14)
    errors = []
    for h in (0.4, 0.2, 0.1):
        rk.hermite_coefficients(np.array([1.0]), np.array([math.cos(h)]), h, np.array([0.0]),
                                np.array([-math.sin(h)]), coeff)
        ig.dense_eval(coeff, 0.5, out)
        errors.append(abs(out[0] - math.cos(0.5 * h)))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(orders > 3.7)


def test_the_step_control_reaches_the_tolerance_on_the_oscillator():
    errors = []
    for rtol in (1e-6, 1e-8, 1e-10):
        y, status, memory, _ = _solve(0, [1.0, 0.0], 2.0 * math.pi, rtol)
        assert status == ig.FINISHED
        errors.append(math.hypot(y[0] - 1.0, y[1]))
        assert memory.evaluations[0] == 1 + 4 * (memory.steps[0] + memory.rejected[0])
    assert errors[-1] < 1e-8
    assert errors[0] > errors[1] > errors[2]


def test_prothero_robinson_follows_the_exact_solution():
    _y, status, _memory, grid = _solve(1, [0.0], 3.0, 1e-8, model=np.array([-50.0]), n_out=31, output_step=0.1)
    assert status == ig.FINISHED
    np.testing.assert_allclose(grid[:, 0], np.sin(np.arange(31) * 0.1), atol=1e-7)


def test_step_budget_pauses_and_the_memory_resumes_exactly():
    y_all, *_ = _solve(0, [1.0, 0.0], 20.0, 1e-8)
    y = np.array([1.0, 0.0])
    memory = ig.new_memory(0.0, 1e-3, 2)
    slices = 0
    while _solve(0, None, 20.0, 1e-8, budget=7, memory=memory, y=y)[1] == ig.PAUSED:
        slices += 1
    assert slices > 3
    np.testing.assert_array_equal(y, y_all)


def test_a_non_finite_right_hand_side_ends_with_step_underflow():
    _y, status, *_ = _solve(1, [0.0], 1.0, 1e-8, model=np.array([float("nan")]))
    assert status == ig.STEP_UNDERFLOW


def test_a_stability_bound_step_costs_fewer_evaluations_than_dormand_prince():
    """The fast oscillator (2e4 rad/s, 2 % damped) follows the slow one quasi-statically: both methods' steps sit on
    their stability bounds, and the classical method's reaches further per evaluation (module docstring of
    auxbearing.core.rk4). Same tolerance; both end within it of the exact slow solution."""
    model = np.array([2e4])
    results = {}
    for method in (0, 1):
        y, status, memory, _ = _solve(2, [1.0, 0.0, 1.0, 0.0], 1.0, 1e-6, model=model, method=method)
        assert status == ig.FINISHED
        assert math.hypot(y[0] - math.cos(1.0), y[1] + math.sin(1.0)) < 1e-5
        results[method] = int(memory.evaluations[0])
    assert results[0] < 0.8 * results[1], results
