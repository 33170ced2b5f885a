"""The coast-down's grown speed step against the base one, where it grows: the blower coasting from 3000 rpm.

Below a few thousand rpm the blower's journals roll quietly in their races, the windows measure steady states
and the stretches' speed step doubles (auxbearing.analysis.coastdown_phases.stretch_growth). The reduced model
with its base step is compared with full dynamics in test_coastdown_reduced.py; here the grown one must give
the same coast-down as the base one. Measured: standstill 47.541 s grown, 47.557 s at the base step and
47.718 s in full dynamics (154 s of computing); damage per drop within 0.02 % of the base step's (against
full dynamics -0.19 / -2.03 % either way); peak temperatures within 0.002 K; 102 windows instead of 125.
"""

import copy

import pytest

from auxbearing.analysis import coastdown_phases
from auxbearing.analysis.coastdown import run_coastdown
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping


def _slow_blower():
    data, name, base = machine_table("blower")
    data = copy.deepcopy(data)
    data["rotor"]["speed"] = "3000 rpm"
    data["coastdown"]["drag_torque"] = "0.05 N*m"  # standstill in 48 s instead of about 90 s
    for key in ("criteria", "candidate"):
        data.pop(key, None)
    return machine_from_mapping(data, name, base)


@pytest.mark.slow
def test_a_grown_speed_step_gives_the_coast_down_of_the_base_one(monkeypatch):
    machine = _slow_blower()
    grown = run_coastdown(machine).summary
    monkeypatch.setattr(coastdown_phases, "MAX_GROWTH", 1.0)
    base = run_coastdown(machine).summary
    assert grown["reached_standstill"] and base["reached_standstill"]
    assert grown["reduced_stretches"] < base["reduced_stretches"]  # it did grow
    assert grown["coastdown_time_s"] == pytest.approx(base["coastdown_time_s"], rel=2e-3)
    for g, b in zip(grown["planes"], base["planes"], strict=True):
        assert g["damage_per_drop"] == pytest.approx(b["damage_per_drop"], rel=5e-3)
        for part, temperature in g["max_temperature_C"].items():
            assert temperature == pytest.approx(b["max_temperature_C"][part], abs=0.05)
        assert g["min_internal_clearance_um"] == pytest.approx(b["min_internal_clearance_um"], abs=0.05)
