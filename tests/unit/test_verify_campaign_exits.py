"""A campaign's drops that leave the model's range fail the range criterion like any other run."""

from auxbearing.verify.judge import _campaign_exits


def test_drops_out_of_range_are_counted_by_their_limit():
    campaign = {"completed": 16, "ok": 1, "verdicts": {"ok": 1, "contact_ellipse_over_shoulder": 15}}
    finding, reason = _campaign_exits(campaign)
    assert finding == "15 of 16 drops out of range"
    assert reason == "15 of the campaign's 16 drops left the model's range (contact ellipse over shoulder: 15)"


def test_budgets_and_refused_samples_are_not_range_exits():
    # a budget reached or a sample the machine refuses says nothing about the machine's range
    campaign = {"completed": 16, "ok": 14, "verdicts": {"ok": 14, "step_budget": 1, "invalid_input": 1}}
    assert _campaign_exits(campaign) is None
    assert _campaign_exits(None) is None and _campaign_exits({"completed": 8, "verdicts": {"ok": 8}}) is None


def test_a_whirl_bound_with_drops_that_gave_no_result_is_not_a_pass():
    from auxbearing.verify.judge import _whirl_probability

    p = {"value": 0.0, "low": 0.0, "high": 0.029}
    criteria = {"max_backward_whirl_probability": 0.05, "given": []}
    whole = {"ok": 128, "samples": 128, "completed": 128, "verdicts": {"ok": 128}, "p_backward_whirl": p}
    assert _whirl_probability(whole, criteria).passed is True
    lost = {**whole, "ok": 126, "verdicts": {"ok": 126, "step_budget": 2}}
    c = _whirl_probability(lost, criteria)
    assert c.passed is None and "2 drops gave no result (step budget: 2)" in c.evidence
