"""``auxbearing contact`` and ``contact-sweep`` from the command line."""

import json
import subprocess
import sys
from pathlib import Path

import pytest
import xarray as xr
from click.testing import CliRunner

from auxbearing.cli.main import cli

EXAMPLE = Path(__file__).parents[2] / "examples" / "my_bearing.toml"
CONTACT_KEYS = {"contact_load_N", "semi_major_mm", "semi_minor_mm", "approach_um", "max_stress_MPa",
                "ellipticity", "stiffness_N_per_m1_5"}


def run(*args):
    return CliRunner().invoke(cli, list(args))


def test_contact_json_matches_the_paper():
    result = run("contact", "--bearing", "QJ202", "--ball-load", "1000", "--json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    assert data["bearing"] == "QJ202"
    assert CONTACT_KEYS <= set(data["inner"]) and CONTACT_KEYS <= set(data["outer"])
    assert data["inner"]["max_stress_MPa"] == pytest.approx(2616, rel=0.01)
    assert data["inner"]["max_stress_MPa"] > data["outer"]["max_stress_MPa"]


def test_units_and_overrides():
    a = json.loads(run("contact", "--ball-load", "1 kN", "--json").output)
    b = json.loads(run("contact", "--ball-load", "1000", "--json").output)
    assert a["inner"]["max_stress_MPa"] == pytest.approx(b["inner"]["max_stress_MPa"])
    c = json.loads(run("contact", "--contact-angle", "20", "--groove-ratio", "0.51", "--json").output)
    assert c["contact_angle_deg"] == pytest.approx(20)
    assert c["inner"]["groove_ratio"] == pytest.approx(0.51)
    assert c["inner"]["max_stress_MPa"] < b["inner"]["max_stress_MPa"]


def test_toml_bearing_and_readable_table():
    result = run("contact", "--bearing", str(EXAMPLE))
    assert result.exit_code == 0
    assert "Max contact stress" in result.output and "MPa" in result.output


@pytest.mark.parametrize(
    ("args", "message"),
    [
        (["--ball-load", "6 kg"], "error: --ball-load = '6 kg': unit kilogram is not a force"),
        (["--ball-load", "-5"], "error: --ball-load = '-5': must be >= 0 N"),
        (["--ball-load", "-5 kN"], "error: --ball-load = '-5 kN': must be >= 0 N"),
        (["--bearing", "nope"], "error: --bearing = 'nope': unknown; catalogue names are QJ202"),
        (["--groove-ratio", "0.4"],
         "error: --groove-ratio = '0.4': must be > 0.5 (groove radius larger than ball radius) (bearing QJ202)"),
        (["--contact-angle", "95"], "error: --contact-angle = '95': must lie in [0, 90) deg (bearing QJ202)"),
        (["--contact-angle", "95 deg"], "error: --contact-angle = '95 deg': must lie in [0, 90) deg (bearing QJ202)"),
    ],
)
def test_user_mistakes_print_one_line_and_exit_2(args, message):
    result = run("contact", *args)
    assert result.exit_code == 2
    assert result.stdout == ""
    assert result.stderr.strip().startswith(message), result.stderr
    assert len(result.stderr.strip().splitlines()) == 1
    assert "Traceback" not in result.output


@pytest.mark.slow
def test_bad_toml_value_from_a_real_process(tmp_path):
    bad = tmp_path / "bad.toml"
    bad.write_text(EXAMPLE.read_text().replace("inner_groove_ratio = 0.52", "inner_groove_ratio = 0.49"))
    proc = subprocess.run([sys.executable, "-m", "auxbearing.cli.main", "contact", "--bearing", str(bad)],
                          capture_output=True, text=True)
    assert proc.returncode == 2
    assert proc.stderr.strip() == ("error: bearing.inner_groove_ratio = 0.49: must be > 0.5 "
                                   "(groove radius larger than ball radius)")
    assert proc.stdout == ""


@pytest.mark.slow
def test_contact_sweep_writes_data_and_figures(tmp_path):
    out = tmp_path / "sweep"
    result = run("contact-sweep", "--out", str(out), "--angle-range", "10", "75", "5",
                 "--ratio-range", "0.505", "0.6", "0.005", "--json")
    assert result.exit_code == 0, result.output
    for name in ("contact_map.nc", "fig2_contact_angle.png", "fig3_groove_ratio.png", "contact_summary.json"):
        assert (out / name).stat().st_size > 0
    ds = xr.open_dataset(out / "contact_map.nc")
    assert ds["max_stress"].attrs["units"] == "Pa"
    assert "auxbearing_version" in ds.attrs and "inputs" in ds.attrs
    assert set(ds.dims) == {"race", "contact_angle", "groove_ratio"}
    summary = json.loads((out / "contact_summary.json").read_text())
    assert summary["provenance"]["auxbearing_version"]


def test_bad_sweep_range_leaves_no_output(tmp_path):
    out = tmp_path / "sweep"
    result = run("contact-sweep", "--out", str(out), "--angle-range", "10", "95", "5")
    assert result.exit_code == 2
    assert not out.exists()
    assert not list(tmp_path.iterdir())


def test_stress_above_iso76_warns_on_stderr_only():
    # 5 kN on a QJ202 ball: both ellipses reach past the groove shoulder, then the stress passes ISO 76.
    result = CliRunner().invoke(cli, ["contact", "--bearing", "QJ202", "--ball-load", "5 kN", "--json"])
    assert result.exit_code == 0
    assert json.loads(result.stdout)["inner"]["max_stress_MPa"] > 4200
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 3, result.stderr
    for line, race in zip(lines[:2], ("inner", "outer"), strict=True):
        assert line.startswith(f"warning: --ball-load 5 kN: the {race} contact ellipse runs over the groove shoulder")
    assert lines[2].startswith("warning: max contact stress") and "ISO 76" in lines[2]
    assert CliRunner().invoke(cli, ["contact", "--ball-load", "1 kN", "--json"]).stderr == ""
