"""The study's experiment stage: labelled SYNTHETIC, its claims cannot be checked (runs both example fits)."""

import pytest

from auxbearing.paper.experiment_stage import experiment_stage


@pytest.mark.slow
def test_report_stage_says_synthetic_and_cannot_check():
    section = experiment_stage()
    assert section.key == "experiment"
    assert "SYNTHETIC" in section.title and any("SYNTHETIC" in n for n in section.notes)
    papers = {c.paper for c in section.claims}
    assert {"1728 MPa", "2348 MPa"} <= papers
    assert all(c.verdict == "cannot be checked" for c in section.claims)
    assert section.figures and section.tables
