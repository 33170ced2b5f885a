"""stretch_load: the equivalent load a reduced stretch is charged at, from the loads before and after it.

Self-consistency of the quadrature (ISO 281:2007 Eq. (1) life goes as P^-3, Palmgren-Miner adds the
revolutions' damages): no published number is compared here.
"""

import numpy as np
import pytest

from auxbearing.analysis.coastdown_phases import stretch_load


def test_a_constant_load_is_kept():
    assert stretch_load(120.0, 120.0) == pytest.approx(120.0, rel=1e-14)


def test_it_is_the_mean_damage_of_a_load_linear_in_the_revolutions():
    before, after = 2700.0, 2400.0
    # P linear in the revolutions over the stretch: the mean of P^3 over them
    revolutions = np.linspace(0.0, 1.0, 100001)
    exact = float(np.trapezoid((before + (after - before) * revolutions) ** 3, revolutions)) ** (1.0 / 3.0)
    assert stretch_load(before, after) == pytest.approx(exact, rel=1e-9)
    assert after < stretch_load(before, after) < before


def test_a_load_going_as_the_square_of_a_steadily_falling_speed_is_charged_exactly():
    """F = k Omega^2 from 18 000 to 16 200 rpm (a 10 % speed step) at a constant deceleration: revolutions run as
    Omega dOmega, so the damage of the stretch is the integral of F^3 Omega dOmega over that of Omega dOmega."""
    speeds = np.linspace(16200.0, 18000.0, 200001)
    load = 300.0 * (speeds / 18000.0) ** 2
    exact = (np.trapezoid(load**3 * speeds, speeds) / np.trapezoid(speeds, speeds)) ** (1.0 / 3.0)
    assert stretch_load(load[-1], load[0]) == pytest.approx(exact, rel=1e-9)
    # the cube taken linear instead (the trapezoidal rule on P^3) overstates that stretch's damage by 2.2 %
    trapezoid = 0.5 * (load[-1] ** 3 + load[0] ** 3)
    assert trapezoid / exact**3 - 1.0 == pytest.approx(0.0218, abs=2e-4)


def test_the_order_of_the_ends_does_not_matter():
    assert stretch_load(80.0, 110.0) == pytest.approx(stretch_load(110.0, 80.0), rel=1e-15)
