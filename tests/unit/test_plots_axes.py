"""Plot functions draw into the caller's axes (``ax=``) or figure (``fig=``), or make a new Figure."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr
from matplotlib.figure import Figure

from auxbearing import get_bearing
from auxbearing.analysis.contact import contact_map
from auxbearing.analysis.statics import load_distribution
from auxbearing.plots import contact, experiment, static

#: the quick loop leaves this module to `make test` (its share of the loop's time against what it guards)
pytestmark = pytest.mark.slow

LOADS = np.array([0.0, 200.0, 400.0])


@pytest.fixture(scope="module")
def inputs() -> dict:
    four, angular = get_bearing("QJ202"), get_bearing("7202")
    cmap = contact_map(four, 1000.0, np.array([10.0, 20.0, 30.0, 40.0]), np.array([0.51, 0.52, 0.53]))
    radial_sweep = load_distribution(four, axial=500.0, radial=np.array([250.0, 1000.0]))
    axial_sweep = load_distribution(four, axial=np.array([0.0, 500.0]), radial=1000.0)
    fa, fr = np.meshgrid(LOADS, LOADS, indexing="ij")
    grid = load_distribution(four, axial=fa.ravel(), radial=fr.ravel())
    fig7 = xr.Dataset(
        {name: (("axial_load", "radial_load"), grid[name].values.reshape(fa.shape))
         for name in ("axial_displacement", "radial_displacement")},
        coords={"axial_load": LOADS, "radial_load": LOADS}, attrs={"title": "Fig. 7 (small grid)"})
    r = np.array([0.0, 500.0, 1000.0])
    runs = [load_distribution(four, radial=r),
            load_distribution(angular, radial=r, axial_condition="located", tilt="fixed")]
    fig8 = xr.Dataset({"max_stress": (("bearing", "radial_load"), np.stack([d["max_stress"].values for d in runs])),
                       "type": ("bearing", [four.type, angular.type])},
                      coords={"bearing": [four.name, angular.name], "radial_load": r})
    t = np.linspace(-1e-3, 5e-3, 61)
    s = 2e-4
    measured = xr.Dataset({"x": ("time", s * np.cos(3e3 * t)), "y": ("time", -s * np.abs(np.sin(3e3 * t))),
                           "contact_force": ("time", 500.0 * np.abs(np.sin(2e3 * t))),
                           "max_ball_stress": ("time", 1.5e9 * np.abs(np.sin(2e3 * t)))}, coords={"time": t})
    sim = xr.Dataset({"rotor_x": ("time", 0.9 * s * np.cos(3e3 * t)), "rotor_y": ("time", -0.9 * s * np.ones_like(t)),
                      "normal_force": ("time", 450.0 * np.abs(np.cos(2e3 * t))),
                      "max_ball_stress": ("time", 1.4e9 * np.abs(np.cos(2e3 * t)))}, coords={"time": t})
    tau = np.linspace(0.0, 2e-3, 21)
    xy = np.column_stack([s * np.cos(3e3 * tau), s * np.sin(3e3 * tau)])
    return {"map": cmap, "radial": radial_sweep, "axial": axial_sweep, "fig7": fig7, "fig8": fig8,
            "measured": measured, "sims": {"simulated, configured": sim, "simulated, fitted": sim}, "s": s,
            "tau": tau, "xy": xy}


SINGLE = {
    "contact_angle_cut": lambda d, ax: contact.plot_contact_angle_cut(d["map"], "approach", ax=ax),
    "groove_ratio_cut": lambda d, ax: contact.plot_groove_ratio_cut(d["map"], "max_stress", ax=ax),
    "contact_map": lambda d, ax: contact.plot_contact_map(d["map"], ax=ax),
    "contact_angle_profile": lambda d, ax: static.plot_contact_angle_profile(d["axial"], 2, ax=ax),
    "axial_displacement": lambda d, ax: static.plot_axial_displacement(d["fig7"], 3, ax=ax),
    "radial_displacement": lambda d, ax: static.plot_radial_displacement(d["fig7"], 3, ax=ax),
    "max_stress": lambda d, ax: static.plot_max_stress(d["fig8"], ax=ax),
    "orbit": lambda d, ax: experiment.plot_orbit(d["measured"], d["s"], ax=ax),
    "contact_force": lambda d, ax: experiment.plot_contact_force(d["measured"], d["sims"], ax=ax),
    "ball_stress": lambda d, ax: experiment.plot_ball_stress(d["measured"], d["sims"], ax=ax),
    "fit_coordinate": lambda d, ax: experiment.plot_fit_coordinate(d["tau"], d["xy"], 0.9 * d["xy"], 1, ax=ax),
}


@pytest.mark.parametrize("name", sorted(SINGLE))
def test_single_panel_draws_into_the_given_axes(inputs, name):
    mine = Figure()
    left, right = mine.subplots(1, 2)
    out = SINGLE[name](inputs, right)
    assert out is mine
    assert right.has_data() and right.get_xlabel() and right.get_ylabel()
    assert not left.has_data()


@pytest.mark.parametrize("name", sorted(SINGLE))
def test_single_panel_without_axes_makes_a_new_figure(inputs, name):
    first = SINGLE[name](inputs, None)
    second = SINGLE[name](inputs, None)
    assert isinstance(first, Figure) and first is not second
    assert first.axes[0].has_data()
    # the contact map adds a colour bar, every other single-panel plot one axes
    assert len(first.axes) == (2 if name == "contact_map" else 1)


MULTI = {  # name -> (call, number of panels, left titles of the panels)
    "contact_angle_sweep": (lambda d, fig: contact.plot_contact_angle_sweep(d["map"], fig=fig), 2, ["(a)", "(b)"]),
    "groove_ratio_sweep": (lambda d, fig: contact.plot_groove_ratio_sweep(d["map"], 30.0, fig=fig), 2,
                           ["(a)", "(b)"]),
    "contact_angles": (lambda d, fig: static.plot_contact_angles(d["radial"], d["axial"], fig=fig), 4,
                       ["(a) pair 1, axial load 500 N", "(b) pair 2, axial load 500 N",
                        "(c) pair 1, radial load 1000 N", "(d) pair 2, radial load 1000 N"]),
    "displacements": (lambda d, fig: static.plot_displacements(d["fig7"], 3, fig=fig), 2, ["(a)", "(b)"]),
    "orbits": (lambda d, fig: experiment.plot_orbits(d["measured"], d["sims"], d["s"], "t", fig=fig), 3, None),
    "force_stress": (lambda d, fig: experiment.plot_force_stress(d["measured"], d["sims"], "t", fig=fig), 2, None),
    "fit_window": (lambda d, fig: experiment.plot_fit_window(d["tau"], d["xy"], d["xy"], "t", fig=fig), 2, None),
}


@pytest.mark.parametrize("name", sorted(MULTI))
def test_multi_panel_keeps_its_panels(inputs, name):
    call, panels, titles = MULTI[name]
    fig = call(inputs, None)
    assert isinstance(fig, Figure)
    assert len(fig.axes) == panels
    assert all(ax.has_data() for ax in fig.axes)
    if titles is not None:
        assert [ax.get_title(loc="left") for ax in fig.axes] == titles
    mine = Figure()
    assert call(inputs, mine) is mine and len(mine.axes) == panels


def test_multi_panel_keeps_old_positional_calls(inputs):
    d = inputs
    assert contact.plot_contact_angle_sweep(d["map"], 0.52).get_suptitle().startswith("Fig. 2: contact angle sweep")
    title = contact.plot_groove_ratio_sweep(d["map"], 20.0).get_suptitle()
    assert title.startswith("Fig. 3: groove ratio sweep, α = 20")
    assert static.plot_displacements(d["fig7"], 2).get_suptitle() == "Fig. 7 (small grid)"
    orbits = experiment.plot_orbits(d["measured"], d["sims"], d["s"], "title", {"simulated, fitted": 1e-4})
    assert "s = 100.0 µm" in orbits.axes[2].get_legend_handles_labels()[1][0]
    assert [ax.get_ylabel() for ax in orbits.axes] == ["y [µm] (up)", "", ""]
    force_stress = experiment.plot_force_stress(d["measured"], d["sims"], "title")
    assert [ax.get_xlabel() for ax in force_stress.axes] == ["", "Time since the drop [ms]"]


def test_contact_map_recommended_window_box(inputs):
    fig = contact.plot_contact_map(inputs["map"])
    box = fig.axes[0].patches[-1]
    assert box.get_xy() == (0.51, 15.0)
    assert box.get_width() == pytest.approx(0.01) and box.get_height() == pytest.approx(30.0)


def test_contact_angle_profile_labels_the_swept_load(inputs):
    ax = static.plot_contact_angle_profile(inputs["radial"]).axes[0]
    assert ax.get_legend().get_title().get_text() == "radial load"
    assert ax.get_legend_handles_labels()[1] == ["250 N", "1000 N"]
    ax = static.plot_contact_angle_profile(inputs["axial"]).axes[0]
    assert ax.get_legend().get_title().get_text() == "axial load"


def test_sweep_panel_rejects_an_unknown_quantity(inputs):
    with pytest.raises(ValueError, match="quantity"):
        contact.plot_contact_angle_cut(inputs["map"], "stiffness")
