"""The generic compiled integrator (auxbearing.core.integrate.dopri5) on problems with exact answers.

Each problem is a compiled right-hand side and observer passed to the same loop the machine uses:
the harmonic oscillator (order of convergence), the Kepler problem (a closed orbit after one period,
energy and angular momentum), the Prothero-Robinson problem y' = lambda (y - g) + g' (exact solution
g; Hairer & Wanner, Solving ODEs II, Sec. IV.15) and an event located on the dense output.
"""

import math
import sys

import numba
import numpy as np
import pytest
from numba import njit

from auxbearing.core import cache_folder
from auxbearing.core import integrate as ig

# The test problems inline the core's integrator, so they are cached where the core's kernels are: in the
# folder named by the fingerprint of every core source (auxbearing.core). A change in the core gives a new
# folder and a recompilation; numba's own cache index watches this file. Compiling them afresh takes ~15 s.
# Functions passed as arguments are named as attributes of this module (``here.oscillator``): numba caches
# the caller then, not when they are plain global names (auxbearing.core.drive does the same).
_numba_cache_dir = numba.config.CACHE_DIR
numba.config.CACHE_DIR = cache_folder()
here = sys.modules[__name__]


@njit(cache=True)
def oscillator(t, y, model, out):
    out[0] = y[1]
    out[1] = -y[0]


@njit(cache=True)
def kepler(t, y, model, out):
    r3 = (y[0] ** 2 + y[1] ** 2) ** 1.5
    out[0] = y[2]
    out[1] = y[3]
    out[2] = -y[0] / r3
    out[3] = -y[1] / r3


@njit(cache=True)
def prothero_robinson(t, y, model, out):
    lam = model[0]
    out[0] = lam * (y[0] - math.sin(t)) + math.cos(t)


@njit(cache=True)
def nothing(t, h, y0, y1, coeff, model, obs):
    return 0


@njit(cache=True)
def height(y, model, arg):
    return -y[0]  # positive once the ball is below the floor


@njit(cache=True)
def stop_at_floor(t, h, y0, y1, coeff, model, obs):
    if y1[0] < 0.0 <= y0[0]:
        tmp = np.empty(y1.size)
        obs[0] = t + ig.dense_root(here.height, coeff, model, tmp, 0) * h
        return 1
    return 0


@njit(cache=True)
def run(rhs_id, observe_id, model, obs, y, t_end, settings, memory, grid):
    """The loop specialised for each test problem (named here: numba needs the functions at compile time)."""
    if observe_id == 1:
        return ig.dopri5(here.oscillator, here.stop_at_floor, model, obs, y, t_end, settings, memory, grid)
    if rhs_id == 0:
        return ig.dopri5(here.oscillator, here.nothing, model, obs, y, t_end, settings, memory, grid)
    if rhs_id == 1:
        return ig.dopri5(here.kepler, here.nothing, model, obs, y, t_end, settings, memory, grid)
    return ig.dopri5(here.prothero_robinson, here.nothing, model, obs, y, t_end, settings, memory, grid)


numba.config.CACHE_DIR = _numba_cache_dir  # numba picks the folder when a function is decorated


def _solve(rhs_id, y0, t_end, rtol, model=None, observe_id=0, n_out=0, output_step=1.0, max_step=1e9):
    model = np.zeros(1) if model is None else model
    y = np.array(y0, float)
    settings = ig.Settings(rtol, np.full(y.size, rtol), max_step, 1e-14, 10**7, output_step)
    memory = ig.new_memory(0.0, 1e-3, y.size)
    grid = np.empty((n_out, y.size))
    if n_out:
        grid[0] = y
        memory.next_output[0] = 1
    obs = np.zeros(1)
    status = run(rhs_id, observe_id, model, obs, y, t_end, settings, memory, grid)
    return y, status, memory, obs, grid


def test_harmonic_oscillator_converges_at_fifth_order():
    """Global error against rtol: DOPRI5's error per unit step ~ h^5 with h ~ rtol^(1/5), so the
    error falls about in proportion to rtol (Hairer et al., Solving ODEs I, Sec. II.4)."""
    errors = []
    for rtol in (1e-5, 1e-7, 1e-9):
        y, status, _memory, _, _ = _solve(0, [1.0, 0.0], 2.0 * math.pi, rtol)
        assert status == ig.FINISHED
        errors.append(math.hypot(y[0] - 1.0, y[1]))
    slope = np.polyfit(np.log10([1e-5, 1e-7, 1e-9]), np.log10(errors), 1)[0]
    assert 0.8 < slope < 1.2
    assert errors[-1] < 1e-8


def test_fixed_step_order_is_five():
    """With the step held fixed (huge rtol, max_step = h), halving h divides the error by about 2^5."""
    errors = []
    for h in (0.2, 0.1, 0.05):
        y, *_ = _solve(0, [1.0, 0.0], 2.0 * math.pi, 1e-2, max_step=h)
        errors.append(math.hypot(y[0] - 1.0, y[1]))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all(orders > 4.5) and np.all(orders < 6.5)


def test_kepler_orbit_closes_and_keeps_its_invariants():
    """Eccentricity 0.6, period 2 pi (mu = 1, a = 1): after one period the body is back at perihelion."""
    e = 0.6
    y0 = [1.0 - e, 0.0, 0.0, math.sqrt((1.0 + e) / (1.0 - e))]
    y, status, _memory, _, grid = _solve(1, y0, 2.0 * math.pi, 1e-11, n_out=101, output_step=2.0 * math.pi / 100)
    assert status == ig.FINISHED
    np.testing.assert_allclose(y, y0, atol=1e-8)
    energy = 0.5 * (grid[:, 2] ** 2 + grid[:, 3] ** 2) - 1.0 / np.hypot(grid[:, 0], grid[:, 1])
    momentum = grid[:, 0] * grid[:, 3] - grid[:, 1] * grid[:, 2]
    assert np.max(np.abs(energy + 0.5)) < 1e-8
    assert np.max(np.abs(momentum - math.sqrt(1.0 - e**2))) < 1e-8


def test_prothero_robinson_follows_the_exact_solution():
    """y' = lambda (y - sin t) + cos t, y(0) = 0 has y = sin t for any lambda; lambda = -50 is mildly stiff."""
    _y, status, _memory, _, grid = _solve(2, [0.0], 3.0, 1e-8, model=np.array([-50.0]), n_out=31, output_step=0.1)
    assert status == ig.FINISHED
    np.testing.assert_allclose(grid[:, 0], np.sin(np.arange(31) * 0.1), atol=1e-7)


def test_event_time_is_located_on_the_dense_output():
    """x(t) = cos t crosses zero at pi/2: the observer stops the run there (bisection on the dense output)."""
    _y, status, _memory, obs, _ = _solve(0, [1.0, 0.0], 10.0, 1e-9, observe_id=1)
    assert status == ig.STOPPED
    assert obs[0] == pytest.approx(math.pi / 2, abs=1e-8)


def test_step_budget_pauses_and_the_memory_resumes_exactly():
    y_all, *_ = _solve(0, [1.0, 0.0], 20.0, 1e-8)
    y = np.array([1.0, 0.0])
    settings = ig.Settings(1e-8, np.full(2, 1e-8), 1e9, 1e-14, 7, 1.0)
    memory = ig.new_memory(0.0, 1e-3, 2)
    grid = np.empty((0, 2))
    slices = 0
    while run(0, 0, np.zeros(1), np.zeros(1), y, 20.0, settings, memory, grid) == ig.PAUSED:
        slices += 1
    assert slices > 3
    np.testing.assert_array_equal(y, y_all)


def test_a_non_finite_right_hand_side_ends_with_step_underflow():
    _y, status, *_ = _solve(2, [0.0], 1.0, 1e-8, model=np.array([float("nan")]))
    assert status == ig.STEP_UNDERFLOW
