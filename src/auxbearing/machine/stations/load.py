"""``[[load]]``: a load on the rotor in time, a force, a sudden unbalance or an acceleration of the base.

Its kernel is :mod:`auxbearing.core.load`. A machine file's ``[[load]]`` tables act in every run (a known
process surge, a shock the machine must ride through); an overload ``[[scenario]]`` (shock, step_load,
unbalance_step, base_acceleration) adds one for its own case (:mod:`auxbearing.machine.scenario`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from auxbearing.common.dimensions import with_article
from auxbearing.common.errors import InputError
from auxbearing.common.params import Param, by_key, read_table
from auxbearing.core import load as kernel
from auxbearing.machine.params import AXIAL_POSITION

KIND = kernel.NAME
#: Keys of each kind of load, beside ``kind``, ``name``, ``start``, ``duration`` and ``shape``.
KIND_KEYS = {"force": ("position", "force", "direction"), "unbalance": ("position", "amount", "phase"),
             "base_acceleration": ("acceleration", "direction")}
PARAMS: tuple[Param, ...] = (
    Param(KIND, "position", "length", None, "mm", "finite", "force, unbalance: axial position on the rotor, "
          + AXIAL_POSITION, "required for those"),
    Param(KIND, "force", "force", None, "N", "nonnegative", "force: its magnitude (the peak of a half sine)",
          "required for a force"),
    Param(KIND, "direction", "angle", -math.pi / 2, "deg", "finite", "force, base_acceleration: its direction "
          "from +x towards +y (-90 deg: downward on a horizontal machine)", "ours"),
    Param(KIND, "amount", "unbalance", None, "g*mm", "nonnegative", "unbalance: U = m e that appears (a blade lost)",
          "required for an unbalance"),
    Param(KIND, "phase", "angle", 0.0, "deg", "finite", "unbalance: its direction at the drop's start, from +x",
          "ours"),
    Param(KIND, "acceleration", "acceleration", None, "m/s^2", "nonnegative",
          "base_acceleration: the housing's acceleration (the peak of a half sine)",
          "required for a base acceleration"),
    Param(KIND, "start", "time", 0.0, "ms", "nonnegative", "When the load starts", "ours"),
    Param(KIND, "duration", "time", None, "ms", "optional_positive",
          "How long it lasts (a step without it lasts to the end of the run; a half sine needs it)", "ours"),
)
TABLE = by_key(PARAMS, KIND)


@dataclass(frozen=True)
class Load:
    """A load on the rotor in time (SI): ``value`` is (F_x, F_y), (U, beta) or (a_x, a_y) by ``kind``."""

    name: str
    kind: str
    value_x: float
    value_y: float
    position: float = 0.0
    start: float = 0.0
    duration: float = math.inf
    shape: str = "step"
    KIND = KIND

    def row(self) -> tuple[float, ...]:
        """The kernel's row (:data:`auxbearing.core.load.FIELDS`)."""
        return (self.position, float(kernel.KINDS.index(self.kind)), self.value_x, self.value_y, self.start,
                self.duration, float(kernel.SHAPES.index(self.shape)))

    @property
    def on_rotor(self) -> bool:
        """Whether it acts at a point of the rotor (a base acceleration acts on every body)."""
        return self.kind != "base_acceleration"


def text_key(table: dict, key: str, where: str, allowed: tuple[str, ...], default: str) -> str:
    """A text key with a fixed list of values (popped from ``table``)."""
    value = table.pop(key, default)
    if value not in allowed:
        raise InputError.for_field(where + key, value, f"must be one of {', '.join(allowed)}")
    return value


def make_load(name: str, kind: str, table: dict, where: str, start: float = 0.0) -> Load:
    """A :class:`Load` of ``kind`` from its keys with units (``shape`` already popped into ``table['shape']``).

    ``start`` is added to the table's own ``start`` (a scenario strikes at its time).
    """
    table = dict(table)
    shape = text_key(table, "shape", where, kernel.SHAPES, "half_sine" if kind != "unbalance" else "step")
    allowed = (*KIND_KEYS[kind], "start", "duration")
    for key in table:
        if key not in allowed:
            raise InputError.for_field(where + key, table[key], f"not a key of {with_article(kind)} load; its keys: "
                                       f"{', '.join(('kind', 'shape', *allowed))}")
    values = read_table(table, TABLE, where)
    if kind != "base_acceleration" and "position" not in values:
        raise InputError(f"{where}position: missing; a {kind} load acts at a place on the rotor")
    if kind == "force":
        if "force" not in values:
            raise InputError(f"{where}force: missing; a force load needs its magnitude")
        angle = values.get("direction", TABLE["direction"].default)
        vx, vy = values["force"] * math.cos(angle), values["force"] * math.sin(angle)
    elif kind == "unbalance":
        if "amount" not in values:
            raise InputError(f"{where}amount: missing; an unbalance load needs its amount")
        vx, vy = values["amount"], values.get("phase", 0.0)
    else:
        if "acceleration" not in values:
            raise InputError(f"{where}acceleration: missing; a base acceleration needs its magnitude")
        angle = values.get("direction", TABLE["direction"].default)
        vx, vy = values["acceleration"] * math.cos(angle), values["acceleration"] * math.sin(angle)
    duration = values.get("duration", math.inf)
    if shape == "half_sine" and math.isinf(duration):
        raise InputError(f"{where}duration: missing; a half-sine pulse needs its duration")
    return Load(name, kind, vx, vy, values.get("position", 0.0), start + values.get("start", 0.0), duration, shape)


def read(tables) -> tuple[Load, ...]:
    """The ``[[load]]`` tables of a machine file (values with units; each kind's keys read by :func:`make_load`)."""
    from auxbearing.machine.stations import each_table

    return tuple(make_load(name, text_key(given, "kind", where, kernel.KINDS, "force"), given, where)
                 for where, name, given in each_table(tables, KIND, "load"))


def pack(loads, modal, n_modes: int, machine=None) -> kernel.Params:
    """The kernel's rows: the file's loads, then the active scenario's, with each mode's shape at them."""
    if machine is not None and machine.active_scenario().load is not None:
        loads = (*loads, machine.active_scenario().load)
    values = np.array([s.row() for s in loads], float).reshape(len(loads), len(kernel.FIELDS))
    shape_x, shape_y = np.zeros((len(loads), n_modes)), np.zeros((len(loads), n_modes))
    if n_modes:
        for i, s in enumerate(loads):
            if s.on_rotor:
                shape_x[i], shape_y[i] = modal.station_shapes(s.position, f"{KIND}.{i}.position")
    return kernel.Params(values, shape_x, shape_y)


def series(loads, journal, states=None, params=None, t=None, rotor_z=None) -> dict:
    """No series of its own: a load's value in time is its input."""
    return {}


def describe(s: Load) -> dict:
    """Inputs with units in the keys, for files and reports."""
    out = {"kind": KIND, "name": s.name, "load_kind": s.kind, "start_s": s.start,
           # a step that holds to the end of the run: said in words, not as a number
           "duration_s": s.duration if math.isfinite(s.duration) else "to the end of the run", "shape": s.shape}
    if s.kind == "force":
        out.update(position_m=s.position, force_N=math.hypot(s.value_x, s.value_y),
                   direction_deg=math.degrees(math.atan2(s.value_y, s.value_x)))
    elif s.kind == "unbalance":
        out.update(position_m=s.position, amount_g_mm=s.value_x * 1e6, phase_deg=math.degrees(s.value_y))
    else:
        out.update(acceleration_m_per_s2=math.hypot(s.value_x, s.value_y),
                   direction_deg=math.degrees(math.atan2(s.value_y, s.value_x)))
    return out
