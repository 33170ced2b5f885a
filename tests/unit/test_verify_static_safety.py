"""Criteria judged over the drops count a drop cut short up to where it stopped: it can fail them, never pass them."""

from types import SimpleNamespace

from auxbearing.verify.criteria import upper_bound
from auxbearing.verify.judge import _static_safety, drops_cut_short

CRITERIA = {"min_s0": 1.0, "given": []}


def _cases(campaign=None, partial_drops="", **drops):
    """Drop case -> (verdict, s0 of its one plane); ``partial_drops``: why every drop ran only its first part."""
    return SimpleNamespace(drops={case: SimpleNamespace(summary={"verdict": verdict,
                                                                 "planes": [{"name": "QJ208", "s0": s0}]})
                                  for case, (verdict, s0) in drops.items()}, campaign=campaign,
                           partial_drops=partial_drops)


def _judged(cases):
    return drops_cut_short(cases, [_static_safety(cases, CRITERIA)])[0]


def test_every_drop_ended_the_smallest_s0_is_judged():
    c = _judged(_cases(high=("ok", 16.0), low=("ok", 9.0)))
    assert c.passed is True and c.found == 9.0 and "low, QJ208" in c.evidence


def test_a_drop_that_left_the_range_above_the_limit_leaves_the_criterion_not_checked():
    # the heavy rotor: s0 1.16 before a contact ellipse ran over the groove shoulder, 16 in the drop that ended
    c = _judged(_cases(top=("contact_ellipse_over_shoulder", 1.16), low=("ok", 16.0)))
    assert c.passed is None and c.kind == "not checked"
    assert c.found == 1.16
    assert "up to where that drop stopped" in c.evidence
    assert "top stopped early (contact ellipse over shoulder)" in c.evidence


def test_a_drop_that_left_the_range_below_the_limit_fails():
    c = _judged(_cases(top=("contact_ellipse_over_shoulder", 0.8), low=("ok", 16.0)))
    assert c.passed is False and c.found == 0.8


def test_a_cut_drop_without_ball_contact_still_leaves_it_unchecked():
    c = _judged(_cases(top=("step_budget", None), low=("ok", 16.0)))
    assert c.passed is None and c.found == 16.0


def test_no_ball_contact_anywhere_fails_with_no_value():
    c = _judged(_cases(top=("contact_ellipse_over_shoulder", None)))
    assert c.passed is False and c.found is None


def test_the_seal_excursion_of_a_cut_drop_is_not_a_pass():
    seal = upper_bound("journal excursion against the seal clearance", 0.2, 0.35, "mm", "user input", "drops")
    other = upper_bound("some other limit", 0.2, 0.35, "mm", "user input", "drops")
    kept = drops_cut_short(_cases(top=("step_budget", 2.0)), [seal, other])
    assert kept[0].passed is None and kept[1].passed is True
    assert drops_cut_short(_cases(top=("ok", 2.0)), [seal])[0].passed is True


def test_a_campaign_drop_below_the_limit_fails_it():
    campaign = {"ok": 120, "smallest_s0": 0.7, "p_s0_below_required": {"successes": 3}}
    c = _judged(_cases(campaign=campaign, high=("ok", 16.0)))
    assert c.passed is False and c.found == 0.7
    assert "3 of the campaign's 120 drops that ended ok fall below 1" in c.evidence
    # above the limit the campaign's drop that came closer still sets the margin: it is a drop the machine may see
    calm = {"ok": 120, "smallest_s0": 12.0, "p_s0_below_required": {"successes": 0}}
    assert _judged(_cases(campaign=calm, high=("ok", 16.0))).found == 12.0


QUICK = "only the first 50 ms of each 500 ms drop ran (--quick): run without --quick"


def test_drops_the_quick_look_cut_pass_nothing_but_fail_what_they_already_fail():
    # the heavy rotor's quick look: s0 7.5 in its 50 ms drops, where the 500 ms drop reaches 1.16 and leaves the
    # model's range at 66.9 ms
    c = _judged(_cases(partial_drops=QUICK, high=("ok", 7.5), low=("ok", 16.0)))
    assert c.passed is None and c.found == 7.5 and c.evidence.endswith(QUICK + ", so this is not a pass")
    assert _judged(_cases(partial_drops=QUICK, high=("ok", 0.8))).passed is False
    in_range = upper_bound("no run leaves the model's range or a limit", 0.0, 1.0, "-", "", "all ok")
    assert drops_cut_short(_cases(partial_drops=QUICK, high=("ok", 7.5)), [in_range])[0].passed is None
    assert drops_cut_short(_cases(high=("ok", 7.5)), [in_range])[0].passed is True
