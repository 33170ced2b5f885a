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
    from auxbearing.core import machine as cm

    session = _blower_session()
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


def _blower_session(seconds=0.002):
    from auxbearing.analysis.coastdown import _Session
    from auxbearing.analysis.drop import integrate_machine

    machine = read_machine("blower")
    return _Session(machine, integrate_machine(machine, seconds, None, None))


def _journal_velocities(session):
    from auxbearing.core import machine as cm

    y, a = session.y, np.asarray(session.core.planes.position[:2])
    return np.column_stack([y[cm.VX] + a * y[cm.WY], y[cm.VY] - a * y[cm.WX]])


def _plane_velocities(session, k):
    from auxbearing.core import machine as cm

    b = session.layout.plane(k)
    return session.y[[b + cm.RVX, b + cm.RVY, b + cm.OVX, b + cm.OVY]].copy()


def test_a_handover_gives_a_driven_journal_the_new_speeds_pace():
    """Every plane driven by the unbalance: journals, races, rings and the mass centre move Omega_1/Omega_0 as fast."""
    from auxbearing.core import machine as cm

    session = _blower_session()
    rotor = session.core.rotor
    journals, planes = _journal_velocities(session), [_plane_velocities(session, k) for k in range(2)]
    kin = cm.rotor_kinematics(session.y, rotor)
    om = session.y[cm.OMEGA]
    centre = np.array([session.y[cm.VX] + kin[0] * om, session.y[cm.VY] + kin[1] * om])
    assert np.abs(journals).max() > 1e-4  # the drop's journals still move
    ratio = 0.8
    omega = ratio * float(session.y[cm.OMEGA])
    session.set_speeds(omega, [0.0, 0.0], driven=[True, True])
    assert _journal_velocities(session) == pytest.approx(ratio * journals, rel=1e-12, abs=1e-15)
    for k in range(2):
        assert _plane_velocities(session, k) == pytest.approx(ratio * planes[k], rel=1e-12, abs=1e-15)
    kin = cm.rotor_kinematics(session.y, rotor)
    assert np.array([session.y[cm.VX] + kin[0] * omega, session.y[cm.VY] + kin[1] * omega]) == pytest.approx(
        ratio * centre, rel=1e-12, abs=1e-15)


def test_a_handover_leaves_a_resting_journal_its_swing_beside_a_driven_one():
    """Drive end driven, non-drive end at rest: each journal takes its own rule's velocity."""
    from auxbearing.core import machine as cm

    driven, resting = _blower_session(), _blower_session()
    journals, planes = _journal_velocities(driven), [_plane_velocities(driven, k) for k in range(2)]
    omega = 0.8 * float(driven.y[cm.OMEGA])
    driven.set_speeds(omega, [0.0, 0.0], driven=[True, False])
    resting.set_speeds(omega, [0.0, 0.0], driven=[False, False])  # the old rule on both planes
    assert _journal_velocities(driven)[0] == pytest.approx(0.8 * journals[0], rel=1e-12, abs=1e-15)
    assert _journal_velocities(driven)[1] == pytest.approx(_journal_velocities(resting)[1], rel=1e-12, abs=1e-15)
    assert _plane_velocities(driven, 0) == pytest.approx(0.8 * planes[0], rel=1e-12, abs=1e-15)
    assert np.array_equal(_plane_velocities(driven, 1), planes[1])


def test_a_single_plane_machine_scales_its_whole_rotor():
    """One plane driven (the paper rig): the rotor's lateral and tilt velocities all take the ratio."""
    from auxbearing.analysis.coastdown import _Session
    from auxbearing.analysis.drop import integrate_machine
    from auxbearing.core import machine as cm

    machine = read_machine("paper_rig")
    session = _Session(machine, integrate_machine(machine, 0.002, None, None))
    lateral = [cm.VX, cm.VY, cm.WX, cm.WY]
    before = session.y[lateral].copy()
    assert np.abs(before[:2]).max() > 1e-4
    session.set_speeds(0.7 * float(session.y[cm.OMEGA]), [0.0], driven=[True])
    assert session.y[lateral] == pytest.approx(0.7 * before, rel=1e-12, abs=1e-15)
