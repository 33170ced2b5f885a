"""Validation of the Hertz point contact against AMESWeb's steel ball bearing example.

Source: AMESWeb, "Example - Contact Stresses in a Steel Ball Bearing",
http://www.amesweb.info/HertzianContact/ContactStressesSteelBallBearing.aspx (a worked example on an
engineering web site; docs/validation_sources.md case H1, grade B). Ball radius 4.90 mm in an inner
groove of radius 5 mm on a 25 mm race radius, E = 210 GPa, nu = 0.29, top-ball load P = 1500 N.
Printed: p_max 2193.6 MPa, a 2.101 mm, b 0.156 mm, approach 0.012 mm.

Tolerances: the page interpolates tabulated coefficients (Boresi/Ugural n_a, n_b), good to about 1 %;
stress 0.5 %, semi-axes 1 %, and the approach (2 digits) to half its last digit, 0.0005 mm.
"""

import pytest

from auxbearing.core import hertz


def test_amesweb_steel_ball_bearing_example():
    s = 2 / 4.9e-3 + 1 / 25e-3 - 1 / 5e-3
    f = (1 / 25e-3 + 1 / 5e-3) / s
    c = hertz.point_contact(1500.0, s, f, 2 * (1 - 0.29**2) / 210e9)
    assert float(c.max_stress) / 1e6 == pytest.approx(2193.6, rel=0.005)
    assert float(c.semi_major) * 1e3 == pytest.approx(2.101, rel=0.01)
    assert float(c.semi_minor) * 1e3 == pytest.approx(0.156, rel=0.01)
    assert float(c.approach) * 1e3 == pytest.approx(0.012, abs=0.0005)
