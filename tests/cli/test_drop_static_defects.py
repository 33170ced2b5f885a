"""A review's finds in drop, static, contact-sweep and bearings: each refused or reported as the rule says."""

import json

from click.testing import CliRunner

from auxbearing.cli.main import cli


def _run(*args):
    return CliRunner().invoke(cli, list(args))


def test_a_sweep_at_no_ball_load_is_refused(tmp_path):
    """0 N passed the option's check and divided 0 by 0 in the four-point/angular-contact comparison."""
    result = _run("contact-sweep", "--ball-load", "0", "--out", str(tmp_path / "cs"))
    assert result.exit_code == 2 and "--ball-load = '0': must be > 0 N" in result.stderr
    assert not (tmp_path / "cs").exists()


def test_the_support_s_reactions_are_reported():
    """Held square, the ring carries no moment: the shaft's support takes the whole 2 N m (the balls' loads are
    those of no moment, 238.8 N at most); located, the shoulder's 793.2 N of the 7202 under 1 kN radial."""
    result = _run("static", "--radial", "1000", "--moment", "2", "--tilt", "fixed", "--json")  # reactions: held only
    mx, my = json.loads(result.stdout)["moment_reaction_Nm"]
    assert abs(mx) < 1e-9 and abs(abs(my) - 2.0) < 1e-9
    result = _run("static", "--bearing", "7202", "--radial", "1000", "--axial-condition", "located", "--tilt",
                  "fixed", "--json")
    assert abs(json.loads(result.stdout)["axial_reaction_N"] - 793.2) < 0.1
    assert "Moment reaction      2 N·m" in _run("static", "--radial", "1000", "--moment", "2", "--tilt",
                                                "fixed").stdout


def test_a_reversed_bore_range_is_refused():
    result = _run("bearings", "--bore", "60-30")
    assert result.exit_code == 2 and "a range runs from the smaller bore to the larger" in result.stderr


def test_a_start_point_outside_the_clearance_names_the_option_typed():
    result = _run("drop", "--duration", "20 ms", "--start-y", "-0.25")
    assert result.exit_code == 2
    assert result.stderr.startswith("error: --start-y = '-0.25': the journal must start inside the clearance circle")


def test_a_plain_ball_constant_reads_as_in_drop():
    """drop reads a plain --ball-constant in N/m**1.5; static refused it as no stiffness."""
    assert _run("static", "--radial", "1000", "--ball-constant", "1e10", "--json").exit_code == 0
    result = _run("static", "--radial", "1000", "--ball-constant", "1e10 kg")
    assert result.exit_code == 2
    assert "--ball-constant = '1e10 kg': unit kilogram is not a ball constant" in result.stderr


def test_a_clearance_a_bearing_cannot_take_names_the_list_as_typed(tmp_path):
    """It named touchdown.0.radial_clearance, a key the user never wrote."""
    result = _run("drop-compare", "--clearances", "0.2,20", "--out", str(tmp_path / "dc"))
    assert result.exit_code == 2 and not (tmp_path / "dc").exists()
    assert result.stderr.startswith("error: --clearances = '0.2,20': 20 mm with QJ202: must be below the race bore")


def test_a_count_with_a_word_for_its_unit_is_told_to_be_a_plain_number():
    import copy

    import pytest

    from auxbearing.common.errors import InputError
    from auxbearing.machine.files import machine_table
    from auxbearing.machine.model import machine_from_mapping

    data, name, base = machine_table("paper_rig")
    data = copy.deepcopy(data)
    data.setdefault("life", {})["required_drops"] = "10 drops"
    with pytest.raises(InputError, match=r"^life.required_drops = '10 drops': must be a plain number, e.g. 10$"):
        machine_from_mapping(data, name, base)
