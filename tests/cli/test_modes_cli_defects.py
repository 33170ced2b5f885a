"""``auxbearing modes`` and ``auxbearing bearings`` on the console: units in the headers, growing modes marked, one row
for a machine at rest (the review of the modes command)."""

import json
from importlib import resources

import pytest
from click.testing import CliRunner

from auxbearing.cli.main import cli

WIDE = {"COLUMNS": "200"}  # rich wraps to the terminal's width; wide enough that no header wraps


def _rows(text: str) -> str:
    """The table rows of a printout (rich draws them between vertical bars)."""
    return "\n".join(line for line in text.splitlines() if line.startswith("│"))


def _blower_file(tmp_path, extra: str = "", speed: str = "18000 rpm"):
    """The shipped blower.toml, with ``extra`` tables appended and its speed replaced."""
    text = resources.files("auxbearing.catalog.machines").joinpath("blower.toml").read_text()
    text = text.replace('speed = "18000 rpm"', f'speed = "{speed}"', 1)
    path = tmp_path / "machine.toml"
    path.write_text(text + "\n" + extra)
    return str(path)


def test_the_headers_keep_their_units():
    """rich took a lowercase "[rpm]" or "[kg/m³]" for a style tag and dropped it (defect E)."""
    r = CliRunner(env=WIDE).invoke(cli, ["modes", "--machine", "blower", "--speeds", "0, 100 Hz"])
    assert r.exit_code == 0, r.output
    assert "speed [rpm]" in r.output and "mode 1 [Hz]" in r.output
    # 100 Hz is 6000 rpm
    assert "6000" in r.output
    r = CliRunner(env=WIDE).invoke(cli, ["bearings", "--bore", "40", "--no-sources"])
    assert r.exit_code == 0, r.output
    assert "ρ [kg/m³]" in r.output and "E [GPa]" in r.output and "computed [kN]" in r.output


def test_a_growing_mode_is_marked_and_warned(tmp_path):
    """The blower with a strongly cross-coupled seal at the mass centre (kxy = -kyx = 5e6 N/m) (defect D).

    Translation (the seal at the mass centre, the tilt untouched), z = x + i y: m z'' + c z' + (2k - i q) z = 0 with
    m = 10 kg, c = 2 * 1200 N s/m, 2k = 2 * 4e5 N/m, q = 5e6 N/m: s = (-c + sqrt(c^2 - 4 m (2k - i q))) / (2 m)
    = 348.3 + 533.8i 1/s, a mode at 533.8 / (2 pi) = 84.96 Hz growing at 348.3 1/s, damping ratio
    -348.3 / |s| = -0.5465; its backward twin decays (-588.3 1/s). Printed "85.0 F ζ=-0.546 UNSTABLE" with a warning.
    """
    seal = '[[linear_support]]\nname = "seal"\nposition = "0 mm"\nkxy = "5e6 N/m"\nkyx = "-5e6 N/m"\n'
    machine = _blower_file(tmp_path, seal)
    r = CliRunner(env=WIDE).invoke(cli, ["modes", "--machine", machine, "--speeds", "0 rpm"])
    assert r.exit_code == 0, r.output
    free = r.output.split("in contact")[0]
    assert _rows(free).count("UNSTABLE") == 1 and "ζ=-" in _rows(free)
    assert "warning:" in free and "1 at 0 rpm" in free
    data = json.loads(CliRunner().invoke(cli, ["modes", "--machine", machine, "--speeds", "0 rpm", "--json"]).output)
    (unstable,) = data["states"][0]["unstable"]
    assert unstable["growth_rate_per_s"] == pytest.approx(348.34, abs=0.01)
    assert unstable["frequency_Hz"] == pytest.approx(84.957, abs=1e-3)
    assert unstable["damping_ratio"] == pytest.approx(-0.5465, abs=1e-4)
    assert "85.0 F ζ=-0.546 UNSTABLE" in _rows(free)


def test_a_divergent_root_is_printed(tmp_path):
    """The blower with -5e6 N/m at the mass centre: net 2 * 4e5 - 5e6 < 0 in translation, which diverges without
    oscillating (defect D); the table shows it (with its e-folding time) instead of dropping it.

    The translation: m s^2 + 2c s + (2k - 5e6) = 0 with m = 10 kg, 2c = 2400 N s/m, 2k = 8e5 N/m:
    s = (-2400 + sqrt(2400^2 + 4 * 10 * 4.2e6)) / 20 = (-2400 + 13182) / 20 = 539.1 1/s, e-folding in 1.85 ms.
    """
    spring = '[[linear_support]]\nposition = "0 mm"\nkxx = "-5e6 N/m"\nkyy = "-5e6 N/m"\n'
    r = CliRunner(env=WIDE).invoke(cli, ["modes", "--machine", _blower_file(tmp_path, spring), "--speeds", "0 rpm"])
    assert r.exit_code == 0, r.output
    free = r.output.split("in contact")[0]
    assert "mode 4 [Hz]" in free and _rows(free).count("no oscillation, e-fold 1.85 ms UNSTABLE") == 2
    assert "2 at 0 rpm" in free


def test_a_machine_at_rest_gets_one_row(tmp_path):
    """rotor.speed = 0 rpm: the default range 0 to 1.2 x 0 was 13 copies of 0 rpm (defect F)."""
    machine = _blower_file(tmp_path, speed="0 rpm")
    data = json.loads(CliRunner().invoke(cli, ["modes", "--machine", machine, "--json"]).output)
    assert [m["speed_rpm"] for m in data["modes"]] == [0.0]
    r = CliRunner(env=WIDE).invoke(cli, ["modes", "--machine", machine])
    assert r.exit_code == 0, r.output
    assert "one row at rest" in r.output
