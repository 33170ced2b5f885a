"""The machine at a glance: rotor, touchdown planes, clearances, bearings, mounts, collars and stations (a sketch)."""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Circle, Rectangle

from auxbearing.plots._axes import axes_for


def plot_machine(machine, ax=None) -> Figure:
    """A side view along the rotor axis: journal, planes with their bearings, clearances (exaggerated), mass centre.

    Lengths along the axis are to scale [mm]; radial clearances are drawn 20 times enlarged and labelled.
    """
    fig, ax = axes_for(ax, (9, 3.6))
    planes = machine.planes
    stations = [s for s in getattr(machine, "stations", ()) if getattr(s, "on_rotor", True)]
    modal = machine.modal()
    nodes = [] if modal is None or len(modal.nodes) < 2 else list(modal.nodes * 1e3)
    positions = ([p.position * 1e3 for p in planes] + [s.position * 1e3 for s in stations]
                 + [u[0] * 1e3 for u in machine.rotor.unbalance_planes])
    span = max(max(positions + nodes) - min(positions + nodes), 100.0)
    if nodes:  # the shaft as its matrices give it, end to end
        left, right = min(nodes), max(nodes)
    else:
        left, right = min(positions) - 0.25 * span, max(positions) + 0.25 * span
    radius = max(p.journal_radius for p in planes) * 1e3
    ax.add_patch(Rectangle((left, -radius), right - left, 2 * radius, facecolor="0.85", edgecolor="0.3", lw=1))
    ax.plot(0.0, 0.0, marker="o", ms=9, mfc="white", mec="black")
    ax.plot(0.0, 0.0, marker="+", ms=9, color="black")
    # under the shaft, or under the bearings where a plane sits at the mass centre (its balls would cover the text)
    top = max(_outer_radius(p) for p in planes)  # the bearings' outer edge [mm]
    crowded = any(abs(p.position * 1e3) < 0.08 * span for p in planes)
    ax.annotate(f"mass centre\n{machine.rotor.mass:g} kg, {machine.rotor.speed * 30 / np.pi:.0f} rpm", (0.0, 0.0),
                (0.0, -top * 1.9 if crowded else -radius * 2.6), ha="center", fontsize=8,
                arrowprops={"arrowstyle": "-", "color": "0.4"})
    for plane in planes:
        z = plane.position * 1e3
        width = (plane.bearing.width or plane.bearing.ball_diameter) * 1e3
        bore = plane.journal_radius * 1e3 + 20.0 * plane.radial_clearance * 1e3  # clearance enlarged x20
        outer = _outer_radius(plane)
        ball = plane.bearing.ball_diameter * 0.5e3
        pitch = plane.bearing.pitch_diameter * 0.5e3
        for sign in (1.0, -1.0):
            ax.add_patch(Rectangle((z - width / 2, sign * bore if sign > 0 else -outer), width, outer - bore,
                                   facecolor="tab:blue", alpha=0.25, edgecolor="tab:blue"))
            ax.add_patch(Circle((z, sign * pitch), ball, facecolor="tab:blue", edgecolor="navy", lw=0.8))
            if plane.mount is not None:
                ax.plot([z - width / 2, z + width / 2], [sign * (outer + 1.5)] * 2, color="tab:green", lw=3)
        if plane.catches_axially:
            ax.add_patch(Rectangle((z - width / 2 - 3.0, radius), 3.0, 0.6 * (bore - radius) + 2.0, color="tab:red"))
        text = (f"{plane.name}\n{plane.unit.name} ({plane.unit.label})\ns = {plane.radial_clearance * 1e3:g} mm"
                + (f", axial {plane.axial_clearance * 1e3:g} mm" if plane.catches_axially else "")
                + (f"\nmount {plane.mount.mount_stiffness:.2g} N/m" if plane.mount is not None else "\nrigid housing"))
        ax.text(z, outer + 6.0, text, ha="center", va="bottom", fontsize=8)
    _stations(ax, machine, stations, radius, top, span)
    ax.set_xlim(min(left, *positions) - 0.05 * span, max(right, *positions) + 0.05 * span)
    ax.set_ylim(-top * 2.9, top * 2.6)
    ax.set_aspect("equal")
    ax.set_xlabel("axial position from the mass centre [mm]; radial clearances drawn 20x\nblue: bearings, "
                  "green: mounts, red: axial collars, magenta: magnetic bearings, orange: supports and loads",
                  fontsize=8)
    ax.set_yticks([])
    ax.set_title(f"{machine.name} ({machine.orientation})", loc="left")
    for spine in ("left", "right", "top"):
        ax.spines[spine].set_visible(False)
    return fig


def _outer_radius(plane) -> float:
    """Outer radius of a plane's bearing as drawn [mm] (1.4 pitch diameters where the catalogue gives none)."""
    return (plane.bearing.outside_diameter or plane.bearing.pitch_diameter * 1.4) * 0.5e3


def _stations(ax, machine, stations, radius: float, top: float, span: float) -> None:
    """The stations beside the planes: magnetic bearings (a thrust bearing as its disc), supports, loads, unbalance."""
    width = 0.03 * span
    for i, s in enumerate(sorted(stations, key=lambda s: s.position)):
        z = s.position * 1e3
        if s.KIND == "amb" and getattr(s, "axial", False):
            ax.add_patch(Rectangle((z - width / 6, -1.6 * radius), width / 3, 3.2 * radius, facecolor="magenta",
                                   alpha=0.5, edgecolor="purple"))
            label = f"{s.name} (axial)"
        elif s.KIND == "amb":
            for sign in (1.0, -1.0):
                ax.add_patch(Rectangle((z - width / 2, sign * 1.15 * radius if sign > 0 else -1.9 * radius), width,
                                       0.75 * radius, facecolor="magenta", alpha=0.35, edgecolor="purple"))
            label = s.name
        elif s.KIND == "linear_support":
            ax.plot([z], [-1.4 * radius], marker="^", ms=9, color="tab:orange")
            label = s.name
        else:  # a load at a place on the rotor
            ax.annotate("", (z, -radius), (z, -2.2 * radius), arrowprops={"arrowstyle": "->", "color": "tab:orange"})
            label = s.name
        ax.text(z, -top * (1.6 + 0.55 * (i % 2)), label, ha="center", va="top", fontsize=7,
                color="purple" if s.KIND == "amb" else "tab:orange")  # staggered: neighbours do not overlap
    for position, amount, _ in machine.rotor.unbalance_planes:
        ax.plot([position * 1e3], [radius * 0.5], marker="$U$", ms=8, color="black")
        ax.text(position * 1e3, radius * 0.9, f"{amount * 1e6:g} g mm", ha="center", va="bottom", fontsize=6)
