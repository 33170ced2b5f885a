"""Open an HTML report in headless Chromium and read back what the browser made of it.

The report is copied with a script that runs after load and records how many <img> elements decoded
(naturalWidth > 0) and which <h2> sections have nothing in them; Chromium's --dump-dom returns the
result. CI installs Debian's chromium (.ci/run); elsewhere the tests that use this skip without it.
"""

import html as html_module
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


#: Words that name a physical quantity in an input key: a bare number under such a key is a value without its unit.
PHYSICAL_WORDS = ("temperature", "speed", "clearance", "gap", "time", "stiffness", "mass", "force", "length",
                  "radius", "diameter", "width", "position", "inertia", "damping", "pressure", "stress", "power",
                  "torque", "duration", "step", "load", "unbalance", "viscosity", "gravity")
#: How a key ends when its value has no unit.
DIMENSIONLESS_WORDS = ("fraction", "ratio", "factor", "step", "share", "count", "number", "exponent")
#: How a key ends when its value is a count.
COUNT_WORDS = ("steps", "points", "samples", "count", "drops", "windows", "balls")
#: How a key ends when it declares its unit (``race_mass_kg``, ``line_stiffness_N_per_m10_9``, ``speed_rpm``).
UNIT_SUFFIX = re.compile(r"_(mm|um|m|m2|m3|kg|kg_m2|g_mm|N|kN|N_m|N_per_m\w*|N_s_per_m\w*|s|ms|us|K|C|degC|rpm|Hz|"
                         r"rad_s|rad|mrad|deg|Pa|kPa|MPa|GPa|W|J|W_per_m_K|J_per_kg_K|Pa_s|mPa_s|percent|1|count|"
                         r"A|N_per_A|A_per_m|A_per_m_s|A_s_per_m)$")


def page_text(page: str) -> str:
    """What a reader sees of a page: tags, styles, scripts and embedded images removed, entities decoded."""
    page = re.sub(r"<(style|script)\b.*?</\1>", " ", page, flags=re.S | re.I)
    page = re.sub(r"data:image/png;base64,[A-Za-z0-9+/=]+", " ", page)
    return html_module.unescape(re.sub(r"<[^>]+>", " ", page))


def unreadable_numbers(page: str) -> list[str]:
    """Numbers on a page a person should not be given: floats printed to machine precision, NaN, and bare
    numbers under an input key that names a physical quantity but not its unit ("ambient_temperature": 293.15)."""
    text = page_text(page)
    found = re.findall(r"(?<![\w.])-?\d+\.\d{8,}(?:e[-+]?\d+)?", text)
    found += re.findall(r"\bnan\b", text, flags=re.I)
    for key, quoted, value in re.findall(r'"([A-Za-z][\w.]*)"\s*:\s*("?)([^",}\n]*)', text):
        words = key.lower().split("_")
        value = value.strip()
        if quoted:  # a quantity string ("0.2 s"): a limit switched off reads as words, not "inf s"
            if re.match(r"-?(inf|nan)\b", value):
                found.append(f"{key}: {value}")
            continue
        if not re.fullmatch(r"-?\d[\d.eE+-]*", value):
            continue
        if re.fullmatch(r"-?\d+\.0", value) and words[-1] in COUNT_WORDS:
            found.append(f"{key}: {value}")  # a count printed as a float
        elif (set(words) & set(PHYSICAL_WORDS) and words[-1] not in DIMENSIONLESS_WORDS
              and not UNIT_SUFFIX.search(key)):
            found.append(f"{key}: {value}")
    return found
