"""``auxbearing modes``: the machine's damped natural frequencies against speed (a Campbell diagram).

Heavy libraries are imported inside the command, so ``--help`` answers at once.
"""

from __future__ import annotations

import contextlib
import math
from pathlib import Path

import click

from auxbearing.cli.common import checked_out_dir, echo_json, json_option, option_named

#: Most speeds of the default range: as many as a listed one may have (auxbearing.analysis.modes.MAX_SPEEDS; not
#: imported here, so that --help answers without scipy).
MAX_SPEEDS = 1000


def _speeds(text: str | None, operating: float, points: int) -> list[float]:
    """Spin speeds [rad/s]: the listed ones ("0, 9000, 18000 rpm"), or 0 to 1.2 x the operating speed."""
    from auxbearing.analysis.modes import spin_speeds

    if text is None:
        if operating == 0.0:  # 0 to 1.2 x nothing: one speed, not --points copies of it
            return [0.0]
        top = 1.2 * abs(operating)
        return [top * i / (points - 1) for i in range(points)]
    return spin_speeds(text, "--speeds").tolist()


def _by_speed(diagram) -> list[dict]:
    """One entry per speed: its damped natural frequencies [Hz], whirl directions and damping ratios.

    A speed with fewer modes than the diagram's widest (its empty cells) lists only the modes it has.
    """
    out = []
    for i, w in enumerate(diagram.speeds):
        have = [j for j, f in enumerate(diagram.frequencies[i]) if math.isfinite(f)]
        out.append({"speed_rpm": float(w) * 30.0 / math.pi,
                    "frequencies_Hz": [float(diagram.frequencies[i, j]) for j in have],
                    "whirl": [diagram.whirl[i, j] for j in have],
                    "damping_ratios": [float(diagram.damping_ratios[i, j]) for j in have]})
    return out


#: How the console table marks each mode's whirl (:data:`auxbearing.analysis.modes.PLANAR` for a line).
_WHIRL_MARK = {"forward": "F", "backward": "B", "planar": "P"}


def _cell(frequency: float, whirl: str, ratio: float, rate: float, growing: bool) -> str:
    """One mode's table cell: its frequency [Hz] and whirl, and for a growing mode its damping ratio and UNSTABLE."""
    if not math.isfinite(frequency):
        return ""  # no such mode at this speed
    if whirl == "none":  # diverges without oscillating: no frequency to show, its e-folding time instead
        return f"no oscillation, e-fold {_duration(1.0 / rate)} UNSTABLE"
    text = f"{frequency:.1f} {_WHIRL_MARK.get(whirl, '-')}"
    return f"{text} ζ={ratio:.3g} UNSTABLE" if growing else text


def _duration(seconds: float) -> str:
    """A time with its unit, in ms below a second."""
    return f"{seconds * 1e3:.3g} ms" if seconds < 1.0 else f"{seconds:.3g} s"


@click.command("modes")
@click.option("--machine", "machine_spec", required=True, metavar="FILE|NAME",
              help="A machine TOML file or an example machine (`auxbearing machines`).")
@click.option("--speeds", default=None, metavar="LIST",
              help="Spin speeds, comma-separated with one unit at the end ('0, 9000, 18000 rpm'); default: "
                   "--points speeds from 0 to 1.2 x the machine's speed.")
@click.option("--points", default=13, show_default=True, type=click.IntRange(min=2, max=MAX_SPEEDS),
              help="Speeds of the default range.")
@click.option("--out", "out_dir", type=click.Path(file_okay=False, path_type=Path), default=None,
              callback=checked_out_dir, help="Write modes.json and the figures (Campbell, mode shapes) here.")
@json_option()
def modes_command(machine_spec, speeds, points, out_dir, as_json):
    """Natural frequencies against speed: free (levitated) and with the touchdown planes in contact at rest.

    The linear model of the drop's rotor: the rigid body and the elastic modes of a rotor given as matrices,
    the linear supports, free the radial magnetic bearings (each controller evaluated at each mode's own
    frequency; an axial bearing carries no lateral load and is left out), and for "in contact" each
    touchdown plane's line contact, ball set (single row or matched pair, with its preload) and mount
    linearised under its share of the weight along it, and the journal swinging on the arc of its clearance
    across it (a pendulum of length c). A plane that carries no weight at rest (every plane of a vertical
    machine) adds nothing: in contact its rotor is held by the linear supports alone. Forward, backward and
    planar (a line orbit) modes are told apart; the critical speeds are where the synchronous line crosses a
    forward or planar mode. A mode that grows is shown with its damping ratio and marked UNSTABLE, a root
    that diverges without oscillating too. A machine whose speed is 0 rpm gets one row at rest by default.
    """
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    from auxbearing.analysis.modes import STATES, campbell
    from auxbearing.cli.common import read_machine_file
    from auxbearing.common.io import atomic_output_dir, save_figure, write_json

    with option_named("--machine", "machine"), option_named("--machine", "file", value=machine_spec):
        machine = read_machine_file(machine_spec)
    omegas = _speeds(speeds, machine.rotor.speed, points)
    diagrams = [campbell(machine, omegas, state) for state in STATES]
    result = {"machine": machine.name, "operating_speed_rpm": abs(machine.rotor.speed) * 30.0 / math.pi,
              "elastic_modes": 0 if machine.modal() is None else machine.modal().natural,
              "static_correction_vectors": 0 if machine.modal() is None else machine.modal().residual,
              "modes": _by_speed(diagrams[0]), "modes_in_contact": _by_speed(diagrams[1]),
              "states": [d.as_dict() for d in diagrams]}
    with atomic_output_dir(out_dir) if out_dir is not None else contextlib.nullcontext() as tmp:
        if tmp is not None:
            from auxbearing.plots.modes import plot_campbell, plot_mode_shapes

            write_json(result, tmp / "modes.json", machine.describe())
            save_figure(plot_campbell(diagrams, machine.rotor.speed), tmp / "campbell")
            modal = machine.modal()
            if modal is not None and modal.n_modes:
                save_figure(plot_mode_shapes(modal), tmp / "mode_shapes")
    if as_json:
        echo_json(result)
        return
    console = Console()
    name = escape(machine.name)  # a machine's name is its author's text, not markup
    if speeds is None and machine.rotor.speed == 0.0:
        console.print(f"{name}: its speed is 0 rpm, so one row at rest; give --speeds for a range")
    for d in diagrams:
        if d.frequencies.shape[1] == 0:
            console.print(f"{name}, {d.state}: no mode; nothing holds the rigid rotor (no linear support), "
                          "only its rigid-body motions")
            continue
        table = Table(title=f"{name}: natural frequencies, {'free' if d.state == 'free' else 'in contact'}")
        # rich reads a lowercase [..] as a style tag and drops it: every header is escaped
        table.add_column(escape("speed [rpm]"), justify="right")
        width = min(d.frequencies.shape[1], 8)
        for j in range(width):
            table.add_column(escape(f"mode {j + 1} [Hz]"), justify="right")
        rates, growing = d.growth_rates, d.growing()
        for i, omega in enumerate(d.speeds):
            cells = [escape(_cell(d.frequencies[i, j], d.whirl[i, j], d.damping_ratios[i, j], rates[i, j],
                                  growing[i, j])) for j in range(width)]
            table.add_row(f"{omega * 30.0 / math.pi:.0f}", *cells)
        console.print(table)
        if d.frequencies.shape[1] > width:
            console.print(f"(the first {width} of {d.frequencies.shape[1]} modes; --json or --out lists them all)")
        crit = ", ".join(f"{c['speed_rpm']:.0f} rpm" for c in d.critical_speeds()) or "none in the range"
        console.print(f"critical speeds (1x on a forward or planar mode): {crit}; F forward, B backward, "
                      "P planar (a line), - a pair of equal frequency", highlight=False)
        counts = d.growing().sum(axis=1)
        if counts.any():
            at = ", ".join(f"{n} at {abs(w) * 30.0 / math.pi:.0f} rpm" for n, w in zip(counts, d.speeds, strict=True)
                           if n)
            console.print(f"[bold red]warning:[/] {name}, {'free' if d.state == 'free' else 'in contact'}: growing "
                          f"modes (negative damping ratio, marked UNSTABLE): {at}; the linear model is unstable there",
                          highlight=False)
        if d.unsettled:
            console.print(f"warning: {d.unsettled} mode(s) whose magnetic bearings' spring and damper did not settle "
                          "at the mode's own frequency; shown at the last iterate", highlight=False)
    if out_dir is not None:
        console.print(f"Wrote modes.json and the figures in {escape(str(out_dir))}/", highlight=False)

#: The commands of this module, for the command table of :mod:`auxbearing.cli.main`.
COMMANDS = (modes_command,)
