"""The rolling pendulum's passages: where a coast-down keeps a swinging journal in full dynamics.

The frequencies are checked against the simple pendulum of length c (Thomson & Dahleh, *Theory of Vibration with
Applications*, 5th ed., Ch. 2), which the swing stiffness reduces to on a rigid support; the rest are the
coast-down's own rules (:mod:`auxbearing.analysis.coastdown_phases`).
"""

import math

import pytest

from auxbearing.analysis import coastdown_phases as phases
from auxbearing.analysis.coastdown_phases import (
    PASSAGE_BAND,
    PASSAGE_ORDERS,
    PASSAGE_SWING,
    PlaneWindow,
    next_passage_top,
    passage_at,
    pendulum_frequencies,
    pendulum_passages,
    pendulum_swinging,
    resting,
)
from auxbearing.machine.files import read_machine


def test_a_journal_on_a_stiff_ball_set_swings_as_a_pendulum_of_length_c():
    rig = read_machine("paper_rig")  # no mount: the ball set alone is in series with W / c
    plane = rig.planes[0]
    simple = math.sqrt(rig.simulation.gravity / plane.radial_clearance)
    (omega,) = pendulum_frequencies(rig)
    assert omega == pytest.approx(simple, rel=0.01)
    assert omega < simple  # a support in series only softens the swing


def test_the_blower_swings_near_its_campbell_frequency_in_contact():
    # 40.3 Hz from the Campbell diagram in contact (auxbearing.analysis.modes), the mounts in series
    for omega in pendulum_frequencies(read_machine("blower")):
        assert omega / (2.0 * math.pi) == pytest.approx(40.3, abs=0.1)


def test_a_vertical_rotor_rests_on_no_plane_and_has_no_passage():
    vertical = read_machine("vertical")
    assert pendulum_frequencies(vertical) == [0.0] * len(vertical.planes)
    assert pendulum_passages(vertical, 1e4) == []


def test_the_passages_are_bands_below_each_order_fastest_first():
    rig = read_machine("paper_rig")
    (omega,) = pendulum_frequencies(rig)
    bands = pendulum_passages(rig, 1e6)
    assert len(bands) == PASSAGE_ORDERS
    for (low, high), n in zip(bands, range(PASSAGE_ORDERS, 0, -1), strict=True):
        assert [low, high] == pytest.approx([PASSAGE_BAND[0] * n * omega, PASSAGE_BAND[1] * n * omega])
    # only the passages a coast-down from this speed reaches
    assert pendulum_passages(rig, 1.2 * omega) == bands[-1:]


def test_overlapping_bands_of_two_planes_merge(monkeypatch):
    monkeypatch.setattr(phases, "pendulum_frequencies", lambda machine: [100.0, 110.0])
    low, high = PASSAGE_BAND
    # each order's two bands overlap; the orders' do not (3 x 0.7 x 100 lies above 2 x 0.95 x 110)
    bands = pendulum_passages(None, 1e4)
    assert [x for band in bands for x in band] == pytest.approx(
        [3 * low * 100.0, 3 * high * 110.0, 2 * low * 100.0, 2 * high * 110.0, low * 100.0, high * 110.0])


def test_a_stretch_ends_at_the_next_passage_below():
    bands = [(400.0, 500.0), (200.0, 300.0)]
    assert passage_at(bands, 450.0) == (400.0, 500.0)
    assert passage_at(bands, -250.0) == (200.0, 300.0)  # either direction of spin
    assert passage_at(bands, 350.0) is None
    assert next_passage_top(bands, 600.0) == 500.0
    assert next_passage_top(bands, 450.0) == 300.0
    assert next_passage_top(bands, 150.0) == 0.0


def _windows(contact, orbit_speed_sq, count=30):
    window = PlaneWindow("rolling", 0, contact, 14.6, 0.0, 400.0, 800.0, 0.0, 0.0, (0.0, 0.0, 0.0),
                         orbit_speed_sq=orbit_speed_sq)
    return [[window]] * count


def test_only_a_journal_that_came_to_rest_and_swings_near_a_lift_off_is_swinging():
    rig = read_machine("paper_rig")
    lift_off = rig.simulation.gravity * rig.planes[0].radial_clearance  # mean square speed of a swing to the side
    big, small = _windows(1.0, 1.2 * PASSAGE_SWING * lift_off), _windows(1.0, 0.8 * PASSAGE_SWING * lift_off)
    calm = small[:3]
    assert pendulum_swinging(rig, big, calm, [True], None)
    assert not pendulum_swinging(rig, small, calm, [True], (100.0, 200.0))
    # a journal the unbalance has kept lifting off since the drop is no pendulum, whatever its motion
    assert not pendulum_swinging(rig, big, calm, [False], None)


def test_a_resting_journal_that_bounces_in_a_passage_is_not_carried():
    rig = read_machine("paper_rig")
    small = _windows(1.0, 0.0)
    struck = [[small[0][0]._replace(onsets=2, contact=0.95)], *small[:2]]
    assert pendulum_swinging(rig, small, struck, [True], (100.0, 200.0))
    assert not pendulum_swinging(rig, small, struck, [True], None)  # outside a passage a rattle may be carried
    assert not pendulum_swinging(rig, small, struck, [False], (100.0, 200.0))


def test_a_journal_rests_when_in_contact_nearly_all_the_time():
    assert resting(_windows(0.995, 0.0)) == [True]
    assert resting(_windows(0.9, 0.0)) == [False]
