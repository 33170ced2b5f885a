"""The test run's distribution over its workers (tests/conftest.py): whole files, but for a few files of long,
independent tests, which go one test at a time; those must hold no fixture that lives for the whole module, or
each worker would compute it again."""

import re
from pathlib import Path

from tests.conftest import SPREAD, _FileOrTestScheduling

ROOT = Path(__file__).resolve().parents[2]
WIDE_FIXTURE = re.compile(r"@pytest\.fixture\([^)]*scope=\"(module|package|session|class)\"")


def test_spread_files_exist_and_hold_no_module_fixture():
    for name in sorted(SPREAD):
        assert not WIDE_FIXTURE.search((ROOT / name).read_text()), name


def test_a_spread_file_goes_test_by_test_and_any_other_whole():
    scope = _FileOrTestScheduling._split_scope
    spread = "tests/consistency/test_coastdown_reduced.py::test_reduced_model_agrees_with_full_dynamics[blower]"
    assert scope(None, spread) == spread
    assert scope(None, "tests/cli/test_verify_cli.py::test_verify_json") == "tests/cli/test_verify_cli.py"


def test_the_makefile_runs_the_tests_by_file():
    runs = [line for line in (ROOT / "Makefile").read_text().splitlines() if "-m pytest" in line]
    assert runs and all("--dist loadfile" in line for line in runs)
