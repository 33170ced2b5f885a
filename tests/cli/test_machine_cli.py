"""The machine commands: drop --machine, machines, coastdown (issues 12 and 13)."""

import json
from pathlib import Path

import numpy as np
import pytest
from click.testing import CliRunner

from auxbearing.cli.main import cli


def _run(*args):
    return CliRunner().invoke(cli, list(args))


def test_machines_lists_the_examples_of_the_issue():
    result = _run("machines", "--json")
    assert result.exit_code == 0, result.output
    names = {m["name"] for m in json.loads(result.output)["machines"]}
    assert {"paper_rig", "paper_rig_two_planes", "blower", "vertical"} <= names
    blower = next(m for m in json.loads(result.output)["machines"] if m["name"] == "blower")
    assert any(p["axial"] for p in blower["planes"]) and blower["planes"][0]["bearing"] == "QJ208"


@pytest.mark.slow
def test_drop_machine_json_has_the_issue_keys(tmp_path):
    out = tmp_path / "run"
    result = _run("drop", "--machine", "paper_rig_two_planes", "--duration", "0.02", "--json", "--out", str(out))
    assert result.exit_code == 0, result.output
    summary = json.loads(result.output)
    for key in ("verdict", "reason", "wall_time_s", "steps", "energy_balance_error", "planes"):
        assert key in summary
    for key in ("name", "peak_contact_force_N", "peak_ball_stress_MPa", "s0", "final_contact_force_N",
                "peak_axial_force_N", "final_axial_force_N", "whirl", "backward_whirl_onset_ms"):
        assert key in summary["planes"][0]
    files = {p.name for p in out.iterdir()}
    assert {"drop.nc", "drop_summary.json", "drop_orbit_0.png", "drop_orbit_1.png", "drop_contact_force.png",
            "drop_tilt.png", "drop_whirl_timeline.png", "drop_speeds.png"} <= files


def test_heavy_fast_rotor_prints_its_failure_not_a_result():
    result = _run("drop", "--machine", "heavy_fast_rotor", "--json")
    assert result.exit_code == 0
    summary = json.loads(result.stdout)
    assert summary["verdict"] == "contact_ellipse_over_shoulder"
    assert summary["planes"][0]["peaks_cover"].startswith("the run up to its stop")
    assert "warning: verdict contact_ellipse_over_shoulder" in result.stderr


@pytest.mark.slow
def test_coastdown_of_a_drop_out_of_range_reports_no_life(tmp_path):
    out = tmp_path / "cd"
    result = _run("coastdown", "--machine", "heavy_fast_rotor", "--until-stop", "--json", "--out", str(out))
    assert result.exit_code == 0
    summary = json.loads(result.stdout)
    assert summary["verdict"] == "contact_ellipse_over_shoulder" and summary["reached_standstill"] is False
    plane = summary["planes"][0]
    for key in ("damage_per_drop", "drops_to_failure", "drops_to_dent_limit", "governing", "allowed_drops"):
        assert plane[key] is None, key
    assert plane["life_note"] == "not computed: the drop ended with verdict contact_ellipse_over_shoulder"
    files = {p.name for p in out.iterdir()}  # no stress cycles of a history cut at the range exit
    assert "coastdown_summary.json" in files and not any(name.startswith("stress_cycles") for name in files)


@pytest.mark.parametrize("polar, rule", [
    ("15 g*cm^2", "radius of gyration of 0.3873 mm against a journal radius of 19.85 mm"),  # a unit slip
])
def test_an_unlikely_rotor_inertia_is_warned_of(tmp_path, polar, rule):
    from importlib import resources

    text = resources.files("auxbearing.catalog").joinpath("machines/blower.toml").read_text()
    assert 'polar_inertia = "0.015 kg*m^2"' in text
    machine = tmp_path / "m.toml"
    machine.write_text(text.replace('polar_inertia = "0.015 kg*m^2"', f'polar_inertia = "{polar}"'))
    result = _run("drop", "--machine", str(machine), "--duration", "1 ms", "--json")
    assert result.exit_code == 0, result.output
    warning = next(line for line in result.stderr.splitlines() if "rotor.polar_inertia" in line)
    assert warning.startswith(f"warning: {machine}: rotor.polar_inertia: ") and rule in warning


def test_paper_options_with_a_machine_are_refused_in_one_line():
    result = _run("drop", "--machine", "blower", "--friction", "0.3")
    assert result.exit_code == 2
    assert result.stderr.count("\n") == 1 and "--friction" in result.stderr


def test_unknown_machine_names_the_examples():
    result = _run("drop", "--machine", "blowr")
    assert result.exit_code == 2 and "paper_rig" in result.stderr and "\n" == result.stderr[-1]


@pytest.mark.slow
def test_coastdown_json_and_files(tmp_path):
    out = tmp_path / "cd"
    result = _run("coastdown", "--machine", "paper_rig", "--duration", "0.3", "--json", "--out", str(out), "--quiet")
    assert result.exit_code == 0, result.output
    summary = json.loads(result.stdout)
    for key in ("verdict", "reason", "coastdown_time_s", "energy_balance_error", "wall_time_s", "planes"):
        assert key in summary
    assert {"coastdown.nc", "drop.nc", "coastdown_summary.json", "coastdown_speeds.png",
            "coastdown_clearances.png", "coastdown_temperatures_0.png", "stress_cycles_0.png"} <= {
        p.name for p in out.iterdir()}


def test_coastdown_bad_duration_is_one_line_and_writes_nothing(tmp_path):
    out = tmp_path / "cd"
    result = _run("coastdown", "--machine", "paper_rig", "--duration", "-3 s", "--out", str(out))
    assert result.exit_code == 2 and result.stderr.startswith("error: --duration")
    assert not out.exists()


def test_modes_of_the_elastic_compressor_write_the_campbell_diagram(tmp_path):
    out = tmp_path / "modes"
    r = CliRunner().invoke(cli, ["modes", "--machine", "compressor", "--speeds", "0, 7500, 15000 rpm", "--out",
                                 str(out), "--json"], catch_exceptions=False)
    assert r.exit_code == 0, r.output
    data = json.loads(r.output)
    assert data["elastic_modes"] == 8  # four bending pairs below 3 kHz: 390, 761, 1247, 2079 Hz free-free
    free, contact = data["states"]
    assert (free["state"], contact["state"]) == ("free", "contact")
    # levitated on its two magnetic bearings: its rigid-body modes near 32 and 41 Hz, then the first bending near
    # its free-free 390 Hz
    at_rest = free["frequencies_Hz"][0]
    assert at_rest[0] == pytest.approx(31.6, abs=0.1)
    assert min(f for f in at_rest if f > 100.0) == pytest.approx(390.8, rel=2e-3)
    assert all(k > 0 for k in contact["contact_stiffness_N_per_m"])
    assert {p.name for p in out.iterdir()} >= {"modes.json", "campbell.png", "mode_shapes.png"}


def test_the_shipped_compressor_matrices_are_what_the_example_script_builds():
    import importlib.util
    from importlib import resources

    spec = importlib.util.spec_from_file_location("compressor_rotor", Path(__file__).parents[2] / "examples" /
                                                  "compressor_rotor.py")
    script = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(script)
    built = script.compressor_structure()
    with resources.as_file(resources.files("auxbearing.catalog").joinpath("machines", "compressor.npz")) as path:
        shipped = np.load(path)
        for name, value in (("M", built.mass), ("K", built.stiffness), ("G", built.gyroscopic), ("nodes", built.nodes)):
            assert np.array_equal(shipped[name], value), name


def test_the_blowers_power_loss_drops_the_levitated_rotor_after_the_scenarios_time():
    r = CliRunner().invoke(cli, ["drop", "--machine", "blower", "--scenario", "power loss", "--duration", "60 ms",
                                 "--json", "--quiet"], catch_exceptions=False)
    assert r.exit_code == 0, r.output
    data = json.loads(r.output)
    assert data["verdict"] == "ok"
    assert data["scenario"].items() >= {"name": "power loss", "kind": "power_loss", "time_ms": 30.0,
                                        "decay_time_ms": 5.0, "restore_after_ms": None}.items()
    assert data["scenario"]["outcome"] == "on the touchdown bearings"  # the power does not come back
    assert [a["levitated_offset_um"] for a in data["amb"]] == pytest.approx([0.0] * 3, abs=1e-3)  # integral action
    # the weight shared by the two bearings at rest: m g / 2 / k_i
    assert data["amb"][0]["levitated_current_A"] == pytest.approx(10.0 * 9.80665 / 2 / 100.0, rel=1e-9)
    assert all(p["first_impact_ms"] > 30.0 for p in data["planes"])


def test_verify_runs_each_scenario_as_a_case():
    from auxbearing.machine.files import machine_table
    from auxbearing.verify.cases import plan_cases

    data, name, base = machine_table("blower")
    cases = plan_cases(data, name, base, quick=True)
    machine = cases.machines["scenario: power loss"]
    assert machine.active_scenario().time == pytest.approx(0.03)
    assert machine.simulation.duration == pytest.approx(0.03 + 0.05)  # levitated, then the quick drop's length


def test_a_machine_drop_prints_its_magnetic_bearings_and_where_the_rotor_went_at_them():
    result = _run("drop", "--machine", "blower", "--duration", "20 ms")
    assert result.exit_code == 0, result.output
    assert "Magnetic bearings" in result.output
    rows = [line for line in result.output.splitlines() if "drive-end AMB" in line]
    assert len(rows) == 2  # the drive end's and the non-drive end's radial bearings
    excursion = float(rows[0].split("│")[-2])
    assert 50.0 < excursion < 200.0  # after the fall onto the 0.15 mm clearance [um]
    thrust = next(line for line in result.output.splitlines() if "thrust AMB" in line)
    assert thrust.split("│")[-2].strip() == "-"  # an axial bearing has no radial excursion
