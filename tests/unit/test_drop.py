"""Unit tests of the rotor-drop model: forces by free-body sketch, inputs, integrator, outputs."""

import math
import re

import numpy as np
import pytest
import xarray as xr

from auxbearing import InputError, get_bearing
from auxbearing import drop as ad
from auxbearing.drop_params import from_mapping, read_config
from auxbearing.core import drop as cd
from auxbearing.io import save_dataset

QJ202 = get_bearing("QJ202")


def _model(**case):
    return ad.build_model(QJ202, ad.Rotor(), ad.DropCase(**case))


def _state(**values):
    names = ("xr", "yr", "thr", "xb", "yb", "thb", "vxr", "vyr", "wr", "vxb", "vyb", "wb")
    y = np.zeros(12)
    for k, v in values.items():
        y[names.index(k)] = v
    return y


# ----------------------------------------------------------------------------- free-body checks
@pytest.mark.parametrize("angle_deg", [-150.0, -90.0, -30.0, 0.0, 45.0, 100.0, 179.0, 225.0])
def test_contact_pushes_rotor_back_toward_race_centre_in_every_quadrant(angle_deg):
    """NOTES item 2: the normal force on the rotor points from the contact to the race centre."""
    m = _model(gravity=0.0, sliding_friction=0.0, rolling_friction=0.0, line_damping=0.0, ball_damping=0.0)
    p = m.params.copy()
    p[cd.P_E] = 0.0
    a = math.radians(angle_deg)
    dist = p[cd.P_S] + 2e-6
    y = _state(xr=dist * math.cos(a), yr=dist * math.sin(a))
    out = np.zeros(12)
    cd.rhs(y, p, m.ballset, out)
    acc = out[6:8] / np.linalg.norm(out[6:8])
    np.testing.assert_allclose(acc, [-math.cos(a), -math.sin(a)], atol=1e-12)
    # the race is pushed the other way (and is held by the ball set, at rest in the centre)
    np.testing.assert_allclose(out[9:11] / np.linalg.norm(out[9:11]), [math.cos(a), math.sin(a)], atol=1e-12)
    delta, fn, *_ = cd.contact_state(y, p, m.ballset)
    assert delta == pytest.approx(2e-6)
    assert fn == pytest.approx(p[cd.P_KL] * 2e-6 ** (10 / 9))


def test_normal_force_never_pulls():
    """Eq. 19 clipped: a separating rotor with large damping feels no (negative) force."""
    m = _model()
    y = _state(yr=-(2e-4 + 1e-8), vyr=1.0)  # barely touching, leaving fast
    delta, fn, *_ = cd.contact_state(y, m.params, m.ballset)
    assert delta > 0 and fn == 0.0


def test_friction_slows_rotor_spins_race_up_and_acts_against_slip():
    """NOTES item 3, at the bottom: rotor CCW, race at rest -> rotor decelerates, race accelerates,
    and the friction on the rotor points along -x (against the rotor surface motion there)."""
    m = _model(gravity=0.0, line_damping=0.0, rolling_friction=0.0)
    p = m.params.copy()
    p[cd.P_E] = 0.0
    y = _state(yr=-(2e-4 + 2e-6), wr=628.0)
    out = np.zeros(12)
    cd.rhs(y, p, m.ballset, out)
    assert out[8] < 0.0 and out[11] > 0.0
    assert out[6] < 0.0
    _, fn, ft, vs, *_ = cd.contact_state(y, p, m.ballset)
    assert vs == pytest.approx(628.0 * p[cd.P_R])
    assert ft == pytest.approx(-0.2 * fn, rel=1e-9)  # full Coulomb far from zero slip


def test_friction_vanishes_at_zero_slip():
    m = _model(gravity=0.0)
    p = m.params
    w_r = 628.0
    y = _state(yr=-(2e-4 + 2e-6), wr=w_r, wb=w_r * p[cd.P_R] / (p[cd.P_R] + p[cd.P_S]))
    _, fn, ft, vs, *_ = cd.contact_state(y, p, m.ballset)
    assert fn > 0 and abs(vs) < 1e-12 and abs(ft) < 1e-9


def test_rolling_resistance_brakes_the_race_and_stops_at_rest():
    m = _model(ball_damping=0.0)
    p = m.params
    out = np.zeros(12)
    loaded = _state(yb=-2e-6, wb=300.0)
    cd.rhs(loaded, p, m.ballset, out)
    assert out[11] < 0.0
    cd.rhs(_state(yb=-2e-6), p, m.ballset, out)
    assert out[11] == 0.0


def test_unbalanced_free_rotor_keeps_its_mass_centre_on_a_straight_line():
    """Newton-Euler about G: without contact or gravity the mass centre moves uniformly and the
    journal centre circles it at radius e (exact kinematics of the unbalance)."""
    case = ad.DropCase(gravity=0.0, duration=4e-3, output_step=1e-4, rtol=1e-9, atol=1e-9)
    ds, _ = ad.run_drop(QJ202, ad.Rotor(eccentricity=1e-5), case)
    th = ds.rotor_angle.values
    gx = ds.rotor_x.values + 1e-5 * np.cos(th)
    gy = ds.rotor_y.values + 1e-5 * np.sin(th)
    w = case.speed
    np.testing.assert_allclose(gx, 1e-5 - 0 * ds.time.values, atol=1e-12)
    np.testing.assert_allclose(gy, 1e-5 * w * ds.time.values, atol=1e-12)
    np.testing.assert_allclose(ds.rotor_speed.values, w, rtol=1e-12)


# ----------------------------------------------------------------------------- integrator and grid
def test_free_fall_is_exact_on_the_output_grid():
    """DOPRI5 and its dense output are exact for the quadratic free fall before the first impact."""
    ds, s = ad.run_drop(QJ202, ad.Rotor(eccentricity=0.0), ad.DropCase(duration=5e-3, output_step=1e-5))
    t = ds.time.values
    assert t.size == 501 and t[-1] == pytest.approx(5e-3)
    np.testing.assert_allclose(ds.rotor_y.values, -0.5 * 9.80665 * t**2, atol=1e-13)
    assert s["impacts"] == 0 and s["first_impact_ms"] is None and s["peak_contact_force_N"] == 0.0


def test_chunking_for_the_progress_bar_does_not_change_the_result():
    case = ad.DropCase(duration=0.012, output_step=1e-4)
    _, one = ad.run_drop(QJ202, None, case, chunks=1)
    _, many = ad.run_drop(QJ202, None, case, chunks=17)
    assert many["peak_contact_force_N"] == pytest.approx(one["peak_contact_force_N"], rel=1e-4)
    assert many["first_impact_ms"] == pytest.approx(one["first_impact_ms"], rel=1e-9)


def test_exact_peak_is_at_least_the_grid_peak_and_close_to_it():
    ds, s = ad.run_drop(QJ202, None, ad.DropCase(duration=0.012, output_step=1e-6))
    grid_peak = float(ds.normal_force.max())
    assert s["peak_contact_force_N"] >= grid_peak * (1 - 1e-9)
    assert s["peak_contact_force_N"] == pytest.approx(grid_peak, rel=2e-3)
    assert s["peak_ball_stress_MPa"] * 1e6 >= float(ds.max_ball_stress.max()) * (1 - 1e-9)


def test_first_impact_matches_free_fall_through_the_clearance():
    """Rotor falls s = 0.2 mm; the race sags under its own weight meanwhile (sub-micrometre)."""
    _, s = ad.run_drop(QJ202, ad.Rotor(eccentricity=0.0), ad.DropCase(duration=0.008, output_step=1e-4))
    assert s["first_impact_ms"] == pytest.approx(1e3 * math.sqrt(2 * 2e-4 / 9.80665), rel=3e-3)


# ----------------------------------------------------------------------------- outputs
def test_dataset_units_and_netcdf_round_trip(tmp_path):
    ds, s = ad.run_drop("7202", None, ad.DropCase(duration=0.01, output_step=1e-4))
    for name in ("rotor_x", "race_y", "normal_force", "friction_force", "penetration", "max_ball_stress",
                 "ball_load", "whirl_angle", "rotor_speed", "race_speed"):
        assert "units" in ds[name].attrs, name
    assert ds.ball_load.dims == ("time", "ball", "pair") and ds.sizes["pair"] == 1
    path = save_dataset(ds, tmp_path / "d.nc", {"x": 1})
    back = xr.load_dataset(path)
    np.testing.assert_allclose(back.normal_force.values, ds.normal_force.values)
    assert "peak_contact_force_N" in back.attrs["summary"]
    issue_keys = {"peak_contact_force_N", "peak_ball_stress_MPa", "first_impact_ms", "impacts", "whirl",
                  "whirl_frequency_Hz", "final_rotor_speed_rad_s", "final_race_speed_rad_s", "contact_fraction",
                  "steps", "wall_time_s", "s0", "largest_bounce_um", "race_spin_up_ms"}
    assert issue_keys <= set(s)


def test_four_point_has_two_pairs_and_same_geometry_otherwise():
    ds, _ = ad.run_drop("QJ202", None, ad.DropCase(duration=0.009, output_step=1e-4))
    assert ds.sizes["pair"] == 2 and ds.sizes["ball"] == 11


@pytest.mark.parametrize(("sign", "expected"), [(1, "forward"), (-1, "backward")])
def test_whirl_direction_from_the_complex_spectrum(sign, expected):
    t = np.arange(0, 0.1, 1e-5)
    x = 1.9e-4 * np.cos(sign * 2 * np.pi * 120 * t) + 3e-6 * np.random.default_rng(1).standard_normal(t.size)
    y = 1.9e-4 * np.sin(sign * 2 * np.pi * 120 * t)
    w = ad.detect_whirl(t, x, y, 2e-4)
    assert w["whirl"] == expected and w["whirl_frequency_Hz"] == pytest.approx(120.0, abs=10.0)
    # the spin direction defines "forward"
    assert ad.detect_whirl(t, x, y, 2e-4, spin=-1.0)["whirl"] != expected


def test_bouncing_or_rocking_is_not_whirl():
    t = np.arange(0, 0.1, 1e-5)
    vertical = ad.detect_whirl(t, 0 * t, -2e-4 + 5e-5 * np.abs(np.sin(2 * np.pi * 30 * t)), 2e-4)
    rocking = ad.detect_whirl(t, 1e-4 * np.sin(2 * np.pi * 25 * t), -2e-4 + 0 * t, 2e-4)
    resting = ad.detect_whirl(t, 1e-7 * np.cos(2 * np.pi * 50 * t), 1e-7 * np.sin(2 * np.pi * 50 * t), 2e-4)
    assert vertical["whirl"] == rocking["whirl"] == resting["whirl"] == "none"
    assert vertical["whirl_frequency_Hz"] is None


# ----------------------------------------------------------------------------- inputs
@pytest.mark.parametrize(("kwargs", "message"), [
    ({"mass": 0.0}, "rotor.mass = '0 kg': must be > 0"),
    ({"polar_inertia": -1.0}, "rotor.polar_inertia"),
    ({"eccentricity": -1e-6}, "rotor.eccentricity = '-1 um': must be >= 0"),
])
def test_rotor_validation(kwargs, message):
    with pytest.raises(InputError, match=message.replace("(", r"\(")):
        ad.Rotor(**kwargs)


@pytest.mark.parametrize(("kwargs", "message"), [
    ({"clearance": 0.0}, "drop.clearance = '0 mm': must be > 0"),
    ({"sliding_friction": -0.1}, r"drop.sliding_friction = -0.1: must lie in \[0, 1\]"),
    ({"rolling_friction": 1.1}, r"drop.rolling_friction = 1.1: must lie in \[0, 1\]"),
    ({"race_mass": -1.0}, "drop.race_mass"),
    ({"race_inertia": 0.0}, "drop.race_inertia"),
    ({"rtol": 0.5}, r"drop.rtol = 0.5: must lie in \(0, 0.01\]"),
    ({"duration": 1e-3, "output_step": 2e-3}, "must not exceed drop.duration"),
    ({"start_x": 3e-4}, "inside the clearance circle"),
    ({"speed": float("nan")}, "drop.speed"),
    ({"ball_constant": -1.0}, "drop.ball_constant"),
])
def test_drop_case_validation(kwargs, message):
    with pytest.raises(InputError, match=message):
        ad.DropCase(**kwargs)


def test_rotor_radius_plus_clearance_must_equal_bore_radius():
    with pytest.raises(InputError, match=r"must equal the race bore radius 7.5 mm"):
        ad.build_model(QJ202, ad.Rotor(radius=7.0e-3), ad.DropCase())
    m = ad.build_model(QJ202, ad.Rotor(radius=7.4e-3), ad.DropCase(clearance=1e-4))
    assert m.rotor_radius == pytest.approx(7.4e-3)
    with pytest.raises(InputError, match=re.escape("drop.clearance = '8 mm': must be below the race bore radius")):
        ad.build_model(QJ202, ad.Rotor(), ad.DropCase(clearance=8e-3))


def test_messages_are_one_line():
    for bad in ({"clearance": "-2 mm"}, {"speed": "6000 kg"}, {"sliding_friction": "abc"}, {"bogus": 1}):
        with pytest.raises(InputError) as err:
            from_mapping(bad, "drop")
        assert "\n" not in str(err.value) and str(err.value).startswith("drop.")


def test_toml_sections_with_units(tmp_path):
    path = tmp_path / "case.toml"
    path.write_text('[rotor]\nmass = "2 kg"\neccentricity = "5 um"\n\n[drop]\nclearance = "0.15 mm"\n'
                    'speed = "3000 rpm"\nball_constant = "5.42e5 N/mm**1.5"\nsliding_friction = 0.1\n')
    bearing, rotor_kw, drop_kw = read_config(path)
    assert bearing is None
    assert rotor_kw == {"mass": 2.0, "eccentricity": pytest.approx(5e-6)}
    assert drop_kw["clearance"] == pytest.approx(1.5e-4)
    assert drop_kw["speed"] == pytest.approx(100 * math.pi)
    assert drop_kw["ball_constant"] == pytest.approx(1.714e10, rel=1e-3)
    path.write_text('[drop]\nclearance = 0.2\n')
    with pytest.raises(InputError, match=r"drop.clearance = 0.2: needs a unit"):
        read_config(path)


def test_static_safety_factor_iso76():
    assert ad.static_safety_factor(4200e6) == pytest.approx(1.0)
    assert ad.static_safety_factor(0.0) is None


def test_stale_numba_cache_is_dropped_when_the_ball_set_source_changes(tmp_path):
    (tmp_path / "drop.integrate-1.py312.nbi").write_text("x")
    (tmp_path / "drop.integrate-1.py312.1.nbc").write_text("x")
    (tmp_path / "other.f-1.nbi").write_text("x")
    assert cd.invalidate_stale_cache(tmp_path)  # no stamp yet: treated as stale
    assert sorted(p.name for p in tmp_path.iterdir()) == ["drop.dependency-stamp", "other.f-1.nbi"]
    (tmp_path / "drop.integrate-1.py312.nbi").write_text("x")
    assert not cd.invalidate_stale_cache(tmp_path)  # same sources: cache kept
    (tmp_path / "drop.dependency-stamp").write_text("an older ball-set model")
    assert cd.invalidate_stale_cache(tmp_path)
    assert not (tmp_path / "drop.integrate-1.py312.nbi").exists()


def test_rhs_ball_set_force_is_the_shared_radial_support():
    """The RHS takes the force from the shared model's accumulate(); it must equal radial_support."""
    from auxbearing.core.ballset import radial_support

    m = _model(gravity=0.0, ball_damping=0.0, rolling_friction=0.0)
    for xb, yb in ((3e-6, -4e-6), (-1e-6, 2e-6), (0.0, -1e-5)):
        out = np.zeros(12)
        cd.rhs(_state(xb=xb, yb=yb), m.params, m.ballset, out)
        fx, fy, _, _ = radial_support(xb, yb, m.ballset)
        np.testing.assert_allclose(out[9:11] * m.params[cd.P_MB], [fx, fy], rtol=1e-12)


def test_a_blown_up_state_stops_with_a_convergence_error_not_a_hang():
    from auxbearing.errors import ConvergenceError

    m = _model()
    y = m.y0.copy()
    y[1] = float("nan")
    grid = np.empty((3, 12))
    stats = cd.new_stats(1e-6)
    cd.integrate(y, 0.0, 1e-3, m.params, m.ballset, 1e-6, m.atol, 5e-5, 5e-4, 1, grid, stats)
    assert stats[cd.S_FAIL] == 0.0
    with pytest.raises(ConvergenceError, match="stalled at t = 0 ms"):
        ad.run_drop(QJ202, None, ad.DropCase(gravity=1e300, duration=1e-3, output_step=1e-4))


def test_chunk_ends_landing_within_roundoff_do_not_shrink_the_next_step():
    """A step shortened to land on a chunk end must not become the next step's proposal (a run
    once underflowed at a chunk boundary reached within roundoff)."""
    m = ad.build_model(QJ202, ad.Rotor(eccentricity=0.0), ad.DropCase())
    y = m.y0.copy()
    grid = np.empty((2, 12))
    stats = cd.new_stats(1e-6)
    for t0, t1 in ((0.0, 5e-3), (5e-3, 5e-3 + 1e-16), (5e-3 + 1e-16, 6e-3)):
        cd.integrate(y, t0, t1, m.params, m.ballset, 1e-6, m.atol, 5e-5, 1.0, 1, grid, stats)
        assert stats[cd.S_FAIL] < 0.0
        assert stats[cd.S_H] > 1e-7
    np.testing.assert_allclose(y[1], -0.5 * 9.80665 * 6e-3**2, rtol=1e-9)
