"""The seal criterion: the case drops' largest journal excursion, or a campaign drop's where one goes past the seal
(its conditions are drops the machine may see); the campaign statistics give that largest excursion."""

from types import SimpleNamespace

import numpy as np
import pytest
import xarray as xr

from auxbearing.campaign.statistics import _largest, sample_outputs
from auxbearing.verify.judge import _seal

CRITERIA = {"seal_clearance": 0.35e-3, "given": ["seal_clearance"]}


def _cases(excursions, campaign=None):
    drops = {case: SimpleNamespace(summary={"largest_excursion_m": e}) for case, e in excursions.items()}
    return SimpleNamespace(drops=drops, campaign=campaign)


def test_the_case_drops_largest_excursion_is_judged():
    c = _seal(_cases({"high": 0.12e-3, "scenario: surge": 0.16e-3}), CRITERIA)
    assert c.passed is True and c.found == pytest.approx(0.16)
    assert c.evidence.endswith("in the drops: scenario: surge")  # the case it comes from, which convergence re-runs


def test_a_campaign_drop_short_of_the_seal_sets_the_margin_when_it_came_closer():
    """The campaign's drops are drops the machine may see: the closest one to the seal sets the margin."""
    c = _seal(_cases({"high": 0.16e-3}, {"ok": 120, "largest_excursion_mm": 0.2}), CRITERIA)
    assert c.passed is True and c.found == pytest.approx(0.2)
    assert "the case drops' largest: 0.16 mm" in c.evidence


def test_a_campaign_drop_past_the_seal_fails_it():
    c = _seal(_cases({"high": 0.16e-3}, {"ok": 120, "largest_excursion_mm": 0.41}), CRITERIA)
    assert c.passed is False and c.found == pytest.approx(0.41)
    assert "the campaign's 120 drops that ended ok" in c.evidence


def test_a_campaign_without_the_figure_and_no_seal_given():
    assert _seal(_cases({"high": 0.16e-3}, {"ok": 120, "largest_excursion_mm": None}), CRITERIA).passed is True
    assert _seal(_cases({"high": 0.16e-3}), {**CRITERIA, "seal_clearance": None}).passed is None


def test_the_campaigns_largest_excursion_over_its_runs_that_ended_ok():
    ds = xr.Dataset({name: (("sample", "plane"), np.ones((3, 2))) for name in
                     ("peak_ball_stress", "peak_contact_force", "s0", "backward_whirl")})
    ds["max_excursion"] = (("sample", "plane"), np.array([[1e-4, 2e-4], [5e-4, 1e-4], [np.nan, 3e-4]]))
    values, unit = sample_outputs(ds)["max_excursion_mm"]
    assert unit == "mm"
    ok = np.array([True, False, True])
    assert _largest(values, ok) == pytest.approx(0.2)  # the second run left the range: its 0.5 mm does not count
    assert _largest(values, np.zeros(3, bool)) is None
    assert "max_excursion_mm" not in sample_outputs(ds.drop_vars("max_excursion"))  # a store made before it


def test_the_campaign_records_the_rotor_at_its_magnetic_bearings_where_it_has_any():
    ds = xr.Dataset({name: (("sample", "plane"), np.ones((2, 2))) for name in
                     ("peak_ball_stress", "peak_contact_force", "s0", "backward_whirl")})
    ds["max_bearing_excursion"] = ("sample", np.array([2.5e-4, 3e-4]))
    values, unit = sample_outputs(ds)["max_bearing_excursion_mm"]
    assert unit == "mm" and values.tolist() == pytest.approx([0.25, 0.3])
    ds["max_bearing_excursion"] = ("sample", np.full(2, np.nan))  # a machine without radial magnetic bearings
    assert "max_bearing_excursion_mm" not in sample_outputs(ds)
