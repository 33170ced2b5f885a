"""confirmed and StretchEnd.close: one window after a stretch carries the next where it finds steady states whose
torques the stretch held, and a stretch charged before all its measuring windows came is charged at those it has.

The windows are the shape of the blower's drive end rolling at low speed, as in test_coastdown_stretch_growth; the
rule is the physics check on the reduced model's own assumption (the torques it held), not a published number.
"""

import pytest

from auxbearing.analysis.coastdown_phases import (
    STATIONARY,
    PlaneWindow,
    StretchEnd,
    confirmed,
    quiet_orbits,
    stretch_load,
)
from auxbearing.machine.files import read_machine

BLOWER = read_machine("blower")


def _still(contact=0.8, state="rolling", load=100.0):
    """Both planes rolling quietly at 600 rpm: contact, bearing and mount powers [W]."""
    window = PlaneWindow(state, 0, 1.0, 130.0, 0.0, 62.8, 170.0, 0.0, 0.0, (contact, 0.4, 0.05), load=load)
    planes = [window, window._replace(powers=(0.5, 0.3, 0.03), load=0.5 * load)]
    quiet = quiet_orbits(BLOWER, planes)
    return [p._replace(orbit_speed_sq=0.5 * q) for p, q in zip(planes, quiet, strict=True)]


def test_a_window_that_finds_the_held_torques_carries_the_next_stretch():
    held = _still()
    after = _still(contact=0.8 * (1.0 + 0.2 * STATIONARY))
    assert confirmed(BLOWER, held, [after]) == after


def test_a_moved_torque_a_motion_or_a_changed_state_leaves_it_to_the_windows():
    held = _still()
    total_power = sum(held[0].powers)
    assert confirmed(BLOWER, held, [_still(contact=0.8 + 0.8 * STATIONARY * total_power)]) is None
    swinging = _still()
    swinging[0] = swinging[0]._replace(orbit_speed_sq=2.0 * quiet_orbits(BLOWER, swinging)[0])
    assert confirmed(BLOWER, held, [swinging]) is None
    assert confirmed(BLOWER, held, [_still(state="whirling")]) is None
    # a rattle is sampled by its windows: its mean needs them all, even where one agrees
    assert confirmed(BLOWER, _still(state="rattling"), [_still(state="rattling")]) is None


def test_only_the_first_window_after_a_stretch_and_only_after_one():
    assert confirmed(BLOWER, None, [_still()]) is None
    assert confirmed(BLOWER, _still(), [_still(), _still()]) is None


def test_a_stretch_cut_short_is_charged_at_the_windows_it_has():
    overrolling = [[(1000.0, 100.0)], [(1000.0, 50.0)]]
    ending = StretchEnd(_still(), [0, 0])
    assert not ending.measure(_still(load=120.0), overrolling)
    ending.close(overrolling)
    assert overrolling[0][0] == (1000.0, pytest.approx(stretch_load(100.0, 120.0), rel=1e-14))
    assert overrolling[1][0] == (1000.0, pytest.approx(stretch_load(50.0, 60.0), rel=1e-14))
    untouched = [[(1000.0, 100.0)], [(1000.0, 50.0)]]
    StretchEnd(_still(), [0, 0]).close(untouched)
    assert untouched == [[(1000.0, 100.0)], [(1000.0, 50.0)]]
