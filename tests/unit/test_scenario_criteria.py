"""The scenarios' criteria in a verification: the magnetic bearings' current against its limit, re-levitation."""

from types import SimpleNamespace

import numpy as np
import pytest

from auxbearing.analysis.scenario_outcome import saturation
from auxbearing.verify.judge import _scenario_criteria


def _cases(peak: float, scenario: dict, simulated: float = 0.5, quick: bool = False) -> SimpleNamespace:
    amb = [{"name": "de", "peak_axis_current_A": peak, "max_current_A": 5.0},
           {"name": "nde", "peak_axis_current_A": 1.0, "max_current_A": 5.0}]
    summary = {"amb": amb, "scenario": {"time_ms": 30.0, **scenario}, "simulated_s": simulated}
    plain = {"amb": amb, "scenario": {"time_ms": 0.0}, "simulated_s": 0.2}  # a drop from the centre: no scenario
    return SimpleNamespace(drops={"drop at the maximum speed": SimpleNamespace(summary=plain),
                                  "scenario: dip": SimpleNamespace(summary=summary)}, quick=quick)


def test_the_current_criterion_takes_the_bearing_closest_to_its_limit():
    (current,) = _scenario_criteria(_cases(2.0, {}))
    # judged against the saturation threshold, 0.999 of the limit (the amplifier only approaches its limit)
    assert current.found == 2.0 and current.margin == pytest.approx(1 - 2.0 / 4.995) and current.passed
    assert "scenario: dip, de: 40.0 % of its limit" in current.evidence


def test_a_saturated_bearing_fails_the_current_criterion():
    (current,) = _scenario_criteria(_cases(5.0, {}))
    assert current.passed is False and "(saturated)" in current.evidence


def test_re_levitation_is_judged_where_the_scenario_asks_for_it():
    lifted = {"relevitate_within_ms": 100.0, "relevitated_at_ms": 80.0, "outcome": "re-levitated"}
    _, within = _scenario_criteria(_cases(2.0, lifted))
    assert within.name == "re-levitation after dip" and within.found == pytest.approx(50.0) and within.passed
    held = {"relevitate_within_ms": 100.0, "relevitated_at_ms": None, "outcome": "sustained forward whirl"}
    _, never = _scenario_criteria(_cases(2.0, held))
    assert never.passed is False and never.found is None and "sustained forward whirl" in never.evidence


def test_saturation_intervals_on_the_grid():
    t = np.arange(10) * 1e-3
    current = np.array([0, 1, 5, 5, 2, 0, -5, -5, -5, 1.0])
    total, spans = saturation(t, current, 5.0)
    assert np.allclose(spans, [(0.002, 0.004), (0.006, 0.009)])
    assert total == pytest.approx(0.005)
    assert saturation(t, current, float("inf")) == (0.0, [])


def test_the_criteria_table_sets_the_current_share_and_a_relevitation_time_for_every_scenario():
    criteria = {"max_amb_current_share": 0.5, "relevitation_time": 0.01, "given": ["max_amb_current_share",
                                                                                  "relevitation_time"]}
    held = {"relevitated_at_ms": None, "outcome": "sustained forward whirl"}
    current, relevitation = _scenario_criteria(_cases(2.0, held), criteria)
    assert current.required == pytest.approx(2.4975) and current.margin == pytest.approx(1 - 2.0 / 2.4975)
    assert current.passed
    assert "max_amb_current_share" in current.origin
    assert relevitation.required == pytest.approx(10.0) and relevitation.passed is False
    assert relevitation.origin == "your [criteria] relevitation_time"
    # a scenario that leaves the bearings without power is not asked to re-levitate
    assert len(_scenario_criteria(_cases(2.0, {"outcome": "on the touchdown bearings"}), criteria)) == 1
    (over,) = _scenario_criteria(_cases(2.6, {"outcome": "on the touchdown bearings"}), criteria)
    assert over.passed is False


def test_a_run_too_short_to_show_a_re_levitation_leaves_it_not_checked():
    # the blower's supply dip under --quick: struck at 30 ms, its run ends at 80 ms, still bouncing; a settled
    # stretch of 20 % of the time after the strike (20 ms at least) past the 40 ms limit needs 60 ms after it
    bouncing = {"relevitated_at_ms": None, "outcome": "not settled"}
    criteria = {"max_amb_current_share": 1.0, "relevitation_time": 0.04, "given": ["relevitation_time"]}
    _, cut = _scenario_criteria(_cases(2.0, bouncing, simulated=0.08, quick=True), criteria)
    assert cut.passed is None and cut.kind == "not checked"
    assert "the run ended 50.0 ms after the strike" in cut.evidence and "60.0 ms" in cut.evidence
    assert "(--quick)" in cut.evidence
    # long enough, and still not re-levitated: a fail
    _, late = _scenario_criteria(_cases(2.0, bouncing, simulated=0.095), criteria)
    assert late.passed is False and late.found is None


def test_without_a_campaign_the_final_verdict_has_its_whirl_probability_not_checked():
    from auxbearing.verify.judge import WHIRL_PROBABILITY, _campaign_criterion

    criteria = {"max_backward_whirl_probability": 0.05, "given": []}
    assert _campaign_criterion(None, criteria, final=False) is None  # judged before the campaign ran
    c = _campaign_criterion(None, criteria, final=True)
    assert c.name == WHIRL_PROBABILITY and c.passed is None and "no campaign was run" in c.evidence
