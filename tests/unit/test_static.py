"""Equilibrium solver (core.static) and the static API (analysis.static)."""

import json

import numpy as np
import pytest

from auxbearing import ConvergenceError, InputError, get_bearing
from auxbearing.analysis import statics as an
from auxbearing.bearings import ballset as bs
from auxbearing.core import statics as cs

QJ202 = get_bearing("QJ202")
B7202 = get_bearing("7202")
B209 = get_bearing("209")
ALL_FREE = np.ones(5, dtype=bool)


def _check_equilibrium(loads, sol, params, free=(True,) * 5, tol=1e-9):
    force = bs.ballset_state(sol.displacement, params).force
    w = np.array([1, 1, 1, 1 / params.moment_arm, 1 / params.moment_arm])
    ref = np.max(np.abs(loads) * w, axis=1)
    resid = np.abs(loads + force) * w * np.asarray(free)
    assert np.all(resid.max(axis=1) <= tol * np.maximum(ref, 1e-300) + 1e-300)


@pytest.mark.parametrize("bearing", [QJ202, B7202, B209, QJ202.with_changes(diametral_clearance=15e-6),
                                     B7202.with_changes(diametral_clearance=15e-6)])
def test_cold_start_cases_converge(bearing):
    """Rigid-ring start: zero load, pure axial, pure radial, pure moment, combined, tiny and huge loads."""
    p = bs.ballset_params(bearing)
    loads = np.array([[0, 0, 0, 0, 0], [1000, 0, 0, 0, 0], [1e-3, 0, 0, 0, 0], [20000, 0, 0, 0, 0],
                      [800, 1000, 0, 0, 0], [500, 300, -200, 1, 2], [3000, 0, 0, 0, 4.0]], float)
    if bearing.type != "angular_contact":
        loads = np.vstack([loads, [[0, 1000, 0, 0, 0], [0, 0, 0, 0, 5.0], [-700, 0, 900, 0, 0]]])
    sol = an.solve_cases(loads, p)
    assert np.all(sol.status == cs.CONVERGED)
    assert np.all(sol.relative_residual <= 1e-9)
    _check_equilibrium(loads, sol, p)
    assert np.all(sol.displacement[0] == 0.0)


def test_pure_axial_start_is_close():
    """The rigid-ring estimate of a pure axial load is the equal-ball solution to the 1-D tolerance."""
    p = bs.ballset_params(QJ202)
    u0 = cs.initial_guess(np.array([1000.0, 0, 0, 0, 0]), ALL_FREE, p)
    force = bs.ballset_state(u0, p).force
    assert force[0] == pytest.approx(-1000.0, rel=0.02)  # the 1-D solves stop at 1 % of the load
    assert np.all(u0[1:] == 0.0)


def test_located_ring_reports_the_axial_reaction():
    p = bs.ballset_params(B7202)
    loads = np.array([[0.0, 1000.0, 0, 0, 0], [200.0, 1000.0, 0, 0, 0]])
    sol = an.solve_cases(loads, p, free=(False, True, True, False, False))
    assert np.all(sol.displacement[:, [0, 3, 4]] == 0.0)
    _check_equilibrium(loads, sol, p, free=(False, True, True, False, False))
    ds = an.solve_loads(B7202, loads, axial_condition="located", tilt="fixed")
    force = bs.ballset_state(sol.displacement, p).force
    np.testing.assert_allclose(ds["axial_reaction"].values, -(loads[:, 0] + force[:, 0]), rtol=1e-9)
    assert np.all(ds["axial_reaction"].values > 0.0)  # the shoulder pushes the ring into its balls


def test_non_convergence_raises_with_residual_and_iterations():
    p = bs.ballset_params(QJ202)
    with pytest.raises(ConvergenceError) as info:
        an.solve_cases([[500.0, 1000.0, 0, 0, 3.0]], p, max_iter=1)
    assert info.value.iterations >= 1  # Newton, then the load-continuation fallback, 1 step each
    assert info.value.residual > 0.0
    assert "load case 0" in str(info.value)
    sol = an.solve_cases([[500.0, 1000.0, 0, 0, 3.0]], p, max_iter=1, raise_on_failure=False)
    assert sol.status[0] == cs.MAX_ITERATIONS


def test_warm_start_and_shape_errors():
    p = bs.ballset_params(QJ202)
    first = an.solve_cases([[500.0, 1000.0, 0, 0, 0]], p)
    again = an.solve_cases([[500.0, 1000.0, 0, 0, 0]], p, initial=first.displacement)
    np.testing.assert_allclose(again.displacement, first.displacement, rtol=1e-8, atol=1e-15)
    assert again.iterations[0] <= 1
    with pytest.raises(ValueError, match="shape"):
        an.solve_cases(np.zeros((2, 3)), p)


def test_load_distribution_units_broadcast_and_attrs():
    a = an.load_distribution("QJ202", axial="0.5 kN", radial="1 kN", moment="2 N*m")
    b = an.load_distribution(QJ202, axial=500, radial=1000, moment=2)
    np.testing.assert_allclose(a["load"].values, b["load"].values)
    many = an.load_distribution(QJ202, axial=[0, 500, 1000], radial=1000)
    assert many.sizes == {"case": 3, "ball": 11, "pair": 2}
    for name, var in many.data_vars.items():
        assert "units" in var.attrs, name
    assert many["contact_angle"].attrs["units"] == "rad"
    assert float(b["moment"][0]) == 2.0 and float(b["moment_y"][0]) == -2.0


def test_safety_factor_follows_stress_cubed():
    ds = an.load_distribution(QJ202, radial=[1000.0, 8000.0])
    s0 = ds["safety_factor_s0"].values
    np.testing.assert_allclose(s0, (4200e6 / ds["max_stress"].values) ** 3)
    assert s0[0] > s0[1]
    assert float(an.safety_factor(0.0)) == np.inf


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"radial": 1000}, "axial = '0 N': a single angular contact bearing with a free ring needs an axial load"),
        ({"radial": 1000, "axial": -100}, "axial = '-100 N'"),
        ({"axial": 100, "moment": 5}, "axial = '100 N': no equilibrium on the contact side"),
        ({"radial": 1000, "axial_condition": "sideways"}, "axial_condition = 'sideways': must be one of free"),
        ({"radial": 1000, "axial": 100, "tilt": "wobbly"}, "tilt = 'wobbly'"),
        ({"radial": "1 kg"}, "radial = '1 kg': unit kilogram is not a force"),
        ({"radial": [1.0, np.nan]}, "radial = "),
        ({"radial": 1000, "axial": 900, "ball_constant": "-1 N/m**1.5"}, "ball_constant"),
        ({"radial": [1, 2], "axial": [1, 2, 3]}, "loads = "),
    ],
)
def test_impossible_or_bad_loads_are_refused_in_one_line(kwargs, message):
    with pytest.raises(InputError) as info:
        an.load_distribution(B7202, **kwargs)
    assert str(info.value).startswith(message)
    assert "\n" not in str(info.value)


def test_ball_constant_override_with_units():
    a = an.load_distribution(QJ202, radial=1000, ball_constant="5.42e5 N/mm**1.5")
    b = an.load_distribution(QJ202, radial=1000, ball_constant=5.42e5 * 1e3**1.5)
    np.testing.assert_allclose(a["load"].values, b["load"].values)
    assert "user" in a.attrs["ball_constant"]


def test_summary_keys_match_the_issue():
    s = an.summary(an.load_distribution(QJ202, axial=500, radial=1000))
    assert list(s) == ["axial_displacement_um", "radial_displacement_um", "tilt_mrad", "max_contact_load_N",
                       "max_stress_MPa", "safety_factor_s0", "residual_N", "balls"]
    assert list(s["balls"][0]) == ["azimuth_deg", "pairs"]
    assert list(s["balls"][0]["pairs"][0]) == ["load_N", "contact_angle_deg", "max_stress_inner_MPa",
                                               "max_stress_outer_MPa"]
    json.dumps(s)


def test_stribeck_discrete_constant():
    assert an.stribeck_discrete_constant(11) == pytest.approx(11 / (1 + 2 * (np.cos(2 * np.pi / 11) ** 2.5
                                                                              + np.cos(4 * np.pi / 11) ** 2.5)))


def test_validity_warnings_follow_the_stated_limits():
    assert an.stress_warning(4200e6) is None and "s0 = 0.512" in an.stress_warning(5250e6)
    ds = an.load_distribution("QJ202", radial=500, moment=[5.0, 200.0, 3000.0])
    arm = ds.attrs["moment_arm_m"]
    for case in range(3):
        c = ds.isel(case=case)
        tilt = float(np.hypot(c["tilt_x"], c["tilt_y"]))
        beyond_tilt = arm * tilt**2 / 2 > an.SMALL_TILT_LIMIT * float(c["compression"].max())
        found = an.validity_warnings(ds, case)
        assert any("small-tilt" in w for w in found) == beyond_tilt
        assert any("ISO 76" in w for w in found) == (float(c["max_stress"]) > 4200e6)
    assert an.validity_warnings(ds, 0) == [] and len(an.validity_warnings(ds, 2)) == 2
