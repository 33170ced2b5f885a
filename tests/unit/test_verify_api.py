"""The verification from Python: a Verification result with its views (auxbearing.verify.result)."""

import json

import pytest

from auxbearing.verify import verify


@pytest.mark.slow
def test_a_verification_reads_as_a_dict_a_table_a_page_and_files(tmp_path):
    result = verify("paper_rig", tmp_path / "stores", quick=True, samples=0, with_recommendation=False)
    assert isinstance(result, dict) and result["verdict"] == result.verdict == "incomplete"
    table = result.criteria
    assert {"name", "required", "found", "margin", "pass", "evidence"} <= set(table.columns)
    assert len(table) == len(result["criteria"]) and table["pass"].isna().any()
    assert repr(result).startswith("<Verification of ") and "\n" not in repr(result)
    page = result._repr_html_()
    assert "INCOMPLETE" in page and page.count("<tr>") == len(table) + 1
    folder = result.save(tmp_path / "out")
    saved = json.loads((folder / "verify.json").read_text())
    assert saved["verdict"] == "incomplete" and "design" not in saved
    # limits and settings as a user types them, with units, in the results and in their provenance alike
    for inputs in (saved["inputs"], saved["provenance"]["inputs"]):
        assert inputs["criteria"]["max_temperature"] == "120 degC"
    assert saved["settings"]["balance_grade"] == "6.3 mm/s"
    assert (folder / "report.html").read_text().count("<h2>") > 3
    # the design's figures, drawn on the verification's cluster, are those this process draws from the same runs
    from auxbearing.report.verify_figures import DESIGN_SECTIONS, build_figures

    drawn = result["figures"]
    assert set(drawn) == {"machine", "modes", "criteria", "drops", "coastdown"} <= set(DESIGN_SECTIONS)
    here = build_figures({**result, "figures": None})
    assert {key: [caption for _, caption in here[key]] for key in drawn} == {
        key: [caption for _, caption in figures] for key, figures in drawn.items()}
    assert here["machine"] == drawn["machine"]  # the same PNG, to the byte


def test_the_drivers_table_names_inputs_in_words_and_leaves_out_what_did_not_vary():
    from auxbearing.verify.run import _campaign_rows

    stats = {"p_backward_whirl": {"value": 0.0, "low": 0.0, "high": 0.3, "among": "runs that ended ok"},
             "p_out_of_range": {"value": 0.0, "low": 0.0, "high": 0.3, "among": "completed samples"},
             "p_s0_below_required": {"value": 0.0, "low": 0.0, "high": 0.3, "among": "runs that ended ok"},
             "quantiles": {"peak_ball_stress_MPa": {"p50": 1446.0, "p95": 1493.0, "unit": "MPa"}},
             "sensitivity": {"outputs": {"backward_whirl": {"rotor.unbalance": {"rho": float("nan")}},
                                         "peak_ball_stress_MPa": {"rotor.unbalance": {"rho": -0.29}}}}}
    spreads = [{"key": "rotor.unbalance", "label": "static unbalance (mass-centre offset)"}]
    rows, drivers = _campaign_rows(stats, spreads)
    assert rows[-1][0] == "peak ball contact stress, median / 95th percentile"
    assert drivers["columns"] == ["input", "rank correlation with the peak ball stress"]
    assert drivers["rows"] == [["static unbalance (mass-centre offset)", "-0.29"]]
    assert "backward whirl: it did not vary" in drivers["caption"]
