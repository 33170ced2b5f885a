"""A load on the rotor in time: a force, a sudden unbalance or an acceleration of the machine's base.

The overloads that drive a rotor into its touchdown bearings while the magnetic bearings still work (ISO
14839-5 names them among the conditions a touchdown bearing is designed for): a process surge or a shock
load, a blade lost at speed, an earthquake or a shock on the base. Each row is one of :data:`KINDS`, switched
on at ``start`` with a time profile:

* step: full value from ``start`` for ``duration`` (inf: to the end of the run);
* half sine: value sin(pi (t - start) / duration) for ``duration``, the classic shock pulse (ISO 18431-4 and
  MIL-STD-810's half-sine shock).

Kinds:

* force: (F_x, F_y) [N] on the rotor's axis at the row's axial position;
* unbalance: an unbalance U [kg m] appearing at phase beta on the rotor at the row's position (a blade lost);
  its force on the shaft is U Omega^2 (cos th, sin th), th = phi + beta, the centrifugal reaction of an
  eccentric mass turning with the rotor (Friswell et al. 2010, Sec. 3.5). Its tangential part U Omega' is left
  out: in a touchdown Omega' / Omega^2 stays below 1e-4. The rotor's own mass and inertia are not changed;
* base acceleration: the housing, the touchdown bearings' outer rings and the magnetic bearings' stators
  accelerate by (a_x, a_y) [m/s^2]; in their frame every body (rotor, races, outer rings) feels the
  d'Alembert field -a, which joins gravity (:func:`frame_field`). The elastic modes, M-orthogonal to a rigid
  translation, take no share of it.

Each row's work on the machine is booked in its ledger slot as energy taken (negative when it puts energy in),
so the energy audit closes. No states of its own.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

NAME = "load"
KINDS = ("force", "unbalance", "base_acceleration")
K_FORCE, K_UNBALANCE, K_BASE = range(len(KINDS))
SHAPES = ("step", "half_sine")
S_STEP, S_HALF_SINE = range(len(SHAPES))
#: value_x, value_y: (F_x, F_y) [N] for a force; (U [kg m], beta [rad]) for an unbalance; (a_x, a_y) [m/s^2]
#: for a base acceleration.
FIELDS = ("position", "kind", "value_x", "value_y", "start", "duration", "shape")
P_POS, P_KIND, P_VX, P_VY, P_START, P_DURATION, P_SHAPE = range(len(FIELDS))
STATES: tuple[str, ...] = ()
LEDGER = ("load_work_taken",)


class Params(NamedTuple):
    """Every load of a machine."""

    values: np.ndarray  #: (loads, len(FIELDS)) SI
    shape_x: np.ndarray  #: (loads, modes) each elastic mode's x displacement at the load's position
    shape_y: np.ndarray


def no_loads(n_modes: int = 0) -> Params:
    """A machine without loads."""
    return Params(np.zeros((0, len(FIELDS))), np.zeros((0, n_modes)), np.zeros((0, n_modes)))


@njit(cache=True, inline="always")
def profile(row, t):
    """The load's share of its value at t: 0 before ``start`` and after its duration, 1 or the half sine."""
    elapsed = t - row[P_START]
    if elapsed < 0.0 or elapsed >= row[P_DURATION]:
        return 0.0
    if row[P_SHAPE] == S_HALF_SINE:
        return math.sin(math.pi * elapsed / row[P_DURATION])
    return 1.0


@njit(cache=True, inline="always")
def force(row, t, phi, omega):
    """(F_x, F_y) of a force or unbalance row on the rotor's axis at the row's position [N]."""
    share = profile(row, t)
    if share == 0.0 or row[P_KIND] == K_BASE:
        return 0.0, 0.0
    if row[P_KIND] == K_FORCE:
        return share * row[P_VX], share * row[P_VY]
    th = phi + row[P_VY]
    u = share * row[P_VX] * omega * omega
    return u * math.cos(th), u * math.sin(th)


@njit(cache=True, inline="always")
def base_field(row, t):
    """The d'Alembert field (-a_x, -a_y) of a base-acceleration row at t [m/s^2] (0 for other kinds)."""
    if row[P_KIND] != K_BASE:
        return 0.0, 0.0
    share = profile(row, t)
    return -share * row[P_VX], -share * row[P_VY]
