"""Validation of an elastic rotor resting in its touchdown bearings against the sag of a simply supported beam.

Source: W. C. Young and R. G. Budynas, *Roark's Formulas for Stress and Strain*, 7th ed., McGraw-Hill, 2002,
Table 8.1, case 2e (uniformly distributed load w on a beam simply supported at both ends): the deflection at
mid-span is 5 w L^4 / (384 E I).

Here: a uniform steel shaft 0.6 m long, 40 mm across, given as matrices (24 Euler-Bernoulli elements), dropped
without spin into QJ208 touchdown bearings at both of its ends and left for 1 s to settle. Only its first
free-free bending pair (below 1 kHz) is kept, with the static correction at the two planes (the default
reduction), which carries the rest of the shaft's flexibility under the planes' forces. The sag is the mid-span
node's displacement against the chord through the two journals, which removes the contacts' and ball sets'
compliance. The formula assumes supports at points: the journals' line contacts sit on the end nodes, and the
Hermite-cubic elements are exact at their nodes for this load. Tolerance 0.1 %: measured +0.005 % (5 kHz of
modes with the correction: -0.005 %, 10 kHz: -0.006 %; the modes alone: -1.27 % at 1 kHz, -0.69 % at 5 kHz,
-0.10 % at 10 kHz, the truncation); after 0.3 s the shaft still rocks (-13 %).
"""

import numpy as np
import pytest

from auxbearing.analysis.drop import run_machine
from auxbearing.machine.files import read_machine
from auxbearing.machine.structure import beam_structure

LENGTH, DIAMETER, DENSITY, MODULUS, G = 0.6, 0.04, 7850.0, 2.1e11, 9.80665
MACHINE = """
[machine]
name = "shaft on its touchdown bearings"
[rotor]
matrices = "shaft.npz"
speed = "0 rpm"
max_mode_frequency = "1 kHz"
modal_damping = 0.02
[[touchdown]]
position = "-0.3 m"
bearing = "QJ208"
radial_clearance = "0.15 mm"
[[touchdown]]
position = "0.3 m"
bearing = "QJ208"
radial_clearance = "0.15 mm"
[drop]
duration = "1 s"
"""


@pytest.mark.slow
def test_shaft_resting_on_its_touchdown_bearings_sags_as_roark(tmp_path):
    shaft = beam_structure(np.linspace(-LENGTH / 2, LENGTH / 2, 25), DIAMETER, DENSITY, MODULUS)
    np.savez(tmp_path / "shaft.npz", M=shaft.mass, K=shaft.stiffness, G=shaft.gyroscopic, nodes=shaft.nodes)
    (tmp_path / "shaft.toml").write_text(MACHINE)
    machine = read_machine(tmp_path / "shaft.toml")
    body = machine.modal()
    assert (body.natural, body.residual) == (2, 4)  # one bending pair; x and y at each of the two planes
    run = run_machine(machine)
    assert run.summary["verdict"] == "ok"
    eta = run.dataset["mode"].values[-1]
    y = body.shapes[1::4].T  # each node's y displacement per unit of each mode
    middle = int(np.argmin(np.abs(body.nodes)))
    sag = y[:, middle] @ eta - 0.5 * (y[:, 0] @ eta + y[:, -1] @ eta)
    area, second = np.pi * DIAMETER**2 / 4, np.pi * DIAMETER**4 / 64
    w = DENSITY * area * G
    assert sag == pytest.approx(-5.0 * w * LENGTH**4 / (384.0 * MODULUS * second), rel=1e-3)
