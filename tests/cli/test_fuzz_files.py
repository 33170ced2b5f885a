"""Fuzz table (issue 11): bad input files of every kind, each refused in one line naming the key as written.

File kinds: bearing TOML (``contact --bearing``), study TOML (``study --config``), machine TOML
(``drop --machine``, ``coastdown --machine``), drop TOML (``drop --config``), load-case CSV
(``static-cases --loads``), measured-drop CSV and NetCDF (``experiment --measured``). A file in another
encoding is read when its encoding can be told (a byte-order mark, UTF-16 without one, Windows-1252) with
a warning naming the encoding assumed, or refused in one line. Cases run as in ``test_fuzz_commands.py``.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from tests.cli.test_fuzz_harness import case, check_case

BEARING = """[bearing]
name = "my bearing"
type = "four_point"
ball_diameter = "6 mm"
pitch_diameter = "25.5 mm"
ball_count = 11
inner_groove_ratio = 0.52
outer_groove_ratio = 0.52
contact_angle = "35 deg"
diametral_clearance = "0 mm"
ball_material = "GCr15"
ring_material = "GCr15"
bore = "15 mm"
outside_diameter = "35 mm"
width = "11 mm"
"""

MACHINE = """[machine]
name = "fuzz rig"
orientation = "horizontal"

[rotor]
mass = "1.48 kg"
polar_inertia = "3.88e-4 kg*m^2"
speed = "6000 rpm"
unbalance = "10 um"

[[touchdown]]
name = "A"
bearing = "QJ202"
position = "0 mm"
radial_clearance = "0.2 mm"

[drop]
duration = "1 ms"
"""

LOADS = "# duty cycle\naxial [N], radial [kN], moment [N*m]\n0, 0.5, 0\n200, 1.0, 2\n"


def _bearing(key: str, value: str) -> str:
    """The good bearing with one line replaced (or added when the key is new)."""
    lines = BEARING.splitlines()
    for k, line in enumerate(lines):
        if line.split("=")[0].strip() == key:
            lines[k] = f"{key} = {value}"
            break
    else:
        lines.append(f"{key} = {value}")
    return "\n".join(lines) + "\n"


def _without(text: str, key: str) -> str:
    return "\n".join(ln for ln in text.splitlines() if ln.split("=")[0].strip() != key) + "\n"


def _machine(old: str, new: str) -> str:
    assert old in MACHINE
    return MACHINE.replace(old, new)


def _measured_rows(n: int = 200, rate: float = 50e3) -> list[list[float]]:
    t = np.arange(n) / rate
    return [[float(ti), 10.0 * np.sin(2e3 * ti), -5.0 + 0.1 * k % 3] for k, ti in enumerate(t)]


def _measured(rows: list[list[object]], header: str = "time [s], x [um], y [um]", comment: str = "") -> str:
    body = "\n".join(", ".join(str(v) for v in row) for row in rows)
    return f"{comment}{header}\n{body}\n"


GOOD_ROWS = _measured_rows()
SYNTHETIC = (Path(__file__).parents[2] / "src/auxbearing/catalog/experiments/qj202_drop_synthetic.csv").read_text()


def _netcdf(**changes):
    """A writer of a measured NetCDF record; ``changes`` edit the variables before it is written."""

    def write(path: Path) -> None:
        import xarray as xr

        rows = np.array(GOOD_ROWS)
        variables = {"x": ("time", rows[:, 1], {"units": "um"}), "y": ("time", rows[:, 2], {"units": "um"})}
        time = ("time", rows[:, 0], {"units": "s"})
        for key, value in changes.items():
            if key == "time":
                time = value
            elif value is None:
                variables.pop(key)
            else:
                variables[key] = value
        xr.Dataset(variables, coords={"time": time}).to_netcdf(path)

    return write


BEARING_FILES = [
    case("btoml-latin1", "contact --bearing b.toml", "b.toml", "Windows-1252",
         files={"b.toml": _bearing("name", '"Müller Lager"').encode("latin-1")}, expect="warning",
         note="issue: a Latin-1 bearing TOML was a UnicodeDecodeError"),
    case("btoml-utf16-bom", "contact --bearing b.toml --json", files={"b.toml": BEARING.encode("utf-16")},
         expect="ok"),
    case("btoml-utf16-no-bom", "contact --bearing b.toml", "b.toml", "UTF-16",
         files={"b.toml": BEARING.encode("utf-16-le")}, expect="warning"),
    case("btoml-binary", "contact --bearing b.toml", "b.toml",
         files={"b.toml": bytes(range(256)) * 4}),
    case("btoml-syntax", "contact --bearing b.toml", "b.toml", files={"b.toml": "[bearing\nx = 1\n"}),
    case("btoml-empty", "contact --bearing b.toml", "b.toml", "[bearing]", files={"b.toml": ""}),
    case("btoml-no-table", "contact --bearing b.toml", "b.toml", "[bearing]", files={"b.toml": "x = 1\n"}),
    case("btoml-not-a-table", "contact --bearing b.toml", "bearing", "5", files={"b.toml": "bearing = 5\n"}),
    case("btoml-unknown-key", "contact --bearing b.toml", "bearing.ball_diam", "6 mm",
         files={"b.toml": _bearing("ball_diam", '"6 mm"')}),
    case("btoml-missing-key", "contact --bearing b.toml", "bearing.ball_count",
         files={"b.toml": _without(BEARING, "ball_count")}),
    case("btoml-two-balls", "contact --bearing b.toml", "bearing.ball_count", "2",
         files={"b.toml": _bearing("ball_count", "2")}),
    case("btoml-count-text", "contact --bearing b.toml", "bearing.ball_count", "11",
         files={"b.toml": _bearing("ball_count", '"11"')}),
    case("btoml-count-fraction", "contact --bearing b.toml", "bearing.ball_count", "11.5",
         files={"b.toml": _bearing("ball_count", "11.5")}),
    case("btoml-6000-balls-overlap", "contact --bearing b.toml", "bearing.ball_count", "6000",
         files={"b.toml": _bearing("ball_count", "6000")}),
    case("btoml-diameter-no-unit", "contact --bearing b.toml", "bearing.ball_diameter", "6",
         files={"b.toml": _bearing("ball_diameter", "6")}),
    case("btoml-diameter-mass", "contact --bearing b.toml", "bearing.ball_diameter", "6 kg",
         files={"b.toml": _bearing("ball_diameter", '"6 kg"')}),
    case("btoml-diameter-huge-int", "contact --bearing b.toml", "bearing.ball_diameter", "10**400 mm",
         files={"b.toml": _bearing("ball_diameter", '"10**400 mm"')}),
    case("btoml-diameter-nan", "contact --bearing b.toml", "bearing.ball_diameter", "nan mm",
         files={"b.toml": _bearing("ball_diameter", '"nan mm"')}),
    case("btoml-diameter-negative", "contact --bearing b.toml", "bearing.ball_diameter", "-6 mm",
         files={"b.toml": _bearing("ball_diameter", '"-6 mm"')}),
    case("btoml-pitch-small", "contact --bearing b.toml", "bearing.pitch_diameter", "5 mm",
         files={"b.toml": _bearing("pitch_diameter", '"5 mm"')}),
    case("btoml-ratio-low", "contact --bearing b.toml", "bearing.inner_groove_ratio", "0.49",
         files={"b.toml": _bearing("inner_groove_ratio", "0.49")}),
    case("btoml-ratio-length", "contact --bearing b.toml", "bearing.inner_groove_ratio", "0.52 mm",
         files={"b.toml": _bearing("inner_groove_ratio", '"0.52 mm"')}),
    case("btoml-angle-95", "contact --bearing b.toml", "bearing.contact_angle", "95 deg",
         files={"b.toml": _bearing("contact_angle", '"95 deg"')}),
    case("btoml-angle-no-unit", "contact --bearing b.toml", "bearing.contact_angle", "35",
         files={"b.toml": _bearing("contact_angle", "35")}),
    case("btoml-type", "contact --bearing b.toml", "bearing.type", "roller",
         files={"b.toml": _bearing("type", '"roller"')}),
    case("btoml-material-unknown", "contact --bearing b.toml", "bearing.ball_material", "Unobtainium",
         files={"b.toml": _bearing("ball_material", '"Unobtainium"')}),
    case("btoml-material-modulus", "contact --bearing b.toml", "bearing.ball_material.elastic_modulus", "-1 GPa",
         files={"b.toml": _bearing("ball_material", '{elastic_modulus = "-1 GPa", poisson_ratio = 0.3}')}),
    case("btoml-material-poisson", "contact --bearing b.toml", "bearing.ball_material.poisson_ratio", "0.7",
         files={"b.toml": _bearing("ball_material", '{elastic_modulus = "207 GPa", poisson_ratio = 0.7}')}),
    case("btoml-clearance-huge", "contact --bearing b.toml", "bearing.diametral_clearance", "5 mm",
         files={"b.toml": _bearing("diametral_clearance", '"5 mm"')}),
    case("btoml-bore-large", "contact --bearing b.toml", "bearing.bore", "30 mm",
         files={"b.toml": _bearing("bore", '"30 mm"')}),
    case("btoml-outside-small", "contact --bearing b.toml", "bearing.outside_diameter", "20 mm",
         files={"b.toml": _bearing("outside_diameter", '"20 mm"')}),
    case("btoml-deep-groove-angle", "contact --bearing b.toml", "bearing.contact_angle", "35 deg",
         files={"b.toml": _bearing("type", '"deep_groove"')}),
    case("btoml-folder", "contact --bearing b.toml", "b.toml", files={"b.toml/": ""}, avoid=("not found",)),
]

STUDY_FILES = [
    case("study-not-a-table", "study --config s.toml", "study", "5", files={"s.toml": "study = 5\n"},
         note="issue: study = 5 was a traceback"),
    case("study-unknown-section", "study --config s.toml", "[foo]", files={"s.toml": "[foo]\nx = 1\n"}),
    case("study-unknown-key", "study --config s.toml", "study.titel", files={"s.toml": '[study]\ntitel = "x"\n'}),
    case("study-angles-no-unit", "study --config s.toml", "study.contact_angles",
         files={"s.toml": "[study]\ncontact_angles = [10, 75, 1]\n"}),
    case("study-angles-two", "study --config s.toml", "study.contact_angles",
         files={"s.toml": '[study]\ncontact_angles = ["10 deg", "75 deg"]\n'}),
    case("study-angles-95", "study --config s.toml", "study.contact_angles", "95 deg",
         files={"s.toml": '[study]\ncontact_angles = ["10 deg", "95 deg", "1 deg"]\n'}),
    case("study-angles-tiny-step", "study --config s.toml", "study.contact_angles",
         files={"s.toml": '[study]\ncontact_angles = ["10 deg", "75 deg", "1e-6 deg"]\n'}),
    case("study-ratios-low", "study --config s.toml", "study.groove_ratios",
         files={"s.toml": "[study]\ngroove_ratios = [0.4, 0.6, 0.01]\n"}),
    case("study-ratios-text", "study --config s.toml", "study.groove_ratios",
         files={"s.toml": '[study]\ngroove_ratios = ["a", 0.6, 0.01]\n'}),
    case("study-load-negative", "study --config s.toml", "study.ball_load", "-1 N",
         files={"s.toml": '[study]\nball_load = "-1 N"\n'}),
    case("study-load-huge-int", "study --config s.toml", "study.ball_load", "10**400 N",
         files={"s.toml": '[study]\nball_load = "10**400 N"\n'}),
    case("study-bearing-deep-groove", "study --config s.toml", "bearing.catalogue", "209",
         files={"s.toml": '[bearing]\ncatalogue = "209"\n'}, note="issue: an IndexError in the plot"),
    case("study-bearing-unknown", "study --config s.toml", "bearing.catalogue", "QJ999",
         files={"s.toml": '[bearing]\ncatalogue = "QJ999"\n'}),
    case("study-bearing-bad-key", "study --config s.toml", "bearing.ball_diam",
         files={"s.toml": BEARING.replace("ball_diameter", "ball_diam")}),
    case("study-comparison-four-point", "study --config s.toml", "comparison_bearing.catalogue", "QJ202",
         files={"s.toml": '[comparison_bearing]\ncatalogue = "QJ202"\n'}),
    case("study-static-table", "study --config s.toml", "[static]",
         files={"s.toml": '[static]\nradial = "1 kN"\n'}, note="issue: [static] was never read"),
    case("study-experiment-table", "study --config s.toml", "[experiment]",
         files={"s.toml": '[experiment]\ncutoff = "8 kHz"\n'}, note="issue: [experiment] was never read"),
    case("study-rotor-negative", "study --config s.toml", "rotor.mass", "-1 kg",
         files={"s.toml": '[rotor]\nmass = "-1 kg"\n'}),
    case("study-drop-unknown", "study --config s.toml", "drop.clearence",
         files={"s.toml": '[drop]\nclearence = "0.2 mm"\n'}),
    case("study-latin1-syntax", "study --config s.toml", "s.toml",
         files={"s.toml": '[study]\ntitle = "Müller\n'.encode("latin-1")}),
    case("study-syntax", "study --config s.toml", "s.toml", files={"s.toml": "[study\n"}),
]

MACHINE_FILES = [
    case("mtoml-unknown-table", "drop --machine m.toml", "[foo]", files={"m.toml": MACHINE + "[foo]\nx = 1\n"}),
    case("mtoml-no-mass", "drop --machine m.toml", "rotor.mass", files={"m.toml": _machine('mass = "1.48 kg"\n', "")}),
    case("mtoml-no-touchdown", "drop --machine m.toml", "touchdown",
         files={"m.toml": MACHINE.split("[[touchdown]]")[0]}),
    case("mtoml-no-clearance", "drop --machine m.toml", "radial_clearance",
         files={"m.toml": _machine('radial_clearance = "0.2 mm"\n', "")}),
    case("mtoml-bearing-unknown", "drop --machine m.toml", "touchdown.0", "QJ999",
         files={"m.toml": _machine('bearing = "QJ202"', 'bearing = "QJ999"')}),
    case("mtoml-bearing-file-missing", "drop --machine m.toml", "nofile.toml",
         files={"m.toml": _machine('bearing = "QJ202"', 'bearing = "nofile.toml"')}),
    case("mtoml-speed-overflow", "drop --machine m.toml", "rotor.speed", "1e400 rpm",
         files={"m.toml": _machine('speed = "6000 rpm"', 'speed = "1e400 rpm"')}),
    case("mtoml-mass-no-unit", "drop --machine m.toml", "rotor.mass", files={"m.toml": _machine('"1.48 kg"', "5")}),
    case("mtoml-duration-zero", "drop --machine m.toml", "drop.duration",
         files={"m.toml": _machine('duration = "1 ms"', 'duration = "0 s"')}),
    case("mtoml-max-steps-fraction", "drop --machine m.toml", "drop.max_steps",
         files={"m.toml": MACHINE + "max_steps = 0.5\n"}),
    case("mtoml-orientation", "drop --machine m.toml", "machine.orientation", "diagonal",
         files={"m.toml": _machine('"horizontal"', '"diagonal"')}),
    case("mtoml-touchdown-table", "drop --machine m.toml", "touchdown",
         files={"m.toml": _machine("[[touchdown]]", "[touchdown]")}),
    case("mtoml-three-planes", "drop --machine m.toml", "touchdown",
         files={"m.toml": MACHINE + "".join(f'[[touchdown]]\nname = "P{k}"\nbearing = "QJ202"\n'
                                            f'position = "{10 * k} mm"\nradial_clearance = "0.2 mm"\n'
                                            for k in (1, 2))}),
    case("mtoml-unbalance-beyond-clearance", "drop --machine m.toml", "rotor.unbalance",
         files={"m.toml": _machine('unbalance = "10 um"', 'unbalance = "1 m"')}, expect="warning"),
    case("mtoml-clearance-vs-bore", "drop --machine m.toml", "radial_clearance", "7 mm",
         files={"m.toml": _machine('radial_clearance = "0.2 mm"', 'radial_clearance = "7 mm"')},
         expect="warning"),
    case("mtoml-latin1", "drop --machine m.toml", "m.toml", "Windows-1252",
         files={"m.toml": _machine('"fuzz rig"', '"Prüfstand"').encode("latin-1")}, expect="warning"),
    case("mtoml-vacuum-text", "coastdown --machine m.toml", "coastdown.vacuum",
         files={"m.toml": MACHINE + '[coastdown]\nvacuum = "yes"\n'}),
    case("mtoml-machine-not-table", "drop --machine m.toml", "machine", "5",
         files={"m.toml": "machine = 5\n" + MACHINE.split("\n", 3)[3]}),
    case("mtoml-folder", "drop --machine m.toml", "m.toml", files={"m.toml/": ""}, avoid=("not found",)),
    case("dtoml-unknown-table", "drop --config d.toml", "[foo]", files={"d.toml": "[foo]\nx = 1\n"}),
    case("dtoml-bad-value", "drop --config d.toml", "drop.clearance", "-1 mm",
         files={"d.toml": '[drop]\nclearance = "-1 mm"\n'}),
    case("dtoml-no-unit", "drop --config d.toml", "rotor.mass", files={"d.toml": "[rotor]\nmass = 2\n"}),
    case("dtoml-speed-hz", "drop --config d.toml --json --quiet", files={"d.toml": '[drop]\nspeed = "100 Hz"\n'
                                                                                    'duration = "1 ms"\n'},
         expect="ok"),
]

LOAD_FILES = [
    case("lcsv-utf16-bom", "static-cases --loads l.csv --json", files={"l.csv": LOADS.encode("utf-16")},
         expect="ok", note="issue: a UTF-16 load CSV was a UnicodeDecodeError"),
    case("lcsv-latin1-comment", "static-cases --loads l.csv", "l.csv", "Windows-1252",
         files={"l.csv": ("# Lastfälle\n" + LOADS).encode("latin-1")}, expect="warning"),
    case("lcsv-no-header", "static-cases --loads l.csv", "l.csv", files={"l.csv": "# only comments\n"}),
    case("lcsv-empty", "static-cases --loads l.csv", "l.csv", files={"l.csv": ""}),
    case("lcsv-unknown-column", "static-cases --loads l.csv", "l.csv", "radal",
         files={"l.csv": "radal [N]\n1000\n"}),
    case("lcsv-no-unit", "static-cases --loads l.csv", "l.csv", "radial", files={"l.csv": "radial\n1000\n"}),
    case("lcsv-wrong-unit", "static-cases --loads l.csv", "l.csv", "kg", files={"l.csv": "radial [kg]\n1000\n"}),
    case("lcsv-huge-unit", "static-cases --loads l.csv", "l.csv", "10**400 N",
         files={"l.csv": "radial [10**400 N]\n1000\n"}),
    case("lcsv-short-row", "static-cases --loads l.csv", "l.csv", "line 3",
         files={"l.csv": "axial [N], radial [N]\n0, 1000\n5\n"}),
    case("lcsv-text-value", "static-cases --loads l.csv", "l.csv", "abc", files={"l.csv": "radial [N]\nabc\n"}),
    case("lcsv-nan-value", "static-cases --loads l.csv", "l.csv", "line 2", files={"l.csv": "radial [N]\nnan\n"}),
    case("lcsv-inf-value", "static-cases --loads l.csv", "l.csv", "inf", files={"l.csv": "radial [N]\ninf\n"}),
    case("lcsv-overflow-value", "static-cases --loads l.csv", "l.csv", "1e400",
         files={"l.csv": "radial [N]\n1e400\n"}),
    case("lcsv-mixed-columns", "static-cases --loads l.csv", "l.csv", "mixed",
         files={"l.csv": "radial [N], force_x [N]\n1000, 0\n"}),
    case("lcsv-header-only", "static-cases --loads l.csv", "l.csv", "no load cases",
         files={"l.csv": "radial [N]\n"}),
    case("lcsv-column-twice", "static-cases --loads l.csv", "l.csv", "twice",
         files={"l.csv": "radial [N], Fr [N]\n1, 2\n"}),
    case("lcsv-binary", "static-cases --loads l.csv", "l.csv", files={"l.csv": bytes(range(256)) * 8}),
    case("lcsv-decimal-comma", "static-cases --loads l.csv", "l.csv", "0,5",
         files={"l.csv": "axial [N]; radial [kN]\n0; 0,5\n"}),
    case("lcsv-enormous-load", "static-cases --loads l.csv", files={"l.csv": "radial [N]\n1e12\n"},
         expect="warning"),
    case("lcsv-overflow-in-unit", "static-cases --loads l.csv", "l.csv", "1e308",
         files={"l.csv": "radial [kN]\n1e308\n"},
         note="issue 20: a RuntimeWarning (overflow) leaked before the error"),
    case("lcsv-largest-double", "static-cases --loads l.csv", "l.csv", "1.7e308",
         files={"l.csv": "radial [N]\n1.7e308\n"}),
]

MEASURED_FILES = [
    case("mcsv-too-few", "experiment --measured m.csv", "m.csv", "samples",
         files={"m.csv": _measured(GOOD_ROWS[:10])}),
    case("mcsv-time-back", "experiment --measured m.csv", "m.csv", "line 5",
         files={"m.csv": _measured([*GOOD_ROWS[:3], GOOD_ROWS[1], *GOOD_ROWS[4:]])}),
    case("mcsv-nonuniform", "experiment --measured m.csv", "m.csv", "sampling interval",
         files={"m.csv": _measured([[r[0] + (0.2 / 50e3 if k > 50 else 0.0), *r[1:]]
                                    for k, r in enumerate(GOOD_ROWS)])}),
    case("mcsv-slow", "experiment --measured m.csv", "m.csv", "sampling rate",
         files={"m.csv": _measured(_measured_rows(200, 100.0))}),
    case("mcsv-no-y", "experiment --measured m.csv", "m.csv", "'y'",
         files={"m.csv": _measured([r[:2] for r in GOOD_ROWS], "time [s], x [um]")}),
    case("mcsv-x-no-unit", "experiment --measured m.csv", "m.csv", "x", "unit",
         files={"m.csv": _measured(GOOD_ROWS, "time [s], x, y [um]")}),
    case("mcsv-x-mass", "experiment --measured m.csv", "m.csv", "kg",
         files={"m.csv": _measured(GOOD_ROWS, "time [s], x [kg], y [um]")}),
    case("mcsv-missing-value", "experiment --measured m.csv", "m.csv", "line 12",
         files={"m.csv": _measured([*GOOD_ROWS[:10], [GOOD_ROWS[10][0], "", 1.0], *GOOD_ROWS[11:]])}),
    case("mcsv-text-value", "experiment --measured m.csv", "m.csv", "abc",
         files={"m.csv": _measured([*GOOD_ROWS[:10], [GOOD_ROWS[10][0], "abc", 1.0], *GOOD_ROWS[11:]])}),
    case("mcsv-header-only", "experiment --measured m.csv", "m.csv", files={"m.csv": "time [s], x [um], y [um]\n"}),
    case("mcsv-latin1-comment-short", "experiment --measured m.csv", "m.csv", "samples",
         files={"m.csv": _measured(GOOD_ROWS[:10], comment="# Prüfstand München\n").encode("latin-1")},
         note="issue: a 'ü' in a comment was a UnicodeDecodeError; the warning comes before the error"),
    case("mcsv-utf16-short", "experiment --measured m.csv", "m.csv", "samples",
         files={"m.csv": _measured(GOOD_ROWS[:10]).encode("utf-16")}),
    case("mcsv-binary", "experiment --measured m.csv", "m.csv", files={"m.csv": bytes(range(256)) * 8}),
    case("mcsv-unit-option-contradicts", "experiment --measured m.csv --unit x=mm", "m.csv", "contradicts",
         files={"m.csv": _measured(GOOD_ROWS)}),
    case("mcsv-unit-mm-for-um", "experiment --measured m.csv", "m.csv", "um", "mm",
         files={"m.csv": SYNTHETIC.replace("x [um]", "x [mm]").replace("y [um]", "y [mm]")},
         note="issue 20: refused as 'touching the wall in fewer than 3 directions', with RuntimeWarnings"),
    case("mcsv-unit-nm-for-um", "experiment --measured m.csv", "m.csv", "um", "nm",
         files={"m.csv": SYNTHETIC.replace("x [um]", "x [nm]").replace("y [um]", "y [nm]")}),
    case("mcsv-unit-m-for-um", "experiment --measured m.csv", "m.csv", "um",
         files={"m.csv": SYNTHETIC.replace("x [um]", "x [m]").replace("y [um]", "y [m]")}),
    case("mcsv-huge-values", "experiment --measured m.csv", "m.csv", "1e+308",
         files={"m.csv": _measured([[r[0], 1e308 * (k % 2), r[2]] for k, r in enumerate(GOOD_ROWS)])}),
    case("mnc-not-netcdf", "experiment --measured m.nc", "m.nc", files={"m.nc": "time,x,y\n"}),
    case("mnc-empty", "experiment --measured m.nc", "m.nc", files={"m.nc": b""}),
    case("mnc-no-x", "experiment --measured m.nc", "m.nc", "'x'", files={"m.nc": _netcdf(x=None)}),
    case("mnc-x-no-units", "experiment --measured m.nc", "m.nc", "'x'", "units",
         files={"m.nc": _netcdf(x=("time", np.array(GOOD_ROWS)[:, 1]))}),
    case("mnc-x-2d", "experiment --measured m.nc", "m.nc", "'x'",
         files={"m.nc": _netcdf(x=(("time", "k"), np.zeros((len(GOOD_ROWS), 2)), {"units": "um"}))}),
    case("mnc-x-nan", "experiment --measured m.nc", "m.nc", "'x'",
         files={"m.nc": _netcdf(x=("time", np.r_[np.nan, np.array(GOOD_ROWS)[1:, 1]], {"units": "um"}))}),
    case("mnc-time-dates", "experiment --measured m.nc", "m.nc", "time",
         files={"m.nc": _netcdf(time=("time", np.array(GOOD_ROWS)[:, 0], {"units": "days since 2000-01-01"}))}),
    case("mnc-x-mass", "experiment --measured m.nc", "m.nc", "kg",
         files={"m.nc": _netcdf(x=("time", np.array(GOOD_ROWS)[:, 1], {"units": "kg"}))}),
    case("mnc-folder", "experiment --measured m.nc", "m.nc", files={"m.nc/": ""}, avoid=("not found",)),
]

CASES = [*BEARING_FILES, *STUDY_FILES, *MACHINE_FILES, *LOAD_FILES, *MEASURED_FILES]


def test_ids_are_unique():
    from tests.cli.test_fuzz_commands import CASES as COMMAND_CASES

    ids = [c.id for c in [*CASES, *COMMAND_CASES]]
    assert len(ids) == len(set(ids))


@pytest.mark.parametrize("c", CASES, ids=[c.id for c in CASES])
def test_bad_file(c, tmp_path):
    check_case(c, tmp_path)
