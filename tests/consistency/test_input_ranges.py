"""Physical inputs keep to a physical range: every temperature of a machine file lies where bearings are used.

``coastdown.ambient_temperature = "1 K"`` was taken (any positive kelvin was), and so was a temperature
difference written where a temperature is meant ("250 delta_degC", which pint makes 250 K, read as -23 degC).
Ambient and the two temperature limits now lie within -73 to 350 degC
(:data:`auxbearing.common.params.SERVICE_TEMPERATURE`), refused in one line naming the key as written.
"""

from __future__ import annotations

import copy

import pytest
from click.testing import CliRunner

from auxbearing.cli.main import cli
from auxbearing.common.errors import InputError
from auxbearing.machine.check import check_machine_document
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import Coastdown

RANGE = ("must lie within -73 degC to 350 degC (200.15 K to 623.15 K), the service range of bearing greases and "
         "heat-stabilised bearing steel")
DIFFERENCE = "is a temperature difference; give a temperature, e.g. '20 degC'"


def _rig(**tables) -> tuple[dict, str, object]:
    data, name, base = machine_table("paper_rig")
    data = copy.deepcopy(data)
    for section, values in tables.items():
        data.setdefault(section, {}).update(values)
    return data, name, base


@pytest.mark.parametrize(("section", "key", "value"), [
    ("coastdown", "ambient_temperature", "1 K"),
    ("coastdown", "ambient_temperature", "-100 degC"),
    ("coastdown", "ambient_temperature", "1000 K"),
    ("coastdown", "max_temperature", "5000 degC"),
    ("coastdown", "max_temperature", "-80 degC"),
    ("criteria", "max_temperature", "1 K"),
    ("criteria", "max_temperature", "400 degC"),
])
def test_a_temperature_outside_the_service_range_is_refused_with_the_range(section, key, value):
    with pytest.raises(InputError) as err:
        check_machine_document(*_rig(**{section: {key: value}}))
    assert str(err.value) == f"{section}.{key} = {value!r}: {RANGE}"


@pytest.mark.parametrize(("section", "key", "value"), [
    ("coastdown", "ambient_temperature", "20 delta_degC"),
    ("coastdown", "ambient_temperature", "250 delta_degC"),  # inside the range once made kelvin: still a slip
    ("coastdown", "ambient_temperature", "30 Δcelsius"),
    ("coastdown", "max_temperature", "400 delta_degF"),
    ("criteria", "max_temperature", "300 delta_degC"),
])
def test_a_temperature_difference_is_no_temperature(section, key, value):
    with pytest.raises(InputError) as err:
        check_machine_document(*_rig(**{section: {key: value}}))
    assert str(err.value) == f"{section}.{key} = {value!r}: {DIFFERENCE}"


@pytest.mark.parametrize(("value", "kelvin"), [("20 degC", 293.15), ("293.15 K", 293.15), ("68 degF", 293.15),
                                               ("-73 degC", 200.15), ("200.15 K", 200.15), ("-10 degC", 263.15)])
def test_absolute_temperatures_in_any_unit_up_to_the_ends_are_taken(value, kelvin):
    machine = check_machine_document(*_rig(coastdown={"ambient_temperature": value}))
    assert machine.coastdown.ambient_temperature == pytest.approx(kelvin, abs=1e-9)


def test_the_hot_end_is_taken_for_the_run_away_stop_and_a_rise_still_takes_a_difference():
    machine = check_machine_document(*_rig(coastdown={"max_temperature": "350 degC",
                                                      "tail_temperature_rise": "0.05 delta_degC"}))
    assert machine.coastdown.max_temperature == pytest.approx(623.15)
    assert machine.coastdown.tail_temperature_rise == pytest.approx(0.05)


def test_a_plain_number_still_needs_its_unit():
    with pytest.raises(InputError, match=r"^coastdown.ambient_temperature = '20': needs a unit, e.g. '20 degC'$"):
        check_machine_document(*_rig(coastdown={"ambient_temperature": "20"}))


def test_the_python_api_keeps_the_same_range():
    # there a plain number is SI: 1.0 is one kelvin
    with pytest.raises(InputError, match=r"^coastdown.ambient_temperature = '-272.15 degC': must lie within -73 degC"):
        Coastdown(ambient_temperature=1.0)
    with pytest.raises(InputError, match=r"^coastdown.max_temperature = '20 delta_degC': is a temperature difference"):
        Coastdown(max_temperature="20 delta_degC")
    assert Coastdown(ambient_temperature="25 degC").ambient_temperature == pytest.approx(298.15)


@pytest.mark.slow  # 0.4 s, most of it importing the commands
def test_the_command_line_refuses_an_absurd_ambient_in_one_line_and_writes_nothing(tmp_path):
    from importlib import resources

    rig = resources.files("auxbearing.catalog").joinpath("machines", "paper_rig.toml").read_text()
    assert "[coastdown]" not in rig
    path = tmp_path / "m.toml"
    path.write_text(rig + '\n[coastdown]\nambient_temperature = "1 K"\n')
    folder = tmp_path / "run"
    folder.mkdir()
    for command in ("drop", "coastdown"):
        result = CliRunner().invoke(cli, [command, "--machine", str(path), "--quiet", "--out", str(folder / "o")])
        assert result.exit_code == 2, result.output
        assert result.stderr == f"error: coastdown.ambient_temperature = '1 K': {RANGE}\n"
        assert "Traceback" not in result.output and list(folder.iterdir()) == []
