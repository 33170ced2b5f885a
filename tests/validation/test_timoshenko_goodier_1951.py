"""Validation of the Hertz kernel against published numbers (each case names its source).

Tolerances are those the source supports: the precision it prints, or the accuracy of the
method it used. Sources are collected in docs/validation_sources.md.
"""

import math

import numpy as np
import pytest

from auxbearing import get_bearing
from auxbearing.contact import ball_contact
from auxbearing.core import hertz

STEEL_207 = 2 * (1 - 0.3**2) / 207e9


def test_source_paper_inner_race_stress_2616_mpa():
    """Source paper Sec. II.B: 2616 MPa theory, QJ202 Table I, 1000 N; 1 % (table-reading error)."""
    stress = ball_contact(get_bearing("QJ202"), 1000.0)["inner"]["max_stress_MPa"]
    assert stress == pytest.approx(2616.0, rel=0.01)


# Timoshenko & Goodier, Theory of Elasticity, 2nd ed. (1951), Sec. 140, table of the Hertz
# coefficients m, n against theta with cos(theta) = (B - A)/(A + B) = F(rho). Printed to 3
# decimals; Cooper, J. Appl. Mech. 36 (1969) 296-303 notes errors in the third place of the
# classical tables, hence an absolute tolerance of 0.003. m = a*, n = b* of Eq. 4-5.
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


@pytest.mark.parametrize(("r1", "r2", "load"), [(5e-3, 5e-3, 100.0), (3e-3, 1e9, 1000.0), (10e-3, 2e-3, 10.0)])
def test_sphere_on_sphere_closed_form(r1, r2, load):
    """Hertz (1882); Johnson, Contact Mechanics (1985) Eq. 4.22-4.23: circular contact, exact."""
    e_star_inv = STEEL_207
    r = 1 / (1 / r1 + 1 / r2)
    a = (3 * load * r * e_star_inv / 4) ** (1 / 3)
    c = hertz.point_contact(load, 2 / r1 + 2 / r2, 0.0, e_star_inv)
    assert float(c.semi_major) == pytest.approx(a, rel=1e-12)
    assert float(c.semi_minor) == pytest.approx(a, rel=1e-12)
    assert float(c.approach) == pytest.approx(a**2 / r, rel=1e-12)
    assert float(c.max_stress) == pytest.approx(3 * load / (2 * np.pi * a**2), rel=1e-12)


def test_harris_steel_shortcut_eq7():
    """Source paper Eq. 7 / Harris & Kotzalas (2007) Eq. 6.43: delta = 2.79e-4 delta* Q^(2/3) sum_rho^(1/3)
    (mm, N) for steel, E = 207 GPa, nu = 0.3. The constant is printed to 3 digits: 0.2 %."""
    s, f = hertz.ball_raceway_curvature(6e-3, 25.5e-3, 0.52, math.radians(35), "inner")
    kappa, k, e = hertz.ellipticity(f)
    delta_star = 2 * k / (np.pi * np.cbrt(2 * kappa**2 * e / np.pi))
    q = 610.0
    shortcut_mm = 2.79e-4 * delta_star * q ** (2 / 3) * (s / 1e3) ** (1 / 3)
    exact = hertz.point_contact(q, s, f, STEEL_207).approach
    assert float(exact) * 1e3 == pytest.approx(float(shortcut_mm), rel=0.002)


def test_amesweb_steel_ball_bearing_example():
    """AMESWeb, "Contact Stresses in a Steel Ball Bearing" (web worked example, grade B): ball
    radius 4.90 mm, groove radius 5 mm, race radius 25 mm, E = 210 GPa, nu = 0.29, P = 1500 N.
    Printed: p_max 2193.6 MPa, a 2.101 mm, b 0.156 mm, approach 0.012 mm. The page uses the
    tabulated-coefficient method (interpolation error ~1 %), approach printed to 2 digits."""
    s = 2 / 4.9e-3 + 1 / 25e-3 - 1 / 5e-3
    f = (1 / 25e-3 + 1 / 5e-3) / s
    c = hertz.point_contact(1500.0, s, f, 2 * (1 - 0.29**2) / 210e9)
    assert float(c.max_stress) / 1e6 == pytest.approx(2193.6, rel=0.005)
    assert float(c.semi_major) * 1e3 == pytest.approx(2.101, rel=0.01)
    assert float(c.semi_minor) * 1e3 == pytest.approx(0.156, rel=0.01)
    assert float(c.approach) * 1e3 == pytest.approx(0.012, abs=0.0005)


def test_eng_tools_6206_example():
    """eng-tools.dev "A2 Hertz contact", bearing 6206 (grade B): D = 9.525 mm, r_i = 4.89 mm,
    dm = 46 mm, alpha = 0, E = 210 GPa, nu = 0.3, ball load 5 Fr/Z = 555.6 N (inferred from the
    printed a, b, p0). Printed a 1.368 mm, b 0.112 mm, p0 1728 MPa, computed with a
    Hamrock-Dowson ellipticity fit (k = 12.19, a few per cent off exact): 3 %."""
    s, f = hertz.ball_raceway_curvature(9.525e-3, 46e-3, 4.89 / 9.525, 0.0, "inner")
    c = hertz.point_contact(5 * 1000 / 9, s, f, 2 * (1 - 0.09) / 210e9)
    assert float(c.semi_major) * 1e3 == pytest.approx(1.368, rel=0.03)
    assert float(c.semi_minor) * 1e3 == pytest.approx(0.112, rel=0.03)
    assert float(c.max_stress) / 1e6 == pytest.approx(1728, rel=0.03)


def test_palmgren_reproduces_paper_line_contact_constant():
    """Source paper Table II K_l = 1.468e9 N/m^(10/9) is Palmgren's line contact
    (Harris & Kotzalas 2007 Eq. 6.51) with l = 11 mm, the bearing width: 4-digit print, 0.5 %."""
    assert float(hertz.line_contact_constant(11e-3)) == pytest.approx(1.468e9, rel=0.005)
