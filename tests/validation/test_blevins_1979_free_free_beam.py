"""Validation of the rotor-as-matrices path against the free-free uniform beam's bending frequencies.

Source: R. D. Blevins, *Formulas for Natural Frequency and Mode Shape*, Van Nostrand Reinhold, 1979, Table 8-1
(single-span beams, free-free): omega_i = (beta_i L)^2 / L^2 sqrt(E I / (rho A)) with (beta L)^2 = 22.3733,
61.6728, 120.9034 for the first three bending modes; each appears twice in a rotor (x and y).

Here: a steel shaft 1 m long, 20 mm across, in 40 Euler-Bernoulli elements without rotary inertia (the
beam Blevins tabulates), through :func:`auxbearing.machine.structure.modal_rotor`, which also separates
the four rigid motions. Tolerance 1e-4: the discretisation error of 40 cubic elements on the third mode is
below 1e-5 (measured: 22.37329, 61.67289, 120.90387); the table gives five to six digits.
"""

import math

import numpy as np
import pytest

from auxbearing.machine.structure import beam_structure, modal_rotor

BETA_L_SQUARED = (22.3733, 61.6728, 120.9034)


def test_free_free_beam_bends_at_blevins_frequencies():
    length, diameter, density, modulus = 1.0, 0.02, 7850.0, 2.1e11
    shaft = beam_structure(np.linspace(0.0, length, 41), diameter, density, modulus, rotary_inertia=False)
    body = modal_rotor(shaft, max_frequency=1e6)
    area, second = math.pi * diameter**2 / 4.0, math.pi * diameter**4 / 64.0
    scale = math.sqrt(modulus * second / (density * area)) / length**2
    for i, value in enumerate(BETA_L_SQUARED):
        for twin in (2 * i, 2 * i + 1):
            assert body.frequencies[twin] / scale == pytest.approx(value, rel=1e-4)
    # the rigid body the drop integrates: the beam's mass and its transverse inertia about the middle
    assert body.mass == pytest.approx(density * area * length, rel=1e-12)
    assert body.transverse_inertia == pytest.approx(density * area * length**3 / 12.0, rel=1e-12)
    assert body.centre == pytest.approx(0.5 * length, rel=1e-12)
