"""Self-consistency of the thermal network, the growth relations, the conductance paths and the friction kernels."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.special import ellipkm1

from auxbearing import get_bearing
from auxbearing.analysis.thermal import BALLS, HOUSING, INNER_RACE, JOURNAL, OUTER_RACE, build_network
from auxbearing.core import bearing_friction as bf
from auxbearing.core import thermal


def random_network(seed, n=5):
    rng = np.random.default_rng(seed)
    c = rng.uniform(1.0, 60.0, n)
    g = np.triu(rng.uniform(0.0, 2.0, (n, n)) * (rng.random((n, n)) < 0.7), 1)
    g = g + g.T
    ga = rng.uniform(0.0, 0.1, n) * (rng.random(n) < 0.5)
    ga[0] = 0.05  # at least one path out
    q = rng.uniform(0.0, 30.0, n)
    t0 = 293.15 + rng.uniform(-5.0, 40.0, n)
    return c, g, ga, q, t0


def qj202(**kw):
    return build_network(get_bearing("QJ202"), 7.4e-3, contact_load=150.0, **kw)


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("dt", [1e-3, 0.7, 50.0, 1e4])
def test_energy_balance_of_exact_step(seed, dt):
    """Heat in = heat stored + heat lost to ambient, with the step-mean temperatures."""
    c, g, ga, q, t0 = random_network(seed)
    ta = 293.15
    t1, tmean = thermal.exact_step(t0, c, g, ga, q, ta, dt)
    stored = np.sum(c * (t1 - t0))
    lost = np.sum(ga * (tmean - ta)) * dt
    assert stored + lost == pytest.approx(np.sum(q) * dt, rel=1e-9, abs=1e-9 * np.sum(c * np.abs(t0 - ta)))


def test_energy_balance_qj202_plane():
    net = qj202(rotor_speed=2000.0)
    c, g, ga, ta = net.kernel_args()
    q = net.heat_inputs(40.0, 3.0)
    t0 = np.full(5, ta)
    t1, tmean = thermal.exact_step(t0, c, g, ga, q, ta, 2.5)
    assert np.sum(c * (t1 - t0)) + np.sum(ga * (tmean - ta)) * 2.5 == pytest.approx(43.0 * 2.5, rel=1e-10)


@pytest.mark.parametrize("seed", range(4))
def test_two_half_steps_equal_one_step(seed):
    c, g, ga, q, t0 = random_network(seed)
    once, _ = thermal.exact_step(t0, c, g, ga, q, 293.15, 8.0)
    half, _ = thermal.exact_step(t0, c, g, ga, q, 293.15, 4.0)
    twice, _ = thermal.exact_step(half, c, g, ga, q, 293.15, 4.0)
    assert twice == pytest.approx(once, rel=1e-12)


@pytest.mark.parametrize("seed", range(4))
def test_exact_step_matches_tight_ode_integration(seed):
    c, g, ga, q, t0 = random_network(seed)
    sol = solve_ivp(lambda _t, y: thermal.temperature_rate(y, c, g, ga, q, 293.15), (0.0, 30.0), t0,
                    method="Radau", rtol=1e-11, atol=1e-10)
    exact, _ = thermal.exact_step(t0, c, g, ga, q, 293.15, 30.0)
    assert exact == pytest.approx(sol.y[:, -1], rel=1e-8)


@pytest.mark.parametrize("seed", range(4))
def test_long_step_reaches_steady_state_and_rate_vanishes_there(seed):
    c, g, ga, q, t0 = random_network(seed)
    steady = thermal.steady_state(g, ga, q, 293.15)
    assert thermal.temperature_rate(steady, c, g, ga, q, 293.15) == pytest.approx(np.zeros(5), abs=1e-10)
    late, _ = thermal.exact_step(t0, c, g, ga, q, 293.15, 1e9)
    assert late == pytest.approx(steady, rel=1e-10)


def test_isolated_network_stores_all_heat():
    """No path to ambient: a zero eigenvalue; the step must stay finite and conserve energy."""
    c = np.array([2.0, 3.0])
    g = np.array([[0.0, 1.0], [1.0, 0.0]])
    t1, _ = thermal.exact_step(np.full(2, 300.0), c, g, np.zeros(2), np.array([5.0, 0.0]), 300.0, 100.0)
    assert np.sum(c * (t1 - 300.0)) == pytest.approx(500.0, rel=1e-12)
    assert t1[0] - t1[1] == pytest.approx(5.0 * 3.0 / (5.0 * 1.0), rel=1e-9)  # q C2 / ((C1 + C2) G)


def test_laplacian_and_network_symmetry():
    net = qj202()
    assert np.array_equal(net.conductances, net.conductances.T)
    assert np.all(np.diag(net.conductances) == 0.0)
    lap = thermal.laplacian(net.conductances, net.ambient_conductances)
    assert lap.sum(axis=1) == pytest.approx(net.ambient_conductances, abs=1e-15)
    assert np.all(np.linalg.eigvalsh(lap) > 0.0)


def test_uniform_rise_of_all_steel_bearing_scales_the_clearance():
    """Same alpha everywhere and one temperature: every length, Pd included, grows by alpha dT."""
    bearing = get_bearing("209")  # GCr15 rings and balls, Pd = 15 um
    net = build_network(bearing, 0.5 * bearing.bore - 20e-6, journal_material="GCr15")
    alpha, rise = bearing.ring_material.thermal_expansion, 60.0
    radial, diametral = net.clearance_changes(np.full(5, net.ambient_temperature + rise))
    assert diametral == pytest.approx(alpha * rise * bearing.diametral_clearance, rel=1e-9)
    assert radial == pytest.approx(alpha * rise * 20e-6, rel=1e-6)


def test_uniform_rise_with_mixed_materials():
    """QJ202: 42CrMo rings, GCr15 balls: dPd = dT [2 D (alpha_ring - alpha_ball) + alpha_ring Pd]."""
    bearing = get_bearing("QJ202")
    net = qj202()
    rise = 80.0
    a_r, a_b = bearing.ring_material.thermal_expansion, bearing.ball_material.thermal_expansion
    _, diametral = net.clearance_changes(np.full(5, net.ambient_temperature + rise))
    expected = rise * (2.0 * bearing.ball_diameter * (a_r - a_b) + a_r * bearing.diametral_clearance)
    assert diametral == pytest.approx(expected, rel=1e-9)


def test_hot_inner_ring_follows_the_catalogue_rule():
    """IKO's rule (reduction = alpha dt x outer raceway) holds up to the term alpha Pd dT_inner."""
    alpha, d_i, d_o, ball, rise = 12.5e-6, 19.5e-3, 31.5e-3, 6.0e-3, 15.0
    change = thermal.diametral_clearance_change(alpha, d_i, rise, alpha, d_o, 0.0, alpha, ball, rise)
    pd = d_o - d_i - 2 * ball
    assert -change == pytest.approx(alpha * rise * d_o - alpha * pd * rise, rel=1e-12)


def test_vacuum_has_no_convection_and_radiation_is_the_only_exit():
    assert np.all(qj202(vacuum=True).ambient_conductances == 0.0)
    assert np.all(qj202(vacuum=True, convection_coefficient=50.0).ambient_conductances == 0.0)
    radiating = qj202(vacuum=True, emissivity=0.4)
    air = qj202(emissivity=0.4)
    assert np.all(radiating.ambient_conductances[[JOURNAL, HOUSING]] > 0.0)
    assert np.all(air.ambient_conductances[[JOURNAL, HOUSING]] > radiating.ambient_conductances[[JOURNAL, HOUSING]])
    assert np.all(radiating.ambient_conductances[[INNER_RACE, BALLS, OUTER_RACE]] == 0.0)


def test_contact_conductance_scales_with_cube_root_of_load():
    """a, b grow as Q^(1/3) at fixed ellipticity and G as the semi-axes, so 8x load doubles G."""
    from auxbearing.analysis.thermal import ball_race_conductance
    bearing = get_bearing("QJ202")
    low = ball_race_conductance(bearing, [50.0] * 4, "outer")
    assert ball_race_conductance(bearing, [400.0] * 4, "outer") == pytest.approx(2.0 * low, rel=1e-9)
    assert ball_race_conductance(bearing, [0.0] * 4, "outer") == 0.0


@pytest.mark.parametrize("ratio", [1.0, 0.5, 0.1, 1e-3])
def test_constriction_uses_the_complete_elliptic_integral(ratio):
    a, k = 1e-4, 40.0
    expected = ellipkm1(ratio**2) / (2.0 * math.pi * k * a)  # K(m) at 1 - m = (b/a)^2, no cancellation
    assert thermal.constriction_resistance(a, ratio * a, k) == pytest.approx(expected, rel=1e-13)


def test_heat_partition_properties():
    assert bf.heat_partition(1.0e4, 30.0, 1.0e4, 30.0) == pytest.approx(0.5)
    assert bf.heat_partition(2.0e4, 7.0, 1.0e4, 7.0) == pytest.approx(2.0 / 3.0)
    share = bf.heat_partition(1.3e4, 80.0, 1.2e4, 20.0)
    assert share + bf.heat_partition(1.2e4, 20.0, 1.3e4, 80.0) == pytest.approx(1.0)
    assert bf.heat_partition(1.3e4, 90.0, 1.2e4, 20.0) > share  # faster surface takes more


def test_palmgren_viscous_term_is_nearly_continuous_at_its_switch():
    """The two branches meet within 1 % at nu n = 2000 (160 vs 2000^(2/3) = 158.7)."""
    nu, dm, f0 = 20e-6, 0.05, 2.0
    switch = 2000.0 / (nu * 1e6) * math.pi / 30.0  # rad/s where nu n = 2000
    below = bf.palmgren_viscous_torque(nu, switch * (1 - 1e-9), dm, f0)
    above = bf.palmgren_viscous_torque(nu, switch * (1 + 1e-9), dm, f0)
    assert above == pytest.approx(below, rel=0.01)
    assert bf.palmgren_viscous_torque(nu, 8 * switch, dm, f0) == pytest.approx(4 * above, rel=1e-6)
    assert bf.palmgren_viscous_torque(nu, 4 * switch, 2 * dm, f0) == pytest.approx(
        8 * bf.palmgren_viscous_torque(nu, 4 * switch, dm, f0), rel=1e-12)


def test_rolling_resistance_is_skf_half_mu_p_d():
    mu = bf.SKF_FRICTION_COEFFICIENT["four_point"]
    assert bf.rolling_resistance_torque(mu, 800.0, 0.5 * 0.015) == pytest.approx(0.5 * mu * 800.0 * 0.015)
    assert bf.friction_power(bf.palmgren_torque(32e-6, 500.0, 0.0255, 2.0, 1e-3, 300.0), -500.0) > 0.0
