"""Levitated starts the magnetic bearings cannot give, refused before any run, and what a scenario's outcome counts.

Each on the shipped blower (10 kg; radial AMBs at +-100 mm, k_i = 100 N/A, k_s = 2e5 N/m; touchdown planes at
+-150 mm with 0.15 mm radial clearance, the drive end's collar 0.2 mm from its face; a 100 N process thrust on an
axial AMB), edited one key at a time. No drop is integrated here: the refusals come from the machine's statics,
the start offset from the packed initial state and its linearisation.
"""

import copy
import math

import numpy as np
import pytest
import xarray as xr

from auxbearing.analysis.scenario_outcome import late_loads, outcome
from auxbearing.common.errors import InputError
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping
from auxbearing.machine.pack import pack
from auxbearing.machine.stations.amb import read

G0 = 9.80665


def _blower_data():
    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    for key in ("criteria", "candidate"):
        data.pop(key)
    return data, base


def _blower(edit=None, scenario="power loss"):
    """The blower with its data edited by ``edit(data)``, running ``scenario`` (None: no scenario)."""
    data, base = _blower_data()
    if edit is not None:
        edit(data)
    machine = machine_from_mapping(data, "blower", base)
    return machine.with_scenario(scenario) if scenario is not None else machine


def _refusal(edit) -> str:
    with pytest.raises(InputError) as err:
        _blower(edit)
    text = str(err.value)
    assert "\n" not in text
    return text


# --- 6: a controller's static stiffness k_i C(0) - k_s -------------------------------------------------------------

def _controller(**controller):
    return read([{"name": "a", "position": "0 mm", "current_stiffness": "100 N/A", "position_stiffness": "2e5 N/m",
                  "controller": controller}])[0]


@pytest.mark.slow
def test_a_lead_controller_of_dc_gain_1500_is_refused_as_kp_1500_is():
    """C(s) = (12.2387 s + 1500) / (1.5915e-4 s + 1): C(0) = 1500 A/m, k_i C(0) - k_s = 1.5e5 - 2e5 = -5e4 N/m."""
    with pytest.raises(InputError) as err:
        _controller(num=[12.2387, 1500.0], den=[1.5915e-4, 1.0])
    assert str(err.value).startswith("amb.0.controller = {'num': [12.2387, 1500.0], 'den': [0.00015915, 1.0]}: too "
                                     "weak to hold the rotor at rest: its static gain C(0) = 1500 A/m gives k_i "
                                     "C(0) - k_s = -5e+04 N/m"), err.value


def test_a_controller_with_an_unstable_pole_has_a_negative_dc_gain_and_is_refused():
    """C(s) = (s + 2) / (s - 5): C(0) = 2 / -5 = -0.4 A/m, k_i C(0) - k_s = -40 - 2e5 = -200040 N/m."""
    with pytest.raises(InputError) as err:
        _controller(num=[1, 2], den=[1, -5])
    assert "C(0) = -0.4 A/m gives k_i C(0) - k_s = -2e+05 N/m" in str(err.value)


def test_an_integrator_of_negative_gain_is_refused_and_of_positive_gain_accepted():
    """C(s) = -(6000 s + 1e5) / s -> -inf at s -> 0: refused; C(s) = 3000 + 1e5 / s -> +inf: held at rest.

    A lead of DC gain 2500 A/m: k_i C(0) - k_s = 2.5e5 - 2e5 = 5e4 N/m > 0, accepted; its static_gain is 2500.
    """
    with pytest.raises(InputError, match="integrator's gain is negative"):
        _controller(num=[-6000, -1e5], den=[1, 0])
    assert _controller(num=[3000, 1e5], den=[1, 0]).static_gain() == math.inf
    assert _controller(num=[20.0, 2500.0], den=[1.5915e-4, 1.0]).static_gain() == pytest.approx(2500.0, rel=1e-12)


# --- 5: the levitated place inside the touchdown clearance --------------------------------------------------------

def test_a_soft_pd_levitation_sagging_past_the_clearance_is_refused_naming_kp():
    """kp 3000 A/m, no ki: k = 100 x 3000 - 2e5 = 1e5 N/m per bearing; each carries 10 x 9.80665 / 2 = 49.03 N,
    so the rotor sags 49.03 / 1e5 = 0.490 mm at both bearings and both planes (symmetric), past 0.15 mm."""
    def soft(data):
        for amb in data["amb"][:2]:
            amb.update(kp="3000 A/m", ki="0 A/(m*s)")

    line = _refusal(soft)
    assert line.startswith("amb.0.kp = '3000 A/m': the levitated rotor's journal sits 0.49 mm from the centre of "
                           "touchdown.0 (drive end), not inside its radial clearance 0.15 mm"), line
    assert "1e+05 N/m" in line


def test_a_start_offset_past_the_clearance_from_the_levitated_place_is_refused_naming_start_x():
    """PD bearings (kp 6000 A/m, no ki): k = 4e5 N/m, sag 49.03 / 4e5 = 0.1226 mm (down, -y). start_x = 0.1 mm moves
    the journal to hypot(0.1, 0.1226) = 0.158 mm from the centre: past 0.15 mm, though 0.1 mm alone is inside."""
    def pd(data):
        for amb in data["amb"][:2]:
            amb["ki"] = "0 A/(m*s)"
        data["rotor"]["start_x"] = "0.1 mm"

    line = _refusal(pd)
    assert line.startswith("rotor.start_x = '0.1 mm': the levitated start moves the journal from its levitated place "
                           "(0.123 mm from the centre of touchdown.0, drive end) to 0.158 mm"), line


# --- 7: a rigid motion no bearing holds ------------------------------------------------------------------------

def test_one_radial_bearing_under_a_tilting_rotor_is_refused_naming_the_tilt():
    """One radial AMB at -100 mm holds one point of the axis: the rotor pivots about it and the weight's moment
    98.07 N x 0.1 m has nothing to oppose it (the statics' matrix has rank 3 of 4 rigid coordinates)."""
    line = _refusal(lambda data: data["amb"].pop(1))
    assert line.startswith("amb.0.position = '-100 mm': the magnetic bearings do not hold the rotor's tilt about"), line
    assert "two axial positions" in line


def test_two_radial_bearings_at_one_station_are_refused_too():
    line = _refusal(lambda data: data["amb"][1].update(position="-100 mm"))
    assert line.startswith("amb.1.position = '-100 mm': the magnetic bearings do not hold the rotor's tilt"), line


def test_one_bearing_without_a_levitated_start_reports_finite_statics():
    """Without a scenario the bearings fail at the drop: the statics are only reported, as the least-squares ones
    with the loose tilt left out (nanometres, where the regularised solve gave 5.4e12 m)."""
    from auxbearing.machine.stations import of_kind
    from auxbearing.machine.stations.amb import levitated_state

    def one(data):
        data["amb"].pop(1)
        data["scenario"] = []

    machine = _blower(one, scenario=None)
    bearings = of_kind(machine.stations, "amb")
    held = levitated_state(machine, machine.modal(), bearings)
    assert np.all(np.abs(held["q"]) < 1e-8)
    assert max(held["offsets"]) < 1e-8


# --- 8: the magnet's air gap beyond the touchdown clearance ---------------------------------------------------

def _circuit(gap, bias="0.5 A"):
    def edit(data):
        for amb in data["amb"][:2]:
            for key in ("current_stiffness", "position_stiffness"):
                amb.pop(key)
            amb.update(turns=100, pole_area="600 mm^2", air_gap=gap, bias_current=bias, kp="8000 A/m",
                       kd="15 A*s/m")
    return edit


def test_an_air_gap_the_rotor_can_close_inside_the_clearance_is_refused():
    """Both planes allow 0.15 mm; the actuator at -100 mm lies between them (-150, +150 mm), where a rigid rotor
    with both journals at their limits moves (0.15 x 250 + 0.15 x 50) / 300 = 0.15 mm: a 0.1 mm gap closes first."""
    line = _refusal(_circuit("0.1 mm"))
    assert line.startswith("amb.0.air_gap = '0.1 mm': must exceed the 0.15 mm the rotor can move at -100 mm"), line


def test_an_air_gap_beyond_the_clearance_is_accepted():
    """0.4 mm > 0.15 mm, bias 2 A: k = mu0 100^2 6e-4 cos(22.5 deg) / 4 = 1.742e-3 N m^2/A^2, k_i = 4 k i0 / g0^2
    = 87.1 N/A (the 49 N share asks 0.56 A of the 2 A bias)."""
    from auxbearing.machine.stations import of_kind

    machine = _blower(_circuit("0.4 mm", "2 A"))
    b = of_kind(machine.stations, "amb")[0]
    assert b.air_gap == pytest.approx(0.4e-3, rel=1e-12)
    assert b.current_stiffness == pytest.approx(87.09, rel=1e-3)


# --- 1: the axial load a levitated start needs carried ----------------------------------------------------------

def test_process_thrust_without_an_axial_bearing_is_refused_for_a_levitated_start():
    """100 N on 10 kg closes the drive end's 0.2 mm axial clearance in sqrt(2 x 0.2e-3 x 10 / 100) = 6.32 ms."""
    line = _refusal(lambda data: data["amb"].pop(2))
    assert line.startswith("rotor.axial_force = '100 N': a levitated start needs an axial magnetic bearing to carry "
                           "the steady axial load 100 N along +z"), line
    assert "in sqrt(2 c m / F) = 6.32 ms" in line


def test_no_thrust_needs_no_axial_bearing():
    def none(data):
        data["amb"].pop(2)
        data["rotor"]["axial_force"] = "0 N"

    assert _blower(none).rotor.axial_force == 0.0


def _dataset(normal, face):
    t = np.arange(len(normal)) * 1e-3
    return xr.Dataset({"normal_force": (("time", "plane"), np.array(normal, float)[:, None]),
                       "axial_penetration": (("time", "plane"), np.array(face, float)[:, None]),
                       "journal_x": (("time", "plane"), np.zeros((t.size, 1))),
                       "journal_y": (("time", "plane"), np.zeros((t.size, 1))),
                       "ring_x": (("time", "plane"), np.zeros((t.size, 1))),
                       "ring_y": (("time", "plane"), np.zeros((t.size, 1)))}, coords={"time": t})


def test_a_face_contact_is_a_touchdown_of_the_outcome():
    """Journal clear all through, the collar in its face from 3 ms (grid of 1 ms) with the thrust bearing's axis
    lost at 2 ms: first contact 3 ms, after the strike; the axial bearing without power: on the touchdown bearings."""
    data, base = _blower_data()
    data["scenario"] = [{"name": "thrust amplifier", "kind": "axis_loss", "bearing": "thrust AMB", "axis": "z",
                         "time": "2 ms"}]
    machine = machine_from_mapping(data, "blower", base).with_scenario("thrust amplifier")
    ds = _dataset([0.0] * 10, [-1e-5, -1e-5, -1e-6, 1e-6, 2e-6, -1e-7, 1e-6, 1e-6, 1e-6, 1e-6])
    out = outcome(machine, ds, [{}])
    assert out["first_contact_ms"] == pytest.approx(3.0)
    assert out["first_face_contact_ms"] == pytest.approx(3.0)
    assert out["touched_before_strike"] is False
    assert out["outcome"] == "on the touchdown bearings"


def test_without_face_contact_the_outcome_stays_no_touchdown():
    data, base = _blower_data()
    data["scenario"] = [{"name": "thrust amplifier", "kind": "axis_loss", "bearing": "thrust AMB", "axis": "z",
                         "time": "2 ms"}]
    machine = machine_from_mapping(data, "blower", base).with_scenario("thrust amplifier")
    out = outcome(machine, _dataset([0.0] * 10, [-1e-5] * 10), [{}])
    assert out["outcome"] == "no touchdown" and out["first_face_contact_ms"] is None


# --- 9: a start offset from the levitated place ------------------------------------------------------------------

def test_a_start_offset_leaves_the_levitated_linearisation_as_it_is():
    """start_x = 50 um moves the packed start by exactly 50 um in x and changes neither the least damped eigenvalue
    (the blower's -16.47 1/s at 38.76 Hz) nor the orbit: both are the levitated machine's, the offset a disturbance
    added after them. Linearised at the offset, the magnet's open loop sqrt(2 k_s / m) = sqrt(4e4) = +200 1/s read
    as an instability."""
    centred = pack(_blower())
    moved = pack(_blower(lambda data: data["rotor"].update(start_x="50 um")))
    assert moved.y0[0] - centred.y0[0] == pytest.approx(50e-6, abs=1e-15)
    assert np.array_equal(np.delete(moved.y0, 0), np.delete(centred.y0, 0))
    assert moved.orbit[2] == pytest.approx(centred.orbit[2], rel=1e-9)
    assert moved.orbit[2].real == pytest.approx(-16.47, abs=0.01)


# --- 13: a load after the run's end ------------------------------------------------------------------------------

def test_a_load_starting_after_the_run_ends_gets_a_notice():
    """A step of 100 N from 5 s in a run of 5 ms never acts; one from 1 ms does."""
    def loads(data):
        data["load"] = [{"kind": "force", "force": "100 N", "position": "0 mm", "start": "5 s", "shape": "step"},
                        {"kind": "force", "force": "100 N", "position": "0 mm", "start": "1 ms", "shape": "step"}]

    machine = _blower(loads, scenario=None)
    assert late_loads(machine, 5e-3) == ["load.0.start = '5000 ms': not applied: the run ends at 5 ms, before the "
                                         "load 'load 0' starts (lengthen the run or move the load into it)"]
    assert late_loads(machine, 6.0) == []
