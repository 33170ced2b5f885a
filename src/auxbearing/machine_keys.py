"""The reference of the machine file: every table and key with its unit, default, rule and source.

``docs/machine_file.md`` is this module's output, so it cannot drift from what the reader accepts::

    python -m auxbearing.machine_keys > docs/machine_file.md

(a test compares the two). The rows come from the same :class:`~auxbearing.params.Param` tables the
reader checks a file against.
"""

from __future__ import annotations

from auxbearing.params import Param, display_value, si_unit

_INTRO = """# The machine file

A machine file is TOML; every number carries its unit as a string (`"0.15 mm"`, `"18000 rpm"`,
`"2e7 N/m"`); a bare number is SI. Every table and key is checked before anything runs: an unknown
table or key, a wrong unit or a value outside its rule stops with one line naming it. The shipped
examples (`auxbearing machines`) are complete files to start from:
`src/auxbearing/catalog/machines/*.toml`.

This page is generated: `python -m auxbearing.machine_keys > docs/machine_file.md`.

| table | what it holds |
|---|---|
| `[machine]` | `name`, `orientation` (`horizontal` or `vertical`), `source` (where the numbers come from) |
| `[rotor]` | the rigid rotor: mass, inertias, speed, unbalance, process loads |
| `[[touchdown]]` | one per touchdown plane (one or two): bearing, clearances, mount, friction, heat |
| `[drop]` | the drop simulation: duration, tolerances, budgets |
| `[coastdown]` | drag of the rotor and the ambient, for `coastdown` and `verify` |
| `[life]` | the number of drops the bearings must survive |
| `[criteria]` | the acceptance values `verify` judges against |
| `[verify]` | the cases and the campaign of `verify` |
| `[[candidate]]` | other bearings for the same seats: `name` and `bearing` (catalogue name, TOML path or table) |
| `[campaign]` | a Monte Carlo campaign over this machine (`auxbearing campaign --help`) |

In `[[touchdown]]`, `bearing` is a catalogue name (`auxbearing bearings`), the path of a bearing TOML
file (relative to the machine file) or an inline table with the keys of a bearing file
(`examples/my_bearing.toml`). A default written as "derived" is computed from the bearing or the rotor
and stated in the reports.
"""


def _sections() -> list[tuple[str, tuple[Param, ...]]]:
    from auxbearing.machine_params import COASTDOWN, LIFE, ROTOR, SIMULATION, TOUCHDOWN
    from auxbearing.verify.cases import VERIFY
    from auxbearing.verify.criteria import CRITERIA

    return [("rotor", ROTOR), ("touchdown", TOUCHDOWN), ("drop", SIMULATION), ("coastdown", COASTDOWN),
            ("life", LIFE), ("criteria", CRITERIA), ("verify", VERIFY)]


def _cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def _default(param: Param) -> str:
    if param.default is None:
        return "required" if param.source == "required" else "derived / none"
    if param.dimension == "temperature":
        return f"{param.default - 273.15:.6g} degC"
    shown = display_value(param, param.default)
    return f"`{shown}`" if isinstance(shown, str) else f"`{shown:g}`"


def markdown() -> str:
    """The whole reference as Markdown text."""
    lines = [_INTRO]
    for name, rows in _sections():
        header = f"[[{name}]]" if name == "touchdown" else f"[{name}]"
        lines += [f"## `{header}`", "", "| key | unit | default | meaning | source |", "|---|---|---|---|---|"]
        for p in rows:
            unit = p.display_unit or si_unit(p.dimension) or "-"
            lines.append(f"| `{p.key}` | {_cell(unit)} | {_cell(_default(p))} | {_cell(p.help)} | "
                         f"{_cell(p.source)} |")
        lines.append("")
    return "\n".join(lines)


if __name__ == "__main__":
    print(markdown(), end="")
