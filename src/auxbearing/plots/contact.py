"""Figures of the contact study in the manner of Fig. 2 and Fig. 3 of the source paper.

Each function takes the Dataset of :func:`auxbearing.analysis.contact.contact_map`. A function that
draws one panel takes ``ax=None``: given an axes it draws there and returns that axes'
figure, otherwise it makes a new :class:`matplotlib.figure.Figure`. The two-panel figures
take ``fig=None`` and are built from the one-panel functions. Nothing global changes.
"""

from __future__ import annotations

import xarray as xr
from matplotlib.figure import Figure

from auxbearing.plots._axes import axes_for, figure_for

_STYLE = {"inner": {"color": "tab:red", "marker": "o"}, "outer": {"color": "tab:blue", "marker": "s"}}
#: Markers on a swept line: about this many, whatever the grid density, so the races stay legible.
_MARKERS_PER_LINE = 12
#: Quantities a sweep panel can show: variable, display scale (SI -> shown unit), axis label.
_QUANTITIES = {
    "approach": ("approach", 1e6, "Elastic approach δ [µm]"),
    "max_stress": ("max_stress", 1e-6, "Maximum contact stress σ_max [MPa]"),
}
#: The source paper's recommended design window (Sec. II.B, conclusion of Fig. 2-3):
#: contact angle 15-45 deg and groove radius coefficient 0.51-0.52.
RECOMMENDED_CONTACT_ANGLE_DEG = (15.0, 45.0)
RECOMMENDED_GROOVE_RATIO = (0.51, 0.52)


def _angle_cut(ds: xr.Dataset, groove_ratio: float | None) -> xr.Dataset:
    """The map at one groove ratio (the middle of the grid unless given)."""
    f = float(ds.groove_ratio.values[len(ds.groove_ratio) // 2]) if groove_ratio is None else groove_ratio
    return ds.sel(groove_ratio=f, method="nearest")


def _ratio_cut(ds: xr.Dataset, contact_angle_deg: float | None) -> xr.Dataset:
    """The map at one contact angle (the middle of the grid unless given)."""
    a = float(ds.contact_angle.values[len(ds.contact_angle) // 2]) if contact_angle_deg is None else contact_angle_deg
    return ds.sel(contact_angle=a, method="nearest")


def _sweep_panel(ax, cut: xr.Dataset, dim: str, quantity: str, xlabel: str) -> None:
    """Inner and outer race lines of one quantity along the one remaining grid dimension."""
    if quantity not in _QUANTITIES:
        raise ValueError(f"quantity must be one of {sorted(_QUANTITIES)}, not {quantity!r}")
    name, scale, ylabel = _QUANTITIES[quantity]
    x = cut[dim].values
    for race in ("inner", "outer"):
        style = dict(_STYLE[race], markevery=max(1, len(x) // _MARKERS_PER_LINE), markersize=4)
        ax.plot(x, cut.sel(race=race)[name].values * scale, label=f"{race} race", **style)
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    ax.grid(alpha=0.3)
    ax.legend()


def plot_contact_angle_cut(ds: xr.Dataset, quantity: str = "max_stress", groove_ratio: float | None = None,
                           ax=None) -> Figure:
    """One panel of Fig. 2: approach [µm] or max stress [MPa] of both races against contact angle.

    Parameters
    ----------
    ds : xarray.Dataset
        :func:`auxbearing.analysis.contact.contact_map`.
    quantity : {"max_stress", "approach"}
    groove_ratio : float, optional
        Groove radius coefficient of the cut [-]; the nearest grid value, default the middle one.
    ax : matplotlib.axes.Axes, optional
        Axes to draw in; default a new figure.
    """
    fig, ax = axes_for(ax, (5, 4))
    cut = _angle_cut(ds, groove_ratio)
    _sweep_panel(ax, cut, "contact_angle", quantity, "Contact angle α [deg]")
    ax.set_title(f"f = {float(cut.groove_ratio):.3f}, ball load {ds.attrs['ball_load_N']:g} N", loc="left")
    return fig


def plot_groove_ratio_cut(ds: xr.Dataset, quantity: str = "max_stress", contact_angle_deg: float | None = None,
                          ax=None) -> Figure:
    """One panel of Fig. 3: approach [µm] or max stress [MPa] of both races against groove ratio.

    Parameters
    ----------
    ds : xarray.Dataset
        :func:`auxbearing.analysis.contact.contact_map`.
    quantity : {"max_stress", "approach"}
    contact_angle_deg : float, optional
        Contact angle of the cut [deg]; the nearest grid value, default the middle one.
    ax : matplotlib.axes.Axes, optional
        Axes to draw in; default a new figure.
    """
    fig, ax = axes_for(ax, (5, 4))
    cut = _ratio_cut(ds, contact_angle_deg)
    _sweep_panel(ax, cut, "groove_ratio", quantity, "Groove radius coefficient f [-]")
    ax.set_title(f"α = {float(cut.contact_angle):g} deg, ball load {ds.attrs['ball_load_N']:g} N", loc="left")
    return fig


def _two_panels(fig, title: str, draw) -> Figure:
    """(a) approach and (b) max stress side by side, each drawn by ``draw(quantity, ax)``."""
    fig = figure_for(fig, (10, 4))
    axes = fig.subplots(1, 2)
    fig.suptitle(title)
    for label, quantity, ax in zip("ab", ("approach", "max_stress"), axes, strict=True):
        draw(quantity, ax)
        ax.set_title(f"({label})", loc="left")
    return fig


def plot_contact_angle_sweep(ds: xr.Dataset, groove_ratio: float | None = None, fig=None) -> Figure:
    """Approach and max stress of inner and outer race against contact angle (Fig. 2)."""
    f = float(_angle_cut(ds, groove_ratio).groove_ratio)
    return _two_panels(fig, f"Fig. 2: contact angle sweep, f = {f:.3f}, ball load {ds.attrs['ball_load_N']:g} N",
                       lambda quantity, ax: plot_contact_angle_cut(ds, quantity, f, ax=ax))


def plot_groove_ratio_sweep(ds: xr.Dataset, contact_angle_deg: float | None = None, fig=None) -> Figure:
    """Approach and max stress of inner and outer race against groove ratio (Fig. 3)."""
    a = float(_ratio_cut(ds, contact_angle_deg).contact_angle)
    return _two_panels(fig, f"Fig. 3: groove ratio sweep, α = {a:g} deg, ball load {ds.attrs['ball_load_N']:g} N",
                       lambda quantity, ax: plot_groove_ratio_cut(ds, quantity, a, ax=ax))


def plot_contact_map(ds: xr.Dataset, race: str = "inner", ax=None) -> Figure:
    """Max stress [MPa] over contact angle x groove ratio, with the paper's recommended window boxed."""
    fig, ax = axes_for(ax, (6, 4.5))
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

    (f0, f1), (a0, a1) = RECOMMENDED_GROOVE_RATIO, RECOMMENDED_CONTACT_ANGLE_DEG
    return Rectangle((f0, a0), f1 - f0, a1 - a0, fill=False, edgecolor="white", linewidth=2, linestyle="--")
