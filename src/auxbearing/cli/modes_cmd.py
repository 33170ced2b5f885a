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
        top = 1.2 * abs(operating)
        return [top * i / (points - 1) for i in range(points)]
    return spin_speeds(text, "--speeds").tolist()


def _by_speed(diagram) -> list[dict]:
    """One entry per speed: its damped natural frequencies [Hz], whirl directions and damping ratios."""
    return [{"speed_rpm": float(w) * 30.0 / math.pi, "frequencies_Hz": diagram.frequencies[i].tolist(),
             "whirl": list(diagram.whirl[i]), "damping_ratios": diagram.damping_ratios[i].tolist()}
            for i, w in enumerate(diagram.speeds)]


#: How the console table marks each mode's whirl (:data:`auxbearing.analysis.modes.PLANAR` for a line).
_WHIRL_MARK = {"forward": "F", "backward": "B", "planar": "P"}


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
    the linear supports, and for "in contact" each touchdown plane's line contact, ball set and mount
    linearised under its share of the weight along it, and the journal swinging on the arc of its clearance
    across it (a pendulum of length c). Forward, backward and planar (a line orbit) modes are told apart; the
    critical speeds are where the synchronous line crosses a forward or planar mode.
    """
    from rich.console import Console
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
    for d in diagrams:
        if d.frequencies.shape[1] == 0:
            console.print(f"{machine.name}, {d.state}: no mode; nothing holds the rigid rotor (no linear support), "
                          "only its rigid-body motions")
            continue
        table = Table(title=f"{machine.name}: natural frequencies, {'free' if d.state == 'free' else 'in contact'}")
        table.add_column("speed [rpm]", justify="right")
        width = min(d.frequencies.shape[1], 8)
        for j in range(width):
            table.add_column(f"mode {j + 1} [Hz]", justify="right")
        for i, omega in enumerate(d.speeds):
            cells = [f"{f:.1f} {_WHIRL_MARK.get(w, '-')}"
                     for f, w in zip(d.frequencies[i, :width], d.whirl[i, :width], strict=True)]
            table.add_row(f"{omega * 30.0 / math.pi:.0f}", *cells)
        console.print(table)
        crit = ", ".join(f"{c['speed_rpm']:.0f} rpm" for c in d.critical_speeds()) or "none in the range"
        console.print(f"critical speeds (1x on a forward or planar mode): {crit}; F forward, B backward, "
                      "P planar (a line), - a pair of equal frequency")
    if out_dir is not None:
        console.print(f"Wrote modes.json and the figures in {out_dir}/")

#: The commands of this module, for the command table of :mod:`auxbearing.cli.main`.
COMMANDS = (modes_command,)
