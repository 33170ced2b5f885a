"""The s0 criterion counts a drop cut short up to where it stopped: it can fail there, never pass."""

from types import SimpleNamespace

from auxbearing.verify.judge import _static_safety

CRITERIA = {"min_s0": 1.0, "given": []}


def _cases(**drops):
    """Drop case -> (verdict, s0 of its one plane)."""
    return SimpleNamespace(drops={case: SimpleNamespace(summary={"verdict": verdict,
                                                                 "planes": [{"name": "QJ208", "s0": s0}]})
                                  for case, (verdict, s0) in drops.items()})


def test_every_drop_ended_the_smallest_s0_is_judged():
    c = _static_safety(_cases(high=("ok", 16.0), low=("ok", 9.0)), CRITERIA)
    assert c.passed is True and c.found == 9.0 and "low, QJ208" in c.evidence


def test_a_drop_that_left_the_range_above_the_limit_leaves_the_criterion_not_checked():
    # the heavy rotor: s0 1.16 before a contact ellipse ran over the groove shoulder, 16 in the drop that ended
    c = _static_safety(_cases(top=("contact_ellipse_over_shoulder", 1.16), low=("ok", 16.0)), CRITERIA)
    assert c.passed is None and c.kind == "not checked"
    assert c.found == 1.16
    assert "up to where that drop stopped" in c.evidence and "top stopped early" in c.evidence


def test_a_drop_that_left_the_range_below_the_limit_fails():
    c = _static_safety(_cases(top=("contact_ellipse_over_shoulder", 0.8), low=("ok", 16.0)), CRITERIA)
    assert c.passed is False and c.found == 0.8


def test_a_cut_drop_without_ball_contact_still_leaves_it_unchecked():
    c = _static_safety(_cases(top=("step_budget", None), low=("ok", 16.0)), CRITERIA)
    assert c.passed is None and c.found == 16.0


def test_no_ball_contact_anywhere_fails_with_no_value():
    c = _static_safety(_cases(top=("contact_ellipse_over_shoulder", None)), CRITERIA)
    assert c.passed is False and c.found is None
