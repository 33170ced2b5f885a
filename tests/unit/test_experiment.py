"""Experiment pipeline: readers and their checks, preprocessing, orbit -> force -> stress, impacts, whirl."""

import math
from types import SimpleNamespace

import numpy as np
import pytest
import xarray as xr
from hypothesis import given, settings
from hypothesis import strategies as st

from auxbearing import get_bearing
from auxbearing.bearings.ballset import ballset_params, ballset_state
from auxbearing.common.errors import InputError
from auxbearing.experiment.io import read_csv, read_measured, read_netcdf
from auxbearing.experiment.orbit import (
    Preprocessing,
    contact_from_orbit,
    count_impacts,
    detect_drop,
    fit_clearance_circle,
    orbit_features,
    preprocess,
)
from auxbearing.experiment.run import peak_table
from auxbearing.planar.params import DropCase, Rotor
from auxbearing.planar.rig import planar_machine, run_drop

HEADER = "time [s], x [um], y [um], speed [rpm]\n"


def write(tmp_path, text, name="drop.csv"):
    path = tmp_path / name
    path.write_text(text)
    return path


def rows(n=200, dt=2e-5, start=0):
    return "".join(f"{k * dt:.6f}, {0.1 * k:.2f}, {-0.2 * k:.2f}, 6000\n" for k in range(start, start + n))


def test_csv_in_the_documented_format(tmp_path):
    path = write(tmp_path, "# a comment\n# rig = bench 2\n" + HEADER + rows())
    ds = read_csv(path)
    assert ds.sizes["time"] == 200
    assert ds.x.values[10] == pytest.approx(1e-6)  # 1.00 um
    assert ds.y.values[10] == pytest.approx(-2e-6)
    assert ds.speed.values[0] == pytest.approx(6000 * math.pi / 30)
    assert ds.attrs["sampling_rate_Hz"] == pytest.approx(50e3)
    assert ds.attrs["rig"] == "bench 2"


def test_units_as_options_aliases_and_other_delimiters(tmp_path):
    text = "t; x; y; trigger\n" + "".join(f"{k * 0.02:.3f}; {k * 1e-3:.6f}; 0.0; 1\n" for k in range(100))
    ds = read_csv(write(tmp_path, text), units={"time": "ms", "x": "mm", "y": "mm"})
    assert ds.time.values[1] == pytest.approx(2e-5)
    assert ds.x.values[1] == pytest.approx(1e-6)
    assert "speed" not in ds


@pytest.mark.parametrize(("text", "message"), [
    ("time [s], x [um], y [um]\n" + rows(100).replace("\n", "", 0), "3 fields"),
    (HEADER + rows(50) + "0.001000, , 1.0, 6000\n" + rows(50, start=51), "column 'x [um]', line 52: missing value"),
    (HEADER + rows(50) + "0.001000, abc, 1.0, 6000\n" + rows(50, start=51), "line 52: 'abc' is not a number"),
    (HEADER + rows(50) + "0.000900, 1.0, 1.0, 6000\n" + rows(50, start=51), "line 52: time 0.0009 s does not increase"),
    ("time [s], x, y [um]\n" + rows(100).replace(", 6000", ""), "column 'x' (line 1) has no unit"),
    ("time [s], x [kg], y [um]\n" + rows(100).replace(", 6000", ""), "not a length"),
    ("time [s], y [um], speed [rpm]\n" + "".join(f"{k * 2e-5:.6f}, 0, 6000\n" for k in range(100)), "no 'x' column"),
    (HEADER + rows(20), "20 samples"),
    (HEADER + "".join(f"{k * 1e-3:.6f}, 0, 0, 6000\n" for k in range(100)), "below 5000 Hz"),
    (HEADER + rows(50) + rows(50, start=52), "sampling interval"),
    ("# only a comment\n", "has no header"),
])
def test_csv_errors_name_the_column_and_line(tmp_path, text, message):
    if message == "3 fields":
        text = HEADER + rows(10) + "0.000200, 1.0, 2.0\n" + rows(100, start=11)
        message = "line 12: 3 fields, the header (line 1) has 4"
    with pytest.raises(InputError) as err:
        read_csv(write(tmp_path, text))
    assert message in str(err.value)
    assert "\n" not in str(err.value)


def test_missing_file_and_contradicting_unit(tmp_path):
    with pytest.raises(InputError, match="not found"):
        read_measured(tmp_path / "none.csv")
    with pytest.raises(InputError, match="contradicts"):
        read_csv(write(tmp_path, HEADER + rows()), units={"x": "mm"})


def test_netcdf_reader_and_its_checks(tmp_path):
    t = np.arange(300) * 2e-5
    ds = xr.Dataset({"x": ("time", np.zeros(300), {"units": "um"}), "y": ("time", t * 1e3, {"units": "mm"})},
                    coords={"time": ("time", t, {"units": "s"})})
    ds.to_netcdf(tmp_path / "d.nc")
    back = read_measured(tmp_path / "d.nc")
    assert back.y.values[-1] == pytest.approx(t[-1])
    del ds.x.attrs["units"]
    ds.to_netcdf(tmp_path / "e.nc")
    with pytest.raises(InputError, match="'x' has no 'units'"):
        read_netcdf(tmp_path / "e.nc")
    assert read_netcdf(tmp_path / "e.nc", units={"x": "um"}).sizes["time"] == 300
    ds["x"] = ("time", np.where(np.arange(300) == 7, np.nan, 0.0), {"units": "um"})
    ds.to_netcdf(tmp_path / "f.nc")
    with pytest.raises(InputError, match="'x', index 7: missing value"):
        read_netcdf(tmp_path / "f.nc")


def test_preprocessing_options_are_checked():
    with pytest.raises(InputError, match="offset"):
        Preprocessing(offset="centre")
    with pytest.raises(InputError, match="scale"):
        Preprocessing(scale=0.0)
    with pytest.raises(InputError, match="cutoff"):
        Preprocessing(cutoff=-1.0)


def test_drop_detection_of_a_free_fall():
    t = np.arange(0, 0.02, 2e-5)
    y = np.where(t > 0.005, -0.5 * 9.80665 * (t - 0.005) ** 2, 0.0)
    drop, info = detect_drop(t, np.zeros_like(t), y, 1e-8)
    assert drop == pytest.approx(0.005, abs=3e-5)
    assert info["levitated_y_m"] == pytest.approx(0.0)


def test_circle_fit_recovers_centre_and_radius():
    rng = np.random.default_rng(3)
    a = rng.uniform(-math.pi, math.pi, 4000)
    r = 200e-6 * rng.uniform(0.3, 1.0, a.size) ** 0.1  # most points near the wall, some inside
    x, y = 20e-6 + r * np.cos(a), -10e-6 + r * np.sin(a)
    fit = fit_clearance_circle(x, y, (0.0, 0.0))
    assert fit["centre"] == pytest.approx((20e-6, -10e-6), abs=0.3e-6)
    assert fit["radius"] == pytest.approx(200e-6, rel=2e-3)
    arc = np.radians(np.linspace(-120.0, -50.0, 500))  # 70 deg of wall: the radius is not determined
    with pytest.raises(InputError, match="too little"):
        fit_clearance_circle(200e-6 * np.cos(arc), 200e-6 * np.sin(arc), (0.0, 0.0))
    fixed = fit_clearance_circle(200e-6 * np.cos(arc), 200e-6 * np.sin(arc), (0.0, 10e-6), radius=200e-6)
    assert fixed["centre"] == pytest.approx((0.0, 0.0), abs=0.1e-6)


def test_count_impacts_merges_chatter():
    t = np.arange(0, 0.01, 1e-5)
    e = np.where((t % 0.004) < 0.0005, 2e-6, -1e-5)
    e[5] = -1e-5  # a one-sample gap inside the first contact is chatter, not a new impact
    out = count_impacts(t, e, 1e-6)
    assert out["impacts"] == 3
    assert out["first_impact_s"] == 0.0


@pytest.fixture(scope="module")
def short_drop():
    bearing = get_bearing("QJ202")
    case = DropCase(duration=0.02, output_step=1e-5)
    ds, summary = run_drop(bearing, Rotor(), case)
    return bearing, case, ds, summary


def test_force_and_stress_from_an_exact_orbit_match_the_simulation(short_drop):
    """The quasi-static split recovers the simulated force and stress from the orbit alone."""
    bearing, case, ds, summary = short_drop
    model = _model(bearing, Rotor(), case)
    c = contact_from_orbit(ds.rotor_x.values, ds.rotor_y.values, case.clearance, model.line_stiffness,
                           model.ballset, case.line_damping, case.output_step)
    # grid peak vs the exact (dense-output) peak: the 10 us grid loses < 0.5 %
    assert c["contact_force"].max() == pytest.approx(summary["peak_contact_force_N"], rel=0.02)
    assert c["max_ball_stress"].max() / 1e6 == pytest.approx(summary["peak_ball_stress_MPa"], rel=0.01)
    k = int(np.argmax(ds.normal_force.values))
    race = math.hypot(float(ds.race_x[k]), float(ds.race_y[k]))
    assert c["race_displacement"][k] == pytest.approx(race, rel=0.03)
    assert c["ball_load"].shape[1:] == (11, 2)
    assert np.all(c["contact_force"] >= 0.0)


@pytest.mark.slow
def test_orbit_features_of_a_backward_whirl():
    t = np.arange(-0.001, 0.1, 2e-5)
    s = 200e-6
    r = s + 2e-6
    w = -2 * math.pi * 80
    orbit = xr.Dataset({"x": ("time", r * np.cos(w * t)), "y": ("time", r * np.sin(w * t))}, coords={"time": t})
    model = _model(get_bearing("QJ202"), Rotor(), DropCase())
    ds, summary = orbit_features(orbit, s, model.line_stiffness, model.ballset, 0.0, 1e-8, 628.0)
    assert summary["whirl"] == "backward"
    assert summary["whirl_frequency_Hz"] == pytest.approx(80, abs=1.0)
    assert summary["impacts"] == 1  # one unbroken contact
    assert summary["peak_contact_force_N"] > 0
    assert ds.ball_load.dims == ("time", "ball", "pair")


def test_preprocess_removes_the_offset_and_finds_the_drop(short_drop):
    _, case, ds, _ = short_drop
    n_pre = 300
    t = np.arange(n_pre + ds.sizes["time"]) * case.output_step
    x = np.r_[np.zeros(n_pre), ds.rotor_x.values] + 30e-6
    y = np.r_[np.zeros(n_pre), ds.rotor_y.values] - 20e-6
    measured = xr.Dataset({"x": ("time", x), "y": ("time", y)}, coords={"time": t})
    _, info = preprocess(measured, Preprocessing(cutoff=None))
    assert info["offset_method"] == "start"
    assert (info["offset_x_m"], info["offset_y_m"]) == pytest.approx((30e-6, -20e-6), abs=1e-9)
    assert info["drop_time_s"] == pytest.approx(n_pre * case.output_step, abs=0.6e-3)


def test_peak_table_differences():
    table = peak_table({"measured": {"peak_contact_force_N": 100.0, "impacts": 4, "whirl": "none"},
                        "sim fitted": {"peak_contact_force_N": 110.0, "impacts": 5, "whirl": "none"}})
    assert table["columns"][-1] == "Δ fitted"
    assert table["rows"][0][1:] == ["100", "110", "+10.0 %"]


def _model(bearing, rotor, case):
    """Line stiffness and ball-set parameters of the paper's planar drop."""
    plane = planar_machine(bearing, rotor, case).planes[0]
    return SimpleNamespace(line_stiffness=plane.line_stiffness, ballset=ballset_params(bearing, case.ball_constant))


@settings(max_examples=25, deadline=None)
@given(excursion=st.floats(0.05e-6, 30e-6), angle=st.floats(-math.pi, math.pi))
def test_series_split_balances_and_grows(excursion, angle):
    """Line contact and ball set carry the same force, and more excursion means more force."""
    model = _model(get_bearing("QJ202"), Rotor(), DropCase())
    s = 200e-6
    r = np.array([s + excursion, s + 1.1 * excursion])
    c = contact_from_orbit(r * math.cos(angle), r * math.sin(angle), s, model.line_stiffness, model.ballset)
    u = c["race_displacement"]
    assert np.all((u > 0) & (u < r - s))
    line = model.line_stiffness * (r - s - u) ** (10 / 9)
    assert c["elastic_force"] == pytest.approx(line, rel=1e-9)
    disp = np.zeros((2, 5))
    disp[:, 1], disp[:, 2] = u * math.cos(angle), u * math.sin(angle)
    ball = -(ballset_state(disp, model.ballset).force[:, 1:3] @ [math.cos(angle), math.sin(angle)])
    assert line == pytest.approx(ball, rel=1e-10)  # the root to rounding (safeguarded Newton)
    assert c["elastic_force"][1] > c["elastic_force"][0]
    assert c["max_ball_stress"][1] > c["max_ball_stress"][0]
