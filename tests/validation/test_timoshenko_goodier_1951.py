"""Validation of the Hertz ellipse coefficients against Timoshenko & Goodier's table.

Source: Timoshenko, S. and Goodier, J. N., Theory of Elasticity, 2nd ed., McGraw-Hill (1951), Sec. 140,
table of the coefficients m and n of the contact ellipse's semi-axes against the angle theta, with
cos(theta) = (B - A)/(A + B), the curvature difference F(rho). Here m = a*, n = b* (source paper Eq. 4-5).

Tolerance: the table is printed to 3 decimals, and Cooper, J. Appl. Mech. 36 (1969) 296-303, notes
errors in the third place of the classical tables: 0.003 absolute.
"""

import math

import numpy as np
import pytest

from auxbearing.core import hertz

TIMOSHENKO = [
    (30, 2.731, 0.493), (35, 2.397, 0.530), (40, 2.136, 0.567), (45, 1.926, 0.604),
    (50, 1.754, 0.641), (55, 1.611, 0.678), (60, 1.486, 0.717), (65, 1.378, 0.759),
    (70, 1.284, 0.802), (75, 1.202, 0.846), (80, 1.128, 0.893), (85, 1.061, 0.944), (90, 1.000, 1.000),
]


@pytest.mark.parametrize(("theta", "m", "n"), TIMOSHENKO)
def test_timoshenko_goodier_coefficients(theta, m, n):
    kappa, _, e = hertz.ellipticity(max(math.cos(math.radians(theta)), 0.0))
    a_star = np.cbrt(2 * kappa**2 * e / np.pi)
    b_star = np.cbrt(2 * e / (np.pi * kappa))
    assert float(a_star) == pytest.approx(m, abs=0.003)
    assert float(b_star) == pytest.approx(n, abs=0.003)
