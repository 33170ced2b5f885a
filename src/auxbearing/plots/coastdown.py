"""Figures of a coast-down: speeds, temperatures and clearances over time, stress cycles of the worst contact.

Each function takes the history of :func:`auxbearing.analysis.coastdown.run_coastdown` (or its life results) and
``ax=None``: given an axes it draws there and returns its figure, otherwise it makes a new
:class:`matplotlib.figure.Figure`. Stretches carried by the reduced model are shaded.
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.collections import PolyCollection
from matplotlib.figure import Figure

from auxbearing.plots._axes import axes_for


def _shade_reduced(ax, history: xr.Dataset) -> None:
    """Shade the stretches the reduced model carried (mode 1 ends a stretch begun at the record before).

    One collection of bands the axes' full height (a span apiece, 124 on the blower in each of four panels, was
    a third of the coast-down figures' drawing time).
    """
    t = history.time.values
    ends = np.flatnonzero(history["mode"].values == 1)
    ends = ends[ends > 0]
    if ends.size == 0:
        return
    bands = [[(t[i - 1], 0.0), (t[i], 0.0), (t[i], 1.0), (t[i - 1], 1.0)] for i in ends]
    ax.add_collection(PolyCollection(bands, facecolors="0.92", linewidths=0, zorder=0,
                                     transform=ax.get_xaxis_transform()), autolim=False)


def plot_speeds(history: xr.Dataset, ax=None) -> Figure:
    """Rotor and race speeds [rpm] from the drop to standstill."""
    fig, ax = axes_for(ax, (7, 4))
    _shade_reduced(ax, history)
    rpm = 30.0 / np.pi
    ax.plot(history.time.values, history.rotor_speed.values * rpm, color="tab:red", label="rotor")
    for k, name in enumerate(history.plane.values):
        ax.plot(history.time.values, history.race_speed.isel(plane=k).values * rpm, lw=0.8, label=f"race, {name}")
    ax.set_xlabel("Time since the drop [s]")
    ax.set_ylabel("Speed [rpm]")
    ax.set_title("spin-down (grey: reduced model)", loc="left")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def plot_temperatures(history: xr.Dataset, plane: int = 0, ax=None, limit_C: float | None = None) -> Figure:
    """Node temperatures of one plane's thermal network [degC], with the limit judged against when given."""
    fig, ax = axes_for(ax, (7, 4))
    _shade_reduced(ax, history)
    sel = history.temperature.isel(plane=plane)
    for j, node in enumerate(history.node.values):
        ax.plot(history.time.values, sel.isel(node=j).values, label=str(node).replace("_", " "))
    if limit_C is not None:
        ax.axhline(limit_C, color="tab:red", ls="--", lw=1.0, label=f"limit {limit_C:.0f} °C")
    ax.set_xlabel("Time since the drop [s]")
    ax.set_ylabel("Temperature [°C]")
    ax.set_title(f"temperatures, {history.plane.values[plane]}", loc="left")
    ax.grid(alpha=0.3)
    # beside the axes: inside, the legend covered the hottest curve near the limit
    ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1.0), borderaxespad=0.0)
    return fig


def plot_clearances(history: xr.Dataset, ax=None) -> Figure:
    """Journal/race radial clearance and bearing diametral clearance [um] with thermal growth."""
    fig, ax = axes_for(ax, (7, 4))
    _shade_reduced(ax, history)
    for k, name in enumerate(history.plane.values):
        ax.plot(history.time.values, history.radial_clearance.isel(plane=k).values * 1e6,
                label=f"radial (journal/race), {name}")
        ax.plot(history.time.values, history.internal_clearance.isel(plane=k).values * 1e6, ls="--",
                label=f"diametral (bearing), {name}")
    ax.axhline(0.0, color="0.3", lw=0.8)
    ax.set_xlabel("Time since the drop [s]")
    ax.set_ylabel("Clearance [µm]")
    ax.set_title("clearances with thermal growth", loc="left")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7)
    return fig


def plot_stress_cycles(cycles: dict | None, ax=None) -> Figure:
    """Rainflow cycles of the drop's most damaged ball/raceway contact: counts against stress range [MPa]."""
    fig, ax = axes_for(ax, (7, 4))
    if cycles is None or np.size(cycles.get("ranges", [])) == 0:
        ax.text(0.5, 0.5, "no stress cycles kept for this drop", ha="center", va="center", transform=ax.transAxes)
        return fig
    ranges = np.asarray(cycles["ranges"]) / 1e6
    counts = np.asarray(cycles["counts"])
    bins = np.linspace(0.0, max(ranges.max(), 1.0), 31)
    ax.hist(ranges, bins=bins, weights=counts, color="tab:purple")
    ax.set_xlabel("Stress range [MPa]")
    ax.set_ylabel("Cycles (rainflow, ASTM E1049)")
    where = f"{cycles.get('race')} race, ball {cycles.get('ball')}, pair {cycles.get('pair')}"
    ax.set_title(f"most damaged contact of the drop: {where}", loc="left", fontsize=9)
    ax.grid(alpha=0.3)
    return fig
