"""Backward whirl after the drop: the coast-down tracks it as a drop does, and the verdict's whirl criterion sees it."""

from types import SimpleNamespace

import pytest

from auxbearing.analysis.coastdown_phases import BackwardWhirl
from auxbearing.analysis.whirl import SUSTAINED
from auxbearing.verify.judge import _sustained_whirl


def _window(*classes, state="unsettled"):
    return SimpleNamespace(whirl_classes=tuple(classes), state=state)


def test_a_backward_run_counts_once_it_is_sustained_across_windows():
    assert SUSTAINED == 3  # the drop's rule: three backward whirl windows in a row
    track = BackwardWhirl(1)
    track.window([_window("forward", "backward")], t_end=1.02, length=0.02)
    assert track.onset == [None]
    track.window([_window("backward_rolling", "backward_rolling")], t_end=1.04, length=0.02)
    # the third backward whirl window in a row (the second of this check window) makes it sustained; the run
    # began with the last of the first check window, at 1.01 s, and has lasted to 1.04 s
    assert track.onset[0] == pytest.approx(1.01)
    assert track.seconds[0] == pytest.approx(0.03)
    track.window([_window("forward")], t_end=1.06, length=0.02)
    track.window([_window("backward", "backward")], t_end=1.08, length=0.02)
    assert track.seconds[0] == pytest.approx(0.03)  # broken by a forward window, not yet sustained again
    track.window([_window("backward")], t_end=1.10, length=0.02)
    assert track.seconds[0] == pytest.approx(0.03 + 3 * 0.02) and track.onset[0] == pytest.approx(1.01)


def test_a_stretch_in_steady_backward_rolling_whirl_carries_it():
    track = BackwardWhirl(2)
    track.stretch([_window(state="rolling"), _window(state="whirling")], t_start=5.0, duration=3.0)
    assert track.onset == [None, 5.0] and track.seconds == [0.0, 3.0]


def _cases(coast_planes):
    drop = SimpleNamespace(summary={"verdict": "ok", "planes": [
        {"name": "drive end", "backward_whirl_onset_ms": None, "whirl": "none"}]})
    return SimpleNamespace(drops={"drop at the maximum speed": drop},
                           coastdown=SimpleNamespace(summary={"planes": coast_planes}))


def test_the_whirl_criterion_fails_on_a_backward_whirl_in_the_coast_down():
    quiet = _sustained_whirl(_cases([{"name": "drive end", "backward_whirl_from_s": None}]))
    assert quiet.passed is True and quiet.found == "none"
    c = _sustained_whirl(_cases([{"name": "drive end", "backward_whirl_from_s": 45.6, "backward_whirl_s": 12.3}]))
    assert c.passed is False
    assert c.found == "coast-down, drive end: backward whirl sustained from 45.60 s, 12.30 s of it"
