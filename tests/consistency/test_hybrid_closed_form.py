"""Hybrid bearings against Hertz closed forms (consistency, not validation: these are our own numbers).

Hertz point contact with the same geometry and load: sigma_max ~ Q^(1/3) eta^(-2/3) and the approach
delta ~ Q^(2/3) eta^(2/3) (Harris & Kotzalas 2007, Eq. 6.38-6.47), eta = sum (1 - nu^2)/E; so a hybrid
scales the stress by (eta_steel/eta_hybrid)^(2/3), the ball constant K = Q/delta^1.5 by eta_steel/eta_hybrid,
and the load at a given stress (C0 at 4200 MPa) by (eta_hybrid/eta_steel)^2. Ball mass by density.
"""

import math

import numpy as np
import pytest

from auxbearing import get_bearing
from auxbearing.analysis.life import static_load_rating
from auxbearing.bearings.ballset import hertz_tables
from auxbearing.bearings.hybrid import hybrid
from auxbearing.bearings.materials import get_material
from auxbearing.bearings.ratings import compliance_ratio


def _etas():
    steel, ceramic = get_material("GCr15"), get_material("Si3N4")
    return 2 * steel.compliance, steel.compliance + ceramic.compliance


def test_tables_scale_as_hertz_says():
    eta_s, eta_h = _etas()
    _, steel = hertz_tables(get_bearing("7208"))
    _, hyb = hertz_tables(get_bearing("7208 hybrid"))
    np.testing.assert_allclose(hyb[0, 0] / steel[0, 0], eta_s / eta_h, rtol=1e-10)  # K_b
    np.testing.assert_allclose(hyb[1, 0] / steel[1, 0], (eta_s / eta_h) ** (2 / 3), rtol=1e-10)  # stress inner
    np.testing.assert_allclose(hyb[3, 0] / steel[3, 0], (eta_h / eta_s) ** (1 / 3), rtol=1e-10)  # semi-major


def test_static_rating_scales_with_compliance_squared():
    eta_s, eta_h = _etas()
    ratio = static_load_rating("6205 hybrid") / static_load_rating("6205")
    assert ratio == pytest.approx((eta_h / eta_s) ** 2, rel=1e-12)
    assert compliance_ratio(get_bearing("6205 hybrid")) == pytest.approx(eta_h / eta_s, rel=1e-12)


def test_ball_mass_and_names():
    steel, ceramic = get_bearing("QJ208"), get_bearing("QJ208 hybrid")
    assert ceramic.ball_mass == pytest.approx(3200 * math.pi * 12.7e-3**3 / 6)
    assert steel.ball_mass / ceramic.ball_mass == pytest.approx(7810 / 3200)
    assert ceramic.is_hybrid and not steel.is_hybrid
    assert hybrid(ceramic) is ceramic
    assert get_bearing("6205/HC5").name == "6205 hybrid"
