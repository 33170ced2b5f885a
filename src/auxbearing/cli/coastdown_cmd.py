"""``auxbearing coastdown``: a machine from its drop to standstill, with heat, thermal growth and life.

Heavy libraries are imported inside the command, so ``--help`` answers at once.
"""

from __future__ import annotations

import contextlib
import math
from pathlib import Path

import click

from auxbearing.cli.common import ProgressReporter, checked_out_dir, echo_json, json_option, option_named, warn
from auxbearing.cli.drop_checks import MAX_BALL_CONTACTS
from auxbearing.common.errors import InputError


def _given_on_command_line(name: str) -> bool:
    """Whether the user typed the option (not its default)."""
    from click.core import ParameterSource

    return click.get_current_context().get_parameter_source(name) == ParameterSource.COMMANDLINE


@click.command("coastdown")
@click.option("--machine", "machine_spec", required=True, metavar="FILE|NAME",
              help="A machine TOML file or an example machine (`auxbearing machines`).")
@click.option("--until-stop/--duration-only", "until_stop", default=True, show_default=True,
              help="Run to standstill (at most the file's coastdown.max_time), or only for --duration.")
@click.option("--duration", default=None, metavar="TIME",
              help="Simulated time instead of running to standstill (plain numbers in s); it stops at standstill "
                   "too, and may exceed the file's coastdown.max_time, which bounds the run to standstill.")
@click.option("--mode", type=click.Choice(["auto", "full"]), default="auto", show_default=True,
              help="auto: settled stretches go to the reduced model; full: full dynamics throughout (slow).")
@click.option("--out", "out_dir", type=click.Path(file_okay=False, path_type=Path), default=None,
              callback=checked_out_dir,
              help="Write coastdown.nc (the coast-down, reduced stretches marked), drop.nc, coastdown_summary.json "
                   "and the figures into this folder.")
@click.option("--max-ball-contacts", default=MAX_BALL_CONTACTS, show_default=True, type=click.IntRange(min=1),
              metavar="N",
              help="Budget: most ball contact pairs (balls x pairs x rows) per touchdown plane; every step evaluates "
                   "each.")
@json_option()
@click.option("--quiet", is_flag=True, help="No progress output.")
def coastdown_command(machine_spec, until_stop, duration, mode, out_dir, max_ball_contacts, as_json, quiet):
    """A machine from the drop to standstill: spin-down, friction heat, thermal growth, drops to failure.

    Full dynamics checks the motion in short windows; once it has settled, a reduced model carries the
    speed and the temperatures (the losses measured in the last window). Thermal growth of journal,
    races and balls changes the clearances as the run goes on; a part above coastdown.max_temperature,
    a closed clearance or an internal preload above ISO 76 ends the run with that verdict. Life: fatigue
    damage of the drop and its coast-down (rainflow, ISO 281) and Palmgren's dent, against life.required_drops.
    """
    from rich.console import Console
    from rich.table import Table

    from auxbearing.analysis.coastdown import run_coastdown, shortest_coastdown, shortest_coastdown_rule
    from auxbearing.analysis.coastdown_life import cycles_of_worst_contact
    from auxbearing.analysis.plausibility import plausibility
    from auxbearing.cli.common import read_machine_file
    from auxbearing.cli.drop_checks import check_ball_contacts, machine_input_names, stiffness_warnings
    from auxbearing.common.io import atomic_output_dir, save_dataset, save_figure, write_json
    from auxbearing.common.units import to_si

    with option_named("--machine", "machine"), option_named("--machine", "file", value=machine_spec):
        machine = read_machine_file(machine_spec)
    check_ball_contacts(machine, max_ball_contacts, f"--machine = {machine_spec!r}")
    warn(*stiffness_warnings(machine, machine.simulation.duration, f"--machine = {machine_spec!r}: "))
    warn(*plausibility(machine, machine_input_names(machine_spec)))
    seconds = None
    if duration is not None and until_stop and _given_on_command_line("until_stop"):
        raise InputError.for_field("--until-stop", "given", f"contradicts --duration {duration}: give one of them")
    if duration is not None:
        seconds = to_si("--duration", duration, "time", "s")
        if not 0.0 < seconds <= 1e6:
            raise InputError.for_field("--duration", duration, "must lie in (0, 1e6] s")
        if seconds < shortest_coastdown(machine):
            raise InputError.for_field("--duration", duration, shortest_coastdown_rule(machine))
        until_stop = False
    elif not until_stop:
        raise InputError.for_field("--duration-only", "given", "needs --duration TIME")
    with atomic_output_dir(out_dir) if out_dir is not None else contextlib.nullcontext() as tmp:
        with ProgressReporter(f"coast-down of {machine.name}", quiet) as progress:
            run = run_coastdown(machine, until_stop=until_stop, duration=seconds, mode=mode, progress=progress)
        summary = run.summary
        if tmp is not None:
            from auxbearing.plots.coastdown import plot_clearances, plot_speeds, plot_stress_cycles, plot_temperatures

            inputs = machine.describe()
            save_dataset(run.history, tmp / "coastdown.nc", inputs)
            save_dataset(run.drop.dataset, tmp / "drop.nc", inputs)
            save_figure(plot_speeds(run.history), tmp / "coastdown_speeds")
            for k in range(len(machine.planes)):
                save_figure(plot_temperatures(run.history, k), tmp / f"coastdown_temperatures_{k}")
                if run.life[k] is not None:
                    save_figure(plot_stress_cycles(cycles_of_worst_contact(run.life[k])), tmp / f"stress_cycles_{k}")
            save_figure(plot_clearances(run.history), tmp / "coastdown_clearances")
            write_json(summary, tmp / "coastdown_summary.json", inputs)
    if out_dir is not None:
        summary = {**summary, "out": str(out_dir)}
    if summary["verdict"] != "ok":
        warn(f"verdict {summary['verdict']}: {summary['reason']}")
    if as_json:
        echo_json(summary)
        return
    console = Console()
    table = Table(title=f"Coast-down of {machine.name}: verdict {summary['verdict']}")
    table.add_column("quantity")
    table.add_column("unit")
    for plane in summary["planes"]:
        table.add_column(plane["name"], justify="right")

    def shown(fmt, value):  # a clearance that moved by -1e-9 um is "0.00", not "-0.00"
        if isinstance(value, float) and math.isinf(value):  # a plane the drop left unloaded: nothing limits it
            return "no limit"
        text = fmt.format(value)
        return text[1:] if text.startswith("-") and isinstance(value, float) and float(text) == 0.0 else text

    def row(label, unit, fmt, key):
        table.add_row(label, unit, *("-" if p.get(key) is None else shown(fmt, p[key]) for p in summary["planes"]))

    table.add_row("Hottest part", "°C", *("-" if p["max_temperature_C"] is None else
                                          f"{max(p['max_temperature_C'].values()):.1f}" for p in summary["planes"]))
    row("Smallest journal/race clearance", "µm", "{:.1f}", "min_radial_clearance_um")
    row("Smallest internal clearance", "µm", "{:.2f}", "min_internal_clearance_um")
    row("Fatigue damage per drop", "-", "{:.3g}", "damage_per_drop")
    row("Drops to fatigue failure (L10)", "-", "{:.3g}", "drops_to_failure")
    row("Drops to the ISO 76 dent limit", "-", "{:.3g}", "drops_to_dent_limit")
    row("Governing", "", "{}", "governing")
    console.print(table)
    if summary["planes"] and summary["planes"][0].get("life_note"):
        console.print(f"Drops to failure {summary['planes'][0]['life_note']}", highlight=False)
    stop = summary["coastdown_time_s"]
    console.print(f"{'standstill after ' + format(stop, '.1f') + ' s' if stop is not None else 'not at standstill'}"
                  f"; simulated {summary['simulated_s']:.3g} s in {summary['wall_time_s']:.1f} s "
                  f"({summary['full_dynamics_s']:.3g} s of full dynamics); energy balance error "
                  f"{summary['energy_balance_error']:.1e}; required drops {summary['required_drops']:g} "
                  f"({summary['required_drops_source']})", highlight=False)
    from auxbearing.analysis.coastdown import rattle_note, tail_note

    for note in (tail_note(summary.get("tail")), rattle_note(summary)):
        if note:
            console.print(note[0].upper() + note[1:] + ".", highlight=False)
    if summary["reason"]:
        console.print(f"[bold]{summary['reason']}[/bold]")
    if out_dir is not None:
        click.echo(f"Wrote coastdown.nc, drop.nc, coastdown_summary.json and the figures in {out_dir}/")


COMMANDS = [coastdown_command]
