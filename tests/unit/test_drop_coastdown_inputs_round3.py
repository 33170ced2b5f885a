"""Drop and coast-down inputs and outputs an engineer could misread: quoted bare numbers, budgets, partial lives."""

import copy

import pytest

from auxbearing.analysis.life import governing
from auxbearing.analysis.whirl import UNCLASSIFIED, timeline
from auxbearing.common.errors import InputError
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping


def _blower(section: str, index: int | None = None, **values):
    data, name, base = machine_table("blower")
    data = copy.deepcopy(data)
    table = data[section] if index is None else data[section][index]
    table.update(values)
    return machine_from_mapping(data, name, base)


@pytest.mark.parametrize(("section", "key", "value"), [("coastdown", "ambient_temperature", "25"),
                                                       ("rotor", "speed", "1885"), ("drop", "duration", " 0.2 ")])
def test_a_quoted_number_without_a_unit_is_refused_not_read_as_si(section, key, value):
    # "25" became 25 K (-248 degC) and "1885" rad/s where the docs say a bare number is refused
    with pytest.raises(InputError, match=rf"^{section}\.{key} = '{value}': needs a unit, e\.g\. '{value.strip()} "):
        _blower(section, **{key: value})


@pytest.mark.parametrize(("key", "value", "rule"), [("max_output_points", 1, "must be 2 or more"),
                                                    ("energy_tolerance", 0, r"must lie in \(0, 1\]")])
def test_drop_settings_that_break_or_stop_every_run_are_refused(key, value, rule):
    with pytest.raises(InputError, match=rf"^drop\.{key} = {value}: {rule}"):
        _blower("drop", **{key: value})


def test_a_shoulder_past_the_balls_centre_or_a_face_off_the_ring_is_refused():
    with pytest.raises(InputError, match=r"^touchdown\.0\.shoulder_height = '7 mm': must be below the ball radius"):
        _blower("touchdown", 0, shoulder_height="7 mm")  # QJ208: 12.7 mm balls
    with pytest.raises(InputError, match=r"^touchdown\.0\.face_radius = '100 mm': must lie on the inner ring's face"):
        _blower("touchdown", 0, face_radius="100 mm", axial_clearance="0.1 mm")


def test_the_required_drops_say_where_they_come_from():
    from auxbearing.analysis.coastdown import required_drops_source

    assert required_drops_source(_blower("life", required_drops=20)) == "the machine file's life.required_drops"
    data, name, base = machine_table("blower")
    data = copy.deepcopy(data)
    data.pop("life", None)
    assert required_drops_source(machine_from_mapping(data, name, base)).startswith("an assumption of auxbearing")


def test_the_life_margin_is_the_share_of_drops_to_spare_as_in_a_verification():
    assert governing(376.2, 1e9, required_drops=20)["margin"] == pytest.approx(376.2 / 20 - 1.0)


def test_a_run_that_closed_no_whirl_window_has_its_whirl_unknown_not_none():
    import numpy as np

    from auxbearing.core.watch import WHIRL_FIELDS

    found = timeline(np.empty((0, len(WHIRL_FIELDS))), 0.03, 1e-4, 0.02, np.empty(0))
    assert found["whirl"] == UNCLASSIFIED and found["whirl_frequency_Hz"] is None and not found["backward_at_end"]


@pytest.mark.slow
def test_a_run_to_standstill_cut_by_max_time_is_a_budget_and_its_life_says_what_it_covers():
    from auxbearing.analysis.coastdown import TIME_BUDGET, run_coastdown

    summary = run_coastdown(_blower("coastdown", max_time="0.3 s")).summary
    assert summary["verdict"] == TIME_BUDGET and summary["coastdown_time_s"] is None
    assert "coastdown.max_time = 0.3 s was reached at" in summary["reason"]
    note = summary["planes"][0]["life_note"]
    assert note.startswith("counted over the first 0.3 s only (stopped: time budget, before standstill)")


def test_a_drop_shorter_than_one_output_step_is_refused_from_a_file_the_api_and_the_command_line():
    from auxbearing.analysis.drop import run_machine

    with pytest.raises(InputError, match=r"^drop\.duration = '5e-06 s': shorter than drop\.output_step = 1e-05 s"):
        _blower("drop", duration="5 us")
    with pytest.raises(InputError, match=r"^duration = '5 us': shorter than drop\.output_step = 1e-05 s"):
        run_machine("blower", duration="5 us")


def test_a_count_given_as_true_is_told_it_must_be_a_plain_number():
    with pytest.raises(InputError, match=r"^drop\.max_steps = True: must be a plain number$"):
        _blower("drop", max_steps=True)
