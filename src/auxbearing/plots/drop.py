"""Figures of a drop: orbit, contact force, speeds, stress, tilt, whirl timeline; the paper's sweep.

Each function takes the Dataset (and summary) of :func:`auxbearing.analysis.drop.run_machine` or
:func:`auxbearing.planar.rig.run_drop`. A function that draws one panel takes ``ax=None``: given an
axes, it draws there and returns its figure; otherwise it makes a new
:class:`matplotlib.figure.Figure`. Nothing global (pyplot state, rcParams) is touched.
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from auxbearing.common.io import loads
from auxbearing.plots._axes import envelope

_COLOURS = {"QJ202": "tab:red", "7202": "tab:blue"}
_WHIRL_COLOURS = {"none": "0.85", "forward": "tab:green", "backward_rolling": "tab:orange", "dry_whip": "tab:red",
                  "backward": "tab:purple"}


def _axes(ax, size=(6, 4)):
    """The caller's axes, or a new figure's."""
    if ax is not None:
        return ax.figure, ax
    fig = Figure(figsize=size, layout="constrained")
    return fig, fig.add_subplot()


def _title(ds: xr.Dataset) -> str:
    return str(ds.attrs.get("title", "Rotor drop"))


def _machine(ds: xr.Dataset) -> dict:
    text = ds.attrs.get("machine", "{}")
    return loads(text) if isinstance(text, str) else dict(text)


def _summary(ds: xr.Dataset) -> dict:
    text = ds.attrs.get("summary", "{}")
    return loads(text) if isinstance(text, str) else dict(text)


def _finite(value) -> float | None:
    """``value`` as a number a line can be drawn at, or None (no limit: missing, null, "inf")."""
    if isinstance(value, bool):
        return None
    try:
        number = float(value)
    except (TypeError, ValueError):
        return None
    return number if math.isfinite(number) else None


def _plane(ds: xr.Dataset, k: int) -> xr.Dataset:
    """Plane k of a machine run, or a one-plane run's planar view (:func:`auxbearing.analysis.drop.planar_view`)."""
    return ds.isel(plane=k) if "plane" in ds.dims else ds


def _n_planes(ds: xr.Dataset) -> int:
    return ds.sizes.get("plane", 1)


def _plane_name(ds: xr.Dataset, k: int) -> str:
    return str(ds.plane.values[k]) if "plane" in ds.dims else str(ds.attrs.get("plane_name", "plane"))


def _clearance(ds: xr.Dataset, plane: int) -> float:
    planes = _machine(ds).get("planes", [])
    return planes[plane]["radial_clearance_mm"] * 1e-3 if planes else 2e-4


def plot_orbit(ds: xr.Dataset, plane: int = 0, ax=None) -> Figure:
    """Journal centre at a plane and its race centre inside the clearance circle (paper Fig. 10-11 (a))."""
    fig, ax = _axes(ax, (5, 5))
    s = _clearance(ds, plane)
    sel = _plane(ds, plane)
    centre = (sel.ring_x.values, sel.ring_y.values)
    phi = np.linspace(0.0, 2.0 * np.pi, 361)
    ax.plot(s * 1e3 * np.cos(phi), s * 1e3 * np.sin(phi), color="0.5", lw=1, ls="--",
            label=f"clearance s = {s * 1e3:g} mm")
    ax.plot((sel.journal_x.values - centre[0]) * 1e3, (sel.journal_y.values - centre[1]) * 1e3, lw=0.6,
            color="tab:red", label="journal centre")
    ax.plot((sel.race_x.values - centre[0]) * 1e3, (sel.race_y.values - centre[1]) * 1e3, lw=0.8, color="tab:blue",
            label="race centre")
    ax.set_aspect("equal")
    lim = 1.15 * max(s, float(np.nanmax(np.hypot(sel.journal_x.values - centre[0], sel.journal_y.values - centre[1]))))
    ax.set_xlim(-lim * 1e3, lim * 1e3)
    ax.set_ylim(-lim * 1e3, lim * 1e3)
    ax.set_xlabel("x [mm] (from the bearing centre)")
    ax.set_ylabel("y [mm]")
    ax.set_title(f"orbit, {_plane_name(ds, plane)}", loc="left")
    ax.legend(loc="upper right", fontsize=8)
    return fig


def plot_contact_force(ds: xr.Dataset, plane: int | None = None, ax=None, paper_peak: float | None = None) -> Figure:
    """Journal/race collision force over time, one line per plane (or one plane), with the exact peak."""
    fig, ax = _axes(ax, (7, 4))
    t_ms = ds.time.values * 1e3
    summary = _summary(ds)
    planes = range(_n_planes(ds)) if plane is None else [plane]
    for k in planes:
        name = _plane_name(ds, k)
        ax.plot(*envelope(t_ms, _plane(ds, k).normal_force.values), lw=0.7, label=f"collision force, {name}")
        peak = _plane_summary(summary, k).get("peak_contact_force_N")
        if peak is not None:
            ax.plot(_plane_summary(summary, k)["peak_force_time_ms"], peak, "kv", label=f"peak {peak:.0f} N")
    if paper_peak is not None:
        ax.axhline(paper_peak, color="0.4", ls=":", label=f"paper peak {paper_peak:g} N")
    ax.set_xlabel("Time [ms]")
    ax.set_ylabel("Collision force [N]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def _plane_summary(summary: dict, k: int) -> dict:
    if "planes" in summary:
        return summary["planes"][k]
    return summary  # the paper drop's flat summary (one plane)


def plot_orbit_force(ds: xr.Dataset, paper: dict | None = None) -> Figure:
    """(a) Orbit inside the clearance circle; (b) collision force: the layout of the paper's Fig. 10-11."""
    fig = Figure(figsize=(11, 4.5), layout="constrained")
    ax_orbit, ax_force = fig.subplots(1, 2, gridspec_kw={"width_ratios": [1, 1.6]})
    fig.suptitle(_title(ds))
    plot_orbit(ds, 0, ax=ax_orbit)
    plot_contact_force(ds, 0, ax=ax_force, paper_peak=None if not paper else paper["peak_contact_force_N"])
    ax_orbit.set_title("(a) orbit", loc="left")
    ax_force.set_title("(b) collision force", loc="left")
    return fig


def plot_speeds(ds: xr.Dataset, ax=None) -> Figure:
    """Spin speeds of the rotor and of each inner race [rad/s]."""
    fig, ax = _axes(ax, (7, 4))
    t_ms = ds.time.values * 1e3
    ax.plot(*envelope(t_ms, ds.rotor_speed.values), color="tab:red", label="rotor")
    for k in range(_n_planes(ds)):
        ax.plot(*envelope(t_ms, _plane(ds, k).race_speed.values), label=f"inner race, {_plane_name(ds, k)}")
    ax.set_xlabel("Time [ms]")
    ax.set_ylabel("Spin speed [rad/s]")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return fig


def plot_ball_stress(ds: xr.Dataset, ax=None, limit_MPa: float | None = None) -> Figure:
    """Hertz max stress of the most loaded ball contact of each plane [MPa], with the limit judged against."""
    fig, ax = _axes(ax, (7, 4))
    t_ms = ds.time.values * 1e3
    for k in range(_n_planes(ds)):
        ax.plot(*envelope(t_ms, _plane(ds, k).max_ball_stress.values / 1e6), lw=0.7, label=_plane_name(ds, k))
    if limit_MPa is not None:
        ax.axhline(limit_MPa, color="tab:red", ls="--", lw=1.0, label=f"limit {limit_MPa:.0f} MPa")
    ax.set_xlabel("Time [ms]")
    ax.set_ylabel("Max ball contact stress [MPa]")
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
    return fig


def plot_speeds_stress(ds: xr.Dataset) -> Figure:
    """(a) Spin speeds of rotor and inner race; (b) max ball contact stress over time."""
    fig = Figure(figsize=(11, 4), layout="constrained")
    ax_speed, ax_stress = fig.subplots(1, 2)
    fig.suptitle(_title(ds))
    plot_speeds(ds, ax=ax_speed)
    plot_ball_stress(ds, ax=ax_stress)
    ax_speed.set_title("(a) spin speeds", loc="left")
    ax_stress.set_title("(b) most loaded ball contact", loc="left")
    return fig


def plot_tilt(ds: xr.Dataset, ax=None) -> Figure:
    """Tilt of the journal axis [mrad] and its axial position [um]."""
    fig, ax = _axes(ax, (7, 4))
    t_ms = ds.time.values * 1e3
    ax.plot(*envelope(t_ms, ds.tilt_x.values * 1e3), label="tilt about x")
    ax.plot(*envelope(t_ms, ds.tilt_y.values * 1e3), label="tilt about y")
    ax.set_xlabel("Time [ms]")
    ax.set_ylabel("Tilt [mrad]")
    twin = ax.twinx()
    twin.plot(*envelope(t_ms, ds.rotor_z.values * 1e6), color="0.4", lw=0.8, ls="--", label="axial position")
    twin.set_ylabel("Axial position [µm]")
    ax.legend(loc="upper left", fontsize=8)
    twin.legend(loc="upper right", fontsize=8)
    ax.grid(alpha=0.3)
    return fig


def plot_whirl_timeline(summary: dict, ax=None) -> Figure:
    """The whirl class of each window, one row per plane (none, forward, backward rolling, dry whip)."""
    fig, ax = _axes(ax, (8, 1.2 + 0.6 * len(summary["planes"])))
    for row, plane in enumerate(summary["planes"]):
        width = plane["whirl_window_ms"]
        for i, cls in enumerate(plane["whirl_timeline"]):
            ax.barh(row, width, left=i * width, color=_WHIRL_COLOURS.get(cls, "0.5"), edgecolor="white", lw=0.5)
    ax.set_yticks(range(len(summary["planes"])), [p["name"] for p in summary["planes"]])
    ax.set_xlabel("Time [ms]")
    handles = [ax.bar(0, 0, color=c, label=name.replace("_", " ")) for name, c in _WHIRL_COLOURS.items()]
    ax.legend(handles=handles, fontsize=7, ncol=5, loc="upper center", bbox_to_anchor=(0.5, -0.35))
    ax.set_title("whirl timeline", loc="left")
    return fig


def machine_figures(ds: xr.Dataset, summary: dict) -> dict[str, Figure]:
    """The figures of a machine run: orbit of each plane, contact forces, tilt, whirl timeline, spin speeds."""
    figures = {f"orbit_{k}": plot_orbit(ds, k) for k in range(_n_planes(ds))}
    figures["contact_force"] = plot_contact_force(ds)
    figures["ball_stress"] = plot_ball_stress(ds)
    figures["tilt"] = plot_tilt(ds)
    figures["whirl_timeline"] = plot_whirl_timeline(summary)
    figures["speeds"] = plot_speeds(ds)
    return figures


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
        :func:`auxbearing.paper.drop_paper.sweep_dataset`.
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


def plot_magnetic_bearings(ds: xr.Dataset, summary: dict) -> Figure:
    """A levitated drop's magnetic bearings: currents against their limits, forces beside the collision forces.

    The scenario's strike is marked.
    """
    fig = Figure(figsize=(7, 6), layout="constrained")
    currents, forces = fig.subplots(2, 1, sharex=True)
    t_ms = ds.time.values * 1e3
    for i, name in enumerate(ds["amb"].values):
        for axis in ("x", "y", "z"):
            if f"amb_current_{axis}" not in ds or np.isnan(ds[f"amb_current_{axis}"].values[:, i]).all():
                continue  # an axis this bearing has not
            currents.plot(*envelope(t_ms, ds[f"amb_current_{axis}"].values[:, i]), lw=0.7, label=f"{name}, {axis}")
            if f"amb_force_{axis}" in ds:
                forces.plot(*envelope(t_ms, ds[f"amb_force_{axis}"].values[:, i]), lw=0.7, label=f"{name}, {axis}")
    # an amplifier without a limit has none to draw: a summary read back holds it as inf, a raw file as "inf"
    limits = {v for v in (_finite(a.get("max_current_A")) for a in summary.get("amb", [])) if v}
    for limit in limits:
        for sign in (1, -1):
            currents.axhline(sign * limit, color="0.3", ls="--", lw=0.8)
    for k in range(_n_planes(ds)):
        forces.plot(*envelope(t_ms, _plane(ds, k).normal_force.values), lw=0.7, color="k", alpha=0.5 + 0.5 * k / max(
            _n_planes(ds), 1), label=f"collision force, {_plane_name(ds, k)}")
    strike = (summary.get("scenario") or {}).get("time_ms")
    for ax in (currents, forces):
        if strike:
            ax.axvline(strike, color="tab:red", ls=":", lw=0.8)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, ncol=2)
    currents.set_ylabel("Control current [A]" + (" (dashed: limit)" if limits else ""))
    forces.set_ylabel("Force on the rotor [N]")
    forces.set_xlabel("Time [ms]" + (" (dotted: the scenario strikes)" if strike else ""))
    return fig


def axis_orbit(machine, ds: xr.Dataset, position: float) -> tuple[np.ndarray, np.ndarray]:
    """The rotor axis' x and y at ``position`` from the mass centre over a run [m].

    The rigid motion (theta_y = dx/dz, theta_x = -dy/dz) and, on an elastic rotor, its modes' shapes there
    (``position`` on a node).
    """
    x = ds.rotor_x.values + position * ds.tilt_y.values
    y = ds.rotor_y.values - position * ds.tilt_x.values
    modal = machine.modal()
    if modal is not None and modal.n_modes and "mode" in ds:
        shape_x, shape_y = modal.station_shapes(position, "orbit position")
        x, y = x + ds["mode"].values @ shape_x, y + ds["mode"].values @ shape_y
    return x, y


def orbit_positions(machine) -> list[tuple[str, float]]:
    """Where an engineer looks at the rotor besides its touchdown planes: each radial station and mid-span."""
    out = [(s.name, s.position) for s in getattr(machine, "stations", ())
           if s.KIND in ("amb", "linear_support") and not getattr(s, "axial", False)]
    planes = [p.position for p in machine.planes]
    if len(planes) >= 2:
        middle = 0.5 * (min(planes) + max(planes))
        modal = machine.modal()
        if modal is not None and modal.n_modes:  # the node nearest the middle of the bearing span
            middle = float(modal.nodes[np.argmin(np.abs(modal.nodes - middle))])
        out.append(("mid-span", middle))
    return out


def plot_axis_orbits(machine, ds: xr.Dataset) -> Figure:
    """Orbits of the rotor axis at the stations and at mid-span [um], each against its nearest plane's clearance."""
    places = orbit_positions(machine)
    fig = Figure(figsize=(3.2 * max(len(places), 1), 3.4), layout="constrained")
    for ax, (name, position) in zip(np.atleast_1d(fig.subplots(1, max(len(places), 1))), places, strict=False):
        x, y = axis_orbit(machine, ds, position)
        ax.plot(x * 1e6, y * 1e6, lw=0.5)
        nearest = min(machine.planes, key=lambda p: abs(p.position - position))
        circle = np.linspace(0, 2 * np.pi, 200)
        c = nearest.radial_clearance * 1e6
        ax.plot(c * np.cos(circle), c * np.sin(circle), "k--", lw=0.6)
        ax.set_aspect("equal")
        ax.set_title(f"{name} ({position * 1e3:.0f} mm)", fontsize=8)
        ax.set_xlabel("x [um]", fontsize=8)
        ax.set_ylabel("y [um]", fontsize=8)
        ax.grid(alpha=0.3)
    return fig
