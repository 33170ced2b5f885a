"""The first drop's side-by-side compilation: who compiles, when it is skipped, and that the helper does its part.

The compilation itself is not timed here (benchmarks/bench_cold_start.py does that). With the kernels already
cached, the helper only loads them, so the whole path runs in seconds.
"""

from __future__ import annotations

import subprocess

import pytest

from auxbearing.analysis import first_compile
from auxbearing.analysis.drop import _first_call
from auxbearing.machine.pack import pack
from auxbearing.planar import rig


@pytest.fixture
def model():
    return pack(rig.paper_rig())


@pytest.fixture
def marker(tmp_path, monkeypatch):
    path = tmp_path / "kernels" / "drop-kernel.compiled"
    monkeypatch.setattr(first_compile, "_marker", lambda model: str(path))
    monkeypatch.setattr(first_compile, "cache_folder", lambda: str(path.parent))
    monkeypatch.delenv(first_compile.ENV_SWITCH, raising=False)
    return path


def _no_helper(*args, **kwargs):
    raise AssertionError("a helper process was started")


def test_a_marked_kernel_is_warmed_up_here_without_a_helper(model, marker, monkeypatch):
    marker.parent.mkdir()
    marker.write_text("done\n")
    monkeypatch.setattr(subprocess, "Popen", _no_helper)
    calls = []
    first_compile.compile_side_by_side(model, calls.append)
    assert calls == [model]


def test_the_switch_turns_the_helper_off(model, marker, monkeypatch):
    monkeypatch.setenv(first_compile.ENV_SWITCH, "0")
    monkeypatch.setattr(subprocess, "Popen", _no_helper)
    calls = []
    first_compile.compile_side_by_side(model, calls.append)
    assert calls == [model]
    assert not marker.exists()  # switched off is not "done": a later run with the helper still gets it


@pytest.mark.slow
def test_a_cold_kernel_gets_a_helper_that_compiles_the_observer_then_a_marker(model, marker, monkeypatch):
    """The real path, with the cache warm: the helper reports the observer, the integrator runs, the marker is left."""
    started = []
    real_start = first_compile._start_helper

    def start(m):
        helper, blob = real_start(m)
        started.append(helper)
        return helper, blob

    calls = []
    monkeypatch.setattr(first_compile, "_start_helper", start)
    first_compile.compile_side_by_side(model, lambda m: calls.append(_first_call(m)))
    assert len(started) == 1 and started[0].returncode == 0
    assert len(calls) == 1
    assert marker.exists()
    calls.clear()
    first_compile.compile_side_by_side(model, calls.append)  # now marked: no second helper
    assert calls == [model] and len(started) == 1


def test_a_cache_folder_that_cannot_be_written_leaves_numba_alone(model, marker, monkeypatch):
    monkeypatch.setattr(first_compile, "cache_folder", lambda: "/proc/no-such-folder")
    monkeypatch.setattr(subprocess, "Popen", _no_helper)
    calls = []
    first_compile.compile_side_by_side(model, calls.append)
    assert calls == [model]


def test_a_helper_that_cannot_start_costs_only_time(model, marker, monkeypatch):
    def cannot(*args, **kwargs):
        raise OSError("no processes left")

    monkeypatch.setattr(subprocess, "Popen", cannot)
    calls = []
    first_compile.compile_side_by_side(model, calls.append)
    assert calls == [model] and marker.exists()


class _SlowHelper:
    """A helper still compiling: it has said nothing and not ended."""

    def __init__(self, *args, **kwargs):
        self.killed = False
        self.stdout = self

    def readline(self):
        return "observer compiled\n"

    def poll(self):
        return -9 if self.killed else None

    def kill(self):
        self.killed = True

    def wait(self):
        return -9


def test_an_interrupted_first_drop_stops_its_helper_and_leaves_no_marker(model, marker, monkeypatch):
    helpers = []

    def start(*args, **kwargs):
        helpers.append(_SlowHelper())
        return helpers[-1]

    def interrupted(m):
        raise KeyboardInterrupt

    monkeypatch.setattr(subprocess, "Popen", start)
    monkeypatch.setattr(first_compile, "_heard_from", lambda helper: True)  # the stand-in has no pipe to wait on
    with pytest.raises(KeyboardInterrupt):
        first_compile.compile_side_by_side(model, interrupted)
    assert helpers[0].killed and not marker.exists()


def test_no_helper_when_numba_does_not_compile(model, marker, monkeypatch):
    import numba

    monkeypatch.setattr(numba.config, "DISABLE_JIT", True)
    monkeypatch.setattr(subprocess, "Popen", _no_helper)
    calls = []
    first_compile.compile_side_by_side(model, calls.append)
    assert calls == [model]


def test_the_marker_is_named_after_the_kernel_signature(model):
    """Machines compiled for the same types share a marker; another plane count gets its own."""
    from auxbearing.machine.files import read_machine
    from tests.consistency.test_open_machine import FAR_PLANE, _blower

    blower = pack(read_machine("blower"))
    three_planes = pack(_blower(FAR_PLANE, duration="0.1 ms"))
    assert first_compile._marker(blower) == first_compile._marker(model)
    assert first_compile._marker(three_planes) != first_compile._marker(model)


def test_a_switch_value_other_than_0_or_1_is_bad_input_named_as_written(model, marker, monkeypatch):
    from auxbearing.common.errors import InputError

    monkeypatch.setenv(first_compile.ENV_SWITCH, "off")
    with pytest.raises(InputError, match=r"^AUXBEARING_COMPILE_HELPER = 'off': must be 0 .* or 1 "):
        first_compile.compile_side_by_side(model, lambda m: None)


def test_the_command_line_refuses_a_bad_switch_before_any_work(tmp_path):
    """One line naming the variable as written, exit 2, nothing written; a verification's workers never see it."""
    import os
    import sys

    env = {**os.environ, first_compile.ENV_SWITCH: "yes", "MPLBACKEND": "Agg"}
    done = subprocess.run([sys.executable, "-m", "auxbearing.cli.main", "verify", "--machine", "blower", "--out",
                           "out"], cwd=tmp_path, env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 2
    assert done.stderr.strip().splitlines() == [
        "error: AUXBEARING_COMPILE_HELPER = 'yes': must be 0 (compile in one process, as numba does on its own) or 1 "
        "(the default: a helper process compiles beside the first drop)"]
    assert not any(tmp_path.iterdir())


def test_a_helper_that_never_reports_is_stopped_after_its_patience(model, marker, monkeypatch):
    """The wait decides only who compiles: past it the helper is killed and the integrator compiles here."""
    import sys

    started = []
    real_popen = subprocess.Popen

    def silent(*args, **kwargs):
        started.append(real_popen([sys.executable, "-c", "import time; time.sleep(60)"], stdout=subprocess.PIPE,
                                  text=True))
        return started[-1]

    monkeypatch.setattr(subprocess, "Popen", silent)
    monkeypatch.setattr(first_compile, "HELPER_PATIENCE", 0.2)
    calls = []
    first_compile.compile_side_by_side(model, calls.append)
    assert calls == [model] and started[0].poll() is not None and marker.exists()


def test_a_process_waits_for_another_compiling_then_compiles_itself_past_the_patience(model, marker, monkeypatch):
    """The lock's holder (here: this test) never lets go; the waiter gives up after its patience and runs alone."""
    import fcntl

    marker.parent.mkdir()
    monkeypatch.setattr(first_compile, "HELPER_PATIENCE", 0.2)
    monkeypatch.setattr(first_compile, "LOCK_POLL", 0.05)
    monkeypatch.setattr(subprocess, "Popen", _no_helper)
    holder = open(str(marker) + ".lock", "w")  # another open file description: flock sees another holder
    try:
        fcntl.flock(holder, fcntl.LOCK_EX)
        calls = []
        first_compile.compile_side_by_side(model, calls.append)
        assert calls == [model] and not marker.exists()
    finally:
        holder.close()
