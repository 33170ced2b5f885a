"""What the observer and the outputs measure at a state of the machine (compiled, SI).

The observer passes :func:`refine_target` and :func:`gap` to the dense-output searches as
``probes.refine_target``: numba 0.68 caches a function that passes compiled functions as arguments
only when they are reached as module attributes, not as plain global names.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from auxbearing.core.ballset import STRESS_INNER, pair, pair_extents
from auxbearing.core.machine import (
    D_FA,
    D_FN,
    D_PEN,
    DIAG_FIELDS,
    N_PLANE,
    N_ROTOR,
    OX,
    OY,
    RX,
    RY,
    RZ,
    Machine,
    journal_gap,
    journal_point,
    plane_forces_once,
    ring_travel,
    rotor_kinematics,
    row_displacement,
)
from auxbearing.core.uncounted import uncounted

#: :func:`limits_out_of_reach` answers True only when both of its bounds stay below this share of their limit
#: (the bounds are exact; the share leaves room for the rounding of the two ways of evaluating the same state).
LIMIT_REACH = 0.99


@njit(cache=True)
def plane_diagnostics(y, m, k):
    """:data:`~auxbearing.core.machine.DIAG_FIELDS` of plane k at state ``y``."""
    diag = np.empty(len(DIAG_FIELDS))
    _diagnostics_into(y, m, k, np.zeros(y.size), np.zeros(6), diag)
    return diag


@njit(cache=True, inline="always")
def _diagnostics_into(y, m, k, out, q, diag):
    """:func:`plane_diagnostics` into ``diag``, with ``out`` (n,) and ``q`` (6,) as working memory."""
    for i in range(out.size):
        out[i] = 0.0
    for i in range(q.size):
        q[i] = 0.0
    plane_forces_once(k, y, m, rotor_kinematics(y, m.rotor), q, out, diag)


#: Bounds of the coefficient tables are inflated by this factor where they decide that a contact can be skipped
#: (:func:`ball_extremes`), so that the rounding of the two ways of evaluating a contact never skips the largest.
BOUND_SLACK = 1.0 + 1e-9


@njit(cache=True, inline="always")
def _may_reach(q, x, target, radius, axis_bound):
    """Whether a pair of load q at |alpha| = x can reach (x + a / radius) >= ``target`` with a <= axis_bound q^(1/3)."""
    room = (target - x) * radius / (axis_bound * BOUND_SLACK)
    return room <= 0.0 or q >= room * room * room


@uncounted
def ball_extremes(y, m, k, bounds):
    """Largest Hertz stress of plane k's ball contacts [Pa] and the largest shoulder use (alpha + a/r)/shoulder.

    ``bounds`` (4,) holds the bounds of the stress and semi-major-axis tables (:func:`table_bound`, filled here
    when negative, as :func:`limits_out_of_reach` keeps them); with them a contact whose load cannot beat the
    largest stress and shoulder use found so far (sigma <= C_max Q^(1/3), a <= c_max Q^(1/3)) is not evaluated,
    which leaves both maxima as they are. An empty ``bounds`` evaluates every contact.
    """
    b = N_ROTOR + k * N_PLANE
    bs = m.ballsets[k]
    pd = m.ballset_clearance[k]
    lim = m.limits
    prune = bounds.size == 4
    if prune:
        fill_bounds(bs, bounds)
    r_in, r_out = lim.groove_radius_inner[k], lim.groove_radius_outer[k]
    psi_in, psi_out = lim.shoulder_angle_inner[k], lim.shoulder_angle_outer[k]
    worst = 0.0
    use = 0.0
    beaten = 0.0  # a pair at or below this load cannot beat ``worst``: C_max q^(1/3) <= worst
    for row in range(2 if m.planes.rows[k] > 1.0 else 1):
        zr, dx, dy = row_displacement(m, k, row, y[b + RZ], y[b + RX] - y[b + OX], y[b + RY] - y[b + OY])
        for j in range(bs.cos_azimuth.size):
            radial = dx * bs.cos_azimuth[j] + dy * bs.sin_azimuth[j]
            for i in range(bs.signs.size):
                q, alpha, _, _, _, _, _, _ = pair(bs.signs[i], zr, radial, bs, pd, False, True)
                if q <= 0.0:
                    continue
                x = abs(alpha)
                if prune and q <= beaten and not (_may_reach(q, x, use * psi_in, r_in, bounds[2])
                                                  or _may_reach(q, x, use * psi_out, r_out, bounds[3])):
                    continue
                s_i, s_o, a_i, a_o = pair_extents(q, alpha, bs)
                if max(s_i, s_o) > worst:
                    worst = max(s_i, s_o)
                    if prune:
                        top = worst / (max(bounds[0], bounds[1]) * BOUND_SLACK)
                        beaten = top * top * top
                use = max(use, (x + a_i / r_in) / psi_in, (x + a_o / r_out) / psi_out)
    return worst, use


@uncounted
def table_bound(bs, row):
    """An upper bound of table ``row`` of a ball set over every contact angle (:func:`~auxbearing.core.ballset.table`).

    On a node interval the cubic Hermite interpolant is y0 h00 + y1 h01 + m0 h10 + m1 h11 with h00, h01 >= 0
    summing to 1 and |h10|, |h11| <= 4/27 (Burden & Faires, *Numerical Analysis*, Sec. 3.4), so it stays below
    max(y0, y1) + 4/27 (|m0| + |m1|); beyond the last node the table is constant.
    """
    values = bs.tables[row, 0]
    slopes = bs.tables[row, 1]
    h = bs.table_step
    bound = values[values.size - 1]
    for i in range(values.size - 1):
        bound = max(bound, max(values[i], values[i + 1]) + 4.0 / 27.0 * h * (abs(slopes[i]) + abs(slopes[i + 1])))
    return bound


@njit(cache=True, inline="always")
def fill_bounds(bs, bounds):
    """Fill ``bounds`` (4,) with :func:`table_bound` of the inner and outer stress and semi-major-axis rows, once."""
    if bounds[0] < 0.0:
        for i in range(4):
            bounds[i] = table_bound(bs, STRESS_INNER + i)


@uncounted
def limits_out_of_reach(y, m, k, qmax, bounds):
    """True when no ball contact of plane k can reach the ball-stress limit or run over a groove shoulder.

    Upper bounds of what :func:`ball_extremes` evaluates contact by contact, from the largest pair load ``qmax``
    alone: sigma = C(alpha) Q^(1/3) <= C_max qmax^(1/3), and (|alpha| + c_a(alpha) Q^(1/3) / R) / psi with
    |alpha| = atan(|a| / r) at most atan((A sin(alpha0) + |delta_a|) / (A cos(alpha0) - Pd/2 - |d|)) for the
    ring's axial and radial displacement delta_a, d (the pair geometry of :func:`auxbearing.core.ballset.pair`).
    ``bounds`` holds the table bounds (:func:`table_bound`: inner and outer stress, inner and outer
    semi-major axis), filled here when negative. Both bounds must stay below :data:`LIMIT_REACH` of their limit.
    """
    bs = m.ballsets[k]
    fill_bounds(bs, bounds)
    if qmax <= 0.0:
        return True
    lim = m.limits
    cube = qmax ** (1.0 / 3.0)
    if max(bounds[0], bounds[1]) * cube >= LIMIT_REACH * lim.ball_stress:
        return False
    b = N_ROTOR + k * N_PLANE
    big_a = bs.curvature_distance
    worst = 0.0
    for row in range(2 if m.planes.rows[k] > 1.0 else 1):
        zr, dx, dy = row_displacement(m, k, row, y[b + RZ], y[b + RX] - y[b + OX], y[b + RY] - y[b + OY])
        r_min = big_a * bs.cos_free_angle - 0.5 * m.ballset_clearance[k] - math.hypot(dx, dy)
        if r_min <= 0.0:
            return False
        worst = max(worst, math.atan((big_a * bs.sin_free_angle + abs(zr)) / r_min))
    use = max((worst + bounds[2] * cube / lim.groove_radius_inner[k]) / lim.shoulder_angle_inner[k],
              (worst + bounds[3] * cube / lim.groove_radius_outer[k]) / lim.shoulder_angle_outer[k])
    return use < LIMIT_REACH


class Probe(NamedTuple):
    """What the observer's dense-output searches evaluate a state with: the machine and working memory.

    The searches run inside the observer, which counts no references (:mod:`auxbearing.core.uncounted`), so
    nothing below it may allocate: the working arrays come from the observer's memory.
    """

    machine: Machine
    out: np.ndarray  #: (n,) the derivative's slots the plane's forces write
    q: np.ndarray  #: (6,) the rotor's generalised forces
    diag: np.ndarray  #: (len(DIAG_FIELDS),) the plane's diagnostics
    bounds: np.ndarray  #: (planes, 4) bounds of the coefficient tables (:func:`fill_bounds`)


@uncounted
def refine_target(y, probe, arg):
    """What the observer refines a peak of: arg = 3 k + what (0 line force, 1 ball stress, 2 |axial force|)."""
    k = arg // 3
    what = arg % 3
    if what == 1:
        return ball_extremes(y, probe.machine, k, probe.bounds[k])[0]
    _diagnostics_into(y, probe.machine, k, probe.out, probe.q, probe.diag)
    return probe.diag[D_FN] if what == 0 else abs(probe.diag[D_FA])


@uncounted
def gap(y, probe, k):
    """Journal/race penetration of plane k [m] (negative: open): the observer's contact-onset function."""
    _diagnostics_into(y, probe.machine, k, probe.out, probe.q, probe.diag)
    return probe.diag[D_PEN]


@njit(cache=True, inline="always")
def orbit(y, m, k):
    """Journal centre relative to the outer-ring centre of plane k (x, y) [m]."""
    b = N_ROTOR + k * N_PLANE
    jx, jy, _, _ = journal_point(y, m, k)
    return jx - y[b + OX], jy - y[b + OY]


@njit(cache=True)
def series(grid, m, with_stress):
    """Per output instant and plane block: diagnostics and largest ball stress, (n, planes, len(DIAG_FIELDS) + 1).

    Without ``with_stress`` the stress column is left at zero (a summary that needs no time series of it).
    """
    n_planes = len(m.planes.active)
    out = np.zeros((grid.shape[0], n_planes, len(DIAG_FIELDS) + 1))
    _series_into(grid, m, with_stress, out, np.zeros(grid.shape[1]), np.zeros(6), np.zeros(len(DIAG_FIELDS)),
                 np.full((n_planes, 4), -1.0))
    return out


@uncounted
def _series_into(grid, m, with_stress, out, work, q, diag, bounds):
    """:func:`series` into ``out``, with its working memory given (a row's plane forces count no references)."""
    for i in range(grid.shape[0]):
        for k in range(len(m.planes.active)):
            if m.planes.active[k] <= 0.0:
                continue
            _diagnostics_into(grid[i], m, k, work, q, diag)
            for j in range(diag.size):
                out[i, k, j] = diag[j]
            if with_stress:
                out[i, k, diag.size] = ball_extremes(grid[i], m, k, bounds[k])[0]


@njit(cache=True)
def contact_series(grid, m):
    """Per output instant and plane block: journal/race penetration and the ring's mount travel, (n, planes, 2) [m].

    What a lean run's summary reads over time (contact fraction, largest bounce, mount travel), by the arithmetic of
    :func:`auxbearing.core.machine.plane_forces` (:func:`~auxbearing.core.machine.journal_gap`,
    :func:`~auxbearing.core.machine.ring_travel`) without its forces: equal to :func:`series`' columns to the bit,
    at a sixtieth of its cost (0.49 against 32.8 ms on a blower drop's 20 001 rows).
    """
    p = m.planes
    n_planes = len(p.active)
    out = np.zeros((grid.shape[0], n_planes, 2))
    for i in range(grid.shape[0]):
        y = grid[i]
        for k in range(n_planes):
            if p.active[k] <= 0.0:
                continue
            b = N_ROTOR + k * N_PLANE
            jx, jy, _, _ = journal_point(y, m, k)
            out[i, k, 0] = journal_gap(jx, jy, y[b + RX], y[b + RY], p.clearance[k])[3]
            if p.ring_free[k] > 0.0:
                out[i, k, 1] = ring_travel(y[b + OX], y[b + OY], p, k)[2]
    return out
