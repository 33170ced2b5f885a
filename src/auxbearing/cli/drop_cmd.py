"""``auxbearing drop``, ``auxbearing machines`` and ``auxbearing drop-compare``.

``drop --machine FILE_OR_NAME`` runs a machine (rigid rotor on one or more touchdown planes,
:mod:`auxbearing.machine.model`); without it, ``drop`` runs the source paper's planar drop (Sec. II.D,
Fig. 9-11), whose rotor and drop parameters of :data:`auxbearing.planar.params.PARAMETERS` are options
(generated from that table, so help, unit and default cannot drift apart) and keys of the
``[rotor]`` / ``[drop]`` tables of a ``--config`` TOML file; options win over the file. Heavy
libraries are imported inside the commands, so ``--help`` answers at once.
"""

from __future__ import annotations

import contextlib
import functools
import math
from pathlib import Path

import click

from auxbearing.analysis.plausibility import impact_rate_warning, plausibility, race_sink_warning, sink_check
from auxbearing.cli.common import (
    ProgressReporter,
    bearing_option,
    checked_out_dir,
    echo_json,
    json_option,
    option_named,
    out_option,
    resolve_bearing,
    warn,
)
from auxbearing.cli.drop_checks import (
    MAX_BALL_CONTACTS,
    budgeted,
    check_ball_contacts,
    check_budget,
    decimation_note,
    machine_input_names,
    paper_stiffness_names,
    stiffness_warnings,
)
from auxbearing.common.errors import InputError
from auxbearing.planar.params import PARAMETERS, Param, check, convert, display_value

#: Option names that differ from the parameter key ("--friction" is the issue's name for mu_1).
_OPTION_NAMES = {
    ("rotor", "mass"): "rotor-mass",
    ("rotor", "polar_inertia"): "rotor-inertia",
    ("rotor", "radius"): "rotor-radius",
    ("drop", "sliding_friction"): "friction",
}


def _option_name(param: Param) -> str:
    return _OPTION_NAMES.get((param.section, param.key), param.key.replace("_", "-"))


def _default_text(param: Param) -> str:
    if param.default is None:
        return "derived"
    if not param.display_unit:
        return f"{param.default:g}"
    return str(display_value(param, param.default))


def parameter_options(func):
    """Add one option per rotor/drop parameter; they arrive as ``params={(section, key): text}``."""
    for param in reversed(PARAMETERS):
        unit = f" Plain numbers in {param.display_unit}." if param.display_unit else ""
        func = click.option(
            f"--{_option_name(param)}", f"p__{param.section}__{param.key}", default=None, metavar="VALUE",
            help=f"{param.help} [{param.section}.{param.key}; default {_default_text(param)}].{unit}",
        )(func)

    @functools.wraps(func)
    def wrapper(*args, **kwargs):
        given = {}
        for name in list(kwargs):
            if name.startswith("p__"):
                text = kwargs.pop(name)
                if text is not None:
                    _, section, key = name.split("__")
                    given[(section, key)] = text
        return func(*args, params=given, **kwargs)

    return wrapper


def config_option():
    """``--config``: a TOML file with [rotor], [drop] and optionally [bearing] tables."""
    return click.option("--config", "config", type=click.Path(dir_okay=False, path_type=Path), default=None,
                        help="TOML file with [rotor] and [drop] tables (values with units) and optionally "
                             "[bearing]; options on the command line override it.")


def quiet_option():
    """``--quiet``: no progress bar."""
    return click.option("--quiet", is_flag=True, help="No progress bar.")


def build_inputs(ctx: click.Context, bearing_spec: str, config: Path | None, params: dict):
    """Bearing, Rotor and DropCase from catalogue/TOML/options (options win); errors name options as typed."""
    from auxbearing.planar.params import DropCase, Rotor, read_config

    if config is None:
        bearing, rotor_kw, drop_kw = None, {}, {}
    else:
        with option_named("--config", "file"):
            bearing, rotor_kw, drop_kw = read_config(config)
    source = ctx.get_parameter_source("bearing_spec")
    if bearing is None or source != click.core.ParameterSource.DEFAULT:
        bearing = resolve_bearing(bearing_spec)
    by_key = {(p.section, p.key): p for p in PARAMETERS}
    for (section, key), text in params.items():
        param = by_key[(section, key)]
        field = f"--{_option_name(param)}"
        value = convert(field, text, param.dimension, param.display_unit or None)
        check(param, value, field, text)
        (rotor_kw if section == "rotor" else drop_kw)[key] = value
    with _options_as_typed(params):
        return bearing, Rotor(**rotor_kw), DropCase(**drop_kw)


@contextlib.contextmanager
def _options_as_typed(params: dict):
    """An error about ``rotor.x`` / ``drop.x`` / the plane's keys, told as the option typed (when one was)."""
    aliases = {"touchdown.0.radial_clearance": ("drop", "clearance"), "drop.start_x, drop.start_y": ("drop", "start_x"),
               "touchdown.0.journal_radius": ("rotor", "radius")}
    try:
        yield
    except InputError as err:
        text = str(err)
        field, sep, rest = text.partition(" = ")
        if not sep:  # "touchdown.0.journal_radius: missing; ..." names no value
            field, _, rest = text.partition(": ")
        if field == "drop.start_x, drop.start_y":  # the start point: both options as typed, whichever were
            start = [("drop", "start_x"), ("drop", "start_y")]
            typed = [f"--{_option_name(p)} = {params[(p.section, p.key)]!r}" for p in PARAMETERS
                     if (p.section, p.key) in start and (p.section, p.key) in params]
            if typed:
                raise InputError(", ".join(typed) + ": " + rest.partition(": ")[2]) from None
        key = aliases.get(field) or tuple(field.split(".", 1))
        param = next((p for p in PARAMETERS if (p.section, p.key) == key), None)
        if param is None:
            raise
        option = f"--{_option_name(param)}"
        if not sep:
            raise InputError(f"{option}: {rest} (give {option})") from None
        if key not in params:
            raise
        _, _, rule = rest.partition(": ")
        raise InputError.for_field(option, params[key], rule) from None


def _clearances_fit(names, s_list, rotor, case, typed: str) -> None:
    """Refuse, before any run, a clearance one of the bearings cannot take, naming --clearances as typed."""
    from dataclasses import replace

    from auxbearing.planar.rig import planar_machine

    for name in names:
        bearing = resolve_bearing(name, option="bearing")
        for s in s_list:
            try:
                planar_machine(bearing, rotor, replace(case, clearance=s))
            except InputError as err:  # the plane's key names what the list gave: say it as the option
                rule = str(err).partition(": ")[2] or str(err)
                raise InputError.for_field("--clearances", typed, f"{s * 1e3:g} mm with {name}: {rule}") from None


def paper_machine(ctx: click.Context, bearing_spec: str, config: Path | None, params: dict):
    """The paper's drop as :func:`build_inputs` gives it and its machine, built before any work is done."""
    from auxbearing.planar.rig import planar_machine

    bearing, rotor, case = build_inputs(ctx, bearing_spec, config, params)
    with _options_as_typed(params):
        machine = planar_machine(bearing, rotor, case)
    return bearing, rotor, case, machine


_ROWS = (("peak_contact_force_N", "Peak collision force", "N", "{:.1f}"),
         ("peak_ball_stress_MPa", "Peak ball contact stress", "MPa", "{:.1f}"),
         ("s0", "Static safety factor s0 (ISO 76)", "-", "{:.2f}"),
         ("first_impact_ms", "First impact", "ms", "{:.3f}"),
         ("impacts", "Impacts (contact onsets)", "-", "{}"),
         ("largest_bounce_um", "Largest bounce", "µm", "{:.1f}"),
         ("whirl", "Whirl", "", "{}"),
         ("whirl_frequency_Hz", "Whirl frequency", "Hz", "{:.1f}"),
         ("final_rotor_speed_rad_s", "Final rotor speed", "rad/s", "{:.1f}"),
         ("final_race_speed_rad_s", "Final race speed", "rad/s", "{:.1f}"),
         ("race_spin_up_ms", "Race spin-up (95 % of rolling)", "ms", "{:.2f}"),
         ("contact_fraction", "Contact fraction after first impact", "-", "{:.3f}"),
         ("steps", "Integration steps", "-", "{}"),
         ("wall_time_s", "Integration wall time", "s", "{:.3f}"))


def _fmt(fmt: str, value) -> str:
    return "-" if value is None else fmt.format(value)


@click.command("drop")
@click.option("--machine", "machine_spec", default=None, metavar="FILE|NAME",
              help="A machine TOML file or an example machine (`auxbearing machines`); without it, the paper's rig.")
@bearing_option()
@config_option()
@parameter_options
@click.option("--max-ball-contacts", default=MAX_BALL_CONTACTS, show_default=True, type=click.IntRange(min=1),
              metavar="N",
              help="Budget: most ball contact pairs (balls x pairs) per touchdown plane; every step evaluates each.")
@click.option("--max-wall-time", default=None, metavar="TIME",
              help="Wall-time budget of the run (plain numbers in s) [default: the machine's drop.max_wall_time, "
                   "600 s for the paper's rig].")
@click.option("--out", "out_dir", type=click.Path(file_okay=False, path_type=Path), default=None,
              callback=checked_out_dir,
              help="Write the time series (drop.nc), drop_summary.json and the figures into this folder.")
@click.option("--scenario", default=None, metavar="NAME",
              help="With --machine: the [[scenario]] that fails its magnetic bearings (levitated until its time); "
                   "without it they fail at the drop.")
@json_option()
@quiet_option()
@click.pass_context
def drop_command(ctx, machine_spec, bearing_spec, config, params, max_ball_contacts, max_wall_time, out_dir, scenario,
                 as_json, quiet):
    """Drop of a rotor onto its touchdown bearings.

    With --machine: a rigid rotor on one or more touchdown planes (gyroscopics, axial touchdown,
    compliant mounts). The run watches the model's range and ends with a verdict: "ok", or the limit it
    crossed, where it stops (its peaks and s0 then cover the run up to that stop only). Whirl is judged window
    by window.

    Without --machine: the source paper's planar drop (Sec. II.D, Eq. 17-26, corrected): Table II
    defaults with the corrected units, clearance 0.2 mm, 6000 rpm, 0.15 s. Values take units
    ("0.2mm", "6000rpm"); plain numbers use the unit named in each option's help.
    """
    wall = None
    if max_wall_time is not None:
        from auxbearing.common.units import to_si

        wall = to_si("--max-wall-time", max_wall_time, "time", "s")
        if not 0.0 < wall <= 1e6:
            raise InputError.for_field("--max-wall-time", max_wall_time, "must lie in (0, 1e6] s")
    if machine_spec is not None:
        duration = params.pop(("drop", "duration"), None)  # --duration applies to both kinds of run
        paper_options = [f"--{_option_name(p)}" for p in PARAMETERS if (p.section, p.key) in params]
        source = ctx.get_parameter_source
        if paper_options or config is not None or source("bearing_spec") != click.core.ParameterSource.DEFAULT:
            given = paper_options or (["--config"] if config is not None else ["--bearing"])
            raise InputError.for_field(given[0], "given with --machine",
                                       "the paper-rig options do not apply to a machine; set them in its file")
        _machine_drop(machine_spec, duration, wall, max_ball_contacts, out_dir, as_json, quiet, scenario)
        return
    if scenario is not None:
        raise InputError.for_field("--scenario", scenario, "needs --machine (a machine file with [[scenario]] tables)")
    _paper_drop(ctx, bearing_spec, config, params, wall, max_ball_contacts, out_dir, as_json, quiet)


def _typed_names(params: dict) -> dict:
    """How the paper drop's plausibility warnings name each input: the option as typed, else the default."""
    names = {"unbalance": ("rotor", "eccentricity"), "clearance": ("drop", "clearance"),
             "line_stiffness": ("drop", "line_stiffness"), "polar_inertia": ("rotor", "polar_inertia")}
    out = {}
    for name, key in names.items():
        param = next(p for p in PARAMETERS if (p.section, p.key) == key)
        option = f"--{_option_name(param)}"
        out[name] = f"{option} {params[key]}" if key in params else f"{option} (default)"
    return out


def _paper_drop(ctx, bearing_spec, config, params, wall, max_contacts, out_dir, as_json, quiet) -> None:
    from rich.console import Console
    from rich.table import Table

    from auxbearing.analysis.statics import stress_warning
    from auxbearing.common.io import atomic_output_dir, save_dataset, save_figure, write_json
    from auxbearing.paper.drop_paper import PAPER_DROP
    from auxbearing.planar.rig import run_drop

    bearing, rotor, case, machine = paper_machine(ctx, bearing_spec, config, params)
    blame = next((f"--{_option_name(p)} = {params[(p.section, p.key)]!r}" for p in PARAMETERS
                  if p.key in ("duration", "max_step") and (p.section, p.key) in params), "the paper's drop")
    check_budget(machine, case.duration, blame, "run it as a machine file (drop --machine), whose drop.max_steps "
                                                "can be raised")
    check_ball_contacts(machine, max_contacts, f"--bearing = {bearing_spec!r}")
    sink_check(bearing, machine, case.ball_constant, f"--ball-constant = {params.get(('drop', 'ball_constant'))!r}")
    warn(*stiffness_warnings(machine, case.duration, names=paper_stiffness_names(params)))
    warn(*plausibility(machine, _typed_names(params)))
    seconds = wall if wall is not None else machine.simulation.max_wall_time
    # The output folder is checked before the integration, so a bad --out costs no run.
    with atomic_output_dir(out_dir) if out_dir is not None else contextlib.nullcontext() as tmp:
        with ProgressReporter(f"drop on {bearing.name}", quiet) as progress:
            ds, summary = run_drop(bearing, rotor, case, progress=budgeted(progress, seconds))
        if tmp is not None:
            from auxbearing.plots.drop import plot_orbit_force, plot_speeds_stress

            inputs = {"bearing": bearing.describe(), "rotor": rotor.describe(), "drop": case.describe()}
            save_dataset(ds, tmp / "drop.nc", inputs)
            save_figure(plot_orbit_force(ds, PAPER_DROP.get(bearing.name)), tmp / "drop_orbit_force")
            save_figure(plot_speeds_stress(ds), tmp / "drop_speeds_stress")
            write_json(summary, tmp / "drop_summary.json", inputs)
    times = ds["time"].values
    step = float(times[1] - times[0]) if times.size > 1 else case.output_step
    summary = {**summary, "output_step_s": step, "output_decimated": step > case.output_step * (1.0 + 1e-9)}
    if summary["output_decimated"]:
        warn(decimation_note(step, case.output_step, machine.simulation.max_output_points))
    if out_dir is not None:
        summary = {**summary, "out": str(out_dir)}
    if summary["verdict"] != "ok":
        warn(summary["reason"])
    elif summary["peak_ball_stress_MPa"] is not None:
        warn(stress_warning(summary["peak_ball_stress_MPa"] * 1e6))
    warn(race_sink_warning(ds, bearing),
         impact_rate_warning(bearing.name, summary["impacts"], summary["first_impact_ms"], float(times[-1])))
    if as_json:
        echo_json(summary)
        return
    paper = PAPER_DROP.get(bearing.name, {})
    table = Table(title=f"Rotor drop on {bearing.name} ({bearing.label}), s = {case.clearance * 1e3:g} mm, "
                        f"μ1 = {case.sliding_friction:g}, {case.speed * 30 / 3.141592653589793:.0f} rpm")
    for col in ("quantity", "unit", "ours", *(["paper"] if paper else [])):
        table.add_column(col, justify="right" if col in ("ours", "paper") else "left")
    for key, label, unit, fmt in _ROWS:
        row = [label, unit, _fmt(fmt, summary.get(key))]
        table.add_row(*row, *([_fmt("{:g}", paper.get(key))] if paper else []))
    Console().print(table)
    if out_dir is not None:
        click.echo(f"Wrote {Path(out_dir) / 'drop.nc'}, figures and drop_summary.json in {out_dir}/")


_PLANE_ROWS = (("peak_contact_force_N", "Peak collision force", "N", "{:.1f}"),
               ("peak_ball_stress_MPa", "Peak ball contact stress", "MPa", "{:.1f}"),
               ("s0", "Static safety factor s0 (ISO 76)", "-", "{:.2f}"),
               ("peak_axial_force_N", "Peak axial (face) force", "N", "{:.1f}"),
               ("final_contact_force_N", "Final collision force", "N", "{:.1f}"),
               ("first_impact_ms", "First impact", "ms", "{:.3f}"),
               ("impacts", "Impacts (contact onsets)", "-", "{}"),
               ("whirl", "Whirl at the end", "", "{}"),
               ("backward_whirl_onset_ms", "Onset of sustained backward whirl", "ms", "{:.1f}"),
               ("max_mount_deflection_um", "Largest mount deflection", "µm", "{:.1f}"))


def _machine_drop(spec: str, duration: str | None, wall: float | None, max_contacts: int, out_dir: Path | None,
                  as_json: bool, quiet: bool, scenario: str | None = None) -> None:
    from rich.console import Console
    from rich.table import Table

    from auxbearing.analysis.drop import run_machine
    from auxbearing.analysis.scenario_outcome import late_loads
    from auxbearing.cli.common import read_machine_file
    from auxbearing.common.io import atomic_output_dir, save_dataset, save_figure, write_json
    from auxbearing.common.units import to_si

    with option_named("--machine", "machine"), option_named("--machine", "file", value=spec):
        machine = read_machine_file(spec)
    machine = machine.with_scenario(scenario, "--scenario")
    seconds = None
    if duration is not None:
        seconds = to_si("--duration", duration, "time", "s")
        if not 0.0 < seconds < 1e6:
            raise InputError.for_field("--duration", duration, "must lie between 0 and 1e6 s")
        if seconds < machine.simulation.output_step:  # one output sample: no history to summarise
            raise InputError.for_field("--duration", duration, "shorter than drop.output_step = "
                                       f"{machine.simulation.output_step:g} s")
    if wall is not None:
        machine = machine.with_simulation(max_wall_time=wall)
    check_budget(machine, seconds if seconds is not None else machine.simulation.duration,
                 f"--duration = {duration!r}" if duration is not None else f"--machine = {spec!r}: drop.duration",
                 "raise drop.max_steps in the machine file")
    check_ball_contacts(machine, max_contacts, f"--machine = {spec!r}")
    warn(*stiffness_warnings(machine, seconds if seconds is not None else machine.simulation.duration,
                             f"--machine = {spec!r}: "))
    warn(*late_loads(machine, seconds if seconds is not None else machine.simulation.duration))
    warn(*plausibility(machine, machine_input_names(spec)))
    with atomic_output_dir(out_dir) if out_dir is not None else contextlib.nullcontext() as tmp:
        with ProgressReporter(f"drop of {machine.name}", quiet) as progress:
            run = run_machine(machine, seconds, progress=progress)
        summary = run.summary
        if tmp is not None:
            from auxbearing.plots.drop import machine_figures

            inputs = machine.describe()
            save_dataset(run.dataset, tmp / "drop.nc", inputs)
            for name, fig in machine_figures(run.dataset, summary).items():
                save_figure(fig, tmp / f"drop_{name}")
            write_json(summary, tmp / "drop_summary.json", inputs)
    if summary["output_decimated"]:
        warn(decimation_note(summary["output_step_s"], machine.simulation.output_step,
                             machine.simulation.max_output_points))
    warn(*(impact_rate_warning(p["name"], p["impacts"], p["first_impact_ms"], summary["simulated_s"])
           for p in summary["planes"]))
    if out_dir is not None:
        summary = {**summary, "out": str(out_dir)}
    if summary["verdict"] != "ok":
        warn(f"verdict {summary['verdict']}: {summary['reason']}")
    if as_json:
        echo_json(summary)
        return
    table = Table(title=f"Drop of {machine.name}: verdict {summary['verdict']}")
    table.add_column("quantity")
    table.add_column("unit")
    for plane in summary["planes"]:
        table.add_column(plane["name"], justify="right")
    for key, label, unit, fmt in _PLANE_ROWS:
        table.add_row(label, unit, *(_fmt(fmt, p.get(key)) for p in summary["planes"]))
    console = Console()
    console.print(table)
    console.print(f"simulated {summary['simulated_s'] * 1e3:.1f} ms in {summary['wall_time_s']:.2f} s "
                  f"({summary['steps']} steps); energy balance error {summary['energy_balance_error']:.1e}",
                  highlight=False)
    bearings = _bearing_table(summary.get("amb"))
    if bearings is not None:
        console.print(bearings)
    scenario_line = _scenario_line(summary.get("scenario"))
    if scenario_line:
        console.print(scenario_line, highlight=False)
    if summary["reason"]:
        console.print(f"[bold]{summary['reason']}[/bold]")
    if out_dir is not None:
        click.echo(f"Wrote drop.nc, drop_summary.json and the figures in {out_dir}/")


def _bearing_table(records: list | None):
    """The magnetic bearings' figures of a drop: where the rotor went at each, and its current against the limit."""
    from rich.table import Table

    if not records:
        return None
    table = Table(title="Magnetic bearings: levitated offset, peak current and its limit, the rotor's largest "
                        "excursion there")
    table.add_column("bearing", no_wrap=True)
    for column in ("axis", "offset [µm]", "peak [A]", "limit [A]", "excursion [µm]"):
        table.add_column(column, justify="left" if column == "axis" else "right")
    for a in records:
        excursion = a.get("max_excursion_um")
        table.add_row(a["name"], a["axis"], f"{a['levitated_offset_um']:.1f}", f"{a['peak_axis_current_A']:.2f}",
                      f"{a['max_current_A']:g}" if math.isfinite(a["max_current_A"]) else "unlimited",
                      "-" if excursion is None else f"{excursion:.1f}")
    return table


def _scenario_line(s: dict | None) -> str:
    """What the magnetic bearings' scenario did, in one line of text (the JSON has it in full)."""
    if not s or "outcome" not in s:
        return ""
    contact = s.get("first_contact_ms")
    saturated = max((b["saturated_ms"] for b in s.get("saturation", [])), default=0.0)
    parts = [f"scenario '{s['name']}' ({s['kind'].replace('_', ' ')}) at {s['time_ms']:.1f} ms: {s['outcome']}",
             "no contact" if contact is None else f"first contact at {contact:.1f} ms"
             + (" (before the strike)" if s.get("touched_before_strike") else "")]
    if s.get("relevitated_at_ms") is not None:
        parts.append(f"re-levitated at {s['relevitated_at_ms']:.1f} ms")
    if saturated > 0.0:
        parts.append(f"{saturated:.1f} ms at a current limit (the longest of the bearings)")
    levitation = s.get("levitation")
    if levitation and not levitation["stable"]:
        parts.append(levitation["note"])
    return "; ".join(parts)


@click.command("machines")
@json_option()
def machines_command(as_json):
    """List the example machines shipped in the catalogue (use with drop --machine NAME)."""
    import math

    from rich.console import Console
    from rich.table import Table

    from auxbearing.cli.common import read_machine_file
    from auxbearing.machine.files import machine_names

    rows = []
    for name in machine_names():
        m = read_machine_file(name)
        rows.append({"name": name, "title": m.name, "orientation": m.orientation, "mass_kg": m.rotor.mass,
                     "speed_rpm": m.rotor.speed * 30.0 / math.pi,
                     "planes": [{"name": p.name, "bearing": p.unit.name,
                                 "radial_clearance_mm": p.radial_clearance * 1e3,
                                 "axial": p.catches_axially, "mount": p.mount is not None} for p in m.planes],
                     "source": m.source})
    if as_json:
        echo_json({"machines": rows})
        return
    table = Table(title="Example machines (auxbearing drop --machine NAME)")
    for col in ("name", "rotor", "speed", "planes"):
        table.add_column(col)
    for r in rows:
        planes = "; ".join(f"{p['name']}: {p['bearing']}, s = {p['radial_clearance_mm']:g} mm"
                           + (", axial" if p["axial"] else "") + (", mount" if p["mount"] else "")
                           for p in r["planes"])
        table.add_row(r["name"], f"{r['mass_kg']:g} kg, {r['orientation']}", f"{r['speed_rpm']:.0f} rpm", planes)
    Console().print(table)


def _list(name: str, text: str, dimension: str, unit: str | None) -> tuple[float, ...]:
    items = [t.strip() for t in text.replace(";", ",").split(",") if t.strip()]
    if not items:
        raise InputError.for_field(name, text, "needs a comma-separated list")
    values = []
    for item in items:
        try:
            values.append(convert(name, item, dimension, unit))
        except InputError as err:
            rule = str(err).partition(": ")[2]
            raise InputError.for_field(name, text, f"item {item!r}: {rule}") from None
    return tuple(values)


@click.command("drop-compare")
@config_option()
@parameter_options
@click.option("--bearings", default="QJ202,7202", show_default=True, help="Comma-separated catalogue bearings.")
@click.option("--clearances", default="0.1,0.15,0.2,0.3", show_default=True, metavar="LIST",
              help="Clearances s of the sweep (plain numbers in mm).")
@click.option("--frictions", default="0.1,0.2,0.3", show_default=True, metavar="LIST",
              help="Sliding friction coefficients μ1 of the sweep.")
@click.option("--phases", default="0,90,180,270", show_default=True, metavar="LIST",
              help="Unbalance phases at the drop of the sweep (plain numbers in deg).")
@click.option("--checks/--no-checks", default=True, show_default=True,
              help="Also rerun with 10x tighter tolerance and 10x smaller slip regularisation.")
@out_option("out/drop-compare")
@json_option()
@quiet_option()
@click.pass_context
def drop_compare_command(ctx, config, params, bearings, clearances, frictions, phases, checks, out_dir, as_json,
                         quiet):
    """Four-point QJ202 versus angular-contact 7202 drop beside the paper (Fig. 10-11, Sec. II.D).

    Writes drop_<bearing>.nc, fig10/fig11 orbit and collision-force figures, spin-speed and
    stress figures, the clearance, friction and unbalance-phase sweep (drop_sweep.nc,
    drop_sweep.png) and
    drop_compare.json (peaks beside 618 N / 1483 MPa and 391 N / 1634 MPa, the paper's K_b read as
    N/mm^1.5, convergence checks and the parameters the paper leaves out).
    """
    from dataclasses import replace

    from rich.console import Console
    from rich.table import Table

    from auxbearing.paper.drop_paper import PAPER_DROP, drop_compare

    if config is not None:
        from auxbearing.bearings.geometry import read_toml

        if "bearing" in read_toml(config, "--config"):
            raise InputError.for_field("--config", str(config), "its [bearing] table does not apply: drop-compare "
                                                                "runs the catalogue bearings of --bearings; remove "
                                                                "the table, or use `auxbearing drop --config`")
    _, rotor, case = build_inputs(ctx, "QJ202", config, params)
    names = tuple(b.strip() for b in bearings.split(",") if b.strip())
    if not names:
        raise InputError.for_field("--bearings", bearings, "needs at least one catalogue bearing, e.g. QJ202,7202")
    for name in names:
        with option_named("--bearings", "bearing"):
            resolve_bearing(name, option="bearing")  # fail early on a typo
    s_list = _list("--clearances", clearances, "length", "mm")
    for s in s_list:
        check(next(p for p in PARAMETERS if p.key == "clearance"), s, "--clearances", clearances)
    _clearances_fit(names, s_list, rotor, case, clearances)
    mu_list = _list("--frictions", frictions, "dimensionless", None)
    for mu in mu_list:
        check(next(p for p in PARAMETERS if p.key == "sliding_friction"), mu, "--frictions", frictions)
    phase_list = _list("--phases", phases, "angle", "deg")
    with ProgressReporter("drop-compare", quiet) as progress:
        result = drop_compare(out_dir, names, s_list, mu_list, rotor, replace(case), checks,
                              progress=lambda label, f: progress(f, label), phases=phase_list)
    if as_json:
        echo_json({**result, "out": str(out_dir)})
        return
    table = Table(title="Rotor drop: ours (Hertz K_b) | ours (paper's K_b as N/mm^1.5) | paper")
    for col in ("bearing", "peak force [N]", "peak stress [MPa]", "s0", "whirl",
                "force, paper K_b [N]", "stress, paper K_b [MPa]", "paper force [N]", "paper stress [MPa]"):
        table.add_column(col, justify="right")
    for name, r in result["results"].items():
        pk = result["paper_ball_constant"][name]
        paper = PAPER_DROP.get(name, {})
        table.add_row(name, f"{r['peak_contact_force_N']:.0f}", f"{r['peak_ball_stress_MPa']:.0f}",
                      _fmt("{:.1f}", r["s0"]), r["whirl"], f"{pk['peak_contact_force_N']:.0f}",
                      f"{pk['peak_ball_stress_MPa']:.0f}", _fmt("{:g}", paper.get("peak_contact_force_N")),
                      _fmt("{:g}", paper.get("peak_ball_stress_MPa")))
    Console().print(table)
    click.echo(f"Wrote the comparison, sweep and figures in {out_dir}/ ({result['wall_time_s']:.1f} s)")


COMMANDS = [drop_command, machines_command, drop_compare_command]
