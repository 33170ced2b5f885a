"""Figures of a measured drop beside its simulations (source paper Fig. 13 and Fig. 10-11 style).

Each function returns a :class:`matplotlib.figure.Figure`; nothing global changes on import.
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

_MEASURED = {"color": "black", "lw": 0.8}
_SIM_COLOURS = ("tab:blue", "tab:red", "tab:green")


def plot_orbits(measured: xr.Dataset, simulated: dict[str, xr.Dataset], clearance: float, title: str = "",
                clearances: dict[str, float] | None = None) -> Figure:
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
    """
    n = 1 + len(simulated)
    fig = Figure(figsize=(4.2 * n, 4.4), layout="constrained")
    axes = np.atleast_1d(fig.subplots(1, n, sharex=True, sharey=True))
    circle = np.linspace(0.0, 2.0 * np.pi, 361)
    panels = [("measured", measured, "x", "y", _MEASURED, clearance)]
    for k, (label, ds) in enumerate(simulated.items()):
        xk, yk = ("rotor_x", "rotor_y") if "rotor_x" in ds else ("x", "y")
        panels.append((label, ds, xk, yk, {"color": _SIM_COLOURS[k % 3], "lw": 0.8},
                       (clearances or {}).get(label, clearance)))
    for ax, (label, ds, xk, yk, style, s) in zip(axes, panels, strict=True):
        after = ds.time.values >= 0.0
        ax.plot(s * 1e6 * np.cos(circle), s * 1e6 * np.sin(circle), color="0.6", ls="--", lw=1,
                label=f"clearance s = {s * 1e6:.1f} µm")
        ax.plot(ds[xk].values[after] * 1e6, ds[yk].values[after] * 1e6, **style, label=label)
        ax.set_aspect("equal")
        ax.set_xlabel("x [µm]")
        ax.set_title(label)
        ax.grid(alpha=0.3)
        ax.legend(loc="upper right", fontsize=7)
    axes[0].set_ylabel("y [µm] (up)")
    if title:
        fig.suptitle(title)
    return fig


def plot_force_stress(measured: xr.Dataset, simulated: dict[str, xr.Dataset], title: str = "") -> Figure:
    """Contact force and max ball stress over time: from the measured orbit and from the simulations.

    ``measured`` needs ``contact_force`` [N] and ``max_ball_stress`` [Pa]; each simulation
    ``normal_force`` and ``max_ball_stress`` (a :func:`auxbearing.drop.run_drop` Dataset).
    """
    fig = Figure(figsize=(10, 6), layout="constrained")
    ax_f, ax_s = fig.subplots(2, 1, sharex=True)
    t = measured.time.values * 1e3
    ax_f.plot(t, measured.contact_force.values, **_MEASURED, label="from the measured orbit")
    ax_s.plot(t, measured.max_ball_stress.values / 1e6, **_MEASURED, label="from the measured orbit")
    for k, (label, ds) in enumerate(simulated.items()):
        style = {"color": _SIM_COLOURS[k % 3], "lw": 0.7, "alpha": 0.8}
        ts = ds.time.values * 1e3
        ax_f.plot(ts, ds.normal_force.values, **style, label=label)
        ax_s.plot(ts, ds.max_ball_stress.values / 1e6, **style, label=label)
    ax_f.set_ylabel("Rotor/race contact force [N]")
    ax_s.set_ylabel("Max ball contact stress [MPa]")
    ax_s.set_xlabel("Time since the drop [ms]")
    for ax in (ax_f, ax_s):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        ax.set_xlim(0.0, t[-1])
    if title:
        fig.suptitle(title)
    return fig


def plot_fit_window(tau: np.ndarray, simulated: np.ndarray, measured: np.ndarray, title: str = "") -> Figure:
    """The fitted stretch: measured x(t), y(t) and the best-fit simulation (same filter) [um vs ms]."""
    fig = Figure(figsize=(10, 4.5), layout="constrained")
    axes = fig.subplots(1, 2, sharex=True)
    for j, (ax, name) in enumerate(zip(axes, ("x", "y"), strict=True)):
        ax.plot(tau * 1e3, measured[:, j] * 1e6, **_MEASURED, label="measured (filtered)")
        ax.plot(tau * 1e3, simulated[:, j] * 1e6, color="tab:red", lw=0.9, ls="--", label="fitted simulation")
        ax.set_xlabel("Time since the drop [ms]")
        ax.set_ylabel(f"{name} [µm]")
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    if title:
        fig.suptitle(title)
    return fig
