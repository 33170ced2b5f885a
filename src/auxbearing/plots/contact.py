"""Figures of the contact study in the manner of Fig. 2 and Fig. 3 of the source paper."""

from __future__ import annotations

import xarray as xr
from matplotlib.figure import Figure

_STYLE = {"inner": {"color": "tab:red", "marker": "o"}, "outer": {"color": "tab:blue", "marker": "s"}}


def _two_panels(title: str) -> tuple[Figure, tuple]:
    fig = Figure(figsize=(10, 4), layout="constrained")
    axes = fig.subplots(1, 2)
    fig.suptitle(title)
    return fig, axes


def _plot_pair(axes, ds: xr.Dataset, dim: str, xlabel: str) -> None:
    x = ds[dim].values
    for race in ("inner", "outer"):
        cut = ds.sel(race=race)
        style = dict(_STYLE[race], markevery=max(1, len(x) // 12), markersize=4)
        axes[0].plot(x, cut["approach"].values * 1e6, label=f"{race} race", **style)
        axes[1].plot(x, cut["max_stress"].values / 1e6, label=f"{race} race", **style)
    axes[0].set_ylabel("Elastic approach δ [µm]")
    axes[1].set_ylabel("Maximum contact stress σ_max [MPa]")
    for label, ax in zip("ab", axes, strict=True):
        ax.set_xlabel(xlabel)
        ax.grid(alpha=0.3)
        ax.legend()
        ax.set_title(f"({label})", loc="left")


def plot_contact_angle_sweep(ds: xr.Dataset, groove_ratio: float | None = None) -> Figure:
    """Approach and max stress of inner and outer race against contact angle (Fig. 2)."""
    f = float(ds.groove_ratio.values[len(ds.groove_ratio) // 2]) if groove_ratio is None else groove_ratio
    cut = ds.sel(groove_ratio=f, method="nearest")
    fig, axes = _two_panels(
        f"Fig. 2: contact angle sweep, f = {float(cut.groove_ratio):.3f}, ball load {ds.attrs['ball_load_N']:g} N"
    )
    _plot_pair(axes, cut, "contact_angle", "Contact angle α [deg]")
    return fig


def plot_groove_ratio_sweep(ds: xr.Dataset, contact_angle_deg: float | None = None) -> Figure:
    """Approach and max stress of inner and outer race against groove ratio (Fig. 3)."""
    a = float(ds.contact_angle.values[len(ds.contact_angle) // 2]) if contact_angle_deg is None else contact_angle_deg
    cut = ds.sel(contact_angle=a, method="nearest")
    fig, axes = _two_panels(
        f"Fig. 3: groove ratio sweep, α = {float(cut.contact_angle):g} deg, ball load {ds.attrs['ball_load_N']:g} N"
    )
    _plot_pair(axes, cut, "groove_ratio", "Groove radius coefficient f [-]")
    return fig


def plot_contact_map(ds: xr.Dataset, race: str = "inner") -> Figure:
    """Max stress over contact angle x groove ratio with the paper's recommended window."""
    fig = Figure(figsize=(6, 4.5), layout="constrained")
    ax = fig.subplots()
    cut = ds.sel(race=race)
    mesh = ax.contourf(cut.groove_ratio, cut.contact_angle, cut["max_stress"].values / 1e6, levels=20)
    fig.colorbar(mesh, ax=ax, label=f"σ_max, {race} race [MPa]")
    ax.add_patch(_window())
    ax.set_xlabel("Groove radius coefficient f [-]")
    ax.set_ylabel("Contact angle α [deg]")
    ax.set_title(f"Max stress map, ball load {ds.attrs['ball_load_N']:g} N (box: paper's recommendation)")
    return fig


def _window():
    from matplotlib.patches import Rectangle

    return Rectangle((0.51, 15.0), 0.01, 30.0, fill=False, edgecolor="white", linewidth=2, linestyle="--")
