"""``auxbearing drop`` and ``auxbearing drop-compare`` (source paper Sec. II.D, Fig. 9-11).

Every rotor and drop parameter of :data:`auxbearing.drop_params.PARAMETERS` is an
option (generated from that table, so help, unit and default cannot drift apart) and a key of
the ``[rotor]`` / ``[drop]`` tables of a ``--config`` TOML file; options win over the file.
"""

from __future__ import annotations

import contextlib
import functools
from dataclasses import replace
from pathlib import Path

import click
from rich.console import Console
from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn
from rich.table import Table

from auxbearing.cli.common import (
    bearing_option,
    checked_out_dir,
    echo_json,
    json_option,
    out_option,
    resolve_bearing,
    warn,
)
from auxbearing.drop import DropCase, Rotor, read_config, run_drop
from auxbearing.drop_params import PARAMETERS, Param, check, convert, display_value
from auxbearing.errors import InputError
from auxbearing.io import atomic_output_dir, save_dataset, save_figure, write_json
from auxbearing.paper.drop_paper import PAPER_DROP, drop_compare
from auxbearing.statics import stress_warning

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
    """Bearing, Rotor and DropCase from catalogue/TOML/options (options win)."""
    bearing, rotor_kw, drop_kw = (None, {}, {}) if config is None else read_config(config)
    source = ctx.get_parameter_source("bearing_spec")
    if bearing is None or source != click.core.ParameterSource.DEFAULT:
        bearing = resolve_bearing(bearing_spec)
    by_key = {(p.section, p.key): p for p in PARAMETERS}
    for (section, key), text in params.items():
        param = by_key[(section, key)]
        field = f"--{_option_name(param)}"
        value = convert(field, text, param.dimension, param.display_unit or None)
        check(param, value, field)
        (rotor_kw if section == "rotor" else drop_kw)[key] = value
    return bearing, Rotor(**rotor_kw), DropCase(**drop_kw)


def _progress(quiet: bool) -> Progress:
    return Progress(TextColumn("{task.description}"), BarColumn(), TextColumn("{task.percentage:>3.0f}%"),
                    TimeElapsedColumn(), console=Console(stderr=True), disable=quiet, transient=True)


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
@bearing_option()
@config_option()
@parameter_options
@click.option("--out", "out_dir", type=click.Path(file_okay=False, path_type=Path), default=None,
              callback=checked_out_dir,
              help="Write drop.nc, the Fig. 10-11 style figures and drop_summary.json into this folder.")
@json_option()
@quiet_option()
@click.pass_context
def drop_command(ctx, bearing_spec, config, params, out_dir, as_json, quiet):
    """Rotor drop onto the auxiliary bearing (source paper Sec. II.D, Eq. 17-26, corrected).

    12 states (rotor and inner race: x, y, spin), Hertz line contact with damping, friction
    against the slip, the inner race carried by the shared ball-set model; Table II defaults
    with the corrected units, clearance 0.2 mm, 6000 rpm, 0.15 s. Values take units
    ("0.2mm", "6000rpm"); plain numbers use the unit named in each option's help.
    """
    bearing, rotor, case = build_inputs(ctx, bearing_spec, config, params)
    # The output folder is checked before the integration, so a bad --out costs no run.
    with atomic_output_dir(out_dir) if out_dir is not None else contextlib.nullcontext() as tmp:
        with _progress(quiet) as bar:
            task = bar.add_task(f"drop on {bearing.name} (first run compiles)", total=1.0)
            ds, summary = run_drop(bearing, rotor, case, progress=lambda f: bar.update(task, completed=f))
        if tmp is not None:
            from auxbearing.plots.drop import plot_orbit_force, plot_speeds_stress

            inputs = {"bearing": bearing.describe(), "rotor": rotor.describe(), "drop": case.describe()}
            save_dataset(ds, tmp / "drop.nc", inputs)
            save_figure(plot_orbit_force(ds, PAPER_DROP.get(bearing.name)), tmp / "drop_orbit_force")
            save_figure(plot_speeds_stress(ds), tmp / "drop_speeds_stress")
            write_json(summary, tmp / "drop_summary.json", inputs)
    if out_dir is not None:
        summary = {**summary, "out": str(out_dir)}
    warn(stress_warning(summary["peak_ball_stress_MPa"] * 1e6))
    if as_json:
        echo_json(summary)
        return
    paper = PAPER_DROP.get(bearing.name, {})
    table = Table(title=f"Rotor drop on {bearing.name} ({bearing.label}), s = {case.clearance * 1e3:g} mm, "
                        f"μ1 = {case.sliding_friction:g}, {case.speed * 30 / 3.141592653589793:.0f} rpm")
    table.add_column("quantity")
    table.add_column("unit")
    table.add_column("ours", justify="right")
    table.add_column("paper", justify="right")
    for key, label, unit, fmt in _ROWS:
        table.add_row(label, unit, _fmt(fmt, summary[key]), _fmt("{:g}", paper.get(key)))
    Console().print(table)
    if out_dir is not None:
        click.echo(f"Wrote {Path(out_dir) / 'drop.nc'}, figures and drop_summary.json in {out_dir}/")


def _list(name: str, text: str, dimension: str, unit: str | None) -> tuple[float, ...]:
    items = [t for t in text.replace(";", ",").split(",") if t.strip()]
    if not items:
        raise InputError.for_field(name, text, "needs a comma-separated list")
    return tuple(convert(name, t.strip(), dimension, unit) for t in items)


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
    _, rotor, case = build_inputs(ctx, "QJ202", config, params)
    names = tuple(b.strip() for b in bearings.split(",") if b.strip())
    for name in names:
        resolve_bearing(name)  # fail early on a typo
    s_list = _list("--clearances", clearances, "length", "mm")
    for s in s_list:
        check(next(p for p in PARAMETERS if p.key == "clearance"), s, "--clearances")
    mu_list = _list("--frictions", frictions, "dimensionless", None)
    for mu in mu_list:
        check(next(p for p in PARAMETERS if p.key == "sliding_friction"), mu, "--frictions")
    phase_list = _list("--phases", phases, "angle", "deg")
    with _progress(quiet) as bar:
        task = bar.add_task("drop-compare (first run compiles)", total=1.0)
        result = drop_compare(out_dir, names, s_list, mu_list, rotor, replace(case), checks,
                              progress=lambda label, f: bar.update(task, completed=f, description=label),
                              phases=phase_list)
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


COMMANDS = [drop_command, drop_compare_command]
