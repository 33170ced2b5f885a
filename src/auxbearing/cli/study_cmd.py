"""``auxbearing study`` (the main job) and ``auxbearing bearings`` (the catalogue)."""

from __future__ import annotations

from pathlib import Path

import click

from auxbearing.cli.common import checked_out_dir, echo_json, json_option

#: Keys of :data:`auxbearing.paper.study.STAGES`, repeated so that ``--help`` needs no numerics (a test keeps
#: them equal).
STAGE_KEYS = ("contact", "static", "drop", "experiment")

_STUDY_HELP = """Reproduce the whole paper into a report with a claims check, or study bearings of your own.

Writes to OUT: report.html (self-contained, figures embedded), results.json (claims table,
headline numbers, assumptions), NetCDF data behind every figure, PNG and PDF figures. Every
file carries the inputs and the package version.

\b
CONFIG is an optional TOML file; every section is optional and defaults to the paper:
  [study]               title; ball_load ("1000 N", contact study load on one ball);
                        contact_angles = ["10 deg", "75 deg", "1 deg"] (start, stop, step);
                        groove_ratios = [0.505, 0.6, 0.0025]
  [bearing]             the four-point bearing: catalogue = "QJ202", or a full [bearing]
                        table as for `auxbearing contact --bearing FILE`
  [comparison_bearing]  the angular-contact bearing: catalogue = "7202", or a full table
  [rotor], [drop]       the drop case, see `auxbearing drop --help`
Every table is checked before the first stage runs.

\b
A file whose bearings, rotor or drop differ from the paper's is a study of your own
bearings: the report speaks of them only (captions from your file, key results, a
warning box for results outside the model's range; no paper claims, no experiment stage
on the paper's synthetic drops). [study] paper_comparison = true or --paper-comparison
sets the paper's QJ202/7202 numbers and claims beside your results, labelled as the paper's.
"""


@click.command("study", help=_STUDY_HELP)
@click.option("--config", "config_path", type=click.Path(path_type=Path), default=None,
              help="Study TOML (every section optional; defaults are the paper's).")
@click.option("--out", "out_dir", type=click.Path(file_okay=False, path_type=Path), default=Path("study"),
              show_default=True, callback=checked_out_dir, help="Output folder.")
@click.option("--stage", "stages", multiple=True, type=click.Choice(STAGE_KEYS),
              help="Run only these stages (repeatable). Default: all.")
@click.option("--paper-comparison", is_flag=True,
              help="In a study of your own bearings, show the paper's QJ202/7202 numbers and claims beside yours.")
@click.option("--quiet", is_flag=True, help="No progress output (for scripts).")
@json_option()
def study_command(config_path, out_dir, stages, paper_comparison, quiet, as_json):  # noqa: D103 (help: _STUDY_HELP)
    from rich.console import Console
    from rich.progress import Progress, SpinnerColumn, TextColumn, TimeElapsedColumn

    from auxbearing.paper.study import run_study
    from auxbearing.paper.study_config import load_study_config
    config = load_study_config(config_path, "--config")
    if paper_comparison:
        from dataclasses import replace

        config = replace(config, paper_comparison=True)
    selected = list(stages) or None
    console = Console(stderr=True, quiet=quiet)
    with Progress(SpinnerColumn(), TextColumn("{task.description}"), TimeElapsedColumn(),
                  console=console, transient=False) as bar:
        state = {"task": None}

        def progress(label: str) -> None:
            if state["task"] is not None:
                bar.update(state["task"], completed=1)
            state["task"] = bar.add_task(label, total=1)

        results = run_study(config, out_dir, progress=progress, stages=selected)
        if state["task"] is not None:
            bar.update(state["task"], completed=1)
    if as_json:
        echo_json({k: results[k] for k in ("title", "study_of", "wall_time_s", "claims_hold", "claims_total", "claims",
                                           "warnings")} | {"out": str(out_dir)})
        return
    if results["claims_total"]:
        click.echo(f"Claims: {results['claims_hold']} of {results['claims_total']} hold. ", nl=False)
    if results["warnings"]:
        click.echo(f"{len(results['warnings'])} result(s) outside the model's range (see the report's top). ", nl=False)
    click.echo(f"Report: {out_dir / 'report.html'} ({results['wall_time_s']:.1f} s)")


@click.command("bearings")
@json_option()
def bearings_command(as_json):
    """List the bearing and material catalogues with their sources."""
    from rich.console import Console
    from rich.table import Table

    from auxbearing.bearings.catalogue import get_bearing
    from auxbearing.bearings.geometry import bearing_names
    from auxbearing.bearings.materials import get_material, material_names
    rows = [get_bearing(name).describe() for name in bearing_names()]
    materials = [{"name": m, "elastic_modulus_GPa": get_material(m).elastic_modulus / 1e9,
                  "poisson_ratio": get_material(m).poisson_ratio, "source": get_material(m).source}
                 for m in material_names()]
    if as_json:
        echo_json({"bearings": rows, "materials": materials})
        return
    table = Table(title="Bearings (use with --bearing NAME)")
    for col in ("name", "type", "D [mm]", "dm [mm]", "Z", "fi", "fo", "α [deg]", "Pd [mm]"):
        table.add_column(col, no_wrap=True)
    for r in rows:
        table.add_row(r["name"], r["type"], f"{r['ball_diameter_mm']:g}", f"{r['pitch_diameter_mm']:g}",
                      str(r["ball_count"]), f"{r['inner_groove_ratio']:g}", f"{r['outer_groove_ratio']:g}",
                      f"{r['contact_angle_deg']:g}", f"{r['diametral_clearance_mm']:g}")
    mats = Table(title="Materials")
    for col in ("name", "E [GPa]", "ν"):
        mats.add_column(col, no_wrap=True)
    for m in materials:
        mats.add_row(m["name"], f"{m['elastic_modulus_GPa']:g}", f"{m['poisson_ratio']:g}")
    console = Console()
    console.print(table)
    console.print(mats)
    console.print("Sources:")
    for entry in rows + materials:
        console.print(f"  {entry['name']}: {entry['source']}", highlight=False)


COMMANDS = [study_command, bearings_command]
