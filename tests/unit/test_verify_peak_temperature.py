"""The temperature criterion names the hottest part's plane, and says so when the figure is where a thermal run-away
stopped the coast-down rather than the peak it was heading for."""

from types import SimpleNamespace

import pytest

from auxbearing.verify.judge import _peak_temperature

CRITERIA = {"max_temperature": 120.0 + 273.15, "given": []}


def _cases(verdict, temperatures):
    planes = [{"name": name, "max_temperature_C": parts} for name, parts in temperatures.items()]
    return SimpleNamespace(coastdown=SimpleNamespace(summary={"verdict": verdict, "planes": planes}),
                           machine=SimpleNamespace(coastdown=SimpleNamespace(ambient_temperature=25.0 + 273.15)))


def test_the_hottest_part_of_any_plane_is_judged():
    c = _peak_temperature(_cases("ok", {"drive end": {"balls": 121.6, "housing": 60.0}, "non-drive end":
                                        {"balls": 111.2}}), CRITERIA)
    assert c.found == pytest.approx(121.6) and c.passed is False
    assert c.margin == pytest.approx((120.0 - 121.6) / (120.0 - 25.0))
    assert c.evidence == "coast-down, drive end, balls"  # the part named: a journal or housing counts too


def test_a_run_away_says_its_figure_is_where_it_stopped():
    c = _peak_temperature(_cases("thermal_runaway", {"lower": {"balls": 150.0}, "upper": {"balls": 143.1}}), CRITERIA)
    assert c.found == pytest.approx(150.0) and c.passed is False
    assert c.evidence.startswith("coast-down, lower, balls; the run stopped there on its thermal run-away")
