"""A regression value frozen by hand (before golden.json existed): the QJ202 under 500 N axial and 1000 N radial.

Values this code gave at the commit that added them (they were in tests/unit/test_static.py), to 1e-4;
golden.json holds the same case (``static --bearing QJ202 --axial 500 --radial 1000``) to 1e-9.
"""

import pytest

from auxbearing import get_bearing
from auxbearing.analysis import statics as an

QJ202 = get_bearing("QJ202")


def test_regression_qj202_combined_load():
    """Regression (not validation): values this code gave at the commit that added it."""
    s = an.summary(an.load_distribution(QJ202, axial=500, radial=1000))
    assert s["axial_displacement_um"] == pytest.approx(10.2421, rel=1e-4)
    assert s["radial_displacement_um"] == pytest.approx(12.4991, rel=1e-4)
    assert s["tilt_mrad"] == pytest.approx(-0.82285, rel=1e-4)
    assert s["max_contact_load_N"] == pytest.approx(274.816, rel=1e-4)
    assert s["max_stress_MPa"] == pytest.approx(2004.67, rel=1e-4)
