"""The static and contact surfaces after their review: the API refuses what the command line refuses, reads
units as it does, and neither shows a sign lost, an infinite s0, a negative zero or a header without its unit.
"""

from __future__ import annotations

import json
import math

import numpy as np
import pytest
import xarray as xr
from click.testing import CliRunner

from auxbearing import get_bearing
from auxbearing.analysis.contact import OutsideHertz, ball_contact, grid_refusal
from auxbearing.analysis.static_cases import format_cell
from auxbearing.analysis.statics import load_distribution, solve_loads
from auxbearing.cli.main import cli
from auxbearing.common.errors import InputError
from auxbearing.paper.study_config import load_study_config

QJ202 = get_bearing("QJ202")
NEGZERO = "axial [N], radial [kN], moment [N*m]\n0, -0.5, 0\n0, 0, 0\n"


def run(*args: str):
    # wide enough that rich never wraps a header, so a unit is either printed or lost
    return CliRunner(env={"COLUMNS": "200"}).invoke(cli, list(args))


def refusal(result) -> str:
    assert result.exit_code == 2, result.output
    assert result.stdout == "" and "Traceback" not in result.output
    lines = result.stderr.strip().splitlines()
    assert len(lines) == 1, result.stderr
    return lines[0]


def api_error(call, *args, **kwargs) -> str:
    with pytest.raises(InputError) as info:
        call(*args, **kwargs)
    text = str(info.value)
    assert "\n" not in text
    return text


def reason(text: str, head: str) -> str:
    assert text.startswith(head), text
    return text[len(head):]


# 1. the API refuses what the command line refuses, for the same reason


def test_ball_load_beyond_hertz_is_refused_by_api_and_cli_alike():
    api = api_error(ball_contact, QJ202, 1e5)
    cli_line = refusal(run("contact", "--ball-load", "1e5 N"))
    why = reason(api, "ball_load = 100000.0: ")
    assert why.startswith("the inner contact ellipse (semi-major axis 4.721 mm) is as large as the ball")
    assert reason(cli_line, "error: --ball-load = '1e5 N': ") == why


def test_conformal_groove_ratio_is_refused_by_api_and_cli_alike():
    with pytest.raises(OutsideHertz) as info:
        ball_contact(QJ202, 1000.0, groove_ratio=0.5001)
    why = reason(str(info.value), "groove_ratio = 0.5001: ")
    assert "no result follows" in why and info.value.reason == why
    assert reason(refusal(run("contact", "--groove-ratio", "0.5001")), "error: --groove-ratio = '0.5001': ") == why


def test_sinking_radial_load_is_refused_by_api_and_cli_alike():
    api = api_error(load_distribution, QJ202, radial=1e6)
    why = reason(api, "radial = '1e+06 N': ")
    assert why.startswith("the rings would move about 1.35 mm into the balls")
    assert reason(refusal(run("static", "--radial", "1e6")), "error: --radial = '1e6': ") == why
    # the 5-DOF API names its own column, and the case when there are several
    five = api_error(solve_loads, QJ202, [[0, 1000, 0, 0, 0], [0, 0, -1e6, 0, 0]])
    assert reason(five, "force_y (load case 1) = '-1e+06 N': ") == why
    # a ball constant that alone sinks the rings is what is named
    assert api_error(load_distribution, QJ202, radial=1000, ball_constant="1 N/m**1.5").startswith(
        "ball_constant = '1 N/m**1.5': the rings would move")


def test_study_config_refuses_a_contact_stage_outside_hertz(tmp_path):
    path = tmp_path / "s.toml"

    def read(text: str):
        path.write_text("[study]\n" + text)
        return load_study_config(path)

    with pytest.raises(InputError) as info:
        read('ball_load = "60 kN"\ncontact_angles = ["10 deg", "89.5 deg", "0.5 deg"]\n')
    assert str(info.value).startswith("study.ball_load = '60 kN': the inner contact ellipse (semi-major axis")
    with pytest.raises(InputError) as info:
        read('contact_angles = ["10 deg", "89.5 deg", "0.5 deg"]\n')
    assert str(info.value).startswith("study.contact_angles = ['10 deg', '89.5 deg', '0.5 deg']: at a contact "
                                      "angle of 89.5 deg and a groove ratio of 0.505, the inner contact ellipse")
    with pytest.raises(InputError) as info:
        read("groove_ratios = [0.5001, 0.6, 0.01]\n")
    assert str(info.value).startswith("study.groove_ratios = [0.5001, 0.6, 0.01]: at a contact angle of 75 deg")
    assert read('ball_load = "1.5 kN"\n').ball_load == 1500.0
    assert read('contact_angles = ["10 deg", "80 deg", "1 deg"]\n').contact_angles_deg == (10.0, 80.0, 1.0)


def test_grid_refusal_is_the_largest_ellipse_of_the_map():
    from auxbearing.analysis.contact import contact_map

    angles, ratios = np.array([10.0, 60.0, 88.0]), np.array([0.505, 0.52, 0.6])
    ds = contact_map(QJ202, 1000.0, angles, ratios)
    too_large = bool((ds["semi_major"] >= 0.5 * QJ202.ball_diameter).any())
    assert too_large and grid_refusal(QJ202, 1000.0, angles, ratios) is not None
    assert float(ds["semi_major"].max()) == pytest.approx(
        float(ds["semi_major"].sel(contact_angle=88.0, groove_ratio=0.505).max()))
    assert grid_refusal(QJ202, 1000.0, angles[:2], ratios) is None


# 2. units as the command line reads them, errors naming the argument


def test_api_reads_units_like_the_cli():
    plain = ball_contact(QJ202, 1000.0)
    assert ball_contact(QJ202, "1 kN")["inner"]["max_stress_MPa"] == pytest.approx(plain["inner"]["max_stress_MPa"])
    by_rad = ball_contact(QJ202, 1000.0, contact_angle=0.6)
    assert ball_contact(QJ202, 1000.0, contact_angle="0.6 rad") == by_rad
    assert ball_contact(QJ202, 1000.0, contact_angle="20 deg")["contact_angle_deg"] == pytest.approx(20.0)
    assert ball_contact(QJ202, 1000.0, groove_ratio="0.51")["inner"]["groove_ratio"] == 0.51
    listed = load_distribution(QJ202, radial=["1 kN", "2 kN"])
    plain = load_distribution(QJ202, radial=[1000.0, 2000.0])
    np.testing.assert_allclose(listed["max_stress"], plain["max_stress"], rtol=1e-12)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"ball_load": "-5 kN"}, "ball_load = '-5 kN': must be >= 0 N"),
        ({"ball_load": "5 kg"}, "ball_load = '5 kg': unit kilogram is not a force"),
        ({"method": "foo"}, "method = 'foo': must be one of exact, hamrock_brewe"),
        ({"contact_angle": 35},
         "contact_angle = 35: must lie in [0, 90) deg; a plain number is in rad (35 rad = 2005 deg), write '35 deg'"),
        ({"contact_angle": "95 deg"}, "contact_angle = '95 deg': must lie in [0, 90) deg"),
        ({"groove_ratio": 0.4}, "groove_ratio = 0.4: must be > 0.5"),
    ],
)
def test_ball_contact_names_its_arguments(kwargs, message):
    kwargs = {"ball_load": 1000.0, **kwargs}
    assert api_error(ball_contact, QJ202, **kwargs).startswith(message)


def test_load_sequences_name_the_element():
    assert api_error(load_distribution, QJ202, radial=["1 kN", "1 kg"]).startswith(
        "radial[1] = '1 kg': unit kilogram is not a force")


# 3. signed displacement and tilt, the same in every output


def test_static_cases_keep_the_sign_in_table_csv_json_and_netcdf(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "negzero.csv").write_text(NEGZERO)
    result = run("static-cases", "--loads", "negzero.csv", "--out", "o1")
    assert result.exit_code == 0, result.output
    static = json.loads(run("static", "--radial", "-500", "--json").stdout)["radial_displacement_um"]
    assert static == pytest.approx(-7.3633, abs=1e-4)
    assert "-7.3633" in result.stdout
    csv_rows = (tmp_path / "o1" / "static_cases.csv").read_text().splitlines()
    assert csv_rows[2].split(",")[2] == "-7.3633"
    saved = json.loads((tmp_path / "o1" / "static_cases.json").read_text())
    assert saved["results"][0]["radial_displacement_um"] == pytest.approx(static, rel=1e-12)
    with xr.open_dataset(tmp_path / "o1" / "static_cases.nc") as ds:
        assert float(ds["radial_displacement"][0]) * 1e6 == pytest.approx(static, rel=1e-12)


def test_tilt_keeps_its_sign_as_static_shows_it(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "l.csv").write_text("axial [N], radial [N], moment [N*m]\n500, 2000, 0\n0, 500, -5\n")
    rows = json.loads(run("static-cases", "--loads", "l.csv", "--json").stdout)["results"]
    for row, args in zip(rows, (["--axial", "500", "--radial", "2000"], ["--radial", "500", "--moment", "-5"]),
                         strict=True):
        static = json.loads(run("static", *args, "--json").stdout)
        assert row["tilt_mrad"] == pytest.approx(static["tilt_mrad"], rel=1e-9)
        assert row["radial_displacement_um"] == pytest.approx(static["radial_displacement_um"], rel=1e-9)
    assert rows[0]["tilt_mrad"] < 0.0 and rows[1]["tilt_mrad"] < 0.0


def test_five_dof_columns_read_as_the_planar_ones(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "p.csv").write_text("axial [N], radial [N], moment [N*m]\n0, -500, 0\n0, 500, 5\n")
    (tmp_path / "f.csv").write_text("axial [N], force_x [N], moment_y [N*m]\n0, -500, 0\n0, 500, -5\n")
    planar = json.loads(run("static-cases", "--loads", "p.csv", "--json").stdout)["results"]
    five = json.loads(run("static-cases", "--loads", "f.csv", "--json").stdout)["results"]
    for a, b in zip(planar, five, strict=True):
        assert b["radial_displacement_um"] == pytest.approx(a["radial_displacement_um"], rel=1e-9)
        assert b["tilt_mrad"] == pytest.approx(a["tilt_mrad"], rel=1e-9, abs=1e-12)


# 4. no load, no s0


def test_unloaded_static_shows_no_s0():
    text = run("static", "--radial", "0").stdout
    assert "Static safety s0     - (no contact is loaded)" in text and "inf" not in text
    assert json.loads(run("static", "--radial", "0", "--json").stdout)["safety_factor_s0"] is None


def test_unloaded_case_has_no_s0_in_any_output(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "negzero.csv").write_text(NEGZERO)
    result = run("static-cases", "--loads", "negzero.csv", "--out", "o1")
    assert result.exit_code == 0, result.output
    assert "inf" not in result.stdout
    row = next(line for line in result.stdout.splitlines() if line.startswith("│    3 "))
    assert row.split("│")[7].strip() == "-"
    csv_text = (tmp_path / "o1" / "static_cases.csv").read_text()
    assert "inf" not in csv_text and csv_text.splitlines()[3].split(",")[6] == ""
    assert json.loads((tmp_path / "o1" / "static_cases.json").read_text())["results"][1]["safety_factor_s0"] is None
    with xr.open_dataset(tmp_path / "o1" / "static_cases.nc") as ds:
        assert math.isnan(float(ds["safety_factor_s0"][1])) and "no s0" in ds["safety_factor_s0"].attrs["comment"]
    only_zero = tmp_path / "zero.csv"
    only_zero.write_text("radial [N]\n0\n")
    assert run("static-cases", "--loads", "zero.csv").stdout.rstrip().endswith("max stress 0.0 MPa, s0 -")


# 5. the option or argument as typed, and the reason


def test_negative_axial_on_angular_contact_names_the_option():
    line = refusal(run("static", "--bearing", "7202", "--axial", "-500"))
    assert line.startswith("error: --axial = '-500': a single angular contact bearing with a free ring carries "
                           "axial load in one direction only")
    assert "-0.0" not in line and "loads =" not in line
    assert api_error(load_distribution, "7202", axial=-500).startswith(
        "axial = '-500 N': a single angular contact bearing with a free ring carries axial load in one direction")
    assert api_error(load_distribution, "7202", axial="-0.5 kN").startswith("axial = '-0.5 kN': ")
    mixed = refusal(run("static", "--bearing", "7202", "--axial", "100", "--moment", "5"))
    assert mixed.startswith("error: --axial = '100': no equilibrium on the contact side")
    assert api_error(load_distribution, "7202", axial=100, moment=5).startswith(
        "axial = '100 N': no equilibrium on the contact side")


# 6. units in every header, singular counts, no negative zero


def test_headers_carry_units_and_counts_read_right(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "one.csv").write_text("radial [N]\n1000\n")
    text = run("static-cases", "--loads", "one.csv").stdout
    assert "θ [mrad]" in text and "1 load case from" in text and "load cases" not in text
    static = run("static", "--radial", "1000").stdout
    assert "φ [deg]" in static and "α 1 [deg]" in static


def test_no_negative_zero_is_printed(tmp_path, monkeypatch):
    text = run("static", "--radial", "0").stdout
    assert "Tilt                 0.0000 mrad" in text and "-0.0" not in text
    assert format_cell({"x": -1e-12}, "x", "{:.4f}") == "0.0000"
    assert format_cell({"x": -1.5e-5}, "x", "{:.1e}") == "-1.5e-05"
    assert format_cell({"x": None}, "x", "{:.3g}", missing="") == ""
    monkeypatch.chdir(tmp_path)
    (tmp_path / "negzero.csv").write_text(NEGZERO)
    result = run("static-cases", "--loads", "negzero.csv", "--out", "o1")
    assert "-0.0" not in result.stdout and "-0.0" not in (tmp_path / "o1" / "static_cases.csv").read_text()
    with xr.open_dataset(tmp_path / "o1" / "static_cases.nc") as ds:
        assert not np.signbit(ds["tilt"].values).any()


def test_an_unloaded_tandem_pair_has_no_s0_as_a_single_bearing_has_none():
    # the matched sets' statics stored s0 = inf where no contact carries load
    import math

    from auxbearing.analysis.statics import load_distribution

    s0 = load_distribution("7208 DT", axial=[0.0, 500.0]).safety_factor_s0.values
    assert math.isnan(s0[0]) and math.isfinite(s0[1])
