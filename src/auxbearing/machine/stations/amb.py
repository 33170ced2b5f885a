"""``[[amb]]``: an active magnetic bearing station (the ``[[scenario]]`` tables: :mod:`auxbearing.machine.scenario`).

Its kernel is :mod:`auxbearing.core.amb` (force law, sensor, PID controller, amplifier). A drop starts at the
levitated static state the model computes itself (:func:`levitated_state`) and the magnetic bearings work
until the scenario's time; without a scenario they fail at the drop (t = 0), which is the drop from the centre.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from auxbearing.common.errors import InputError
from auxbearing.common.params import Param, by_key
from auxbearing.core import amb as kernel

KIND = kernel.NAME
PARAMS: tuple[Param, ...] = (
    Param(KIND, "position", "length", None, "mm", "finite", "Axial position of the actuator from the mass centre; "
          "with rotor.matrices, the coordinate of one of the matrices' nodes", "required"),
    Param(KIND, "sensor_position", "length", None, "mm", "finite",
          "Axial position of the displacement sensor; default the actuator's (collocated)", "ours"),
    Param(KIND, "current_stiffness", "current_stiffness", None, "N/A", "positive",
          "Force per control current k_i at the bias", "the bearing's data"),
    Param(KIND, "position_stiffness", "stiffness", 0.0, "N/m", "nonnegative",
          "Negative stiffness k_s of the bias flux (F = k_i i + k_s x, k_s > 0 destabilising)", "the bearing's data"),
    Param(KIND, "kp", "current_per_length", None, "A/m", "positive", "Proportional gain (i = -(kp x + ki int x + "
          "kd dx/dt))", "the controller's data"),
    Param(KIND, "ki", "current_per_length_time", 0.0, "A/(m*s)", "nonnegative", "Integral gain",
          "the controller's data"),
    Param(KIND, "kd", "current_time_per_length", 0.0, "A*s/m", "nonnegative", "Derivative gain",
          "the controller's data"),
    Param(KIND, "sensor_bandwidth", "frequency", 5000.0, "Hz", "positive", "Bandwidth of the sensor (first order)",
          "ours: a typical eddy-current sensor's 5-20 kHz"),
    Param(KIND, "amplifier_bandwidth", "frequency", 1000.0, "Hz", "positive",
          "Current bandwidth of the amplifier (first order)", "ours: a typical switching amplifier's 1-3 kHz"),
    Param(KIND, "max_current", "current", math.inf, "A", "positive", "Largest control current the amplifier gives",
          "ours: none unless given"),
)
TABLE = by_key(PARAMS, KIND)


@dataclass(frozen=True)
class MagneticBearing:
    """An AMB station (SI)."""

    name: str
    position: float
    current_stiffness: float
    kp: float
    sensor_position: float | None = None
    position_stiffness: float = 0.0
    ki: float = 0.0
    kd: float = 0.0
    sensor_bandwidth: float = 5000.0
    amplifier_bandwidth: float = 1000.0
    max_current: float = math.inf
    KIND = KIND

    @property
    def sensor(self) -> float:
        """Where the sensor reads [m]."""
        return self.position if self.sensor_position is None else self.sensor_position

    def closed_loop_stiffness(self) -> float:
        """k_i k_p - k_s: the PD law's static stiffness with ideal sensor and amplifier [N/m]."""
        return self.current_stiffness * self.kp - self.position_stiffness


def read(tables) -> tuple[MagneticBearing, ...]:
    """The ``[[amb]]`` tables of a machine file (values with units)."""
    from auxbearing.machine.stations import read_tables

    out = []
    for where, name, values, table in read_tables(tables, KIND, TABLE, ("position", "current_stiffness", "kp"),
                                                  "AMB"):
        bearing = MagneticBearing(name=name, **values)
        if bearing.closed_loop_stiffness() <= 0.0:
            raise InputError.for_field(where + "kp", table.get("kp"), "too small to hold the rotor: kp "
                                       "current_stiffness must exceed position_stiffness "
                                       f"({bearing.position_stiffness:g} N/m)")
        out.append(bearing)
    return tuple(out)


def pack(bearings, modal, n_modes: int, machine=None) -> kernel.Params:
    """The kernel's parameters: shapes at the actuators and sensors, the failures from the active scenario."""
    from auxbearing.machine.scenario import AT_THE_DROP

    scenario = machine.active_scenario() if machine is not None else AT_THE_DROP
    rows = []
    for b in bearings:
        fail_x, fail_y, restore, sensor_x, sensor_y, stuck = scenario.failure_times(b.name)
        rows.append((b.position, b.sensor, b.current_stiffness, b.position_stiffness, b.kp, b.ki, b.kd,
                     2 * math.pi * b.sensor_bandwidth, 2 * math.pi * b.amplifier_bandwidth, b.max_current, fail_x,
                     fail_y, scenario.decay_time, restore, sensor_x, sensor_y, stuck))
    values = np.array(rows, float).reshape(len(bearings), len(kernel.FIELDS))
    shapes = [np.zeros((len(bearings), n_modes)) for _ in range(4)]
    if n_modes:
        for i, b in enumerate(bearings):
            shapes[0][i], shapes[1][i] = modal.station_shapes(b.position, f"{KIND}.{i}.position")
            shapes[2][i], shapes[3][i] = modal.station_shapes(b.sensor, f"{KIND}.{i}.sensor_position")
    return kernel.Params(values, *shapes)


def series(bearings, journal, states) -> dict:
    """Each bearing's coil currents over a run (``states(i)``: its states on the run's grid, kernel order)."""
    if not bearings:
        return {}
    x = np.stack([states(i)[:, kernel.S_CURRENT] for i in range(len(bearings))], axis=1)
    y = np.stack([states(i)[:, 3 + kernel.S_CURRENT] for i in range(len(bearings))], axis=1)
    return {"amb_current_x": (("time", "amb"), x, {"units": "A", "long_name": "Magnetic bearing's control current, x"}),
            "amb_current_y": (("time", "amb"), y, {"units": "A", "long_name": "Magnetic bearing's control current, y"}),
            "amb": ("amb", [b.name for b in bearings], {})}


def describe(b: MagneticBearing) -> dict:
    """Inputs with units in the keys, for files and reports."""
    return {"kind": KIND, "name": b.name, "position_m": b.position, "sensor_position_m": b.sensor,
            "current_stiffness_N_per_A": b.current_stiffness, "position_stiffness_N_per_m": b.position_stiffness,
            "kp_A_per_m": b.kp, "ki_A_per_m_s": b.ki, "kd_A_s_per_m": b.kd, "sensor_bandwidth_Hz": b.sensor_bandwidth,
            "amplifier_bandwidth_Hz": b.amplifier_bandwidth, "max_current_A": b.max_current,
            "closed_loop_stiffness_N_per_m": b.closed_loop_stiffness()}


def levitated_state(machine, modal, bearings) -> dict:
    """The static state of the rotor held by its magnetic bearings: the linear statics of the model.

    Unknowns: the rotor's coordinates q (x, y, theta_x, theta_y and the elastic modes) and, for a bearing with
    integral action, its steady currents (its sensor then reads zero); without integral action the current is
    -k_p times the sensor's reading. Forces: gravity, the constant process forces and the linear supports; the
    touchdown planes are clear. Returns q and each bearing's (measured, integral, current) for x and y.
    """
    r = machine.rotor
    n = 4 + (modal.n_modes if modal is not None else 0)
    g = machine.simulation.gravity
    gravity = (0.0, -g) if machine.orientation == "horizontal" else (0.0, 0.0)

    def rows(position, key):
        bx, by = np.zeros(n), np.zeros(n)
        bx[0], bx[3], by[1], by[2] = 1.0, position, 1.0, -position
        if n > 4:
            bx[4:], by[4:] = modal.station_shapes(position, key)
        return bx, by

    stiff = np.zeros((n, n))
    if n > 4:
        stiff[4:, 4:] = np.diag(modal.frequencies ** 2)
    for i, s in enumerate(getattr(machine, "stations", ())):
        if s.KIND != "linear_support":
            continue
        bx, by = rows(s.position, f"linear_support.{i}.position")
        b = np.vstack([bx, by])
        stiff += b.T @ np.array([[s.kxx, s.kxy], [s.kyx, s.kyy]]) @ b
    force = np.zeros(n)
    force[0] = r.mass * gravity[0] + r.side_force_x
    force[1] = r.mass * gravity[1] + r.side_force_y
    integral = [b for b in bearings if b.ki > 0.0]
    size = n + 2 * len(integral)
    a, rhs = np.zeros((size, size)), np.zeros(size)
    a[:n, :n] = stiff
    rhs[:n] = force
    extra = n
    for i, b in enumerate(bearings):
        act, sense = rows(b.position, f"{KIND}.{i}.position"), rows(b.sensor, f"{KIND}.{i}.sensor_position")
        for axis in range(2):
            a[:n, :n] -= b.position_stiffness * np.outer(act[axis], act[axis])
            if b.ki > 0.0:
                a[:n, extra] -= b.current_stiffness * act[axis]  # the unknown steady current
                a[extra, :n] = sense[axis]  # the sensor reads zero
                extra += 1
            else:
                a[:n, :n] += b.current_stiffness * b.kp * np.outer(act[axis], sense[axis])
    locked = () if machine.tilt_free else (2, 3)
    for i in locked:  # the planar rotor: tilts held at zero
        a[i, :], a[:, i], a[i, i], rhs[i] = 0.0, 0.0, 1.0, 0.0
    solution = np.linalg.lstsq(a, rhs, rcond=None)[0]
    q = solution[:n]
    states, extra = [], n
    for i, b in enumerate(bearings):
        sense = rows(b.sensor, f"{KIND}.{i}.sensor_position")
        per_axis = []
        for axis in range(2):
            measured = float(sense[axis] @ q)
            if b.ki > 0.0:
                current = float(solution[extra])
                extra += 1
                per_axis += [measured, -current / b.ki, current]
            else:
                per_axis += [measured, 0.0, -b.kp * measured]
        states.append(per_axis)
    return {"q": q, "states": states,
            "offsets": [float(np.hypot(*(row @ q for row in rows(b.position, f"{KIND}.{i}.position"))))
                        for i, b in enumerate(bearings)]}
