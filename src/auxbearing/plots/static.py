"""Figures of the static study in the manner of Fig. 6, 7 and 8 of the source paper.

A function that draws one panel takes ``ax=None``: given an axes it draws there and returns
that axes' figure, otherwise it makes a new :class:`matplotlib.figure.Figure`. The
multi-panel figures take ``fig=None`` and are built from the one-panel functions. Nothing
global changes.
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from auxbearing.bearings.ratings import ISO76_BALL_STRESS
from auxbearing.plots._axes import axes_for, figure_for

_MARKERS = "osd^v<>"
#: Load levels a displacement panel draws by default (evenly picked from the grid).
DEFAULT_LEVELS = 5


def _position_order(ds: xr.Dataset) -> tuple[np.ndarray, np.ndarray]:
    """Ball position angles wrapped to [-180, 180) deg and the order that sorts them."""
    phi = (np.degrees(ds["azimuth"].values) + 180.0) % 360.0 - 180.0
    order = np.argsort(phi)
    return phi[order], order


def _swept(ds: xr.Dataset) -> str:
    """The load that changes from case to case (radial unless only the axial one does)."""
    varies = {name: np.ptp(np.atleast_1d(ds[name].values)) > 0.0 for name in ("radial_load", "axial_load")}
    return "axial_load" if varies["axial_load"] and not varies["radial_load"] else "radial_load"


def plot_contact_angle_profile(sweep: xr.Dataset, pair: int = 1, ax=None) -> Figure:
    """One panel of Fig. 6: loaded contact angle of one pair [deg] along the position angle [deg].

    One line per load case, labelled by the swept load (radial, or axial when only it varies);
    open markers: the pair carries nothing at that position.

    Parameters
    ----------
    sweep : xarray.Dataset
        :func:`auxbearing.analysis.statics.load_distribution` over several cases.
    pair : {1, 2}
        Contact pair of the four-point ball.
    ax : matplotlib.axes.Axes, optional
        Axes to draw in; default a new figure.
    """
    fig, ax = axes_for(ax, (6, 4))
    var = _swept(sweep)
    fixed = "axial_load" if var == "radial_load" else "radial_load"
    phi, order = _position_order(sweep)
    for i in range(sweep.sizes["case"]):
        marker = _MARKERS[i % len(_MARKERS)]
        angle = np.degrees(sweep["contact_angle"].isel(case=i, pair=pair - 1).values[order])
        loaded = sweep["load"].isel(case=i, pair=pair - 1).values[order] > 0.0
        value = float(sweep[var].isel(case=i))
        line = ax.plot(phi, angle, marker=marker, markersize=4, label=f"{value:g} N")[0]
        # open markers: the pair is not compressed (carries nothing) at that position
        ax.plot(phi[~loaded], angle[~loaded], linestyle="none", marker=marker, markersize=6,
                markerfacecolor="white", color=line.get_color())
    ax.set_xlabel("Position angle φ [deg]")
    ax.set_ylabel(f"Contact angle α{pair} [deg]")
    ax.set_xticks(np.arange(-180, 181, 60))
    ax.grid(alpha=0.3)
    ax.legend(title=var.replace("_", " "), fontsize=8)
    fixed_value = float(np.atleast_1d(sweep[fixed].values)[0])
    ax.set_title(f"pair {pair}, {fixed.replace('_', ' ')} {fixed_value:g} N", loc="left")
    return fig


def plot_contact_angles(radial_sweep: xr.Dataset, axial_sweep: xr.Dataset, fig=None) -> Figure:
    """Loaded contact angle of pair 1 and pair 2 along the position angle (source paper Fig. 6).

    (a), (b): pairs 1 and 2 for several radial loads at a fixed axial load; (c), (d): pairs 1
    and 2 for several axial loads at a fixed radial load. Open markers: pair not loaded.
    """
    fig = figure_for(fig, (10, 7.5))
    axes = fig.subplots(2, 2)
    panels = ((radial_sweep, 1), (radial_sweep, 2), (axial_sweep, 1), (axial_sweep, 2))
    for label, ax, (ds, pair) in zip("abcd", axes.ravel(), panels, strict=True):
        plot_contact_angle_profile(ds, pair, ax=ax)
        ax.set_title(f"({label}) {ax.get_title(loc='left')}", loc="left")
    bearing = radial_sweep.attrs.get("title", "").split(", ")[-1]
    fig.suptitle(f"Fig. 6: contact angle along the position angle, {bearing}")
    return fig


def _picks(n: int, levels: int) -> np.ndarray:
    """About ``levels`` indices spread evenly over 0..n-1."""
    return np.unique(np.linspace(0, n - 1, levels).round().astype(int))


def plot_axial_displacement(fig7: xr.Dataset, levels: int = DEFAULT_LEVELS, ax=None) -> Figure:
    """Fig. 7 (a): axial ring displacement [µm] against axial load [N], one line per radial load.

    ``fig7`` holds ``axial_displacement`` [m] over (``axial_load``, ``radial_load``) [N]
    (:func:`auxbearing.paper.static_paper.static_study`'s ``fig7``).
    """
    fig, ax = axes_for(ax, (5, 4))
    fa = fig7["axial_load"].values
    fr = fig7["radial_load"].values
    for k, j in enumerate(_picks(fr.size, levels)):
        ax.plot(fa, fig7["axial_displacement"].values[:, j] * 1e6, marker=_MARKERS[k % len(_MARKERS)], markevery=4,
                markersize=4, label=f"Fr = {fr[j]:g} N")
    ax.set_xlabel("Axial load Fa [N]")
    ax.set_ylabel("Axial displacement δa [µm]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def plot_radial_displacement(fig7: xr.Dataset, levels: int = DEFAULT_LEVELS, ax=None) -> Figure:
    """Fig. 7 (b): radial ring displacement [µm] against radial load [N], one line per axial load."""
    fig, ax = axes_for(ax, (5, 4))
    fa = fig7["axial_load"].values
    fr = fig7["radial_load"].values
    for k, i in enumerate(_picks(fa.size, levels)):
        ax.plot(fr, fig7["radial_displacement"].values[i, :] * 1e6, marker=_MARKERS[k % len(_MARKERS)], markevery=4,
                markersize=4, label=f"Fa = {fa[i]:g} N")
    ax.set_xlabel("Radial load Fr [N]")
    ax.set_ylabel("Radial displacement δr [µm]")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    return fig


def plot_displacements(fig7: xr.Dataset, levels: int = DEFAULT_LEVELS, fig=None) -> Figure:
    """Axial and radial ring displacement against axial and radial load (source paper Fig. 7).

    (a) axial displacement against axial load, one line per radial load; (b) radial
    displacement against radial load, one line per axial load.
    """
    fig = figure_for(fig, (10, 4))
    ax_a, ax_r = fig.subplots(1, 2)
    plot_axial_displacement(fig7, levels, ax=ax_a)
    plot_radial_displacement(fig7, levels, ax=ax_r)
    for label, ax in zip("ab", (ax_a, ax_r), strict=True):
        ax.set_title(f"({label})", loc="left")
    fig.suptitle(fig7.attrs.get("title", "Fig. 7: displacements"))
    return fig


def plot_max_stress(fig8: xr.Dataset, ax=None) -> Figure:
    """Max Hertz contact stress [MPa] against radial load [N], one line per bearing (source paper Fig. 8)."""
    fig, ax = axes_for(ax, (6.5, 4.5))
    r = fig8["radial_load"].values
    for k, name in enumerate(fig8["bearing"].values):
        kind = str(fig8["type"].values[k]).replace("_", "-")
        ax.plot(r, fig8["max_stress"].values[k] / 1e6, marker=_MARKERS[k % len(_MARKERS)], markevery=4,
                markersize=4, label=f"{name} ({kind})")
    ax.axhline(ISO76_BALL_STRESS / 1e6, color="grey", linestyle="--", linewidth=1,
               label=f"ISO 76 permissible {ISO76_BALL_STRESS / 1e6:g} MPa (s0 = 1)")
    ax.set_xlabel("Radial load Fr [N]")
    ax.set_ylabel("Maximum contact stress σ_max [MPa]")
    ax.set_ylim(bottom=0.0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("Fig. 8: max stress under radial load", loc="left")
    return fig
