"""What the file's [criteria] and [verify] tables may hold, checked before any run, and the API's candidates."""

import copy
import json

import pytest

from auxbearing.common.errors import InputError
from auxbearing.machine.check import check_machine_document
from auxbearing.machine.files import machine_table
from auxbearing.machine.judging import candidate_tables
from auxbearing.machine.model import machine_from_mapping


def _with(section: str, **values):
    data, name, base = machine_table("blower")
    data = copy.deepcopy(data)
    data.setdefault(section, {}).update(values)
    return data, name, base


def _refused(section: str, **values) -> str:
    data, name, base = _with(section, **values)
    with pytest.raises(InputError) as err:
        check_machine_document(data, name, base)
    return str(err.value)


def test_a_friction_range_blames_the_end_the_file_gives_and_quotes_the_default():
    assert _refused("verify", friction_high=0.05) == (
        "verify.friction_high = 0.05: below verify.friction_low = '0.1 (default)'")
    assert _refused("verify", friction_low=0.5) == (
        "verify.friction_low = 0.5: above verify.friction_high = '0.3 (default)'")


@pytest.mark.parametrize("samples", [1e9, 100001, 12.5])
def test_the_campaign_size_in_the_file_follows_the_command_lines_rule(samples):
    assert "verify.campaign_samples" in _refused("verify", campaign_samples=samples)
    assert "[0, 100000]" in _refused("verify", campaign_samples=samples)


def test_a_campaign_of_zero_drops_is_accepted_in_the_file_as_on_the_command_line():
    data, name, base = _with("verify", campaign_samples=0)
    check_machine_document(data, name, base)


@pytest.mark.parametrize(("key", "value", "rule"), [("air_gap_fraction", 0, "(0, 1]"),
                                                    ("max_backward_whirl_probability", 0, "(0, 1]"),
                                                    ("required_drops", 0.5, "whole number")])
def test_limits_no_design_can_meet_or_no_count_are_refused(key, value, rule):
    message = _refused("criteria", **{key: value})
    assert message.startswith(f"criteria.{key} = {value}") and rule in message


def test_a_candidate_takes_its_own_ball_constant_and_shoulder_not_the_designs_overrides():
    data, name, base = machine_table("blower")
    data = copy.deepcopy(data)
    data["touchdown"][0].update(ball_constant="1e10 N/m^1.5", shoulder_height="2 mm")
    design = machine_from_mapping(data, name, base)
    assert design.planes[0].ball_constant == pytest.approx(1e10)
    ((_, tables),) = candidate_tables(data, ["6208"])
    candidate = machine_from_mapping(tables, name, base)
    own = machine_from_mapping(candidate_tables(machine_table("blower")[0], ["6208"])[0][1], name, base)
    assert candidate.planes[0].ball_constant == pytest.approx(own.planes[0].ball_constant)
    assert candidate.planes[0].ball_constant != pytest.approx(1e10)
    assert "shoulder_height" not in tables["touchdown"][0]


def test_the_api_takes_candidates_as_the_command_line_writes_them_and_refuses_one_given_twice(tmp_path):
    from auxbearing.verify.run import verify

    with pytest.raises(InputError, match=r"^candidates = '6208': each candidate once"):
        verify("blower", str(tmp_path), "6208, 6208", quick=True)
    with pytest.raises(InputError, match=r"^candidates = '6208,': a comma-separated list"):
        verify("blower", tmp_path, "6208,", quick=True)


def test_the_command_line_refuses_an_empty_candidate_in_its_list_writing_nothing(tmp_path):
    from click.testing import CliRunner

    from auxbearing.cli.main import cli

    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["verify", "--machine", "blower", "--out", str(out), "--quick",
                                       "--candidates", "6208,"])
    assert result.exit_code == 2 and not out.exists()
    assert "--candidates = '6208,': a comma-separated list of bearings, no empty item" in result.output


def test_none_asks_for_the_design_alone_without_the_file_s_candidates():
    from auxbearing.verify.run import candidate_specs

    # an engineer iterating on one design: the blower's file names three candidates, "none" runs none of them
    assert candidate_specs("none", "--candidates") == [] == candidate_specs(" NONE ")
    assert candidate_specs(None) is None  # the file's [[candidate]] tables
    assert candidate_specs("none, 6208", "--candidates") == ["none", "6208"]  # a list is a list: refused as a name


@pytest.mark.slow  # a quick verification of the blower without its campaign: about 15 s
def test_the_command_line_verifies_the_design_alone_with_candidates_none(tmp_path):
    from click.testing import CliRunner

    from auxbearing.cli.main import cli

    out = tmp_path / "out"
    result = CliRunner().invoke(cli, ["verify", "--machine", "blower", "--out", str(out), "--quick", "--json",
                                       "--campaign-samples", "0", "--no-recommendation", "--candidates", "none"])
    assert result.exit_code == 3, result.output  # INCOMPLETE: a quick look
    assert json.loads(result.stdout)["candidates"] == []
