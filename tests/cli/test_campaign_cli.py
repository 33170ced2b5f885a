"""Command line: ``auxbearing campaign`` and ``campaign-report`` on real Dask clusters; kill and resume."""

import json
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from auxbearing.cli.main import cli
from tests.browser import CHROMIUM, probe_report, unreadable_numbers

AUXBEARING = str(Path(sys.executable).with_name("auxbearing"))

CONFIG = """
[campaign]
machine = "paper_rig"
sampler = "sobol"
samples = {samples}
seed = 3
batch_size = 2
[[campaign.input]]
key = "rotor.unbalance_phase"
distribution = "uniform"
low = "0 deg"
high = "360 deg"
[[campaign.input]]
key = "touchdown.0.sliding_friction"
distribution = "normal"
mean = 0.2
std = 0.03
{extra}
[drop]
duration = "{duration}"
"""


def write_config(folder: Path, samples=8, duration="20 ms", extra="") -> Path:
    path = folder / "campaign.toml"
    path.write_text(CONFIG.format(samples=samples, duration=duration, extra=extra))
    return path


def _run(*args):
    return CliRunner().invoke(cli, [str(a) for a in args], catch_exceptions=False)


def test_module_and_help_are_light():
    code = ("import sys, auxbearing.cli.campaign_cmd; "
            "print(sorted(m for m in ('numpy', 'dask', 'distributed', 'xarray', 'zarr', 'scipy') if m in sys.modules))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True).stdout
    assert out.strip() == "[]"
    r = _run("campaign", "--help")
    assert r.exit_code == 0 and "--scheduler" in r.output and "--workers" in r.output
    assert _run("campaign-report", "--help").exit_code == 0


BAD = {
    "unknown key": ("[[campaign.input]]\nkey = \"rotor.unbalance_phaze\"\ndistribution = \"uniform\"\n"
                    "low = \"0 deg\"\nhigh = \"1 deg\"", "unknown key"),
    "impossible distribution": ("[[campaign.input]]\nkey = \"rotor.unbalance\"\ndistribution = \"normal\"\n"
                                "mean = \"10 um\"\nstd = \"0 um\"", "must be > 0"),
    "key naming nothing": ("[[campaign.input]]\nkey = \"touchdown.2.sliding_friction\"\ndistribution = \"uniform\"\n"
                           "low = 0.1\nhigh = 0.3", "names nothing"),
}


@pytest.mark.parametrize("case", list(BAD))
def test_bad_campaign_file_exit_2_one_line_nothing_written(tmp_path, case):
    extra, message = BAD[case]
    config = write_config(tmp_path, extra=extra)
    store = tmp_path / "out" / "store.zarr"
    r = CliRunner().invoke(cli, ["campaign", "--config", str(config), "--out", str(store)])
    assert r.exit_code == 2
    lines = r.stderr.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: campaign.input.2") and message in lines[0]
    assert not (tmp_path / "out").exists()


@pytest.mark.parametrize(("args", "message"), [
    (["--workers", "0"], "--workers = '0'"),
    (["--workers", "two"], "--workers = 'two'"),
    (["--workers", "2", "--scheduler", "tcp://127.0.0.1:1"], "a --scheduler brings its own workers"),
    pytest.param(["--scheduler", "tcp://127.0.0.1:1"], "no Dask scheduler answers there", marks=pytest.mark.slow),
])
def test_bad_options_exit_2_one_line(tmp_path, args, message):
    config = write_config(tmp_path)
    r = CliRunner().invoke(cli, ["campaign", "--config", str(config), "--out", str(tmp_path / "s.zarr"), *args])
    assert r.exit_code == 2 and message in r.stderr and len(r.stderr.strip().splitlines()) == 1
    assert not (tmp_path / "s.zarr").exists()


def test_out_that_is_a_file_and_report_of_no_store(tmp_path):
    config = write_config(tmp_path)
    (tmp_path / "file").write_text("x")
    r = CliRunner().invoke(cli, ["campaign", "--config", str(config), "--out", str(tmp_path / "file")])
    assert r.exit_code == 2 and "not a folder" in r.stderr
    r = CliRunner().invoke(cli, ["campaign-report", str(tmp_path / "nothing"), "--out", str(tmp_path / "rep")])
    assert r.exit_code == 2 and "does not exist" in r.stderr and not (tmp_path / "rep").exists()


ISSUE_KEYS = ("samples", "completed", "failed", "out_of_range", "p_backward_whirl", "peak_ball_stress_MPa",
              "wall_time_s", "drops_per_second")


@pytest.mark.slow
def test_campaign_on_a_running_local_cluster_of_two_workers(tmp_path):
    from distributed import LocalCluster

    from auxbearing.campaign.config import read_campaign
    from auxbearing.campaign.evaluate import evaluate_sample
    from auxbearing.campaign.sampling import design
    from auxbearing.campaign.store import load_results

    # a normal unbalance of 2 +- 5 um gives some negative samples, which the machine refuses
    config = write_config(tmp_path, samples=8, extra='[[campaign.input]]\nkey = "rotor.unbalance"\n'
                          'distribution = "normal"\nmean = "2 um"\nstd = "5 um"')
    store = tmp_path / "s.zarr"
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True, dashboard_address=None) as cluster:
        r = CliRunner().invoke(cli, ["campaign", "--config", str(config), "--out", str(store), "--scheduler",
                                     cluster.scheduler_address, "--json", "--quiet"])
        assert r.exit_code == 0, r.output
        assert "rotor.unbalance" in r.stderr and "invalid_input" in r.stderr  # the campaign's note
        data = json.loads(r.stdout)
        assert len(cluster.scheduler.workers) == 2  # the command leaves a cluster it did not start running
    assert set(ISSUE_KEYS) <= set(data) and data["workers"] == 2
    assert data["samples"] == data["completed"] == 8
    assert {"value", "low", "high"} <= set(data["p_backward_whirl"])
    assert {"p50", "p95", "p99"} <= set(data["peak_ball_stress_MPa"])
    ds = load_results(store)
    campaign = read_campaign(config)
    values = design(campaign).values
    negative = values[:, 2] < 0.0  # refused by the machine: a record, not a crash
    assert negative.any() and data["failed"] == int(negative.sum())
    verdicts = np.array(ds.attrs["verdicts"])[ds["verdict"].values]
    assert (verdicts[negative] == "invalid_input").all() and (verdicts[~negative] == "ok").all()
    i = int(np.nonzero(~negative)[0][0])
    here = evaluate_sample(campaign, values[i])  # the workers' record equals one made here
    assert ds["peak_ball_stress"].values[i, 0] == here["peak_ball_stress"][0]
    assert ds["steps"].values[i] == here["steps"]
    report = tmp_path / "report"
    r = _run("campaign-report", store, "--out", report, "--json", "--whirl-map", "rotor.unbalance",
             "rotor.unbalance_phase")
    assert r.exit_code == 0
    for name in ("statistics.json", "probabilities.csv", "quantiles.csv", "sensitivity.csv", "samples.csv",
                 "histograms.png", "scatter_matrix.png", "whirl_map.png"):
        assert (report / name).is_file(), name
    header = (report / "quantiles.csv").read_text().splitlines()[0]
    assert "peak_ball_stress [MPa]" in header and "peak_contact_force [N]" in header
    page = (report / "report.html").read_text(encoding="utf-8")
    for heading in ("Probabilities", "Outcomes", "What drives the outcomes", "Figures"):
        assert f"<h2>{heading}" in page, heading
    # an engineer's words on the page: no variable names, no unformatted numbers
    assert "p_backward_whirl" not in page and "peak_ball_stress_MPa" not in page and "rotor.unbalance" not in page
    assert unreadable_numbers(page) == []
    if CHROMIUM is not None:
        seen = probe_report(page, tmp_path)
        assert seen["loaded"] == seen["images"] >= 2 and seen["empty"] == []
    r = CliRunner().invoke(cli, ["campaign-report", str(store), "--out", str(tmp_path / "r2"), "--whirl-map",
                                 "rotor.speed", "rotor.unbalance"])
    assert r.exit_code == 2 and "rotor.speed" in r.stderr and not (tmp_path / "r2").exists()


def _completed_batches(store: Path) -> int:
    folder = store / "completed"
    return len([p for p in folder.iterdir() if not p.name.startswith(".")]) if folder.is_dir() else 0


def _start(config: Path, store: Path) -> subprocess.Popen:
    return subprocess.Popen([AUXBEARING, "campaign", "--config", str(config), "--out", str(store), "--workers", "2",
                             "--quiet", "--json"], start_new_session=True, stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True)


def _stop_when(process: subprocess.Popen, store: Path, batches: int, sig: int, timeout: float = 300.0) -> None:
    deadline = time.monotonic() + timeout
    while _completed_batches(store) < batches:
        assert process.poll() is None, process.communicate()
        assert time.monotonic() < deadline, "the campaign did not write its first batches in time"
        time.sleep(0.02)
    os.killpg(process.pid, sig)  # the whole group, as a terminal's Ctrl-C or a kill of the session would


@pytest.mark.slow
def test_kill_and_resume_gives_the_store_of_an_uninterrupted_run(tmp_path):
    from auxbearing.campaign.store import load_results

    config = write_config(tmp_path, samples=16, duration="20 ms")
    store = tmp_path / "resumed.zarr"
    first = _start(config, store)
    _stop_when(first, store, 2, signal.SIGINT)
    _, err = first.communicate(timeout=120)
    assert first.returncode == 130 and "run the same command to resume" in err, err
    after_interrupt = _completed_batches(store)
    second = _start(config, store)
    _stop_when(second, store, after_interrupt + 2, signal.SIGKILL)
    second.communicate(timeout=60)
    assert second.returncode == -signal.SIGKILL
    part = load_results(store)
    done = int(part["completed"].values.sum())
    assert 0 < done < 16
    third = _start(config, store)
    out, err = third.communicate(timeout=600)
    assert third.returncode == 0, err
    resumed = json.loads(out)
    assert resumed["completed"] == 16 and resumed["new"] == 16 - done
    clean = _start(config, tmp_path / "clean.zarr")
    out, err = clean.communicate(timeout=600)
    assert clean.returncode == 0, err
    a, b = load_results(store), load_results(tmp_path / "clean.zarr")
    assert set(a.variables) == set(b.variables)
    for name in a.variables:
        if name in a.attrs["timing"]:
            continue
        x, y = a[name].values, b[name].values
        assert np.array_equal(x, y, equal_nan=x.dtype.kind == "f"), name
    assert {k: v for k, v in a.attrs.items() if k != "created"} == {k: v for k, v in b.attrs.items()
                                                                   if k != "created"}
    # a finished store runs nothing again
    again = _start(config, store)
    out, _ = again.communicate(timeout=120)
    assert json.loads(out)["new"] == 0
