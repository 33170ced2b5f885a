"""``[[scenario]]``: what brings a levitated rotor onto its touchdown bearings, each a case of the drop and verify.

ISO 14839-5 names the conditions a touchdown bearing is designed for: the magnetic bearings losing power, one
axis or amplifier failing, a sensor failing, and overloads with the bearings on (a process surge or shock, a
blade lost, a shock on the base). Every scenario starts from the levitated state (:func:`auxbearing.machine.
stations.amb.levitated_state`) and strikes at its ``time``:

* ``power_loss``: every magnetic bearing loses its power (the coils discharge over ``decay_time``);
* ``axis_loss``: one axis (``axis`` x or y) of one bearing (``bearing``) loses its amplifier, the others go on;
* ``sensor_failure``: one bearing's sensor (``axis`` x, y or both) sticks at its reading or reads zero (``mode``);
* ``shock`` and ``step_load``: a force on the rotor at ``position`` (a half-sine pulse, a step);
* ``unbalance_step``: an unbalance ``amount`` appears at ``position`` (a blade lost);
* ``base_acceleration``: the housing accelerates (a half-sine pulse by default: a shock or a seismic event).

``restore_time`` (power_loss, axis_loss) brings the power back after that long: a re-levitation attempt.
``relevitate_within`` asks the verification to require the rotor back in levitation within that time of the
strike (a criterion of the scenario's case).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from auxbearing.common.errors import InputError
from auxbearing.common.params import Param, by_key, read_table
from auxbearing.machine.stations.load import PARAMS as LOAD_PARAMS
from auxbearing.machine.stations.load import Load, make_load, text_key

#: A scenario's case in a verification is named this prefix and the scenario's name.
SCENARIO_CASE = "scenario: "
FAILURES = ("power_loss", "axis_loss", "sensor_failure")
#: Overloads with the bearings on, and the kind of :mod:`auxbearing.core.load` each adds.
OVERLOADS = {"shock": "force", "step_load": "force", "unbalance_step": "unbalance",
             "base_acceleration": "base_acceleration"}
KINDS = (*FAILURES, *OVERLOADS)
#: Keys of each kind beside ``name``, ``kind``, ``time`` and ``relevitate_within``.
KIND_KEYS = {
    "power_loss": ("decay_time", "ride_through", "restore_time"),
    "axis_loss": ("bearing", "axis", "decay_time", "ride_through", "restore_time"),
    "sensor_failure": ("bearing", "axis", "mode"),
    "shock": ("position", "force", "direction", "duration", "shape"),
    "step_load": ("position", "force", "direction", "duration", "shape"),
    "unbalance_step": ("position", "amount", "phase"),
    "base_acceleration": ("acceleration", "direction", "duration", "shape"),
}
PARAMS: tuple[Param, ...] = (
    Param("scenario", "time", "time", 0.0, "ms", "nonnegative", "When the scenario strikes; levitated until then",
          "ours"),
    Param("scenario", "decay_time", "time", 0.0, "ms", "nonnegative",
          "power_loss, axis_loss: time constant of the coils' discharge (0: the forces vanish at once)", "ours"),
    Param("scenario", "ride_through", "time", 0.0, "ms", "nonnegative",
          "power_loss, axis_loss: the amplifiers go on this long after the supply is lost (their DC link, a UPS)",
          "ours: none"),
    Param("scenario", "restore_time", "time", None, "ms", "optional_positive",
          "power_loss, axis_loss: the power comes back this long after the strike (a re-levitation attempt)",
          "ours: never"),
    Param("scenario", "relevitate_within", "time", None, "ms", "optional_positive",
          "The verification requires the rotor levitated again within this time of the strike", "ours: not asked"),
)
TABLE = by_key(PARAMS, "scenario")
#: Keys every kind of scenario takes beside ``name`` and ``kind``.
COMMON_KEYS = ("time", "relevitate_within")
#: Every key a scenario can have with a unit, for the documentation: its own and its load's (ms from its time).
DOC_PARAMS = (*PARAMS, *(p._replace(section="scenario") for p in LOAD_PARAMS if p.key != "start"))
#: Default shape of each overload's pulse.
_SHAPES = {"shock": "half_sine", "step_load": "step", "unbalance_step": "step", "base_acceleration": "half_sine"}


@dataclass(frozen=True)
class Scenario:
    """What happens to a levitated machine (SI)."""

    name: str
    kind: str = "power_loss"
    time: float = 0.0
    decay_time: float = 0.0
    ride_through: float = 0.0
    restore_time: float | None = None
    relevitate_within: float | None = None
    bearing: str | None = None  #: axis_loss, sensor_failure: the bearing's name
    axis: str = "both"  #: x, y or both
    mode: str = "zero"  #: sensor_failure: stuck or zero
    load: Load | None = None  #: overloads: the load it adds

    @property
    def levitated(self) -> bool:
        """Whether the run starts levitated (all but a power loss at the drop itself)."""
        return not (self.kind == "power_loss" and self.time <= 0.0)

    @property
    def bearings_stay_on(self) -> bool:
        """Whether every magnetic bearing keeps working through the scenario (overloads, a sensor failure)."""
        return self.kind not in ("power_loss", "axis_loss")

    def failure_times(self, bearing) -> tuple[float, float, float, float, float, float]:
        """(fail x, fail y, restore, sensor fail x, sensor fail y, stuck) for the AMB row of ``bearing`` [s].

        An axial bearing's one axis takes the x slots (the kernel's convention) and answers to ``axis = "z"``.
        """
        never = math.inf
        restore = self.time + self.restore_time if self.restore_time is not None else never
        fail = self.time + self.ride_through
        if fail >= restore:  # the power is back before the amplifiers stop
            fail = never
        stuck = 1.0 if self.mode == "stuck" else 0.0
        mine = self.bearing is None or self.bearing == bearing.name
        first = ("z", "both") if bearing.axial else ("x", "both")
        if self.kind == "power_loss":
            return fail, fail, restore, never, never, stuck
        if self.kind == "axis_loss" and mine:
            return (fail if self.axis in first else never,
                    fail if self.axis in ("y", "both") else never, restore, never, never, stuck)
        if self.kind == "sensor_failure" and mine:
            return (never, never, never, self.time if self.axis in first else never,
                    self.time if self.axis in ("y", "both") else never, stuck)
        return never, never, never, never, never, stuck

    def shifted(self, centre: float) -> Scenario:
        """Positions from the file's coordinates to the mass centre's (rotor.matrices)."""
        if self.load is None or not self.load.on_rotor or centre == 0.0:
            return self
        return replace(self, load=replace(self.load, position=self.load.position - centre))

    def describe(self) -> dict:
        """The scenario's inputs with units in the keys, for files and reports."""
        out = {"name": self.name, "kind": self.kind, "time_ms": self.time * 1e3}
        if not self.bearings_stay_on:
            out["decay_time_ms"] = self.decay_time * 1e3
            out["ride_through_ms"] = self.ride_through * 1e3
            out["restore_after_ms"] = None if self.restore_time is None else self.restore_time * 1e3
        if self.kind in ("axis_loss", "sensor_failure"):
            out.update(bearing=self.bearing, axis=self.axis)
        if self.kind == "sensor_failure":
            out["mode"] = self.mode
        if self.load is not None:
            from auxbearing.machine.stations.load import describe

            out["load"] = {k: v for k, v in describe(self.load).items() if k not in ("kind", "name")}
        if self.relevitate_within is not None:
            out["relevitate_within_ms"] = self.relevitate_within * 1e3
        return out


def breakpoints(machine) -> tuple[float, ...]:
    """Times where the machine's right-hand side jumps or kinks: a scenario's strike and restore, a load's ends.

    The integrator lands a step on each, so no step straddles a short pulse.
    """
    from auxbearing.machine.stations import of_kind

    s = machine.active_scenario()
    times = {t for b in of_kind(machine.stations, "amb") for t in s.failure_times(b)[:5]}
    loads = (*of_kind(machine.stations, "load"), *((s.load,) if s.load is not None else ()))
    for load in loads:
        times.update((load.start, load.start + load.duration))
    return tuple(sorted(t for t in times if 0.0 < t < math.inf))


#: The drop of a machine with magnetic bearings but no scenario named: they fail at the drop, at once.
AT_THE_DROP = Scenario("power loss at the drop")


def read_scenarios(tables, bearings: tuple = ()) -> tuple[Scenario, ...]:
    """The ``[[scenario]]`` tables: each a case of the drop and of the verification (``bearings``: the AMBs)."""
    if tables is None:
        return ()
    if not isinstance(tables, list) or not all(isinstance(t, dict) for t in tables):
        raise InputError.for_field("scenario", tables, "give one [[scenario]] table per scenario")
    out = []
    names = [b.name for b in bearings]
    for i, table in enumerate(tables):
        where = f"scenario.{i}."
        table = dict(table)
        name, kind = table.pop("name", None), table.pop("kind", "power_loss")
        if not isinstance(name, str) or not name:
            raise InputError.for_field(where + "name", name, "every [[scenario]] needs a name")
        if kind not in KINDS:
            raise InputError.for_field(where + "kind", kind, f"must be one of {', '.join(KINDS)}")
        # the keys of every kind, then the kind's own; a failure's keys (decay_time, ...) are in TABLE too, for
        # their units, but belong to the failures alone: each key listed once, the others refused
        allowed = (*COMMON_KEYS, *KIND_KEYS[kind])
        for key in table:
            if key not in allowed:
                raise InputError.for_field(where + key, table[key], f"not a key of a {kind} scenario; its keys: "
                                           f"{', '.join(('name', 'kind', *allowed))}")
        if kind in FAILURES and not bearings:
            raise InputError.for_field(where + "kind", kind, "the machine has no [[amb]] to fail")
        text = {}
        if kind in ("axis_loss", "sensor_failure"):
            bearing = table.pop("bearing", None)
            if bearing not in names:
                raise InputError.for_field(where + "bearing", bearing, f"name one of the [[amb]] tables: "
                                           f"{', '.join(names)}")
            axial = next(b.axial for b in bearings if b.name == bearing)
            axes = ("z",) if axial else ("x", "y") if kind == "axis_loss" else ("x", "y", "both")
            default = "z" if axial else None if kind == "axis_loss" else "both"
            text.update(bearing=bearing, axis=text_key(table, "axis", where, axes, default))
            if kind == "sensor_failure":
                text["mode"] = text_key(table, "mode", where, ("stuck", "zero"), "zero")
        own = {k: table.pop(k) for k in list(table) if k in TABLE}
        values = read_table(own, TABLE, where)
        if kind in OVERLOADS:
            table.setdefault("shape", _SHAPES[kind])
            text["load"] = make_load(name, OVERLOADS[kind], table, where, values.get("time", 0.0))
        out.append(Scenario(name, kind, **values, **text))
        if any(s.name == name for s in out[:-1]):
            raise InputError.for_field(where + "name", name, "two scenarios of one name")
    return tuple(out)
