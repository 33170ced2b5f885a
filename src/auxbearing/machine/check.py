"""A machine file checked whole, before any work: every table, every key, and what no machine can be.

A machine file is one document. Every command that reads one (``drop``, ``coastdown``, ``campaign``
through its machine, ``verify``) calls :func:`check_machine_document` on it before it computes
anything, so a file is accepted or refused alike whichever command reads it: a ``drop`` refuses a
``[criteria]`` table that ``verify`` would refuse, though the drop never judges by it.

What is checked, each as one :class:`~auxbearing.common.errors.InputError` line naming the key as written:

* every table and key (an unknown one is told the closest allowed name: "did you mean mount_damping?");
* every value against its unit and rule (:mod:`auxbearing.common.params`), the ``[criteria]``, ``[verify]``
  and ``[[candidate]]`` tables through the readers ``verify`` uses, a ``[campaign]`` table through the
  campaign's own reader;
* values legal one by one but impossible together (:func:`check_combinations`, named by both keys): a
  start outside a clearance, a journal larger than its bore, face or mount keys without the collar or
  mount they act through, a hard stop inside the dead band, a temperature limit at or below ambient;
* candidate bearings that do not fit the design's seat (:func:`check_candidate_seat`).

Before the run, :func:`stiffness_notes` says when a mount, a hard stop or a light race makes the
integration stiff: the explicit step it forces against the run's duration and the step budget.
"""

from __future__ import annotations

import math
from pathlib import Path
from typing import TYPE_CHECKING

from auxbearing.common.errors import InputError
from auxbearing.common.params import display_value, unknown

if TYPE_CHECKING:
    from auxbearing.machine.model import Machine

#: Tables of a machine file; a campaign file is a machine file whose ``[campaign]`` table is the campaign.
MACHINE_FILE_TABLES = ("machine", "rotor", "touchdown", "drop", "coastdown", "life", "criteria", "candidate",
                       "verify", "campaign")
#: Keys of ``[[touchdown]]`` that act only in a compliant mount (with ``mount_stiffness``).
MOUNT_KEYS = ("mount_damping", "mount_mass", "mount_deadband", "mount_stop", "stop_stiffness", "stop_damping",
              "mount_travel")
#: Keys of ``[[touchdown]]`` that act only where a collar meets the race face (with ``axial_clearance``).
FACE_KEYS = ("face_stiffness", "face_damping", "face_friction", "face_radius")
#: Keys of a ``[[candidate]]`` table.
CANDIDATE_KEYS = ("name", "bearing")
#: How far a candidate's bore may differ from the seat's, and its width and outside diameter exceed the
#: design's, before it no longer fits [m]: catalogue sizes are nominal, so equal sizes are equal to far
#: better than this; a micrometre is below any bore tolerance (ISO 492 normal class: 8 um at 18-30 mm).
SEAT_TOLERANCE = 1e-6


def check_machine_document(data: dict, name: str = "machine", base: Path | None = None, *,
                           campaign: bool = True) -> Machine:
    """Check every table of a machine file (module docstring) and return its machine.

    Parameters
    ----------
    data : dict
        The file's tables as read (values with units).
    name, base
        The machine's name when the file gives none, and the folder relative bearing files are read from.
    campaign : bool
        Check a ``[campaign]`` table through the campaign's reader too (the campaign's reader itself passes
        False: it checks that table).

    Examples
    --------
    >>> from auxbearing.machine.model import machine_table
    >>> data, name, base = machine_table("paper_rig")
    >>> check_machine_document({**data, "criteria": {"min_s00": 2}}, name)
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: criteria.min_s00 = 2: unknown key; allowed keys: ...; did you mean min_s0?
    """
    from auxbearing.common.io import MAX_TOML_DEPTH, nesting_depth
    from auxbearing.machine.model import machine_from_mapping
    from auxbearing.verify.cases import verify_settings
    from auxbearing.verify.criteria import read_criteria

    if not isinstance(data, dict):
        raise InputError.for_field("machine", data, "must be a TOML document of tables")
    depth = nesting_depth(data)
    if depth > MAX_TOML_DEPTH:
        raise InputError.for_field("machine", f"{depth} levels", "is nested too deeply (arrays or tables inside "
                                   f"one another); our files need at most {MAX_TOML_DEPTH}")
    check_tables(data, MACHINE_FILE_TABLES)
    for key in ("criteria", "verify"):
        if key in data and not isinstance(data[key], dict):
            raise InputError.for_field(key, data[key], "must be a table of keys")
    machine = machine_from_mapping(data, name, base)
    criteria = read_criteria(data.get("criteria"))
    settings = verify_settings(data)
    _check_judging(data, machine, criteria, settings)
    check_candidates(data, machine, name, base)
    if campaign and "campaign" in data:
        from auxbearing.campaign.config import campaign_from_mapping

        campaign_from_mapping(data, name, base, check_machine=False)
    return machine


def check_tables(data: dict, allowed: tuple[str, ...]) -> None:
    """Refuse a table that is not one of ``allowed``, with the closest allowed name."""
    for key in data:
        if key not in allowed:
            raise unknown(f"[{key}]", "table", key, allowed, "table")


# ----------------------------------------------------------------------------- values impossible together
def typed(table: dict | None, key: str, param=None) -> object:
    """A value as the file wrote it (a unit-library quantity as text), or the default with "(default)"."""
    if table and key in table:
        value = table[key]
        return value if isinstance(value, (str, int, float)) else str(value)
    if param is None or param.default is None:
        return "none"
    return f"{display_value(param, param.default)} (default)"


def _param(section: str, key: str):
    from auxbearing.machine.params import TABLES

    return TABLES[section][key]


def check_combinations(data: dict, machine: Machine) -> None:
    """Refuse values that are legal one by one but no machine can have together (both keys named).

    Called by :func:`auxbearing.machine.model.machine_from_mapping` on every machine it builds, so a campaign's
    sample that lands on such a pair is an ``invalid_input`` record with the same sentence.
    """
    rotor = data.get("rotor") or {}
    for k, (plane, table) in enumerate(zip(machine.planes, data.get("touchdown") or [], strict=False)):
        _check_requires(table, (*FACE_KEYS, "axial_direction"), "axial_clearance", k,
                        "acts only where a rotor collar meets the race face")
        _check_requires(table, MOUNT_KEYS, "mount_stiffness", k, "acts only in a compliant mount")
        _check_start(rotor, table, plane, machine, k)
        _check_journal(table, plane, k)
        if plane.mount is not None:
            _check_mount(table, plane, k)
    _check_coastdown(data, machine)


def _check_requires(table: dict, keys: tuple[str, ...], anchor: str, k: int, why: str) -> None:
    if anchor in table:
        return
    for key in keys:
        if key in table:
            raise InputError.for_field(f"touchdown.{k}.{key}", typed(table, key), f"{why}; give touchdown.{k}."
                                       f"{anchor} too, or leave {key} out")


def _check_start(rotor: dict, table: dict, plane, machine: Machine, k: int) -> None:
    r = machine.rotor
    mx, my = plane.misalignment
    offset = math.hypot(r.start_x - mx, r.start_y - my)
    if offset < plane.radial_clearance:
        return
    given = [key for key in ("start_x", "start_y") if key in rotor]
    if given:
        field = f"rotor.{given[0]}"
        value = typed(rotor, given[0])
        other = f" (rotor.{given[1]} = {typed(rotor, given[1])!r})" if len(given) > 1 else ""
    else:
        key = next(key for key in ("misalignment_x", "misalignment_y") if key in table)
        field, value, other = f"touchdown.{k}.{key}", typed(table, key), " (the bearing centre's offset)"
    raise InputError.for_field(field, value, f"the journal starts {offset * 1e3:.4g} mm from the centre of "
                               f"touchdown.{k} ({plane.name}){other}, not inside its radial_clearance = "
                               f"{typed(table, 'radial_clearance')!r}: a rotor let go by its magnetic bearings "
                               "starts inside every touchdown clearance")


def _check_journal(table: dict, plane, k: int) -> None:
    bore = plane.bearing.bore
    if "journal_radius" not in table or bore is None:
        return
    r, s = plane.journal_radius, plane.radial_clearance
    field = f"touchdown.{k}.journal_radius"
    if r >= 0.5 * bore:
        raise InputError.for_field(field, typed(table, "journal_radius"), f"the journal is not smaller than the "
                                   f"bore of its bearing {plane.bearing.name} (bore {bore * 1e3:g} mm, radius "
                                   f"{bore * 500:g} mm): it does not fit")
    if r + s > 0.5 * bore + SEAT_TOLERANCE:
        raise InputError.for_field(field, typed(table, "journal_radius"), f"with touchdown.{k}.radial_clearance = "
                                   f"{typed(table, 'radial_clearance')!r} the race bore would be "
                                   f"{(r + s) * 1e3:.4g} mm in radius, beyond the bore radius {bore * 500:g} mm of "
                                   f"bearing {plane.bearing.name}: the clearance is bore / 2 - journal_radius "
                                   "(leave journal_radius out to derive it)")


def _check_mount(table: dict, plane, k: int) -> None:
    mount = plane.mount
    where = f"touchdown.{k}."
    deadband = typed(table, "mount_deadband", _param("touchdown", "mount_deadband"))
    if mount.stop is not None and mount.stop <= mount.deadband:
        raise InputError.for_field(where + "mount_stop", typed(table, "mount_stop"), f"not beyond {where}"
                                   f"mount_deadband = {deadband!r}: the ring crosses the dead band before its "
                                   "spring engages, and a hard stop lies beyond that")
    if "mount_travel" not in table:
        return
    if mount.stop is not None and mount.travel <= mount.stop:
        raise InputError.for_field(where + "mount_travel", typed(table, "mount_travel"), f"not beyond {where}"
                                   f"mount_stop = {typed(table, 'mount_stop')!r}: the run stops at mount_travel, so "
                                   "the ring would never reach its hard stop")
    if mount.travel <= mount.deadband:
        raise InputError.for_field(where + "mount_travel", typed(table, "mount_travel"), f"not beyond {where}"
                                   f"mount_deadband = {deadband!r}: the run stops at mount_travel, so the mount's "
                                   "spring would never engage")


def _check_coastdown(data: dict, machine: Machine) -> None:
    table = data.get("coastdown") or {}
    cd = machine.coastdown
    if cd.max_temperature <= cd.ambient_temperature:
        pair = [("max_temperature", "ambient_temperature"), ("ambient_temperature", "max_temperature")]
        key, other = pair[0] if "max_temperature" in table else pair[1]
        rule = ("not above" if key == "max_temperature" else "not below")
        raise InputError.for_field(f"coastdown.{key}", typed(table, key, _param("coastdown", key)),
                                   f"{rule} coastdown.{other} = {typed(table, other, _param('coastdown', other))!r}: "
                                   "every part starts at ambient, so the run would end as a thermal run-away before "
                                   "its first step")
    if "stop_speed" in table and cd.stop_speed >= abs(machine.rotor.speed):
        raise InputError.for_field("coastdown.stop_speed", typed(table, "stop_speed"), "not below rotor.speed = "
                                   f"{typed(data.get('rotor'), 'speed')!r}: the coast-down would be over before it "
                                   "began")


def _check_judging(data: dict, machine: Machine, criteria: dict, settings: dict) -> None:
    """What ``verify`` judges by against the machine: a temperature limit above ambient, a low speed below the top."""
    ambient = machine.coastdown.ambient_temperature
    table = data.get("criteria") or {}
    if criteria["max_temperature"] <= ambient:
        coast = data.get("coastdown") or {}
        from auxbearing.verify.criteria import TABLE

        param = _param("coastdown", "ambient_temperature")
        if "max_temperature" in table or "ambient_temperature" not in coast:
            raise InputError.for_field("criteria.max_temperature", typed(table, "max_temperature",
                                                                          TABLE["max_temperature"]),
                                       f"not above coastdown.ambient_temperature = "
                                       f"{typed(coast, 'ambient_temperature', param)!r}: no bearing can stay below "
                                       "the temperature it starts at")
        raise InputError.for_field("coastdown.ambient_temperature", typed(coast, "ambient_temperature", param),
                                   f"not below criteria.max_temperature = "
                                   f"{typed(table, 'max_temperature', TABLE['max_temperature'])!r}: no bearing can "
                                   "stay below the temperature it starts at")
    verify = data.get("verify") or {}
    low = settings.get("low_speed")
    if low is not None and low >= abs(machine.rotor.speed):
        raise InputError.for_field("verify.low_speed", typed(verify, "low_speed"), "not below rotor.speed = "
                                   f"{typed(data.get('rotor'), 'speed')!r}: the low-speed drop is the slower one")
    if {"friction_low", "friction_high"} <= set(settings) and settings["friction_low"] > settings["friction_high"]:
        raise InputError.for_field("verify.friction_low", typed(verify, "friction_low"), "above verify.friction_high "
                                   f"= {typed(verify, 'friction_high')!r}")


# ----------------------------------------------------------------------------- candidates in the design's seat
def check_candidates(data: dict, design: Machine, name: str = "machine", base: Path | None = None) -> None:
    """Check the ``[[candidate]]`` tables: keys, bearing, fit in the design's seat, and the machine each makes."""
    specs = data.get("candidate")
    if specs is None:
        return
    if not isinstance(specs, list) or not all(isinstance(s, (dict, str)) for s in specs):
        raise InputError.for_field("candidate", specs, "give [[candidate]] tables, each with a bearing")
    from auxbearing.machine.model import machine_from_mapping
    from auxbearing.verify.designs import candidate_tables

    for i, spec in enumerate(specs):
        where = f"candidate.{i}"
        if isinstance(spec, dict):
            for key in spec:
                if key not in CANDIDATE_KEYS:
                    raise unknown(f"{where}.{key}", spec[key], key, CANDIDATE_KEYS)
            if "bearing" not in spec:
                raise InputError(f"{where}.bearing: missing; a [[candidate]] names its bearing")
            bearing_spec = spec["bearing"]
        else:
            bearing_spec = spec
        label = str(spec.get("name", bearing_spec)) if isinstance(spec, dict) and (
            "name" in spec or isinstance(bearing_spec, str)) else (bearing_spec if isinstance(spec, str) else
                                                                   "inline bearing")
        bearing = candidate_bearing(bearing_spec, f"{where}.bearing", base)
        check_candidate_seat(design, bearing, f"{where} = {label!r}")
        ((_, tables),) = candidate_tables(data, [spec if isinstance(spec, dict) else {"bearing": spec}])
        tables.pop("candidate", None)
        tables.pop("campaign", None)
        try:
            machine_from_mapping(tables, name, base)
        except InputError as err:
            raise InputError(f"{where} = {label!r}: in the design's seats: {err}") from None


def candidate_bearing(spec: object, field: str, base: Path | None = None):
    """The bearing a candidate names: a catalogue name, a bearing TOML file (relative to ``base``) or a table."""
    from auxbearing.bearings.geometry import bearing_from_mapping
    from auxbearing.machine.model import read_bearing_spec

    if isinstance(spec, dict):
        return bearing_from_mapping(spec, name=str(spec.get("name", "candidate")), prefix=field + ".")
    if not isinstance(spec, str) or not spec.strip():
        raise InputError.for_field(field, spec, "must be a catalogue bearing, a bearing TOML file or a table")
    return read_bearing_spec(spec.strip(), base, field)


def check_candidate_seat(design: Machine, bearing, where: str) -> None:
    """Refuse a candidate bearing that does not fit every seat of the design, naming ``where`` and the reason.

    A seat is where the design's bearing sits: the journal inside it (journal radius plus radial clearance
    is the bore the journal runs in), the housing around it (the design's outside diameter) and the axial
    room (its width). A candidate must have that bore (another bore means another journal: another rotor,
    not another bearing), an outside diameter and a width no larger than the design's. A size the design's
    bearing does not give is not checked; one the seat needs and the candidate does not give is refused.

    ``where`` names the candidate as the user gave it (``"candidate.0 = 'QJ208'"``,
    ``"--candidates = 'QJ208'"``).

    >>> from auxbearing.machine.model import read_machine
    >>> from auxbearing.bearings.catalogue import get_bearing
    >>> check_candidate_seat(read_machine("paper_rig"), get_bearing("7202"), "candidate.0 = '7202'")
    >>> check_candidate_seat(read_machine("paper_rig"), get_bearing("QJ208"), "candidate.0 = 'QJ208'")
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: candidate.0 = 'QJ208': its bore 40 mm does not fit the seat of touchdown.0 ...
    """
    sizes = {key: getattr(bearing, key, None) for key in ("bore", "outside_diameter", "width")}
    for k, plane in enumerate(design.planes):
        seat = f"the seat of touchdown.{k} ({plane.name})"
        bore = 2.0 * (plane.journal_radius + plane.radial_clearance)
        if sizes["bore"] is None:
            raise InputError(f"{where}: gives no bore, so its fit on the journal of {seat} cannot be checked; give "
                             "its bore")
        if abs(sizes["bore"] - bore) > SEAT_TOLERANCE:
            raise InputError(f"{where}: its bore {sizes['bore'] * 1e3:g} mm does not fit {seat}: the journal there "
                             f"runs in a {bore * 1e3:.4g} mm bore (journal radius {plane.journal_radius * 1e3:.4g} mm "
                             f"+ radial clearance {plane.radial_clearance * 1e3:.4g} mm); a candidate must take the "
                             "same journal, another bore is another rotor")
        for key, room in (("outside_diameter", "housing bore"), ("width", "axial room")):
            limit = getattr(plane.bearing, key, None)
            if limit is None:
                continue
            size = sizes[key]
            if size is None:
                raise InputError(f"{where}: gives no {key}, so its fit in the {room} of {seat} "
                                 f"({limit * 1e3:g} mm) cannot be checked; give its {key}")
            if size > limit + SEAT_TOLERANCE:
                raise InputError(f"{where}: its {key} {size * 1e3:g} mm is larger than the {room} of {seat}, "
                                 f"{limit * 1e3:g} mm (the design bearing {plane.bearing.name}'s {key}): it does "
                                 "not fit")


# ----------------------------------------------------------------------------- stiffness before the run
#: Stability limit of the Dormand-Prince 5(4) pair on the negative real axis, |h lambda| (Hairer, Norsett &
#: Wanner, Solving ODEs I, 2nd ed., Sec. II.10, Fig. 10.4: about 3.3): an overdamped mode lets an explicit
#: integration take steps of about this over its fast eigenvalue once it has decayed.
DOPRI5_STABILITY = 3.3
#: An oscillating mode, once excited (an impact rings a mount), is followed to the run's tolerance at about
#: this many radians of it per step (h omega); measured: a 1 ms drop on a 1e16 N/m mount (omega 8e8 rad/s)
#: took 8.0e5 steps, h omega = 1.0.
OSCILLATION_STEP = 1.0
#: A mode is stiff when the step it allows is this many times below the largest step of the run ...
STIFF_RATIO = 10.0
#: ... and it matters once the run it implies has this many steps (some seconds of integration).
STIFF_STEPS = 2e5
#: Exponent of the journal/race line contact, Q = K_l delta^(10/9) (Palmgren; source paper Eq. 19).
LINE_EXPONENT = 10.0 / 9.0


def mode_step(mass: float, stiffness: float, damping: float) -> float:
    """The step an explicit integration can take through the mode m x'' + c x' + k x = 0 [s].

    Overdamped, the fast real eigenvalue a + sqrt(a^2 - k/m) (a = c / 2m) bounds it by stability
    (:data:`DOPRI5_STABILITY`); underdamped, the oscillation at sqrt(k/m) bounds it by accuracy
    (:data:`OSCILLATION_STEP` radians a step).

    >>> round(mode_step(1.0, 100.0, 0.0), 6), round(mode_step(1.0, 0.0, 33.0), 6)
    (0.1, 0.1)
    """
    if mass <= 0.0:
        return 0.0
    a = damping / (2.0 * mass)
    disc = a * a - stiffness / mass
    if disc >= 0.0:
        rate = a + math.sqrt(disc)
        return DOPRI5_STABILITY / rate if rate > 0.0 else math.inf
    return OSCILLATION_STEP / math.sqrt(stiffness / mass)


def _modes(machine: Machine) -> list[tuple[str, str, float, str]]:
    """(key, what, the step it allows [s], when it acts) of the fast modes a plane brings."""
    g = machine.simulation.gravity
    load = max(machine.rotor.mass * max(g, 1.0) / len(machine.planes), 1e-3)
    out = []
    for k, p in enumerate(machine.planes):
        where = f"touchdown.{k}."
        race = p.race_mass
        out.append((where + "race_mass", f"the race of {race:.3g} kg on its ball-set damping ball_damping = "
                    f"{p.ball_damping:g} N*s/m", mode_step(race, 0.0, p.ball_damping), "throughout"))
        # the journal/race line contact at the rotor's weight: F = K_l d^(10/9), tangent stiffness (10/9) F / d
        depth = (load / p.line_stiffness) ** (1.0 / LINE_EXPONENT)
        contact = LINE_EXPONENT * load / depth
        out.append((where + "race_mass", f"the race of {race:.3g} kg on the journal contact ({contact:.3g} N/m at the "
                    f"rotor's weight, line_damping = {p.line_damping:g} N*s/m)",
                    mode_step(race, contact, p.line_damping), "while the journal touches the race"))
        m = p.mount
        if m is None:
            continue
        ring = m.mass
        out.append((where + "mount_stiffness", f"the mount ({m.stiffness:.3g} N/m, mount_damping = {m.damping:g} "
                    f"N*s/m) on a ring of {ring:.3g} kg", mode_step(ring, m.stiffness, m.damping + p.ball_damping),
                    "throughout" if m.deadband == 0.0 else "once the ring crosses its dead band"))
        if m.stop is not None:
            out.append((where + "stop_stiffness", f"the hard stop ({m.stop_stiffness:.3g} N/m) on a ring of "
                        f"{ring:.3g} kg", mode_step(ring, m.stop_stiffness + m.stiffness, m.stop_damping + m.damping),
                        "while the ring rests on its stop"))
    return out


def stiffness_notes(machine: Machine, duration: float | None = None, names: dict | None = None) -> list[str]:
    """Warnings for the inputs that make the integration stiff; a refusal when one cannot fit the step budget.

    Each fast mode (a race on its ball-set damping or on the journal contact, a ring in its mount or on its
    hard stop) lets an explicit integration take steps of :func:`mode_step` only.
    When that step is :data:`STIFF_RATIO` times below the run's largest step and the run would take more
    than :data:`STIFF_STEPS` steps at it, the run is stiff: said before it starts, with the step and the
    steps it implies over ``duration`` (default the machine's ``drop.duration``). When the steps exceed the
    step budget ``drop.max_steps``, the run could only end at its budget: refused (an
    :class:`~auxbearing.common.errors.InputError`). ``names`` maps a key (``touchdown.0.race_mass``) to how the
    user gave it (``--race-mass``).
    """
    sim = machine.simulation
    duration = sim.duration if duration is None else duration
    names = names or {}
    fastest: dict[str, tuple] = {}
    for mode in _modes(machine):  # one sentence per input: its fastest mode
        if mode[0] not in fastest or mode[2] < fastest[mode[0]][2]:
            fastest[mode[0]] = mode
    notes = []
    for key, what, step, when in fastest.values():
        steps = duration / step if step > 0.0 else math.inf
        if step * STIFF_RATIO > sim.max_step or steps < STIFF_STEPS:
            continue
        shown = names.get(key, key)
        sentence = (f"{shown}: {what} makes the integration stiff: explicit steps of about {step:.2g} s "
                    f"{when}, about {steps:.2g} steps for the {duration * 1e3:.4g} ms run")
        if steps > sim.max_steps:
            raise InputError(f"{sentence}, beyond the step budget drop.max_steps = {sim.max_steps:.3g}; such a run "
                             "could only end at its budget: give a stiffness, damping or mass a real part has, a "
                             "shorter run, or raise drop.max_steps")
        notes.append(sentence + f" (step budget drop.max_steps = {sim.max_steps:.3g})")
    return notes
