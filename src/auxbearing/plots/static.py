"""Figures of the static study in the manner of Fig. 6, 7 and 8 of the source paper.

Each function returns a :class:`matplotlib.figure.Figure` and touches no global state.
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from matplotlib.figure import Figure

from auxbearing.statics import ISO76_BALL_STRESS

_MARKERS = "osd^v<>"


def _position_order(ds: xr.Dataset) -> tuple[np.ndarray, np.ndarray]:
    """Ball position angles wrapped to [-180, 180) deg and the order that sorts them."""
    phi = (np.degrees(ds["azimuth"].values) + 180.0) % 360.0 - 180.0
    order = np.argsort(phi)
    return phi[order], order


def _angle_panel(ax, ds: xr.Dataset, pair: int, label_var: str, label_unit: str) -> None:
    phi, order = _position_order(ds)
    for i in range(ds.sizes["case"]):
        angle = np.degrees(ds["contact_angle"].isel(case=i, pair=pair - 1).values[order])
        loaded = ds["load"].isel(case=i, pair=pair - 1).values[order] > 0.0
        value = float(ds[label_var].isel(case=i))
        line = ax.plot(phi, angle, marker=_MARKERS[i % len(_MARKERS)], markersize=4,
                       label=f"{value:g} {label_unit}")[0]
        # open markers: the pair is not compressed (carries nothing) at that position
        ax.plot(phi[~loaded], angle[~loaded], linestyle="none", marker=_MARKERS[i % len(_MARKERS)],
                markersize=6, markerfacecolor="white", color=line.get_color())
    ax.set_xlabel("Position angle φ [deg]")
    ax.set_ylabel(f"Contact angle α{pair} [deg]")
    ax.set_xticks(np.arange(-180, 181, 60))
    ax.grid(alpha=0.3)


def plot_contact_angles(radial_sweep: xr.Dataset, axial_sweep: xr.Dataset) -> Figure:
    """Loaded contact angle of pair 1 and pair 2 along the position angle (source paper Fig. 6).

    (a), (b): pairs 1 and 2 for several radial loads at a fixed axial load; (c), (d): pairs 1
    and 2 for several axial loads at a fixed radial load. Open markers: pair not loaded.
    """
    fig = Figure(figsize=(10, 7.5), layout="constrained")
    axes = fig.subplots(2, 2)
    fa = float(radial_sweep["axial_load"][0])
    fr = float(axial_sweep["radial_load"][0])
    panels = ((radial_sweep, 1, "radial_load", f"(a) pair 1, axial load {fa:g} N"),
              (radial_sweep, 2, "radial_load", f"(b) pair 2, axial load {fa:g} N"),
              (axial_sweep, 1, "axial_load", f"(c) pair 1, radial load {fr:g} N"),
              (axial_sweep, 2, "axial_load", f"(d) pair 2, radial load {fr:g} N"))
    for ax, (ds, pair, var, title) in zip(axes.ravel(), panels, strict=True):
        _angle_panel(ax, ds, pair, var, "N")
        ax.set_title(title, loc="left")
        ax.legend(title="radial load" if var == "radial_load" else "axial load", fontsize=8)
    bearing = radial_sweep.attrs.get("title", "").split(", ")[-1]
    fig.suptitle(f"Fig. 6: contact angle along the position angle, {bearing}")
    return fig


def plot_displacements(fig7: xr.Dataset, levels: int = 5) -> Figure:
    """Axial and radial ring displacement against axial and radial load (source paper Fig. 7).

    (a) axial displacement against axial load, one line per radial load; (b) radial
    displacement against radial load, one line per axial load.
    """
    fig = Figure(figsize=(10, 4), layout="constrained")
    ax_a, ax_r = fig.subplots(1, 2)
    fa = fig7["axial_load"].values
    fr = fig7["radial_load"].values
    pick_r = np.unique(np.linspace(0, fr.size - 1, levels).round().astype(int))
    pick_a = np.unique(np.linspace(0, fa.size - 1, levels).round().astype(int))
    for k, j in enumerate(pick_r):
        ax_a.plot(fa, fig7["axial_displacement"].values[:, j] * 1e6, marker=_MARKERS[k % 7], markevery=4,
                  markersize=4, label=f"Fr = {fr[j]:g} N")
    for k, i in enumerate(pick_a):
        ax_r.plot(fr, fig7["radial_displacement"].values[i, :] * 1e6, marker=_MARKERS[k % 7], markevery=4,
                  markersize=4, label=f"Fa = {fa[i]:g} N")
    ax_a.set_xlabel("Axial load Fa [N]")
    ax_a.set_ylabel("Axial displacement δa [µm]")
    ax_r.set_xlabel("Radial load Fr [N]")
    ax_r.set_ylabel("Radial displacement δr [µm]")
    for label, ax in zip("ab", (ax_a, ax_r), strict=True):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
        ax.set_title(f"({label})", loc="left")
    fig.suptitle(fig7.attrs.get("title", "Fig. 7: displacements"))
    return fig


def plot_max_stress(fig8: xr.Dataset) -> Figure:
    """Max Hertz contact stress against radial load, one line per bearing (source paper Fig. 8)."""
    fig = Figure(figsize=(6.5, 4.5), layout="constrained")
    ax = fig.subplots()
    r = fig8["radial_load"].values
    for k, name in enumerate(fig8["bearing"].values):
        kind = str(fig8["type"].values[k]).replace("_", "-")
        ax.plot(r, fig8["max_stress"].values[k] / 1e6, marker=_MARKERS[k], markevery=4, markersize=4,
                label=f"{name} ({kind})")
    ax.axhline(ISO76_BALL_STRESS / 1e6, color="grey", linestyle="--", linewidth=1,
               label="ISO 76 permissible 4200 MPa (s0 = 1)")
    ax.set_xlabel("Radial load Fr [N]")
    ax.set_ylabel("Maximum contact stress σ_max [MPa]")
    ax.set_ylim(bottom=0.0)
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8)
    ax.set_title("Fig. 8: max stress under radial load", loc="left")
    return fig
