"""An active magnetic bearing: a station that holds the rotor through its controller until it fails.

Per axis (x and y alike), linearised about the bias (G. Schweitzer and E. H. Maslen, eds., *Magnetic Bearings*,
Springer, 2009: the linearised force law and decentralised PID control):

* force on the rotor at the actuator, F = g(t) (k_i i + k_s u), u the rotor's displacement there, k_s > 0 the
  negative (destabilising) stiffness of the bias flux; or, given the magnetic circuit, the force of the pair of
  opposed magnets in differential driving, F = g(t) k [(i_0 + i)^2 / (g_0 - u)^2 - (i_0 - i)^2 / (g_0 + u)^2]
  with k = mu_0 N^2 A cos(alpha) / 4 (Schweitzer & Maslen 2009, Ch. 2; the form ROSS's MagneticBearingElement
  linearises), whose slopes at the bias are k_i = 4 k i_0 / g_0^2 and k_s = 4 k i_0^2 / g_0^3; either law
  clipped at the bearing's load capacity (the iron saturates: no more force for more current);
* sensor: the displacement at the sensor through a first-order lag of bandwidth w_s, x_m' = w_s (x_s - x_m);
* controller: i_c = -(k_p x_m + k_int X + k_d x_m'), X' = x_m (a PID whose derivative is the sensor's filtered
  rate); or any proper linear controller given as a state space, z' = A z + B x_m, i_c = -(C z + D x_m) (a
  transfer function C(s) from the reading to the current, i_c = -C(s) x_m, realised by python-control at the
  boundary);
* amplifier: i' = w_a (sat(i_c) - i), the command clipped at the current limit and the rate at the voltage's,
  |i'| <= U_max / L (the coil's inductance across the amplifier's supply: its slew rate).

Below the speed of the controller, a PD law gives the closed-loop stiffness k_i k_p - k_s and damping k_i k_d.

Failures, each axis on its own (a radial bearing has one amplifier per axis):

* power lost at t_f: the axis' states freeze and its force decays as g = exp(-(t - t_f) / tau), the coils'
  discharge (tau = 0: at once);
* power back at t_r > t_f (a re-levitation attempt): the controller goes on from its frozen states (it kept
  its own supply) and the force recovers as g = 1 - (1 - g(t_r)) exp(-(t - t_r) / tau), the coils charging
  with the same time constant;
* an axial bearing has one axis, along the spin axis: the rotor's axial position is its u and its reading, its
  force acts at the mass centre's axial line and its failure times are the row's x ones;
* the sensor failing at t_s: stuck (the reading holds its value, x_m' = 0) or zero (x_s read as 0, the lag
  decaying to it); the controller goes on acting on the false reading.

The station's work on the rotor (the controller's and the bias's) is booked in its ledger slot as energy
taken, so the energy audit closes.

Parameters: one row per station of :data:`FIELDS` (SI) in :attr:`Params.values`. States per station and axis
(:func:`width`): the reading, the controller's ``order`` states (the PID's one: its integral) and the coil current,
x then y.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

NAME = "amb"
FIELDS = ("position", "sensor_position", "current_stiffness", "position_stiffness", "kp", "ki", "kd",
          "sensor_bandwidth", "amplifier_bandwidth", "max_current", "fail_time_x", "fail_time_y", "decay_time",
          "restore_time", "sensor_fail_time_x", "sensor_fail_time_y", "sensor_stuck", "circuit_constant",
          "bias_current", "air_gap", "order", "states_at", "controller_at", "slew_rate", "load_capacity", "axial")
(P_POS, P_SENSOR, P_KI_FORCE, P_KS, P_KP, P_KI, P_KD, P_WS, P_WA, P_IMAX, P_FAIL_X, P_FAIL_Y, P_DECAY, P_RESTORE,
 P_SENSOR_FAIL_X, P_SENSOR_FAIL_Y, P_STUCK, P_CIRCUIT, P_BIAS, P_GAP, P_ORDER, P_STATES_AT,
 P_CONTROLLER_AT, P_SLEW, P_FMAX, P_AXIAL) = range(len(FIELDS))
#: Smallest gap the circuit law divides by, as a share of the nominal gap (the touchdown clearance keeps the rotor
#: far from the poles; this only keeps a run that leaves its range finite).
MIN_GAP = 1e-3
#: Per station with a PID (order 1): the reading, its integral and the coil current, for x then y.
STATES = ("amb_measured_x", "amb_integral_x", "amb_current_x", "amb_measured_y", "amb_integral_y", "amb_current_y")
S_MEASURED, S_INTEGRAL, S_CURRENT = range(3)
LEDGER = ("amb_work_taken",)


def width(order: int, axial: bool = False) -> int:
    """States of one station whose controller has ``order`` states per axis (an axial bearing has one axis)."""
    return (1 if axial else 2) * (2 + order)


def state_names(order: int, pid: bool, axial: bool = False) -> tuple[str, ...]:
    """The state names of one station (:data:`STATES` for a radial bearing's PID)."""
    if pid and not axial:
        return STATES
    inner = ("integral",) if pid else tuple(f"controller{j}" for j in range(order))
    return tuple(f"amb_{name}_{axis}" for axis in ("z" if axial else "xy")
                 for name in ("measured", *inner, "current"))


class Params(NamedTuple):
    """Every magnetic bearing of a machine."""

    values: np.ndarray  #: (stations, len(FIELDS)) SI
    shape_x: np.ndarray  #: (stations, modes) each elastic mode's x displacement at the actuator
    shape_y: np.ndarray
    sensor_shape_x: np.ndarray  #: (stations, modes) and at the sensor
    sensor_shape_y: np.ndarray
    #: every state-space controller's A (order x order), B, C (order each) and D, flat; a row's controller_at
    #: points into it (-1: the PID)
    controllers: np.ndarray = np.zeros(0)

    @property
    def state_count(self) -> int:
        """States of all the stations."""
        return int(sum(width(int(row[P_ORDER]), row[P_AXIAL] > 0.0) for row in self.values))


def no_stations(n_modes: int = 0) -> Params:
    """A machine without magnetic bearings."""
    z = np.zeros((0, n_modes))
    return Params(np.zeros((0, len(FIELDS))), z, z.copy(), z.copy(), z.copy(), np.zeros(0))


@njit(cache=True, inline="always")
def _decay(row, elapsed):
    if row[P_DECAY] <= 0.0:
        return 0.0
    return math.exp(-elapsed / row[P_DECAY])


@njit(cache=True, inline="always")
def strength(row, t, fail):
    """g(t): 1 while powered, the coils' decay after the failure time ``fail``, their recharge after restore."""
    if t < fail:
        return 1.0
    restore = row[P_RESTORE]
    if t < restore:
        return _decay(row, t - fail)
    return 1.0 - (1.0 - _decay(row, restore - fail)) * _decay(row, t - restore)


@njit(cache=True, inline="always")
def powered(row, t, fail):
    """Whether the axis' amplifier has power at t."""
    return t < fail or t >= row[P_RESTORE]


#: exp(-x) is exactly 0 in double precision beyond x = 745.13 (below the smallest subnormal, 4.9e-324).
EXP_ZERO = 746.0


@njit(cache=True, inline="always")
def dead(row, t, fail):
    """Whether the axis is unpowered and its coils' field gone at t: no force, its states frozen (:func:`axis`).

    Exactly where :func:`strength` is 0 without power (a failure with no decay time, or one decayed past
    exp's range), so a right-hand side may skip the axis: the same rates and forces, without the work.
    """
    if powered(row, t, fail):
        return False
    return row[P_DECAY] <= 0.0 or t - fail > EXP_ZERO * row[P_DECAY]


@njit(cache=True, inline="always")
def magnet_force(row, current, u):
    """The magnets' force on the rotor along one axis at full strength [N]: linearised, or the circuit's."""
    k = row[P_CIRCUIT]
    if k <= 0.0:
        force = row[P_KI_FORCE] * current + row[P_KS] * u
    else:
        i0, g0 = row[P_BIAS], row[P_GAP]
        near = max(g0 - u, MIN_GAP * g0)
        far = max(g0 + u, MIN_GAP * g0)
        force = k * ((i0 + current) ** 2 / (near * near) - (i0 - current) ** 2 / (far * far))
    capacity = row[P_FMAX]
    return min(max(force, -capacity), capacity)


@njit(cache=True)
def forces(row, times, fail, currents, displacements):
    """The axis' force on the rotor at each of ``times`` from its currents and the rotor's displacements [N]."""
    out = np.empty(times.size)
    for k in range(times.size):
        out[k] = strength(row, times[k], fail) * magnet_force(row, currents[k], displacements[k])
    return out


@njit(cache=True, inline="always")
def axis(row, t, fail, sensor_fail, u, sensed, y, out, at, controllers):
    """One axis whose states start at ``y[at]``: writes their rates into ``out``, returns the force on the rotor.

    ``fail`` and ``sensor_fail`` are the axis' failure times (row's P_FAIL_X or P_FAIL_Y and the sensor's);
    ``controllers`` holds the state-space controllers (:attr:`Params.controllers`). Unpowered, the rates stay 0.
    """
    order = int(row[P_ORDER])
    current = y[at + 1 + order]
    force = strength(row, t, fail) * magnet_force(row, current, u)
    if not powered(row, t, fail):
        return force
    measured = y[at]
    if t >= sensor_fail:
        sensed = measured if row[P_STUCK] > 0.0 else 0.0
    rate = row[P_WS] * (sensed - measured)
    out[at] = rate
    c = int(row[P_CONTROLLER_AT])
    if c < 0:
        command = -(row[P_KP] * measured + row[P_KI] * y[at + 1] + row[P_KD] * rate)
        out[at + 1] = measured
    else:
        b, cc = c + order * order, c + order * order + order
        command = -controllers[cc + order] * measured
        for j in range(order):
            acc = controllers[b + j] * measured
            for k in range(order):
                acc += controllers[c + j * order + k] * y[at + 1 + k]
            out[at + 1 + j] = acc
            command -= controllers[cc + j] * y[at + 1 + j]
    limit = row[P_IMAX]
    command = min(max(command, -limit), limit)
    slew = row[P_SLEW]
    out[at + 1 + order] = min(max(row[P_WA] * (command - current), -slew), slew)
    return force
