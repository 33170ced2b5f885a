"""The campaign store: layout, batch writes, completed flags, resume checks; records and verdict codes."""

import json

import numpy as np
import pytest

from auxbearing.campaign import evaluate as ev
from auxbearing.campaign.config import campaign_from_mapping
from auxbearing.campaign.sampling import design
from auxbearing.campaign.store import (
    MARK,
    completed,
    load_results,
    pending_batches,
    prepare_store,
    read_attrs,
    write_batch,
)
from auxbearing.common.errors import InputError


def small(seed=1, samples=6, batch=2, duration="2 ms"):
    return campaign_from_mapping({
        "campaign": {"machine": "paper_rig", "samples": samples, "seed": seed, "batch_size": batch, "input": [
            {"key": "rotor.unbalance_phase", "distribution": "uniform", "low": "0 deg", "high": "360 deg"},
            {"key": "touchdown.0.sliding_friction", "distribution": "normal", "mean": 0.2, "std": 0.03}]},
        "drop": {"duration": duration}})


def test_verdict_codes_cover_the_drop_verdicts():
    from auxbearing.analysis import drop
    from auxbearing.analysis.whirl import BACKWARD, CLASSES
    from auxbearing.core.watch import STOP_NAMES

    assert set(ev.OUT_OF_RANGE) == set(STOP_NAMES.values())
    for verdict in (drop.OK, drop.STEP_BUDGET, drop.WALL_BUDGET, drop.INTEGRATION_FAILED):
        assert verdict in ev.VERDICTS
    assert ev.WHIRL_CODES[1:] == CLASSES and set(ev.BACKWARD_CLASSES) == set(BACKWARD)


def test_store_layout(tmp_path):
    c = small()
    points = design(c)
    path = tmp_path / "s.zarr"
    assert prepare_store(path, c, points) is True
    assert read_attrs(path)[MARK] == c.fingerprint()
    assert not [p for p in tmp_path.iterdir() if p.name.startswith(".")]  # the scratch folder is gone
    ds = load_results(path)
    assert dict(ds.sizes) == {"sample": 6, "input": 2, "plane": 1}
    assert np.array_equal(ds["unit"].values, points.unit) and np.array_equal(ds["value"].values, points.values)
    assert list(ds["input"].values) == list(c.keys) and list(ds["input_display_unit"].values) == ["deg", ""]
    assert ds["input_display_scale"].values[0] == pytest.approx(180 / np.pi)
    assert not completed(path).any() and (ds["verdict"].values == 0).all()
    assert np.isnan(ds["peak_ball_stress"].values).all() and ds["peak_ball_stress"].attrs["units"] == "Pa"
    sample_vars, plane_vars = ev.output_variables("drop")
    for name in [*sample_vars, *plane_vars]:
        assert name in ds
    raw = json.loads((path / "verdict" / ".zarray").read_text())
    assert raw["chunks"] == [2]  # one chunk per batch: a batch write touches its own files only
    assert json.loads(ds.attrs["campaign"])["seed"] == 1


@pytest.mark.slow
def test_batches_are_written_into_their_region_and_flagged(tmp_path):
    c = small()
    points = design(c)
    path = tmp_path / "s.zarr"
    prepare_store(path, c, points)
    assert pending_batches(path, c.runs, c.batch_size) == [(0, 2), (2, 4), (4, 6)]
    arrays = ev.evaluate_batch(c, points.values[2:4])
    write_batch(path, 2, arrays)
    assert completed(path).tolist() == [False, False, True, True, False, False]
    assert pending_batches(path, c.runs, c.batch_size) == [(0, 2), (4, 6)]
    ds = load_results(path)
    assert ds["verdict"].values.tolist()[2:4] == [ev.VERDICTS.index("ok")] * 2
    assert np.isfinite(ds["peak_contact_force"].values[2:4]).all()
    assert np.isnan(ds["peak_contact_force"].values[[0, 1, 4, 5]]).all()
    # the same campaign finds its store; another one is refused with one line
    assert prepare_store(path, c, points) is False
    with pytest.raises(InputError, match=r"holds another campaign \(it differs in seed\)"):
        prepare_store(path, small(seed=2), design(small(seed=2)))


def test_a_folder_that_is_not_a_store_is_refused(tmp_path):
    (tmp_path / "x").mkdir()
    (tmp_path / "x" / "file.txt").write_text("hello")
    c = small()
    with pytest.raises(InputError, match="not a campaign store"):
        prepare_store(tmp_path / "x", c, design(c))
    with pytest.raises(InputError, match="nothing': does not exist"):
        load_results(tmp_path / "nothing")


def test_records_of_refused_and_failing_samples(monkeypatch):
    c = small()
    bad = ev.evaluate_sample(c, [0.0, -0.5])  # a friction below 0: the machine refuses it
    assert ev.VERDICTS[bad["verdict"]] == "invalid_input"
    assert bad["reason"].startswith("touchdown.0.sliding_friction") and np.isnan(bad["peak_ball_stress"]).all()

    import auxbearing.analysis.drop

    def broken(*args, **kwargs):
        raise RuntimeError("boom\nsecond line")

    monkeypatch.setattr(auxbearing.analysis.drop, "run_machine", broken)
    record = ev.evaluate_sample(c, [0.0, 0.2])
    assert ev.VERDICTS[record["verdict"]] == "error" and record["reason"] == "RuntimeError: boom second line"
    assert record["sample_time"] >= 0.0


def test_out_of_range_run_is_a_record_with_its_verdict():
    c = campaign_from_mapping({
        "campaign": {"machine": "paper_rig", "samples": 2, "input": [
            {"key": "rotor.unbalance_phase", "distribution": "uniform", "low": "0 deg", "high": "360 deg"}]},
        "drop": {"duration": "20 ms", "ball_stress_limit": "1000 MPa"}})
    record = ev.evaluate_sample(c, [0.0])
    assert ev.VERDICTS[record["verdict"]] == "ball_stress_beyond_elastic"
    # the peaks up to the stop are kept (the statistics use only runs that ended ok)
    assert (record["peak_ball_stress"] > 1000e6).all() and np.isfinite(record["s0"]).all()
    assert "1000 MPa" in record["reason"]


@pytest.mark.slow
def test_coastdown_campaign_records_heat_and_life(tmp_path):
    pytest.importorskip("auxbearing.analysis.coastdown")
    from auxbearing.campaign.statistics import campaign_statistics

    c = campaign_from_mapping({
        "campaign": {"machine": "paper_rig", "samples": 2, "analysis": "coastdown", "batch_size": 2, "input": [
            {"key": "touchdown.0.sliding_friction", "distribution": "uniform", "low": 0.1, "high": 0.3},
            {"key": "coastdown.ambient_temperature", "distribution": "normal", "mean": "20 degC", "std": "3 K"}]},
        "drop": {"duration": "20 ms"}, "coastdown": {"max_time": "0.3 s"}})
    assert c.inputs[1].distribution.params == pytest.approx((293.15, 3.0))
    points = design(c)
    path = tmp_path / "s.zarr"
    prepare_store(path, c, points)
    write_batch(path, 0, ev.evaluate_batch(c, points.values))
    ds = load_results(path)
    assert (ds["verdict"].values == ev.VERDICTS.index("ok")).all()
    ambient_c = points.values[:, 1] - 273.15  # each sample's own ambient: friction heat lifts the parts above it
    assert (ds["max_temperature"].values[:, 0] > ambient_c).all() and (ds["damage_per_drop"].values > 0.0).all()
    assert np.isnan(ds["coastdown_time"].values).all()  # 0.3 s is too short to stand still
    assert np.isfinite(ds["peak_ball_stress"].values).all()
    stats = campaign_statistics(ds)
    assert {"max_temperature_C", "damage_per_drop", "allowed_drops_min"} <= set(stats["quantiles"])


def test_temperature_spread_in_degrees_celsius_is_refused():
    with pytest.raises(InputError, match="a spread of temperature is given in K"):
        campaign_from_mapping({
            "campaign": {"machine": "paper_rig", "samples": 2, "input": [
                {"key": "coastdown.ambient_temperature", "distribution": "normal", "mean": "20 degC",
                 "std": "3 degC"}]}})


# ----------------------------------------------------------------------------- one writer per store (issue 20)
def _dead_pid() -> int:
    import subprocess
    import sys

    process = subprocess.Popen([sys.executable, "-c", "pass"])
    process.wait()
    return process.pid


def test_the_lock_is_held_while_writing_and_released_after(tmp_path):
    import os
    import socket

    from auxbearing.campaign.store import lock_path, store_lock

    path = tmp_path / "s.zarr"
    with store_lock(path) as lock:
        assert lock == lock_path(path) and lock.name == ".s.zarr.lock"
        host, pid, since = lock.read_text().split()
        assert host == socket.gethostname() and int(pid) == os.getpid() and since
        with pytest.raises(InputError) as err:  # a second writer, here a live process (this one)
            with store_lock(path):
                pass
        text = str(err.value)
        assert text.startswith(f"store = '{path}': another campaign is writing it (process {os.getpid()} on this host")
        assert ".partial" not in text and ".lock" not in text
    assert not lock.exists() and [p.name for p in tmp_path.iterdir()] == []


def test_a_stale_lock_is_taken_over_with_a_note(tmp_path):
    import socket

    from auxbearing.campaign.store import StoreLockNote, lock_path, store_lock

    path = tmp_path / "s.zarr"
    dead = _dead_pid()
    lock_path(path).write_text(f"{socket.gethostname()} {dead} 2024-01-01T00:00:00+00:00\n")
    with pytest.warns(StoreLockNote, match=f"took over the lock of process {dead} on this host, which has ended"):
        with store_lock(path):
            pass
    lock_path(path).write_text("not a lock\n")  # a file that names no process is no one's lock either
    with pytest.warns(StoreLockNote, match="a lock file that names no process"):
        with store_lock(path):
            pass
    assert [p.name for p in tmp_path.iterdir()] == []


def test_a_lock_of_another_host_is_refused_with_where_it_is(tmp_path):
    from auxbearing.campaign.store import lock_path, store_lock

    path = tmp_path / "s.zarr"
    lock_path(path).write_text("elsewhere.example 1234 2024-01-01T00:00:00+00:00\n")
    with pytest.raises(InputError, match=r"process 1234 on host elsewhere\.example since 2024-01-01") as err:
        with store_lock(path):
            pass
    assert "delete the lock file" in str(err.value) and lock_path(path).exists()


def test_a_campaign_run_refuses_a_store_another_writes(tmp_path):
    import os
    import socket

    from auxbearing.campaign.run import run_campaign
    from auxbearing.campaign.store import lock_path

    path = tmp_path / "s.zarr"
    lock_path(path).write_text(f"{socket.gethostname()} {os.getpid()} 2024-01-01T00:00:00+00:00\n")
    with pytest.raises(InputError, match="another campaign is writing it"):
        run_campaign(small(), path)
    assert not path.exists()  # refused before the store was made


# ----------------------------------------------------------------------------- damaged stores (issue 20)
def _written_store(tmp_path):
    c = small()
    points = design(c)
    path = tmp_path / "s.zarr"
    prepare_store(path, c, points)
    sample, plane = ev.output_variables(c.analysis)
    arrays = {name: np.full((2, 1) if name in plane else (2,), "" if dtype.startswith("<U") else 1, dtype=dtype)
              for name, (dtype, *_) in {**sample, **plane}.items()}
    write_batch(path, 0, arrays)
    return c, points, path


def test_damaged_stores_are_one_line_naming_the_store(tmp_path):
    import shutil

    from auxbearing.campaign.store import check_chunks

    c, points, path = _written_store(tmp_path)
    assert load_results(path)["verdict"].values.tolist()[:2] == [1, 1]
    check_chunks(path)
    chunk = path / "peak_ball_stress" / "0.0"
    data = chunk.read_bytes()
    chunk.write_bytes(data[:-4])  # blosc would decode this from memory past the file's end, without a word
    with pytest.raises(InputError, match=r"store = '.*s\.zarr': the array 'peak_ball_stress' has a chunk cut short"):
        load_results(path)
    with pytest.raises(InputError, match="chunk cut short"):  # a resume is refused alike
        prepare_store(path, c, points)
    chunk.write_bytes(data)
    # a chunk write that a killed campaign left unfinished (zarr's temporary file) is no damage: a resume redoes it
    (path / "peak_ball_stress" / "1.0.0123456789abcdef0123456789abcdef.partial").write_bytes(b"")
    check_chunks(path)
    assert load_results(path)["verdict"].values.tolist()[:2] == [1, 1]
    shutil.rmtree(path / "s0")
    with pytest.raises(InputError, match="the array 's0' is missing"):
        load_results(path)
    (path / ".zattrs").write_text("{not json")
    with pytest.raises(InputError, match=r"its metadata \(\.zattrs\) cannot be read \(JSONDecodeError"):
        load_results(path)
    (path / ".zattrs").write_text("[1, 2]")
    with pytest.raises(InputError, match="is not a table of attributes"):
        read_attrs(path)


def test_complete_run_counts_samples_from_the_first_without_a_gap():
    import numpy as np

    from auxbearing.campaign.run import _complete_run

    assert _complete_run(np.array([True, True, False, True])) == 2
    assert _complete_run(np.array([False, True])) == 0
    assert _complete_run(np.ones(3, bool)) == 3


def test_a_batch_that_waits_holds_back_the_ones_after_it():
    import numpy as np

    from auxbearing.campaign.run import _within_reach

    settled = np.zeros(64, dtype=bool)
    settled[8:40] = True  # batches of 8: the first still out, the next four in
    assert _within_reach(16, settled, 32) and not _within_reach(32, settled, 32) and not _within_reach(40, settled, 32)
    settled[:8] = True  # it came in: the reach counts from the first sample not in
    assert _within_reach(64 - 8, settled, 32)


@pytest.mark.slow
def test_a_decided_campaign_stops_on_its_first_complete_samples(tmp_path):
    from auxbearing.campaign.run import run_campaign

    asked = []

    def decided(store, n):
        asked.append(n)
        return n >= 4

    out = run_campaign(small(samples=12, batch=2), tmp_path / "s.zarr", workers=1, decided=decided)
    # asked of every batch end in design order, each once; stopped at the first that settles it
    assert asked == [2, 4]
    assert out["decided_at"] == 4
    assert out["completed"] < 12
    # a resumed store that already settles it runs nothing more, and stops where the first run did
    asked.clear()
    again = run_campaign(small(samples=12, batch=2), tmp_path / "s.zarr", workers=1, decided=decided)
    assert again["decided_at"] == 4 and again["new"] == 0 and asked == [2, 4]


def test_the_whirl_criterion_fails_whatever_follows_only_when_the_rest_cannot_save_it():
    from auxbearing.verify.criteria import whirl_fails_whatever_follows

    # 7 whirls among 60 drops, 68 left: at best 7 / 128 = 0.055 > 0.05
    assert whirl_fails_whatever_follows(7, 60, 68, 0.05)
    # 6 whirls: 6 / 128 = 0.047, the rest could still bring the estimate within the limit
    assert not whirl_fails_whatever_follows(6, 60, 68, 0.05)
    assert not whirl_fails_whatever_follows(0, 0, 0, 0.05)


def test_a_store_part_written_opens_with_xarrays_defaults_and_shows_its_batches(tmp_path):
    """Its metadata is consolidated when it is made (arrays and attributes never change after): a user's plain
    xarray.open_zarr reads it without a warning, and the batches written since are there."""
    import warnings

    import xarray as xr

    c = small()
    points = design(c)
    path = tmp_path / "s.zarr"
    prepare_store(path, c, points)
    write_batch(path, 2, ev.evaluate_batch(c, points.values[2:4]))
    with warnings.catch_warnings():
        warnings.simplefilter("error", RuntimeWarning)
        ds = xr.open_zarr(path)
    assert ds["completed"].values.tolist() == [0, 0, 1, 1, 0, 0]
    assert np.isfinite(ds["max_excursion"].values[2:4]).all()


def test_a_sample_records_the_rotor_at_its_magnetic_bearings_and_nan_without_them():
    from dataclasses import replace

    from auxbearing.analysis.drop import run_machine
    from auxbearing.machine.files import read_machine

    inputs = [{"key": "touchdown.0.sliding_friction", "distribution": "uniform", "low": 0.1, "high": 0.3}]
    blower = campaign_from_mapping({"campaign": {"machine": "blower", "samples": 1, "input": inputs},
                                    "drop": {"duration": "2 ms"}})
    record = ev.evaluate_sample(blower, [0.2])
    # the same drop run directly: the largest of its radial bearings' records (the thrust bearing has none)
    machine = read_machine("blower").with_simulation(duration=0.002)
    planes = (replace(machine.planes[0], sliding_friction=0.2), *machine.planes[1:])
    amb = run_machine(replace(machine, planes=planes).for_batch(), lean=True).summary["amb"]
    radial = [a["max_excursion_um"] for a in amb if a["max_excursion_um"] is not None]
    assert len(radial) == 2 and record["max_bearing_excursion"] == pytest.approx(max(radial) * 1e-6, rel=1e-12)
    assert np.isnan(ev.evaluate_sample(small(), [0.2])["max_bearing_excursion"])  # the paper rig has none


def test_a_store_made_before_an_output_was_recorded_is_read_but_not_resumed(tmp_path):
    import shutil

    from auxbearing.campaign.statistics import campaign_statistics

    c = small()
    points = design(c)
    path = tmp_path / "s.zarr"
    prepare_store(path, c, points)
    write_batch(path, 0, ev.evaluate_batch(c, points.values[0:2]))
    shutil.rmtree(path / "max_bearing_excursion")  # as a store of the version before
    ds = load_results(path)
    assert "max_bearing_excursion" not in ds
    assert campaign_statistics(ds)["largest_bearing_excursion_mm"] is None
    with pytest.raises(InputError, match="the array 'max_bearing_excursion' is missing"):
        prepare_store(path, c, points)  # its new samples would record what its old ones lack
