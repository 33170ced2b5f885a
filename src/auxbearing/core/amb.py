"""An active magnetic bearing: a station that holds the rotor through its controller until it fails.

Per axis (x and y alike), linearised about the bias (G. Schweitzer and E. H. Maslen, eds., *Magnetic Bearings*,
Springer, 2009: the linearised force law and decentralised PID control):

* force on the rotor at the actuator, F = g(t) (k_i i + k_s u), u the rotor's displacement there, k_s > 0 the
  negative (destabilising) stiffness of the bias flux;
* sensor: the displacement at the sensor through a first-order lag of bandwidth w_s, x_m' = w_s (x_s - x_m);
* controller: i_c = -(k_p x_m + k_int X + k_d x_m'), X' = x_m (a PID whose derivative is the sensor's filtered
  rate);
* amplifier: i' = w_a (sat(i_c) - i), the command clipped at the current limit.

Below the speed of the controller, a PD law gives the closed-loop stiffness k_i k_p - k_s and damping k_i k_d.
At the failure time the amplifier loses its power: the states freeze and the force decays as
g = exp(-(t - t_f) / tau), the coils' discharge (tau = 0: at once). The station's work on the rotor (the
controller's and the bias's) is booked in its ledger slot as energy taken, so the energy audit closes.

Parameters: one row per station of :data:`FIELDS` (SI) in :attr:`Params.values`; states per station
:data:`STATES`.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

NAME = "amb"
FIELDS = ("position", "sensor_position", "current_stiffness", "position_stiffness", "kp", "ki", "kd",
          "sensor_bandwidth", "amplifier_bandwidth", "max_current", "fail_time", "decay_time")
(P_POS, P_SENSOR, P_KI_FORCE, P_KS, P_KP, P_KI, P_KD, P_WS, P_WA, P_IMAX, P_FAIL, P_DECAY) = range(len(FIELDS))
#: Per station: the measured displacement, the integral of it and the coil current, for x then y.
STATES = ("amb_measured_x", "amb_integral_x", "amb_current_x", "amb_measured_y", "amb_integral_y", "amb_current_y")
S_MEASURED, S_INTEGRAL, S_CURRENT = range(3)
LEDGER = ("amb_work_taken",)


class Params(NamedTuple):
    """Every magnetic bearing of a machine."""

    values: np.ndarray  #: (stations, len(FIELDS)) SI
    shape_x: np.ndarray  #: (stations, modes) each elastic mode's x displacement at the actuator
    shape_y: np.ndarray
    sensor_shape_x: np.ndarray  #: (stations, modes) and at the sensor
    sensor_shape_y: np.ndarray


def no_stations(n_modes: int = 0) -> Params:
    """A machine without magnetic bearings."""
    z = np.zeros((0, n_modes))
    return Params(np.zeros((0, len(FIELDS))), z, z.copy(), z.copy(), z.copy())


@njit(cache=True, inline="always")
def strength(row, t):
    """g(t): 1 while powered, the coils' decay after the failure time."""
    if t < row[P_FAIL]:
        return 1.0
    if row[P_DECAY] <= 0.0:
        return 0.0
    return math.exp(-(t - row[P_FAIL]) / row[P_DECAY])


@njit(cache=True, inline="always")
def axis(row, t, u, sensed, measured, integral, current):
    """One axis: (force on the rotor, d measured/dt, d integral/dt, d current/dt)."""
    force = strength(row, t) * (row[P_KI_FORCE] * current + row[P_KS] * u)
    if t >= row[P_FAIL]:
        return force, 0.0, 0.0, 0.0
    rate = row[P_WS] * (sensed - measured)
    command = -(row[P_KP] * measured + row[P_KI] * integral + row[P_KD] * rate)
    limit = row[P_IMAX]
    command = min(max(command, -limit), limit)
    return force, rate, measured, row[P_WA] * (command - current)
