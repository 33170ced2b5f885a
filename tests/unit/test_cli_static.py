"""``auxbearing static`` and ``static-study`` from the command line."""

import json
import re
from pathlib import Path

import pytest
import xarray as xr
from click.testing import CliRunner

from auxbearing.cli.main import cli

EXAMPLE = Path(__file__).parents[2] / "examples" / "my_bearing.toml"
TOP_KEYS = ["axial_displacement_um", "radial_displacement_um", "tilt_mrad", "max_contact_load_N",
            "max_stress_MPa", "safety_factor_s0", "residual_N", "balls"]
PAIR_KEYS = ["load_N", "contact_angle_deg", "max_stress_inner_MPa", "max_stress_outer_MPa"]


def run(*args):
    return CliRunner().invoke(cli, list(args))


def test_static_json_has_exactly_the_issue_keys():
    result = run("static", "--bearing", "QJ202", "--radial", "1000", "--axial", "500", "--moment", "0", "--json")
    assert result.exit_code == 0, result.output
    data = json.loads(result.output)
    assert list(data) == TOP_KEYS
    assert len(data["balls"]) == 11
    for ball in data["balls"]:
        assert list(ball) == ["azimuth_deg", "pairs"]
        assert len(ball["pairs"]) == 2
        assert all(list(pair) == PAIR_KEYS for pair in ball["pairs"])
    assert data["balls"][1]["azimuth_deg"] == pytest.approx(360 / 11)
    assert data["residual_N"] <= 1e-9 * 1000
    assert data["max_stress_MPa"] == pytest.approx(max(
        max(p["max_stress_inner_MPa"], p["max_stress_outer_MPa"]) for b in data["balls"] for p in b["pairs"]))
    assert data["safety_factor_s0"] == pytest.approx((4200 / data["max_stress_MPa"]) ** 3)


def test_loads_take_units():
    a = json.loads(run("static", "--radial", "1 kN", "--axial", "0.5 kN", "--moment", "2 N*m", "--json").output)
    b = json.loads(run("static", "--radial", "1000", "--axial", "500", "--moment", "2", "--json").output)
    assert a["max_stress_MPa"] == pytest.approx(b["max_stress_MPa"], rel=1e-12)
    c = json.loads(run("static", "--radial", "1000", "--axial", "500", "--moment", "2000 N*mm", "--json").output)
    assert c["tilt_mrad"] == pytest.approx(b["tilt_mrad"], rel=1e-9)


def test_toml_bearing_and_readable_table():
    result = run("static", "--bearing", str(EXAMPLE), "--radial", "1000")
    assert result.exit_code == 0, result.output
    assert "Max contact stress" in result.output and "MPa" in result.output and "s0" in result.output


def test_angular_contact_located_reports_reaction():
    result = run("static", "--bearing", "7202", "--radial", "1000", "--axial-condition", "located", "--tilt", "fixed")
    assert result.exit_code == 0, result.output
    assert "Axial reaction" in result.output
    data = json.loads(run("static", "--bearing", "7202", "--radial", "1000", "--axial-condition", "located",
                          "--json").output)
    assert data["axial_displacement_um"] == 0.0
    assert len(data["balls"][0]["pairs"]) == 1


@pytest.mark.parametrize(
    ("args", "message"),
    [
        # --axial not typed: its default, 0 N, is named with its unit
        (["--bearing", "7202", "--radial", "1000"],
         ("error: --axial = '0 N': a single angular contact bearing with a free ring needs an axial load > 0 N",
          "--axial-condition located")),
        (["--radial", "5 kg"], ("error: --radial = '5 kg': unit kilogram is not a force",)),
        (["--moment", "3 N"], ("error: --moment = '3 N': unit newton is not a moment",)),
        (["--bearing", "nope"], ("error: --bearing = 'nope': unknown; catalogue names are QJ202",)),
        (["--ball-constant", "abc"], ("error: --ball-constant = 'abc': cannot read it as a ball constant such as",)),
    ],
)
def test_user_mistakes_print_one_line_and_exit_2(args, message):
    result = run("static", *args)
    assert result.exit_code == 2
    assert result.stdout == ""
    assert result.stderr.strip().startswith(message[0]), result.stderr
    assert all(part in result.stderr for part in message[1:]), result.stderr
    assert len(result.stderr.strip().splitlines()) == 1


def test_help_names_units():
    text = run("static", "--help").output
    assert "N*m" in text and "'1 kN'" in text and "located" in text


@pytest.mark.slow
def test_static_study_writes_data_and_figures(tmp_path):
    out = tmp_path / "static"
    result = run("static-study", "--out", str(out), "--json")
    assert result.exit_code == 0, result.output
    for name in ("fig6_radial.nc", "fig6_axial.nc", "fig7.nc", "fig8.nc", "stribeck.nc",
                 "fig6_contact_angles.png", "fig7_displacements.png", "fig8_max_stress.png", "static_summary.json"):
        assert (out / name).stat().st_size > 0, name
    with xr.open_dataset(out / "fig8.nc") as ds:
        assert ds["max_stress"].attrs["units"] == "Pa"
        assert set(ds["max_stress"].dims) == {"bearing", "radial_load"}
        assert "auxbearing_version" in ds.attrs
    with xr.open_dataset(out / "fig6_radial.nc") as ds:
        assert ds["contact_angle"].attrs["units"] == "rad"
    summary = json.loads((out / "static_summary.json").read_text())
    assert summary["angular_exceeds_four_point_everywhere"] is True
    assert summary["provenance"]["auxbearing_version"]
    assert json.loads(result.output)["out"] == str(out)


def test_out_of_range_load_is_flagged_on_stderr_and_json_stays_clean():
    # 200 N*m on a 15 mm bore bearing: sigma_max ~ 4.9 GPa > 4200 MPa (ISO 76).
    result = run("static", "--bearing", "QJ202", "--radial", "500", "--moment", "200", "--json")
    assert result.exit_code == 0
    data = json.loads(result.stdout)
    assert data["safety_factor_s0"] < 1
    assert result.stderr.startswith("warning: max contact stress")
    assert "ISO 76" in result.stderr and "tilt" not in result.stderr
    # 3000 N*m: tilt beyond the small-tilt kinematics as well.
    big = run("static", "--bearing", "QJ202", "--moment", "3000", "--json")
    assert big.exit_code == 0
    assert json.loads(big.stdout)["safety_factor_s0"] < 1
    lines = big.stderr.strip().splitlines()
    assert len(lines) == 2 and all(line.startswith("warning: ") for line in lines), big.stderr
    assert "ISO 76" in lines[0] and "small-tilt" in lines[1]
    # 1e6 N*m would push the rings millimetres into a 6 mm ball: refused, no JSON.
    huge = run("static", "--bearing", "QJ202", "--moment", "1e6", "--json")
    assert huge.exit_code == 2 and huge.stdout == ""
    assert len(huge.stderr.strip().splitlines()) == 1
    assert re.match(r"error: --moment = '1e6': the rings would move about [0-9.]+ mm into the balls "
                    r"\(ball diameter 6 mm\), beyond 10% of a ball", huge.stderr), huge.stderr
    assert "no result follows" in huge.stderr
    calm = run("static", "--bearing", "QJ202", "--radial", "1000", "--moment", "5", "--json")
    assert calm.stderr == ""
