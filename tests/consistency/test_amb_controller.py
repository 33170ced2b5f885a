"""A magnetic bearing under a controller of its own (`[[amb]] controller`, a transfer function or state space read
by python-control) against the linear frequency response of the same loop.

The controller is a lead-lag with integral action, C(s) = k_p (1 + s / w_z) / (1 + s / w_p) + k_int / s, from the
sensor's reading to the current (i = -C(s) x), realised as a state space of order two at the boundary. Levitated at
18 000 rpm with its 3 um unbalance, the blower's orbit settles to m e W^2 / |2 k(iW) - m W^2| with each bearing's
dynamic stiffness k(s) = k_i G_a(s) G_s(s) C(s) - k_s (Schweitzer & Maslen 2009, the decentralised loop), as
for the PID of tests/consistency/test_amb.py; the levitated start has the sensors at zero (integral action).
"""

import copy
import functools
import math

import numpy as np
import pytest

from auxbearing.analysis.drop import run_machine
from auxbearing.common.errors import InputError
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping

KP, WZ, WP, KINT = 6000.0, 2 * math.pi * 60.0, 2 * math.pi * 600.0, 1e5


# python-control (with scipy.signal) takes about a second to import: built when a test runs, not at collection,
# so that the quick loop's workers do not pay for it
@functools.cache
def _lead_lag():
    import control

    return control.tf([KP / WZ, KP], [1 / WP, 1]) + control.tf([KINT], [1, 0])


def _discrete_first_order():
    import control

    return control.tf([1.0], [1.0, 1.0], 1e-3)


def _blower(controller, **rotor):
    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    for key in ("criteria", "candidate"):
        data.pop(key)
    data["rotor"].update(axial_force="0 N", **rotor)
    data["scenario"] = [{"name": "held", "kind": "power_loss", "time": "10 s"}]
    for amb in data["amb"]:
        for key in ("kp", "ki", "kd"):
            amb.pop(key)
        amb["controller"] = controller
    return machine_from_mapping(data, "blower", base).with_scenario("held")


def test_the_levitated_orbit_under_a_lead_lag_is_the_linear_response():
    machine = _blower(_lead_lag()).with_simulation(duration=0.3)
    bearing = machine.stations[0]
    assert bearing.order == 2
    run = run_machine(machine)
    s = run.summary
    assert s["verdict"] == "ok" and s["planes"][0]["impacts"] == 0
    assert abs(s["energy_balance_error"]) < 1e-6
    # integral action: the readings at zero, each bearing's current carrying half the weight
    assert s["amb"][0]["levitated_offset_um"] == pytest.approx(0.0, abs=1e-3)  # measured 1.6e-6 um
    assert s["amb"][0]["levitated_current_A"] == pytest.approx(10.0 * 9.80665 / 2 / 100.0, rel=1e-9)
    late = run.dataset.time.values > 0.25
    x = run.dataset.rotor_x.values[late]
    w = machine.rotor.speed
    m, e = machine.rotor.mass, machine.rotor.unbalance
    expected = abs(m * e * w * w / (2 * bearing.dynamic_stiffness(1j * w) - m * w * w))
    # measured +0.04 %: the integral's slow pole has not quite died away by 0.25 s
    assert 0.5 * np.ptp(x) == pytest.approx(expected, rel=2e-3)


def test_the_same_controller_from_a_table_of_coefficients():
    import control

    lead_lag = _lead_lag()
    num, den = (np.asarray(v, float).ravel().tolist() for v in control.tfdata(lead_lag)[:2])
    table = _blower({"num": num, "den": den}).stations[0]
    assert table.transfer(2j * math.pi * 300) == pytest.approx(complex(lead_lag(2j * math.pi * 300)), rel=1e-9)


@pytest.mark.parametrize(("controller", "expected"), [
    ({"num": [5.0, 6000.0, 1e5], "den": [1.0, 0.0]}, "amb.0.controller = {'num': [5.0, 6000.0, 100000.0], 'den': "
                                                       "[1.0, 0.0]}: must be proper"),
    ({"num": [1.0]}, "amb.0.controller = {'num': [1.0]}: give {num"),
    (_discrete_first_order, "amb.0.controller = "),
    ({"num": [6000.0], "den": [1.0]}, "amb.0.controller = {'num': [6000.0], 'den': [1.0]}: is a pure gain"),
    ({"A": [[0.0]], "B": [[1.0]], "C": [[float("nan")]], "D": [[0.0]]}, "amb.0.controller = "),
])
def test_a_bad_controller_names_the_key(controller, expected):
    with pytest.raises(InputError) as err:
        _blower(controller if isinstance(controller, dict) else controller())  # a factory: built when run
    assert str(err.value).startswith(expected), str(err.value)


def test_a_controller_and_pid_gains_together_are_refused():
    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    data["amb"][0]["controller"] = {"num": [1.0], "den": [1.0, 1.0]}
    with pytest.raises(InputError, match=r"^amb.0.kp = '6000 A/m': give either the PID's gains or a controller"):
        machine_from_mapping(data, "blower", base)
