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
#: Permeability of free space [H/m].
MU0 = 4e-7 * math.pi
CIRCUIT = ("turns", "pole_area", "air_gap", "bias_current")
PARAMS: tuple[Param, ...] = (
    Param(KIND, "position", "length", None, "mm", "finite", "Axial position of the actuator from the mass centre; "
          "with rotor.matrices, the coordinate of one of the matrices' nodes", "required"),
    Param(KIND, "sensor_position", "length", None, "mm", "finite",
          "Axial position of the displacement sensor; default the actuator's (collocated)", "ours"),
    Param(KIND, "current_stiffness", "current_stiffness", None, "N/A", "positive",
          "Force per control current k_i at the bias (or give the magnetic circuit)", "the bearing's data"),
    Param(KIND, "position_stiffness", "stiffness", 0.0, "N/m", "nonnegative",
          "Negative stiffness k_s of the bias flux (F = k_i i + k_s x, k_s > 0 destabilising)", "the bearing's data"),
    Param(KIND, "turns", "dimensionless", None, "", "count", "Magnetic circuit: turns of each coil (with pole_area, "
          "air_gap and bias_current instead of current_stiffness and position_stiffness: the nonlinear force "
          "law)", "the bearing's data"),
    Param(KIND, "pole_area", "area", None, "mm^2", "positive", "Magnetic circuit: area of one pole face",
          "the bearing's data"),
    Param(KIND, "air_gap", "length", None, "mm", "positive", "Magnetic circuit: nominal air gap at each pole",
          "the bearing's data"),
    Param(KIND, "bias_current", "current", None, "A", "positive", "Magnetic circuit: bias current i_0 of each coil "
          "(the control current cannot exceed it: a coil's current stays positive)", "the bearing's data"),
    Param(KIND, "pole_angle", "angle", math.pi / 8, "deg", "finite", "Magnetic circuit: angle of each pole to its "
          "axis (the force is cos(alpha) of the poles' pull)", "ours: 22.5 deg, an eight-pole stator"),
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
    turns: float | None = None  #: the magnetic circuit (all four given, or none: the linearised law)
    pole_area: float | None = None
    air_gap: float | None = None
    bias_current: float | None = None
    pole_angle: float = math.pi / 8
    KIND = KIND

    @property
    def circuit(self) -> bool:
        """Whether the force law is the magnetic circuit's (nonlinear) rather than the linearised one."""
        return self.turns is not None

    def circuit_constant(self) -> float:
        """The circuit law's constant mu_0 N^2 A cos(alpha) / 4 [N m^2 / A^2]; 0 without a circuit."""
        if not self.circuit:
            return 0.0
        return MU0 * self.turns ** 2 * self.pole_area * math.cos(self.pole_angle) / 4.0

    def current_limit(self) -> float:
        """The largest control current: the amplifier's, and with the circuit no more than the bias [A]."""
        return min(self.max_current, self.bias_current) if self.circuit else self.max_current

    def force(self, current: float, displacement: float) -> float:
        """The magnets' force along one axis at full strength [N] (:func:`auxbearing.core.amb.magnet_force`)."""
        from auxbearing.core.amb import magnet_force

        return float(magnet_force(np.array(self._row()), current, displacement))

    def _row(self, failures=(math.inf,) * 5 + (0.0,), decay: float = 0.0) -> tuple[float, ...]:
        """The kernel's row (:data:`auxbearing.core.amb.FIELDS`) with a scenario's failure times."""
        fail_x, fail_y, restore, sensor_x, sensor_y, stuck = failures
        return (self.position, self.sensor, self.current_stiffness, self.position_stiffness, self.kp, self.ki,
                self.kd, 2 * math.pi * self.sensor_bandwidth, 2 * math.pi * self.amplifier_bandwidth,
                self.current_limit(), fail_x, fail_y, decay, restore, sensor_x, sensor_y, stuck,
                self.circuit_constant(), self.bias_current or 0.0, self.air_gap or 0.0)

    def dynamic_stiffness(self, s: complex) -> complex:
        """Force per displacement of the bearing in the loop at the Laplace variable s [N/m] (linearised).

        k_i G_a(s) G_s(s) (k_p + k_int / s + k_d s) - k_s with the first-order sensor and amplifier lags
        G = w / (s + w); at s = i w its real part is the bearing's stiffness, its imaginary part / w its damping.
        """
        ws, wa = 2 * math.pi * self.sensor_bandwidth, 2 * math.pi * self.amplifier_bandwidth
        pid = self.kp + self.ki / s + self.kd * s
        return self.current_stiffness * wa / (s + wa) * ws / (s + ws) * pid - self.position_stiffness

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
    for where, name, values, table in read_tables(tables, KIND, TABLE, ("position", "kp"), "AMB"):
        given = [key for key in CIRCUIT if key in values]
        if given:
            missing = [key for key in CIRCUIT if key not in values]
            if missing:
                raise InputError(f"{where}{missing[0]}: missing; the magnetic circuit needs "
                                 f"{', '.join(CIRCUIT)}")
            for key in ("current_stiffness", "position_stiffness"):
                if key in values:
                    raise InputError.for_field(where + key, table.get(key), "give either the force law's slopes "
                                               "or the magnetic circuit (turns, ...), not both")
            k = MU0 * values["turns"] ** 2 * values["pole_area"] * math.cos(values.get("pole_angle", math.pi / 8)) / 4
            i0, g0 = values["bias_current"], values["air_gap"]
            values.update(current_stiffness=4 * k * i0 / g0 ** 2, position_stiffness=4 * k * i0 ** 2 / g0 ** 3)
        elif "current_stiffness" not in values:
            raise InputError(f"{where}current_stiffness: missing; give it (and position_stiffness) or the magnetic "
                             f"circuit ({', '.join(CIRCUIT)})")
        elif "pole_angle" in values:
            raise InputError.for_field(where + "pole_angle", table.get("pole_angle"), "belongs to the magnetic "
                                       f"circuit ({', '.join(CIRCUIT)})")
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
    rows = [b._row(scenario.failure_times(b.name), scenario.decay_time) for b in bearings]
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
            "closed_loop_stiffness_N_per_m": b.closed_loop_stiffness(),
            **({"turns": b.turns, "pole_area_mm2": b.pole_area * 1e6, "air_gap_mm": b.air_gap * 1e3,
                "bias_current_A": b.bias_current, "pole_angle_deg": math.degrees(b.pole_angle),
                "force_law": "magnetic circuit (nonlinear)", "current_limit_A": b.current_limit()}
               if b.circuit else {"force_law": "linearised"})}


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
