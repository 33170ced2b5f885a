"""Invariants of Hertz contact (hypothesis)."""

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from auxbearing.core import hertz

STEEL = 2 * (1 - 0.09) / 207e9
loads = st.floats(1e-2, 1e5)
factors = st.floats(1.01, 1e3)
f_values = st.floats(0.0, 0.999)
curvatures = st.floats(1.0, 1e4)


@pytest.mark.slow
@settings(max_examples=60, deadline=None)
@given(q=loads, c=factors, f=f_values, s=curvatures)
def test_scaling_laws(q, c, f, s):
    """a, b ~ Q^(1/3); delta ~ Q^(2/3); sigma_max ~ Q^(1/3) (source paper Eq. 4-8)."""
    r1 = hertz.point_contact(q, s, f, STEEL)
    r2 = hertz.point_contact(q * c, s, f, STEEL)
    np.testing.assert_allclose(r2.semi_major / r1.semi_major, c ** (1 / 3), rtol=1e-12)
    np.testing.assert_allclose(r2.semi_minor / r1.semi_minor, c ** (1 / 3), rtol=1e-12)
    np.testing.assert_allclose(r2.approach / r1.approach, c ** (2 / 3), rtol=1e-12)
    np.testing.assert_allclose(r2.max_stress / r1.max_stress, c ** (1 / 3), rtol=1e-12)


@settings(max_examples=40, deadline=None)
@given(rho=curvatures, rho2=st.floats(-0.9, 10.0))
def test_equal_principal_curvatures_give_circle(rho, rho2):
    _, f = hertz.curvature_sum_difference(rho, rho, rho2 * rho, rho2 * rho)
    kappa, _, _ = hertz.ellipticity(f)
    assert float(kappa) == 1.0


@settings(max_examples=40, deadline=None)
@given(a=curvatures, b=curvatures, c=st.floats(-0.4, 1.0), d=st.floats(-0.4, 1.0), q=loads)
def test_swapping_bodies_changes_nothing(a, b, c, d, q):
    c, d = c * min(a, b), d * min(a, b)
    s1, f1 = hertz.curvature_sum_difference(a, b, c, d)
    s2, f2 = hertz.curvature_sum_difference(c, d, a, b)
    r1 = hertz.point_contact(q, s1, f1, STEEL)
    r2 = hertz.point_contact(q, s2, f2, STEEL)
    # 1e-11: with curvatures 8000:1 apart the two orders of summation differ by 1.4e-12 in the stress
    for x, y in zip(r1, r2, strict=True):
        np.testing.assert_allclose(x, y, rtol=1e-11)


@pytest.mark.slow
@settings(max_examples=60, deadline=None)
@given(ratio=st.floats(1.0, 100.0), q=loads)
def test_hamrock_brewe_within_its_error(ratio, q):
    """Hamrock & Brewe (1983) report errors of a few per cent for 1 <= Ry/Rx <= 100; measured
    maxima over that range: kappa 3.8 %, K 2.1 %, E 0.91 %, sigma_max 1.6 %, a 2.7 %, delta 4.1 %."""
    f = (ratio - 1) / (ratio + 1)
    exact = np.array(hertz.ellipticity(f))
    approx = np.array(hertz.hamrock_brewe(f))
    for got, want, tol in zip(approx, exact, (0.04, 0.022, 0.0095), strict=True):
        np.testing.assert_allclose(got, want, rtol=tol)
    ce = hertz.point_contact(q, 300.0, f, STEEL)
    ca = hertz.point_contact(q, 300.0, f, STEEL, method="hamrock_brewe")
    np.testing.assert_allclose(ca.max_stress, ce.max_stress, rtol=0.017)
    np.testing.assert_allclose(ca.semi_major, ce.semi_major, rtol=0.028)
    np.testing.assert_allclose(ca.approach, ce.approach, rtol=0.042)
