"""Fuzz table (issue 11): bad option values on every command, each refused in one line, nothing written.

Every case runs in an empty folder (the harness, ``test_fuzz_harness.py``); an ``error`` case must end with
exit status 2 and one ``error:`` line on stderr naming the option as typed (``--ball-load``, not
``ball_load``) and the value as typed (not converted to SI), and leave the folder as it found it. A
``warning`` case is a legal number whose result would mean nothing: a ``warning:`` line, or a refusal.
The input-file kinds (TOML, CSV, NetCDF) have their own table in ``test_fuzz_files.py``.
"""

from __future__ import annotations

from dataclasses import replace

import pytest

from tests.cli.test_fuzz_harness import case, check_case

#: A file that is not a folder, for ``--out`` cases.
A_FILE = {"afile": "not a folder\n"}
A_FOLDER = {"adir.toml/": ""}

CONTACT = [
    case("contact-load-huge-int", "contact --ball-load '10**400 N'", "--ball-load", "10**400 N"),
    case("contact-load-text", "contact --ball-load abc", "--ball-load", "abc"),
    case("contact-load-negative", "contact --ball-load '-5 N'", "--ball-load", "-5 N"),
    case("contact-load-nan", "contact --ball-load nan", "--ball-load", "nan"),
    case("contact-load-inf", "contact --ball-load 'inf N'", "--ball-load", "inf N"),
    case("contact-load-mass", "contact --ball-load '5 kg'", "--ball-load", "5 kg"),
    case("contact-load-empty", "contact --ball-load ''", "--ball-load"),
    case("contact-load-overflow-float", "contact --ball-load 1e400", "--ball-load", "1e400"),
    case("contact-load-squared", "contact --ball-load '5 N N'", "--ball-load", "5 N N"),
    case("contact-load-moment", "contact --ball-load '1 N*m'", "--ball-load", "1 N*m"),
    case("contact-load-offset-unit", "contact --ball-load '20 degC'", "--ball-load", "20 degC"),
    case("contact-angle-95", "contact --contact-angle 95", "--contact-angle", "95"),
    case("contact-angle-negative", "contact --contact-angle '-1 deg'", "--contact-angle", "-1 deg"),
    case("contact-angle-2rad", "contact --contact-angle '2 rad'", "--contact-angle", "2 rad"),
    case("contact-angle-nan", "contact --contact-angle 'nan deg'", "--contact-angle", "nan deg"),
    case("contact-angle-length", "contact --contact-angle '35 mm'", "--contact-angle", "35 mm"),
    case("contact-angle-90", "contact --contact-angle 90", "--contact-angle", "90"),
    case("contact-ratio-half", "contact --groove-ratio 0.5", "--groove-ratio", "0.5"),
    case("contact-ratio-low", "contact --groove-ratio 0.4", "--groove-ratio", "0.4"),
    case("contact-ratio-text", "contact --groove-ratio abc", "--groove-ratio", "abc"),
    case("contact-ratio-length", "contact --groove-ratio '0.52 mm'", "--groove-ratio", "0.52 mm"),
    case("contact-ratio-nan", "contact --groove-ratio nan", "--groove-ratio", "nan"),
    case("contact-ratio-conformal", "contact --groove-ratio 0.5000001", "--groove-ratio", expect="warning",
         note="issue: an 89.5 mm semi-axis on a 6 mm ball"),
    case("contact-ratio-huge", "contact --groove-ratio 1e9", "--groove-ratio", expect="warning"),
    case("contact-load-beyond-shoulder", "contact --ball-load '1e7 N'", "--ball-load", expect="warning"),
    case("contact-bearing-unknown", "contact --bearing QJ999", "--bearing", "QJ999"),
    case("contact-bearing-empty", "contact --bearing ''", "--bearing"),
    case("contact-bearing-missing-file", "contact --bearing nofile.toml", "--bearing", "nofile.toml"),
    case("contact-bearing-folder", "contact --bearing adir.toml", "--bearing", "adir.toml",
         files=A_FOLDER, avoid=("not found",)),
    case("contact-method", "contact --method foo", "--method", "foo"),
    case("contact-unknown-option", "contact --foo 1", "--foo"),
    case("contact-extra-argument", "contact extra", "extra"),
    case("contact-missing-value", "contact --ball-load", "--ball-load"),
    case("contact-zero-load", "contact --ball-load 0 --json", expect="ok"),
    case("contact-help", "contact --help", expect="ok"),
]

SWEEP = [
    case("sweep-angle-nan", "contact-sweep --angle-range nan 75 1", "--angle-range", "nan"),
    case("sweep-angle-step-tiny", "contact-sweep --angle-range 10 75 1e-6", "--angle-range", "1e-06"),
    case("sweep-angle-reversed", "contact-sweep --angle-range 75 10 1", "--angle-range", "75"),
    case("sweep-angle-step-zero", "contact-sweep --angle-range 10 75 0", "--angle-range"),
    case("sweep-angle-step-negative", "contact-sweep --angle-range 10 75 -1", "--angle-range", "-1"),
    case("sweep-angle-beyond-90", "contact-sweep --angle-range 10 95 1", "--angle-range", "95"),
    case("sweep-angle-negative", "contact-sweep --angle-range -5 75 1", "--angle-range", "-5"),
    case("sweep-angle-inf", "contact-sweep --angle-range 10 inf 1", "--angle-range", "inf"),
    case("sweep-angle-text", "contact-sweep --angle-range a b c", "--angle-range"),
    case("sweep-angle-two-numbers", "contact-sweep --angle-range 10 75", "--angle-range"),
    case("sweep-ratio-below-half", "contact-sweep --ratio-range 0.4 0.6 0.01", "--ratio-range", "0.4"),
    case("sweep-ratio-step-tiny", "contact-sweep --ratio-range 0.505 0.6 1e-9", "--ratio-range", "1e-09"),
    case("sweep-ratio-inf", "contact-sweep --ratio-range inf 0.6 0.01", "--ratio-range", "inf"),
    case("sweep-ratio-step-nan", "contact-sweep --ratio-range 0.505 0.6 nan", "--ratio-range", "nan"),
    case("sweep-grid-product", "contact-sweep --angle-range 0 89 0.01 --ratio-range 0.505 0.6 0.0001",
         "--angle-range", "--ratio-range"),
    case("sweep-load-negative", "contact-sweep --ball-load '-1 N'", "--ball-load", "-1 N"),
    case("sweep-load-huge-int", "contact-sweep --ball-load '10**400 N'", "--ball-load", "10**400 N"),
    case("sweep-out-empty", "contact-sweep --out ''", "--out"),
    case("sweep-out-file", "contact-sweep --out afile", "--out", "afile", files=A_FILE),
    case("sweep-out-below-file", "contact-sweep --out afile/sub", "--out", "afile/sub", files=A_FILE),
    case("sweep-bearing-unknown", "contact-sweep --bearing QJ999", "--bearing", "QJ999"),
]

STATIC = [
    case("static-radial-huge-int", "static --radial '10**400 N'", "--radial", "10**400 N"),
    case("static-radial-text", "static --radial abc", "--radial", "abc"),
    case("static-radial-nan", "static --radial 'nan N'", "--radial", "nan N"),
    case("static-axial-mass", "static --axial '5 kg'", "--axial", "5 kg"),
    case("static-moment-force", "static --moment '5 N'", "--moment", "5 N"),
    case("static-moment-overflow", "static --moment '1e400 N*m'", "--moment", "1e400 N*m"),
    case("static-kb-mass", "static --radial 1000 --ball-constant '1 kg'", "--ball-constant", "1 kg"),
    case("static-kb-negative", "static --radial 1000 --ball-constant '-5 N/m**1.5'", "--ball-constant",
         "-5 N/m**1.5"),
    case("static-kb-text", "static --radial 1000 --ball-constant abc", "--ball-constant", "abc"),
    case("static-kb-zero", "static --radial 1000 --ball-constant '0 N/m**1.5'", "--ball-constant", "0 N/m**1.5"),
    case("static-kb-tiny", "static --radial 1000 --ball-constant '1 N/m**1.5'", "--ball-constant",
         expect="warning", note="the rings would move metres into the balls"),
    case("static-axial-condition", "static --axial-condition foo", "--axial-condition", "foo"),
    case("static-tilt", "static --tilt foo", "--tilt", "foo"),
    case("static-bearing-unknown", "static --bearing QJ999", "--bearing", "QJ999"),
    case("static-radial-enormous", "static --radial '1e12 N'", expect="warning"),
    case("static-ac-radial-free", "static --bearing 7202 --radial 1000", "--axial-condition"),
    case("static-json", "static --radial 1000 --json", expect="ok"),
]

STATIC_CASES = [
    case("cases-loads-missing-option", "static-cases", "--loads"),
    case("cases-loads-no-file", "static-cases --loads nofile.csv", "--loads", "nofile.csv"),
    case("cases-loads-folder", "static-cases --loads adir", "adir", files={"adir/": ""}, avoid=("not found",)),
    case("cases-kb-text", "static-cases --loads l.csv --ball-constant abc", "--ball-constant", "abc",
         files={"l.csv": "radial [N]\n1000\n"}),
    case("cases-out-file", "static-cases --loads l.csv --out afile", "--out", "afile",
         files={"l.csv": "radial [N]\n1000\n", **A_FILE}),
    case("cases-out-empty", "static-cases --loads l.csv --out ''", "--out", files={"l.csv": "radial [N]\n1000\n"}),
]

STATIC_STUDY = [
    case("study4pt-deep-groove", "static-study --bearing-4pt 209", "--bearing-4pt", "209"),
    case("study4pt-angular", "static-study --bearing-4pt 7202", "--bearing-4pt", "7202"),
    case("studyac-four-point", "static-study --bearing-ac QJ202", "--bearing-ac", "QJ202"),
    case("study4pt-unknown", "static-study --bearing-4pt QJ999", "--bearing-4pt", "QJ999"),
    case("study4pt-out-empty", "static-study --out ''", "--out"),
    case("study4pt-out-file", "static-study --out afile", "--out", "afile", files=A_FILE),
]

DROP = [
    case("drop-speed-overflow", "drop --speed '1e400 rpm'", "--speed", "1e400 rpm"),
    case("drop-speed-huge-int", "drop --speed '10**400 rpm'", "--speed", "10**400 rpm"),
    case("drop-speed-text", "drop --speed abc", "--speed", "abc"),
    case("drop-speed-length", "drop --speed '5 mm'", "--speed", "5 mm"),
    case("drop-clearance-zero", "drop --clearance '0 mm'", "--clearance", "0 mm"),
    case("drop-clearance-negative", "drop --clearance '-0.1 mm'", "--clearance", "-0.1 mm"),
    case("drop-clearance-bore", "drop --clearance '7.5 mm'", "--clearance", "7.5 mm"),
    case("drop-friction-high", "drop --friction 1.5", "--friction", "1.5"),
    case("drop-friction-nan", "drop --friction nan", "--friction", "nan"),
    case("drop-duration-zero", "drop --duration 0", "--duration", "0"),
    case("drop-duration-negative", "drop --duration '-1 s'", "--duration", "-1 s"),
    case("drop-duration-overflow", "drop --duration '1e400 s'", "--duration", "1e400 s"),
    case("drop-duration-budget", "drop --duration '1e7 s'", "--duration", "max_steps"),
    case("drop-max-step-budget", "drop --max-step 0.001us", "--max-step", "max_steps"),
    case("drop-output-step-long", "drop --output-step '1 s'", "--output-step", "1 s"),
    case("drop-max-step-zero", "drop --max-step 0", "--max-step", "0"),
    case("drop-rtol-one", "drop --rtol 1", "--rtol", "1"),
    case("drop-start-outside", "drop --start-x '1 mm'", "--start-x"),
    case("drop-rotor-radius", "drop --rotor-radius '7.4 mm'", "--rotor-radius", "7.4 mm"),
    case("drop-race-mass-zero", "drop --race-mass '0 kg'", "--race-mass", "0 kg"),
    case("drop-line-stiffness-negative", "drop --line-stiffness -1", "--line-stiffness", "-1"),
    case("drop-kb-mass", "drop --ball-constant '1 kg'", "--ball-constant", "1 kg"),
    case("drop-gravity-negative", "drop --gravity '-9.81 m/s**2'", "--gravity", "-9.81 m/s**2"),
    case("drop-eccentricity-negative", "drop --eccentricity '-1 um'", "--eccentricity", "-1 um"),
    case("drop-eccentricity-beyond-clearance", "drop --eccentricity '1 m' --json", "--eccentricity", "1 m",
         expect="warning", note="issue: never finished; now a warning and the line-contact overload verdict"),
    case("drop-config-missing", "drop --config nofile.toml", "--config", "nofile.toml"),
    case("drop-config-folder", "drop --config adir.toml", "adir.toml",
         files=A_FOLDER, avoid=("not found",)),
    case("drop-bearing-unknown", "drop --bearing QJ999", "--bearing", "QJ999"),
    case("drop-machine-unknown", "drop --machine nomachine", "--machine", "nomachine"),
    case("drop-machine-folder", "drop --machine adir.toml", "--machine", "adir.toml",
         files=A_FOLDER, avoid=("not found",)),
    case("drop-machine-with-paper-option", "drop --machine paper_rig --friction 0.1", "--friction"),
    case("drop-machine-with-bearing", "drop --machine paper_rig --bearing 7202", "--bearing"),
    case("drop-machine-duration-zero", "drop --machine paper_rig --duration 0", "--duration", "0"),
    case("drop-machine-duration-text", "drop --machine paper_rig --duration abc", "--duration", "abc"),
    case("drop-machine-duration-budget", "drop --machine paper_rig --duration '1e5 s'", "--duration", "max_steps"),
    case("drop-out-empty", "drop --out ''", "--out"),
    case("drop-out-file", "drop --out afile", "--out", "afile", files=A_FILE),
    case("drop-out-below-file", "drop --out afile/x", "--out", "afile/x", files=A_FILE),
    case("drop-unknown-option", "drop --frction 0.1", "--frction"),
]

DROP_COMPARE = [
    case("compare-bearings-empty", "drop-compare --bearings ''", "--bearings"),
    case("compare-bearings-commas", "drop-compare --bearings ,,", "--bearings", ",,"),
    case("compare-bearings-unknown", "drop-compare --bearings QJ999", "--bearings", "QJ999"),
    case("compare-clearances-empty", "drop-compare --clearances ''", "--clearances"),
    case("compare-clearances-text", "drop-compare --clearances a,b", "--clearances", "a"),
    case("compare-clearances-negative", "drop-compare --clearances 0.1,-0.2", "--clearances", "-0.2"),
    case("compare-frictions-high", "drop-compare --frictions 0.1,2", "--frictions", "2"),
    case("compare-phases-text", "drop-compare --phases x", "--phases", "x"),
    case("compare-config-missing", "drop-compare --config nofile.toml", "--config", "nofile.toml"),
    case("compare-config-bearing", "drop-compare --config c.toml", "--config", "[bearing]",
         files={"c.toml": '[bearing]\ncatalogue = "7202"\n'},
         note="issue: drop-compare --config ignored the file's [bearing]"),
    case("compare-out-empty", "drop-compare --out ''", "--out"),
    case("compare-duration-zero", "drop-compare --duration 0", "--duration", "0"),
    case("compare-speed-text", "drop-compare --speed abc", "--speed", "abc"),
]

EXPERIMENT = [
    case("exp-measured-missing-option", "experiment", "--measured"),
    case("exp-measured-no-file", "experiment --measured nofile.csv", "--measured", "nofile.csv"),
    case("exp-measured-folder", "experiment --measured adir", "--measured", "adir", files={"adir/": ""},
         avoid=("not found",), note="a folder is not 'not found'"),
    case("exp-offset-three", "experiment --measured m.csv --offset a,b,c", "--offset", "a,b,c"),
    case("exp-offset-mass", "experiment --measured m.csv --offset '1 kg,2 um'", "--offset", "1 kg"),
    case("exp-scale-text", "experiment --measured m.csv --scale abc", "--scale", "abc"),
    case("exp-scale-zero", "experiment --measured m.csv --scale 0", "--scale", "0"),
    case("exp-scale-nan", "experiment --measured m.csv --scale nan", "--scale", "nan"),
    case("exp-cutoff-negative", "experiment --measured m.csv --cutoff '-5 Hz'", "--cutoff", "-5 Hz"),
    case("exp-cutoff-text", "experiment --measured m.csv --cutoff abc", "--cutoff", "abc"),
    case("exp-cutoff-mass", "experiment --measured m.csv --cutoff '8 kg'", "--cutoff", "8 kg"),
    case("exp-cutoff-huge-int", "experiment --measured m.csv --cutoff '10**400 Hz'", "--cutoff", "10**400 Hz"),
    case("exp-drop-time-text", "experiment --measured m.csv --drop-time abc", "--drop-time", "abc"),
    case("exp-drop-time-mass", "experiment --measured m.csv --drop-time '5 kg'", "--drop-time", "5 kg"),
    case("exp-clearance-negative", "experiment --measured m.csv --clearance '-1 mm'", "--clearance", "-1 mm"),
    case("exp-clearance-zero", "experiment --measured m.csv --clearance 0", "--clearance", "0"),
    case("exp-clearance-text", "experiment --measured m.csv --clearance abc", "--clearance", "abc"),
    case("exp-fit-window-zero", "experiment --measured m.csv --fit-window '0 ms'", "--fit-window", "0 ms"),
    case("exp-fit-window-negative", "experiment --measured m.csv --fit-window '-1 ms'", "--fit-window", "-1 ms"),
    case("exp-fit-window-text", "experiment --measured m.csv --fit-window abc", "--fit-window", "abc"),
    case("exp-unit-no-equals", "experiment --measured m.csv --unit x", "--unit", "x"),
    case("exp-unit-no-channel", "experiment --measured m.csv --unit =um", "--unit", "=um"),
    case("exp-unit-mass", "experiment --measured m.csv --unit x=kg", "--unit", "kg"),
    case("exp-unit-unknown-channel", "experiment --measured m.csv --unit q=um", "--unit", "q"),
    case("exp-bearing-unknown", "experiment --measured m.csv --bearing QJ999", "--bearing", "QJ999"),
    case("exp-config-missing", "experiment --measured m.csv --config nofile.toml", "--config", "nofile.toml"),
    case("exp-out-empty", "experiment --measured m.csv --out ''", "--out"),
    case("exp-out-file", "experiment --measured m.csv --out afile", "--out", "afile", files=A_FILE),
]

COASTDOWN = [
    case("coast-machine-missing-option", "coastdown", "--machine"),
    case("coast-machine-unknown", "coastdown --machine nomachine", "--machine", "nomachine"),
    case("coast-machine-folder", "coastdown --machine adir.toml", "--machine", "adir.toml",
         files=A_FOLDER, avoid=("not found",)),
    case("coast-duration-zero", "coastdown --machine paper_rig --duration 0", "--duration", "0"),
    case("coast-duration-text", "coastdown --machine paper_rig --duration abc", "--duration", "abc"),
    case("coast-duration-only", "coastdown --machine paper_rig --duration-only", "--duration-only"),
    case("coast-mode", "coastdown --machine paper_rig --mode foo", "--mode", "foo"),
    case("coast-out-empty", "coastdown --machine paper_rig --out ''", "--out"),
    case("coast-out-file", "coastdown --machine paper_rig --out afile", "--out", "afile", files=A_FILE),
]

STUDY = [
    case("study-config-missing", "study --config nofile.toml", "--config", "nofile.toml"),
    case("study-config-folder", "study --config adir.toml", "--config", "adir.toml",
         files=A_FOLDER, avoid=("not found",)),
    case("study-stage", "study --stage foo", "--stage", "foo"),
    case("study-out-empty", "study --out ''", "--out"),
    case("study-out-file", "study --out afile", "--out", "afile", files=A_FILE),
]

CAMPAIGN = [
    case("campaign-config-missing", "campaign --config nofile.toml --out s.zarr", "--config", "nofile.toml"),
    case("campaign-out-missing", "campaign --config c.toml", "--out", files={"c.toml": "[campaign]\n"}),
    case("campaign-workers-zero", "campaign --config c.toml --out s.zarr --workers 0", "--workers", "0",
         files={"c.toml": "[campaign]\n"}),
    case("campaign-workers-text", "campaign --config c.toml --out s.zarr --workers abc", "--workers", "abc",
         files={"c.toml": "[campaign]\n"}),
    case("campaign-out-empty", "campaign --config c.toml --out ''", "--out", files={"c.toml": "[campaign]\n"}),
    case("campaign-config-empty", "campaign --config c.toml --out s.zarr", "campaign",
         files={"c.toml": "[campaign]\n"}),
    case("report-store-missing", "campaign-report nostore.zarr --out r", "nostore.zarr"),
    case("report-store-file", "campaign-report afile --out r", "afile", files=A_FILE),
    case("report-out-empty", "campaign-report nostore.zarr --out ''", "--out"),
]

BUDGETS = [
    case("budget-sweep-points-zero", "contact-sweep --max-points 0", "--max-points", "0"),
    case("budget-sweep-points-text", "contact-sweep --max-points abc", "--max-points", "abc"),
    case("budget-sweep-points-small", "contact-sweep --max-points 10", "--max-points", "10"),
    case("budget-cases-zero", "static-cases --loads l.csv --max-cases 0", "--max-cases", "0",
         files={"l.csv": "radial [N]\n1000\n"}),
    case("budget-cases-small", "static-cases --loads l.csv --max-cases 1", "--max-cases", "1",
         files={"l.csv": "radial [N]\n1000\n2000\n"}),
    case("budget-wall-zero", "drop --max-wall-time 0", "--max-wall-time", "0"),
    case("budget-wall-text", "drop --max-wall-time abc", "--max-wall-time", "abc"),
    case("budget-wall-mass", "drop --max-wall-time '5 kg'", "--max-wall-time", "5 kg"),
    case("budget-contacts-zero", "drop --max-ball-contacts 0", "--max-ball-contacts", "0"),
    case("budget-contacts-small", "drop --max-ball-contacts 10", "--max-ball-contacts", "10"),
    case("budget-coast-contacts-small", "coastdown --machine paper_rig --max-ball-contacts 10", "--max-ball-contacts",
         "10"),
]

VERIFY = [
    case("verify-machine-missing-option", "verify", "--machine"),
    case("verify-machine-unknown", "verify --machine nomachine --out v", "--machine", "nomachine"),
    case("verify-machine-folder", "verify --machine adir.toml --out v", "adir.toml", files=A_FOLDER,
         avoid=("not found",)),
    case("verify-candidates-unknown", "verify --machine blower --candidates QJ999 --out v", "--candidates",
         "QJ999"),
    case("verify-candidates-empty", "verify --machine blower --candidates '' --out v", "--candidates"),
    case("verify-samples-negative", "verify --machine blower --campaign-samples -1 --out v", "--campaign-samples",
         "-1"),
    case("verify-workers-zero", "verify --machine blower --workers 0 --out v", "--workers", "0"),
    case("verify-out-empty", "verify --machine blower --out ''", "--out"),
    case("verify-out-file", "verify --machine blower --out afile", "--out", "afile", files=A_FILE),
]

SCENARIOS = [
    case("drop-scenario-without-machine", "drop --scenario power", "--scenario", "power"),
    case("drop-scenario-unknown", "drop --machine blower --scenario nope", "--scenario", "nope"),
]

MODES = [
    case("modes-speeds-text", "modes --machine blower --speeds abc", "--speeds", "abc"),
    case("modes-speeds-negative", "modes --machine blower --speeds '-100 rpm'", "--speeds", "-100 rpm"),
    case("modes-speeds-mass", "modes --machine blower --speeds '0, 5 kg'", "--speeds", "5 kg"),
    case("modes-speeds-empty", "modes --machine blower --speeds ','", "--speeds", ","),
    case("modes-points-one", "modes --machine blower --points 1", "--points", "1"),
    case("modes-machine-missing", "modes --machine nofile.toml", "--machine", "nofile.toml"),
    case("modes-out-file", "modes --machine blower --out afile", "--out", "afile", files=A_FILE),
    case("modes-json", "modes --machine blower --json", expect="ok"),
]

OTHERS = [
    case("top-unknown-command", "nocommand", "nocommand"),
    case("bearings-extra", "bearings extra", "extra"),
    case("machines-option", "machines --foo", "--foo"),
    case("bearings-json", "bearings --json", expect="ok"),
    case("machines-json", "machines --json", expect="ok"),
]

CASES = [*CONTACT, *SWEEP, *STATIC, *STATIC_CASES, *STATIC_STUDY, *DROP, *DROP_COMPARE, *EXPERIMENT, *COASTDOWN,
         *STUDY, *CAMPAIGN, *VERIFY, *BUDGETS, *MODES, *SCENARIOS,
         *OTHERS]


def _measured_placeholder(c):
    """The experiment cases need a file to name; the options fail before it is read."""
    if "m.csv" in c.args and not any(name == "m.csv" for name, _ in c.files):
        return replace(c, files=(*c.files, ("m.csv", "time [s], x [um], y [um]\n0, 0, 0\n")))
    return c


CASES = [_measured_placeholder(c) for c in CASES]


def test_ids_are_unique():
    ids = [c.id for c in CASES]
    assert len(ids) == len(set(ids))


#: Cases that fail in modules this suite's author may not change, with where the fix belongs (strict: once the
#: module is fixed the mark must go).
KNOWN: dict[str, str] = {}


@pytest.mark.parametrize("c", [pytest.param(c, marks=pytest.mark.xfail(reason=KNOWN[c.id], strict=True))
                               if c.id in KNOWN else c for c in CASES], ids=[c.id for c in CASES])
def test_bad_option(c, tmp_path):
    check_case(c, tmp_path)
