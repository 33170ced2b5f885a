"""Figures of the rotor drop in the manner of Fig. 10-11 of the source paper, and the sweep.

Each function takes the Dataset of :func:`auxbearing.analysis.drop.run_drop` (or the sweep of
:func:`auxbearing.analysis.drop_paper.sweep_dataset`) and returns a new
:class:`matplotlib.figure.Figure`; nothing global (pyplot state, rcParams) is touched.
"""

from __future__ import annotations

import json

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

_COLOURS = {"QJ202": "tab:red", "7202": "tab:blue"}


def _title(ds: xr.Dataset) -> str:
    return str(ds.attrs.get("title", "Rotor drop"))


def _clearance(ds: xr.Dataset) -> float:
    drop = ds.attrs.get("drop", {})
    if isinstance(drop, str):
        drop = json.loads(drop)
    return float(drop.get("clearance_m", 2e-4))


def plot_orbit_force(ds: xr.Dataset, paper: dict | None = None) -> Figure:
    """(a) Journal-centre orbit inside the clearance circle; (b) collision force over time.

    The layout of the source paper's Fig. 10 (four-point) and Fig. 11 (angular contact).

    Parameters
    ----------
    ds : xarray.Dataset
        A drop time series.
    paper : dict, optional
        ``{"peak_contact_force_N": ...}`` to mark the paper's peak force.
    """
    s = _clearance(ds)
    fig = Figure(figsize=(11, 4.5), layout="constrained")
    ax_orbit, ax_force = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1, 1.6]})
    fig.suptitle(_title(ds))
    phi = np.linspace(0.0, 2.0 * np.pi, 361)
    ax_orbit.plot(s * 1e3 * np.cos(phi), s * 1e3 * np.sin(phi), color="0.5", lw=1, ls="--",
                  label=f"clearance s = {s * 1e3:g} mm")
    ax_orbit.plot(ds.rotor_x.values * 1e3, ds.rotor_y.values * 1e3, lw=0.6, color="tab:red", label="journal centre")
    ax_orbit.plot(ds.race_x.values * 1e3, ds.race_y.values * 1e3, lw=0.8, color="tab:blue", label="race centre")
    ax_orbit.set_aspect("equal")
    lim = 1.15 * s * 1e3
    ax_orbit.set_xlim(-lim, lim)
    ax_orbit.set_ylim(-lim, lim)
    ax_orbit.set_xlabel("x [mm]")
    ax_orbit.set_ylabel("y [mm]")
    ax_orbit.set_title("(a) orbit", loc="left")
    ax_orbit.legend(loc="upper right", fontsize=8)
    t_ms = ds.time.values * 1e3
    ax_force.plot(t_ms, ds.normal_force.values, lw=0.7, color="tab:red", label="collision force $F_{n1}$")
    summary = json.loads(ds.attrs["summary"]) if "summary" in ds.attrs else {}
    if summary:
        ax_force.plot(summary["peak_force_time_ms"], summary["peak_contact_force_N"], "kv",
                      label=f"peak {summary['peak_contact_force_N']:.0f} N")
    if paper:
        ax_force.axhline(paper["peak_contact_force_N"], color="0.4", ls=":",
                         label=f"paper peak {paper['peak_contact_force_N']:g} N")
    ax_force.set_xlabel("Time [ms]")
    ax_force.set_ylabel("Collision force [N]")
    ax_force.set_title("(b) collision force", loc="left")
    ax_force.grid(alpha=0.3)
    ax_force.legend(fontsize=8)
    return fig


def plot_speeds_stress(ds: xr.Dataset) -> Figure:
    """(a) Spin speeds of rotor and inner race; (b) max ball contact stress over time."""
    fig = Figure(figsize=(11, 4), layout="constrained")
    ax_speed, ax_stress = fig.subplots(1, 2)
    fig.suptitle(_title(ds))
    t_ms = ds.time.values * 1e3
    ax_speed.plot(t_ms, ds.rotor_speed.values, color="tab:red", label="rotor")
    ax_speed.plot(t_ms, ds.race_speed.values, color="tab:blue", label="inner race")
    ax_speed.set_xlabel("Time [ms]")
    ax_speed.set_ylabel("Spin speed [rad/s]")
    ax_speed.set_title("(a) spin speeds", loc="left")
    ax_speed.legend()
    ax_speed.grid(alpha=0.3)
    ax_stress.plot(t_ms, ds.max_ball_stress.values / 1e6, lw=0.7, color="tab:purple")
    ax_stress.set_xlabel("Time [ms]")
    ax_stress.set_ylabel("Max ball contact stress [MPa]")
    ax_stress.set_title("(b) most loaded ball contact", loc="left")
    ax_stress.grid(alpha=0.3)
    return fig


_SWEEP_AXES = (  # dimension, variable suffix, display scale, axis label
    ("clearance", "vs_clearance", 1e3, "Clearance s [mm]"),
    ("sliding_friction", "vs_friction", 1.0, "Sliding friction μ1 [-]"),
    ("unbalance_phase", "vs_unbalance_phase", 180.0 / np.pi, "Unbalance phase at the drop [deg]"),
)


def plot_sweep(sweep: xr.Dataset, paper: dict | None = None) -> Figure:
    """Peak collision force and peak ball stress against each swept parameter, per bearing.

    Parameters
    ----------
    sweep : xarray.Dataset
        :func:`auxbearing.analysis.drop_paper.sweep_dataset`.
    paper : dict, optional
        The paper's peaks per bearing, drawn as horizontal dotted lines.
    """
    axes_present = [a for a in _SWEEP_AXES if a[0] in sweep.dims]
    fig = Figure(figsize=(4.2 * max(1, len(axes_present)), 7), layout="constrained")
    grid = fig.subplots(2, max(1, len(axes_present)), squeeze=False)
    fig.suptitle("Rotor drop: four-point (QJ202) against angular contact (7202)")
    rows = (("peak_contact_force", "peak_contact_force_N", "Peak collision force [N]"),
            ("peak_ball_stress", "peak_ball_stress_MPa", "Peak ball stress [MPa]"))
    for col, (dim, suffix, scale, xlabel) in enumerate(axes_present):
        for row, (prefix, key, ylabel) in enumerate(rows):
            ax = grid[row, col]
            for name in sweep.bearing.values:
                colour = _COLOURS.get(str(name))
                ax.plot(sweep[dim].values * scale, sweep[f"{prefix}_{suffix}"].sel(bearing=name).values, "o-",
                        color=colour, label=str(name))
                if paper and str(name) in paper:
                    ax.axhline(paper[str(name)][key], color=colour, ls=":", lw=1, label=f"{name} paper")
            ax.set_xlabel(xlabel)
            ax.set_ylabel(ylabel)
            ax.grid(alpha=0.3)
            ax.legend(fontsize=7)
    return fig
