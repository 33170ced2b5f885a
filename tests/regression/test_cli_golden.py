"""Regression (golden) values: what the command line printed when golden.json was written.

Not validation: these are this code's own numbers, kept so that a change that moves them is seen. Each
case of golden.json holds the arguments of one ``auxbearing ... --json`` command and its output:

* ``contact`` and ``static`` for the catalogue bearings QJ202, 7202, 7202-40, 209 and 218 (two load cases
  each), ``static-cases --loads examples/duty_cycle.csv``: every number to a relative 1e-9 (the solvers
  converge to ~1e-12), the equilibrium residuals only to 1e-6 N (they are round-off);
* ``drop --bearing QJ202 / 7202 / 7202-40`` (the paper's rig): verdict, peak force, peak ball stress, s0,
  first impact and number of impacts to a relative 1e-4 (the adaptive step sequence may move by round-off);
* the claims verdicts of ``auxbearing study`` (18 hold, 3 do not hold, 6 cannot be checked), marked slow.

Regenerate, only for an intended and explained change: ``.venv/bin/python tests/regression/regenerate.py``
(rewrites golden.json from the current code; review the diff before committing it).
"""

import json
import math
from collections import Counter
from pathlib import Path

import pytest

from tests.regression.regenerate import GOLDEN, run_case, study_claims

GOLDEN_DATA = json.loads(Path(GOLDEN).read_text())
#: Keys whose values are round-off (Newton residuals): compared in absolute terms only.
RESIDUAL_KEYS = {"residual_N"}
RESIDUAL_ABS_N = 1e-6
#: Below this magnitude (in the printed unit) a number is a round-off zero.
ZERO_ABS = 1e-9


def _differences(golden, current, rtol, path="$"):
    """Every place where ``current`` differs from ``golden`` beyond the tolerance, as readable lines."""
    if isinstance(golden, dict):
        if not isinstance(current, dict) or set(golden) != set(current):
            return [f"{path}: keys {sorted(golden)} became {sorted(current) if isinstance(current, dict) else current}"]
        return [d for k in golden for d in _differences(golden[k], current[k], rtol, f"{path}.{k}")]
    if isinstance(golden, list):
        if not isinstance(current, list) or len(golden) != len(current):
            return [f"{path}: {len(golden)} items became {current if not isinstance(current, list) else len(current)}"]
        return [d for i, (g, c) in enumerate(zip(golden, current, strict=True))
                for d in _differences(g, c, rtol, f"{path}[{i}]")]
    if isinstance(golden, bool) or golden is None or isinstance(golden, str):
        return [] if golden == current else [f"{path}: {golden!r} became {current!r}"]
    if not isinstance(current, int | float) or isinstance(current, bool):
        return [f"{path}: {golden!r} became {current!r}"]
    if path.rsplit(".", 1)[-1] in RESIDUAL_KEYS:
        ok = abs(current - golden) <= RESIDUAL_ABS_N
    else:
        ok = math.isclose(current, golden, rel_tol=rtol, abs_tol=ZERO_ABS)
    return [] if ok else [f"{path}: {golden!r} became {current!r} ({(current - golden) / (abs(golden) or 1):+.3g})"]


def _case_id(case):
    return " ".join(a for a in case["args"] if a not in ("--json", "--quiet"))


@pytest.mark.parametrize("case", GOLDEN_DATA["cases"], ids=_case_id)
def test_command_line_numbers_unchanged(case):
    differences = _differences(case["output"], run_case(case), case["rtol"])
    assert not differences, "\n".join(differences[:20])


def test_the_numbers_the_issue_names_are_in_the_golden_file():
    """The headline numbers of the README, to the digits printed there, so that a regeneration cannot
    silently move them."""
    out = {_case_id(c): c["output"] for c in GOLDEN_DATA["cases"]}
    assert round(out["contact --bearing QJ202"]["inner"]["max_stress_MPa"], 1) == 2610.2
    qj, ac = out["drop --bearing QJ202"], out["drop --bearing 7202"]
    assert (round(qj["peak_contact_force_N"], 1), round(qj["peak_ball_stress_MPa"], 1)) == (657.1, 1660.3)
    assert (round(ac["peak_contact_force_N"]), round(ac["peak_ball_stress_MPa"])) == (524, 1938)
    assert Counter(c["verdict"] for c in GOLDEN_DATA["study_claims"]) == {
        "holds": 18, "does not hold": 3, "cannot be checked": 6}


@pytest.mark.slow
def test_study_claims_verdicts_unchanged(tmp_path):
    """The whole study (about a minute): every claim keeps its verdict; 18 hold, 3 do not, 6 cannot be checked.

    The same run's report is the paper's study, framed as such (the one run of the whole paper study in the tests).
    """
    claims = study_claims(tmp_path / "study")
    assert Counter(c["verdict"] for c in claims) == {"holds": 18, "does not hold": 3, "cannot be checked": 6}
    text = (tmp_path / "study" / "report.html").read_text()
    assert "Claims of the paper" in text and "Paper says" in text and "1.48 kg" in text
    summary = json.loads((tmp_path / "study" / "results.json").read_text())
    assert summary["study_of"] == "the paper's bearings" and "experiment" in summary["stage_times_s"]
    differences = _differences(GOLDEN_DATA["study_claims"], claims, 0.0)
    assert not differences, "\n".join(differences)
