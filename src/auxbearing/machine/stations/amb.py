"""``[[amb]]``: an active magnetic bearing station (the ``[[scenario]]`` tables: :mod:`auxbearing.machine.scenario`).

Its kernel is :mod:`auxbearing.core.amb` (force law, sensor, PID controller, amplifier). A drop starts at the
levitated static state the model computes itself (:func:`levitated_state`) and the magnetic bearings work
until the scenario's time; without a scenario they fail at the drop (t = 0), which is the drop from the centre.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from auxbearing.common.errors import InputError
from auxbearing.common.params import Param, by_key, display_value, unknown
from auxbearing.core import amb as kernel
from auxbearing.machine.params import AXIAL_POSITION
from auxbearing.machine.stations.load import text_key

KIND = kernel.NAME
#: Permeability of free space [H/m].
MU0 = 4e-7 * math.pi
CIRCUIT = ("turns", "pole_area", "air_gap", "bias_current")
#: 90 deg less the rounding of a unit conversion ("90 deg" may land a few ulp either side of pi / 2, where
#: cos is 6e-17 rather than 0): the pole angle stays below it.
RIGHT_ANGLE = math.pi / 2 - 1e-12
PARAMS: tuple[Param, ...] = (
    Param(KIND, "position", "length", None, "mm", "finite", "Axial position of the actuator, " + AXIAL_POSITION,
          "required"),
    Param(KIND, "sensor_position", "length", None, "mm", "finite",
          "Axial position of the displacement sensor, from the same origin and in the same direction as position; "
          "default the actuator's (collocated)", "ours"),
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
          "axis, in [0, 90) deg (the force is cos(alpha) of the poles' pull)", "ours: 22.5 deg, an eight-pole stator"),
    Param(KIND, "kp", "current_per_length", None, "A/m", "positive", "Proportional gain (i = -(kp x + ki int x + "
          "kd dx/dt)); or give a controller", "the controller's data"),
    Param(KIND, "ki", "current_per_length_time", 0.0, "A/(m*s)", "nonnegative", "Integral gain",
          "the controller's data"),
    Param(KIND, "kd", "current_time_per_length", 0.0, "A*s/m", "nonnegative", "Derivative gain",
          "the controller's data"),
    Param(KIND, "sensor_bandwidth", "frequency", 5000.0, "Hz", "positive", "Bandwidth of the sensor (first order)",
          "ours: a typical eddy-current sensor's 5-20 kHz"),
    Param(KIND, "amplifier_bandwidth", "frequency", 1000.0, "Hz", "positive",
          "Current bandwidth of the amplifier (first order)", "ours: a typical switching amplifier's 1-3 kHz"),
    Param(KIND, "max_current", "current", math.inf, "A", "positive", "Largest control current the amplifier gives; "
          "a run that starts levitated needs more than the current that carries the bearing's share of the static "
          "load", "ours: none unless given"),
    Param(KIND, "load_capacity", "force", math.inf, "N", "positive", "Largest force the bearing gives along each "
          "axis (its iron saturates)", "the bearing's data; none unless given"),
    Param(KIND, "derivative_bandwidth", "frequency", None, "Hz", "optional_positive", "The PID's derivative "
          "filter: kd s / (1 + s / (2 pi f)) on the reading (without it the derivative is the sensor's rate)",
          "the controller's data"),
    Param(KIND, "max_voltage", "voltage", math.inf, "V", "positive", "The amplifier's supply voltage: with "
          "coil_inductance it limits the current's rate to max_voltage / coil_inductance (slew)",
          "ours: none unless given"),
    Param(KIND, "coil_inductance", "inductance", None, "mH", "optional_positive", "Inductance of one axis' coil "
          "(needed with max_voltage)", "the bearing's data"),
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
    max_voltage: float = math.inf
    coil_inductance: float | None = None
    load_capacity: float = math.inf
    derivative_bandwidth: float | None = None
    turns: float | None = None  #: the magnetic circuit (all four given, or none: the linearised law)
    pole_area: float | None = None
    air_gap: float | None = None
    bias_current: float | None = None
    pole_angle: float = math.pi / 8
    #: a state-space controller (A, B, C, D) as nested tuples, from the reading [m] to the current i = -(C z + D x)
    #: [A]; None: the PID of kp, ki, kd
    controller: tuple | None = None
    #: an axial (thrust) bearing: one axis along the spin axis, on the rotor's axial position
    axial: bool = False
    #: the keys as the machine file wrote them, (key, text) pairs: a refusal after reading quotes the user's text
    given: tuple = field(default=(), compare=False, repr=False)
    KIND = KIND

    def as_written(self, key: str) -> object:
        """A key's value as the file wrote it, or its SI value in the key's display unit (the Python API)."""
        given = dict(self.given)
        if key in given:
            return given[key]
        if key == "controller":  # no number with a unit: what describe() calls it
            return f"state space of order {self.order}"
        return display_value(TABLE[key], getattr(self, key))

    @property
    def order(self) -> int:
        """Controller states per axis (the PID's one: its integral)."""
        return 1 if self.controller is None else len(self.controller[0])

    def transfer(self, s: complex) -> complex:
        """The controller's C(s) from the reading to the current command, i = -C(s) x [A/m]."""
        if self.controller is None:
            return self.kp + self.ki / s + self.kd * s
        a, b, c, d = (np.asarray(v, float) for v in self.controller)
        return complex(c @ np.linalg.solve(s * np.eye(len(a)) - a, b) + d)

    def static_gain(self) -> float:
        """C(0), the controller's gain at rest [A/m]: kp for the PID, D - C A^-1 B for a state space.

        An integrator (a pole at s = 0) makes it infinite, with the sign C(s) takes just above s = 0 (its residue's):
        A is then singular and C is read at a real s far below the controller's own rates instead.
        """
        if self.controller is None:
            return math.inf if self.ki > 0.0 else self.kp
        a = np.asarray(self.controller[0], float)
        try:
            if np.linalg.cond(a) < 1e12:
                return self.transfer(0.0).real
        except np.linalg.LinAlgError:
            pass
        rates = np.abs(np.linalg.eigvals(a))
        probe = 1e-9 * max(float(rates.max()), 1.0)
        gain = self.transfer(probe).real
        # C ~ r / s grows a thousandfold from 1000 probe down to probe; a C that stays put has no integrator (its
        # singular A has a pole at 0 that the reading or the current does not see): that value is its DC gain
        return math.copysign(math.inf, gain) if abs(gain) > 100.0 * abs(self.transfer(1e3 * probe).real) else gain

    def spring_and_damper(self, speed: float) -> tuple[float, float]:
        """(k, c) of the bearing with ideal sensor and amplifier [N/m, N s/m].

        The PD's k_i k_p - k_s and k_i k_d, or a state-space controller's k_i Re C(i w) - k_s and k_i Im C(i w) / w
        at the running speed w (the frequency the unbalance drives).
        """
        if self.controller is None:
            return self.closed_loop_stiffness(), self.current_stiffness * self.kd
        w = max(abs(speed), 1.0)
        gain = self.transfer(1j * w)
        return self.current_stiffness * gain.real - self.position_stiffness, self.current_stiffness * gain.imag / w

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

    def _row(self, failures=(math.inf,) * 5 + (0.0,), decay: float = 0.0, states_at: int = 0,
             controller_at: int = -1) -> tuple[float, ...]:
        """The kernel's row (:data:`auxbearing.core.amb.FIELDS`) with a scenario's failure times and its offsets."""
        fail_x, fail_y, restore, sensor_x, sensor_y, stuck = failures
        return (self.position, self.sensor, self.current_stiffness, self.position_stiffness, self.kp or 0.0, self.ki,
                self.kd, 2 * math.pi * self.sensor_bandwidth, 2 * math.pi * self.amplifier_bandwidth,
                self.current_limit(), fail_x, fail_y, decay, restore, sensor_x, sensor_y, stuck,
                self.circuit_constant(), self.bias_current or 0.0, self.air_gap or 0.0, self.order, states_at,
                controller_at, self.slew_rate(), self.load_capacity, float(self.axial))

    def slew_rate(self) -> float:
        """The largest rate of the coil current, U_max / L [A/s] (inf without a voltage limit)."""
        if math.isinf(self.max_voltage):
            return math.inf
        return self.max_voltage / self.coil_inductance

    def flat_controller(self) -> np.ndarray:
        """A, B, C, D of the state-space controller, flat (the kernel's layout); empty for the PID."""
        if self.controller is None:
            return np.zeros(0)
        return np.concatenate([np.ravel(np.asarray(v, float)) for v in self.controller])

    def dynamic_stiffness(self, s: complex) -> complex:
        """Force per displacement of the bearing in the loop at the Laplace variable s [N/m] (linearised).

        k_i G_a(s) G_s(s) (k_p + k_int / s + k_d s) - k_s with the first-order sensor and amplifier lags
        G = w / (s + w); at s = i w its real part is the bearing's stiffness, its imaginary part / w its damping.
        """
        ws, wa = 2 * math.pi * self.sensor_bandwidth, 2 * math.pi * self.amplifier_bandwidth
        return self.current_stiffness * wa / (s + wa) * ws / (s + ws) * self.transfer(s) - self.position_stiffness

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
    controllers, axes, written_controllers = [], [], []
    if isinstance(tables, list):  # a controller and the axis are no numbers with units: taken out first
        tables = [dict(t) if isinstance(t, dict) else t for t in tables]
        for i, t in enumerate(tables):
            if isinstance(t, dict):  # checked whole, before the text keys leave the table: every key listed
                allowed = [*TABLE, "name", "axis", "controller"]
                for key in t:
                    if key not in allowed:
                        raise unknown(f"{KIND}.{i}.{key}", t[key], key, allowed)
            raw = t.pop("controller") if isinstance(t, dict) and "controller" in t else None
            written_controllers.append(raw)
            controllers.append(read_controller(raw, f"{KIND}.{i}.controller") if raw is not None else None)
            axes.append(text_key(t, "axis", f"{KIND}.{i}.", ("radial", "axial"), "radial")
                        if isinstance(t, dict) else "radial")
    for (where, name, values, table), controller, axis, raw in zip(
            read_tables(tables, KIND, TABLE, ("position",), "AMB"), controllers, axes, written_controllers,
            strict=True):
        if any(b.name == name for b in out):  # an axis_loss or sensor_failure scenario names its bearing by it
            raise InputError.for_field(where + "name", name, "two [[amb]] tables of one name (a scenario names "
                                       "the bearing it fails by it)")
        values["axial"] = axis == "axial"
        if values["axial"] and "sensor_position" in values:
            raise InputError.for_field(where + "sensor_position", table.get("sensor_position"), "an axial bearing "
                                       "reads the rotor's axial position: it has no sensor plane")
        if controller is not None:
            for key in ("kp", "ki", "kd"):
                if key in values:
                    raise InputError.for_field(where + key, table.get(key), "give either the PID's gains or a "
                                               "controller, not both")
            values.update(controller=controller, kp=0.0)
        elif "kp" not in values:
            raise InputError(f"{where}kp: missing; give the PID's gains (kp, ki, kd) or a controller")
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
            angle = values.get("pole_angle", math.pi / 8)
            # checked before anything built on cos(alpha): past 90 deg the slopes change sign and the kp check below
            # would blame the gain for the geometry
            if not 0.0 <= angle < RIGHT_ANGLE:
                raise InputError.for_field(where + "pole_angle", table.get("pole_angle"), "must lie in [0, 90) deg: "
                                           "a pole pair pulls along its axis with cos(pole_angle) of its poles' pull "
                                           "(Schweitzer & Maslen, Magnetic Bearings, 2009, Ch. 2), nothing at 90 deg")
            k = MU0 * values["turns"] ** 2 * values["pole_area"] * math.cos(angle) / 4
            i0, g0 = values["bias_current"], values["air_gap"]
            values.update(current_stiffness=4 * k * i0 / g0 ** 2, position_stiffness=4 * k * i0 ** 2 / g0 ** 3)
        elif "current_stiffness" not in values:
            raise InputError(f"{where}current_stiffness: missing; give it (and position_stiffness) or the magnetic "
                             f"circuit ({', '.join(CIRCUIT)})")
        elif "pole_angle" in values:
            raise InputError.for_field(where + "pole_angle", table.get("pole_angle"), "belongs to the magnetic "
                                       f"circuit ({', '.join(CIRCUIT)})")
        if "derivative_bandwidth" in values:
            if controller is not None:
                raise InputError.for_field(where + "derivative_bandwidth", table.get("derivative_bandwidth"),
                                           "filters the PID's derivative; put the filter into the controller")
            values["controller"] = _filtered_pid(values, where)
        if "max_voltage" in values and "coil_inductance" not in values:
            raise InputError(f"{where}coil_inductance: missing; max_voltage limits the current's rate through it")
        if "coil_inductance" in values and "max_voltage" not in values:  # it would be read and change nothing
            raise InputError.for_field(where + "coil_inductance", table.get("coil_inductance"), "acts only with "
                                       "max_voltage (the amplifier's voltage limits the current's rate through it)")
        written = tuple((key, value if isinstance(value, (str, int, float)) else str(value))
                        for key, value in table.items() if key in TABLE)
        if raw is not None:  # a refusal of the statics quotes it as written
            written += (("controller", raw if isinstance(raw, (str, dict)) else str(raw)),)
        bearing = MagneticBearing(name=name, **values, given=written)
        if controller is None and bearing.closed_loop_stiffness() <= 0.0:
            raise InputError.for_field(where + "kp", table.get("kp"), "too small to hold the rotor: kp "
                                       "current_stiffness must exceed position_stiffness "
                                       f"({bearing.position_stiffness:g} N/m)")
        if controller is not None:
            _check_static_stiffness(bearing, where + "controller", raw)
        out.append(bearing)
    return tuple(out)


def _check_static_stiffness(bearing: MagneticBearing, where: str, written) -> None:
    """Refuse a state-space controller whose static stiffness k_i C(0) - k_s is not positive.

    The same rule as kp's (k_i k_p - k_s > 0) for a controller given as a transfer function or state space: at
    s = 0 the bearing's force per displacement is k_i C(0) - k_s (:meth:`MagneticBearing.dynamic_stiffness` at
    s = 0, the lags' gains being 1 there; Schweitzer & Maslen, Magnetic Bearings, 2009, Ch. 2). Not positive, the
    bias flux's pull wins over the controller's at rest and the levitated rotor has no static place: it runs to a
    pole (a DC gain below k_s / k_i, or negative: an unstable pole of C(s) flips its sign). An integrator makes
    C(0) infinite, of the sign of its residue.
    """
    gain = bearing.static_gain()
    stiffness = bearing.current_stiffness * gain - bearing.position_stiffness
    if stiffness > 0.0:
        return
    said = (f"its static gain C(0) = {gain:.4g} A/m gives k_i C(0) - k_s = {stiffness:.4g} N/m"
            if math.isfinite(gain) else "its integrator's gain is negative (C(s) falls to -inf as s -> 0)")
    raise InputError.for_field(where, written, f"too weak to hold the rotor at rest: {said} (k_i = "
                               f"{bearing.current_stiffness:g} N/A, k_s = {bearing.position_stiffness:g} N/m), which "
                               "must be positive as kp's k_i k_p - k_s (the bias flux's negative stiffness pulls the "
                               "rotor to a pole)")


def _filtered_pid(values: dict, where: str) -> tuple:
    """The PID kp + ki / s + kd s / (1 + s / w_f) as a state-space controller (python-control realises it)."""
    import control

    s = control.tf("s")
    wf = 2 * math.pi * values["derivative_bandwidth"]
    pid = values["kp"] + values.get("kd", 0.0) * s / (1 + s / wf)
    if values.get("ki", 0.0) > 0.0:
        pid = pid + values["ki"] / s
    return read_controller(control.minreal(pid, verbose=False), where + "derivative_bandwidth")


#: Most controller states per axis (a controller of higher order is refused: reduce it first).
MAX_ORDER = 20


def read_controller(value, where: str) -> tuple:
    """A controller as (A, B, C, D) nested tuples, read by python-control.

    A ``TransferFunction`` or ``StateSpace``, or a table ``{num = [...], den = [...]}`` (coefficients in descending
    powers of s) or ``{A, B, C, D}``, in SI, from the sensor's reading [m] to the control current [A] with
    i = -C(s) x (so a PID is kp + ki / s + kd s / (1 + s / w)).
    """
    import control

    try:
        if isinstance(value, (control.TransferFunction, control.StateSpace)):
            system = value
        elif isinstance(value, dict) and set(value) == {"num", "den"}:
            num, den = (np.atleast_1d(np.asarray(value[k], float)) for k in ("num", "den"))
            if not np.any(den):  # an all-zero den trims to nothing, which the properness test would call improper
                raise InputError.for_field(where, value, "the denominator den must not be all zeros (C(s) = num / "
                                           "den divides by it)")
            if len(np.trim_zeros(num, "f")) > len(np.trim_zeros(den, "f")):
                raise InputError.for_field(where, value, "must be proper: a derivative needs its filter "
                                           "(kd s / (1 + s / w))")
            system = control.tf(num, den)
        elif isinstance(value, dict) and set(value) == {"A", "B", "C", "D"}:
            system = control.ss(*(np.atleast_2d(np.asarray(value[k], float)) for k in ("A", "B", "C", "D")))
        else:
            raise InputError.for_field(where, value, "give {num = [...], den = [...]} or {A, B, C, D} (SI: A per m) "
                                       "or a python-control TransferFunction / StateSpace")
        if not control.isctime(system, strict=False):
            raise InputError.for_field(where, value, "must be a continuous-time controller (dt = 0)")
        if system.ninputs != 1 or system.noutputs != 1:
            raise InputError.for_field(where, value, "must have one input (the reading) and one output (the current)")
        ss = control.ss(system)
    except InputError:
        raise
    except (ValueError, TypeError, np.linalg.LinAlgError) as err:
        raise InputError.for_field(where, value, f"is no linear controller python-control can read ({err})") from None
    a, b, c, d = (np.asarray(m, float) for m in (ss.A, ss.B, ss.C, ss.D))
    if not all(np.all(np.isfinite(m)) for m in (a, b, c, d)):
        raise InputError.for_field(where, value, "has coefficients that are not finite")
    if a.shape[0] == 0:
        raise InputError.for_field(where, value, "is a pure gain: give it as kp")
    if a.shape[0] > MAX_ORDER:
        raise InputError.for_field(where, value, f"has {a.shape[0]} states; at most {MAX_ORDER} (reduce it)")
    return (tuple(map(tuple, a)), tuple(b[:, 0]), tuple(c[0]), float(d[0, 0]))


def pack(bearings, modal, n_modes: int, machine=None) -> kernel.Params:
    """The kernel's parameters: shapes at the actuators and sensors, the failures from the active scenario."""
    from auxbearing.machine.scenario import AT_THE_DROP

    scenario = machine.active_scenario() if machine is not None else AT_THE_DROP
    rows, flat, states_at = [], [], 0
    for b in bearings:
        at = sum(part.size for part in flat) if b.controller is not None else -1
        rows.append(b._row(scenario.failure_times(b), scenario.decay_time, states_at, at))
        flat.append(b.flat_controller())
        states_at += kernel.width(b.order, b.axial)
    values = np.array(rows, float).reshape(len(bearings), len(kernel.FIELDS))
    shapes = [np.zeros((len(bearings), n_modes)) for _ in range(4)]
    if n_modes:
        for i, b in enumerate(bearings):
            shapes[0][i], shapes[1][i] = modal.station_shapes(b.position, f"{KIND}.{i}.position")
            shapes[2][i], shapes[3][i] = modal.station_shapes(b.sensor, f"{KIND}.{i}.sensor_position")
    controllers = np.concatenate(flat) if flat else np.zeros(0)
    return kernel.Params(values, *shapes, controllers)


def series(bearings, journal, states, params=None, t=None, rotor_z=None) -> dict:
    """Each bearing's coil currents over a run and, with its packed rows and the times, its force on the rotor.

    ``states(i)``: its states on the run's grid (kernel order); ``journal(i, position)``: the rotor axis at its
    actuator; ``params``: the packed :class:`auxbearing.core.amb.Params` (the scenario's failure times);
    ``rotor_z``: the rotor's axial position (an axial bearing's). A radial bearing's series are x and y, an axial
    one's z; the axes a bearing has not are NaN.
    """
    if not bearings:
        return {}
    n = len(states(0))
    axes = ("x", "y", "z") if any(b.axial for b in bearings) else ("x", "y")
    currents = {a: np.full((n, len(bearings)), np.nan) for a in axes}
    forces = {a: np.full((n, len(bearings)), np.nan) for a in axes}
    for i, b in enumerate(bearings):
        own = ("z",) if b.axial else ("x", "y")
        for k, a in enumerate(own):
            currents[a][:, i] = states(i)[:, k * (2 + b.order) + 1 + b.order]
        if params is None or t is None:
            continue
        row = params.values[i]
        if b.axial:
            moved = {"z": rotor_z}
        else:
            ux, uy, _, _ = journal(i, b.position)
            moved = {"x": ux, "y": uy}
        for a, fail in zip(own, (kernel.P_FAIL_X, kernel.P_FAIL_Y), strict=False):
            forces[a][:, i] = kernel.forces(row, np.ascontiguousarray(t, float), row[fail],
                                            np.ascontiguousarray(currents[a][:, i]),
                                            np.ascontiguousarray(moved[a], float))
    out = {"amb": ("amb", [b.name for b in bearings], {}),
           "amb_axis": ("amb", ["axial" if b.axial else "radial" for b in bearings], {})}
    inductance = np.array([b.coil_inductance or np.nan for b in bearings])
    if t is not None and len(t) > 1 and np.isfinite(inductance).any():
        for a in axes:  # the coil's inductive voltage L di/dt on the output grid (its resistance left out)
            out[f"amb_voltage_{a}"] = (("time", "amb"), inductance * np.gradient(currents[a], t, axis=0),
                                       {"units": "V", "long_name": f"Magnetic bearing's coil voltage L di/dt, {a}"})
    for a in axes:
        out[f"amb_current_{a}"] = (("time", "amb"), currents[a], {"units": "A",
                                   "long_name": f"Magnetic bearing's control current, {a}"})
        if params is not None and t is not None:
            out[f"amb_force_{a}"] = (("time", "amb"), forces[a], {"units": "N",
                                     "long_name": f"Magnetic bearing's force on the rotor, {a}"})
    return out


def describe(b: MagneticBearing) -> dict:
    """Inputs with units in the keys, for files and reports."""
    return {"kind": KIND, "name": b.name, "axis": "axial" if b.axial else "radial", "position_m": b.position,
            "sensor_position_m": b.sensor,
            "current_stiffness_N_per_A": b.current_stiffness, "position_stiffness_N_per_m": b.position_stiffness,
            **({"kp_A_per_m": b.kp, "ki_A_per_m_s": b.ki, "kd_A_s_per_m": b.kd} if b.controller is None else
               {"controller": f"state space of order {b.order} (A per m of reading)",
                "controller_gain_at_1_Hz_A_per_m": abs(b.transfer(2j * math.pi))}),
            "sensor_bandwidth_Hz": b.sensor_bandwidth,
            "amplifier_bandwidth_Hz": b.amplifier_bandwidth,
            "max_current_A": b.max_current if math.isfinite(b.max_current) else "unlimited (no max_current)",
            # without max_voltage the slew rate has no limit: said in words, which a file and a report page both read
            "slew_rate_A_per_s": b.slew_rate() if math.isfinite(b.slew_rate()) else "unlimited (no max_voltage)",
            **({"closed_loop_stiffness_N_per_m": b.closed_loop_stiffness()} if b.controller is None else {}),
            **({"turns": b.turns, "pole_area_mm2": b.pole_area * 1e6, "air_gap_mm": b.air_gap * 1e3,
                "bias_current_A": b.bias_current, "pole_angle_deg": math.degrees(b.pole_angle),
                "force_law": "magnetic circuit (nonlinear)", "current_limit_A": b.current_limit()}
               if b.circuit else {"force_law": "linearised"})}


def levitated_state(machine, modal, bearings) -> dict:
    """The static state of the rotor held by its magnetic bearings: the linear statics of the model.

    Unknowns: the rotor's coordinates q (x, y, theta_x, theta_y and the elastic modes, and its axial position when
    an axial bearing holds it) and, for a bearing with integral action, its steady currents (its sensor then reads
    zero); without integral action the current is -k_p times the sensor's reading; a state-space controller's
    steady states z solve A z + B x = 0 with the rest. Forces: gravity, the constant process forces and the linear
    supports; the touchdown planes are clear. Returns q (lateral and modes), the axial position ``z`` and each
    bearing's states in the kernel's order (reading, controller states, current; x then y, or z).
    """
    r = machine.rotor
    lateral = 4 + (modal.n_modes if modal is not None else 0)
    axial = any(b.axial for b in bearings)
    n = lateral + (1 if axial else 0)
    g = machine.simulation.gravity
    gravity = (0.0, -g, 0.0) if machine.orientation == "horizontal" else (0.0, 0.0, -g)

    def rows(position, key):
        bx, by = np.zeros(n), np.zeros(n)
        bx[0], bx[3], by[1], by[2] = 1.0, position, 1.0, -position
        if lateral > 4:
            bx[4:lateral], by[4:lateral] = modal.station_shapes(position, key)
        return bx, by

    def axes(b, i):
        if b.axial:
            bz = np.zeros(n)
            bz[lateral] = 1.0
            return ((bz, bz),)
        act, sense = rows(b.position, f"{KIND}.{i}.position"), rows(b.sensor, f"{KIND}.{i}.sensor_position")
        return (act[0], sense[0]), (act[1], sense[1])

    stiff = np.zeros((n, n))
    if lateral > 4:
        stiff[4:lateral, 4:lateral] = np.diag(modal.frequencies ** 2)
    for i, s in enumerate(getattr(machine, "stations", ())):
        if s.KIND != "linear_support":
            continue
        bx, by = rows(s.position, f"linear_support.{i}.position")
        b = np.vstack([bx, by])
        stiff += b.T @ np.array([[s.kxx, s.kxy], [s.kyx, s.kyy]]) @ b
    force = np.zeros(n)
    force[0] = r.mass * gravity[0] + r.side_force_x
    force[1] = r.mass * gravity[1] + r.side_force_y
    if axial:
        force[lateral] = r.mass * gravity[2] + r.axial_force
    unknowns = sum((1 if b.axial else 2) * (b.order if b.controller is not None else int(b.ki > 0.0))
                   for b in bearings)
    size = n + unknowns
    a, rhs = np.zeros((size, size)), np.zeros(size)
    a[:n, :n] = stiff
    rhs[:n] = force
    extra = n
    for i, b in enumerate(bearings):
        for act, sense in axes(b, i):
            a[:n, :n] -= b.position_stiffness * np.outer(act, act)
            if b.controller is not None:  # steady: A z + B x = 0, the current -(C z + D x)
                sys_a, sys_b, sys_c, sys_d = (np.asarray(v, float) for v in b.controller)
                z = slice(extra, extra + b.order)
                a[:n, z] += b.current_stiffness * np.outer(act, sys_c)
                a[:n, :n] += b.current_stiffness * sys_d * np.outer(act, sense)
                a[z, z] = sys_a
                a[z, :n] = np.outer(sys_b, sense)
                extra += b.order
            elif b.ki > 0.0:
                a[:n, extra] -= b.current_stiffness * act  # the unknown steady current
                a[extra, :n] = sense  # the sensor reads zero
                extra += 1
            else:
                a[:n, :n] += b.current_stiffness * b.kp * np.outer(act, sense)
    locked = () if machine.tilt_free else (2, 3)
    for i in locked:  # the planar rotor: tilts held at zero
        a[i, :], a[:, i], a[i, i], rhs[i] = 0.0, 0.0, 1.0, 0.0
    levitated = machine.active_scenario().levitated
    loose, rows_scale, cols_scale = _unheld_motion(a, n)
    if loose is None:  # square and regular: the bearings hold every rigid motion
        solution = np.linalg.solve(a, rhs)
    elif levitated:
        _refuse_unheld(machine, modal, bearings, loose, lateral)
    else:  # a drop from the centre only reports these statics: the least-squares ones, the loose motion left out
        scaled = a * rows_scale[:, None] * cols_scale[None, :]
        solution = cols_scale * np.linalg.lstsq(scaled, rows_scale * rhs, rcond=UNHELD)[0]
    q = solution[:n]
    states, extra = [], n
    for i, b in enumerate(bearings):
        per_axis = []
        for _, sense in axes(b, i):
            measured = float(sense @ q)
            if b.controller is not None:
                z = solution[extra:extra + b.order]
                extra += b.order
                per_axis += [measured, *z, -float(np.asarray(b.controller[2]) @ z + b.controller[3] * measured)]
            elif b.ki > 0.0:
                current = float(solution[extra])
                extra += 1
                per_axis += [measured, -current / b.ki, current]
            else:
                per_axis += [measured, 0.0, -b.kp * measured]
        states.append(per_axis)
    if levitated:  # a drop from the centre only reports the statics it never reaches
        _check_levitation(machine, bearings, states)
        _check_axial_load(machine, axial, gravity)
        _check_offsets(machine, modal, bearings, q[:lateral])
    return {"q": q[:lateral], "z": float(q[lateral]) if axial else 0.0, "states": states,
            "offsets": [abs(float(q[lateral])) if b.axial else float(np.hypot(*(act @ q for act, _ in axes(b, i))))
                        for i, b in enumerate(bearings)]}


def check_levitation(machine) -> None:
    """Refuse magnetic bearings that cannot levitate the rotor that any of the machine's scenarios starts from.

    A whole-file check (the levitated statics' checks in :func:`levitated_state`, which do not depend on the
    scenario), for :func:`auxbearing.machine.combinations.check_combinations`; a run starting levitated makes it on
    its own. The air gaps against the touchdown clearances (:func:`_check_air_gaps`) with any scenario.
    """
    from auxbearing.machine.stations import of_kind

    bearings = of_kind(machine.stations, KIND)
    if not bearings:
        return
    _check_air_gaps(machine, bearings)
    start = next((s for s in machine.scenarios if s.levitated), None)
    if start is not None:
        levitated_state(machine.with_scenario(start.name), machine.modal(), bearings)


#: Ratio of the smallest to the largest singular value of the (equilibrated) statics below which a motion counts as
#: held by nothing: well above the rounding of a singular matrix's (1e-16 times its size) and far below what a
#: real pair of bearings gives (their stiffnesses within a few decades of each other and of the load's lever).
UNHELD = 1e-10
#: The rotor's coordinates in the statics, for a refusal that says which motion nothing holds.
MOTIONS = ("translation along x", "translation along y", "tilt about x", "tilt about y")


def _unheld_motion(a: np.ndarray, n: int) -> tuple[np.ndarray | None, np.ndarray, np.ndarray]:
    """The rotor's motion (its n coordinates) that the statics' matrix ``a`` does not hold, or None; the scales.

    The matrix mixes stiffnesses [N/m], lever arms and controller rows of other units, so its rows and columns are
    first brought to one scale (Ruiz's equilibration, a few sweeps); a singular value below :data:`UNHELD` of the
    largest then is a motion with no restoring force (Golub & Van Loan, Matrix Computations, 4th ed., 2013,
    Sec. 2.4 and 3.5.2: the numerical rank). Its right singular vector, scaled back, is that motion. The scales
    r, c make diag(r) a diag(c) the equilibrated matrix.
    """
    rows, cols = np.ones(a.shape[0]), np.ones(a.shape[1])
    scaled = a.copy()
    for _ in range(5):
        r = np.sqrt(np.abs(scaled).max(axis=1))
        c = np.sqrt(np.abs(scaled).max(axis=0))
        r[r == 0.0], c[c == 0.0] = 1.0, 1.0
        scaled = scaled / r[:, None] / c[None, :]
        rows, cols = rows / r, cols / c
    _, sigma, vt = np.linalg.svd(scaled)
    if sigma[-1] > UNHELD * sigma[0]:
        return None, rows, cols
    return (vt[-1] * cols)[:n], rows, cols


def _refuse_unheld(machine, modal, bearings, motion: np.ndarray, lateral: int) -> None:
    """Refuse a levitated start whose magnetic bearings leave a rigid motion of the rotor free (one line).

    With a motion no force restores, the statics K q = f have no solution under a load with a component along it
    (one radial bearing under a tilting rotor: the weight's moment about the bearing), and a least-squares answer
    is no place the rotor can hang at: it ran off to 5e12 m.
    """
    radial = [(i, b) for i, b in enumerate(bearings) if not b.axial]
    reach = max([abs(b.position) for b in bearings] + [abs(p.position) for p in machine.planes] + [1e-3])
    moves = np.abs(motion[:4]) * np.array([1.0, 1.0, reach, reach])  # a tilt by its largest sideways travel
    bending = np.abs(motion[4:lateral])
    which = MOTIONS[int(np.argmax(moves))] if moves.max() >= bending.max(initial=0.0) else None
    if which is None:  # an elastic mode of (nearly) no stiffness: parts of the matrices' rotor joined by nothing
        j = int(np.argmax(bending))
        raise InputError.for_field("rotor.matrices", "as given", f"the rotor's elastic mode {j + 1} has "
                                   f"{modal.frequencies[j] / (2 * math.pi):.3g} Hz, next to no stiffness, and the "
                                   "magnetic bearings do not hold it: a levitated start has no static place (is the "
                                   "stiffness matrix K whole, every element joined?)")
    if not radial:
        i, key, value = 0, "axis", "axial"
        why = "a levitated rotor needs radial magnetic bearings too (here every [[amb]] is axial)"
    else:
        i = radial[-1][0]
        # as the file wrote them: a rotor of matrices places them in its own coordinates, not from the mass centre
        places = ", ".join(f"{KIND}.{j}.position = {b.as_written('position')!r}"
                           + (f" (sensor_position = {b.as_written('sensor_position')!r})"
                              if b.sensor_position is not None else "") for j, b in radial)
        key = "position"
        value = bearings[i].as_written(key)
        why = (f"the radial ones are {places}: a rotor free to tilt needs radial bearings at two axial positions, "
               "and with integral action their sensors too")
    tips = " (the load's moment about the bearing tips the rotor)" if which.startswith("tilt") else ""
    raise InputError.for_field(f"{KIND}.{i}.{key}", value, f"the magnetic bearings do not hold the rotor's {which}: "
                               f"{why}, else nothing restores that motion and the levitated statics K q = f have no "
                               f"solution{tips}, so scenario '{machine.active_scenario().name}' cannot start "
                               "levitated")


def _check_axial_load(machine, axial: bool, gravity: tuple) -> None:
    """Refuse a levitated start with a steady axial load that no axial magnetic bearing carries.

    The rotor moves axially (a touchdown plane catches it on a race face); a constant axial force F, the process
    thrust plus the weight along a vertical spin axis, then accelerates it at F / m until its collar meets the
    face, after sqrt(2 c m / |F|) for an axial clearance c: the rotor rests on its touchdown bearing from the
    start, which is no levitation (the compressor's 300 N on 40.3 kg closes 0.25 mm in 8.2 ms).
    """
    if axial or not machine.axial_free:
        return
    r = machine.rotor
    load = r.mass * gravity[2] + r.axial_force
    if load == 0.0:
        return
    from auxbearing.machine.params import TABLES

    if r.axial_force != 0.0:
        key, value = "rotor.axial_force", display_value(TABLES["rotor"]["axial_force"], r.axial_force)
    else:
        key, value = "machine.orientation", machine.orientation
    side = "+z" if load > 0.0 else "-z"
    faces = [(p.axial_clearance, k, p.name) for k, p in enumerate(machine.planes)
             if p.catches_axially and p.axial_direction in ("both", side)]
    if faces:
        clearance, k, name = min(faces)
        lands = (f"its collar closes the {clearance * 1e3:g} mm axial clearance of touchdown.{k} ({name}) in "
                 f"sqrt(2 c m / F) = {math.sqrt(2.0 * clearance * r.mass / abs(load)) * 1e3:.3g} ms and rests on that "
                 "face")
    else:
        lands = f"nothing catches it towards {side}"
    raise InputError.for_field(key, value, f"a levitated start needs an axial magnetic bearing to carry the steady "
                               f"axial load {load:.4g} N along {side} (the process thrust rotor.axial_force and the "
                               f"weight along a vertical spin axis): no [[amb]] has axis = \"axial\", so {lands} "
                               f"before scenario '{machine.active_scenario().name}' strikes; add an axial [[amb]] "
                               "that carries it")


def _nearest_radial(bearings, position: float) -> int:
    """The table index of the radial magnetic bearing nearest an axial position."""
    return min((abs(b.position - position), i) for i, b in enumerate(bearings) if not b.axial)[1]


def _check_offsets(machine, modal, bearings, q: np.ndarray) -> None:
    """Refuse a levitated place (or the start offset from it) outside a touchdown plane's radial clearance.

    The journal's centre at plane k is the rotor's axis there (x + a theta_y, y - a theta_x, with the elastic
    modes' shapes), measured from the bearing's centre (its misalignment). The statics sag the rotor by its load
    over the bearings' static stiffness (F = (k_i k_p - k_s) u for a PD law, Schweitzer & Maslen, Magnetic
    Bearings, 2009, Ch. 2); at or past the clearance the run would start with the journal inside the race.
    rotor.start_x / start_y move the start from that place (:func:`auxbearing.machine.pack._levitate`).
    """
    r = machine.rotor
    n_modes = q.size - 4  # q: the lateral coordinates, the elastic modes' after the rigid four
    for k, p in enumerate(machine.planes):
        x, y = q[0] + p.position * q[3], q[1] - p.position * q[2]
        if n_modes > 0:
            sx, sy = modal.station_shapes(p.position, f"touchdown.{k}.position")
            x, y = x + float(sx @ q[4:4 + n_modes]), y + float(sy @ q[4:4 + n_modes])
        mx, my = p.misalignment
        held = math.hypot(x - mx, y - my)
        if held >= p.radial_clearance:
            i = _nearest_radial(bearings, p.position)
            b = bearings[i]
            key = "kp" if b.controller is None or "kp" in dict(b.given) else "controller"
            static = b.current_stiffness * b.static_gain() - b.position_stiffness
            raise InputError.for_field(f"{KIND}.{i}.{key}", b.as_written(key), f"the levitated rotor's journal sits "
                                       f"{held * 1e3:.3g} mm from the centre of touchdown.{k} ({p.name}), not inside "
                                       f"its radial clearance {p.radial_clearance * 1e3:g} mm: the magnetic bearings' "
                                       f"static stiffness (k_i C(0) - k_s, here {static:.4g} N/m) sags it into the "
                                       "race under its load; stiffen them (kp, or ki > 0, whose sensor then reads "
                                       "zero)")
        started = math.hypot(x + r.start_x - mx, y + r.start_y - my)
        if started >= p.radial_clearance:
            from auxbearing.machine.params import TABLES

            key = "start_x" if r.start_x != 0.0 else "start_y"
            raise InputError.for_field(f"rotor.{key}", display_value(TABLES["rotor"][key], getattr(r, key)),
                                       f"the levitated start moves the journal from its levitated place "
                                       f"({held * 1e3:.3g} mm from the centre of touchdown.{k}, {p.name}) to "
                                       f"{started * 1e3:.3g} mm, not inside its radial clearance "
                                       f"{p.radial_clearance * 1e3:g} mm: with a levitated scenario rotor.start_x "
                                       "and start_y are offsets from the levitated place")


def _check_air_gaps(machine, bearings) -> None:
    """Refuse a magnetic circuit whose air gap the rotor can close before a touchdown bearing stops it.

    The circuit's force k (i_0 + i)^2 / (g_0 - u)^2 grows without bound as the gap g_0 - u closes (Schweitzer &
    Maslen, Magnetic Bearings, 2009, Ch. 2); the touchdown bearings are there to keep the rotor off the poles, so
    the rotor must meet a race before a pole: the air gap must exceed the travel the touchdown clearances allow at
    the actuator. For a rigid rotor whose journals stay within c_j + |misalignment_j| of the axis at planes a_j,
    the travel at station a is the least over pairs of planes of c_j |a_k - a| / L + c_k |a - a_j| / L, L = |a_k
    - a_j| (the axis through the two planes, each at its limit: a linear programme's vertex), one plane's own
    reach with one plane. Axially: the smallest axial clearance of a plane that catches the rotor.
    """
    planes = machine.planes
    reach = [(p.position, p.radial_clearance + math.hypot(*p.misalignment)) for p in planes]
    for i, b in enumerate(bearings):
        if not b.circuit:
            continue
        if b.axial:
            faces = [(p.axial_clearance, k) for k, p in enumerate(planes) if p.catches_axially]
            if not faces:
                continue
            travel, k = min(faces)
            where = f"the axial clearance of touchdown.{k} ({planes[k].name}), {travel * 1e3:g} mm"
        else:
            travel = min((c for _, c in reach), default=math.inf) if len(reach) < 2 else math.inf
            for j, (aj, cj) in enumerate(reach):
                for ak, ck in reach[j + 1:]:
                    span = abs(ak - aj)
                    if span > 0.0:
                        travel = min(travel, (cj * abs(ak - b.position) + ck * abs(b.position - aj)) / span)
            if not math.isfinite(travel):  # every plane at one station: the rotor pivots there, its own reach
                travel = min(c for _, c in reach)
            where = (f"the {travel * 1e3:.3g} mm the rotor can move at {b.position * 1e3:g} mm with its journals "
                     "inside the touchdown clearances")
        if b.air_gap <= travel:
            raise InputError.for_field(f"{KIND}.{i}.air_gap", b.as_written("air_gap"), f"must exceed {where}: the "
                                       "touchdown bearings must stop the rotor before it closes the gap, where the "
                                       "circuit's pull k (i_0 + i)^2 / (g_0 - u)^2 grows without bound and pulls it "
                                       "onto the pole")


def _check_levitation(machine, bearings, states) -> None:
    """Refuse a bearing whose current limit cannot carry its share of the static load (before any run starts).

    Levitated, each axis' steady current carries the load the statics give it (weight, process forces), the force
    law F = k_i i + k_s u (Schweitzer & Maslen, Magnetic Bearings, 2009, Ch. 2). An axis that needs its current
    limit or more to do so is saturated at rest: its clipped command gives less than the load and leaves nothing
    to control with, so the rotor falls before any scenario strikes. With the magnetic circuit the limit is also
    the bias (a coil's current stays positive); at zero offset the circuit's force is exactly k_i i, so the
    statics' current is its.
    """
    scenario = machine.active_scenario()
    for i, (b, held) in enumerate(zip(bearings, states, strict=True)):
        limit = b.current_limit()
        if not math.isfinite(limit):
            continue
        width = 2 + b.order
        need = max(abs(held[k * width + 1 + b.order]) for k in range(1 if b.axial else 2))
        if need < limit:
            continue
        key = "bias_current" if b.circuit and b.bias_current <= b.max_current else "max_current"
        why = " (the control current cannot exceed the bias)" if key == "bias_current" else ""
        raise InputError.for_field(f"{KIND}.{i}.{key}", b.as_written(key),
                                   f"must exceed the levitation current {need:.3g} A{why}, which {b.name} needs to "
                                   "carry its share of the rotor's static load at current_stiffness "
                                   f"{b.current_stiffness:.4g} N/A: saturated at rest, it cannot levitate the rotor "
                                   f"that scenario '{scenario.name}' starts from")
