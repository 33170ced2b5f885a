"""The magnetic bearing's force from its magnetic circuit against its linearisation (`[[amb]]` turns, pole_area,
air_gap, bias_current; kernel :func:`auxbearing.core.amb.magnet_force`).

Schweitzer & Maslen 2009, Ch. 2: a pair of opposed magnets in differential driving pulls with
F = k [(i0 + i)^2 / (g0 - u)^2 - (i0 - i)^2 / (g0 + u)^2], k = mu0 N^2 A cos(alpha) / 4. Its slopes at the bias
are the linearised law's k_i = 4 k i0 / g0^2 and k_s = 4 k i0^2 / g0^3; along u = 0 it is linear in i; the even
terms cancel, so it departs from the linear law by O((u / g0)^2) only, which a levitated unbalance orbit of a few
micrometres in a half-millimetre gap does not see.
"""

import copy
import math

import numpy as np
import pytest

from auxbearing.analysis.drop import run_machine
from auxbearing.common.errors import InputError
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping
from auxbearing.machine.stations.amb import MU0

#: Close to the blower's own linearised bearings: k_i = 99.98 N/A, k_s = 2.0e5 N/m.
CIRCUIT = {"turns": 232, "pole_area": "400 mm^2", "air_gap": "0.5 mm", "bias_current": "1 A"}


def _blower(circuit: dict | None):
    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    for key in ("criteria", "candidate"):
        data.pop(key)
    data["rotor"]["axial_force"] = "0 N"
    data["scenario"] = [{"name": "held", "kind": "power_loss", "time": "10 s"}]
    for amb in data["amb"]:
        amb.pop("max_current")
        if circuit is not None:
            amb.pop("current_stiffness")
            amb.pop("position_stiffness")
            amb.update(circuit)
        else:
            amb.update(_slopes())
    return machine_from_mapping(data, "blower", base).with_scenario("held")


def _slopes() -> dict:
    k = MU0 * 232 ** 2 * 400e-6 * math.cos(math.pi / 8) / 4
    return {"current_stiffness": f"{4 * k / 0.5e-3 ** 2!r} N/A", "position_stiffness": f"{4 * k / 0.5e-3 ** 3!r} N/m"}


def test_the_circuit_law_has_the_slopes_of_the_linearised_one():
    bearing = _blower(CIRCUIT).stations[0]
    assert bearing.circuit
    assert bearing.current_stiffness == pytest.approx(4 * bearing.circuit_constant() / 0.5e-3 ** 2, rel=1e-12)
    h, d = 1e-6, 1e-9
    slope_i = (bearing.force(h, 0.0) - bearing.force(-h, 0.0)) / (2 * h)
    slope_u = (bearing.force(0.0, d) - bearing.force(0.0, -d)) / (2 * d)
    assert slope_i == pytest.approx(bearing.current_stiffness, rel=1e-9)
    assert slope_u == pytest.approx(bearing.position_stiffness, rel=1e-6)
    # linear in the current on the axis, odd in (i, u) together, and stronger than linear away from it
    assert bearing.force(1.0, 0.0) == pytest.approx(bearing.current_stiffness, rel=1e-12)
    assert bearing.force(0.7, 20e-6) == pytest.approx(-bearing.force(-0.7, -20e-6), rel=1e-12)
    assert bearing.force(0.0, 0.25e-3) > bearing.position_stiffness * 0.25e-3
    assert bearing.current_limit() == 1.0  # no limit given: the bias (each coil's current stays positive)


def test_a_levitated_orbit_of_micrometres_does_not_see_the_nonlinearity():
    circuit = run_machine(_blower(CIRCUIT).with_simulation(duration=0.1))
    linear = run_machine(_blower(None).with_simulation(duration=0.1))
    assert circuit.summary["planes"][0]["impacts"] == 0
    assert abs(circuit.summary["energy_balance_error"]) < 1e-6
    x, x_linear = circuit.dataset.rotor_x.values, linear.dataset.rotor_x.values
    late = circuit.dataset.time.values > 0.05
    assert np.ptp(x[late]) > 2e-6  # the unbalance orbit
    # measured: the orbits differ by a few 1e-5 of their size ((u / g0)^2 ~ 1e-4)
    assert np.max(np.abs(x - x_linear)) < 1e-3 * np.max(np.abs(x_linear))


@pytest.mark.parametrize(("change", "expected"), [
    ({"turns": 120}, "amb.0.pole_area: missing; the magnetic circuit needs turns, pole_area, air_gap, bias_current"),
    ({**CIRCUIT, "current_stiffness": "100 N/A"}, "amb.0.current_stiffness = '100 N/A': give either"),
    ({"pole_angle": "20 deg"}, "amb.0.pole_angle = '20 deg': belongs to the magnetic circuit"),
    ({**CIRCUIT, "turns": 12.5}, "amb.0.turns = 12.5: must be a whole number"),
])
def test_a_half_given_circuit_names_the_key(change, expected):
    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    data["amb"][0].update(change)
    if "turns" in change:
        for key in ("current_stiffness", "position_stiffness"):
            if key not in change:
                data["amb"][0].pop(key)
    with pytest.raises(InputError) as err:
        machine_from_mapping(data, "blower", base)
    assert str(err.value).startswith(expected), str(err.value)
