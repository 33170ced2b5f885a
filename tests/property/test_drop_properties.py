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
from auxbearing import drop as ad
from auxbearing.core import drop as cd
from auxbearing.core.ballset import radial_support

BEARINGS = ("QJ202", "7202")
_COLUMNS = ("rotor_x", "rotor_y", "rotor_angle", "race_x", "race_y", "race_angle", "rotor_vx", "rotor_vy",
            "rotor_speed", "race_vx", "race_vy", "race_speed")


def _peaks(summary):
    return np.array([summary["peak_contact_force_N"], summary["peak_ball_stress_MPa"]])


@pytest.mark.parametrize("name", BEARINGS)
def test_peaks_converge_as_the_tolerance_tightens(name):
    """Full 0.15 s Table II drop: rtol 1e-5 -> 1e-6 (default) -> 1e-7 change the peaks by < 1 %.

    Measured (QJ202): 657.075 / 657.091 / 657.091 N; changes ~1e-5 %. The paper's fixed 100 us
    RK4 step cannot be checked like this (NOTES item 7)."""
    out = []
    for tol in (1e-5, 1e-6, 1e-7):
        _, s = ad.run_drop(name, None, ad.DropCase(rtol=tol, atol=tol, output_step=1e-4))
        out.append(_peaks(s))
    for coarse, fine in itertools.pairwise(out):
        np.testing.assert_allclose(coarse, fine, rtol=1e-2)
    np.testing.assert_allclose(out[1], out[2], rtol=1e-4)  # much better than required


@pytest.mark.parametrize("name", BEARINGS)
def test_peaks_insensitive_to_the_friction_regularisation(name):
    """v_eps 10 mm/s (default) versus 1 mm/s: peaks agree to 0.1 % (measured ~1e-5 %)."""
    a = ad.run_drop(name, None, ad.DropCase(duration=0.04, output_step=1e-4))[1]
    b = ad.run_drop(name, None, ad.DropCase(duration=0.04, output_step=1e-4, slip_velocity=1e-3))[1]
    np.testing.assert_allclose(_peaks(a), _peaks(b), rtol=1e-3)
    assert a["race_spin_up_ms"] == pytest.approx(b["race_spin_up_ms"], abs=0.05)


def _energy_drift(name, clearance=2e-4, start=(0.0, 0.0), speed=628.0, tol=1e-9, duration=0.03):
    rotor = ad.Rotor(eccentricity=0.0)
    case = ad.DropCase(sliding_friction=0.0, rolling_friction=0.0, line_damping=0.0, ball_damping=0.0,
                       clearance=clearance, start_x=start[0], start_y=start[1], speed=speed,
                       duration=duration, output_step=1e-4, rtol=tol, atol=tol)
    bearing = get_bearing(name)
    ds, s = ad.run_drop(bearing, rotor, case)
    model = ad.build_model(bearing, rotor, case)
    states = np.stack([ds[c].values for c in _COLUMNS], axis=1)
    energy = cd.mechanical_energy(states, model.params, model.ballset, 400)
    scale = rotor.mass * case.gravity * clearance  # the energy of the fall
    return float(np.abs(energy - energy[0]).max() / scale), s


@pytest.mark.parametrize("name", BEARINGS)
def test_energy_is_conserved_without_friction_damping_and_unbalance(name):
    """Kinetic + gravity + line-contact strain + ball-set strain energy over 30 ms with several
    impacts: drift below 1e-5 of m g s at rtol 1e-9 (measured ~1e-7 for QJ202)."""
    drift, s = _energy_drift(name)
    assert s["impacts"] >= 3
    assert drift < 1e-5


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
    rotor = ad.Rotor(eccentricity=0.0)
    case = ad.DropCase(speed=0.0, duration=0.3, output_step=1e-3)
    ds, _ = ad.run_drop(bearing, rotor, case)
    model = ad.build_model(bearing, rotor, case)
    weight = (rotor.mass + case.race_mass) * case.gravity
    y_b = brentq(lambda y: radial_support(0.0, y, model.ballset)[1] - weight, -1e-4, 0.0, xtol=1e-16)
    y_r = y_b - case.clearance - (rotor.mass * case.gravity / model.line_stiffness) ** 0.9
    assert ds.race_y.values[-1] == pytest.approx(y_b, abs=5e-9)
    assert ds.rotor_y.values[-1] == pytest.approx(y_r, abs=5e-9)
    assert abs(ds.rotor_x.values[-1]) < 1e-6  # at the bottom (rocking decays slowly)
    assert abs(ds.rotor_vy.values[-1]) < 1e-5
