"""One ball-set model: the pair kernel (auxbearing.core.ballset) and its array face (auxbearing.bearings.ballset)."""

import math

import numpy as np
import pytest

from auxbearing import get_bearing
from auxbearing.analysis.contact import raceway_contact
from auxbearing.bearings import ballset as bs
from auxbearing.core import ballset as cb

QJ202 = get_bearing("QJ202")
B7202 = get_bearing("7202")
B209 = get_bearing("209")
STATE = np.array([3e-6, 10e-6, 2e-6, 1e-4, -2e-4])


def test_params_fields_and_cache():
    p = bs.ballset_params(QJ202)
    assert p.cos_azimuth.size == 11
    assert list(p.signs) == [1.0, -1.0]
    assert p.curvature_distance == pytest.approx(0.04 * 6e-3)
    assert p.moment_arm == pytest.approx(QJ202.inner_curvature_centre_radius)
    np.testing.assert_allclose(np.arctan2(p.sin_azimuth, p.cos_azimuth) % (2 * np.pi), 2 * np.pi * np.arange(11) / 11,
                               atol=1e-15)
    assert bs.ballset_params(QJ202) is p  # cached per bearing
    assert list(bs.ballset_params(B7202).signs) == [1.0]
    assert list(bs.ballset_params(B209).signs) == [0.0]


def test_bad_ball_constant():
    with pytest.raises(ValueError, match="ball_constant"):
        bs.ballset_params(QJ202, ball_constant=-1.0)


@pytest.mark.parametrize("bearing", [QJ202, B209])
def test_hermite_tables_match_exact_hertz_between_nodes(bearing):
    """Interpolation error at the mid-points between table nodes (measured ~6e-14)."""
    p = bs.ballset_params(bearing)
    nodes = np.linspace(0.0, np.pi / 2, bs.TABLE_POINTS)
    mid = 0.5 * (nodes[1:] + nodes[:-1])
    for row, exact in enumerate(bs._exact_rows(bearing, mid)):
        value = np.array([cb.table(p, row, x)[0] for x in mid])
        assert np.max(np.abs(value / exact - 1.0)) < 1e-9


@pytest.mark.parametrize("bearing", [QJ202, B209])
def test_ball_constant_on_cosines_matches_exact_hertz_between_nodes(bearing):
    """The load's K_b table on cos(alpha): interpolation error at the mid-points (measured ~3e-14)."""
    p = bs.ballset_params(bearing)
    nodes = np.linspace(0.0, 1.0, bs.TABLE_POINTS)
    mid = 0.5 * (nodes[1:] + nodes[:-1])
    exact = bs._exact_rows(bearing, np.arccos(mid))[cb.K_B]
    value = np.array([cb.ball_constant(p, c)[0] for c in mid])
    assert np.max(np.abs(value / exact - 1.0)) < 1e-9
    # and it is the angle table's K_b, read at the same contact angles
    on_angles = np.array([cb.table(p, cb.K_B, a)[0] for a in np.arccos(mid)])
    assert np.max(np.abs(value / on_angles - 1.0)) < 1e-12


def test_ball_constant_at_free_angle_is_eq15():
    p = bs.ballset_params(QJ202)
    k_i = raceway_contact(QJ202, 0.0, "inner").stiffness
    k_o = raceway_contact(QJ202, 0.0, "outer").stiffness
    expected = k_i * k_o / (k_i ** (2 / 3) + k_o ** (2 / 3)) ** 1.5
    assert cb.table(p, cb.K_B, QJ202.contact_angle)[0] == pytest.approx(float(expected), rel=1e-12)


@pytest.mark.parametrize("bearing", [QJ202, B7202, B209])
def test_jacobian_matches_finite_differences(bearing):
    p = bs.ballset_params(bearing)
    u = STATE * 5 if bearing is B209 else STATE  # 209 has clearance: move further to load balls
    jac = bs.ballset_state(u, p).jacobian
    steps = np.array([1e-10, 1e-10, 1e-10, 1e-8, 1e-8])
    fd = np.empty((5, 5))
    for i, h in enumerate(steps):
        e = np.zeros(5)
        e[i] = h
        fd[:, i] = (bs.ballset_state(u + e, p).force - bs.ballset_state(u - e, p).force) / (2 * h)
    np.testing.assert_allclose(fd, jac, rtol=1e-5, atol=1e-6 * np.abs(jac).max())


def test_resultant_is_the_sum_of_pair_forces():
    """Eq. 14: Fa = -sum Q sin(alpha) with signs, Fr = -sum Q cos(alpha) cos(phi), moments with r_ic."""
    p = bs.ballset_params(QJ202)
    st = bs.ballset_state(STATE, p)
    phi = np.arctan2(p.sin_azimuth, p.cos_azimuth)[:, None]
    sigma = np.array([1.0, -1.0])
    axial = -(st.load * sigma * np.sin(st.contact_angle)).sum()
    radial = -(st.load * np.cos(st.contact_angle))
    ric = QJ202.inner_curvature_centre_radius
    assert st.force[0] == pytest.approx(axial, rel=1e-12)
    assert st.force[1] == pytest.approx((radial * np.cos(phi)).sum(), rel=1e-12)
    assert st.force[2] == pytest.approx((radial * np.sin(phi)).sum(), rel=1e-12)
    fz = -(st.load * sigma * np.sin(st.contact_angle))
    assert st.force[4] == pytest.approx((-ric * np.cos(phi) * fz).sum(), rel=1e-12)


def test_zero_displacement_zero_clearance_carries_nothing():
    for bearing in (QJ202, B7202):
        st = bs.ballset_state(np.zeros(5), bs.ballset_params(bearing))
        assert np.all(st.load == 0.0) and np.all(st.force == 0.0) and np.all(st.jacobian == 0.0)
        assert np.allclose(st.compression, 0.0, atol=1e-18)
        np.testing.assert_allclose(st.contact_angle, bearing.contact_angle, rtol=1e-12)


def test_four_point_radial_compresses_both_pairs_equally():
    st = bs.ballset_state([0.0, 10e-6, 0.0, 0.0, 0.0], bs.ballset_params(QJ202))
    assert st.load[0, 0] > 0.0
    np.testing.assert_allclose(st.load[:, 0], st.load[:, 1], rtol=1e-12)
    assert abs(st.force[0]) < 1e-9 * abs(st.force[1])


def test_types_differ_only_through_geometry():
    """An angular-contact ball is pair 1 of the four-point ball at the same displacement."""
    four = bs.ballset_state(STATE, bs.ballset_params(QJ202))
    angular = bs.ballset_state(STATE, bs.ballset_params(QJ202.with_changes(type="angular_contact")))
    np.testing.assert_array_equal(angular.load[:, 0], four.load[:, 0])
    np.testing.assert_array_equal(angular.contact_angle[:, 0], four.contact_angle[:, 0])


def test_contacts_never_pull():
    st = bs.ballset_state([-5e-6, -5e-6, 0.0, 0.0, 0.0], bs.ballset_params(B7202))
    assert np.all(st.load >= 0.0)
    assert np.all(st.load[st.compression <= 0.0] == 0.0)
    away = bs.ballset_state([-20e-6, 0.0, 0.0, 0.0, 0.0], bs.ballset_params(B7202))
    assert np.all(away.load == 0.0) and np.all(away.force == 0.0)


def test_clearance_is_taken_up_before_load():
    pd = 20e-6
    p = bs.ballset_params(QJ202.with_changes(diametral_clearance=pd))
    assert bs.ballset_state([0.0, 0.45 * pd, 0.0, 0.0, 0.0], p).load.max() == 0.0
    assert bs.ballset_state([0.0, 0.55 * pd, 0.0, 0.0, 0.0], p).load.max() > 0.0
    force = np.zeros(5)
    assert cb.accumulate(np.array([0.0, 0.45 * pd, 0.0, 0.0, 0.0]), p, pd, force, np.zeros((1, 1)), False, True) == (
        0.0, 0.0)
    assert np.all(force == 0.0)


def test_ball_constant_override():
    k = 1.71e10
    p = bs.ballset_params(QJ202, ball_constant=k)
    st = bs.ballset_state(STATE, p)
    loaded = st.compression > 0
    np.testing.assert_allclose(st.load[loaded], k * st.compression[loaded] ** 1.5, rtol=1e-13)
    # stresses still from Hertz at the loaded angle
    j, m = np.unravel_index(np.argmax(st.load), st.load.shape)
    hertz = raceway_contact(QJ202, st.load[j, m], "inner", contact_angle=abs(st.contact_angle[j, m]))
    assert st.stress_inner[j, m] == pytest.approx(float(hertz.max_stress), rel=1e-9)


def test_stresses_are_hertz_at_the_loaded_angle():
    st = bs.ballset_state(STATE, bs.ballset_params(QJ202))
    j, m = np.unravel_index(np.argmax(st.load), st.load.shape)
    for race, value in (("inner", st.stress_inner[j, m]), ("outer", st.stress_outer[j, m])):
        hertz = raceway_contact(QJ202, st.load[j, m], race, contact_angle=st.contact_angle[j, m])
        assert value == pytest.approx(float(hertz.max_stress), rel=1e-9)


def test_compression_is_the_sum_of_hertz_approaches():
    """Eq. 15: S - A = delta_inner + delta_outer at the pair load."""
    st = bs.ballset_state(STATE, bs.ballset_params(QJ202))
    j, m = np.unravel_index(np.argmax(st.load), st.load.shape)
    q, a = st.load[j, m], st.contact_angle[j, m]
    total = sum(float(raceway_contact(QJ202, q, r, contact_angle=a).approach) for r in ("inner", "outer"))
    assert st.compression[j, m] == pytest.approx(total, rel=1e-9)


def test_accumulate_reports_the_largest_load_and_stress_of_the_arrays():
    p = bs.ballset_params(QJ202)
    for u in (STATE, np.array([0.0, 3e-6, -7e-6, 0.0, 0.0])):
        force = np.zeros(5)
        qmax, smax = cb.accumulate(u, p, p.clearance, force, np.zeros((1, 1)), False, True)
        st = bs.ballset_state(u, p)
        assert qmax == st.load.max()
        assert smax == max(st.stress_inner.max(), st.stress_outer.max())
        np.testing.assert_array_equal(force, st.force)
        assert force[1] * u[1] + force[2] * u[2] <= 0.0  # restoring


def test_thermal_clearance_argument_moves_the_onset():
    """The kernels take the diametral clearance as an argument (thermal growth changes it while running)."""
    p = bs.ballset_params(QJ202)
    u = [0.0, 4e-6, 0.0, 0.0, 0.0]
    assert bs.ballset_state(u, p, clearance=10e-6).load.max() == 0.0
    assert bs.ballset_state(u, p, clearance=6e-6).load.max() > 0.0


def test_azimuth_convention_and_rotation():
    """Ball j sits at 2 pi j / Z from +x: a displacement toward ball 1 loads ball 1 most."""
    p = bs.ballset_params(QJ202)
    phi1 = 2 * math.pi / 11
    st = bs.ballset_state([0.0, 8e-6 * math.cos(phi1), 8e-6 * math.sin(phi1), 0.0, 0.0], p)
    assert int(np.argmax(st.load[:, 0])) == 1
    ref = bs.ballset_state([0.0, 8e-6, 0.0, 0.0, 0.0], p)
    np.testing.assert_allclose(np.roll(ref.load, 1, axis=0), st.load, rtol=1e-9, atol=1e-9)


def test_batched_shapes():
    p = bs.ballset_params(QJ202)
    st = bs.ballset_state(np.zeros((4, 3, 5)) + STATE, p)
    assert st.load.shape == (4, 3, 11, 2)
    assert st.force.shape == (4, 3, 5) and st.jacobian.shape == (4, 3, 5, 5)
    np.testing.assert_allclose(st.force[2, 1], bs.ballset_state(STATE, p).force)
