"""The README's Python examples run as written.

Every ```python block of README.md is run, in order, in one fresh namespace, inside a temporary working
folder: files the examples write (drop.nc, ...) land there. The README is read from a checkout's root, so
the examples' relative paths (examples/duty_cycle.csv) resolve against a copy of the repository's
examples/ folder placed in the temporary folder. A failure points at the README line that raised.
"""

import re
import shutil
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
FENCE = re.compile(r"^```python[^\n]*\n(.*?)^```", re.MULTILINE | re.DOTALL)


def python_blocks(text: str) -> list[tuple[int, str]]:
    """(first line number in the file, source) of every ```python block."""
    return [(text.count("\n", 0, m.start(1)) + 1, m.group(1)) for m in FENCE.finditer(text)]


def test_blocks_are_found():
    text = "intro\n```python\nx = 1\n```\n```sh\nls\n```\n```python\ny = x + 1\n```\n"
    assert python_blocks(text) == [(3, "x = 1\n"), (9, "y = x + 1\n")]


@pytest.mark.slow  # the examples run a drop, a coast-down and a quick verification: 10 s
def test_readme_python_examples_run(tmp_path, monkeypatch):
    blocks = python_blocks(README.read_text())
    assert blocks, "README.md has no ```python block"
    shutil.copytree(ROOT / "examples", tmp_path / "examples")
    monkeypatch.chdir(tmp_path)
    namespace = {"__name__": "__readme__"}
    for line, source in blocks:
        # Padding with blank lines makes a traceback name the README's own line numbers.
        code = compile("\n" * (line - 1) + source, str(README), "exec")
        try:
            exec(code, namespace)
        except Exception as error:
            error.add_note(f"in the README.md python block that starts at line {line}")
            raise
