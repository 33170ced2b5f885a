"""Coast-down and life defects found by a review, each held by the value a hand calculation gives."""

import copy
import math

import pytest

from auxbearing import get_bearing
from auxbearing.analysis.coastdown import run_coastdown
from auxbearing.analysis.coastdown_life import equivalent_load
from auxbearing.analysis.life import dent_per_drop, governing
from auxbearing.common.errors import InputError
from auxbearing.common.params import convert
from auxbearing.machine.files import machine_table, read_machine
from auxbearing.machine.model import machine_from_mapping


def test_a_deep_groove_bearing_counts_its_thrust_in_the_equivalent_load():
    """6208 (C0 18 979 N, f0 13.8): 92.83 N of thrust on 92.47 N radial gives f0 Fa / C0 = 0.068, below ISO 281
    Table 3's first row (e = 0.19, Y = 2.30); Fa / Fr = 1.0 > e, so P = 0.56 x 92.47 + 2.30 x 92.83 = 265.29 N
    (the radial load alone was taken before, 24 times less damage at p = 3)."""
    bearing = get_bearing("6208")
    assert equivalent_load(bearing, 92.47, 92.83) == pytest.approx(0.56 * 92.47 + 2.30 * 92.83, rel=1e-6)
    assert equivalent_load(bearing, 92.47, 10.0) == pytest.approx(92.47)  # Fa / Fr = 0.11 <= e: X = 1, Y = 0


def test_the_interpolated_deep_groove_factors():
    """Between Table 3's rows 0.345 (e 0.22, Y 1.99) and 0.689 (e 0.26, Y 1.71) at f0 Fa / C0 = 0.517: halfway."""
    from auxbearing.core.fatigue import deep_groove_factors

    e, _, _, x2, y2 = deep_groove_factors(0.517)
    assert (e, x2, y2) == pytest.approx((0.24, 0.56, 1.85), abs=1e-3)


def test_governing_when_nothing_limits_and_on_bad_counts():
    assert governing(math.inf, math.inf, 10)["limit"] == "none"
    for bad in (math.nan, -5.0, "10"):
        with pytest.raises(InputError):
            governing(bad, 800.0, 10)
    for required in (0, -5, "10", math.nan):
        with pytest.raises(InputError, match="required_drops"):
            governing(5000.0, 800.0, required)


@pytest.mark.slow
def test_dent_per_drop_takes_a_load_with_a_unit_and_a_catalogue_name():
    by_name = dent_per_drop("1 kN", "QJ202")
    assert by_name["drops_to_dent_limit"] == dent_per_drop(1000.0, get_bearing("QJ202"))["drops_to_dent_limit"]


@pytest.mark.parametrize("text", ["1,5", "0,5 s", "2 3 s", "1 000 s"])
def test_a_time_pint_would_read_otherwise_is_refused(text):
    with pytest.raises(InputError, match="no commas, no spaces inside it"):
        convert("--duration", text, "time")


def test_numbers_with_units_that_hold_a_number_still_read():
    assert convert("thermal_expansion", "11.9e-6 1/K", "thermal_expansion") == pytest.approx(11.9e-6)


@pytest.mark.parametrize(("kwargs", "match"), [
    ({"duration": "0.2"}, r"needs a unit, e.g. '0.2 s'"),
    ({"duration": "1e7 s"}, r"must lie in \(0, 1e\+06\] s"),
    ({"until_stop": "no"}, r"until_stop = 'no': must be True or False"),
    ({"until_stop": None}, r"until_stop = None"),
])
def test_the_api_refuses_what_the_command_line_refuses(kwargs, match):
    with pytest.raises(InputError, match=match):
        run_coastdown("paper_rig", **kwargs)


def _blower(**drop):
    data, name, base = machine_table("blower")
    data = copy.deepcopy(data)
    data["drop"].update(drop)
    for key in ("criteria", "candidate"):
        data.pop(key, None)
    return data, name, base


def test_a_record_too_coarse_for_the_fatigue_count_is_refused_before_the_run():
    """Blower at 18 000 rpm (1885 rad/s), QJ208-class: 11 balls of 12.7 mm on a 60 mm pitch, gamma = 0.212 at
    35 deg. The inner raceway passes under the balls at 1885 x 1.173 / 2 = 1105 rad/s (its ball spacing pi / 11 in
    258 us): 500 us is refused, naming the key."""
    data, name, base = _blower(output_step="500 us")
    with pytest.raises(InputError, match=r"^drop.output_step = 500 us: too coarse .* use 258 us or less$"):
        run_coastdown(machine_from_mapping(data, name, base))


def test_a_max_time_shorter_than_two_output_steps_is_refused():
    data, name, base = _blower()
    data["coastdown"]["max_time"] = "1 us"
    with pytest.raises(InputError, match=r"^coastdown.max_time = .*must be at least 20 us"):
        run_coastdown(machine_from_mapping(data, name, base))


@pytest.mark.slow
def test_a_run_for_a_duration_ends_at_it_in_the_api_as_on_the_command_line():
    summary = run_coastdown("paper_rig", duration="0.05 s").summary
    assert summary["until_stop"] is False and summary["simulated_s"] == pytest.approx(0.05)


def test_an_empty_machine_is_named_as_typed():
    with pytest.raises(InputError, match=r"^machine = '': is empty"):
        read_machine("")


def test_the_ball_contact_budget_counts_both_rows_of_a_pair():
    from auxbearing.cli.drop_checks import check_ball_contacts

    data, name, base = _blower()
    for plane in data["touchdown"]:
        plane["bearing"] = "7208 DB light"
    machine = machine_from_mapping(data, name, base)
    rows = machine.planes[0].rows
    contacts = machine.planes[0].bearing.ball_count * machine.planes[0].bearing.pairs_per_ball * rows
    assert rows == 2
    with pytest.raises(InputError, match=f"x 2 rows = {contacts} contacts"):
        check_ball_contacts(machine, contacts - 1, "--machine")


@pytest.mark.slow
def test_a_drop_that_does_not_finish_shows_no_coastdown_figures():
    """The heavy rotor's drop runs a ball over its groove shoulder at 66.85 ms: no coast-down starts, so its
    hottest part and clearances are none, not the ambient and the clearance as built."""
    summary = run_coastdown("heavy_fast_rotor").summary
    plane = summary["planes"][0]
    assert summary["drop_verdict"] == "contact_ellipse_over_shoulder"
    assert plane["max_temperature_C"] is None and plane["min_internal_clearance_um"] is None


@pytest.mark.slow
def test_a_last_window_shorter_than_a_whirl_window_adds_its_over_rolling():
    """The paper rig's whirl window is 30 ms: runs of 0.18 and 0.20 s both ended in a window that closed none, and
    both gave the same coast-down damage (1.52e-14), the last 20 ms counted as no revolutions."""
    short = run_coastdown("paper_rig", duration="0.18 s").summary["planes"][0]["coastdown_damage"]
    longer = run_coastdown("paper_rig", duration="0.2 s").summary["planes"][0]["coastdown_damage"]
    assert longer > short * 1.2
