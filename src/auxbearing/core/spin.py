"""The coast-down's reduced model: the spin speeds of rotor and races under the losses a window measured (SI).

A settled stretch of a coast-down (:mod:`auxbearing.analysis.coastdown_phases` says which states qualify) keeps
only the slow quantities: the rotor's spin speed Omega, each race's spin speed and the energy integrals.
Each touchdown plane is either *coupled* to the rotor (its race rolls on the journal, so
w_race = rho Omega with the ratio rho the last window measured: rolling without slip, rho = r/R, or a
steady backward rolling whirl, rho = (r + s lambda)/R with lambda = w_whirl/Omega from the same
no-slip condition s w_whirl = R w_race - r Omega) or *free* (out of contact: the race spins down on
its own bearing torque).

Losses: each plane's journal-contact and mount powers as torques on the rotor speed, constant over
the stretch (their loads, gravity or a whirl's centripetal force, do not follow the spin); the
bearing's own torque as Palmgren's load-free viscous torque M_0(w_race) (Harris & Kotzalas 2007,
Essential Concepts, Ch. 10, :func:`auxbearing.core.bearing_friction.palmgren_viscous_torque`), which
the right-hand side evaluates at every speed, plus the rest of the measured bearing power (rolling
resistance, ball-set damping) as a constant torque on the race; the rotor's drag law
T0 + c1 Omega + c2 Omega^2 and the process torque. Energy of spin (the kinetic energy of a whirling
journal, m (s w_whirl)^2 / 2, is of order 1e-6 of it and is left out):

    (J_p + sum_coupled J_race rho^2) dOmega/dt = -sum_coupled P_k / Omega - T_drag + T_process
    J_race dw_race/dt = -(T_rest + M_0(w_race))                                          (free planes)

with P_k = (T_contact + T_mount) |Omega| + (T_rest + M_0(w_race)) |w_race|. Torques carry
tanh(speed / scale) so that a speed through zero meets no jump (as the full model's drag).

State layout (:func:`layout`, from the number of planes): rotor speed, race speeds, heats, drag loss, work in,
race turns, rotor turn. :func:`observe` stops the integration where |Omega| falls to the
stretch's floor (a speed step, or standstill), located on the dense output.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from auxbearing.core import integrate as ig
from auxbearing.core.bearing_friction import palmgren_viscous_torque

OMEGA = 0
RACE_AT = 1  #: + k: race spin speed of plane k [rad/s]


class Layout(NamedTuple):
    """Where each quantity sits in the state of a stretch with ``planes`` planes (:func:`layout`)."""

    planes: int
    heat_at: int  #: + 3 k + (0 contact, 1 bearing, 2 mount) [J]
    drag_loss: int  #: [J]
    work_in: int  #: work of the process torque [J]
    turn_at: int  #: + k: angle the race of plane k turned [rad]
    rotor_turn: int  #: angle the rotor turned [rad]
    size: int


@njit(cache=True, inline="always")
def layout(n_planes):
    """The state layout of a stretch with ``n_planes`` planes (module docstring)."""
    heat_at = RACE_AT + n_planes
    drag_loss = heat_at + 3 * n_planes
    turn_at = drag_loss + 2
    return Layout(n_planes, heat_at, drag_loss, drag_loss + 1, turn_at, turn_at + n_planes, turn_at + n_planes + 1)


class SpinModel(NamedTuple):
    """Parameters of one stretch (SI); per-plane fields are tuples of one float per plane."""

    inertia: float  #: J_p + sum over coupled planes of J_race rho^2 [kg m^2]
    drag_constant: float  #: T0 [N m]
    drag_viscous: float  #: c1 [N m s]
    drag_windage: float  #: c2 [N m s^2]
    speed_scale: float  #: regularisation speed of every constant torque [rad/s]
    process_torque: float  #: [N m], positive drives the rotor
    floor: float  #: the stretch ends where |Omega| falls to this [rad/s]
    active: tuple  #: 1.0 for a plane in use
    coupled: tuple  #: 1.0: the race turns at rho Omega; 0.0: free
    ratio: tuple  #: rho [-]
    contact_torque: tuple  #: journal-contact loss as a torque on the rotor [N m]
    mount_torque: tuple  #: mount-damper loss as a torque on the rotor [N m]
    bearing_torque: tuple  #: the bearing's measured torque beyond M_0, on the race [N m]
    race_inertia: tuple  #: [kg m^2]
    viscosity: tuple  #: oil kinematic viscosity [m^2/s] (0: no viscous torque)
    pitch_diameter: tuple  #: d_m [m]
    viscous_factor: tuple  #: Palmgren's f_0 [-]


@njit(cache=True, inline="always")
def _viscous(m, k, speed):
    if m.viscous_factor[k] <= 0.0 or m.viscosity[k] <= 0.0:
        return 0.0
    return palmgren_viscous_torque(m.viscosity[k], speed, m.pitch_diameter[k], m.viscous_factor[k])


@njit(cache=True)
def rhs(t, y, m, out):
    """d/dt of the stretch state (module docstring)."""
    for i in range(out.size):
        out[i] = 0.0
    om = y[OMEGA]
    sign = math.tanh(om / m.speed_scale)
    aom = abs(om)
    load = 0.0  # power-equivalent torque of the coupled planes on the rotor [N m]
    at = layout(len(m.active))
    for k in range(at.planes):
        if m.active[k] <= 0.0:
            continue
        wr = y[RACE_AT + k]
        race_sign = math.tanh(wr / m.speed_scale)
        bearing = (m.bearing_torque[k] + _viscous(m, k, wr)) * race_sign
        out[at.turn_at + k] = abs(wr)
        out[at.heat_at + 3 * k + 1] = bearing * wr
        if m.coupled[k] > 0.0:
            out[at.heat_at + 3 * k] = m.contact_torque[k] * sign * om
            out[at.heat_at + 3 * k + 2] = m.mount_torque[k] * sign * om
            load += (m.contact_torque[k] + m.mount_torque[k]) * sign + bearing * m.ratio[k] * (1.0 if wr * om >= 0.0
                                                                                               else -1.0)
        else:
            out[RACE_AT + k] = -bearing / m.race_inertia[k]
    drag = m.drag_constant * sign + m.drag_viscous * om + m.drag_windage * om * aom
    out[OMEGA] = (m.process_torque - drag - load) / m.inertia
    for k in range(at.planes):
        if m.active[k] > 0.0 and m.coupled[k] > 0.0:
            out[RACE_AT + k] = m.ratio[k] * out[OMEGA] * (1.0 if y[RACE_AT + k] * om >= 0.0 else -1.0)
    out[at.drag_loss] = drag * om
    out[at.work_in] = m.process_torque * om
    out[at.rotor_turn] = aom


@njit(cache=True)
def observe(t, h, y0, y1, coeff, m, obs):
    """Stop where |Omega| reaches the floor; ``obs`` (state size + 2,): the state there, then t and a flag.

    The crossing is bisected on the step's dense output (60 halvings, as
    :func:`auxbearing.core.integrate.dense_root`).
    """
    if abs(y1[OMEGA]) > m.floor:
        return 0
    tmp = np.empty(y1.size)
    lo, hi = 0.0, 1.0
    if abs(y0[OMEGA]) > m.floor:
        for _ in range(60):
            mid = 0.5 * (lo + hi)
            ig.dense_eval(coeff, mid, tmp)
            if abs(tmp[OMEGA]) <= m.floor:
                hi = mid
            else:
                lo = mid
    else:
        hi = 0.0
    ig.dense_eval(coeff, hi, tmp)
    for i in range(y1.size):
        obs[i] = tmp[i]
    obs[y1.size] = t + hi * h
    obs[y1.size + 1] = 1.0
    return 1


def new_state(omega: float, race_speeds, n_planes: int) -> np.ndarray:
    """A stretch's initial state for a model of ``n_planes`` planes: the speeds given, every integral zero."""
    y = np.zeros(layout.py_func(n_planes).size)
    y[OMEGA] = omega
    for k, w in enumerate(race_speeds):
        y[RACE_AT + k] = w
    return y
