import numpy as np
import pytest
from scipy.special import ellipe, ellipk, ellipkm1

from auxbearing.core import hertz

STEEL = 2 * (1 - 0.09) / 207e9


def test_zero_load_gives_zero_contact_not_nan():
    c = hertz.point_contact(0.0, 400.0, 0.9, STEEL)
    assert float(c.semi_major) == 0.0
    assert float(c.semi_minor) == 0.0
    assert float(c.approach) == 0.0
    assert float(c.max_stress) == 0.0
    assert np.isfinite(c.stiffness) and float(c.stiffness) > 0


def test_negative_load_refused():
    with pytest.raises(ValueError, match=r"contact load = -1\.0 N"):
        hertz.point_contact(-1.0, 400.0, 0.9, STEEL)


@pytest.mark.parametrize("bad", [-0.1, 1.0, 1.5, float("nan")])
def test_curvature_difference_outside_range_refused(bad):
    with pytest.raises(ValueError, match="F\\(rho\\)"):
        hertz.ellipticity(bad)


def test_ellipticity_solves_to_machine_precision():
    """Residual of Harris Eq. 6.22 with scipy's independent ellipk/ellipe (from F = 0.05 up the
    closed form evaluated here is itself free of cancellation at this level)."""
    f = np.r_[np.linspace(0.05, 0.5, 200), np.linspace(0.5, 0.9999, 500)]
    kappa, k, e = hertz.ellipticity(f)
    m = 1 - 1 / kappa**2
    np.testing.assert_allclose(k, ellipkm1(1 / kappa**2), rtol=1e-13)
    np.testing.assert_allclose(e, ellipe(m), rtol=1e-13)
    residual = ((kappa**2 + 1) * ellipe(m) - 2 * ellipk(m)) / ((kappa**2 - 1) * ellipe(m))
    assert np.max(np.abs(residual - f) / f) < 1e-12


def test_ellipticity_near_circular_contacts():
    # F ~ 3m/8 for small m (series of Eq. 6.22): kappa^2 = 1/(1 - m) ~ 1 + 8F/3
    f = np.array([1e-10, 1e-8, 1e-6])
    kappa, _, _ = hertz.ellipticity(f)
    np.testing.assert_allclose(kappa**2 - 1, 8 * f / 3, rtol=2e-5)
    assert float(hertz.ellipticity(0.0)[0]) == 1.0


def test_series_and_closed_form_agree_where_they_meet():
    below = hertz._curvature_difference_of(0.5 + 1e-12)
    above = hertz._curvature_difference_of(0.5 - 1e-12)
    assert below[0] == pytest.approx(above[0], rel=1e-11)
    assert below[1] == pytest.approx(above[1], rel=1e-6)


def test_vectorised_over_arrays_keeps_shape():
    f = np.full((3, 4), 0.9)
    q = np.linspace(0, 100, 12).reshape(3, 4)
    c = hertz.point_contact(q, 400.0, f, STEEL)
    assert c.semi_major.shape == (3, 4)
    assert c.stiffness.shape == (3, 4)


def test_stiffness_is_load_over_approach_to_the_1_5():
    c = hertz.point_contact(700.0, 400.0, 0.93, STEEL)
    assert float(c.stiffness) == pytest.approx(700.0 / float(c.approach) ** 1.5, rel=1e-12)


def test_series_constant_equal_contacts():
    # two equal springs Q = K d^1.5 in series: d doubles, so K_b = K / 2^1.5
    assert float(hertz.series_constant(8.0, 8.0)) == pytest.approx(8.0 / 2**1.5)


def test_outer_race_is_more_conforming_than_inner():
    si, fi = hertz.ball_raceway_curvature(6e-3, 25.5e-3, 0.52, 0.6, "inner")
    so, fo = hertz.ball_raceway_curvature(6e-3, 25.5e-3, 0.52, 0.6, "outer")
    assert so < si
    assert fo < fi


def test_unknown_race_refused():
    with pytest.raises(ValueError, match="race"):
        hertz.ball_raceway_curvature(6e-3, 25.5e-3, 0.52, 0.6, "middle")


def test_line_contact_softer_material_gives_smaller_constant():
    k_steel = hertz.line_contact_constant(10e-3)
    k_soft = hertz.line_contact_constant(10e-3, compliance=2 * STEEL)
    assert float(k_soft) == pytest.approx(float(k_steel) * 2 ** (-1.0), rel=1e-12)
