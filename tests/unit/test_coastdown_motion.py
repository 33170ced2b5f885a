"""motion_steady: a coast-down's reduced stretch waits until the journals' motion no longer changes.

The series below have the shape measured on the blower's drive end after the drop (mean square orbit speed over
0.25 s: 7e-4, 4e-4, 1.7e-4, 1.5e-4, 2.5e-4, then 4.7e-4 m^2/s^2 steady); the rule itself is the issue's physics
check, not a published number.
"""

import numpy as np

from auxbearing.analysis.coastdown_phases import (
    QUIET_LOAD,
    QUIET_ORBIT,
    STEADY_MOTION,
    STEADY_SPANS,
    STEADY_TREND,
    PlaneWindow,
    motion_steady,
    quiet_orbits,
)

SPAN = 30  # windows in a span


def _windows(values, planes=1):
    window = PlaneWindow("rattling", 0, 1.0, 50.0, 0.0, 1800.0, 1790.0, 0.0, 0.0, (1.0, 1.0, 0.0))
    return [[window._replace(orbit_speed_sq=float(v))] * planes for v in values]


def _noisy(mean, n, rng, scatter=0.3):
    return mean * (1.0 + scatter * rng.standard_normal(n)).clip(0.05)


def test_a_steady_rattle_is_steady():
    rng = np.random.default_rng(1)
    assert motion_steady(_windows(_noisy(4.7e-4, STEADY_SPANS * SPAN, rng)), SPAN)


def test_too_few_windows_are_never_steady():
    assert not motion_steady(_windows([4.7e-4] * (STEADY_SPANS * SPAN - 1)), SPAN)
    assert not motion_steady(_windows([4.7e-4] * 10), 0)


def test_a_swing_building_up_is_not_steady():
    values = np.concatenate([np.full(SPAN, 1.5e-4), np.full(SPAN, 2.5e-4), np.full(SPAN, 4.7e-4)])
    assert not motion_steady(_windows(values), SPAN)


def test_a_bounce_dying_out_then_a_swing_building_up_is_not_steady_where_they_meet():
    """Two spans either side of the trough agree (1.2e-4 each); the third shows the change."""
    values = np.concatenate([np.full(SPAN, 4.0e-4), np.linspace(2.0e-4, 0.4e-4, SPAN),
                             np.linspace(0.4e-4, 2.0e-4, SPAN)])
    halves = [values[SPAN:2 * SPAN].mean(), values[2 * SPAN:].mean()]
    assert abs(halves[0] - halves[1]) <= STEADY_MOTION * max(halves)  # two spans alone would pass
    assert not motion_steady(_windows(values), SPAN)


def test_a_transient_dying_out_slowly_is_not_steady():
    """The compressor's coupling end after its drop: the orbit speed falls by about 7 % a span for seconds.

    Every span is within STEADY_MOTION of the largest; the first and last differ by more than STEADY_TREND.
    """
    values = np.concatenate([np.full(SPAN, 2.07e-4 * 0.93**j) for j in range(STEADY_SPANS)])
    means = values.reshape(STEADY_SPANS, SPAN).mean(axis=1)
    assert means.max() - means.min() <= STEADY_MOTION * means.max()
    assert means[0] - means[-1] > STEADY_TREND * means.max()
    assert not motion_steady(_windows(values), SPAN)


def test_a_steady_rattle_with_span_to_span_scatter_is_steady():
    """Scatter without a trend (a middle span off by 15 %) passes: only a drift from first to last fails."""
    values = np.concatenate([np.full(SPAN, 4.7e-4), np.full(SPAN, 4.7e-4 * 0.85), np.full(SPAN, 4.7e-4 * 0.97)])
    assert motion_steady(_windows(values), SPAN)


def test_a_drift_the_slowing_rotor_explains_is_steady():
    """A rotor losing 9 % of its speed over the spans: a motion locked to it loses 17 % of its mean square speed."""
    omega = np.linspace(1800.0, 1800.0 * 0.91, STEADY_SPANS * SPAN)
    values = 4.7e-4 * (omega / omega[0]) ** 2
    windows = [[w[0]._replace(rotor_speed=float(o))] for w, o in zip(_windows(values), omega, strict=True)]
    assert motion_steady(windows, SPAN)
    assert not motion_steady(_windows(values), SPAN)  # the same drift at a steady speed is a transient


def test_every_plane_must_be_steady():
    steady = [[w[0], w[0]._replace(orbit_speed_sq=v)] for w, v in
              zip(_windows([4.7e-4] * (3 * SPAN)), np.linspace(1e-4, 4e-4, 3 * SPAN), strict=True)]
    assert not motion_steady(steady, SPAN)


def test_a_journal_at_rest_in_its_bore_is_steady():
    values = np.linspace(0.0, 0.5 * QUIET_ORBIT, STEADY_SPANS * SPAN)
    assert motion_steady(_windows(values, planes=2), SPAN)


def test_a_swing_dying_out_below_the_quiet_level_is_steady():
    """The blower at low speed: its swing halves every 0.5 s while the journals roll; a load of 130 N, 0.2 mm."""
    from types import SimpleNamespace

    machine = SimpleNamespace(rotor=SimpleNamespace(mass=20.0), planes=[SimpleNamespace(radial_clearance=2e-4)])
    quiet = quiet_orbits(machine, _windows([0.0])[0][:1])[0]  # the window's mean force is 50 N
    assert quiet == QUIET_LOAD * 50.0 * 2e-4 / 20.0
    dying = quiet * 0.9 * 0.5 ** np.linspace(0.0, 2.0, STEADY_SPANS * SPAN)
    assert not motion_steady(_windows(dying), SPAN)  # a trend the range and drift tests refuse
    assert motion_steady(_windows(dying), SPAN, [quiet])
    assert not motion_steady(_windows(dying * 2.0), SPAN, [quiet])  # above it, the motion still matters


def test_a_run_that_carried_a_rattle_says_how_far_its_damage_may_be_off():
    from auxbearing.analysis.coastdown import RATTLE_DAMAGE_RANGE, RATTLE_DAMAGE_RANGE_TO_STANDSTILL, rattle_note

    assert rattle_note({"reduced_plane_states": {"rolling": 12, "free": 3}}) == ""
    assert rattle_note({}) == ""
    states = {"reduced_plane_states": {"rolling": 40, "rattling": 208}}
    for until_stop, (low, high), span in ((False, RATTLE_DAMAGE_RANGE, "first 30 s"),
                                          (True, RATTLE_DAMAGE_RANGE_TO_STANDSTILL, "to standstill")):
        note = rattle_note(states | {"until_stop": until_stop})
        assert "208 of 248 plane-stretches" in note
        assert span in note
        assert f"{100 * low:+.1f} %" in note and f"{100 * high:+.1f} %" in note
