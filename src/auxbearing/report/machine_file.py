"""The reference of the machine file: every table and key with its unit, default, rule and source.

``docs/machine_file.md`` is this module's output, so it cannot drift from what the reader accepts::

    python -m auxbearing.report.machine_file > docs/machine_file.md

(a test compares the two). The rows come from the same :class:`~auxbearing.common.params.Param` tables the
reader checks a file against.
"""

from __future__ import annotations

from auxbearing.common.params import Param, display_value, si_unit

_INTRO = """# The machine file

A machine file is TOML. A value with a unit is a string that spells its unit (`"0.15 mm"`,
`"18000 rpm"`, `"2e7 N/m"`); a bare number there is refused (`rotor.mass = 5: needs a unit, e.g.
'5 kg'`), never read as SI. Keys without a unit (the column "unit" shows `-`: friction coefficients,
ratios, counts) take plain numbers (`sliding_friction = 0.2`). (The Python API is the exception: there
a plain number is SI.)

The whole file is checked before anything runs, by every command that reads it (`drop`,
`coastdown`, `campaign`, `verify`), the tables a command does not use included: an unknown table or
key (the message names the closest allowed one), a wrong unit, a value outside its rule, two values
that cannot hold together (a start outside the clearance, a hard stop inside the dead band, a
temperature limit below ambient, mount or face keys without `mount_stiffness` or `axial_clearance`)
or a candidate that does not fit the design's seat stops with one line naming the keys. The shipped
examples (`auxbearing machines`) are complete files to start from:
`src/auxbearing/catalog/machines/*.toml`.

This page is generated: `python -m auxbearing.report.machine_file > docs/machine_file.md`.

| table | what it holds |
|---|---|
| `[machine]` | `name`, `orientation` (`horizontal` or `vertical`), `source` (where the numbers come from) |
| `[rotor]` | the rotor: mass and inertias (a rigid rotor) or `matrices` (an elastic one), speed, unbalance, \
process loads |
| `[[unbalance]]` | one per unbalance plane (instead of `rotor.unbalance` and `couple_unbalance`): position, amount \
`U = m e`, phase; with `matrices` they also bend the rotor |
| `[[touchdown]]` | one per touchdown plane (one or more): bearing, clearances, mount, friction, heat |
| `[[amb]]` | one per magnetic bearing: position, force law, PID gains, sensor and amplifier; it holds the rotor \
until a `[[scenario]]` fails it (without one, it fails at the drop) |
| `[[scenario]]` | what brings the levitated rotor down, and when: a failure of the magnetic bearings or an \
overload with them on (`name`, `kind`, `time`, the kind's keys); each is a case of `drop --scenario` and `verify` |
| `[[load]]` | a load on the rotor in every run: a force, an unbalance appearing, a base acceleration; a step or a \
half-sine pulse from `start` |
| `[[linear_support]]` | one per linear station (a seal, a damper, a linearised bearing): `name`, position, \
stiffness and damping coefficients |
| `[drop]` | the drop simulation: duration, tolerances, budgets |
| `[coastdown]` | drag of the rotor and the ambient, for `coastdown` and `verify` |
{life_row}
| `[criteria]` | the acceptance values `verify` judges against |
| `[verify]` | the cases and the campaign of `verify` |
| `[[candidate]]` | bearings for the same seats (same bore, no larger outside diameter, width within `axial_room`): \
`name`, `bearing`, `preload`; a candidate takes the design's seat and mount, but its own ring masses, contact \
stiffnesses, `ball_constant` and `shoulder_height` from its geometry, not the design's overrides |
| `[campaign]` | a Monte Carlo campaign over this machine (`auxbearing campaign --config`; keys below) |

In `[[touchdown]]`, `bearing` is a catalogue name (`auxbearing bearings`), the path of a bearing TOML
file (relative to the machine file) or an inline table with the keys of a bearing file
(`examples/my_bearing.toml`). A matched pair of angular-contact bearings is named as makers write it
(`"7208 DB"`, `"7208 DF"`, `"7208 DT"`); its `preload` is `light`, `medium` or `heavy` (this project's classes:
1, 2 and 4 % of a row's C0), a force (`"500 N"`) or an axial offset (`"8 um"`), given in the name
(`"7208 DB medium"`) or as the key `preload`; an inline table of an angular-contact row makes a pair of it with
the key `arrangement` (`"DB"`, `"DF"` or `"DT"`). A default written as "derived" is computed from the bearing
or the rotor and stated in the reports.

In `[rotor]`, `matrices = "rotor.npz"` (relative to the machine file) gives the free-free rotor as matrices: a
NumPy `.npz` of the arrays `M`, `K`, `G` (the gyroscopic matrix, to be multiplied by the spin speed), `nodes`
(the nodes' axial positions in metres) and optionally `C`, in SI, over four degrees of freedom per node in the
order x, y, theta_x, theta_y, with theta_y = dx/dz and theta_x = -dy/dz. `M` must be symmetric positive definite,
`K` symmetric positive semi-definite (the rigid motions are its zero eigenvalues: exactly four, two translations and
two tilts; a fifth is a mechanism, refused) and the symmetric part of `C` positive semi-definite, each square of
side four times the number of nodes; `G` holds +J_p of each disk at (theta_x, theta_y), and the polar inertia it
gives must be positive and at most twice the transverse one `M` gives (the perpendicular-axis theorem). An error
names the file as written and the array in it (`rotor.matrices = 'rotor.npz': its array 'C' ...`). Mass and
inertias then come from the
matrices (give neither), every `position` (of each `[[touchdown]]`, `[[unbalance]]` and station) is the axial
coordinate of one of the matrices' `nodes`, in the matrices' own frame, and the rotor bends in its free-free
elastic modes up to `max_mode_frequency` with the static correction at its stations (`reduction`): a force at a
station then bends the shaft with its whole flexibility, whatever the cut.
"""


#: The ``[life]`` row of the table of tables (one Markdown line, longer than a source line).
_LIFE_ROW = ("| `[life]` | the number of drops the bearings must survive; `dent_accumulation` (`same_spot`, "
             "the default: every drop dents one spot of each race, depths added; or `spread`: the rotating inner "
             "race's dents fall round it at random, the stationary outer race's on one spot) |")
_INTRO = _INTRO.replace("{life_row}", _LIFE_ROW)


#: Rows of the keys whose value is text, not a number with a unit.
_TEXT_ROWS = {"rotor": ["| `matrices` | - | none (a rigid rotor) | A .npz file of the free-free rotor's matrices M, K, "
                        "G (and C) and its nodes (see above); mass and inertias then come from it | the machine's "
                        "FE model |",
                        "| `ross_file` | - | none | A rotor saved by ROSS (`Rotor.save`; needs `pip install "
                        "'auxbearing[ross]'`): its shaft and disks are the matrices, its nodes' coordinates the "
                        "positions | ROSS |",
                        "| `ross_bearings` | - | `keep` | With `ross_file`: `keep` its bearings and seals as "
                        "`[[linear_support]]` stations (coefficients at `rotor.speed`) or `drop` them | ours |",
                        "| `reduction` | - | `static_correction` | With `matrices` or `ross_file`: `static_correction` "
                        "keeps the modes up to `max_mode_frequency` and adds, for x and y at every station, the "
                        "flexibility of the modes left out (Ritz vectors of the residual flexibility, above the cut; "
                        "not reported as modes); `modes` keeps the modes alone | Craig & Kurdila 2006, Sec. 17.4 |"],
              "touchdown": ["| `axial_direction` | - | `both` | With `axial_clearance`: the way the collar meets the "
                            "race face, `both` (the rotor is caught moving either way), `+z` (only moving towards "
                            "+z) or `-z` (only towards -z), as at the two ends of a rotor that each catch one way | "
                            "ours |"],
              "coastdown": ["| `vacuum` | - | `false` | `true`: the machine runs in vacuum, where no air carries heat "
                            "off the housing and journal (no convection; radiation by `emissivity`, conduction and a "
                            "given `housing_to_ambient` stay) | ours |"],
              "scenario": ["| `name` | - | required | The scenario's name (`drop --scenario NAME`) | ours |",
                           "| `kind` | - | `power_loss` | `power_loss` (every magnetic bearing loses its amplifiers; "
                           "the coils discharge with `decay_time`), `axis_loss` (one axis of one bearing), "
                           "`sensor_failure` (one bearing's sensor sticks or reads zero; the controller acts on it), "
                           "`shock` (a half-sine force pulse), `step_load` (a force step), `unbalance_step` (an "
                           "unbalance appears: a blade lost), `base_acceleration` (the housing accelerates; a "
                           "half-sine pulse by default) | ISO 14839-5's conditions |",
                           "| `bearing` | - | required for axis_loss, sensor_failure | The `[[amb]]` that fails, by "
                           "its name | ours |",
                           "| `axis` | - | required (axis_loss); `both` (sensor_failure) | `x` or `y` (or `both`) | "
                           "ours |",
                           "| `mode` | - | `zero` | sensor_failure: `stuck` (holds its reading) or `zero` | ours |",
                           "| `shape` | - | `half_sine` (shock, base_acceleration), `step` | The load's time "
                           "profile | ours |"],
              "amb": ["| `axis` | - | `radial` | `radial` (x and y at `position`) or `axial` (a thrust bearing on the "
                      "rotor's axial position; the machine needs a plane with `axial_clearance`) | ours |",
                      "| `controller` | - | none (the PID of `kp`, `ki`, `kd`) | The controller from the sensor's "
                      "reading to the current, `i = -C(s) x`, in SI (A per m): `{ num = [...], den = [...] }` "
                      "(coefficients in descending powers of s; proper: a derivative needs its filter) or "
                      "`{ A = [[...]], B = [[...]], C = [[...]], D = [[...]] }`; from Python also a python-control "
                      "`TransferFunction` or `StateSpace` | the controller's data |"],
              "load": ["| `name` | - | `load N` | The load's name | ours |",
                       "| `kind` | - | `force` | `force`, `unbalance` (it appears at `start`) or "
                       "`base_acceleration` | ours |",
                       "| `shape` | - | `half_sine` (`step` for an unbalance) | `step` (for `duration`, or to the "
                       "end) or `half_sine` (a shock pulse of `duration`) | ours |"]}


def _sections() -> list[tuple[str, tuple[Param, ...]]]:
    from auxbearing.machine.judging import CRITERIA, VERIFY
    from auxbearing.machine.params import COASTDOWN, LIFE, ROTOR, SIMULATION, TOUCHDOWN, UNBALANCE
    from auxbearing.machine.scenario import DOC_PARAMS as SCENARIO_PARAMS
    from auxbearing.machine.stations import kinds

    stations = [(kind.KIND, kind.PARAMS) for kind in kinds()]
    return [("rotor", ROTOR), ("unbalance", UNBALANCE), ("touchdown", TOUCHDOWN), *stations,
            ("scenario", SCENARIO_PARAMS), ("drop", SIMULATION), ("coastdown", COASTDOWN), ("life", LIFE),
            ("criteria", CRITERIA), ("verify", VERIFY)]


def _cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def _default(param: Param) -> str:
    if param.default is None:
        return "required" if param.source == "required" else "derived / none"
    if param.dimension == "temperature" and param.display_unit == "degC":  # a rise in K has no offset
        return f"{param.default - 273.15:.6g} degC"
    shown = display_value(param, param.default)
    return f"`{shown}`" if isinstance(shown, str) else f"`{shown:g}`"


def _campaign() -> list[str]:
    from auxbearing.campaign.config import CAMPAIGN_KEY_HELP
    from auxbearing.campaign.distributions import KINDS

    lines = ["## `[campaign]`", "",
             "A campaign file is a machine file whose `[campaign]` table runs many drops (or coast-downs) over "
             "uncertain inputs; `examples/campaign_*.toml` are complete ones.", "",
             "| key | default | meaning |", "|---|---|---|"]
    lines += [f"| `{key}` | {_cell(default)} | {_cell(meaning)} |" for key, (default, meaning) in
              CAMPAIGN_KEY_HELP.items()]
    lines += ["", "Each `[[campaign.input]]` has `key`, the dotted name of the value it varies (`rotor.<key>`, "
              "`drop.<key>`, `coastdown.<key>`, `touchdown.<plane>.<key>` or `touchdown.*.<key>` for every plane), "
              "`distribution`, and that distribution's parameters, with the input's unit:", "",
              "| distribution | parameters |", "|---|---|"]
    lines += [f"| `{kind}` | {', '.join(f'`{name}`' for name in names)} |" for kind, names in KINDS.items()]
    return [*lines, ""]


def markdown() -> str:
    """The whole reference as Markdown text."""
    from auxbearing.machine.stations import TABLES

    lines = [_INTRO]
    for name, rows in _sections():
        header = f"[[{name}]]" if name in ("touchdown", "unbalance", "scenario", *TABLES) else f"[{name}]"
        lines += [f"## `{header}`", "", "| key | unit | default | meaning | source |", "|---|---|---|---|---|"]
        for p in rows:
            unit = p.display_unit or si_unit(p.dimension) or "-"
            lines.append(f"| `{p.key}` | {_cell(unit)} | {_cell(_default(p))} | {_cell(p.help)} | "
                         f"{_cell(p.source)} |")
        lines += _TEXT_ROWS.get(name, [])
        lines.append("")
    lines += _campaign()
    return "\n".join(lines)


if __name__ == "__main__":
    print(markdown(), end="")
