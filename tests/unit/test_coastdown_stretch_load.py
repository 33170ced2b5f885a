"""stretch_load: the equivalent load a reduced stretch is charged at, from the loads before and after it.

Self-consistency of the quadrature (ISO 281:2007 Eq. (1) life goes as P^-3, Palmgren-Miner adds the
revolutions' damages): no published number is compared here.
"""

import numpy as np
import pytest

from auxbearing.analysis.coastdown_phases import stretch_load


def test_a_constant_load_is_kept():
    assert stretch_load(120.0, 120.0) == pytest.approx(120.0, rel=1e-14)


def test_it_is_the_mean_damage_of_a_linearly_changing_damage_rate():
    before, after = 2700.0, 2400.0
    # P^3 linear in the revolutions over the stretch: the mean of P^3 over many equal slices
    cubes = np.linspace(before**3, after**3, 100001)
    exact = float(np.mean(cubes)) ** (1.0 / 3.0)
    assert stretch_load(before, after) == pytest.approx(exact, rel=1e-9)
    assert after < stretch_load(before, after) < before


def test_the_order_of_the_ends_does_not_matter():
    assert stretch_load(80.0, 110.0) == pytest.approx(stretch_load(110.0, 80.0), rel=1e-15)
