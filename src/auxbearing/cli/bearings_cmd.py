"""``auxbearing bearings``: the bearing catalogue, filtered, with ratings and what is published or estimated."""

from __future__ import annotations

import re

import click

from auxbearing.cli.common import echo_json, json_option

_HELP = """List the bearing and material catalogues with their sources.

Every bearing shows its ball set, the basic ratings computed from it (C by ISO 281 times the
maker's rating factor, C0 by ISO 76), the maker's published ratings where the catalogue holds
them, and which geometry is estimated (makers do not publish ball sets; the rule is in
auxbearing.bearings.series). Names work as makers write them in every command and machine file:
'6205', '7208 BECBP', 'QJ 208 N2MA', 'QJ208 hybrid' (silicon-nitride balls), '7208 DB' (a
back-to-back pair, light preload; also DF, DT and 'medium' or 'heavy').

\b
Examples:
  auxbearing bearings --type angular --bore 40
  auxbearing bearings --type deep_groove --bore 30-60mm --json
"""


_BORE = re.compile(r"^\s*(\d+(?:\.\d*)?|\.\d+)\s*(?:(?:-|\.\.)\s*(\d+(?:\.\d*)?|\.\d+)\s*)?([a-zA-Z]+)?\s*$")


def _bore_range(text: str | None):
    """'40', '40 mm', '30-60', '30-60 mm', '30..60mm' -> (low, high) in m; plain numbers are mm.

    >>> _bore_range("30-60"), _bore_range("40 mm")
    ((0.03, 0.06), (0.04, 0.04))
    """
    if text is None:
        return None
    from auxbearing.common.errors import InputError
    from auxbearing.common.units import to_si

    rule = "must be a bore or a range, each above 0 (mm unless a unit is given), e.g. 40 or 30-60"
    match = _BORE.match(str(text))
    if match is None:  # '-5', '30-' or '30-60-90' would otherwise read as some other bore
        raise InputError.for_field("--bore", text, rule)
    low, high, unit = match.groups()
    try:
        values = [to_si("--bore", f"{float(n)} {unit or 'mm'}", "length") for n in (low, high) if n is not None]
    except ValueError:
        raise InputError.for_field("--bore", text, rule) from None
    if any(v <= 0.0 for v in values):
        raise InputError.for_field("--bore", text, rule)
    if len(values) == 2 and values[0] > values[1]:  # as contact-sweep refuses START > STOP
        raise InputError.for_field("--bore", text, "a range runs from the smaller bore to the larger, e.g. 30-60")
    low, high = (values[0], values[0]) if len(values) == 1 else values
    return low, high


@click.command("bearings", help=_HELP)
@click.option("--type", "types", multiple=True, metavar="TYPE",
              help="Keep only this type: deep_groove, angular_contact (or 'angular'), four_point (or 'QJ'); "
                   "repeat or separate by commas for several.")
@click.option("--bore", "bore", default=None, metavar="MM|MIN-MAX",
              help="Keep bores in this range, mm unless a unit is given ('40', '30-60', '25-50 mm').")
@click.option("--sources/--no-sources", default=True, show_default=True, help="Print every entry's source.")
@json_option()
def bearings_command(types, bore, sources, as_json):
    """The catalogue command (see the help text)."""
    from auxbearing.bearings.catalogue import entries, parse_type
    from auxbearing.bearings.materials import get_material, material_names

    kinds = [parse_type(t) for group in types for t in group.split(",") if t.strip()]
    rows = entries(types=kinds or None, bore_range=_bore_range(bore))
    materials = [{"name": m, "elastic_modulus_GPa": get_material(m).elastic_modulus / 1e9,
                  "poisson_ratio": get_material(m).poisson_ratio, "density_kg_m3": get_material(m).density,
                  "source": get_material(m).source} for m in material_names()]
    if as_json:
        echo_json({"bearings": rows, "materials": materials,
                   "names": "as makers write them; add 'hybrid' for Si3N4 balls, 'DB'/'DF'/'DT' for a matched pair"})
        return
    from rich.console import Console
    from rich.markup import escape
    from rich.table import Table

    # rich reads a lowercase [..] as a style tag and drops it ("[kN]", "[kg/m³]"): every title, header and cell
    # goes through escape, the catalogue's names and sources too
    table = Table(title=escape(f"Bearings ({len(rows)}): C, C0 computed [kN] (the maker's in brackets)"))
    for col in ("name", "type", "d×D×B mm", "Z × D_w mm", "C kN", "C0 kN", "geometry"):
        table.add_column(escape(col), no_wrap=True)
    short = {"deep_groove": "DG", "angular_contact": "AC", "four_point": "4P"}
    for r in rows:
        envelope = "×".join(f"{r[k]:g}" for k in ("bore_mm", "outside_diameter_mm", "width_mm") if r.get(k) is not None)
        table.add_row(
            escape(r["name"]), f"{short[r['type']]} {r['contact_angle_deg']:g}°", envelope,
            f"{r['ball_count']} × {r['ball_diameter_mm']:.2f}",
            f"{r['C_N'] / 1e3:.1f}" + ("" if r["C_published_N"] is None else f" ({r['C_published_N'] / 1e3:g})"),
            f"{r['C0_N'] / 1e3:.1f}" + ("" if r["C0_published_N"] is None else f" ({r['C0_published_N'] / 1e3:g})"),
            "estimated" if r["estimated"] else "source")
    mats = Table(title="Materials")
    for col in ("name", "E [GPa]", "ν", "ρ [kg/m³]"):
        mats.add_column(escape(col), no_wrap=True)
    for m in materials:
        mats.add_row(escape(m["name"]), f"{m['elastic_modulus_GPa']:g}", f"{m['poisson_ratio']:g}",
                     "" if m["density_kg_m3"] is None else f"{m['density_kg_m3']:g}")
    console = Console()
    console.print(table)
    console.print(mats)
    if sources:
        console.print("Sources:")
        for entry in rows + materials:
            console.print(escape(f"  {entry['name']}: {entry['source']}"), highlight=False)


COMMANDS = [bearings_command]
