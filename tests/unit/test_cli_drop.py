"""Command line: ``auxbearing drop`` and ``auxbearing drop-compare``."""

import json

import pytest
import xarray as xr
from click.testing import CliRunner

from auxbearing.cli.main import cli

ISSUE_KEYS = ["peak_contact_force_N", "peak_ball_stress_MPa", "first_impact_ms", "impacts", "whirl",
              "whirl_frequency_Hz", "final_rotor_speed_rad_s", "final_race_speed_rad_s", "contact_fraction",
              "steps", "wall_time_s"]


def _run(*args):
    return CliRunner().invoke(cli, list(args), catch_exceptions=False)


def test_drop_json_has_the_issue_keys():
    r = _run("drop", "--bearing", "QJ202", "--json", "--quiet", "--clearance", "0.2mm", "--friction", "0.2",
             "--speed", "6000rpm", "--duration", "0.02s")
    assert r.exit_code == 0, r.output
    data = json.loads(r.output)
    assert set(ISSUE_KEYS) <= set(data)
    assert data["impacts"] >= 1 and data["peak_contact_force_N"] > 100
    # 20 ms at 6000 rpm is shorter than one whirl window: its whirl is not known, and says so
    assert data["whirl"] in ("forward", "backward", "none", "not classified")


def test_plain_numbers_take_the_documented_units():
    a = json.loads(_run("drop", "--json", "--quiet", "--clearance", "0.15", "--duration", "0.01").output)
    b = json.loads(_run("drop", "--json", "--quiet", "--clearance", "150um", "--duration", "10ms").output)
    assert a["clearance_mm"] == pytest.approx(0.15) and a == {**b, "wall_time_s": a["wall_time_s"],
                                                             "compile_or_cache_load_s": a["compile_or_cache_load_s"]}


@pytest.mark.slow
def test_drop_out_writes_netcdf_figures_and_summary(tmp_path):
    out = tmp_path / "run"
    r = _run("drop", "--bearing", "7202", "--duration", "0.012", "--output-step", "50us", "--out", str(out),
             "--quiet")
    assert r.exit_code == 0, r.output
    assert "Peak collision force" in r.output
    names = {p.name for p in out.iterdir()}
    assert {"drop.nc", "drop_orbit_force.png", "drop_speeds_stress.png", "drop_summary.json"} <= names
    ds = xr.load_dataset(out / "drop.nc")
    assert ds.sizes["time"] == 241 and "auxbearing_version" in ds.attrs


@pytest.mark.parametrize(("args", "message"), [
    (["--friction", "1.5"], ("error: --friction = '1.5': must lie in [0, 1]",)),
    (["--clearance", "-1mm"], ("error: --clearance = '-1mm': must be > 0",)),
    (["--clearance", "2kg"], ("error: --clearance = '2kg': unit kilogram is not a length",)),
    (["--rotor-radius", "7.4mm"], ("error: --rotor-radius = '7.4mm': ", "must equal the race bore radius 7.5 mm")),
    (["--rotor-mass", "0"], ("error: --rotor-mass = '0': must be > 0",)),
    (["--bearing", "QJ999"], ("error: --bearing = 'QJ999': unknown; catalogue names are QJ202",)),
])
def test_user_errors_are_one_line_and_exit_2(tmp_path, args, message):
    out = tmp_path / "run"
    r = CliRunner().invoke(cli, ["drop", "--quiet", "--out", str(out), *args])
    assert r.exit_code == 2
    assert r.stdout == "" and not out.exists()
    lines = [ln for ln in r.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith(message[0]), r.stderr
    assert all(part in lines[0] for part in message[1:]), r.stderr


def test_config_file_and_options_override_it(tmp_path):
    cfg = tmp_path / "drop.toml"
    cfg.write_text('[rotor]\nmass = "1.48 kg"\n[drop]\nclearance = "0.1 mm"\nduration = "8 ms"\n')
    a = json.loads(_run("drop", "--config", str(cfg), "--json", "--quiet").output)
    assert a["clearance_mm"] == pytest.approx(0.1)
    b = json.loads(_run("drop", "--config", str(cfg), "--clearance", "0.15mm", "--json", "--quiet").output)
    assert b["clearance_mm"] == pytest.approx(0.15)
    cfg.write_text('[drop]\nsliding_friction = 2\n')
    r = CliRunner().invoke(cli, ["drop", "--config", str(cfg), "--quiet"])
    assert r.exit_code == 2 and r.stdout == ""
    assert r.stderr == "error: drop.sliding_friction = 2: must lie in [0, 1]\n"


@pytest.mark.slow
def test_drop_compare_writes_the_comparison(tmp_path):
    out = tmp_path / "cmp"
    r = _run("drop-compare", "--out", str(out), "--json", "--quiet", "--duration", "0.012",
             "--output-step", "100us", "--clearances", "0.15,0.2", "--frictions", "0.2", "--phases", "0",
             "--no-checks")
    assert r.exit_code == 0, r.output
    data = json.loads(r.output)
    assert set(data["results"]) == {"QJ202", "7202"}
    assert data["paper"]["QJ202"]["peak_contact_force_N"] == 618.0
    assert data["sweep"]["clearance_mm"] == [0.15, 0.2]
    assert data["sweep"]["unbalance_phase_deg"] == [0.0]
    names = {p.name for p in out.iterdir()}
    assert {"drop_QJ202.nc", "drop_7202.nc", "drop_sweep.nc", "drop_compare.json",
            "fig10_QJ202_orbit_force.png", "fig11_7202_orbit_force.png"} <= names
    saved = json.loads((out / "drop_compare.json").read_text())
    assert saved["unstated_parameters"] and "provenance" in saved


def test_drop_compare_rejects_bad_sweep_values(tmp_path):
    out = tmp_path / "cmp"
    r = CliRunner().invoke(cli, ["drop-compare", "--quiet", "--out", str(out), "--frictions", "0.1,2"])
    assert r.exit_code == 2 and r.stdout == "" and not out.exists()
    assert r.stderr == "error: --frictions = '0.1,2': must lie in [0, 1]\n"


def test_help_lists_every_parameter_with_default_and_unit():
    r = _run("drop", "--help")
    for option in ("--clearance", "--friction", "--speed", "--duration", "--rotor-mass", "--race-inertia",
                   "--ball-constant", "--line-stiffness", "--slip-velocity", "--rtol", "--quiet", "--config"):
        assert option in r.output
    assert "default 0.2 mm" in r.output and "default 6000 rpm" in r.output
