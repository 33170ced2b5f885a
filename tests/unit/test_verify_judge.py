"""The verdict on P(backward whirl): judged by its 95 % upper bound, with the campaign size that would show it."""

from auxbearing.campaign.statistics import wilson_interval
from auxbearing.machine.judging import read_criteria
from auxbearing.verify.judge import _drops_to_show, _whirl_probability


def _campaign(k, n):
    value, low, high = wilson_interval(k, n)
    return {"samples": n, "ok": n, "p_backward_whirl": {"value": value, "low": low, "high": high}}


def test_whirl_free_campaign_size_is_where_scipys_wilson_bound_reaches_the_limit():
    n = _drops_to_show(0.0, 0.05)
    assert wilson_interval(0, n)[2] <= 0.05 < wilson_interval(0, n - 1)[2]
    assert _drops_to_show(0.06, 0.05) is None


def test_pass_inconclusive_and_fail():
    criteria = read_criteria(None)  # limit 0.05
    assert _whirl_probability(_campaign(0, 128), criteria).passed is True  # bound 0.029
    small = _whirl_probability(_campaign(0, 32), criteria)  # estimate 0, bound 0.107
    assert small.passed is None and "73 or more drops without whirl would show it" in small.evidence
    some = _whirl_probability(_campaign(2, 128), criteria)  # estimate 0.016, bound 0.055
    assert some.passed is None and "at the estimated rate about" in some.evidence
    assert _whirl_probability(_campaign(10, 128), criteria).passed is False  # estimate 0.078 > 0.05
