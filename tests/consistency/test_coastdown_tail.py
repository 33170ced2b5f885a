"""A coast-down's spent tail (auxbearing.analysis.coastdown.spent_tail) against simulating it to standstill.

Leaving out the tail must not move a result: every part's peak temperature within the tail's own bound
(coastdown.tail_temperature_rise), the damage per drop within the 0.1 % the rule allows, the extrapolated time
to standstill within 1 % of the simulated one, and the internal clearance within 10 nm (see the test). The
blower runs here from 3000 rpm with a seal drag of 0.2 N m and reduced stretches of up to 30 % of the speed,
so that both runs reach standstill in seconds (18.8 s, of which 10.5 s in reduced stretches once the swings
have died out below coastdown_phases.QUIET_LOAD); the closing note of the coast-down issue gives the same
comparison on the blower from its full speed (standstill 223.25 s simulated, 222.60 s with the tail left
out; 93.6 against 43.9 s of computing).
"""

import copy

import pytest

from auxbearing.analysis.coastdown import run_coastdown, tail_note
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping


def _blower(tail: str):
    data, name, base = machine_table("blower")
    data = copy.deepcopy(data)
    data["rotor"]["speed"] = "3000 rpm"
    data.setdefault("coastdown", {}).update({"drag_torque": "0.2 N*m", "speed_step": 0.3,
                                             "tail_temperature_rise": tail})
    return machine_from_mapping(data, name, base)


@pytest.mark.slow
def test_the_spent_tail_moves_no_result():
    left_out = run_coastdown(_blower("0.05 K")).summary
    simulated = run_coastdown(_blower("0 K")).summary
    assert simulated["tail"] is None and simulated["reached_standstill"]
    tail = left_out["tail"]
    assert tail is not None and tail["temperature_rise_bound_K"] <= 0.05
    assert "were not simulated" in tail_note(tail) and tail_note(simulated["tail"]) == ""
    assert left_out["simulated_s"] < simulated["simulated_s"]  # some of the run was really left out
    assert left_out["coastdown_time_s"] == pytest.approx(simulated["coastdown_time_s"], rel=0.01)
    for a, b in zip(left_out["planes"], simulated["planes"], strict=True):
        for node, value in b["max_temperature_C"].items():
            assert a["max_temperature_C"][node] == pytest.approx(value, abs=tail["temperature_rise_bound_K"])
        # the journal's stored heat still flows into the inner ring in the left-out 0.6 s and closes the internal
        # clearance by a further 3.5 nm (measured); neither run follows that soak past standstill
        assert a["min_internal_clearance_um"] == pytest.approx(b["min_internal_clearance_um"], abs=0.01)
        assert a["damage_per_drop"] == pytest.approx(b["damage_per_drop"], rel=1e-3, abs=0.0)


def test_a_rise_given_in_degc_is_refused_with_the_key():
    from auxbearing.common.errors import InputError

    with pytest.raises(InputError, match=r"tail_temperature_rise.*temperature rise in K"):
        _blower("0.05 degC")
