"""report.html rendered by a real browser (headless Chromium): every figure loads, no section is empty.

The report is a fast one, built by the study's own renderer (auxbearing.report.html.render_report)
from the real contact stage on a coarse grid: its three figures, table, claims and assumptions,
so the whole study (a minute) is not needed to check what the browser makes of the HTML. The test
instruments a copy of the report with a script that records, after load, how many <img> elements
decoded (naturalWidth > 0) and which <h2> sections have no content, and reads the result back from
Chromium's --dump-dom. CI installs Debian's chromium (.ci/run); elsewhere the test skips without it.
"""

import numpy as np
import pytest

from auxbearing import get_bearing
from auxbearing.paper.study import summary_rows
from auxbearing.paper.study_contact import run_contact_stage
from auxbearing.report.html import render_report
from tests.browser import needs_chromium, probe_report

pytestmark = needs_chromium


@pytest.mark.slow  # chromium's start-up alone takes a few seconds
def test_report_renders_in_chromium(tmp_path):
    section = run_contact_stage(get_bearing("QJ202"), 1000.0, np.arange(10.0, 76.0, 5.0),
                                np.arange(0.505, 0.6001, 0.005))
    report = render_report([section], summary_rows([section]), {"bearing": "QJ202"}, "browser check", 0.0)
    data = probe_report(report, tmp_path)
    assert data["images"] >= 3
    assert data["loaded"] == data["images"]
    assert data["sections"] >= 4
    assert data["empty"] == []
