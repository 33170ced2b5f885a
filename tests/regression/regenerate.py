"""Rewrite tests/regression/golden.json from the current code: ``.venv/bin/python tests/regression/regenerate.py``.

Runs every command of :data:`CASES` through the command line (in this process, from the repository root)
and stores its JSON output, and the claims verdicts of ``auxbearing study``. Regenerate only when a change
of the numbers is intended and explained in the commit; the golden file is the record of what the command
line printed before.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
GOLDEN = Path(__file__).with_name("golden.json")

#: Relative tolerance of the statics and contact numbers: the solvers converge to ~1e-12, so only
#: round-off may move them.
STATICS_RTOL = 1e-9
#: Relative tolerance of the drop peaks: the adaptive integrator's step sequence may move by round-off,
#: and a peak between two steps moves with it.
DROP_RTOL = 1e-4
#: The drop numbers kept (timings and step counts are not results).
DROP_KEYS = ("verdict", "peak_contact_force_N", "peak_ball_stress_MPa", "s0", "first_impact_ms", "impacts")

STATIC_LOADS = {
    "QJ202": [["--axial", "500", "--radial", "1000"], ["--radial", "1000"]],
    "7202": [["--axial", "1000", "--radial", "500"], ["--radial", "1000", "--axial-condition", "located", "--tilt",
                                                      "fixed"]],
    "7202-40": [["--axial", "1000", "--radial", "500"], ["--radial", "1000", "--axial-condition", "located",
                                                         "--tilt", "fixed"]],
    "209": [["--radial", "1000"], ["--axial", "500", "--radial", "1000", "--tilt", "fixed"]],
    "218": [["--axial", "5000", "--radial", "2000"], ["--radial", "5000", "--axial-condition", "located", "--tilt",
                                                      "fixed"]],
}

CASES: list[dict] = (
    [{"args": ["contact", "--bearing", name, "--json"], "rtol": STATICS_RTOL} for name in STATIC_LOADS]
    + [{"args": ["static", "--bearing", name, *loads, "--json"], "rtol": STATICS_RTOL}
       for name, cases in STATIC_LOADS.items() for loads in cases]
    + [{"args": ["static-cases", "--loads", "examples/duty_cycle.csv", "--json"], "rtol": STATICS_RTOL}]
    + [{"args": ["drop", "--bearing", name, "--json", "--quiet"], "rtol": DROP_RTOL, "keys": list(DROP_KEYS)}
       for name in ("QJ202", "7202", "7202-40")]
)


def run_cli(args: list[str]) -> dict:
    """Output of ``auxbearing <args>`` (a JSON command) run from the repository root."""
    from click.testing import CliRunner

    from auxbearing.cli.main import cli

    here = os.getcwd()
    os.chdir(ROOT)
    try:
        result = CliRunner().invoke(cli, args, catch_exceptions=False)
    finally:
        os.chdir(here)
    if result.exit_code != 0:
        raise RuntimeError(f"auxbearing {' '.join(args)} exited {result.exit_code}: {result.output}")
    return json.loads(result.stdout)


def run_case(case: dict) -> dict:
    """The case's JSON output, reduced to its ``keys`` when it names them."""
    out = run_cli(case["args"])
    return {k: out[k] for k in case["keys"]} if "keys" in case else out


def study_claims(out: Path) -> list[dict]:
    """Section, statement and verdict of every claim of ``auxbearing study`` (written into ``out``)."""
    data = run_cli(["study", "--out", str(out), "--quiet", "--json"])
    return [{k: c[k] for k in ("section", "statement", "verdict")} for c in data["claims"]]


def main() -> None:
    """Run every case and the study and write :data:`GOLDEN`."""
    cases = []
    for case in CASES:
        print("auxbearing", " ".join(case["args"]), file=sys.stderr)
        cases.append({**case, "output": run_case(case)})
    print("auxbearing study --json", file=sys.stderr)
    with tempfile.TemporaryDirectory() as tmp:
        claims = study_claims(Path(tmp) / "study")
    commit = subprocess.run(["git", "rev-parse", "HEAD"], cwd=ROOT, capture_output=True, text=True).stdout.strip()
    golden = {
        "regenerate": ".venv/bin/python tests/regression/regenerate.py",
        "generated_at_commit": commit,
        "cases": cases,
        "study_claims": claims,
    }
    GOLDEN.write_text(json.dumps(golden, indent=1) + "\n")
    print(f"wrote {GOLDEN.relative_to(ROOT)}: {len(cases)} commands, {len(claims)} claims", file=sys.stderr)


if __name__ == "__main__":
    main()
