"""too_short: the coast-down lengthens its windows where a steady motion's losses repeat slower than a window.

The beat below has the shape measured on the vertical rotor before its run-away (each plane's loss repeating every
four 10 ms windows by about +-40 %); the rule is the reduced model's own check, not a published number.
"""

from auxbearing.analysis.coastdown_phases import MAX_WINDOWS, MIN_WINDOWS, PlaneWindow, settled, too_short

BEAT = (0.33, 0.50, 0.25, 0.21)  # loss torque over four consecutive windows [N m], repeating


def _windows(torques, state="rolling"):
    window = PlaneWindow(state, 0, 1.0, 1500.0, 0.0, 1550.0, 1550.0, 1300.0, 0.0, (0.0, 0.0, 0.0))
    return [[window._replace(powers=(0.0, t * 1550.0, 0.0))] for t in torques]


def test_a_beat_slower_than_the_windows_never_settles_and_asks_for_longer_windows():
    beat = _windows(BEAT * (MAX_WINDOWS // len(BEAT)))
    assert settled(beat) is None
    assert too_short(beat)


def test_windows_that_average_the_beat_settle_and_stay_as_they_are():
    # a window four times as long holds a whole beat: its loss is the beat's mean
    mean = sum(BEAT) / len(BEAT)
    steady = _windows([mean] * MIN_WINDOWS)
    assert settled(steady) is not None
    assert not too_short(steady)


def test_only_a_full_set_of_windows_in_one_reducible_state_asks_for_longer_ones():
    assert not too_short(_windows(BEAT * 2))  # fewer than MAX_WINDOWS: the check goes on with more windows
    assert not too_short(_windows(BEAT * (MAX_WINDOWS // len(BEAT)), state="sliding"))


def test_a_journal_swinging_in_the_bottom_of_its_bore_keeps_its_windows():
    # a rolling pendulum repeats every 0.3 s: no window of a few tens of ms averages it
    swing = [[w[0]._replace(whirl_speed=0.004 * 1550.0)] for w in _windows(BEAT * (MAX_WINDOWS // len(BEAT)))]
    assert settled(swing) is None and not too_short(swing)
