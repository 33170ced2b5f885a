"""ISO 76 f0 and C0 computed from Hertz (consistency: the table is ours, derived as ISO 76 derives its own).

* The tabulated f0 (auxbearing.bearings.ratings.ISO76_F0) equals the Hertz computation at its nodes.
* At the factor's definition: a bearing loaded with F_r = C0 under ISO 76's distribution Q_max =
  5 F_r/(i Z cos alpha) reaches exactly 4200 MPa in its most stressed contact (groove radii 0.52/0.53).
"""

import numpy as np
import pytest

from auxbearing.analysis.contact import ball_contact
from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.bearings.materials import Material
from auxbearing.bearings.ratings import ISO76_F0, ISO76_F0_STEP, ISO76_STRESS, f0_exact, static_load_rating_si


def test_table_equals_hertz_at_the_nodes():
    gamma = np.arange(len(ISO76_F0)) * ISO76_F0_STEP
    np.testing.assert_allclose(f0_exact(gamma), ISO76_F0, atol=6e-5)


@pytest.mark.parametrize(("ball", "pitch", "z"), [(7.94e-3, 39.04e-3, 9), (12.7e-3, 60e-3, 10), (6e-3, 60e-3, 20)])
def test_c0_load_gives_4200_mpa(ball, pitch, z):
    steel = Material(207e9, 0.3, "ISO 76 steel")
    b = BearingGeometry("deep_groove", ball, pitch, z, 0.52, 0.53, 0.0, 0.0, steel, steel)
    c0 = float(f0_exact(ball / pitch)) * z * (ball * 1e3) ** 2
    assert static_load_rating_si(ball, pitch, z, 0.0) == pytest.approx(c0, rel=6e-3)  # the table's interpolation
    result = ball_contact(b, 5.0 * c0 / z)
    stresses = [result[race]["max_stress_MPa"] * 1e6 for race in ("inner", "outer")]
    assert max(stresses) == pytest.approx(ISO76_STRESS, rel=1e-9)
