"""The failure and overload scenarios of a levitated machine (`[[scenario]]`, `[[load]]`) against closed forms.

On the blower held by two identical magnetic bearings at +-100 mm (Schweitzer & Maslen 2009's linear force law
and PID, :mod:`auxbearing.core.amb`; the loads of :mod:`auxbearing.core.load`):

* a short half-sine shock gives the rotor its impulse, m dv = 2 F T / pi (Newton's second law over the pulse);
* the base accelerating downward by g / 2 halves the gravity the rotor feels in the housing's frame: the PD
  bearings' static sag m g / (2 (k_i k_p - k_s)) halves;
* a blade lost at the drop, an unbalance U = m e appearing at the mass centre, moves the journal exactly as
  the rotor's own static unbalance e does (the same equation of the geometric centre, m O'' = F + m e W^2 u);
* one axis lost drops only its end; the power back after a loss lifts the rotor off its touchdown bearings;
* every run's energy audit closes (the loads' work booked as taken).
"""

import copy
import math

import numpy as np
import pytest

from auxbearing.analysis.drop import run_machine
from auxbearing.common.errors import InputError
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping

#: the quick loop leaves this module to `make test` (its share of the loop's time against what it guards)
pytestmark = pytest.mark.slow

KI, KS, KP, KD = 100.0, 2e5, 6000.0, 12.0
G0 = 9.80665


def _blower(scenario=None, loads=None, integral=True, ideal=False, **rotor):
    """The blower with its two AMBs (with or without integral action) and one scenario."""
    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    for key in ("criteria", "candidate"):
        data.pop(key)
    data["rotor"].update(rotor)
    for amb in data["amb"]:
        if not integral:
            amb.pop("ki")
        if ideal:
            amb.update(sensor_bandwidth="1 MHz", amplifier_bandwidth="1 MHz")
    data["scenario"] = [scenario] if scenario is not None else []
    if loads is not None:
        data["load"] = loads
    machine = machine_from_mapping(data, "blower", base)
    return machine.with_scenario(scenario["name"]) if scenario is not None else machine


HELD = {"name": "held", "kind": "power_loss", "time": "10 s"}
QUIET = {"speed": "0 rpm", "unbalance": "0 um", "axial_force": "0 N"}


def _audit(summary):
    assert abs(summary["energy_balance_error"]) < 1e-6


def test_a_short_shock_gives_the_rotor_its_impulse():
    force, pulse, mass = 200.0, 2e-4, 10.0
    shock = {"name": "knock", "kind": "shock", "time": "5 ms", "position": "0 mm", "force": f"{force} N",
             "direction": "0 deg", "duration": f"{pulse * 1e3} ms"}
    run = run_machine(_blower(shock, **QUIET).with_simulation(duration=0.006))
    _audit(run.summary)
    ds = run.dataset
    t, vx = ds.time.values, ds.rotor_vx.values
    before, after = np.argmin(abs(t - 0.005)), np.argmin(abs(t - 0.005 - pulse))
    # the bearings push back over the pulse too (their damping: -0.43 % of the shock's impulse), with their
    # recorded currents; the rotor, pushed at its mass centre between two equal bearings, does not tilt
    span = slice(before, after + 1)
    radial = run.dataset.amb_axis.values == "radial"
    bearings = (KI * run.dataset.amb_current_x.values[span][:, radial].sum(axis=1) + 2 * KS * ds.rotor_x.values[span])
    impulse = 2 * force * pulse / math.pi + np.trapezoid(bearings, t[span])
    assert mass * (vx[after] - vx[before]) == pytest.approx(impulse, rel=1e-3)
    assert abs(ds.tilt_y.values).max() < 1e-12
    assert run.summary["scenario"]["outcome"] == "no touchdown"


def test_the_base_falling_at_half_g_halves_the_weight_the_bearings_carry():
    base = [{"name": "fall", "kind": "base_acceleration", "acceleration": f"{G0 / 2} m/s^2", "direction": "-90 deg",
             "start": "5 ms", "shape": "step"}]
    run = run_machine(_blower(HELD, loads=base, integral=False, ideal=True, **QUIET).with_simulation(duration=0.2))
    _audit(run.summary)
    sag = 10.0 * G0 / (2 * (KI * KP - KS))
    y = run.dataset.rotor_y.values
    assert y[0] == pytest.approx(-sag, rel=1e-9)
    assert y[-1] == pytest.approx(-sag / 2, rel=1e-4)  # after 39 time constants of the 50 1/s decay


def test_a_blade_lost_at_the_start_moves_the_journal_as_the_rotors_own_unbalance():
    own = run_machine(_blower(HELD, axial_force="0 N").with_simulation(duration=0.03))
    lost = {"name": "blade", "kind": "unbalance_step", "time": "0 ms", "position": "0 mm", "amount": "30 g*mm"}
    blade = run_machine(_blower(lost, axial_force="0 N", unbalance="0 um").with_simulation(duration=0.03))
    _audit(blade.summary)
    x, x_blade = own.dataset.rotor_x.values, blade.dataset.rotor_x.values
    # equal to the integration's tolerance (measured 8.5e-7 of the orbit: the two runs take their own steps; the
    # unbalance's Omega' term the load leaves out is 1e-10 of its force here)
    assert np.max(np.abs(x_blade - x)) < 1e-5 * np.max(np.abs(x))
    assert np.max(np.abs(x)) > 1e-6


def test_losing_one_axis_drops_that_end_and_the_other_bearing_holds():
    loss = {"name": "de y", "kind": "axis_loss", "bearing": "drive-end AMB", "axis": "y", "time": "5 ms"}
    run = run_machine(_blower(loss).with_simulation(duration=0.04))
    s = run.summary
    _audit(s)
    assert s["planes"][0]["impacts"] > 0 and s["planes"][1]["impacts"] == 0
    assert s["scenario"]["outcome"] == "on the touchdown bearings"
    current = run.dataset.amb_current_y.values
    assert current[-1, 1] > 1.2 * current[0, 1]  # the non-drive end takes a larger share of the weight


def test_the_power_back_after_a_loss_lifts_the_rotor_off_its_touchdown_bearings():
    loss = {"name": "blackout", "kind": "power_loss", "time": "5 ms", "decay_time": "1 ms", "restore_time": "20 ms",
            "relevitate_within": "100 ms"}
    run = run_machine(_blower(loss).with_simulation(duration=0.15))
    s = run.summary
    _audit(s)
    out = s["scenario"]
    assert out["outcome"] == "re-levitated", out
    assert 5.0 < out["first_contact_ms"] < out["relevitated_at_ms"] < 120.0


def test_a_sensor_reading_zero_lets_the_bias_pull_the_rotor_down():
    failure = {"name": "sensor", "kind": "sensor_failure", "bearing": "drive-end AMB", "time": "5 ms"}
    run = run_machine(_blower(failure).with_simulation(duration=0.06))
    s = run.summary
    _audit(s)
    assert s["scenario"]["first_contact_ms"] > 5.0
    assert s["scenario"]["outcome"] not in ("no touchdown", "re-levitated", "on the touchdown bearings")


@pytest.mark.parametrize(("scenario", "loads", "expected"), [
    ({"name": "s", "kind": "meteor"}, None, "scenario.0.kind = 'meteor': must be one of power_loss, axis_loss"),
    ({"name": "s", "kind": "axis_loss", "axis": "x"}, None, "scenario.0.bearing = None: name one of the [[amb]]"),
    ({"name": "s", "kind": "axis_loss", "bearing": "drive-end AMB"}, None, "scenario.0.axis = None: must be one of"),
    ({"name": "s", "kind": "sensor_failure", "bearing": "drive-end AMB", "mode": "jammed"}, None,
     "scenario.0.mode = 'jammed': must be one of stuck, zero"),
    ({"name": "s", "kind": "power_loss", "force": "10 N"}, None, "scenario.0.force = '10 N': not a key of a "
                                                                   "power_loss scenario"),
    ({"name": "s", "kind": "shock", "position": "0 mm"}, None, "scenario.0.force: missing"),
    ({"name": "s", "kind": "shock", "force": "10 N", "position": "0 mm"}, None, "scenario.0.duration: missing"),
    ({"name": "s", "kind": "step_load", "force": "10 N", "position": "0 mm", "shape": "square"}, None,
     "scenario.0.shape = 'square': must be one of step, half_sine"),
    ({"name": "s", "kind": "power_loss", "restore_time": "0 ms"}, None,
     "scenario.0.restore_time = '0 ms': must be > 0"),
    (None, [{"kind": "force", "force": "10 N"}], "load.0.position: missing"),
    (None, [{"kind": "unbalance", "position": "0 mm", "amount": "1 g*mm", "acceleration": "1 m/s^2"}],
     "load.0.acceleration = '1 m/s^2': not a key of an unbalance load"),
    (None, [{"kind": "base_acceleration", "acceleration": "-1 m/s^2", "duration": "1 ms"}],
     "load.0.acceleration = '-1 m/s^2': must be >= 0"),
])
def test_bad_scenarios_and_loads_name_the_key(scenario, loads, expected):
    with pytest.raises(InputError) as err:
        _blower(scenario, loads=loads)
    assert str(err.value).startswith(expected), str(err.value)


def test_the_amplifiers_voltage_limits_the_currents_rate():
    data_shock = {"name": "knock", "kind": "shock", "time": "5 ms", "position": "0 mm", "force": "300 N",
                  "duration": "2 ms"}
    machine = _blower(data_shock)
    slow = machine_from_mapping(*_knock(max_voltage="4 V", coil_inductance="40 mH")).with_scenario("knock")
    run = run_machine(slow.with_simulation(duration=0.012))
    _audit(run.summary)
    t = run.dataset.time.values
    rate = np.abs(np.diff(run.dataset.amb_current_y.values[:, :2], axis=0)) / np.diff(t)[:, None]
    # U / L = 4 V / 40 mH; on the output grid the dense output rounds the kink where the limit engages (+1.0 %)
    assert rate.max() <= 100.0 * 1.02
    assert rate.max() >= 0.99 * 100.0  # and the shock asks for more
    fast = run_machine(machine.with_simulation(duration=0.012))
    fast_rate = np.abs(np.diff(fast.dataset.amb_current_y.values[:, :2], axis=0)) / np.diff(t)[:, None]
    assert fast_rate.max() > 3 * 100.0  # measured 549 A/s without the limit


def _knock(**amb_keys):
    """The blower's tables with a 300 N, 2 ms shock at 5 ms and ``amb_keys`` on every magnetic bearing."""
    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    for key in ("criteria", "candidate"):
        data.pop(key)
    for amb in data["amb"]:
        amb.update(amb_keys)
    data["scenario"] = [{"name": "knock", "kind": "shock", "time": "5 ms", "position": "0 mm", "force": "300 N",
                         "duration": "2 ms"}]
    return data, "blower", base


def test_a_ride_through_is_the_power_loss_it_delays():
    delayed = {"name": "dip", "kind": "power_loss", "time": "5 ms", "ride_through": "10 ms", "decay_time": "2 ms"}
    later = {"name": "dip", "kind": "power_loss", "time": "15 ms", "decay_time": "2 ms"}
    a = run_machine(_blower(delayed).with_simulation(duration=0.05)).summary
    b = run_machine(_blower(later).with_simulation(duration=0.05)).summary
    assert a["steps"] == b["steps"]
    assert [p["peak_contact_force_N"] for p in a["planes"]] == [p["peak_contact_force_N"] for p in b["planes"]]
    assert a["scenario"]["ride_through_ms"] == 10.0 and a["scenario"]["time_ms"] == 5.0
    # the power back before the amplifiers stop: nothing fails
    back = {**delayed, "restore_time": "8 ms"}
    assert run_machine(_blower(back).with_simulation(duration=0.05)).summary["scenario"]["outcome"] == "no touchdown"


def test_the_bearings_load_capacity_caps_their_force():
    data, name, base = _knock()
    for amb in data["amb"]:
        amb["load_capacity"] = "80 N"
    run = run_machine(machine_from_mapping(data, name, base).with_scenario("knock").with_simulation(duration=0.012))
    _audit(run.summary)
    force = np.hypot(run.dataset.amb_force_x.values[:, :2], run.dataset.amb_force_y.values[:, :2])
    assert np.abs(run.dataset.amb_force_y.values[:, :2]).max() == pytest.approx(80.0, rel=1e-9)
    assert force.max() <= 80.0 * math.sqrt(2) * (1 + 1e-9)


def test_a_pid_with_a_derivative_filter_levitates_on_its_linear_response():
    data, name, base = _knock()
    for amb in data["amb"]:
        amb["derivative_bandwidth"] = "300 Hz"
    data["rotor"]["axial_force"] = "0 N"
    data["scenario"] = [HELD]
    machine = machine_from_mapping(data, name, base).with_scenario("held").with_simulation(duration=0.3)
    bearing = machine.stations[0]
    wf = 2 * math.pi * 300
    assert bearing.transfer(1j * 1000) == pytest.approx(KP + 1e5 / 1000j + KD * 1000j / (1 + 1000j / wf), rel=1e-9)
    run = run_machine(machine)
    assert run.summary["planes"][0]["impacts"] == 0
    x = run.dataset.rotor_x.values[run.dataset.time.values > 0.25]
    w, m, e = machine.rotor.speed, machine.rotor.mass, machine.rotor.unbalance
    assert 0.5 * np.ptp(x) == pytest.approx(abs(m * e * w * w / (2 * bearing.dynamic_stiffness(1j * w) - m * w * w)),
                                            rel=2e-3)


def test_the_thrust_bearing_carries_the_process_thrust_until_the_power_fails():
    run = run_machine(_blower({"name": "off", "kind": "power_loss", "time": "10 ms"}).with_simulation(duration=0.04))
    s = run.summary
    _audit(s)
    thrust = next(a for a in s["amb"] if a["axis"] == "axial")
    # integral action: held at its place, its current balancing the 100 N thrust, i = -F / k_i
    assert thrust["levitated_offset_um"] == pytest.approx(0.0, abs=1e-3)
    assert run.dataset.amb_current_z.values[0, 2] == pytest.approx(-100.0 / 150.0, rel=1e-9)
    assert np.isnan(run.dataset.amb_current_x.values[:, 2]).all()  # an axis it has not
    assert abs(run.dataset.rotor_z.values[run.dataset.time.values < 0.01]).max() < 1e-9
    assert s["planes"][0]["peak_axial_force_N"] > 100.0  # then the thrust drives the collar onto the race


def test_a_pd_thrust_bearing_gives_way_by_the_thrust_over_its_stiffness():
    data, name, base = _knock()
    data["amb"][2].pop("ki")
    data["scenario"] = [HELD]
    machine = machine_from_mapping(data, name, base).with_scenario("held")
    run = run_machine(machine.with_simulation(duration=0.01))
    # F = 100 N against k_i k_p - k_s = 150 * 6000 - 3e5 = 6e5 N/m: 166.7 um, within the 200 um collar clearance
    assert run.dataset.rotor_z.values[0] == pytest.approx(100.0 / 6e5, rel=1e-9)
    assert run.summary["planes"][0]["peak_axial_force_N"] == 0.0


@pytest.mark.parametrize(("change", "expected"), [
    ({"sensor_position": "10 mm"}, "amb.2.sensor_position = '10 mm': an axial bearing reads the rotor's axial"),
    ({"axis": "diagonal"}, "amb.2.axis = 'diagonal': must be one of radial, axial"),
])
def test_a_bad_thrust_bearing_names_the_key(change, expected):
    data, name, base = _knock()
    data["amb"][2].update(change)
    with pytest.raises(InputError) as err:
        machine_from_mapping(data, name, base)
    assert str(err.value).startswith(expected), str(err.value)


def test_a_thrust_bearing_needs_a_rotor_that_moves_axially():
    data, name, base = _knock()
    data["touchdown"][0].pop("axial_clearance")
    with pytest.raises(InputError, match=r"^amb.2.axis = 'axial': needs a rotor that moves axially"):
        machine_from_mapping(data, name, base)


def test_a_thrust_bearing_loses_its_z_axis_only():
    loss = {"name": "z", "kind": "axis_loss", "bearing": "thrust AMB", "time": "5 ms"}
    run = run_machine(_blower(loss).with_simulation(duration=0.03))
    assert run.summary["scenario"]["axis"] == "z"
    assert run.summary["planes"][0]["peak_axial_force_N"] > 100.0
    assert run.summary["planes"][0]["impacts"] == 0  # the radial bearings hold on
    with pytest.raises(InputError, match=r"^scenario.0.axis = 'x': must be one of z"):
        _blower({**loss, "axis": "x"})


def test_the_coil_voltage_is_its_inductance_times_the_currents_rate():
    data, name, base = _knock(max_voltage="4 V", coil_inductance="40 mH")
    run = run_machine(machine_from_mapping(data, name, base).with_scenario("knock").with_simulation(duration=0.012))
    voltage = run.dataset.amb_voltage_y.values
    assert run.dataset.amb_voltage_y.attrs["units"] == "V"
    # the current's rate is held at U / L, so the inductive voltage reaches the supply's 4 V and no more
    assert np.nanmax(np.abs(voltage)) == pytest.approx(4.0, rel=2e-2)  # the same rounded kink: +0.5 %
