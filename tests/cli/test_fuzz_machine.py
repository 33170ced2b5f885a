"""Fuzz table (issue 20): machine files on ``drop``, ``coastdown`` and ``verify``, class by class.

A machine file is one document: every command that reads one checks all of it, ``[criteria]``,
``[verify]``, ``[life]``, ``[[candidate]]`` and ``[campaign]`` included, before any work. The classes:

* the whole document on every command (a table ``drop`` does not use is still checked);
* a typed key that is close to an allowed one is named with it ("did you mean mount_damping?");
* values legal one by one but impossible together, refused in one line naming both keys;
* candidate bearings that do not fit the design's seat (bore, width, outside diameter);
* documents nested thousands of levels deep (one line naming the file, never a RecursionError);
* inputs that make the integration stiff, said before the run starts;
* legal extremes, which must end with a verdict or a reasoned refusal (``expect="verdict"``).

Cases that run a drop or a coast-down are marked slow; the refusals answer before any step.
"""

from __future__ import annotations

import pytest

from tests.cli.test_fuzz_harness import case, check_case


def machine(rotor: str = "", plane: str = "", tables: str = "", duration: str = "1 ms", bearing: str = "QJ202",
            clearance: str = "0.2 mm") -> str:
    """A one-plane QJ202 machine (1 ms drop) with lines added to [rotor] and [[touchdown]] and tables after."""
    return (f'[machine]\nname = "fuzz rig"\n\n[rotor]\nmass = "1.48 kg"\npolar_inertia = "3.88e-4 kg*m^2"\n'
            f'speed = "6000 rpm"\nunbalance = "10 um"\n{rotor}\n[[touchdown]]\nname = "A"\nbearing = "{bearing}"\n'
            f'radial_clearance = "{clearance}"\n{plane}\n[drop]\nduration = "{duration}"\n\n{tables}')


MOUNT = 'mount_stiffness = "2e7 N/m"\n'


def nested(depth: int, opener: str = "[", closer: str = "]", key: str = "x") -> str:
    """A key whose value is ``depth`` arrays (or inline tables) inside one another."""
    if opener == "{":
        return f"{key} = " + "{a = " * depth + "1" + "}" * depth + "\n"
    return f"{key} = " + opener * depth + "1" + closer * depth + "\n"


def on_every_command(case_id: str, text: str, *names: str) -> list:
    """The same file refused alike by drop, coastdown and verify (one document, one check)."""
    return [case(f"{case_id}-{command}", f"{command} --machine m.toml" + (" --out v" if command == "verify" else ""),
                 *names, files={"m.toml": text})
            for command in ("drop", "coastdown", "verify")]


WHOLE_DOCUMENT = [
    *on_every_command("doc-criteria-unknown", machine(tables="[criteria]\nmin_s00 = 2\n"), "criteria.min_s00"),
    *on_every_command("doc-criteria-temperature-mm", machine(tables='[criteria]\nmax_temperature = "120 mm"\n'),
                      "criteria.max_temperature", "120 mm"),
    *on_every_command("doc-criteria-negative", machine(tables="[criteria]\nmin_s0 = -2\n"), "criteria.min_s0", "-2"),
    *on_every_command("doc-verify-negative-count", machine(tables="[verify]\ncampaign_samples = -5\n"),
                      "verify.campaign_samples", "-5"),
    *on_every_command("doc-verify-fraction-count", machine(tables="[verify]\ncampaign_samples = 2.5\n"),
                      "verify.campaign_samples", "2.5"),
    *on_every_command("doc-verify-unknown", machine(tables='[verify]\nlow_sped = "1000 rpm"\n'),
                      "verify.low_sped", "low_speed"),
    *on_every_command("doc-life-negative", machine(tables="[life]\nrequired_drops = -3\n"), "life.required_drops",
                      "-3"),
    *on_every_command("doc-candidate-unknown-bearing", machine(tables='[[candidate]]\nbearing = "QJ999"\n'),
                      "candidate.0.bearing", "QJ999"),
    *on_every_command("doc-candidate-unknown-key", machine(tables='[[candidate]]\nbearng = "7202"\n'),
                      "candidate.0.bearng", "bearing"),
    case("doc-candidate-no-bearing", "drop --machine m.toml", "candidate.0.bearing",
         files={"m.toml": machine(tables='[[candidate]]\nname = "x"\n')}),
    case("doc-candidate-not-tables", "drop --machine m.toml", "candidate", files={"m.toml": "candidate = 5\n"
                                                                                           + machine()}),
    case("doc-campaign-unknown-key", "drop --machine m.toml", "campaign.samplez", "samples",
         files={"m.toml": machine(tables="[campaign]\nsamplez = 4\n")}),
    case("doc-campaign-bad-input", "coastdown --machine m.toml", "campaign.input.0.key", "rotor.speeed",
         files={"m.toml": machine(tables='[campaign]\nsamples = 4\n[[campaign.input]]\nkey = "rotor.speeed"\n'
                                         'distribution = "uniform"\nlow = "1000 rpm"\nhigh = "2000 rpm"\n')}),
    case("doc-table-typo", "drop --machine m.toml", "[criterion]", "criteria",
         files={"m.toml": machine(tables="[criterion]\nmin_s0 = 2\n")}),
    *on_every_command("doc-candidate-duplex-set", machine(tables='[[candidate]]\nbearing = "7202 DB"\n'),
                      "candidate.0", "7202 DB"),
    case("doc-touchdown-typo", "drop --machine m.toml", "touchdown.0.mount_dampng", "mount_damping",
         files={"m.toml": machine(plane=MOUNT + 'mount_dampng = "100 N*s/m"\n')}),
    case("doc-rotor-typo", "coastdown --machine m.toml", "rotor.unbalence", "unbalance",
         files={"m.toml": machine(rotor='unbalence = "1 um"\n')}),
    case("doc-machine-typo", "drop --machine m.toml", "machine.orientaton", "orientation",
         files={"m.toml": machine().replace('name = "fuzz rig"\n', 'name = "fuzz rig"\norientaton = "vertical"\n')}),
    case("doc-coastdown-typo", "coastdown --machine m.toml", "coastdown.ambient_temprature", "ambient_temperature",
         files={"m.toml": machine(tables='[coastdown]\nambient_temprature = "30 degC"\n')}),
    case("doc-coastdown-temperature-mm", "drop --machine m.toml", "coastdown.ambient_temperature", "30 mm",
         files={"m.toml": machine(tables='[coastdown]\nambient_temperature = "30 mm"\n')}),
    case("doc-criteria-not-table", "drop --machine m.toml", "criteria", files={"m.toml": "criteria = 5\n" + machine()}),
    case("doc-criteria-bare-number", "coastdown --machine m.toml", "criteria.amb_air_gap", "unit",
         files={"m.toml": machine(tables="[criteria]\namb_air_gap = 0.4\n")}),
]

COMBINATIONS = [
    case("combo-start-outside", "drop --machine m.toml", "rotor.start_x", "0.8 mm", "radial_clearance",
         files={"m.toml": machine(rotor='start_x = "0.8 mm"\n')},
         note="issue: began 0.8 mm inside the race with 0.5 MN and reported an overload"),
    case("combo-start-on-wall", "coastdown --machine m.toml", "rotor.start_y", "radial_clearance",
         files={"m.toml": machine(rotor='start_y = "-0.2 mm"\n')}),
    case("combo-start-diagonal", "drop --machine m.toml", "rotor.start_x", "radial_clearance",
         files={"m.toml": machine(rotor='start_x = "0.15 mm"\nstart_y = "0.15 mm"\n')}),
    case("combo-misalignment-outside", "drop --machine m.toml", "touchdown.0.misalignment_x", "radial_clearance",
         files={"m.toml": machine(plane='misalignment_x = "300 um"\n')}),
    case("combo-journal-beyond-bore", "drop --machine m.toml", "touchdown.0.journal_radius", "7.6 mm", "bore",
         files={"m.toml": machine(plane='journal_radius = "7.6 mm"\n')},
         note="issue: a journal larger than the bore ran 'ok'"),
    case("combo-journal-clearance-beyond-bore", "coastdown --machine m.toml", "touchdown.0.journal_radius",
         "radial_clearance", "bore", files={"m.toml": machine(plane='journal_radius = "7.45 mm"\n')}),
    case("combo-face-stiffness-no-axial", "drop --machine m.toml", "touchdown.0.face_stiffness", "axial_clearance",
         files={"m.toml": machine(plane='face_stiffness = "1e9 N/m"\n')}),
    case("combo-face-friction-no-axial", "coastdown --machine m.toml", "touchdown.0.face_friction",
         "axial_clearance", files={"m.toml": machine(plane="face_friction = 0.3\n")}),
    case("combo-axial-direction-no-axial", "drop --machine m.toml", "touchdown.0.axial_direction",
         "axial_clearance", files={"m.toml": machine(plane='axial_direction = "+z"\n')}),
    case("combo-mount-damping-no-mount", "drop --machine m.toml", "touchdown.0.mount_damping", "mount_stiffness",
         files={"m.toml": machine(plane='mount_damping = "100 N*s/m"\n')}),
    case("combo-mount-mass-no-mount", "coastdown --machine m.toml", "touchdown.0.mount_mass", "mount_stiffness",
         files={"m.toml": machine(plane='mount_mass = "0.5 kg"\n')}),
    case("combo-deadband-no-mount", "drop --machine m.toml", "touchdown.0.mount_deadband", "mount_stiffness",
         files={"m.toml": machine(plane='mount_deadband = "20 um"\n')}),
    case("combo-stop-no-mount", "drop --machine m.toml", "touchdown.0.mount_stop", "mount_stiffness",
         files={"m.toml": machine(plane='mount_stop = "50 um"\n')}),
    case("combo-stop-stiffness-no-mount", "drop --machine m.toml", "touchdown.0.stop_stiffness", "mount_stiffness",
         files={"m.toml": machine(plane='stop_stiffness = "1e9 N/m"\n')}),
    case("combo-travel-no-mount", "drop --machine m.toml", "touchdown.0.mount_travel", "mount_stiffness",
         files={"m.toml": machine(plane='mount_travel = "1 mm"\n')}),
    case("combo-stop-inside-deadband", "drop --machine m.toml", "touchdown.0.mount_stop", "20 um",
         "touchdown.0.mount_deadband", files={"m.toml": machine(
             plane=MOUNT + 'mount_deadband = "50 um"\nmount_stop = "20 um"\n')}),
    case("combo-stop-at-deadband", "coastdown --machine m.toml", "touchdown.0.mount_stop", "mount_deadband",
         files={"m.toml": machine(plane=MOUNT + 'mount_deadband = "50 um"\nmount_stop = "50 um"\n')}),
    case("combo-travel-inside-stop", "drop --machine m.toml", "touchdown.0.mount_travel", "mount_stop",
         files={"m.toml": machine(plane=MOUNT + 'mount_stop = "50 um"\nmount_travel = "0.02 mm"\n')}),
    case("combo-coast-max-below-ambient", "coastdown --machine m.toml", "coastdown.max_temperature", "10 degC",
         "coastdown.ambient_temperature", files={"m.toml": machine(tables='[coastdown]\nmax_temperature = '
                                                                          '"10 degC"\n')},
         note="issue: reported as thermal_runaway"),
    case("combo-coast-max-at-ambient", "drop --machine m.toml", "coastdown.max_temperature",
         "coastdown.ambient_temperature", files={"m.toml": machine(
             tables='[coastdown]\nmax_temperature = "40 degC"\nambient_temperature = "40 degC"\n')}),
    case("combo-coast-ambient-above-default-max", "coastdown --machine m.toml", "coastdown.ambient_temperature",
         "coastdown.max_temperature", files={"m.toml": machine(tables='[coastdown]\nambient_temperature = '
                                                                          '"200 degC"\n')}),
    case("combo-coast-speed-step-zero", "coastdown --machine m.toml", "coastdown.speed_step", "0",
         files={"m.toml": machine(tables="[coastdown]\nspeed_step = 0\n")}),
    case("combo-coast-stop-speed-above-speed", "coastdown --machine m.toml", "coastdown.stop_speed", "rotor.speed",
         files={"m.toml": machine(tables='[coastdown]\nstop_speed = "10000 rpm"\n')}),
    case("combo-criteria-temperature-below-ambient", "drop --machine m.toml", "criteria.max_temperature",
         "coastdown.ambient_temperature",
         files={"m.toml": machine(tables='[criteria]\nmax_temperature = "15 degC"\n')}),
    case("combo-verify-low-speed-above-speed", "coastdown --machine m.toml", "verify.low_speed", "rotor.speed",
         files={"m.toml": machine(tables='[verify]\nlow_speed = "7000 rpm"\n')}),
    case("combo-verify-low-speed-verify", "verify --machine m.toml --out v", "verify.low_speed", "rotor.speed",
         files={"m.toml": machine(tables='[verify]\nlow_speed = "7000 rpm"\n')}),
]

#: A 40 mm bore bearing in a 15 mm seat, a too wide and a too large one as inline tables.
_WIDE = ('[[candidate]]\nname = "wide"\n[candidate.bearing]\ntype = "four_point"\nball_diameter = "6 mm"\n'
         'pitch_diameter = "25.5 mm"\nball_count = 11\ninner_groove_ratio = 0.52\nouter_groove_ratio = 0.52\n'
         'contact_angle = "35 deg"\ndiametral_clearance = "0 mm"\nball_material = "GCr15"\nring_material = "GCr15"\n'
         'bore = "15 mm"\noutside_diameter = "35 mm"\nwidth = "{width}"\n')
CANDIDATES = [
    *on_every_command("cand-bore-too-large", machine(tables='[[candidate]]\nbearing = "QJ208"\n'), "candidate.0",
                      "QJ208", "bore"),
    case("cand-too-wide", "drop --machine m.toml", "candidate.0", "width",
         files={"m.toml": machine(tables=_WIDE.format(width="20 mm"))}),
    case("cand-too-large-outside", "coastdown --machine m.toml", "candidate.0", "outside_diameter",
         files={"m.toml": machine(tables=_WIDE.format(width="11 mm").replace('"35 mm"', '"40 mm"'))}),
    case("cand-option-bore-too-large", "verify --machine m.toml --candidates QJ208 --out v", "--candidates",
         "QJ208", "bore", files={"m.toml": machine()},
         note="needs verify to call auxbearing.machine.check.check_candidate_seat on --candidates"),
]

NESTING = [
    *on_every_command("nest-arrays", machine(rotor=nested(20000)), "m.toml", "nested"),
    case("nest-inline-tables", "drop --machine m.toml", "m.toml", "nested",
         files={"m.toml": machine(rotor=nested(20000, "{"))}),
    case("nest-moderate-arrays", "coastdown --machine m.toml", "m.toml", "nested",
         files={"m.toml": machine(tables="[criteria]\n" + nested(300, key="min_s0"))}),
    case("nest-bearing-file", "drop --machine m.toml", "b.toml", "nested",
         files={"m.toml": machine(bearing="b.toml"), "b.toml": "[bearing]\n" + nested(20000)}),
]

STIFF = [
    case("stiff-mount", "drop --machine m.toml", "touchdown.0.mount_stiffness", "stiff",
         files={"m.toml": machine(plane='mount_stiffness = "1e20 N/m"\n', duration="10 ms")}, expect="warning",
         note="issue: ran into the 600 s wall budget with nothing said"),
    case("stiff-hard-stop", "drop --machine m.toml", "touchdown.0.stop_stiffness", "stiff",
         files={"m.toml": machine(plane=MOUNT + 'mount_stop = "20 um"\nstop_stiffness = "1e22 N/m"\n',
                                  duration="10 ms")}, expect="warning"),
    case("stiff-mount-within-budget", "drop --machine m.toml --quiet", "touchdown.0.mount_stiffness", "stiff",
         files={"m.toml": machine(plane='mount_stiffness = "1e15 N/m"\n')}, expect="warning",
         note="stiff but within the step budget: said at the start, then run"),
    case("stiff-race-mass-paper", "drop --race-mass 1e-9 --duration 10ms", "--race-mass", "stiff", expect="warning"),
    case("stiff-race-mass-machine", "coastdown --machine m.toml --duration 1ms", "touchdown.0.race_mass", "stiff",
         files={"m.toml": machine(plane='race_mass = "1e-9 kg"\nrace_inertia = "1e-15 kg*m^2"\n')},
         expect="warning"),
]

#: Legal values at the edge of their range: a verdict, or a refusal that says why (exit 2, one line).
LEGAL = [
    case("legal-speed-zero", "drop --machine m.toml --quiet", files={"m.toml": machine().replace(
        '"6000 rpm"', '"0 rpm"')}, expect="verdict"),
    case("legal-speed-negative", "drop --machine m.toml --quiet", files={"m.toml": machine().replace(
        '"6000 rpm"', '"-6000 rpm"')}, expect="verdict"),
    case("legal-gravity-zero", "drop --machine m.toml --quiet", files={"m.toml": machine(
        tables="").replace('duration = "1 ms"', 'duration = "1 ms"\ngravity = "0 m/s^2"')}, expect="verdict"),
    case("legal-clearance-1um", "drop --machine m.toml --quiet", files={"m.toml": machine(clearance="1 um")},
         expect="verdict"),
    case("legal-start-near-wall", "drop --machine m.toml --quiet",
         files={"m.toml": machine(rotor='start_x = "0.199 mm"\n')}, expect="verdict"),
    case("legal-soft-mount", "drop --machine m.toml --quiet", files={"m.toml": machine(
        plane='mount_stiffness = "1 N/m"\n')}, expect="verdict"),
    case("legal-mount-deadband-large", "drop --machine m.toml --quiet", files={"m.toml": machine(
        plane=MOUNT + 'mount_deadband = "1 mm"\n')}, expect="verdict"),
    case("legal-unbalance-zero", "drop --machine m.toml --quiet", files={"m.toml": machine().replace(
        '"10 um"', '"0 um"')}, expect="verdict"),
    case("legal-max-steps-one", "drop --machine m.toml --quiet", files={"m.toml": machine().replace(
        'duration = "1 ms"', 'duration = "1 ms"\nmax_steps = 1')}, expect="verdict"),
    case("legal-coast-max-just-above-ambient", "coastdown --machine m.toml --duration 0.01 --quiet",
         files={"m.toml": machine(tables='[coastdown]\nmax_temperature = "20.001 degC"\n')}, expect="verdict"),
    case("legal-coast-speed-step-one", "coastdown --machine m.toml --duration 0.01 --quiet",
         files={"m.toml": machine(tables="[coastdown]\nspeed_step = 1\n")}, expect="verdict"),
    case("legal-coast-cold-ambient", "coastdown --machine m.toml --duration 0.01 --quiet",
         files={"m.toml": machine(tables='[coastdown]\nambient_temperature = "-73 degC"\n')}, expect="verdict"),
    case("legal-coast-stop-speed-just-below", "coastdown --machine m.toml --duration 0.5 --quiet",
         files={"m.toml": machine(tables='[coastdown]\nstop_speed = "5999 rpm"\n')}, expect="verdict"),
    case("legal-candidate-same-seat", "drop --machine m.toml --quiet",
         files={"m.toml": machine(tables='[[candidate]]\nbearing = "7202"\n')}, expect="verdict"),
    case("legal-verify-quick", "verify --machine m.toml --quick --campaign-samples 0 --no-recommendation --quiet "
         "--out v", files={"m.toml": machine(tables='[criteria]\namb_air_gap = "0.5 mm"\n')}, expect="verdict"),
]

#: Cases that fail in modules this suite's author may not change, with the change they need (strict: once made,
#: the mark must go).
KNOWN: dict[str, str] = {}

CASES = [*WHOLE_DOCUMENT, *COMBINATIONS, *CANDIDATES, *NESTING, *STIFF, *LEGAL]
#: Cases that run a drop, a coast-down or a verification (the rest answer before any step).
RUNS = {c.id for c in [*STIFF, *LEGAL]}


def test_ids_are_unique():
    from tests.cli.test_fuzz_commands import CASES as COMMAND_CASES
    from tests.cli.test_fuzz_files import CASES as FILE_CASES

    ids = [c.id for c in [*CASES, *COMMAND_CASES, *FILE_CASES]]
    assert len(ids) == len(set(ids))


def _marks(c) -> list:
    marks = [pytest.mark.slow] if c.id in RUNS else []
    if c.id in KNOWN:
        marks.append(pytest.mark.xfail(reason=KNOWN[c.id], strict=True))
    return marks


@pytest.mark.parametrize("c", [pytest.param(c, marks=_marks(c)) for c in CASES], ids=[c.id for c in CASES])
def test_machine_file(c, tmp_path):
    check_case(c, tmp_path)
