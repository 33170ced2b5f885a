"""Magnetic-bearing inputs that were accepted and gave absurd or wrong results, each now one line or an honest summary.

Most are refused before any simulation (one line, exit 2, nothing written); the saturation and first-contact
bookkeeping runs a short drop of the blower made unstable (no derivative gain) and pushed off its centre, so it
saturates its currents on both axes and touches down before its scenario strikes.
"""

import json

import numpy as np
import pytest
from click.testing import CliRunner

from auxbearing.analysis.drop import _levitation
from auxbearing.cli.main import cli
from auxbearing.machine.levitation import NEUTRAL

CIRCUIT = ('current_stiffness = "100 N/A"\nposition_stiffness = "2e5 N/m"',
           'turns = 100\npole_area = "400 mm^2"\nair_gap = "0.5 mm"\nbias_current = "2 A"\npole_angle = "{}"')


def _blower_text() -> str:
    from importlib import resources

    return resources.files("auxbearing.catalog").joinpath("machines", "blower.toml").read_text()


def _drop(tmp_path, text: str, *extra: str):
    """``drop --machine`` on the blower's text edited to ``text``, from an empty folder; (result, files written)."""
    folder = tmp_path / "run"
    folder.mkdir()
    path = tmp_path / "machine.toml"
    path.write_text(text)
    result = CliRunner().invoke(cli, ["drop", "--machine", str(path), "--json", "--quiet", "--out",
                                      str(folder / "out"), *extra])
    return result, list(folder.iterdir())


def _refused(tmp_path, text: str, *extra: str) -> str:
    result, written = _drop(tmp_path, text, "--scenario", "power loss", "--duration", "50 ms", *extra)
    assert result.exit_code == 2, result.output
    assert written == []
    assert result.stderr.count("\n") == 1 and "Traceback" not in result.output, result.stderr
    return result.stderr.strip()


def test_bearings_too_weak_to_carry_the_rotor_are_refused_for_a_levitated_start(tmp_path):
    weak = _blower_text().replace('max_current = "5 A"', 'max_current = "0.1 A"')
    line = _refused(tmp_path, weak)
    assert line.startswith("error: amb.0.max_current = '0.1 A': must exceed the levitation current 0.49 A"), line
    assert "'power loss'" in line


def test_the_bias_bounds_a_magnetic_circuits_current(tmp_path):
    # at 60 deg the circuit's k_i is 20 N/A: 49 N of weight ask 2.44 A of a 2 A bias
    text = _blower_text().replace(CIRCUIT[0], CIRCUIT[1].format("60 deg"), 1)
    line = _refused(tmp_path, text)
    assert line.startswith("error: amb.0.bias_current = '2 A': must exceed the levitation current 2.44 A"), line


@pytest.mark.parametrize("angle", ["90 deg", "180 deg", "-10 deg", "1.5707963267948966 rad"])
def test_a_pole_angle_outside_0_to_90_deg_is_refused_by_its_own_key(tmp_path, angle):
    text = _blower_text().replace(CIRCUIT[0], CIRCUIT[1].format(angle), 1)
    line = _refused(tmp_path, text)
    assert line.startswith(f"error: amb.0.pole_angle = '{angle}': must lie in [0, 90) deg"), line


def test_two_ambs_of_one_name_are_refused(tmp_path):
    text = _blower_text().replace('name = "non-drive-end AMB"', 'name = "drive-end AMB"')
    assert _refused(tmp_path, text) == ("error: amb.1.name = 'drive-end AMB': two [[amb]] tables of one name (a "
                                        "scenario names the bearing it fails by it)")


def test_an_unknown_scenario_key_lists_each_allowed_key_once(tmp_path):
    text = _blower_text().replace('decay_time = "5 ms"      # the coils discharge', 'decay_time = "5 ms"\nfoo = 1')
    line = _refused(tmp_path, text)
    allowed = line.split("its keys: ")[1].split(", ")
    assert len(allowed) == len(set(allowed)), line
    assert set(allowed) == {"name", "kind", "time", "relevitate_within", "decay_time", "ride_through", "restore_time"}


def test_a_failures_keys_are_refused_on_an_overload(tmp_path):
    text = _blower_text().replace('duration = "5 ms"\n', 'duration = "5 ms"\ndecay_time = "5 ms"\n')
    line = _refused(tmp_path, text)
    assert line.startswith("error: scenario.3.decay_time = '5 ms': not a key of a shock scenario"), line


@pytest.mark.parametrize("den", ["[0, 0]", "[0.0]"])
def test_a_controller_with_a_zero_denominator_is_told_so(tmp_path, den):
    text = _blower_text().replace('kp = "6000 A/m"\nki = "1e5 A/(m*s)"\nkd = "12 A*s/m"',
                                  f"controller = {{ num = [1], den = {den} }}", 1)
    line = _refused(tmp_path, text)
    assert "the denominator den must not be all zeros" in line and "proper" not in line, line


@pytest.mark.slow  # a drop of the blower: about 2 s
def test_a_scenario_after_the_run_says_it_never_struck(tmp_path):
    # not refused: verify runs a scenario case for its time plus drop.duration, and a scenario far ahead is how a
    # run is held levitated throughout; the summary must not read as a scenario survived
    text = _blower_text().replace('time = "30 ms"           # the levitated', 'time = "5 s"  # the levitated')
    result, _ = _drop(tmp_path, text, "--scenario", "power loss", "--duration", "5 ms")
    assert result.exit_code == 0, result.output
    s = json.loads(result.stdout)["scenario"]
    assert s["struck"] is False and s["first_contact_ms"] is None
    assert s["outcome"].startswith("not struck: the run ends at 5 ms, before the scenario's time 5000 ms"), s


def test_a_rate_zero_to_the_computations_precision_is_no_instability():
    note = _levitation(complex(0.0, 0.0))  # steady_orbit sets a rate within NEUTRAL of the fastest one to 0
    assert note["undamped"] is True and note["stable"] is False
    assert "UNSTABLE" not in note["note"] and "+0.00" not in note["note"] and "undamped" in note["note"]
    grows = _levitation(complex(1e-3, 2.0))  # a real, slow growth is still told, with its digits
    assert grows["undamped"] is False and "grows at +0.001 1/s" in grows["note"]
    # the blower's fastest rate is its sensor's, 2 pi 5 kHz: the 5.7e-9 1/s once reported as a growth is noise
    assert NEUTRAL * 2 * np.pi * 5000 > 5.7e-9


@pytest.mark.slow  # a drop of the blower: about 2 s
def test_an_iron_saturated_bearing_reports_an_undamped_mode_not_a_growth(tmp_path):
    text = _blower_text().replace('max_current = "5 A"', 'max_current = "5 A"\nload_capacity = "10 N"')
    result, _ = _drop(tmp_path, text, "--scenario", "power loss", "--duration", "2 ms")
    assert result.exit_code == 0, result.output
    levitation = json.loads(result.stdout)["scenario"]["levitation"]
    assert levitation["stable"] is False and levitation["undamped"] is True
    assert levitation["least_damped_rate_per_s"] == 0.0
    assert "UNSTABLE" not in levitation["note"] and "+0.00" not in levitation["note"]


@pytest.mark.slow  # a drop of the blower: about 2 s
def test_saturation_and_first_contact_are_booked_once_and_in_time(tmp_path):
    text = _blower_text().replace('unbalance_phase = "0 deg"',
                                  'unbalance_phase = "0 deg"\nstart_x = "0.1 mm"\nstart_y = "-0.05 mm"')
    text = text.replace('kd = "12 A*s/m"', 'kd = "0 A*s/m"')  # no damping: the levitated rotor swings up
    radial = text.split("[[amb]]")
    for k in (1, 2):  # the radial bearings saturate on both axes at the start (0.6 A asked in x)
        radial[k] = radial[k].replace('max_current = "5 A"', 'max_current = "0.55 A"')
    result, _ = _drop(tmp_path, "[[amb]]".join(radial), "--scenario", "power loss", "--duration", "35 ms")
    assert result.exit_code == 0, result.output
    summary = json.loads(result.stdout)
    s = summary["scenario"]
    impacts = [p["first_impact_ms"] for p in summary["planes"] if p["first_impact_ms"] is not None]
    # the rotor lands before the 30 ms strike: the first contact is that landing, not the first after the strike
    assert min(impacts) < 30.0
    assert s["first_contact_ms"] == pytest.approx(min(impacts), rel=1e-12)
    assert s["touched_before_strike"] is True
    simulated = summary["simulated_s"] * 1e3
    for bearing in s["saturation"]:
        spans = np.array(bearing["first_intervals_ms"]).reshape(-1, 2)
        assert bearing["saturated_ms"] <= simulated
        assert np.all(spans[1:, 0] >= spans[:-1, 1])  # x and y at their limits together count once
        assert np.all(spans[:, 1] <= 30.0 + 1e-9)  # a current frozen at its limit after the power loss does not
    assert s["saturation"][0]["saturated_ms"] > 10.0


def test_a_verification_of_bearings_too_weak_to_levitate_stops_before_its_first_drop(tmp_path):
    # the file is refused as it is read (machine.combinations), not at the first levitated start minutes in
    path = tmp_path / "weak.toml"
    path.write_text(_blower_text().replace('max_current = "', 'max_current = "0.1 A" #'))
    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["verify", "--machine", str(path), "--quick", "--out", str(out)])
    assert result.exit_code == 2
    assert "amb.0.max_current = '0.1 A': must exceed the levitation current" in result.output
    assert not out.exists()


def test_a_coil_inductance_without_a_voltage_limit_is_refused(tmp_path):
    # it was read and changed nothing: the inductance limits the current's rate only against max_voltage
    text = _blower_text().replace('max_current = "5 A"', 'max_current = "5 A"\ncoil_inductance = "10 mH"', 1)
    result, written = _drop(tmp_path, text)
    assert result.exit_code == 2 and not written
    assert "amb.0.coil_inductance = '10 mH': acts only with max_voltage" in result.output


def test_the_text_output_of_a_scenario_drop_says_what_the_scenario_did():
    # the outcome was in --json alone: a text reader saw the table and not that the rotor had landed
    result = CliRunner().invoke(cli, ["drop", "--machine", "blower", "--scenario", "power loss", "--duration",
                                      "50 ms", "--quiet"])
    assert result.exit_code == 0, result.output
    text = " ".join(result.output.split())
    assert "scenario 'power loss' (power loss) at 30.0 ms: on the touchdown bearings; first contact at" in text


def test_an_amplifier_without_a_current_limit_is_unlimited_in_the_json_and_the_table(tmp_path):
    # the drop's summary held the missing limit as null, the same as a number not computed; now inf, written "inf"
    path = tmp_path / "machine.toml"
    path.write_text("\n".join(line for line in _blower_text().splitlines() if not line.startswith("max_current")))
    args = ["drop", "--machine", str(path), "--scenario", "power loss", "--duration", "2 ms", "--quiet"]
    as_json = CliRunner().invoke(cli, [*args, "--json"])
    assert as_json.exit_code == 0, as_json.output
    limits = [a["max_current_A"] for a in json.loads(as_json.stdout)["amb"]]
    assert limits and set(limits) == {"inf"}
    shown = CliRunner().invoke(cli, args)
    assert shown.exit_code == 0, shown.output
    rows = [line for line in shown.stdout.splitlines() if "AMB " in line and ("radial" in line or "axial" in line)]
    assert len(rows) == len(limits) and all("unlimited" in row for row in rows), shown.stdout
