"""Invariants of the rotor drop: convergence, energy, rest, insensitivity to regularisation.

Issue 4 "Done when": peak collision force and peak stress change by < 1 % with a 10x tighter
tolerance; with friction, damping and unbalance off the mechanical energy stays constant; with
no unbalance the rotor comes to rest where statics puts it.
"""

import itertools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from auxbearing import get_bearing
from auxbearing.bearings.ballset import ballset_params, ballset_state
from auxbearing.core import drive
from auxbearing.core import integrate as ig
from auxbearing.core import machine as cm
from auxbearing.core import watch as cw
from auxbearing.machine.pack import pack
from auxbearing.planar import params as dp
from auxbearing.planar import rig
from auxbearing.planar.rig import planar_machine

BEARINGS = ("QJ202", "7202")


def _peaks(summary):
    return np.array([summary["peak_contact_force_N"], summary["peak_ball_stress_MPa"]])


@pytest.mark.slow
@pytest.mark.parametrize("name", BEARINGS)
def test_peaks_converge_as_the_tolerance_tightens(name):
    """Full 0.15 s Table II drop: rtol 1e-5 -> 1e-6 (default) -> 1e-7 change the peaks by < 1 %.

    Measured (QJ202): 657.075 / 657.091 / 657.091 N; changes ~1e-5 %. The paper's fixed 100 us
    RK4 step cannot be checked like this (NOTES item 7)."""
    out = []
    for tol in (1e-5, 1e-6, 1e-7):
        _, s = rig.run_drop(name, None, dp.DropCase(rtol=tol, atol=tol, output_step=1e-4))
        out.append(_peaks(s))
    for coarse, fine in itertools.pairwise(out):
        np.testing.assert_allclose(coarse, fine, rtol=1e-2)
    np.testing.assert_allclose(out[1], out[2], rtol=1e-4)  # much better than required


@pytest.mark.parametrize("name", BEARINGS)
def test_peaks_insensitive_to_the_friction_regularisation(name):
    """v_eps 10 mm/s (default) versus 1 mm/s: peaks agree to 0.1 % (measured ~1e-5 %)."""
    a = rig.run_drop(name, None, dp.DropCase(duration=0.04, output_step=1e-4))[1]
    b = rig.run_drop(name, None, dp.DropCase(duration=0.04, output_step=1e-4, slip_velocity=1e-3))[1]
    np.testing.assert_allclose(_peaks(a), _peaks(b), rtol=1e-3)
    assert a["race_spin_up_ms"] == pytest.approx(b["race_spin_up_ms"], abs=0.05)


def _energy_drift(name, clearance=2e-4, start=(0.0, 0.0), speed=628.0, tol=1e-9, duration=0.03):
    rotor = dp.Rotor(eccentricity=0.0)
    case = dp.DropCase(sliding_friction=0.0, rolling_friction=0.0, line_damping=0.0, ball_damping=0.0,
                       clearance=clearance, start_x=start[0], start_y=start[1], speed=speed,
                       duration=duration, output_step=1e-4, rtol=tol, atol=tol)
    km = pack(planar_machine(get_bearing(name), rotor, case))
    y = km.y0.copy()
    n = round(duration / 1e-4) + 1
    grid = np.empty((n, y.size))
    grid[0] = y
    memory = ig.new_memory(0.0, 1e-7, y.size)
    memory.next_output[0] = 1
    watch = cw.new_watch(y.size, len(km.machine.planes.active), 1.0, 2, km.energy0)
    assert drive.advance(km.machine, watch, y, duration, km.settings._replace(step_budget=10**9, output_step=1e-4),
                         memory, grid) == ig.FINISHED
    drift = max(abs(np.subtract(*cm.energy_balance(row, km.machine, km.energy0)[:2])) for row in grid)
    scale = rotor.mass * case.gravity * clearance  # the energy of the fall
    return drift / scale, {"impacts": int(watch.onsets[0])}


@pytest.mark.parametrize("name", BEARINGS)
def test_energy_is_conserved_without_friction_damping_and_unbalance(name):
    """Kinetic + gravity + line-contact strain + the work stored in the ball set over 30 ms with several
    impacts: drift below 1e-5 of m g s at rtol 1e-9."""
    drift, s = _energy_drift(name)
    assert s["impacts"] >= 3
    assert drift < 1e-5


@pytest.mark.slow
@settings(max_examples=4, deadline=None)
@given(clearance=st.floats(0.05e-3, 0.4e-3), frac=st.floats(0.0, 0.9), phase=st.floats(0, 2 * math.pi),
       name=st.sampled_from(BEARINGS))
def test_energy_conserved_from_any_start(clearance, frac, phase, name):
    start = (frac * clearance * math.cos(phase), frac * clearance * math.sin(phase))
    drift, _ = _energy_drift(name, clearance, start, tol=1e-9, duration=0.015)
    assert drift < 1e-5


@pytest.mark.parametrize("name", BEARINGS)
def test_rotor_comes_to_rest_where_statics_puts_it(name):
    """No unbalance, no spin, Table II damping: after 0.3 s the journal sits at
    y = y_b - s - (m_r g / K_l)^(9/10), with y_b from the ball set carrying (m_r + m_b) g."""
    bearing = get_bearing(name)
    rotor = dp.Rotor(eccentricity=0.0)
    case = dp.DropCase(speed=0.0, duration=0.3, output_step=1e-3)
    ds, _ = rig.run_drop(bearing, rotor, case)
    line_stiffness = planar_machine(bearing, rotor, case).planes[0].line_stiffness
    weight = (rotor.mass + case.race_mass) * case.gravity
    params = ballset_params(bearing)
    y_b = brentq(lambda y: ballset_state([0.0, 0.0, y, 0.0, 0.0], params).force[2] - weight, -1e-4, 0.0, xtol=1e-16)
    y_r = y_b - case.clearance - (rotor.mass * case.gravity / line_stiffness) ** 0.9
    assert ds.race_y.values[-1] == pytest.approx(y_b, abs=5e-9)
    assert ds.rotor_y.values[-1] == pytest.approx(y_r, abs=5e-9)
    assert abs(ds.rotor_x.values[-1]) < 1e-6  # at the bottom (rocking decays slowly)
    assert abs(ds.rotor_vy.values[-1]) < 1e-5
