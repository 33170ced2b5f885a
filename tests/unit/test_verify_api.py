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
    assert (folder / "report.html").read_text().count("<h2>") > 3
