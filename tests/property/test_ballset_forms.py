"""The force-only radial kernel of the drop equals the full ball-set model (hypothesis)."""

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from auxbearing import get_bearing
from auxbearing.core.ballset import kernel_params, radial_force, radial_support

PARAMS = {
    "QJ202": kernel_params(get_bearing("QJ202")),
    "7202": kernel_params(get_bearing("7202")),
    "209": kernel_params(get_bearing("209")),
    "QJ202+clearance": kernel_params(get_bearing("QJ202").with_changes(diametral_clearance=12e-6)),
}


@pytest.mark.parametrize("name", list(PARAMS))
@settings(max_examples=80, deadline=None)
@given(r=st.floats(0.0, 60e-6), angle=st.floats(0.0, 2 * math.pi))
def test_radial_force_equals_radial_support(name, r, angle):
    p = PARAMS[name]
    dx, dy = r * math.cos(angle), r * math.sin(angle)
    fx, fy, q = radial_force(dx, dy, p)
    fx2, fy2, q2, _ = radial_support(dx, dy, p)
    scale = max(1e-300, math.hypot(fx2, fy2))
    assert abs(fx - fx2) <= 1e-12 * scale
    assert abs(fy - fy2) <= 1e-12 * scale
    assert q == pytest.approx(q2, rel=1e-12, abs=1e-300)
