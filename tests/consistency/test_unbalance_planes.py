"""Unbalance given per plane (`[[unbalance]]`): the rigid body's static and couple unbalance, and the elastic
modes' forcing.

Self-consistency with linear algebra, not published numbers:

* an elastic shaft (a disk mid-span, 372 and 771 Hz free-free) held by two linear supports, its journals clear
  of the touchdown races, spun at 24 000 rpm with 100 g mm at the disk: after the start has died away its orbit
  at the disk is the linear model's unbalance response, (K - W^2 M + i W (C + W G)) X = F (analysis.modes'
  matrices). Measured: 9.19112 um against 9.19114 um (2.5e-6); the bending carries 15 % of it, so a mode
  left unforced would show;
* two equal unbalances 180 deg apart at +-a on the rigid blower are the couple unbalance chi = 2 U a / (J_t - J_p)
  (the tilted principal axis), and the blower held by two linear supports whirls at its journals as the linear
  model driven by the two point forces.
"""

import copy

import numpy as np
import pytest

from auxbearing.analysis.drop import run_machine
from auxbearing.analysis.modes import linear_matrices, station_rows
from auxbearing.common.errors import InputError
from auxbearing.machine.files import machine_table, read_machine
from auxbearing.machine.model import machine_from_mapping
from auxbearing.machine.structure import beam_structure

SHAFT = """
[machine]
name = "shaft on two supports"
[rotor]
matrices = "shaft.npz"
speed = "24000 rpm"
max_mode_frequency = "2 kHz"
modal_damping = 0.02
[[unbalance]]
position = "0 mm"
amount = "100 g*mm"
phase = "30 deg"
""" + "".join(f"""
[[touchdown]]
position = "{a} mm"
bearing = "QJ208"
radial_clearance = "5 mm"
[[linear_support]]
position = "{a} mm"
kxx = "5e6 N/m"
kyy = "5e6 N/m"
cxx = "2000 N*s/m"
cyy = "2000 N*s/m"
""" for a in (-300, 300)) + """
[drop]
duration = "0.5 s"
"""


@pytest.mark.slow
def test_the_steady_unbalance_response_of_an_elastic_shaft_is_the_linear_one(tmp_path):
    shaft = beam_structure(np.linspace(-0.3, 0.3, 13), 0.04, 7850.0, 2.1e11, disks=[(6, 8.0, 0.03, 0.05)])
    np.savez(tmp_path / "shaft.npz", M=shaft.mass, K=shaft.stiffness, G=shaft.gyroscopic, nodes=shaft.nodes)
    (tmp_path / "m.toml").write_text(SHAFT)
    machine = read_machine(tmp_path / "m.toml")
    run = run_machine(machine)
    assert run.summary["verdict"] == "ok" and run.summary["planes"][0]["impacts"] == 0
    assert abs(run.summary["largest_energy_error"]) < 1e-9  # the unbalance's work on the modes is booked
    ds = run.dataset
    px, py = machine.modal().station_shapes(0.0, "disk")
    x = ds["rotor_x"].values + ds["mode"].values @ px
    y = ds["rotor_y"].values + ds["mode"].values @ py
    late = ds["time"].values > 0.45
    w = machine.rotor.speed
    mass, damping, gyro, stiffness, _ = linear_matrices(machine, "free")
    bx, by = station_rows(machine, 0.0, "disk")
    _, amount, phase = machine.rotor.unbalance_planes[0]
    response = np.linalg.solve(stiffness - w * w * mass + 1j * w * (damping + w * gyro),
                               amount * w * w * np.exp(1j * phase) * (bx - 1j * by))
    assert 0.5 * np.ptp(x[late]) == pytest.approx(abs(bx @ response), rel=1e-4)
    assert 0.5 * np.ptp(y[late]) == pytest.approx(abs(by @ response), rel=1e-4)
    assert abs(response[4:] @ px) > 0.1 * abs(bx @ response)  # the bending's share is no rounding


def _blower(**rotor):
    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    for key in ("criteria", "candidate", "amb", "scenario"):
        data.pop(key)
    data["rotor"].pop("unbalance")
    data["rotor"].pop("unbalance_phase")
    data["rotor"].update(rotor)
    data["drop"]["duration"] = "0.03 s"
    return data, base


def test_opposed_unbalance_planes_are_the_couple_unbalance():
    data, base = _blower()
    data["unbalance"] = [{"position": "150 mm", "amount": "20 g*mm", "phase": "0 deg"},
                         {"position": "-150 mm", "amount": "20 g*mm", "phase": "180 deg"}]
    data["drop"]["duration"] = "0.15 s"
    for plane in data["touchdown"]:
        plane.update(radial_clearance="5 mm")
        plane.pop("axial_clearance", None)
    data["linear_support"] = [{"position": f"{a} mm", "kxx": "5e6 N/m", "kyy": "5e6 N/m", "cxx": "2000 N*s/m",
                               "cyy": "2000 N*s/m"} for a in (-150, 150)]
    machine = machine_from_mapping(data, "blower", base)
    r = machine.rotor
    assert r.unbalance == 0.0
    assert r.couple_unbalance == pytest.approx(2 * 20e-6 * 0.15 / (0.2 - 0.015), rel=1e-12)
    # the kernel's tilted principal axis whirls the journals as the two point forces +-U W^2 of the linear model
    run = run_machine(machine)
    assert run.summary["verdict"] == "ok" and run.summary["planes"][0]["impacts"] == 0
    ds = run.dataset
    late = ds["time"].values > 0.12
    w = r.speed
    mass, damping, gyro, stiffness, _ = linear_matrices(machine, "free")
    force = np.zeros(4, complex)
    for a, amount, phase in r.unbalance_planes:
        bx, by = station_rows(machine, a, "plane")
        force += amount * w * w * np.exp(1j * phase) * (bx - 1j * by)
    response = np.linalg.solve(stiffness - w * w * mass + 1j * w * (damping + w * gyro), force)
    for k, a in enumerate((-0.15, 0.15)):
        bx, by = station_rows(machine, a, "plane")
        journal = ds["journal_x"].values[late, k]
        assert 0.5 * np.ptp(journal) == pytest.approx(abs(bx @ response), rel=1e-3)


@pytest.mark.parametrize(("change", "expected"), [
    ({"rotor": {"unbalance": "3 um"}}, "rotor.unbalance = '3 um': comes from the [[unbalance]] planes"),
    ({"unbalance": [{"position": "0 mm"}]}, "unbalance.0.amount: missing"),
    ({"unbalance": [{"position": "0 mm", "amount": "5 mm"}]}, "unbalance.0.amount = '5 mm'"),
    ({"unbalance": {"position": "0 mm"}}, "unbalance = "),
])
def test_bad_unbalance_planes_name_the_key(change, expected):
    data, base = _blower()
    data["unbalance"] = [{"position": "0 mm", "amount": "10 g*mm"}]
    for key, value in change.items():
        if key == "rotor":
            data["rotor"].update(value)
        else:
            data[key] = value
    with pytest.raises(InputError) as err:
        machine_from_mapping(data, "blower", base)
    assert str(err.value).startswith(expected), str(err.value)
    assert "\n" not in str(err.value)
