"""The paper's planar drop through the machine path: inputs, integration on the output grid, outputs."""

import math

import numpy as np
import pytest
import xarray as xr

from auxbearing import InputError, get_bearing
from auxbearing.analysis import drop as ad
from auxbearing.common.io import save_dataset
from auxbearing.planar import params as dp
from auxbearing.planar import rig
from auxbearing.planar.params import from_mapping, read_config
from auxbearing.planar.rig import planar_machine

QJ202 = get_bearing("QJ202")


# ----------------------------------------------------------------------------- integration and grid
def test_free_fall_is_exact_on_the_output_grid():
    """DOPRI5 and its dense output are exact for the quadratic free fall before the first impact."""
    ds, s = rig.run_drop(QJ202, dp.Rotor(eccentricity=0.0), dp.DropCase(duration=5e-3, output_step=1e-5))
    t = ds.time.values
    assert t.size == 501 and t[-1] == pytest.approx(5e-3)
    np.testing.assert_allclose(ds.rotor_y.values, -0.5 * 9.80665 * t**2, atol=1e-13)
    assert s["impacts"] == 0 and s["first_impact_ms"] is None and s["peak_contact_force_N"] == 0.0


def test_unbalanced_free_rotor_keeps_its_mass_centre_on_a_straight_line():
    """Without contact or gravity the mass centre moves uniformly and the journal centre circles it at
    radius e (exact kinematics of the unbalance, Newton-Euler about the mass centre)."""
    case = dp.DropCase(gravity=0.0, duration=4e-3, output_step=1e-4, rtol=1e-9, atol=1e-9)
    ds, _ = rig.run_drop(QJ202, dp.Rotor(eccentricity=1e-5), case)
    th = ds.rotor_angle.values
    gx = ds.rotor_x.values + 1e-5 * np.cos(th)
    gy = ds.rotor_y.values + 1e-5 * np.sin(th)
    np.testing.assert_allclose(gx, 1e-5, atol=1e-12)
    np.testing.assert_allclose(gy, 1e-5 * case.speed * ds.time.values, atol=1e-12)
    np.testing.assert_allclose(ds.rotor_speed.values, case.speed, rtol=1e-12)


def test_exact_peak_is_at_least_the_grid_peak_and_close_to_it():
    ds, s = rig.run_drop(QJ202, None, dp.DropCase(duration=0.012, output_step=1e-6))
    grid_peak = float(ds.normal_force.max())
    assert s["peak_contact_force_N"] >= grid_peak * (1 - 1e-9)
    assert s["peak_contact_force_N"] == pytest.approx(grid_peak, rel=2e-3)
    assert s["peak_ball_stress_MPa"] * 1e6 >= float(ds.max_ball_stress.max()) * (1 - 1e-9)


def test_first_impact_matches_free_fall_through_the_clearance():
    """The journal falls s = 0.2 mm; the race sags under its own weight meanwhile (sub-micrometre)."""
    _, s = rig.run_drop(QJ202, dp.Rotor(eccentricity=0.0), dp.DropCase(duration=0.008, output_step=1e-4))
    assert s["first_impact_ms"] == pytest.approx(1e3 * math.sqrt(2 * 2e-4 / 9.80665), rel=3e-3)


def test_progress_reports_do_not_change_the_result():
    case = dp.DropCase(duration=0.012, output_step=1e-4)
    seen = []
    _, quiet = rig.run_drop(QJ202, None, case)
    _, told = rig.run_drop(QJ202, None, case, progress=seen.append)
    assert seen[-1] == 1.0
    assert told["peak_contact_force_N"] == quiet["peak_contact_force_N"]


def test_a_non_finite_run_ends_with_a_verdict_not_a_hang():
    _, s = rig.run_drop(QJ202, None, dp.DropCase(gravity=1e300, duration=1e-3, output_step=1e-4))
    assert s["verdict"] != "ok" and s["peak_contact_force_N"] is None


def test_journal_orbit_raises_instead_of_padding_a_failed_run():
    """The driver the experiment fit uses: a failed integration raises (never padded and fitted)."""
    from auxbearing.common.errors import ConvergenceError

    machine = planar_machine(QJ202, dp.Rotor(), dp.DropCase(gravity=1e300, duration=1e-3))
    with pytest.raises(ConvergenceError, match="ended with"):
        ad.journal_orbit(machine, 1e-3, 1e-4)
    good = ad.journal_orbit(planar_machine(QJ202, dp.Rotor(eccentricity=0.0), dp.DropCase()), 2e-3, 1e-4)
    np.testing.assert_allclose(good[:, 1], -0.5 * 9.80665 * (np.arange(21) * 1e-4) ** 2, atol=1e-13)


# ----------------------------------------------------------------------------- outputs
def test_dataset_units_and_netcdf_round_trip(tmp_path):
    ds, s = rig.run_drop("7202", None, dp.DropCase(duration=0.01, output_step=1e-4))
    for name in ("rotor_x", "race_y", "normal_force", "friction_force", "penetration", "max_ball_stress",
                 "ball_load", "rotor_speed", "race_speed", "journal_x", "axial_force"):
        assert "units" in ds[name].attrs, name
    assert ds.ball_load.dims == ("time", "ball", "pair") and ds.sizes["pair"] == 1
    path = save_dataset(ds, tmp_path / "d.nc", {"x": 1})
    back = xr.load_dataset(path)
    np.testing.assert_allclose(back.normal_force.values, ds.normal_force.values)
    assert "peak_contact_force_N" in back.attrs["summary"]
    keys = {"peak_contact_force_N", "peak_ball_stress_MPa", "first_impact_ms", "impacts", "whirl",
            "whirl_frequency_Hz", "final_rotor_speed_rad_s", "final_race_speed_rad_s", "contact_fraction",
            "steps", "wall_time_s", "s0", "largest_bounce_um", "race_spin_up_ms", "verdict", "energy_balance_error"}
    assert keys <= set(s)


def test_four_point_has_two_pairs_and_same_geometry_otherwise():
    ds, _ = rig.run_drop("QJ202", None, dp.DropCase(duration=0.009, output_step=1e-4))
    assert ds.sizes["pair"] == 2 and ds.sizes["ball"] == 11


def test_static_safety_factor_iso76():
    assert ad.static_safety_factor(4200e6) == pytest.approx(1.0)
    assert ad.static_safety_factor(0.0) is None


# ----------------------------------------------------------------------------- inputs
@pytest.mark.parametrize(("kwargs", "message"), [
    ({"mass": 0.0}, "rotor.mass = '0 kg': must be > 0"),
    ({"polar_inertia": -1.0}, "rotor.polar_inertia"),
    ({"eccentricity": -1e-6}, "rotor.eccentricity = '-1 um': must be >= 0"),
    ({"eccentricity": "10 kg"}, "rotor.eccentricity = '10 kg': unit kilogram is not a length"),
])
def test_rotor_validation(kwargs, message):
    with pytest.raises(InputError, match=message.replace("(", r"\(")):
        dp.Rotor(**kwargs)


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
        dp.DropCase(**kwargs)


def test_strings_with_units_in_the_python_api():
    """Issue 10 item 9: the API takes strings with units as the command line does; a number is SI."""
    case = dp.DropCase(speed="6000 rpm", clearance="0.2 mm", duration="150 ms")
    assert case.speed == pytest.approx(200 * math.pi) and case.clearance == pytest.approx(2e-4)
    assert dp.DropCase(speed=628.0).speed == 628.0
    assert dp.DropCase(speed="100 Hz").speed == pytest.approx(200 * math.pi)  # revolutions per second
    assert dp.Rotor(eccentricity="10 um").eccentricity == pytest.approx(1e-5)


def test_rotor_radius_plus_clearance_must_equal_bore_radius():
    with pytest.raises(InputError, match=r"must equal the race bore radius 7.5 mm"):
        planar_machine(QJ202, dp.Rotor(radius=7.0e-3), dp.DropCase())
    m = planar_machine(QJ202, dp.Rotor(radius=7.4e-3), dp.DropCase(clearance=1e-4))
    assert m.planes[0].journal_radius == pytest.approx(7.4e-3)
    with pytest.raises(InputError, match="radial_clearance = '8 mm': must be below the race bore radius"):
        planar_machine(QJ202, dp.Rotor(), dp.DropCase(clearance=8e-3))


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
    path.write_text('[static]\nx = 1\n')
    with pytest.raises(InputError, match="unknown table"):
        read_config(path)
