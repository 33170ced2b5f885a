"""The whole-document check of a machine file (issue 20): keys, combinations, candidate seats, nesting, stiffness."""

from __future__ import annotations

import copy
import math

import pytest

from auxbearing.bearings.catalogue import get_bearing
from auxbearing.common.errors import InputError
from auxbearing.common.io import MAX_TOML_DEPTH, nesting_depth, read_toml
from auxbearing.common.units import Quantity
from auxbearing.machine.check import (
    check_candidate_seat,
    check_machine_document,
    mode_step,
    stiffness_notes,
)
from auxbearing.machine.files import machine_table, read_machine
from auxbearing.machine.model import machine_from_mapping


def paper() -> dict:
    return copy.deepcopy(machine_table("paper_rig")[0])


def refused(data: dict, *words: str) -> str:
    with pytest.raises(InputError) as err:
        check_machine_document(data, "paper rig")
    text = str(err.value)
    assert "\n" not in text and all(w in text for w in words), text
    return text


def test_the_examples_pass_whole():
    from auxbearing.machine.files import machine_names

    for name in machine_names():
        data, title, base = machine_table(name)
        assert check_machine_document(data, title, base).planes


def test_a_mistyped_key_is_told_the_closest_allowed_one():
    data = paper()
    data["touchdown"][0]["sliding_fricton"] = 0.2
    assert refused(data, "touchdown.0.sliding_fricton").endswith("did you mean sliding_friction?")
    data = paper()
    data["critera"] = {"min_s0": 2}
    assert refused(data, "[critera]").endswith("did you mean criteria?")
    data = paper()
    data["touchdown"][0]["bearng"] = "QJ202"
    assert refused(data, "touchdown.0.bearng").endswith("did you mean bearing?")


def test_tables_no_drop_uses_are_checked_as_verify_checks_them():
    for table, value, words in (("criteria", {"max_temperature": "120 mm"}, ("criteria.max_temperature", "120 mm")),
                                ("verify", {"campaign_samples": -4}, ("verify.campaign_samples", "-4")),
                                ("life", {"required_drops": 0}, ("life.required_drops",)),
                                ("candidate", [{"bearing": "QJ999"}], ("candidate.0.bearing", "QJ999"))):
        data = paper()
        data[table] = value
        refused(data, *words)


def test_a_machine_files_campaign_table_is_checked_by_every_command(tmp_path):
    """The [campaign] table belongs to the campaign room; the command line's reader asks it (no room below
    the campaign imports it)."""
    from auxbearing.cli.common import read_machine_file
    from auxbearing.machine.files import _catalogue_files

    path = tmp_path / "m.toml"
    path.write_text(_catalogue_files()["paper_rig"] + '\n[campaign]\nsamples = 2\nsampler = "grid"\n')
    with pytest.raises(InputError) as err:
        read_machine_file(str(path))
    assert "campaign.sampler" in str(err.value) and "grid" in str(err.value)


def test_values_impossible_together_name_both_keys():
    cases = [
        ("rotor", {"start_x": "0.15 mm", "start_y": "-0.15 mm"}, ("rotor.start_x", "radial_clearance")),
        ("plane", {"journal_radius": "7.5 mm"}, ("touchdown.0.journal_radius", "bore 15 mm")),
        ("plane", {"face_damping": "10 N*s/m"}, ("touchdown.0.face_damping", "touchdown.0.axial_clearance")),
        ("plane", {"stop_damping": "10 N*s/m"}, ("touchdown.0.stop_damping", "touchdown.0.mount_stiffness")),
        ("plane", {"mount_stiffness": "1e7 N/m", "mount_deadband": "30 um", "mount_stop": "10 um"},
         ("touchdown.0.mount_stop", "touchdown.0.mount_deadband")),
        ("plane", {"mount_stiffness": "1e7 N/m", "mount_deadband": "30 um", "mount_travel": "20 um"},
         ("touchdown.0.mount_travel", "touchdown.0.mount_deadband")),
        ("coastdown", {"max_temperature": "25 degC", "ambient_temperature": "30 degC"},
         ("coastdown.max_temperature", "coastdown.ambient_temperature")),
        ("coastdown", {"stop_speed": "6000 rpm"}, ("coastdown.stop_speed", "rotor.speed")),
        ("criteria", {"max_temperature": "20 degC"}, ("criteria.max_temperature", "coastdown.ambient_temperature")),
    ]
    for where, values, words in cases:
        data = paper()
        target = data["touchdown"][0] if where == "plane" else data.setdefault(where, {})
        target.update(values)
        refused(data, *words)


def test_combinations_hold_for_api_values_and_campaign_samples():
    # a campaign's worker hands quantities in; the sentence is the same, the value shown as the quantity
    data = paper()
    data["rotor"]["start_x"] = Quantity(0.3e-3, "m")
    with pytest.raises(InputError, match=r"rotor\.start_x = '0.0003 meter': the journal starts 0.3 mm"):
        machine_from_mapping(data, "rig")
    from auxbearing.campaign import evaluate as ev
    from auxbearing.campaign.config import campaign_from_mapping

    c = campaign_from_mapping({"campaign": {"machine": "paper_rig", "samples": 2, "input": [
        {"key": "rotor.start_x", "distribution": "uniform", "low": "-0.1 mm", "high": "0.1 mm"}]}})
    record = ev.evaluate_sample(c, [0.5e-3])  # a sample beyond the clearance: a record, not an exception
    assert ev.VERDICTS[record["verdict"]] == "invalid_input" and record["reason"].startswith("rotor.start_x")


def test_speed_step_of_zero_is_refused_and_one_is_legal():
    data = paper()
    data["coastdown"] = {"speed_step": 0}
    refused(data, "coastdown.speed_step = 0", "(0, 1]")
    data["coastdown"] = {"speed_step": 1}
    assert check_machine_document(data, "rig").coastdown.speed_step == 1.0


def test_a_candidate_must_fit_the_seat():
    design = read_machine("paper_rig")
    check_candidate_seat(design, get_bearing("7202"), "x")  # same bore, width and outside diameter
    with pytest.raises(InputError, match=r"x: its bore 40 mm does not fit the seat of touchdown\.0"):
        check_candidate_seat(design, get_bearing("QJ208"), "x")
    qj202 = get_bearing("QJ202")
    with pytest.raises(InputError, match="its width 12 mm is larger than the axial room"):
        check_candidate_seat(design, qj202.with_changes(width=12e-3), "x")
    with pytest.raises(InputError, match="its outside_diameter 36 mm is larger than the housing bore"):
        check_candidate_seat(design, qj202.with_changes(outside_diameter=36e-3), "x")
    with pytest.raises(InputError, match="gives no bore"):
        check_candidate_seat(design, qj202.with_changes(bore=None), "x")
    check_candidate_seat(design, qj202.with_changes(width=10e-3, outside_diameter=34e-3), "x")  # smaller fits
    blower = read_machine("blower")
    for name in ("7208 DB", "QJ208 hybrid", "6208"):  # the blower's own candidates
        check_candidate_seat(blower, get_bearing(name), name)
    with pytest.raises(InputError, match=r"its width 40.1 mm is larger than the axial room .*touchdown.0.axial_room"):
        check_candidate_seat(blower, get_bearing("7208 DB").with_changes(spacer=4e-3 + 1e-4), "x")


def test_the_file_reader_refuses_deep_nesting_in_one_line(tmp_path):
    deep = tmp_path / "deep.toml"
    deep.write_text("x = " + "[" * 50000 + "]" * 50000 + "\n")
    with pytest.raises(InputError, match=r"--machine = '.*deep.toml': is nested too deeply to read"):
        read_toml(deep, "--machine")
    moderate = tmp_path / "moderate.toml"
    moderate.write_text("x = " + "[" * 40 + "1" + "]" * 40 + "\n")
    with pytest.raises(InputError, match="is nested 41 levels deep"):
        read_toml(moderate, "--machine")
    assert nesting_depth({"campaign": {"input": [{"key": "x", "low": "1 mm"}]}}) == 4 <= MAX_TOML_DEPTH
    with pytest.raises(InputError, match="nested too deeply"):
        check_machine_document({"rotor": {"x": [[[[[[[[[[[[[[[[[[[1]]]]]]]]]]]]]]]]]]]}})


def test_stiffness_is_said_before_the_run_and_refused_past_the_budget():
    assert mode_step(1.0, 0.0, 0.0) == math.inf
    assert all(not stiffness_notes(read_machine(name)) for name in ("paper_rig", "blower", "vertical"))
    data = paper()
    data["touchdown"][0]["mount_stiffness"] = "1e16 N/m"
    data["drop"]["duration"] = "10 ms"
    machine = machine_from_mapping(data, "rig")
    notes = stiffness_notes(machine)
    assert len(notes) == 1 and notes[0].startswith("touchdown.0.mount_stiffness: the mount (1e+16 N/m")
    assert "makes the integration stiff" in notes[0] and "steps for the 10 ms run" in notes[0]
    assert stiffness_notes(machine, 1e-5) == []  # a short run at that step is quick: nothing to say
    data["touchdown"][0]["mount_stiffness"] = "1e20 N/m"
    with pytest.raises(InputError, match=r"beyond the step budget drop\.max_steps"):
        stiffness_notes(machine_from_mapping(data, "rig"))
    names = {"touchdown.0.mount_stiffness": "--stiff"}
    assert stiffness_notes(machine, names=names)[0].startswith("--stiff: the mount")


def test_the_reference_says_what_the_reader_does():
    from auxbearing.campaign.config import CAMPAIGN_KEYS
    from auxbearing.report.machine_file import markdown

    text = markdown()
    assert "a bare number there is refused" in text and "a bare number is SI" not in text
    for key in CAMPAIGN_KEYS:  # every key of [campaign] is listed
        assert f"| `{key}` |" in text.split("## `[campaign]`")[1], key
    data = paper()
    data["rotor"]["mass"] = 5  # as the reference says: refused, never read as 5 kg
    refused(data, "rotor.mass = 5", "needs a unit")
    data = paper()
    data["touchdown"][0]["sliding_friction"] = 0.25  # a key without a unit takes a plain number
    assert check_machine_document(data, "rig").planes[0].sliding_friction == 0.25
