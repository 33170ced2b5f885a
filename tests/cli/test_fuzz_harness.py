"""Harness of the command-line fuzz suite (issue 11): a case, how it is run, and how its outcome is judged.

A :class:`Case` is one command line with the files it needs (written into an empty folder first) and
what the user must get back:

``error``
    exit status 2, exactly one line on stderr, starting ``error:``, that holds every string of
    ``names`` (the option or key as the user wrote it, the value as typed), and nothing written.
``warning``
    exit status 0 and a ``warning:`` line holding every string of ``names``; or a refusal as for
    ``error`` (a legal number whose result means nothing may be refused).
``ok``
    exit status 0 and no traceback.
``verdict``
    a legal extreme: it ends with a verdict (exit status 0, or 1 and 3 where a command reports a failing or
    incomplete verdict by its status) or with a reasoned refusal as for ``error``; no traceback, no hang.

In every case a numpy ``RuntimeWarning`` on stderr counts as a message that is not one line: it is a
library talking past the command (issue 20).

The tables live in ``test_fuzz_commands.py`` (options of every command) and ``test_fuzz_files.py``
(every input-file kind). Run as a script, this module runs both tables as subprocesses, each in its
own empty folder with a time limit, and prints the counts of each outcome (the before/after numbers
of issue 11)::

    .venv/bin/python -m tests.cli.test_fuzz_harness [--timeout 120] [--jobs 2] [--only ID,...]
"""

from __future__ import annotations

import os
import shlex
import signal
import subprocess
import sys
import tempfile
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import pytest
from click.testing import CliRunner

#: Seconds an in-process case may take before it counts as a hang (a bad input must be refused at once).
IN_PROCESS_LIMIT = 60
#: Outcomes, in the order the report prints them.
OUTCOMES = ("pass", "traceback", "hang", "accepted", "wrong_exit", "not_one_line", "message", "left_behind")

FileSpec = str | bytes | Callable[[Path], None]


@dataclass(frozen=True)
class Case:
    """One command line, the files it needs and what it must give (module docstring)."""

    id: str
    args: tuple[str, ...]
    names: tuple[str, ...] = ()
    files: tuple[tuple[str, FileSpec], ...] = ()
    expect: str = "error"
    note: str = ""
    avoid: tuple[str, ...] = ()  #: text the message must not hold ("not found" for a folder)

    def __repr__(self) -> str:
        return self.id


def case(case_id: str, command: str, *names: str, files: dict[str, FileSpec] | None = None,
         expect: str = "error", note: str = "", avoid: tuple[str, ...] = ()) -> Case:
    """A :class:`Case` from a shell-like command line (``shlex`` quoting)."""
    return Case(case_id, tuple(shlex.split(command)), tuple(names), tuple((files or {}).items()), expect, note,
                tuple(avoid))


@dataclass
class Outcome:
    """What a run gave back."""

    exit_code: int | None
    stderr: str
    stdout: str = ""
    traceback: str = ""
    new_files: list[str] = field(default_factory=list)
    seconds: float = 0.0
    timed_out: bool = False


def write_files(folder: Path, files: tuple[tuple[str, FileSpec], ...]) -> None:
    """Make the case's input files (text as UTF-8, bytes as they are, a callable writes its own)."""
    for name, spec in files:
        path = folder / name
        if name.endswith("/"):
            path.mkdir(parents=True, exist_ok=True)
            continue
        path.parent.mkdir(parents=True, exist_ok=True)
        if callable(spec):
            spec(path)
        elif isinstance(spec, bytes):
            path.write_bytes(spec)
        else:
            path.write_text(spec, encoding="utf-8")


def snapshot(folder: Path) -> set[str]:
    """Every path below ``folder`` (hidden ones too), relative."""
    return {str(p.relative_to(folder)) for p in folder.rglob("*")}


class _Timeout(Exception):
    pass


def _alarm(signum, frame):
    raise _Timeout


_WARM: list[bool] = []


def warm_kernels() -> None:
    """Load (or, on a fresh machine, compile) the drop and coast-down kernels once per test process.

    A case's time limit is for the input handling under test; the first compile of the kernels (about a
    minute of CPU on a fresh machine, longer with two test workers compiling at once) is not part of it.
    """
    if _WARM:
        return
    from auxbearing.cli.main import cli

    runner = CliRunner()
    for args in (["drop", "--machine", "paper_rig", "--duration", "0.1 ms", "--quiet"],
                 ["coastdown", "--machine", "paper_rig", "--duration", "0.01", "--quiet"]):
        with tempfile.TemporaryDirectory() as scratch:
            old = os.getcwd()
            os.chdir(scratch)
            try:
                runner.invoke(cli, args, catch_exceptions=True)
            finally:
                os.chdir(old)
    _WARM.append(True)


def run_in_process(c: Case, folder: Path, limit: float = IN_PROCESS_LIMIT) -> Outcome:
    """Run a case with click's test runner in ``folder`` (which becomes the working folder)."""
    from auxbearing.cli.main import cli

    warm_kernels()
    write_files(folder, c.files)
    before = snapshot(folder)
    old = os.getcwd()
    os.chdir(folder)
    previous = signal.signal(signal.SIGALRM, _alarm)
    signal.setitimer(signal.ITIMER_REAL, limit)
    start = time.perf_counter()
    timed_out = False
    try:
        result = CliRunner().invoke(cli, list(c.args), catch_exceptions=True)
    except _Timeout:
        timed_out, result = True, None
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)
        signal.signal(signal.SIGALRM, previous)
        os.chdir(old)
    seconds = time.perf_counter() - start
    new = sorted(snapshot(folder) - before)
    if result is None:
        return Outcome(None, "", new_files=new, seconds=seconds, timed_out=True)
    trace = ""
    if result.exception is not None and not isinstance(result.exception, SystemExit):
        if isinstance(result.exception, _Timeout):
            return Outcome(None, result.stderr, new_files=new, seconds=seconds, timed_out=True)
        import traceback

        trace = "".join(traceback.format_exception(result.exception))
    return Outcome(result.exit_code, result.stderr, result.stdout, trace, new, seconds, timed_out)


def run_subprocess(c: Case, folder: Path, timeout: float) -> Outcome:
    """Run a case as ``python -m auxbearing.cli.main ...`` in ``folder`` with a time limit."""
    write_files(folder, c.files)
    before = snapshot(folder)
    env = {**os.environ, "MPLBACKEND": "Agg", "COLUMNS": "200"}
    start = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "auxbearing.cli.main", *c.args], cwd=folder, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, start_new_session=True)
    try:
        out, err = proc.communicate(timeout=timeout)
        timed_out = False
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
        timed_out = True
    seconds = time.perf_counter() - start
    trace = err if "Traceback (most recent call last)" in err else ""
    return Outcome(None if timed_out else proc.returncode, err, out, trace, sorted(snapshot(folder) - before),
                   seconds, timed_out)


def _lines(text: str) -> list[str]:
    return [line for line in text.splitlines() if line.strip()]


def judge(c: Case, o: Outcome) -> str:
    """The outcome's class (one of :data:`OUTCOMES`)."""
    if o.timed_out:
        return "hang"
    if o.traceback:
        return "traceback"
    lines = _lines(o.stderr)
    if "RuntimeWarning" in o.stderr:
        return "not_one_line"
    if c.expect == "ok":
        return "pass" if o.exit_code == 0 else "wrong_exit"
    if c.expect == "verdict" and o.exit_code in (0, 1, 3):
        return "pass"
    if c.expect == "warning" and o.exit_code == 0:
        found = [ln for ln in lines if ln.startswith("warning:") and all(n in ln for n in c.names)]
        return "pass" if found else "accepted"
    if o.exit_code == 0:
        return "accepted"
    if o.exit_code != 2:
        return "wrong_exit"
    # warnings may come first (a file read in another encoding); the error itself is one line
    errors = [ln for ln in lines if not ln.startswith("warning:")]
    if len(errors) != 1 or not errors[0].startswith("error:"):
        return "not_one_line"
    if not all(n in errors[0] for n in c.names) or any(a in errors[0] for a in c.avoid):
        return "message"
    if o.new_files:
        return "left_behind"
    return "pass"


def explain(c: Case, o: Outcome) -> str:
    """A few lines for a failed assertion."""
    return (f"{c.id}: auxbearing {shlex.join(c.args)}\n  exit {o.exit_code}, {o.seconds:.1f} s, new files "
            f"{o.new_files}\n  names wanted {c.names}\n  stderr: {o.stderr.strip()[-1500:]}\n"
            f"  stdout: {o.stdout.strip()[-300:]}\n{o.traceback[-3000:]}")


def check_case(c: Case, tmp_path: Path) -> None:
    """Run a case in process and assert that it passes (the test body of both tables)."""
    folder = tmp_path / "work"
    folder.mkdir()
    outcome = run_in_process(c, folder)
    verdict = judge(c, outcome)
    assert verdict == "pass", f"{verdict}\n{explain(c, outcome)}"


# ----------------------------------------------------------------------------- the harness's own tests
def test_judge_sorts_the_outcomes():
    c = case("x", "contact --ball-load '-1 N'", "--ball-load", "-1 N")
    assert judge(c, Outcome(2, "error: --ball-load = '-1 N': must be >= 0 N\n")) == "pass"
    assert judge(c, Outcome(2, "error: ball_load = -1.0: must be >= 0 N\n")) == "message"
    assert judge(c, Outcome(2, "Usage: x\nError: y\n")) == "not_one_line"
    assert judge(c, Outcome(0, "")) == "accepted"
    assert judge(c, Outcome(1, "error: x")) == "wrong_exit"
    assert judge(c, Outcome(2, "error: --ball-load = '-1 N': bad\n", new_files=["out"])) == "left_behind"
    assert judge(c, Outcome(None, "", timed_out=True)) == "hang"
    assert judge(c, Outcome(1, "", traceback="Traceback ...")) == "traceback"
    w = case("w", "contact", "groove", expect="warning")
    assert judge(w, Outcome(0, "warning: groove shoulder\n")) == "pass"
    assert judge(w, Outcome(2, "error: groove ratio\n")) == "pass"


def test_a_good_command_passes_as_ok(tmp_path):
    check_case(case("good", "contact --ball-load '1 kN' --json", expect="ok"), tmp_path)


@pytest.mark.slow
def test_the_subprocess_runner_judges_like_the_in_process_one(tmp_path):
    c = case("sub", "contact --ball-load '10**400 N'", "--ball-load", "10**400 N")
    (tmp_path / "a").mkdir()
    assert judge(c, run_subprocess(c, tmp_path / "a", 120)) == "pass"


# ----------------------------------------------------------------------------- the before/after report
def summary_counts(cases: list[Case], verdicts: list[str]) -> dict[str, int]:
    """The counts issue 20 asks for: clean refusals, legal runs, bad inputs accepted, tracebacks, hangs, other."""
    counts = {"clean refusals": 0, "legal runs": 0, "bad inputs accepted": 0, "tracebacks": 0, "hangs": 0,
              "other failures": 0}
    for c, verdict in zip(cases, verdicts, strict=True):
        if verdict == "pass":
            counts["legal runs" if c.expect in ("ok", "verdict") else "clean refusals"] += 1
        elif verdict == "accepted":
            counts["bad inputs accepted"] += 1
        elif verdict == "traceback":
            counts["tracebacks"] += 1
        elif verdict == "hang":
            counts["hangs"] += 1
        else:
            counts["other failures"] += 1
    return counts


TABLES = ("test_fuzz_commands", "test_fuzz_files", "test_fuzz_machine", "test_fuzz_campaign")


def _report(argv: list[str]) -> int:
    import argparse
    import importlib
    from concurrent.futures import ThreadPoolExecutor

    parser = argparse.ArgumentParser(description="Run the fuzz tables as subprocesses and count the outcomes.")
    parser.add_argument("--timeout", type=float, default=120.0)
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--only", default="", help="comma-separated case ids")
    parser.add_argument("--tables", default=",".join(TABLES), help="comma-separated table modules")
    parser.add_argument("--verbose", action="store_true")
    args = parser.parse_args(argv)
    cases = [c for name in args.tables.split(",") for c in importlib.import_module(f"tests.cli.{name}").CASES]
    if args.only:
        wanted = set(args.only.split(","))
        cases = [c for c in cases if c.id in wanted]

    def one(c: Case) -> tuple[Case, Outcome, str]:
        with tempfile.TemporaryDirectory(prefix="fuzz-") as folder:
            o = run_subprocess(c, Path(folder), args.timeout)
        return c, o, judge(c, o)

    counts = dict.fromkeys(OUTCOMES, 0)
    verdicts = []
    with ThreadPoolExecutor(args.jobs) as pool:
        for c, o, verdict in pool.map(one, cases):
            counts[verdict] += 1
            verdicts.append(verdict)
            if verdict != "pass" or args.verbose:
                last = (_lines(o.stderr) or [""])[-1][:160]
                print(f"{verdict:13s} {c.id:40s} exit {o.exit_code} {o.seconds:5.1f} s  {last}", flush=True)
    print(f"{len(cases)} cases: " + ", ".join(f"{k} {v}" for k, v in counts.items()))
    print("; ".join(f"{k} {v}" for k, v in summary_counts(cases, verdicts).items()))
    return 0


if __name__ == "__main__":
    sys.exit(_report(sys.argv[1:]))
