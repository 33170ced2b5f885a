"""The general Hertz point-contact solver against its own circular special case (an identity).

Two spheres touch in a circle; Hertz (1882), as written in Johnson, Contact Mechanics (1985) Eq. 4.22-4.23,
gives its radius, the approach and the peak pressure in closed form. The elliptic solver must reduce to it
to round-off.
"""

import numpy as np
import pytest

from auxbearing.core import hertz

STEEL_207 = 2 * (1 - 0.3**2) / 207e9


@pytest.mark.parametrize(("r1", "r2", "load"), [(5e-3, 5e-3, 100.0), (3e-3, 1e9, 1000.0), (10e-3, 2e-3, 10.0)])
def test_sphere_on_sphere_closed_form(r1, r2, load):
    e_star_inv = STEEL_207
    r = 1 / (1 / r1 + 1 / r2)
    a = (3 * load * r * e_star_inv / 4) ** (1 / 3)
    c = hertz.point_contact(load, 2 / r1 + 2 / r2, 0.0, e_star_inv)
    assert float(c.semi_major) == pytest.approx(a, rel=1e-12)
    assert float(c.semi_minor) == pytest.approx(a, rel=1e-12)
    assert float(c.approach) == pytest.approx(a**2 / r, rel=1e-12)
    assert float(c.max_stress) == pytest.approx(3 * load / (2 * np.pi * a**2), rel=1e-12)
