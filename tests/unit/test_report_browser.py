"""report.html rendered by a real browser (headless Chromium): every figure loads, no section is empty.

The report is a fast one, built by the study's own renderer (auxbearing.report.html.render_report)
from the real contact stage on a coarse grid: its three figures, table, claims and assumptions,
so the whole study (a minute) is not needed to check what the browser makes of the HTML. The test
instruments a copy of the report with a script that records, after load, how many <img> elements
decoded (naturalWidth > 0) and which <h2> sections have no content, and reads the result back from
Chromium's --dump-dom. CI installs Debian's chromium (.ci/run); elsewhere the test skips without it.
"""

import json
import os
import re
import shutil
import subprocess

import numpy as np
import pytest

from auxbearing import get_bearing
from auxbearing.paper.study import summary_rows
from auxbearing.paper.study_contact import run_contact_stage
from auxbearing.report.html import render_report

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
pytestmark = pytest.mark.skipif(CHROMIUM is None and not os.environ.get("CI"), reason="chromium not installed")

PROBE = """
<script>
window.addEventListener('load', () => {
  const imgs = Array.from(document.images);
  const empty = [];
  document.querySelectorAll('h2').forEach(h => {
    let n = h.nextElementSibling, count = 0;
    while (n && n.tagName !== 'H2') {
      if (n.textContent.trim() || n.querySelector('img')) count++;
      n = n.nextElementSibling;
    }
    if (count === 0) empty.push(h.textContent);
  });
  const out = {images: imgs.length, loaded: imgs.filter(i => i.complete && i.naturalWidth > 0).length,
               sections: document.querySelectorAll('h2').length, empty: empty};
  const pre = document.createElement('pre'); pre.id = 'probe-result'; pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
});
</script>
"""


@pytest.mark.slow  # chromium's start-up alone takes a few seconds
def test_report_renders_in_chromium(tmp_path):
    assert CHROMIUM is not None, "CI must install chromium (.ci/run)"
    section = run_contact_stage(get_bearing("QJ202"), 1000.0, np.arange(10.0, 76.0, 5.0),
                                np.arange(0.505, 0.6001, 0.005))
    report = render_report([section], summary_rows([section]), {"bearing": "QJ202"}, "browser check", 0.0)
    probe = tmp_path / "probe.html"
    probe.write_text(report.replace("</body>", PROBE + "</body>"))
    proc = subprocess.run(
        [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         f"--user-data-dir={tmp_path / 'profile'}", "--virtual-time-budget=10000", "--dump-dom", probe.as_uri()],
        capture_output=True, text=True, timeout=180,
    )
    match = re.search(r'<pre id="probe-result">(.*?)</pre>', proc.stdout)
    assert match, proc.stderr[-2000:]
    data = json.loads(match.group(1).replace("&quot;", '"'))
    assert data["images"] >= 3
    assert data["loaded"] == data["images"]
    assert data["sections"] >= 4
    assert data["empty"] == []
