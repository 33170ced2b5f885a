"""``auxbearing experiment``: a measured drop against the simulation (source paper Sec. III).

Reads a CSV or NetCDF drop record (format in docs/experiment.md), estimates contact force and
ball stress from the orbit, fits friction, clearance and unbalance phase, simulates the same
case and writes data, figures and a JSON summary.
"""

from __future__ import annotations

import contextlib
import math
import re
from pathlib import Path

import click

from auxbearing.catalog import bearing_names
from auxbearing.cli.common import echo_json, json_option, option_named, out_option, quantity, resolve_bearing, warn
from auxbearing.common.errors import InputError


def _offset(text: str) -> str | tuple[float, float]:
    from auxbearing.common.units import to_si
    if text in ("auto", "fit", "start"):
        return text
    parts = text.split(",")
    if len(parts) != 2:
        raise InputError.for_field("--offset", text, "must be auto, fit, start or 'X0,Y0' (e.g. '31.7 um,-18.4 um')")
    with _as_option("--offset", text):
        return (to_si("x0", parts[0], "length", "um"), to_si("y0", parts[1], "length", "um"))


@contextlib.contextmanager
def _as_option(option: str, text: str):
    """An error about a part of an option's value, told as the whole option as typed."""
    try:
        yield
    except InputError as err:
        field, _, rule = str(err).partition(": ")
        raise InputError.for_field(option, text, f"{field}: {rule}") from None


_FIELD_VALUE_RULE = re.compile(r"^(?P<field>[^=]+?) = (?P<value>.*?): (?P<rule>.*)$", re.DOTALL)


@contextlib.contextmanager
def _as_typed(typed: dict[str, tuple[str, str | None]]):
    """A library error about one of its inputs, told with the option and the value as typed.

    The library sees the SI numbers converted from the options (``cutoff = 30000.0: ...``), so it cannot quote
    what the person typed (``--cutoff = '30 kHz': ...``). ``typed`` maps a field to (option, text).
    """
    try:
        yield
    except InputError as err:
        match = _FIELD_VALUE_RULE.match(str(err))
        if match is None or match["field"] not in typed:
            raise
        option, text = typed[match["field"]]
        raise InputError.for_field(option, text, match["rule"]) from None


def _positive(option: str, text: str | None, dimension: str, unit: str) -> float | None:
    value = quantity(option, text, dimension, unit)
    if value is not None and not value > 0.0:
        raise InputError.for_field(option, text, f"must be > 0 {unit}")
    return value


def _units(items: tuple[str, ...]) -> dict[str, str]:
    """``--unit CHANNEL=UNIT`` items, each channel known and each unit of its channel's dimension."""
    from auxbearing.common.unit_csv import unit_scale
    from auxbearing.experiment.io import CHANNELS, channel_name

    out = {}
    for item in items:
        channel, sep, unit = item.partition("=")
        if not sep or not channel.strip() or not unit.strip():
            raise InputError.for_field("--unit", item, "must be CHANNEL=UNIT, e.g. x=um")
        key = channel_name(channel)
        if key is None:
            raise InputError.for_field("--unit", item, "unknown channel; channels are " + ", ".join(CHANNELS))
        with _as_option("--unit", item):
            unit_scale(channel.strip(), unit.strip(), CHANNELS[key][0])
        out[channel.strip()] = unit.strip()
    return out


@click.command("experiment")
@click.option("--measured", "measured", required=True, type=click.Path(path_type=Path),
              help="Drop record: CSV ('time [s], x [um], y [um][, speed [rpm]]') or NetCDF (x, y over time).")
@click.option("--bearing", "bearing_spec", default=None, metavar="NAME|FILE.toml",
              help="Auxiliary bearing of the test (" + ", ".join(bearing_names()) + ") or a TOML file; "
                   "default: the [bearing] of --config, else QJ202.")
@click.option("--config", type=click.Path(dir_okay=False, path_type=Path), default=None,
              help="TOML file with [rotor] and [drop] tables (values with units) and optionally [bearing]: "
                   "the simulated case (see `auxbearing drop --help`).")
@click.option("--offset", default="auto", show_default=True, metavar="auto|fit|start|X0,Y0",
              help="Sensor reading at the bearing centre: 'start' = levitated position before the drop, 'fit' = "
                   "centre of the clearance circle fitted to the orbit, 'auto' = start if the record has a "
                   "levitated stretch, or two lengths (plain numbers in um).")
@click.option("--scale", default="1", show_default=True, help="Factor on the displacement channels.")
@click.option("--cutoff", default="8 kHz", show_default=True,
              help="Zero-phase low-pass cutoff (plain number in Hz); 'none' for no filter.")
@click.option("--drop-time", default=None, help="Moment of the drop in record time (plain number in s); "
                                                "default: detected.")
@click.option("--clearance", default=None,
              help="Clearance s for the force estimate (plain number in mm); default: the fitted one.")
@click.option("--no-fit", is_flag=True, help="Skip the fit of friction, clearance and unbalance phase.")
@click.option("--fit-window", default="12 ms", show_default=True,
              help="Opening stretch of the drop the fit matches (plain number in ms); it must reach a few ms past "
                   "the first impact.")
@click.option("--unit", "units", multiple=True, metavar="CHANNEL=UNIT",
              help="Unit of a channel whose header has none, e.g. --unit x=um --unit time=ms (repeatable).")
@out_option("out/experiment")
@json_option()
@click.option("--quiet", is_flag=True, help="No progress bar.")
def experiment_command(measured, bearing_spec, config, offset, scale, cutoff, drop_time, clearance, no_fit,
                       fit_window, units, out_dir, as_json, quiet):
    """Measured rotor drop: force and ball stress from the orbit, fit, comparison with the simulation.

    Writes measured.nc (orbit, force, ball loads and stress since the drop), simulated_*.nc,
    experiment_*.png and experiment_summary.json (peaks side by side, fitted parameters with
    their standard errors, recovered vs true values for a SYNTHETIC file).
    """
    from rich.console import Console
    from rich.progress import BarColumn, Progress, TextColumn, TimeElapsedColumn

    from auxbearing.common.io import atomic_output_dir, save_dataset, save_figure, write_json
    from auxbearing.common.units import to_si
    from auxbearing.experiment.fit import FitOptions
    from auxbearing.experiment.io import read_measured
    from auxbearing.experiment.orbit import Preprocessing
    from auxbearing.experiment.run import run_experiment
    from auxbearing.planar.params import DropCase, Rotor, read_config
    from auxbearing.plots.experiment import experiment_figures
    unit_map = _units(units)
    cfg_bearing, rotor_kw, drop_kw = None, {}, {}
    if config is not None:
        with option_named("--config", "file"):
            cfg_bearing, rotor_kw, drop_kw = read_config(config)
    bearing = resolve_bearing(bearing_spec) if bearing_spec is not None else cfg_bearing or resolve_bearing("QJ202")
    factor = to_si("--scale", scale, "dimensionless")
    if factor <= 0.0:
        raise InputError.for_field("--scale", scale, "must be > 0 (a sensor sensitivity correction)")
    typed = {"offset": ("--offset", offset), "scale": ("--scale", scale), "cutoff": ("--cutoff", cutoff),
             "drop_time": ("--drop-time", drop_time), "window": ("--fit-window", fit_window),
             "clearance": ("--clearance", clearance)}
    with _as_typed(typed):
        prep = Preprocessing(
            offset=_offset(offset.strip()),
            scale=factor,
            cutoff=None if cutoff.strip().lower() == "none" else _frequency(cutoff),
            drop_time=quantity("--drop-time", drop_time, "time", "s"),
        )
        fit_options = FitOptions(window=_positive("--fit-window", fit_window, "time", "ms"))
    clearance_si = _positive("--clearance", clearance, "length", "mm")
    with option_named("--measured", "measured file"):
        data = read_measured(measured, unit_map, field="--measured")
    with _as_typed(typed):
        from auxbearing.experiment.orbit import preprocess

        preprocess(data, prep)  # the record against the options, before any fit or simulation
    progress = Progress(TextColumn("{task.description:<48}"), BarColumn(), TextColumn("{task.percentage:>3.0f}%"),
                        TimeElapsedColumn(), console=Console(stderr=True), disable=quiet or as_json, transient=True)
    with progress, _as_typed(typed):
        task = progress.add_task("experiment", total=1.0)
        result = run_experiment(data, bearing, Rotor(**rotor_kw), DropCase(**drop_kw), prep, fit=not no_fit,
                                fit_options=fit_options, clearance=clearance_si,
                                progress=lambda f, label: progress.update(task, completed=f, description=label))
    warn(*result.summary.get("warnings", []))
    inputs = {"measured": str(measured), "bearing": bearing.describe(), "config": str(config) if config else None,
              "offset": offset, "scale": scale, "cutoff": cutoff, "drop_time": drop_time, "clearance": clearance,
              "fit": not no_fit, "fit_window": fit_window, "units": unit_map}
    with atomic_output_dir(out_dir) as tmp:
        for name, ds in result.datasets.items():
            save_dataset(ds, tmp / f"{name}.nc", inputs)
        for name, fig in experiment_figures(result.drawing).items():
            save_figure(fig, tmp / name)
        write_json(result.summary, tmp / "experiment_summary.json", inputs)
    if as_json:
        echo_json({**result.summary, "out": str(out_dir)})
        return
    _print(result.summary, out_dir)


def _frequency(text: str) -> float:
    """A cutoff frequency in Hz ('8 kHz', '8000'); units.SI_UNITS has no frequency, so pint directly."""
    import pint

    from auxbearing.common.units import ureg
    try:
        q = ureg.Quantity(text.strip())
        value = float(q.to("Hz").magnitude) if isinstance(q, pint.Quantity) and not q.dimensionless else float(
            getattr(q, "magnitude", q))
    except pint.DimensionalityError as err:  # a TypeError too: caught before the generic branch
        raise InputError.for_field("--cutoff", text, f"unit {err.units1} is not a frequency (use e.g. Hz, kHz)"
                                   ) from None
    except (OverflowError, ValueError, TypeError):
        raise InputError.for_field("--cutoff", text, "is not a finite number") from None
    except Exception:  # pint raises several unrelated types for malformed text
        raise InputError.for_field("--cutoff", text, "must be a frequency such as '8 kHz' or 8000 (Hz)") from None
    if not (math.isfinite(value) and value > 0.0):
        raise InputError.for_field("--cutoff", text, "must be > 0 Hz")
    return value


def _clearance_line(m: dict) -> str:
    """The clearance behind the force estimate and how much 1 um of it moves the peak stress."""
    head = f"Clearance used for the force: {m['clearance_used_um']:.2f} µm ({m['clearance_source']}); "
    plus, minus = m["peak_stress_if_clearance_plus_1um_MPa"], m["peak_stress_if_clearance_minus_1um_MPa"]
    if m["peak_contact_force_N"] > 0.0:
        return head + f"±1 µm moves the peak stress to {plus:.0f} / {minus:.0f} MPa"
    # no contact: "moves the peak stress to 0 / 0 MPa" would read as a result
    gap = m.get("gap_to_clearance_um")
    inside = f"the orbit stays {gap:.2f} µm inside it: " if gap is not None else ""
    if minus > 0.0:
        return head + inside + f"no contact (1 µm less would give a peak stress of {minus:.0f} MPa)"
    return head + inside + "no contact, so no force or stress from the orbit"


def _print(summary: dict, out_dir: Path) -> None:
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    console = Console()
    if summary["synthetic"]:
        console.print("[bold]Note: this record is SYNTHETIC (made by the simulation), not a measurement.[/bold]")
    table = Table(title=escape(f"{summary['bearing']}: peaks from the orbit and from the simulation"))
    columns = summary["peak_table"]["columns"]
    rows = summary["peak_table"]["rows"]
    # the terminal gets the values and the last difference; the JSON has every difference
    keep = [k for k, c in enumerate(columns) if not c.startswith("Δ")] + [len(columns) - 1]
    # rich shrinks columns that do not fit by cutting their words ("configu…"); narrowed to their longest
    # word (or value) instead, the headers wrap between words and a table of a fit fits 80 columns
    widest = [max([len(columns[k])] + [len(r[k]) for r in rows]) for k in keep]
    narrowest = [max([len(w) for w in columns[k].split()] + [len(r[k]) for r in rows] + [1]) for k in keep]
    tight = sum(widest) + 3 * len(keep) + 1 > console.width
    for j, k in enumerate(keep):
        # escaped: rich reads "[ms]" as a style tag and would drop the unit
        table.add_column(escape(columns[k]), justify="left" if k == 0 else "right", no_wrap=k == 0,
                         width=narrowest[j] if tight and k else None)
    for row in rows:
        table.add_row(*(escape(row[k]) for k in keep))
    console.print(table)
    m = summary["measured"]
    console.print(escape(_clearance_line(m)))
    if "fit" in summary:
        fit = summary["fit"]
        ft = Table(title=f"Fit over the first {fit['window_ms']:g} ms (residual rms {fit['residual_rms_um']:.2f} µm)")
        for col in ("parameter", "value", "± 1σ", "unit"):
            ft.add_column(col, justify="right")
        for name, p in fit["parameters"].items():
            ft.add_row(name, f"{p['value_shown']:.5g}", f"{p['std_shown']:.2g}", p["unit"])
        console.print(ft)
    for row in summary.get("recovery", []):
        console.print(f"  {row['parameter']}: true {row['true']:.4g}, recovered {row['recovered']:.4g} ± "
                      f"{row['std']:.2g} {row['unit']}")
    speed = summary["speed_at_drop_rpm"]
    console.print(f"Speed at the drop {speed:.0f} rpm ({speed * math.pi / 30:.1f} rad/s). Wrote {out_dir}/")


COMMANDS = [experiment_command]
