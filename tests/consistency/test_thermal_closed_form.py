"""Validation of the lumped thermal network against closed-form solutions and a textbook example.

Sources:

* Incropera, DeWitt, Bergman & Lavine, *Fundamentals of Heat and Mass Transfer*, 6th ed. (2007),
  Sec. 5.1-5.3 (lumped capacitance). One body of capacity C losing heat to ambient through a
  conductance G and receiving a constant heat input Q obeys C dtheta/dt = Q - G theta, so from
  theta(0) = theta_0: theta(t) = Q/G + (theta_0 - Q/G) exp(-t G / C). Closed form, so the tolerance
  is round-off: 1e-9 relative.
* Two bodies, the textbook energy balance written for each (Sec. 5.3) and solved here by hand:
      C1 theta1' = Q1 - G12 (theta1 - theta2) - Ga1 theta1
      C2 theta2' = Q2 - G12 (theta2 - theta1) - Ga2 theta2
  i.e. theta' = -M theta + C^-1 Q with M = C^-1 L, L = [[G12 + Ga1, -G12], [-G12, G12 + Ga2]].
  M has real eigenvalues lam_pm = (tr M +- sqrt(tr^2 - 4 det M)) / 2, an eigenvector of M for lam is
  (M12, lam - M11), and theta(t) = theta_ss + sum_pm c_pm v_pm exp(-lam_pm t) with theta_ss = L^-1 Q
  (Cramer's rule) and c_pm from theta(0) (Cramer's rule again). Tolerance 1e-9 relative.
* Incropera et al. (2007), Example 5.1: thermocouple junction (sphere, h = 400 W/(m^2 K),
  rho = 8500 kg/m^3, c = 400 J/(kg K)) with a 1 s time constant has D = 0.706 mm and takes 5.2 s
  to go from 25 degC to 199 degC in a 200 degC gas. The book prints two significant figures for the
  time and three for the diameter, hence tolerances of 0.05 s and 0.0005 mm.
"""

import math

import numpy as np
import pytest

from auxbearing.core import thermal


def one_node(q, g, c, theta0, t):
    return q / g + (theta0 - q / g) * math.exp(-t * g / c)


@pytest.mark.parametrize(("q", "g", "c", "theta0", "t"), [
    (10.0, 0.5, 40.0, 0.0, 30.0),
    (150.0, 0.02, 5.0, 0.0, 1.0e3),
    (0.0, 3.0, 2.0, 50.0, 0.7),
    (2.5, 1.0e-3, 1.0e4, -5.0, 1.0e5),
])
def test_one_node_step_response(q, g, c, theta0, t):
    ta = 293.15
    new, _ = thermal.exact_step(np.array([ta + theta0]), np.array([c]), np.zeros((1, 1)), np.array([g]),
                                np.array([q]), ta, t)
    assert new[0] - ta == pytest.approx(one_node(q, g, c, theta0, t), rel=1e-9, abs=1e-12)


def two_node(c1, c2, g12, ga1, ga2, q1, q2, t):
    l11, l12, l22 = g12 + ga1, -g12, g12 + ga2
    det_l = l11 * l22 - l12 * l12
    steady = ((q1 * l22 - l12 * q2) / det_l, (l11 * q2 - l12 * q1) / det_l)
    m11, m12, m21, m22 = l11 / c1, l12 / c1, l12 / c2, l22 / c2
    tr, det = m11 + m22, m11 * m22 - m12 * m21
    root = math.sqrt(tr * tr - 4.0 * det)
    lams = (0.5 * (tr + root), 0.5 * (tr - root))
    vecs = [(m12, lam - m11) for lam in lams]
    # theta(0) = 0: c+ v+ + c- v- = -theta_ss
    (a, b), (cc, d) = vecs
    rhs = (-steady[0], -steady[1])
    det_v = a * d - cc * b
    coef = ((rhs[0] * d - cc * rhs[1]) / det_v, (a * rhs[1] - b * rhs[0]) / det_v)
    return tuple(steady[i] + sum(coef[k] * vecs[k][i] * math.exp(-lams[k] * t) for k in range(2)) for i in range(2))


@pytest.mark.parametrize(("c1", "c2", "g12", "ga1", "ga2", "q1", "q2", "t"), [
    (5.0, 50.0, 0.4, 0.0, 0.05, 20.0, 0.0, 60.0),
    (5.0, 50.0, 0.4, 0.0, 0.05, 20.0, 0.0, 6000.0),
    (4.9, 7.4, 0.46, 0.003, 0.0, 3.0, 1.0, 12.5),
    (1.0, 1.0, 10.0, 1.0, 1.0, 1.0, 0.0, 0.01),
])
def test_two_node_step_response(c1, c2, g12, ga1, ga2, q1, q2, t):
    ta = 300.0
    g = np.array([[0.0, g12], [g12, 0.0]])
    new, _ = thermal.exact_step(np.full(2, ta), np.array([c1, c2]), g, np.array([ga1, ga2]),
                                np.array([q1, q2]), ta, t)
    expected = two_node(c1, c2, g12, ga1, ga2, q1, q2, t)
    assert new - ta == pytest.approx(expected, rel=1e-9, abs=1e-12)


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
