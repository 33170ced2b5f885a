"""Figures of a measured drop beside its simulations (source paper Fig. 13 and Fig. 10-11 style).

A function that draws one panel takes ``ax=None``: given an axes it draws there and returns
that axes' figure, otherwise it makes a new :class:`matplotlib.figure.Figure`. The
multi-panel figures take ``fig=None`` and are built from the one-panel functions. Nothing
global changes on import.
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from auxbearing.plots._axes import axes_for, figure_for

_MEASURED = {"color": "black", "lw": 0.8}
_SIM_COLOURS = ("tab:blue", "tab:red", "tab:green")
_COORDINATES = ("x", "y")


def _sim_style(k: int) -> dict:
    return {"color": _SIM_COLOURS[k % len(_SIM_COLOURS)], "lw": 0.7, "alpha": 0.8}


def plot_orbit(ds: xr.Dataset, clearance: float, label: str = "measured", color: str = "black", ax=None) -> Figure:
    """One orbit of the journal centre [µm] after the drop, inside its clearance circle.

    Parameters
    ----------
    ds : xarray.Dataset
        ``rotor_x``, ``rotor_y`` (a simulation) or ``x``, ``y`` (a measurement) [m] over
        ``time`` [s] since the drop; samples before the drop are left out.
    clearance : float
        Radius of the clearance circle [m].
    label : str
        Legend entry and panel title.
    color : str
        Colour of the orbit line.
    ax : matplotlib.axes.Axes, optional
        Axes to draw in; default a new figure.
    """
    fig, ax = axes_for(ax, (4.4, 4.4))
    xk, yk = ("rotor_x", "rotor_y") if "rotor_x" in ds else ("x", "y")
    after = ds.time.values >= 0.0
    circle = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(clearance * 1e6 * np.cos(circle), clearance * 1e6 * np.sin(circle), color="0.6", ls="--", lw=1,
            label=f"clearance s = {clearance * 1e6:.1f} µm")
    ax.plot(ds[xk].values[after] * 1e6, ds[yk].values[after] * 1e6, color=color, lw=_MEASURED["lw"], label=label)
    ax.set_aspect("equal")
    ax.set_xlabel("x [µm]")
    ax.set_ylabel("y [µm] (up)")
    ax.set_title(label)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right", fontsize=7)
    return fig


def plot_orbits(measured: xr.Dataset, simulated: dict[str, xr.Dataset], clearance: float, title: str = "",
                clearances: dict[str, float] | None = None, fig=None) -> Figure:
    """Orbits of the journal centre inside the clearance circle: measured and each simulation.

    Parameters
    ----------
    measured : xarray.Dataset
        Orbit in the bearing frame (``x``, ``y`` [m] over ``time`` since the drop).
    simulated : dict
        Label -> Dataset with ``rotor_x``, ``rotor_y`` [m] (or ``x``, ``y``).
    clearance : float
        Radius of the clearance circle drawn with the measurement [m].
    title : str
    clearances : dict, optional
        Label -> clearance of that simulation [m]; default ``clearance``.
    fig : matplotlib.figure.Figure, optional
        Figure to draw in; default a new one.
    """
    n = 1 + len(simulated)
    fig = figure_for(fig, (4.2 * n, 4.4))
    axes = np.atleast_1d(fig.subplots(1, n, sharex=True, sharey=True))
    plot_orbit(measured, clearance, "measured", _MEASURED["color"], ax=axes[0])
    for k, (ax, (label, ds)) in enumerate(zip(axes[1:], simulated.items(), strict=True)):
        plot_orbit(ds, (clearances or {}).get(label, clearance), label, _SIM_COLOURS[k % len(_SIM_COLOURS)], ax=ax)
        ax.set_ylabel("")  # the shared y axis is labelled once, on the measured panel
    if title:
        fig.suptitle(title)
    return fig


def _time_panel(ax, measured: xr.Dataset, simulated: dict[str, xr.Dataset], measured_var: str, sim_var: str,
                scale: float, ylabel: str) -> None:
    """One quantity over time since the drop [ms]: from the measured orbit and from each simulation."""
    t = measured.time.values * 1e3
    ax.plot(t, measured[measured_var].values * scale, **_MEASURED, label="from the measured orbit")
    for k, (label, ds) in enumerate(simulated.items()):
        ax.plot(ds.time.values * 1e3, ds[sim_var].values * scale, **_sim_style(k), label=label)
    ax.set_ylabel(ylabel)
    ax.set_xlabel("Time since the drop [ms]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_xlim(0.0, t[-1])


def plot_contact_force(measured: xr.Dataset, simulated: dict[str, xr.Dataset], ax=None) -> Figure:
    """Rotor/race contact force [N] over time [ms]: from the measured orbit and from each simulation.

    ``measured`` needs ``contact_force`` [N]; each simulation ``normal_force`` [N] (a
    :func:`auxbearing.planar.rig.run_drop` Dataset).
    """
    fig, ax = axes_for(ax, (10, 3.2))
    _time_panel(ax, measured, simulated, "contact_force", "normal_force", 1.0, "Rotor/race contact force [N]")
    return fig


def plot_ball_stress(measured: xr.Dataset, simulated: dict[str, xr.Dataset], ax=None) -> Figure:
    """Max ball contact stress [MPa] over time [ms]: ``max_ball_stress`` [Pa] of the measurement and simulations."""
    fig, ax = axes_for(ax, (10, 3.2))
    _time_panel(ax, measured, simulated, "max_ball_stress", "max_ball_stress", 1e-6, "Max ball contact stress [MPa]")
    return fig


def plot_force_stress(measured: xr.Dataset, simulated: dict[str, xr.Dataset], title: str = "", fig=None) -> Figure:
    """Contact force and max ball stress over time: from the measured orbit and from the simulations.

    ``measured`` needs ``contact_force`` [N] and ``max_ball_stress`` [Pa]; each simulation
    ``normal_force`` and ``max_ball_stress`` (a :func:`auxbearing.planar.rig.run_drop` Dataset).
    """
    fig = figure_for(fig, (10, 6))
    ax_f, ax_s = fig.subplots(2, 1, sharex=True)
    plot_contact_force(measured, simulated, ax=ax_f)
    plot_ball_stress(measured, simulated, ax=ax_s)
    ax_f.set_xlabel("")  # the shared time axis is labelled once, under the lower panel
    if title:
        fig.suptitle(title)
    return fig


def plot_fit_coordinate(tau: np.ndarray, simulated: np.ndarray, measured: np.ndarray, coordinate: int = 0,
                        ax=None) -> Figure:
    """One coordinate (0: x, 1: y) [µm] of the fitted stretch over time [ms]: measured and best-fit simulation.

    ``tau`` [s] since the drop; ``simulated`` and ``measured`` [m] of shape (len(tau), 2), both
    through the same filter.
    """
    fig, ax = axes_for(ax, (5, 4.5))
    name = _COORDINATES[coordinate]
    ax.plot(tau * 1e3, measured[:, coordinate] * 1e6, **_MEASURED, label="measured (filtered)")
    ax.plot(tau * 1e3, simulated[:, coordinate] * 1e6, color="tab:red", lw=0.9, ls="--", label="fitted simulation")
    ax.set_xlabel("Time since the drop [ms]")
    ax.set_ylabel(f"{name} [µm]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def plot_fit_window(tau: np.ndarray, simulated: np.ndarray, measured: np.ndarray, title: str = "",
                    fig=None) -> Figure:
    """The fitted stretch: measured x(t), y(t) and the best-fit simulation (same filter) [um vs ms]."""
    fig = figure_for(fig, (10, 4.5))
    axes = fig.subplots(1, 2, sharex=True)
    for j, ax in enumerate(axes):
        plot_fit_coordinate(tau, simulated, measured, j, ax=ax)
    if title:
        fig.suptitle(title)
    return fig


def experiment_figures(drawing) -> dict:
    """The experiment's figures from what :func:`auxbearing.experiment.run.run_experiment` returns to draw.

    ``experiment_orbits``, ``experiment_force_stress`` and, after a fit, ``experiment_fit_window``.
    """
    d = drawing
    figures = {
        "experiment_orbits": plot_orbits(d.orbit, d.simulated, d.clearance, f"{d.label}: orbits in the clearance "
                                         "circle", d.clearances),
        "experiment_force_stress": plot_force_stress(d.measured, d.simulated, f"{d.label}: force and stress"),
    }
    if d.fitted_orbit is not None:
        tau, sim_xy, meas_xy = d.fitted_orbit
        figures["experiment_fit_window"] = plot_fit_window(tau, sim_xy, meas_xy, f"{d.label}: fitted stretch")
    return figures
