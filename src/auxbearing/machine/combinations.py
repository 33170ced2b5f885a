"""Values a machine file may hold one by one but no machine can have together, refused with both keys named.

Checked on every machine built (:func:`auxbearing.machine.model.machine_from_mapping`), so a campaign's sample
that lands on such a pair is an ``invalid_input`` record with the same sentence as the command line's.
"""

from __future__ import annotations

import math

from auxbearing.common.errors import InputError
from auxbearing.common.params import display_value
from auxbearing.machine.params import TABLES
from auxbearing.machine.stations.amb import check_levitation

#: Keys of ``[[touchdown]]`` that act only in a compliant mount (with ``mount_stiffness``).
MOUNT_KEYS = ("mount_damping", "mount_mass", "mount_deadband", "mount_stop", "stop_stiffness", "stop_damping",
              "mount_travel")
#: Keys of ``[[touchdown]]`` that act only where a collar meets the race face (with ``axial_clearance``).
FACE_KEYS = ("face_stiffness", "face_damping", "face_friction", "face_radius")
#: How far a candidate's bore may differ from the seat's, and its width and outside diameter exceed the
#: design's, before it no longer fits [m]: catalogue sizes are nominal, so equal sizes are equal to far
#: better than this; a micrometre is below any bore tolerance (ISO 492 normal class: 8 um at 18-30 mm).
SEAT_TOLERANCE = 1e-6


def typed(table: dict | None, key: str, param=None) -> object:
    """A value as the file wrote it (a unit-library quantity as text), or the default with "(default)"."""
    if table and key in table:
        value = table[key]
        return value if isinstance(value, (str, int, float)) else str(value)
    if param is None or param.default is None:
        return "none"
    return f"{display_value(param, param.default)} (default)"


def param_of(section: str, key: str):
    """The parameter-table row of ``[section] key`` (its unit, default and rule for a message)."""
    return TABLES[section][key]


def check_combinations(data: dict, machine) -> None:
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
    for i, bearing in enumerate(getattr(machine, "stations", ())):
        if getattr(bearing, "axial", False) and not machine.axial_free:
            raise InputError.for_field(f"amb.{i}.axis", "axial", "needs a rotor that moves axially: give a "
                                       "[[touchdown]] plane an axial_clearance (the collar that catches it)")
    # bearings too weak to levitate the rotor a scenario starts from: refused when the file is read, so a
    # verification stops before its first drop, not at its first levitated start
    check_levitation(machine)


def _check_requires(table: dict, keys: tuple[str, ...], anchor: str, k: int, why: str) -> None:
    if anchor in table:
        return
    for key in keys:
        if key in table:
            raise InputError.for_field(f"touchdown.{k}.{key}", typed(table, key), f"{why}; give touchdown.{k}."
                                       f"{anchor} too, or leave {key} out")


def _check_start(rotor: dict, table: dict, plane, machine, k: int) -> None:
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
    deadband = typed(table, "mount_deadband", param_of("touchdown", "mount_deadband"))
    if mount.mount_stop is not None and mount.mount_stop <= mount.mount_deadband:
        raise InputError.for_field(where + "mount_stop", typed(table, "mount_stop"), f"not beyond {where}"
                                   f"mount_deadband = {deadband!r}: the ring crosses the dead band before its "
                                   "spring engages, and a hard stop lies beyond that")
    if "mount_travel" not in table:
        return
    if mount.mount_stop is not None and mount.mount_travel <= mount.mount_stop:
        raise InputError.for_field(where + "mount_travel", typed(table, "mount_travel"), f"not beyond {where}"
                                   f"mount_stop = {typed(table, 'mount_stop')!r}: the run stops at mount_travel, so "
                                   "the ring would never reach its hard stop")
    if mount.mount_travel <= mount.mount_deadband:
        raise InputError.for_field(where + "mount_travel", typed(table, "mount_travel"), f"not beyond {where}"
                                   f"mount_deadband = {deadband!r}: the run stops at mount_travel, so the mount's "
                                   "spring would never engage")


def _check_coastdown(data: dict, machine) -> None:
    table = data.get("coastdown") or {}
    cd = machine.coastdown
    if cd.max_temperature <= cd.ambient_temperature:
        pair = [("max_temperature", "ambient_temperature"), ("ambient_temperature", "max_temperature")]
        key, other = pair[0] if "max_temperature" in table else pair[1]
        rule = ("not above" if key == "max_temperature" else "not below")
        raise InputError.for_field(f"coastdown.{key}", typed(table, key, param_of("coastdown", key)),
                                   f"{rule} coastdown.{other} = {typed(table, other, param_of('coastdown', other))!r}: "
                                   "every part starts at ambient, so the run would end as a thermal run-away before "
                                   "its first step")
    if "stop_speed" in table and cd.stop_speed >= abs(machine.rotor.speed):
        raise InputError.for_field("coastdown.stop_speed", typed(table, "stop_speed"), "not below rotor.speed = "
                                   f"{typed(data.get('rotor'), 'speed')!r}: the coast-down would be over before it "
                                   "began")
