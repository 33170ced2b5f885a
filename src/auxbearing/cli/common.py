"""Options and parsing shared by the commands."""

from __future__ import annotations

from pathlib import Path

import click

from auxbearing.bearing import BearingGeometry, bearing_names, load_bearing
from auxbearing.io import check_output_dir, dumps
from auxbearing.units import to_si


def bearing_option(default: str = "QJ202"):
    """``--bearing``: a catalogue name or a TOML file with a [bearing] table."""
    return click.option(
        "--bearing", "bearing_spec", default=default, show_default=True, metavar="NAME|FILE.toml",
        help="Catalogue bearing (" + ", ".join(bearing_names()) + ") or a TOML file with a [bearing] table.",
    )


def json_option():
    """``--json``: print one JSON object instead of a table."""
    return click.option("--json", "as_json", is_flag=True, help="Print one JSON object (for scripts).")


def checked_out_dir(ctx: click.Context, param: click.Parameter, value: Path | None) -> Path | None:
    """Click callback: refuse an output folder that cannot be made before the command does any work."""
    # An InputError here reaches the group's one-line handler (click parses inside Group.invoke).
    return None if value is None else check_output_dir(value)


def warn(*warnings: str | None, where: str = "") -> None:
    """Print each non-empty warning as one ``warning: ...`` line on stderr (stdout stays clean JSON)."""
    for text in warnings:
        if text:
            click.echo(f"warning: {where}{text}", err=True)


def out_option(default: str):
    """``--out``: output folder."""
    return click.option(
        "--out", "out_dir", type=click.Path(file_okay=False, path_type=Path), default=default,
        show_default=True, callback=checked_out_dir, help="Output folder (created; files in it are replaced).",
    )


def quantity(field: str, text: str | None, dimension: str, default_unit: str | None = None) -> float | None:
    """A command-line value with an optional unit, in SI (None stays None)."""
    if text is None:
        return None
    return to_si(field, text, dimension, default_unit)


def resolve_bearing(spec: str, contact_angle: str | None = None, groove_ratio: str | None = None) -> BearingGeometry:
    """Load a bearing and apply the common overrides."""
    bearing = load_bearing(spec)
    changes: dict = {}
    if contact_angle is not None:
        changes["contact_angle"] = to_si("--contact-angle", contact_angle, "angle", "deg")
    if groove_ratio is not None:
        ratio = to_si("--groove-ratio", groove_ratio, "dimensionless")
        changes.update(inner_groove_ratio=ratio, outer_groove_ratio=ratio)
    return bearing.with_changes(**changes) if changes else bearing


def echo_json(obj: object) -> None:
    """Print a JSON document."""
    click.echo(dumps(obj))
