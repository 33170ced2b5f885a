"""A linear support: a station that pushes on the rotor through a 2x2 stiffness and damping.

Seals, dampers, a bearing linearised about its operating point, an FE model's own bearings kept as stations.

F = -K u - C u', u the rotor axis' lateral displacement at the station's axial position a (rigid motion and
bending) and u' its velocity; K and C are general 2x2 matrices, k_xy != k_yx being the cross-coupled stiffness
of a seal or a fluid-film bearing (the dynamic coefficients of J. W. Lund, "Review of the concept of dynamic
coefficients for fluid film journal bearings", ASME J. Tribol. 109, 1987, 37-41). The symmetric part
of K stores energy (u^T K_s u / 2); the work of the rest of the force, the cross-coupling's and the
damping's, is booked in the station's ledger slot (energy taken from the mechanics), so the energy audit
closes. No states of its own.

Parameters: one row per station of :data:`FIELDS` (SI) in :attr:`Params.values` (an array, so that any number
of supports shares one compiled kernel).
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np
from numba import njit

NAME = "linear_support"
#: Each station's parameters, in the columns of :attr:`Params.values`.
FIELDS = ("position", "kxx", "kxy", "kyx", "kyy", "cxx", "cxy", "cyx", "cyy")
STATES: tuple[str, ...] = ()
LEDGER = ("support_loss",)


class Params(NamedTuple):
    """Every linear support of a machine."""

    values: np.ndarray  #: (stations, len(FIELDS)) [m, N/m, N s/m]
    shape_x: np.ndarray  #: (stations, modes) each elastic mode's x displacement at each station [1/sqrt(kg)]
    shape_y: np.ndarray  #: (stations, modes)


def no_stations(n_modes: int = 0) -> Params:
    """A machine without linear supports."""
    return Params(np.zeros((0, len(FIELDS))), np.zeros((0, n_modes)), np.zeros((0, n_modes)))


@njit(cache=True, inline="always")
def _motion(row, jx, jy, vx, vy):
    """The support's force on the rotor (x, y) and the rate its non-conservative part takes energy [N, W]."""
    kxx, kxy, kyx, kyy, cxx, cxy, cyx, cyy = row[1], row[2], row[3], row[4], row[5], row[6], row[7], row[8]
    fx = -(kxx * jx + kxy * jy + cxx * vx + cxy * vy)
    fy = -(kyx * jx + kyy * jy + cyx * vx + cyy * vy)
    skew = 0.5 * (kxy - kyx)  # K - K_s = [[0, skew], [-skew, 0]]
    taken = (skew * jy + cxx * vx + cxy * vy) * vx + (-skew * jx + cyx * vx + cyy * vy) * vy
    return fx, fy, taken


@njit(cache=True, inline="always")
def energy(row, jx, jy):
    """Energy stored in the support's symmetric stiffness at displacement (jx, jy) [J]."""
    kxx, kyy, ks = row[1], row[4], 0.5 * (row[2] + row[3])
    return 0.5 * (kxx * jx * jx + 2.0 * ks * jx * jy + kyy * jy * jy)


@njit(cache=True, inline="always")
def force(row, jx, jy, vx, vy):
    """(fx, fy, energy-taking rate) of one support at the rotor's displacement and velocity there."""
    return _motion(row, jx, jy, vx, vy)
