"""``auxbearing experiment`` from the command line: a hand-written CSV, a short synthetic drop, errors."""

import json
import math

import numpy as np
import pytest
import xarray as xr
from click.testing import CliRunner

from auxbearing.cli.main import cli
from auxbearing.experiment.synth import SensorModel, synthesize, write_csv
from auxbearing.planar.params import DropCase


def run(*args):
    return CliRunner().invoke(cli, list(args))


def hand_written_csv(path):
    """A drop typed in the docs' format: levitated, free fall onto the wall, rolling along it (no simulation)."""
    lines = ["# hand-written example in the format of docs/experiment.md", "time [ms], x [mm], y [mm]"]
    s, g = 0.2e-3, 9.80665
    t_drop = 2e-3
    t_hit = t_drop + math.sqrt(2 * (s + 3e-6) / g)
    for k in range(1500):
        t = k * 2e-5
        if t < t_drop:
            x, y = 0.0, 0.0
        elif t < t_hit:
            x, y = 0.0, -0.5 * g * (t - t_drop) ** 2
        else:  # pressed 3 um into the wall, creeping backward along it
            a = -math.pi / 2 - 40.0 * (t - t_hit)
            x, y = (s + 3e-6) * math.cos(a), (s + 3e-6) * math.sin(a)
        lines.append(f"{t * 1e3:.3f}, {x * 1e3 + 0.05:.6f}, {y * 1e3 - 0.02:.6f}")
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.slow
def test_hand_written_csv_without_fit(tmp_path):
    path = hand_written_csv(tmp_path / "hand.csv")
    out = tmp_path / "out"
    result = run("experiment", "--measured", str(path), "--bearing", "QJ202", "--no-fit", "--clearance", "0.2",
                 "--out", str(out), "--json", "--quiet")
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    assert data["synthetic"] is False
    assert data["preprocessing"]["offset_x_m"] == pytest.approx(50e-6, abs=1e-9)
    assert data["preprocessing"]["drop_time_s"] == pytest.approx(2e-3, abs=0.6e-3)
    m = data["measured"]
    assert m["clearance_source"] == "given"
    assert m["impacts"] == 1
    assert m["peak_excursion_um"] == pytest.approx(3.0, abs=0.25)  # the filter rings a little at the hit
    # 3 um beyond the wall, shared by line contact and ball set: a few hundred newtons
    assert 100 < m["peak_contact_force_N"] < 500
    assert {p.name for p in out.iterdir()} >= {"measured.nc", "simulated_configured.nc", "experiment_orbits.png",
                                               "experiment_force_stress.png", "experiment_summary.json"}
    ds = xr.open_dataset(out / "measured.nc")
    assert ds.contact_force.attrs["units"] == "N"
    ds.close()


@pytest.mark.slow
def test_short_synthetic_drop_with_fit_and_table(tmp_path):
    channels, truth = synthesize("QJ202", case=DropCase(sliding_friction=0.15, clearance=0.18e-3),
                                 sensor=SensorModel(pre_drop=2e-3), duration=0.02)
    path = write_csv(tmp_path / "short.csv", channels, truth)
    result = run("experiment", "--measured", str(path), "--fit-window", "14", "--out", str(tmp_path / "o"))
    assert result.exit_code == 0, result.output
    assert "SYNTHETIC" in result.output
    assert "Peak ball stress" in result.output and "clearance" in result.output
    summary = json.loads((tmp_path / "o" / "experiment_summary.json").read_text())
    rec = {r["parameter"]: r for r in summary["recovery"]}
    assert abs(rec["clearance"]["error"]) < 2.0  # um; the validation tests state the tolerances
    assert abs(rec["sliding_friction"]["error"]) < 0.02


@pytest.mark.parametrize(("args", "message"), [
    (("--measured", "nope.csv"), "error: --measured = 'nope.csv': not found"),
    (("--offset", "left"), "--offset = 'left'"),
    (("--cutoff", "8 kg"), "--cutoff = '8 kg': unit kilogram is not a frequency"),
    (("--unit", "x"), "--unit = 'x'"),
    (("--bearing", "QJ999"), "bearing = 'QJ999'"),
])
def test_user_mistakes_are_one_line(tmp_path, args, message):
    path = hand_written_csv(tmp_path / "hand.csv")
    base = ["experiment", "--measured", str(path), "--no-fit", "--out", str(tmp_path / "o")]
    result = run(*base, *args)
    assert result.exit_code == 2
    assert result.stdout == "" and not (tmp_path / "o").exists()
    assert len(result.stderr.strip().splitlines()) == 1
    assert message in result.stderr
    assert "Traceback" not in result.output


def test_bad_row_in_the_file_is_named(tmp_path):
    path = hand_written_csv(tmp_path / "hand.csv")
    lines = path.read_text().splitlines()
    lines[40] = "0.078, x, 0.0"
    path.write_text("\n".join(lines) + "\n")
    result = run("experiment", "--measured", str(path), "--no-fit", "--out", str(tmp_path / "o"))
    assert result.exit_code == 2
    assert "column 'x [mm]', line 41: 'x' is not a number" in result.output


@pytest.mark.slow
def test_units_given_as_options(tmp_path):
    t = np.arange(800) * 2e-5
    y = np.where(t > 2e-3, -0.5 * 9.80665 * (t - 2e-3) ** 2, 0.0)
    y = np.maximum(y, -203e-6)
    text = "time, x, y\n" + "".join(f"{a * 1e3:.3f}, 0.0, {b * 1e6:.3f}\n" for a, b in zip(t, y, strict=True))
    (tmp_path / "u.csv").write_text(text)
    result = run("experiment", "--measured", str(tmp_path / "u.csv"), "--unit", "time=ms", "--unit", "x=um",
                 "--unit", "y=um", "--no-fit", "--clearance", "0.2 mm", "--out", str(tmp_path / "o"), "--json")
    assert result.exit_code == 0, result.output
    assert json.loads(result.output)["measured"]["impacts"] == 1
