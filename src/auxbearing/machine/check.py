"""A machine file checked whole, before any work: every table, every key, and what no machine can be.

A machine file is one document. Every command that reads one (``drop``, ``coastdown``, ``campaign``
through its machine, ``verify``) calls :func:`check_machine_document` on it before it computes
anything, so a file is accepted or refused alike whichever command reads it: a ``drop`` refuses a
``[criteria]`` table that ``verify`` would refuse, though the drop never judges by it.

What is checked, each as one :class:`~auxbearing.common.errors.InputError` line naming the key as written:

* every table and key (an unknown one is told the closest allowed name: "did you mean mount_damping?");
* every value against its unit and rule (:mod:`auxbearing.common.params`), the ``[criteria]``, ``[verify]``
  and ``[[candidate]]`` tables through the readers ``verify`` uses (:mod:`auxbearing.machine.judging`); a
  ``[campaign]`` table is the campaign's to check (:func:`auxbearing.campaign.config.campaign_from_mapping`,
  which the command line calls on every machine file it reads: a room below the campaign does not import it);
* values legal one by one but impossible together (:func:`check_combinations`, named by both keys): a
  start outside a clearance, a journal larger than its bore, face or mount keys without the collar or
  mount they act through, a hard stop inside the dead band, a temperature limit the file writes at or below
  ambient or at or above the coast-down's run-away stop (its default is verify's to check);
* candidate bearings that do not fit the design's seat (:func:`check_candidate_seat`), are the design's own bearing
  or share a name (each named by the key the file writes: ``candidate.2.bearing``).

Before the run, :func:`stiffness_notes` says when a mount, a hard stop or a light race makes the
integration stiff: the explicit step it forces against the run's duration and the step budget.
"""

from __future__ import annotations

import math
from pathlib import Path

from auxbearing.common.errors import InputError
from auxbearing.common.params import unknown
from auxbearing.machine.combinations import SEAT_TOLERANCE, param_of, typed
from auxbearing.machine.judging import (
    CRITERIA_TABLE,
    MAX_CAMPAIGN_SAMPLES,
    VERIFY_TABLE,
    candidate_tables,
    read_criteria,
    verify_settings,
)
from auxbearing.machine.model import Machine, machine_from_mapping, read_bearing_spec
from auxbearing.machine.stations import TABLES as STATION_TABLES

#: Tables of a machine file; a campaign file is a machine file whose ``[campaign]`` table is the campaign.
MACHINE_FILE_TABLES = ("machine", "rotor", "unbalance", "touchdown", *STATION_TABLES, "scenario", "drop", "coastdown",
                       "life",
                       "criteria", "candidate", "verify", "campaign")
#: Keys of a ``[[candidate]]`` table.
CANDIDATE_KEYS = ("name", "bearing", "preload")


def check_machine_document(data: dict, name: str = "machine", base: Path | None = None) -> Machine:
    """Check every table of a machine file (module docstring) and return its machine.

    Parameters
    ----------
    data : dict
        The file's tables as read (values with units).
    name, base
        The machine's name when the file gives none, and the folder relative bearing files are read from.

    Examples
    --------
    >>> from auxbearing.machine.files import machine_table
    >>> data, name, base = machine_table("paper_rig")
    >>> check_machine_document({**data, "criteria": {"min_s00": 2}}, name)
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: criteria.min_s00 = 2: unknown key; allowed keys: ...; did you mean min_s0?
    """
    from auxbearing.common.io import MAX_TOML_DEPTH, nesting_depth

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
    return machine


def check_tables(data: dict, allowed: tuple[str, ...]) -> None:
    """Refuse a table that is not one of ``allowed``, with the closest allowed name."""
    for key in data:
        if key not in allowed:
            raise unknown(f"[{key}]", "table", key, allowed, "table")


def _check_judging(data: dict, machine: Machine, criteria: dict, settings: dict) -> None:
    """What ``verify`` judges by against the machine: a temperature limit above ambient, a low speed below the top.

    The temperature limit is checked here only when the file writes it: its default is verify's alone, and a
    ``drop`` or ``coastdown`` of a machine whose ambient lies above that default (a hot process) never judges by it;
    ``verify`` checks it in every case (:func:`check_temperature_criterion`).
    """
    if "max_temperature" in (data.get("criteria") or {}):
        check_temperature_criterion(data, machine, criteria)
    verify = data.get("verify") or {}
    low = settings.get("low_speed")
    if low is not None and low >= abs(machine.rotor.speed):
        raise InputError.for_field("verify.low_speed", typed(verify, "low_speed"), "not below rotor.speed = "
                                   f"{typed(data.get('rotor'), 'speed')!r}: the low-speed drop is the slower one")
    if {"friction_low", "friction_high"} <= set(settings) and settings["friction_low"] > settings["friction_high"]:
        # blame the end the file gives (the other may be the default), quoting the other as it stands
        low, high = (typed(verify, key, VERIFY_TABLE[key]) for key in ("friction_low", "friction_high"))
        if "friction_low" in verify:
            raise InputError.for_field("verify.friction_low", low, f"above verify.friction_high = {high!r}")
        raise InputError.for_field("verify.friction_high", high, f"below verify.friction_low = {low!r}")
    samples = settings.get("campaign_samples")
    if samples is not None and not (samples == int(samples) and 0 <= samples <= MAX_CAMPAIGN_SAMPLES):
        raise InputError.for_field("verify.campaign_samples", typed(verify, "campaign_samples"),
                                   f"must be a whole number in [0, {MAX_CAMPAIGN_SAMPLES}] (0: no campaign)")
    tol = settings.get("clearance_tolerance")
    if tol is not None and machine.planes:
        k, plane = min(enumerate(machine.planes), key=lambda item: item[1].radial_clearance)
        if tol >= 0.5 * plane.radial_clearance:
            # the campaign keeps a clearance as made at half the file's or more (verify.cases.campaign_spreads)
            raise InputError.for_field("verify.clearance_tolerance", typed(verify, "clearance_tolerance"),
                                       f"must be below half the smallest radial clearance, touchdown.{k}."
                                       f"radial_clearance = {typed(_touchdown_table(data, k), 'radial_clearance')!r} "
                                       f"(half: {0.5 * plane.radial_clearance * 1e3:.4g} mm): the campaign's spread "
                                       "of the clearance would be cut off there")


def _touchdown_table(data: dict, k: int) -> dict | None:
    tables = data.get("touchdown") or []
    return tables[k] if k < len(tables) and isinstance(tables[k], dict) else None


def check_temperature_criterion(data: dict, machine: Machine, criteria: dict) -> None:
    """Refuse a ``criteria.max_temperature`` (written or its default) no coast-down of this machine can be judged by.

    At or below ``coastdown.ambient_temperature`` no bearing can stay under it; at or above
    ``coastdown.max_temperature`` the coast-down stops as a thermal run-away before any part gets there, so the
    criterion would never be checked and the run-away would fail the design on the model's range instead. Each
    refusal names the key the file writes (the other is quoted, "(default)" if the file leaves it out).
    """
    table = data.get("criteria") or {}
    coast = data.get("coastdown") or {}
    limit = criteria["max_temperature"]
    shown = typed(table, "max_temperature", CRITERIA_TABLE["max_temperature"])
    written = "max_temperature" in table
    for key, value, rule, why in (
            ("ambient_temperature", machine.coastdown.ambient_temperature, "above",
             "no bearing can stay below the temperature it starts at"),
            ("max_temperature", machine.coastdown.max_temperature, "below",
             "the coast-down stops there as a thermal run-away, so the temperature criterion could never be checked")):
        if (limit > value) if rule == "above" else (limit < value):
            continue
        other = typed(coast, key, param_of("coastdown", key))
        if written or key not in coast:
            raise InputError.for_field("criteria.max_temperature", shown,
                                       f"not {rule} coastdown.{key} = {other!r}: {why}")
        raise InputError.for_field(f"coastdown.{key}", other, f"not {'below' if rule == 'above' else 'above'} "
                                   f"criteria.max_temperature = {shown!r}: {why}")


# ----------------------------------------------------------------------------- candidates in the design's seat
def check_candidates(data: dict, design: Machine, name: str = "machine", base: Path | None = None) -> None:
    """Check the ``[[candidate]]`` tables: keys, bearing, fit in the design's seat, and the machine each makes."""
    specs = data.get("candidate")
    if specs is None:
        return
    if not isinstance(specs, list) or not all(isinstance(s, (dict, str)) for s in specs):
        raise InputError.for_field("candidate", specs, "give [[candidate]] tables, each with a bearing")

    seen: dict[str, str] = {}
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
        # messages name the key the user wrote, not the candidate's name: the bearing is what decides its fit
        named = candidate_key(where, spec)
        labelled = f"{where}.name" if isinstance(spec, dict) and "name" in spec else named
        if label in seen:  # a ranking and a report that cannot tell two rows apart
            raise InputError.for_field(labelled, label, f"the same as {seen[label]}: each candidate once")
        seen[label] = labelled
        bearing = candidate_bearing(bearing_spec, f"{where}.bearing", base)
        check_candidate_seat(design, bearing, named)
        ((_, tables),) = candidate_tables(data, [spec if isinstance(spec, dict) else {"bearing": spec}])
        tables.pop("candidate", None)
        tables.pop("campaign", None)
        try:
            candidate = machine_from_mapping(tables, name, base)
        except InputError as err:
            raise InputError(f"{named}: in the design's seats: {err}") from None
        check_not_the_design(design, candidate, named)


def candidate_key(where: str, spec: object) -> str:
    """How a message names a candidate's bearing as the user wrote it: ``candidate.2.bearing = '6308'``.

    >>> candidate_key("candidate.2", {"name": "6208 deep groove", "bearing": "6308"})
    "candidate.2.bearing = '6308'"
    >>> candidate_key("candidate.0", {"bearing": {"type": "four_point"}})
    'candidate.0.bearing (a table)'
    """
    bearing = spec.get("bearing") if isinstance(spec, dict) else spec
    key = f"{where}.bearing" if isinstance(spec, dict) else where
    return f"{key} = {bearing!r}" if isinstance(bearing, str) else f"{key} (a table)"


def _plain(unit):
    """A bearing (or matched pair) with its name and source blanked: two spellings of one bearing compare equal."""
    from dataclasses import fields, replace

    names = {f.name for f in fields(unit)}
    blank = {key: "" for key in ("name", "source") if key in names}
    if "row" in names:
        blank["row"] = _plain(unit.row)
    return replace(unit, **blank)


def check_not_the_design(design: Machine, candidate: Machine, where: str) -> None:
    """Refuse a candidate whose bearing is the design's own on every plane: the design is ranked already."""
    if all(_plain(c.unit) == _plain(d.unit) for c, d in zip(candidate.planes, design.planes, strict=True)):
        raise InputError(f"{where}: the design's own bearing on every plane; the design is verified and ranked "
                         "already: give another bearing")


def candidate_bearing(spec: object, field: str, base: Path | None = None):
    """The bearing a candidate names: a catalogue name, a bearing TOML file (relative to ``base``) or a table."""
    from auxbearing.bearings.geometry import bearing_from_mapping

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

    ``where`` names the candidate as the user gave it (``"candidate.0.bearing = 'QJ208'"``,
    ``"--candidates = 'QJ208'"``).

    >>> from auxbearing.machine.files import read_machine
    >>> from auxbearing.bearings.catalogue import get_bearing
    >>> check_candidate_seat(read_machine("paper_rig"), get_bearing("7202"), "candidate.0.bearing = '7202'")
    >>> check_candidate_seat(read_machine("paper_rig"), get_bearing("QJ208"), "candidate.0.bearing = 'QJ208'")
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: candidate.0.bearing = 'QJ208': its bore 40 mm does not fit ...
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
            limit = getattr(plane.unit, key, None)
            if key == "width" and plane.axial_room is not None:
                limit = plane.axial_room
            if limit is None:
                continue
            size = sizes[key]
            if size is None:
                raise InputError(f"{where}: gives no {key}, so its fit in the {room} of {seat} "
                                 f"({limit * 1e3:g} mm) cannot be checked; give its {key}")
            if size > limit + SEAT_TOLERANCE:
                given = (f"touchdown.{k}.axial_room" if key == "width" and plane.axial_room is not None
                         else f"the design bearing {plane.unit.name}'s {key}")
                raise InputError(f"{where}: its {key} {size * 1e3:g} mm is larger than the {room} of {seat}, "
                                 f"{limit * 1e3:g} mm ({given}): it does not fit")


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
        ring = m.mount_mass
        out.append((where + "mount_stiffness", f"the mount ({m.mount_stiffness:.3g} N/m, mount_damping = "
                    f"{m.mount_damping:g} N*s/m) on a ring of {ring:.3g} kg",
                    mode_step(ring, m.mount_stiffness, m.mount_damping + p.ball_damping),
                    "throughout" if m.mount_deadband == 0.0 else "once the ring crosses its dead band"))
        if m.mount_stop is not None:
            out.append((where + "stop_stiffness", f"the hard stop ({m.stop_stiffness:.3g} N/m) on a ring of "
                        f"{ring:.3g} kg", mode_step(ring, m.stop_stiffness + m.mount_stiffness,
                                                    m.stop_damping + m.mount_damping),
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
