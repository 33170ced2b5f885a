"""``auxbearing static-cases``: a CSV of load cases through the batched solver."""

import json

import numpy as np
import pytest
import xarray as xr
from click.testing import CliRunner

from auxbearing.analysis.static_cases import case_rows, load_cases, read_load_cases, worst_case
from auxbearing.analysis.statics import load_distribution, solve_loads
from auxbearing.cli.main import cli
from auxbearing.common.errors import InputError

DUTY = """# duty cycle
axial [N], radial [kN], moment [N*m]
0, 0.5, 0
200, 1.0, 2

500, 2.0, 0
0, 0.5, 200
"""


def write(tmp_path, text, name="loads.csv"):
    path = tmp_path / name
    path.write_text(text)
    return path


def test_planar_cases_equal_load_distribution_with_units_and_lines(tmp_path):
    ds = load_cases("QJ202", write(tmp_path, DUTY))
    direct = load_distribution("QJ202", axial=[0, 200, 500, 0], radial=[500, 1000, 2000, 500], moment=[0, 2, 0, 200])
    np.testing.assert_allclose(ds["max_stress"], direct["max_stress"], rtol=1e-12)
    np.testing.assert_allclose(ds["tilt"], direct["tilt"], rtol=1e-12, atol=1e-15)
    assert list(ds["line"].values) == [3, 4, 6, 7]
    rows = case_rows(ds)
    assert worst_case(rows)["line"] == 7
    assert [bool(r["warnings"]) for r in rows] == [False, False, False, True]  # 200 N*m: above 4200 MPa


def test_five_dof_columns_and_missing_ones_are_zero(tmp_path):
    path = write(tmp_path, "Fa [N], Fy [N], Mx [N*m]\n300, 800, 1.5\n300, 0, 0\n")
    ds = load_cases("QJ202", path)
    direct = solve_loads("QJ202", [[300, 0, 800, 1.5, 0], [300, 0, 0, 0, 0]])
    np.testing.assert_allclose(ds["max_contact_load"], direct["max_contact_load"], rtol=1e-12)
    data, lines = read_load_cases(path)
    assert set(data) == {"axial", "force_y", "moment_x"} and lines == [2, 3]


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("axial [N], radail [N]\n1, 2\n", "column 'radail [N]' (line 1): unknown; allowed: axial, radial"),
        ("axial [N], radial [N], fx [N]\n1, 2, 3\n", "(planar) and force_x (5-DOF) mixed"),
        ("axial [N], radial [N]\n", "no load cases below the header (line 1)"),
        ("axial [N], radial [kg]\n1, 2\n", "loads.csv: column 'radial [kg]' unit"),
        ("axial [N], radial\n1, 2\n", "column 'radial' (line 1) has no unit: write e.g. 'radial [N]'"),
        ("axial [N], radial [N]\n1, x\n", "column 'radial [N]', line 2: 'x' is not a number"),
        ("axial [N], radial [N]\n1\n", "line 2: 1 fields, the header (line 1) has 2"),
        ("# only a comment\n", "has no header line"),
    ],
)
def test_bad_tables_are_one_line_errors(tmp_path, text, message):
    with pytest.raises(InputError) as info:
        load_cases("QJ202", write(tmp_path, text))
    assert message in str(info.value) and "\n" not in str(info.value)


def test_solver_errors_name_the_file_line(tmp_path):
    with pytest.raises(InputError, match=r"axial \(loads.csv: line 3\) = '0 N': a single angular contact"):
        load_cases("7202", write(tmp_path, "axial [N], radial [N]\n100, 100\n0, 100\n"))


def test_cli_writes_the_three_files_and_warns_with_the_line(tmp_path):
    path = write(tmp_path, DUTY)
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["static-cases", "--loads", str(path), "--out", str(out), "--json"])
    assert result.exit_code == 0, result.output
    data = json.loads(result.stdout)
    assert data["cases"] == 4 and data["cases_with_warnings"] == 1 and data["worst"]["line"] == 7
    assert result.stderr.startswith("warning: case on line 7: max contact stress")
    csv_lines = (out / "static_cases.csv").read_text().splitlines()
    assert csv_lines[0].startswith("# auxbearing")
    assert csv_lines[1].startswith("line,axial_displacement [um],radial_displacement [um],tilt [mrad]")
    assert len(csv_lines) == 2 + 4
    with xr.open_dataset(out / "static_cases.nc") as ds:
        assert ds["max_stress"].attrs["units"] == "Pa" and list(ds["line"].values) == [3, 4, 6, 7]
    saved = json.loads((out / "static_cases.json").read_text())
    assert saved["provenance"]["auxbearing_version"]
    table = CliRunner().invoke(cli, ["static-cases", "--loads", str(path)])
    assert "Worst case: line 7" in table.stdout


def test_cli_bad_file_is_exit_2_without_folder(tmp_path):
    out = tmp_path / "out"
    bad = write(tmp_path, "axial [N], radail [N]\n1, 2\n")
    result = CliRunner().invoke(cli, ["static-cases", "--loads", str(bad), "--out", str(out)])
    assert result.exit_code == 2 and result.output.startswith("error: loads.csv: column 'radail [N]'")
    assert not out.exists()


def test_shipped_example_reads():
    from pathlib import Path

    example = Path(__file__).parents[2] / "examples" / "duty_cycle.csv"
    rows = case_rows(load_cases("QJ202", example))
    assert len(rows) == 5 and worst_case(rows)["safety_factor_s0"] < 1 < rows[0]["safety_factor_s0"]
