"""``auxbearing static`` and ``auxbearing static-study`` (source paper Sec. II.C, Fig. 6-8)."""

from __future__ import annotations

import contextlib
import math
from pathlib import Path

import click

from auxbearing.analysis.plausibility import static_sink_warning
from auxbearing.analysis.statics import refuse_sinking
from auxbearing.cli.common import (
    bearing_option,
    checked_out_dir,
    echo_json,
    json_option,
    option_named,
    out_option,
    quantity,
    resolve_bearing,
    warn,
)
from auxbearing.common.errors import InputError

#: The choices of :data:`auxbearing.analysis.statics.AXIAL_CONDITIONS` and ``TILT_CONDITIONS``, repeated here so that
#: ``--help`` needs no numerics (a test keeps them equal).
AXIAL_CONDITIONS = ("free", "located")
TILT_CONDITIONS = ("free", "fixed")


def _condition_options(command):
    """--axial-condition, --tilt, --ball-constant: how the ring is held and which K_b (static, static-cases)."""
    for option in reversed((
        click.option("--axial-condition", type=click.Choice(AXIAL_CONDITIONS), default="free", show_default=True,
                     help="free: the axial load is given (source paper Eq. 14/16); located: the ring is held at "
                          "zero axial displacement and the axial reaction is reported (needed for a single "
                          "angular-contact bearing under pure radial load)."),
        click.option("--tilt", type=click.Choice(TILT_CONDITIONS), default="free", show_default=True,
                     help="free: the moment is given (Eq. 14); fixed: the ring is kept square, moment reaction "
                          "reported."),
        click.option("--ball-constant", default=None, metavar="K",
                     help="Override the Hertz ball constant K_b, e.g. '1.71e10 N/m**1.5' (stresses stay Hertz)."),
    )):
        command = option(command)
    return command


@click.command("static")
@bearing_option()
@click.option("--radial", default="0", show_default=True, metavar="LOAD",
              help="Radial load Fr on the inner ring: a number in N, or with a unit ('1 kN').")
@click.option("--axial", default="0", show_default=True, metavar="LOAD",
              help="Axial load Fa on the inner ring: a number in N, or with a unit ('500 N').")
@click.option("--moment", default="0", show_default=True, metavar="MOMENT",
              help="Tilting moment M in the plane of the radial load: a number in N*m, or with a unit ('2 N*m').")
@_condition_options
@json_option()
def static_command(bearing_spec, radial, axial, moment, axial_condition, tilt, ball_constant, as_json):
    """Quasi-static load distribution of the ball set under Fa, Fr and M (source paper Eq. 9-16).

    Solves the inner-ring equilibrium by Newton-Raphson (residual <= 1e-9 of the load) and prints
    ring displacements, per-ball pair loads, loaded contact angles, Hertz max stresses and the
    static safety factor s0 = (4200 MPa / σ_max)^3 (ISO 76:2006 with Hertz σ ~ Q^(1/3)).
    """
    import numpy as np
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    from auxbearing.analysis.static_cases import format_cell
    from auxbearing.analysis.statics import (
        load_distribution,
        summary,
        validity_warnings,
    )
    bearing = resolve_bearing(bearing_spec)
    loads = {
        "axial": quantity("--axial", axial, "force", "N"),
        "radial": quantity("--radial", radial, "force", "N"),
        "moment": quantity("--moment", moment, "moment", "N*m"),
    }
    typed = {"--axial": axial, "--radial": radial, "--moment": moment}
    five = np.array([[loads["axial"], loads["radial"], 0.0, 0.0, -loads["moment"]]])
    with option_named("--ball-constant", "ball_constant"):
        refuse_sinking(bearing, five, ball_constant, lambda k: _blame(bearing, five[k], typed, ball_constant))
    with option_named("--ball-constant", "ball_constant"), _named_as_typed(typed):
        ds = load_distribution(bearing, **loads, axial_condition=axial_condition, tilt=tilt,
                               ball_constant=ball_constant)
    result = summary(ds)
    warn(*validity_warnings(ds), static_sink_warning(bearing, ds, 0))
    if as_json:
        echo_json(result)
        return
    console = Console()
    # escaped: rich reads a lowercase "[deg]" as a style tag and drops it
    table = Table(title=escape(f"{bearing.name} ({bearing.label}): Fa = {loads['axial']:g} N, "
                               f"Fr = {loads['radial']:g} N, M = {loads['moment']:g} N·m; axial {axial_condition}, "
                               f"tilt {tilt}"))
    table.add_column(escape("φ [deg]"), justify="right")
    for k in range(bearing.pairs_per_ball):
        suffix = f" {k + 1}" if bearing.pairs_per_ball > 1 else ""
        table.add_column(escape(f"Q{suffix} [N]"), justify="right")
        table.add_column(escape(f"α{suffix} [deg]"), justify="right")
        table.add_column(escape(f"σ inner{suffix} [MPa]"), justify="right")
    for ball in result["balls"]:
        row = [f"{ball['azimuth_deg']:.1f}"]
        for pair in ball["pairs"]:
            row += [f"{pair['load_N']:.1f}", f"{pair['contact_angle_deg']:.2f}", f"{pair['max_stress_inner_MPa']:.0f}"]
        table.add_row(*row)
    console.print(table)
    click.echo(f"Axial displacement   {format_cell(result, 'axial_displacement_um', '{:.3f}')} µm")
    click.echo(f"Radial displacement  {format_cell(result, 'radial_displacement_um', '{:.3f}')} µm")
    click.echo(f"Tilt                 {format_cell(result, 'tilt_mrad', '{:.4f}')} mrad")
    click.echo(f"Max contact load     {result['max_contact_load_N']:.1f} N")
    click.echo(f"Max contact stress   {result['max_stress_MPa']:.1f} MPa")
    if result["safety_factor_s0"] is None:
        click.echo("Static safety s0     - (no contact is loaded)")
    else:
        click.echo(f"Static safety s0     {result['safety_factor_s0']:.3g} (ISO 76: 4200 MPa)")
    if axial_condition == "located":
        click.echo(f"Axial reaction       {result['axial_reaction_N']:.1f} N")
    if tilt == "fixed":  # the ring held square: the shaft's support carries the moment the balls do not
        mx, my = result["moment_reaction_Nm"]
        click.echo(f"Moment reaction      {math.hypot(mx, my):.3g} N·m (about x {mx:.3g}, about y {my:.3g} N·m)")
    click.echo(f"Residual             {result['residual_N']:.2e} N")


@click.command("static-study")
@click.option("--bearing-4pt", default="QJ202", show_default=True, metavar="NAME|FILE.toml",
              help="Four-point bearing of Fig. 6-8.")
@click.option("--bearing-ac", default="7202", show_default=True, metavar="NAME|FILE.toml",
              help="Angular-contact bearing compared in Fig. 8 (axially located, square).")
@out_option("out/static")
@json_option()
def static_study_command(bearing_4pt, bearing_ac, out_dir, as_json):
    """The paper's static study: write Fig. 6-8 data (NetCDF) and figures (PNG).

    Writes fig6_radial.nc, fig6_axial.nc (contact angles along the position angle), fig7.nc
    (displacements over an axial x radial load grid), fig8.nc (max stress against radial load,
    four-point versus angular contact), stribeck.nc, the three figures and static_summary.json.
    """
    from rich.progress import Progress

    from auxbearing.paper.static_paper import static_study
    four = resolve_bearing(bearing_4pt, option="--bearing-4pt")
    angular = resolve_bearing(bearing_ac, option="--bearing-ac")
    for option, spec, bearing, kind in (("--bearing-4pt", bearing_4pt, four, "four_point"),
                                        ("--bearing-ac", bearing_ac, angular, "angular_contact")):
        if bearing.type != kind:
            raise InputError.for_field(option, spec, f"is a {bearing.type} bearing; Fig. 6-8 compare a four_point "
                                                     "bearing (--bearing-4pt) with an angular_contact one "
                                                     "(--bearing-ac)")
    with Progress(transient=True, disable=as_json) as bar:
        task = bar.add_task("static study", total=5)

        def advance(text: str) -> None:
            bar.update(task, advance=1, description=text)

        result = static_study(out_dir, four, angular, progress=advance)
    if as_json:
        echo_json({**result["summary"], "out": str(out_dir)})
        return
    s = result["summary"]
    for name, value in s["max_stress_at_1000N_MPa"].items():
        click.echo(f"Max stress at Fr = 1000 N, {name}: {value:.1f} MPa")
    click.echo(f"Angular contact above four-point at every load: {s['angular_exceeds_four_point_everywhere']}; "
               f"excess grows with load: {s['excess_grows_with_load']} (paper Sec. II.C: both)")
    click.echo(f"Wrote Fig. 6-8 data and figures in {out_dir}/")


#: Most case rows printed as a table; the files hold all of them.
_PRINTED_CASES = 40
#: Default budget of static-cases: load cases of one file. A case costs ~1.3 kB in memory and ~0.1 ms to solve,
#: so 200 000 cases are ~250 MB and well under a minute.
MAX_CASES = 200_000


@click.command("static-cases")
@bearing_option()
@click.option("--loads", "loads_path", required=True, type=click.Path(path_type=Path),
              metavar="FILE.csv", help="Load cases, one per row, units in the header: 'axial [N], radial [kN], "
                                       "moment [N*m]' or the 5-DOF 'axial, force_x, force_y, moment_x, moment_y'.")
@_condition_options
@click.option("--max-cases", default=MAX_CASES, show_default=True, type=click.IntRange(min=1), metavar="N",
              help="Budget: most load cases (rows) a file may hold.")
@click.option("--out", "out_dir", type=click.Path(file_okay=False, path_type=Path), default=None,
              callback=checked_out_dir, help="Write static_cases.nc, static_cases.csv and static_cases.json here.")
@json_option()
def static_cases_command(bearing_spec, loads_path, axial_condition, tilt, ball_constant, max_cases, out_dir,
                         as_json):
    """Every load case of a CSV file (a duty cycle, a load spectrum) in one batched solve.

    Prints per case the ring displacements, the largest contact load, the max Hertz stress and
    s0, names the worst case, and flags cases outside the model's range (stderr). Missing
    columns are zero; the CSV format is that of a measured drop (units in brackets, '#' comments).
    """
    import numpy as np
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    from auxbearing import __version__
    from auxbearing.analysis.static_cases import (
        FIVE_DOF,
        RESULT_COLUMNS,
        case_rows,
        format_cell,
        load_cases,
        read_load_cases,
        worst_case,
        write_rows_csv,
    )
    from auxbearing.common.io import atomic_output_dir, save_dataset, write_json
    bearing = resolve_bearing(bearing_spec)
    data, lines = read_load_cases(loads_path, field="--loads", max_cases=max_cases)
    n = len(lines)
    five = np.column_stack([data.get(k, np.zeros(n)) for k in FIVE_DOF])
    if "radial" in data or "moment" in data:  # the planar columns: Fx = Fr, My = -M
        five[:, 1] = data.get("radial", np.zeros(n))
        five[:, 4] = -data.get("moment", np.zeros(n))

    def blame(k: int) -> str:
        name = "--ball-constant" if ball_constant is not None else "--loads"
        value = ball_constant if ball_constant is not None else str(loads_path)
        return f"{name} = {value!r}: line {lines[k]}"

    with option_named("--ball-constant", "ball_constant"):
        refuse_sinking(bearing, five, ball_constant, blame)
    with atomic_output_dir(out_dir) if out_dir is not None else contextlib.nullcontext() as tmp, \
            option_named("--ball-constant", "ball_constant"):
        ds = load_cases(bearing, loads_path, axial_condition=axial_condition, tilt=tilt,
                        ball_constant=ball_constant, table=(data, lines))
        rows = case_rows(ds)
        worst = worst_case(rows)
        result = {"bearing": bearing.name, "loads_file": str(loads_path), "cases": len(rows),
                  "cases_with_warnings": sum(bool(r["warnings"]) for r in rows), "worst": worst, "results": rows}
        if tmp is not None:
            inputs = {"bearing": bearing.describe(), "loads_file": str(loads_path), "axial_condition": axial_condition,
                      "tilt": tilt, "ball_constant": ball_constant}
            save_dataset(ds, tmp / "static_cases.nc", inputs)
            write_rows_csv(rows, tmp / "static_cases.csv", f"auxbearing {__version__}: {bearing.name}, "
                                                            f"cases of {loads_path}")
            write_json(result, tmp / "static_cases.json", inputs)
    for row in rows:
        warn(*row["warnings"], where=f"case on line {row['line']}: ")
    if as_json:
        echo_json({**result, "out": str(out_dir) if out_dir is not None else None})
        return
    # escaped: rich reads a lowercase "[mrad]" as a style tag and drops it
    table = Table(title=escape(f"{bearing.name} ({bearing.label}): {_count(len(rows), 'load case')} from "
                               f"{loads_path}"))
    for *_, short in RESULT_COLUMNS:
        table.add_column(escape(short), justify="right")
    for row in rows[:_PRINTED_CASES]:
        table.add_row(*[format_cell(row, key, fmt) for key, _, fmt, _ in RESULT_COLUMNS])
    Console().print(table)
    if len(rows) > _PRINTED_CASES:
        click.echo(f"... {_count(len(rows) - _PRINTED_CASES, 'more case')}"
                   + (" in the files" if out_dir else "; use --out"))
    click.echo(f"Worst case: line {worst['line']}, max stress {worst['max_stress_MPa']:.1f} MPa, "
               f"s0 {format_cell(worst, 'safety_factor_s0', '{:.3g}')}")
    if out_dir is not None:
        click.echo(f"Wrote static_cases.nc, static_cases.csv and static_cases.json in {out_dir}/")


def _blame(bearing, load, typed: dict, ball_constant: str | None) -> str:
    """The option a load that sinks the rings into the balls comes from, as ``--option = 'value'``.

    ``load`` is the case's (Fa, Fx, Fy, Mx, My); the input is the one
    :func:`~auxbearing.analysis.statics.sink_culprit` finds, as the API names it.
    """
    from auxbearing.analysis.statics import sink_culprit

    column = sink_culprit(bearing, load, ball_constant)
    if column is None:
        return f"--ball-constant = {ball_constant!r}"
    name = ("--axial", "--radial", "--radial", "--moment", "--moment")[column]
    return f"{name} = {typed[name]!r}"


@contextlib.contextmanager
def _named_as_typed(typed: dict):
    """An error of the API about ``axial``, ``radial`` or ``moment`` named as the option, with the text typed.

    An option left at its default keeps the API's value, which carries its unit ("--axial = '0 N'").
    """
    try:
        yield
    except InputError as err:
        head, sep, rule = str(err).partition(": ")
        option = "--" + head.split(" = ")[0]
        if not sep or option not in typed:
            raise
        source = click.get_current_context().get_parameter_source(option[2:])
        if source == click.core.ParameterSource.DEFAULT:
            raise InputError(option + str(err)[len(option) - 2:]) from None
        raise InputError.for_field(option, typed[option], rule) from None


def _count(n: int, noun: str) -> str:
    """"1 load case", "3 load cases"."""
    return f"{n} {noun}" if n == 1 else f"{n} {noun}s"


COMMANDS = [static_command, static_study_command, static_cases_command]
