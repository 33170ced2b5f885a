"""Open an HTML report in headless Chromium and read back what the browser made of it.

The report is copied with a script that runs after load and records how many <img> elements decoded
(naturalWidth > 0) and which <h2> sections have nothing in them; Chromium's --dump-dom returns the
result. CI installs Debian's chromium (.ci/run); elsewhere the tests that use this skip without it.
"""

import json
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

CHROMIUM = shutil.which("chromium") or shutil.which("chromium-browser")
needs_chromium = pytest.mark.skipif(CHROMIUM is None and not os.environ.get("CI"), reason="chromium not installed")

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


def probe_report(html: str, workdir: Path) -> dict:
    """{images, loaded, sections, empty} of ``html`` as headless Chromium rendered it."""
    assert CHROMIUM is not None, "CI must install chromium (.ci/run)"
    probe = workdir / "probe.html"
    probe.write_text(html.replace("</body>", PROBE + "</body>"), encoding="utf-8")
    proc = subprocess.run(
        [CHROMIUM, "--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync",
         f"--user-data-dir={workdir / 'profile'}", "--virtual-time-budget=10000", "--dump-dom", probe.as_uri()],
        capture_output=True, text=True, timeout=180,
    )
    match = re.search(r'<pre id="probe-result">(.*?)</pre>', proc.stdout)
    assert match, proc.stderr[-2000:]
    return json.loads(match.group(1).replace("&quot;", '"'))
