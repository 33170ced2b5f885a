"""The lumped thermal network's exact step against closed-form solutions of its own equations.

Identities, not published numbers: the network integrates C dtheta/dt = Q - L theta exactly, and for one
and two nodes that equation has a closed form (Incropera, DeWitt, Bergman & Lavine, Fundamentals of Heat
and Mass Transfer, 6th ed., 2007, Sec. 5.1-5.3, lumped capacitance):

* one body of capacity C losing heat through a conductance G with a constant input Q:
  theta(t) = Q/G + (theta_0 - Q/G) exp(-t G / C);
* two bodies, the energy balance of each solved here by hand:
      C1 theta1' = Q1 - G12 (theta1 - theta2) - Ga1 theta1
      C2 theta2' = Q2 - G12 (theta2 - theta1) - Ga2 theta2
  i.e. theta' = -M theta + C^-1 Q with M = C^-1 L, L = [[G12 + Ga1, -G12], [-G12, G12 + Ga2]].
  M has real eigenvalues lam_pm = (tr M +- sqrt(tr^2 - 4 det M)) / 2, an eigenvector of M for lam is
  (M12, lam - M11), and theta(t) = theta_ss + sum_pm c_pm v_pm exp(-lam_pm t) with theta_ss = L^-1 Q
  (Cramer's rule) and c_pm from theta(0) (Cramer's rule again).

Tolerance: round-off, 1e-9 relative.
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

