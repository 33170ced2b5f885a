"""stretch_growth and calm: a coast-down's stretches grow, where the windows measure steady states, while the
torques they hold do not move, and shrink when they do.

The windows are the shape of the blower's drive end rolling at low speed (a loss of about 0.02 N m); the rule is
the issue's physics check on the reduced model's own assumption (held torques), not a published number.
"""

from auxbearing.analysis.coastdown_phases import (
    MAX_GROWTH,
    MAX_SPEED_FALL,
    STATIONARY,
    PlaneWindow,
    calm,
    quiet_orbits,
    stretch_growth,
)
from auxbearing.machine.files import read_machine

BLOWER = read_machine("blower")


def _planes(contact=0.8, state="rolling"):
    """Both planes rolling at 600 rpm: contact, bearing and mount powers [W]."""
    window = PlaneWindow(state, 0, 1.0, 130.0, 0.0, 62.8, 170.0, 0.0, 0.0, (contact, 0.4, 0.05))
    return [window, window._replace(powers=(0.5, 0.3, 0.03))]


def test_steps_double_up_to_their_limit_while_the_held_torques_stay():
    growth = 1.0
    seen = []
    for _ in range(4):
        growth = stretch_growth(growth, _planes(), _planes(contact=0.8 * (1.0 + 0.2 * STATIONARY)), BLOWER)
        seen.append(growth)
    assert seen == [2.0, 4.0, MAX_GROWTH, MAX_GROWTH]


def test_a_held_torque_that_moved_beyond_the_windows_scatter_brings_the_steps_back():
    before = _planes()
    total = sum(before[0].powers) / before[0].rotor_speed
    moved = 1.3 * STATIONARY * total * before[0].rotor_speed  # contact power that moves the loss by 2.6 %
    assert stretch_growth(4.0, before, _planes(contact=0.8 + moved), BLOWER) == 1.0


def test_a_change_between_the_two_bounds_keeps_the_steps():
    before = _planes()
    total_power = sum(before[0].powers)
    after = _planes(contact=0.8 + 0.8 * STATIONARY * total_power)
    assert stretch_growth(2.0, before, after, BLOWER) == 2.0


def test_a_change_of_state_brings_the_steps_back():
    assert stretch_growth(4.0, _planes(), _planes(state="whirling"), BLOWER) == 1.0
    # rolling and rattling are one family for the reduced model: that is no change
    assert stretch_growth(1.0, _planes(), _planes(state="rattling"), BLOWER) == 2.0


def test_the_default_speed_step_grown_stays_below_the_largest_fall():
    assert MAX_GROWTH * BLOWER.coastdown.speed_step <= MAX_SPEED_FALL


def test_only_steady_states_let_a_stretch_grow():
    """A rattle or a swing is sampled by the windows; a journal sitting in its rolling race, a steady backward
    whirl or a free race is not."""
    planes = _planes()
    quiet = quiet_orbits(BLOWER, planes)
    still = [p._replace(orbit_speed_sq=0.5 * q) for p, q in zip(planes, quiet, strict=True)]
    assert calm(BLOWER, [still, still])
    assert calm(BLOWER, [[still[0], still[1]._replace(state="free")], [still[0]._replace(state="whirling"), still[1]]])
    swinging = [still[0]._replace(orbit_speed_sq=2.0 * quiet[0]), still[1]]
    assert not calm(BLOWER, [still, swinging])
    rattling = [still[0], still[1]._replace(state="rattling")]
    assert not calm(BLOWER, [rattling, still])
