"""Figures of the machine's natural frequencies: a Campbell diagram (:func:`auxbearing.analysis.modes.campbell`).

``ax=None`` as the other figures: given an axes it draws there and returns its figure.
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from auxbearing.plots._axes import axes_for

_STYLE = {"forward": ("tab:red", "forward"), "backward": ("tab:blue", "backward"),
          "planar": ("tab:green", "planar (a line)"), "pair": ("0.4", "pair (either direction)")}


def plot_campbell(diagrams, operating_speed: float, ax=None) -> Figure:
    """Damped natural frequencies [Hz] against speed [rpm] for each state, with 1x and the operating speed.

    Free: filled markers, in contact: hollow; coloured by whirl direction. A mode that grows (an unstable one) is
    crossed out in black, and a root that diverges without oscillating (a static instability: its frequency is 0)
    is a purple triangle on the speed axis, as the tables list them (``Campbell.unstable``).
    """
    fig, ax = axes_for(ax, (7, 4.5))
    rpm = 30.0 / np.pi
    top, span = 0.0, 1.0
    seen = set()
    for diagram in diagrams:
        hollow = diagram.state == "contact"
        speeds = np.abs(diagram.speeds) * rpm
        for whirl, (colour, label) in _STYLE.items():
            mask = diagram.whirl == whirl
            if not mask.any():
                continue
            rows, cols = np.nonzero(mask)
            name = f"{label}, {'in contact' if hollow else 'free'}"
            ax.scatter(speeds[rows], diagram.frequencies[rows, cols], s=14, marker="o",
                       facecolors="none" if hollow else colour, edgecolors=colour, linewidths=0.8,
                       label=None if name in seen else name)
            seen.add(name)
        growing = diagram.growing()
        for mask, marker, colour, name in ((growing & (diagram.whirl != "none"), "x", "k", "growing (unstable)"),
                                           (growing & (diagram.whirl == "none"), "^", "tab:purple",
                                            "diverging without oscillating (0 Hz)")):
            if mask.any():
                rows, cols = np.nonzero(mask)
                ax.scatter(speeds[rows], np.nan_to_num(diagram.frequencies[rows, cols]), s=30, marker=marker,
                           color=colour, linewidths=1.0, clip_on=False, zorder=3,
                           label=None if name in seen else name)
                seen.add(name)
        top = max(top, float(np.nanmax(diagram.frequencies)) if diagram.frequencies.size else 0.0)
        span = speeds.max() if speeds.size else 1.0
    ax.plot([0.0, span], [0.0, span / 60.0], color="k", lw=0.8, label="1x (synchronous)")
    ax.axvline(abs(operating_speed) * rpm, color="k", ls=":", lw=0.8, label="operating speed")
    ax.set_xlabel("Spin speed [rpm]")
    ax.set_ylabel("Damped natural frequency [Hz]")
    ax.set_ylim(0.0, 1.05 * max(top, span / 60.0, 1.0))
    ax.set_title("Campbell diagram: free (filled) and in contact at rest (hollow)", loc="left")
    ax.grid(alpha=0.3)
    ax.legend(fontsize=7, ncol=3, loc="upper center", bbox_to_anchor=(0.5, -0.14), frameon=False)
    return fig


def plot_mode_shapes(modal, count: int = 4, ax=None) -> Figure:
    """The first ``count`` elastic free-free mode shapes along the rotor (x displacement, scaled to 1)."""
    fig, ax = axes_for(ax, (7, 3.5))
    z = modal.nodes * 1e3
    shown = 0
    for j in range(0, modal.natural):  # the static correction's vectors are not modes of the shaft
        shape = modal.shapes[0::4, j]
        if np.abs(shape).max() < 0.5 * np.abs(modal.shapes[1::4, j]).max():
            continue  # the y twin of a pair: drawn once
        ax.plot(z, shape / np.abs(shape).max(), marker=".", label=f"{modal.frequencies[j] / (2 * np.pi):.0f} Hz")
        shown += 1
        if shown == count:
            break
    ax.axhline(0.0, color="k", lw=0.5)
    ax.set_xlabel("Axial position from the mass centre [mm]")
    ax.set_ylabel("Lateral displacement [-]")
    ax.set_title("free-free elastic modes at rest", loc="left")
    ax.grid(alpha=0.3)
    if shown:
        ax.legend(fontsize=8)
    return fig
