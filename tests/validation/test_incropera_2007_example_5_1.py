"""Validation of the lumped thermal network against Incropera et al.'s Example 5.1.

Source: Incropera, DeWitt, Bergman & Lavine, Fundamentals of Heat and Mass Transfer, 6th ed., Wiley
(2007), Example 5.1: a thermocouple junction (sphere; h = 400 W/(m^2 K), rho = 8500 kg/m^3,
c = 400 J/(kg K)) with a 1 s time constant has D = 0.706 mm and takes 5.2 s to go from 25 degC to
199 degC in a 200 degC gas.

Tolerance: the book prints the time to two significant figures and the diameter to three: 0.05 s and
0.0005 mm.
"""

import math

import numpy as np
import pytest

from auxbearing.core import thermal


def test_incropera_example_5_1_thermocouple():
    h, rho, c, tau = 400.0, 8500.0, 400.0, 1.0
    diameter = 6.0 * h * tau / (rho * c)  # tau = rho V c / (h A_s), V/A_s = D/6 for a sphere
    assert diameter * 1e3 == pytest.approx(0.706, abs=5e-4)
    area, volume = math.pi * diameter**2, math.pi * diameter**3 / 6.0
    cap, cond = np.array([rho * c * volume]), np.array([h * area])
    gas, start, target = 473.15, 298.15, 472.15
    rates, modes, root = thermal.decompose(cap, np.zeros((1, 1)), cond)

    def temperature(t):
        return thermal.step_decomposed(np.array([start]), np.zeros(1), gas, t, rates, modes, root)[0][0]

    lo, hi = 0.0, 20.0  # bisection on the network's own step: no closed form of ours is used
    for _ in range(80):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if temperature(mid) < target else (lo, mid)
    assert lo == pytest.approx(5.2, abs=0.05)
