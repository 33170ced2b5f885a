"""What a verification says: PASS only when every criterion holds, margins in each criterion's physical sense."""

import math

import pytest

from auxbearing.verify.criteria import (
    lower_bound,
    not_checked,
    overall_verdict,
    ranking_key,
    temperature_bound,
    upper_bound,
    worst_margin,
    yes_no,
)


def _held():
    return [lower_bound("s0", 4.0, 2.0, "-", "", ""), upper_bound("stress", 2100.0, 4200.0, "MPa", "", ""),
            yes_no("range", "ok", "ok", True, "", "")]


def test_incomplete_is_never_pass():
    assert overall_verdict(_held()) == "pass"
    assert overall_verdict([*_held(), not_checked("air gap", "give criteria.amb_air_gap", "")]) == "incomplete"
    failing = [*_held(), not_checked("air gap", "", ""), upper_bound("x", 2.0, 1.0, "", "", "")]
    assert overall_verdict(failing) == "fail"


def test_temperature_margin_is_the_unused_share_of_the_allowed_rise():
    # 120 degC allowed at 25 degC ambient: 72.5 degC found uses half the allowed rise
    c = temperature_bound("peak bearing temperature", 72.5, 120.0, 25.0, "", "")
    assert c.passed and c.margin == pytest.approx(0.5)
    over = temperature_bound("peak bearing temperature", 120.9, 120.0, 25.0, "", "")
    assert not over.passed and over.margin == pytest.approx(-0.9 / 95.0)


def test_ratio_margins_and_no_margin_for_yes_no():
    assert lower_bound("s0", 3.0, 2.0, "-", "", "").margin == pytest.approx(0.5)
    assert upper_bound("stress", 3150.0, 4200.0, "MPa", "", "").margin == pytest.approx(0.25)
    failed = yes_no("no run leaves the model's range", "ok", "overload", False, "", "")
    assert failed.margin is None  # not a -100 %
    assert worst_margin([failed]) != worst_margin([failed])  # NaN: no margin to show
    assert worst_margin(_held()) == pytest.approx(0.5)


def test_ranking_puts_failing_designs_last_whatever_their_margins():
    good = _held()
    incomplete = [*_held(), not_checked("air gap", "", "")]
    bad = [lower_bound("s0", 40.0, 2.0, "-", "", ""), yes_no("range", "ok", "overload", False, "", "")]
    order = sorted([("bad", bad), ("incomplete", incomplete), ("good", good)], key=lambda d: ranking_key(d[1]))
    assert [name for name, _ in order] == ["good", "incomplete", "bad"]
    assert math.isfinite(ranking_key(good)[2])


def test_designs_whose_margins_are_all_unchecked_go_by_the_margins_they_show():
    # a --quick look: every criterion with a margin is shown but not checked
    def quick(s0):
        return [lower_bound("s0", s0, 2.0, "-", "", "")._replace(passed=None, kind="not checked"),
                upper_bound("whirl bound", 0.32, 0.05, "-", "", "")._replace(passed=None, kind="not checked"),
                yes_no("stable", "stable", "stable", True, "", "")]

    order = sorted([("thin", quick(3.0)), ("thick", quick(9.0))], key=lambda d: ranking_key(d[1]))
    assert [name for name, _ in order] == ["thick", "thin"]


def test_a_failing_verdict_names_the_criteria_it_could_not_check():
    # mending a failure does not make a pass while other criteria stay open: a FAIL's reason names them too
    from auxbearing.report.verify_html import verdict_reason

    failing = [*_held(), not_checked("air gap", "give criteria.amb_air_gap", ""), upper_bound("x", 2.0, 1.0, "", "",
                                                                                              "case a")]
    reason = verdict_reason(failing)
    assert reason.startswith("fails on x (2 against 1: case a)")
    assert reason.endswith("besides, 1 of 5 are not checked: air gap")
    assert "not checked" not in verdict_reason([*_held(), upper_bound("x", 2.0, 1.0, "", "", "")])


def test_an_incomplete_verdict_names_the_criteria_one_cut_left_open_together():
    # a --quick look: the criteria its cut drops passed share one clause, the cut said once
    from auxbearing.report.verify_html import verdict_reason

    cut = "only the first 50 ms of each 200 ms drop ran (--quick): run without --quick"
    passed = (lower_bound("s0", 9.0, 2.0, "-", "", "drive end"), upper_bound("seal", 0.1, 0.3, "mm", "", "NDE"))
    quick = [c._replace(passed=None, kind="not checked", evidence=f"{c.evidence}; {cut}, so this is not a pass")
             for c in passed]
    alone = not_checked("air gap", "give criteria.amb_air_gap", "")
    reason = verdict_reason([*quick, alone, *_held()])
    assert reason == ("no checked criterion fails, but 3 of 6 are not checked: s0, seal "
                      f"({cut}, so none of them is a pass); air gap (give criteria.amb_air_gap)")
    assert verdict_reason([quick[0], *_held()]).endswith(f"s0 (drive end; {cut}, so this is not a pass)")
