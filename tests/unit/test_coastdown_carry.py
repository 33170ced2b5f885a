"""The coast-down carries each race across a step of its bearing's internal clearance at the force it had.

Thermal growth changes a ball set's diametral clearance in steps (after each window and each reduced stretch);
the race is moved to where the balls push it as they did (analysis.coastdown._race_carry), so the step adds no
jolt. Self-consistency: the ball-set law before and after the step.
"""

import numpy as np
import pytest

from auxbearing.analysis.coastdown import _ballset_radial, _race_carry
from auxbearing.machine.files import read_machine
from auxbearing.machine.pack import pack


def _core(case="blower"):
    return pack(read_machine(case)).machine


@pytest.mark.parametrize(("clearance_um", "step_um"), [(20.0, -1.0), (20.0, 1.0), (-20.0, -1.0), (-20.0, 1.0)])
def test_the_race_keeps_its_ball_force_across_a_clearance_step(clearance_um, step_um):
    core = _core()
    before = core._replace(ballset_clearance=np.full_like(core.ballset_clearance, clearance_um * 1e-6))
    after = core._replace(ballset_clearance=before.ballset_clearance + step_um * 1e-6)
    d = np.array([0.3e-6, -1.5e-6]) + (0.5 * max(clearance_um, 0.0) * 1e-6) * np.array([0.2, -0.98])
    force = _ballset_radial(before, 0, 0.0, d)
    assert np.hypot(*force) > 10.0  # loaded
    moved = _race_carry(before, after, 0, 0.0, d)
    assert _ballset_radial(after, 0, 0.0, moved) == pytest.approx(force, rel=1e-9, abs=1e-9)
    half = 0.5 * abs(step_um) * 1e-6
    if clearance_um > 0.0:  # in clearance: about the old rule, half the change along the load
        assert np.hypot(*(moved - d)) == pytest.approx(half, rel=0.3)
    else:  # preloaded: both sides compressed, the race hardly moves
        assert np.hypot(*(moved - d)) < 0.2 * half


def test_an_unloaded_race_keeps_its_gap_to_the_balls():
    core = _core()
    before = core._replace(ballset_clearance=np.full_like(core.ballset_clearance, 40e-6))
    after = core._replace(ballset_clearance=before.ballset_clearance - 2e-6)
    d = np.array([0.0, -5e-6])
    assert np.hypot(*_ballset_radial(before, 0, 0.0, d)) == 0.0
    # half the 2 um the clearance closed, along d: towards the centre
    assert _race_carry(before, after, 0, 0.0, d) == pytest.approx(np.array([0.0, -4e-6]), abs=1e-15)


def test_a_handover_keeps_the_mass_centres_momentum_and_the_principal_axis_turning():
    from auxbearing.analysis.coastdown import _Session
    from auxbearing.analysis.drop import integrate_machine
    from auxbearing.core import machine as cm

    machine = read_machine("blower")
    session = _Session(machine, integrate_machine(machine, 0.002, None, None))
    rotor = session.core.rotor
    rotor = rotor._replace(unbalance=2e-5, couple_unbalance=1e-4)  # both unbalances, large enough to see
    session.core = session.core._replace(rotor=rotor)

    def momenta(y):
        kin = cm.rotor_kinematics(y, rotor)
        om = y[cm.OMEGA]
        return np.array([y[cm.VX] + kin[0] * om, y[cm.VY] + kin[1] * om, kin[8], kin[9]])

    before = momenta(session.y.copy())
    omega = 0.9 * float(session.y[cm.OMEGA])
    session.set_speeds(omega, [0.9 * float(session.y[cm.N_ROTOR + k * cm.N_PLANE + cm.ROMEGA]) for k in range(2)])
    assert session.y[cm.OMEGA] == omega
    assert momenta(session.y) == pytest.approx(before, rel=1e-12, abs=1e-15)
