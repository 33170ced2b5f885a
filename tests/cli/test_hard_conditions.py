"""Hard conditions of issue 11: each run that used to hang now ends within its budget, a long drop stays in
bounded memory, a killed run leaves nothing a later run trips over, a full disk or Ctrl-C is one line.

Budgets are made small so the tests are quick. Runs that must be killed, limited or measured as a whole
process (SIGKILL, SIGINT, a file-size limit, peak memory) run as subprocesses; the rest in process.
"""

from __future__ import annotations

import json
import os
import resource
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest

from tests.cli.test_fuzz_harness import case, explain, judge, run_in_process

SYNTHETIC = Path(__file__).parents[2] / "src" / "auxbearing" / "catalog" / "experiments" / "qj202_drop_synthetic.csv"


def _run(tmp_path: Path, command: str, files: dict | None = None, expect: str = "ok", *names: str):
    """Run a command in process in an empty folder; returns (outcome, seconds)."""
    c = case("hard", command, *names, files=files, expect=expect)
    folder = tmp_path / "work"
    folder.mkdir(exist_ok=True)
    outcome = run_in_process(c, folder, limit=240)
    assert judge(c, outcome) == "pass", explain(c, outcome)
    return outcome


def _error_line(outcome) -> str:
    return next(ln for ln in outcome.stderr.splitlines() if ln.startswith("error:"))


def _subprocess(args: list[str], cwd: Path, **kwargs) -> subprocess.Popen:
    env = {**os.environ, "MPLBACKEND": "Agg"}
    return subprocess.Popen([sys.executable, "-m", "auxbearing.cli.main", *args], cwd=cwd, env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, **kwargs)


def _scratch(folder: Path, name: str) -> list[Path]:
    return sorted(folder.glob(f".{name}.partial-*"))


# ----------------------------------------------------------------------------- the hangs
def test_tiny_race_mass_is_refused_before_any_step(tmp_path):
    # issue 11: `drop --race-mass 1e-9` never finished; issue 20: it ran into its wall budget with nothing said.
    # The race on its damped contacts allows explicit steps of ~3e-12 s: some 1e10 steps, beyond the step budget
    start = time.monotonic()
    o = _run(tmp_path, "drop --race-mass 1e-9 --quiet", None, "error", "--race-mass", "1e-9", "stiff",
             "drop.max_steps")
    assert time.monotonic() - start < 10 and "e+10 steps for the 150 ms run" in _error_line(o)


@pytest.mark.slow
def test_light_race_is_said_stiff_and_ends_at_the_wall_time_budget(tmp_path):
    # a race of 1e-6 kg fits the step budget (2.3e7 steps) but not two seconds: said at the start, then the
    # wall-time budget ends the run in one line
    (tmp_path / "work").mkdir()
    o = run_in_process(case("budget", "drop --race-mass 1e-6 --max-wall-time 2s --quiet"), tmp_path / "work")
    lines = [ln for ln in o.stderr.splitlines() if ln.strip()]
    assert o.exit_code == 1 and not o.traceback and o.seconds < 30 and not o.new_files
    assert len(lines) == 2 and lines[0].startswith("warning: --race-mass = '1e-6': the race of 1e-06 kg")
    assert "makes the integration stiff" in lines[0]
    assert lines[1].startswith("error: --max-wall-time = 2 s: the drop used up its wall-time")
    assert "raise --max-wall-time" in lines[1]


def test_tiny_max_step_is_refused_before_any_step(tmp_path):
    # issue: `drop --max-step 0.001us` never finished: 1.5e8 steps at least, beyond the step budget
    start = time.monotonic()
    o = _run(tmp_path, "drop --max-step 0.001us", None, "error", "--max-step", "0.001us", "drop.max_steps")
    assert time.monotonic() - start < 10 and "1.5e+08 steps" in _error_line(o)


@pytest.mark.slow
def test_a_machine_run_past_its_budget_ends_with_that_verdict(tmp_path):
    # the machine's own budgets: a file's drop.max_wall_time stops the run with a verdict and partial results
    machine = (Path(__file__).parents[2] / "src/auxbearing/catalog/machines/paper_rig.toml").read_text()
    machine = machine.replace('race_mass = "0.0125 kg"', 'race_mass = "1e-9 kg"') + 'max_wall_time = "1 s"\n' \
        + "max_steps = 1e11\n"  # the stiff race fits a budget this large: the wall time ends it
    o = _run(tmp_path, "drop --machine m.toml --json --quiet", {"m.toml": machine})
    summary = json.loads(o.stdout)
    assert summary["verdict"] == "wall_time_budget" and summary["simulated_s"] < 0.15
    assert "drop.max_wall_time" in summary["reason"] and "raise it" in summary["reason"]
    assert "verdict wall_time_budget" in o.stderr


def test_a_spin_of_1e7_rpm_ends_with_a_range_verdict(tmp_path):
    # `drop --speed '1e7 rpm'` once never finished; the unbalance force is 1.5e7 N: the balls run over the
    # shoulder in the first impact, and the peaks up to there are reported with that verdict
    o = _run(tmp_path, "drop --speed '1e7 rpm' --json --quiet")
    summary = json.loads(o.stdout)
    assert summary["verdict"] == "contact_ellipse_over_shoulder" and summary["impacts"] == 1
    assert summary["peak_contact_force_N"] > 1e4
    assert "ran over the groove shoulder" in o.stderr


def test_an_eccentricity_of_1_m_is_warned_and_ends_with_a_verdict(tmp_path):
    # `drop --eccentricity '1 m'` once never finished
    o = _run(tmp_path, "drop --eccentricity '1 m' --json --quiet", None, "warning", "--eccentricity 1 m")
    assert json.loads(o.stdout)["verdict"] == "contact_ellipse_over_shoulder"
    assert "larger than the clearance" in o.stderr


def test_a_line_stiffness_of_1e15_is_refused(tmp_path):
    # `drop --line-stiffness 1e15` reported 407 662 impacts in 0.15 s: no material pair has such a contact
    o = _run(tmp_path, "drop --line-stiffness 1e15 --json --quiet", None, "error", "--line-stiffness", "1e+15")
    assert "times Palmgren's constant" in o.stderr and "Traceback" not in o.stderr


def test_a_ball_constant_of_1_is_refused_before_the_race_sinks(tmp_path):
    # issue: `drop --ball-constant '1 N/m**1.5'` sank the race 4.3 mm into the balls
    o = _run(tmp_path, "drop --ball-constant '1 N/m**1.5'", None, "error", "--ball-constant", "1 N/m**1.5")
    assert "sink" in _error_line(o)


@pytest.mark.slow
def test_a_bearing_of_6000_balls_is_refused_by_the_contact_budget(tmp_path):
    # issue: a bearing TOML with 6000 balls never finished (each step evaluates every ball contact)
    bearing = ('[bearing]\ntype = "four_point"\nball_diameter = "6 mm"\npitch_diameter = "12 m"\nball_count = 6000\n'
               'inner_groove_ratio = 0.52\nouter_groove_ratio = 0.52\ncontact_angle = "35 deg"\n'
               'diametral_clearance = "0 mm"\nball_material = "GCr15"\nring_material = "GCr15"\nbore = "11.99 m"\n'
               'width = "11 mm"\n')
    start = time.monotonic()
    o = _run(tmp_path, "drop --bearing big.toml", {"big.toml": bearing}, "error", "--bearing", "big.toml",
             "--max-ball-contacts")
    assert time.monotonic() - start < 10 and "12000 contacts" in _error_line(o)
    # the statics of the same bearing are one solve, not a time integration: they run
    _run(tmp_path, "static --bearing big.toml --radial 1000 --json", {"big.toml": bearing})


def _loads_csv(path: Path, rows: int) -> None:
    rng = np.random.default_rng(1)
    with path.open("w") as handle:
        handle.write("axial [N], radial [N], moment [N*m]\n")
        np.savetxt(handle, np.c_[rng.uniform(0, 500, rows), rng.uniform(0, 2000, rows), rng.uniform(0, 5, rows)],
                   delimiter=",", fmt="%.2f")


@pytest.mark.slow
def test_a_million_load_cases_are_refused_by_the_case_budget(tmp_path):
    # issue: `static-cases` with 10^6 rows never finished (the per-row post-processing took ~1 ms a row)
    start = time.monotonic()
    o = _run(tmp_path, "static-cases --loads big.csv", {"big.csv": lambda p: _loads_csv(p, 1_000_000)}, "error",
             "--loads", "big.csv", "--max-cases")
    assert time.monotonic() - start < 60 and "split the file or raise --max-cases" in _error_line(o)


@pytest.mark.slow
def test_twenty_thousand_load_cases_are_post_processed_column_by_column(tmp_path):
    start = time.monotonic()
    o = _run(tmp_path, "static-cases --loads big.csv --json", {"big.csv": lambda p: _loads_csv(p, 20_000)})
    assert json.loads(o.stdout)["cases"] == 20_000
    assert time.monotonic() - start < 60  # ~20 s one row at a time before; the solve itself takes ~2 s


def test_a_contact_sweep_step_of_1e_6_is_refused_before_any_array(tmp_path):
    # issue: a contact-sweep step of 1e-6 asked for 19 GiB
    start = time.monotonic()
    o = _run(tmp_path, "contact-sweep --angle-range 10 75 1e-6", None, "error", "--angle-range", "--max-points")
    assert time.monotonic() - start < 10 and "6.5e+07 values" in _error_line(o)


@pytest.mark.slow
def test_a_sweep_never_goes_past_its_stop(tmp_path):
    # issue: `10 89.9 5` swept 90 deg and was then refused
    import xarray as xr

    o = _run(tmp_path, "contact-sweep --angle-range 10 89.9 5 --ratio-range 0.52 0.53 0.005 --out o --json")
    angles = xr.load_dataset(tmp_path / "work" / "o" / "contact_map.nc").contact_angle.values
    assert angles.max() == pytest.approx(85.0) and json.loads(o.stdout)["out"] == "o"


def test_a_speed_in_hz_is_revolutions_per_second(tmp_path):
    # issue: `drop --speed '100 Hz'` ran at 100 rad/s (955 rpm)
    o = _run(tmp_path, "drop --speed '100 Hz' --duration '0.5 ms' --output-step '50 us' --json --quiet")
    assert json.loads(o.stdout)["final_rotor_speed_rad_s"] == pytest.approx(200 * np.pi, rel=1e-3)


# ----------------------------------------------------------------------------- memory of a long drop
@pytest.mark.slow
def test_an_8_s_drop_runs_in_bounded_memory(tmp_path):
    # issue: `drop --duration 20` reached 10 GB and died; the output is now written on a coarser grid (and says so).
    # 8 s is twice the default output cap: on the full grid it would take about 4 GB
    proc = _subprocess(["drop", "--duration", "8", "--json", "--quiet"], tmp_path)
    out, err = proc.communicate(timeout=1200)
    peak_kb = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss  # the largest child so far, in kB on Linux
    assert proc.returncode == 0, err
    summary = json.loads(out)
    assert summary["verdict"] == "ok" and summary["output_decimated"]
    assert summary["output_step_s"] == pytest.approx(8.0 / (4e5 - 1))
    assert "drop.max_output_points" in err
    assert peak_kb < 2.5e6, f"peak RSS {peak_kb / 1e6:.2f} GB"


# ----------------------------------------------------------------------------- output folders
def _wait_for(predicate, seconds: float) -> bool:
    end = time.monotonic() + seconds
    while time.monotonic() < end:
        if predicate():
            return True
        time.sleep(0.05)
    return False


@pytest.mark.slow
def test_a_killed_run_leaves_scratch_that_the_next_run_removes(tmp_path):
    _loads_csv(tmp_path / "l.csv", 200_000)
    proc = _subprocess(["static-cases", "--loads", "l.csv", "--out", "o"], tmp_path)
    try:
        assert _wait_for(lambda: _scratch(tmp_path, "o"), 120), proc.stderr.read() if proc.poll() else "no scratch"
    finally:
        proc.send_signal(signal.SIGKILL)
        proc.communicate()
    assert _scratch(tmp_path, "o") and not (tmp_path / "o").exists()  # what a hard kill leaves
    (tmp_path / "small.csv").write_text("radial [N]\n1000\n")
    o = _run(tmp_path, "static-cases --loads small.csv --out ../o --json", {"small.csv": "radial [N]\n1000\n"})
    assert o.exit_code == 0 and not _scratch(tmp_path, "o")
    assert {p.name for p in (tmp_path / "o").iterdir()} == {"static_cases.nc", "static_cases.csv",
                                                            "static_cases.json"}


def test_scratch_of_a_live_run_is_kept_and_of_a_dead_one_removed(tmp_path):
    import socket

    from auxbearing.common.io import SCRATCH_OWNER, remove_stale_scratch

    live, dead, foreign = tmp_path / ".o.partial-live", tmp_path / ".o.partial-dead", tmp_path / ".o.partial-x"
    for folder in (live, dead, foreign):
        folder.mkdir()
    (live / SCRATCH_OWNER).write_text(f"{socket.gethostname()} {os.getpid()}\n")
    gone = subprocess.Popen([sys.executable, "-c", "pass"])
    gone.wait()
    (dead / SCRATCH_OWNER).write_text(f"{socket.gethostname()} {gone.pid}\n")
    assert remove_stale_scratch(tmp_path / "o") == [dead]
    assert live.exists() and foreign.exists() and not dead.exists()  # no marker: not ours, left alone


@pytest.mark.slow
def test_ctrl_c_leaves_no_folder_and_no_traceback(tmp_path):
    proc = _subprocess(["drop", "--duration", "3", "--out", "o", "--quiet"], tmp_path)
    try:
        assert _wait_for(lambda: _scratch(tmp_path, "o"), 120)
        # into the integration (about 6 s of this 3 s drop): an interrupt while the interpreter is still importing
        # or numba loading a cached kernel can be printed as "Exception ignored" by CPython itself (seen on a
        # loaded machine, where those last longer); that race is known and not what this test is about
        time.sleep(3.0)
    finally:
        proc.send_signal(signal.SIGINT)
        _, err = proc.communicate(timeout=120)
    assert proc.returncode != 0 and "Traceback" not in err
    assert not _scratch(tmp_path, "o") and not (tmp_path / "o").exists()


def _file_size_limit(limit: int):
    def apply() -> None:
        signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # a write past the limit then fails with EFBIG
        resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))

    return apply


@pytest.mark.slow
def test_a_full_disk_is_one_line_and_leaves_nothing(tmp_path):
    # issue: a full disk under --out was a 55-line NetCDF/HDF traceback; a file-size limit fails writes alike
    _loads_csv(tmp_path / "l.csv", 2000)
    # the same solve once without the limit, so the compiled kernels are on disk and the limited run only loads them
    _run(tmp_path, "static-cases --loads l.csv --json", {"l.csv": (tmp_path / "l.csv").read_text()})
    proc = _subprocess(["static-cases", "--loads", "l.csv", "--out", "o"], tmp_path,
                       preexec_fn=_file_size_limit(100_000))
    _, err = proc.communicate(timeout=300)
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert proc.returncode == 2 and len(lines) == 1 and lines[0].startswith("error: file"), err
    assert "static_cases" in lines[0]
    assert not (tmp_path / "o").exists() and not _scratch(tmp_path, "o")


# ----------------------------------------------------------------------------- experiment records
@pytest.mark.slow
def test_a_record_with_rest_appended_is_read(tmp_path):
    # issue: 0.4 s of rest appended made the first 1 % of samples reach past the drop; the record was refused
    text = SYNTHETIC.read_text().rstrip("\n").splitlines()
    last = text[-1].split(",")
    t_end, step = float(last[0]), 1.0 / 50e3
    rest = [f"{t_end + k * step:.6f},{last[1]},{last[2]}" + ("," + last[3] if len(last) > 3 else "")
            for k in range(1, 20_001)]
    o = _run(tmp_path, "experiment --measured m.csv --no-fit --clearance '180 um' --out o --json --quiet",
             {"m.csv": "\n".join([*text, *rest]) + "\n"})
    summary = json.loads(o.stdout)
    assert summary["preprocessing"]["drop_detection"].startswith("first excursion")
    assert summary["measured"]["impacts"] > 0 and summary["measured"]["peak_contact_force_N"] > 100


@pytest.mark.slow
def test_no_fit_with_a_clearance_above_the_orbit_is_warned(tmp_path):
    # issue: `experiment --no-fit` on the shipped drop reported 0 N, 0 MPa, 0 impacts without a word (200 > 180 um)
    o = _run(tmp_path, "experiment --measured m.csv --no-fit --out o --json --quiet",
             {"m.csv": SYNTHETIC.read_text()}, "warning", "never reaches the clearance circle", "--clearance")
    assert json.loads(o.stdout)["measured"]["impacts"] == 0


# ----------------------------------------------------------------------------- one writer per campaign store
CAMPAIGN = ('[campaign]\nmachine = "paper_rig"\nsamples = {samples}\nseed = 1\nbatch_size = 2\n[[campaign.input]]\n'
            'key = "rotor.unbalance_phase"\ndistribution = "uniform"\nlow = "0 deg"\nhigh = "360 deg"\n'
            '[drop]\nduration = "{duration}"\n')


def _campaign(folder: Path, samples: int = 8, duration: str = "5 ms") -> subprocess.Popen:
    (folder / "c.toml").write_text(CAMPAIGN.format(samples=samples, duration=duration))
    return _subprocess(["campaign", "--config", "c.toml", "--out", "s.zarr", "--workers", "1", "--quiet", "--json"],
                       folder, start_new_session=True)


@pytest.mark.slow
def test_two_campaigns_on_one_fresh_store_one_writes_the_other_is_refused(tmp_path):
    # issue 20: both ran (every drop computed and written twice), or one failed naming a hidden scratch folder
    first, second = _campaign(tmp_path), _campaign(tmp_path)
    results = [(p.returncode, out, err) for p in (first, second) for out, err in [p.communicate(timeout=600)]]
    codes = sorted(code for code, _, _ in results)
    assert codes == [0, 2], results
    _, _, refusal = next(r for r in results if r[0] == 2)
    lines = [ln for ln in refusal.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: --out = 's.zarr': another campaign is writing it")
    assert ".s.zarr" not in lines[0] and "partial" not in lines[0] and "Traceback" not in refusal
    _, out, _ = next(r for r in results if r[0] == 0)
    assert json.loads(out)["completed"] == 8
    assert sorted(p.name for p in tmp_path.iterdir()) == ["c.toml", "s.zarr"]  # no lock, no scratch left


@pytest.mark.slow
def test_a_killed_campaign_leaves_a_stale_lock_the_next_one_takes_over(tmp_path):
    from auxbearing.campaign.store import load_results, lock_path

    first = _campaign(tmp_path, samples=16, duration="20 ms")
    lock = lock_path(tmp_path / "s.zarr")
    assert _wait_for(lambda: (tmp_path / "s.zarr" / "completed").is_dir() and lock.exists(), 300)
    held_by = int(lock.read_text().split()[1])
    assert held_by == first.pid
    second = _campaign(tmp_path, samples=16, duration="20 ms")  # while the first runs: refused
    _, err = second.communicate(timeout=120)
    assert second.returncode == 2 and f"another campaign is writing it (process {held_by} on this host" in err
    os.killpg(first.pid, signal.SIGKILL)
    first.communicate(timeout=60)
    assert lock.exists()  # a kill leaves the lock behind
    third = _campaign(tmp_path, samples=16, duration="20 ms")
    out, err = third.communicate(timeout=600)
    lines = [ln for ln in err.splitlines() if ln.strip()]
    assert third.returncode == 0 and len(lines) == 1, err
    assert lines[0].startswith(f"warning: store = 's.zarr': took over the lock of process {held_by} on this host")
    assert json.loads(out)["completed"] == 16 and not lock.exists()
    assert int(load_results(tmp_path / "s.zarr")["completed"].values.sum()) == 16
