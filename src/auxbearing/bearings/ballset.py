"""The ball-set model for people: pack a bearing for the kernels, evaluate it over many states.

Mirror of :mod:`auxbearing.core.ballset` (the one contact-pair kernel): this module turns a
:class:`~auxbearing.bearings.geometry.BearingGeometry` into the kernel's :class:`~auxbearing.core.ballset.BallSet`
(the Hertz tables against contact angle) and offers the array face :func:`ballset_state`.
"""

from __future__ import annotations

import math
from functools import lru_cache
from typing import NamedTuple

import numpy as np

from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.core import ballset as kernel
from auxbearing.core import hertz
from auxbearing.core.ballset import BallSet

#: Nodes of the Hertz tables over |alpha| in [0, 90] deg (0.125 deg spacing). Measured interpolation
#: error against the exact Hertz solution at the mid-points (QJ202): below 1e-13 relative.
TABLE_POINTS = 721
_TABLE_MAX = 0.5 * math.pi
_FD_STEP = 1e-5  # [rad] central-difference step for the node slopes (error ~ h^2 ~ 1e-10)

__all__ = ["TABLE_POINTS", "BallSet", "BallSetState", "ball_constant_table", "ballset_params", "ballset_state",
           "hertz_tables"]


def _exact_rows(bearing: BearingGeometry, alpha: np.ndarray) -> list[np.ndarray]:
    """K_b, stress and semi-major-axis coefficients at contact angles ``alpha`` (exact Hertz)."""
    eta = bearing.contact_compliance
    d, dm = bearing.ball_diameter, bearing.pitch_diameter
    s_i, f_i = hertz.ball_raceway_curvature(d, dm, bearing.inner_groove_ratio, alpha, "inner")
    s_o, f_o = hertz.ball_raceway_curvature(d, dm, bearing.outer_groove_ratio, alpha, "outer")
    unit_i = hertz.point_contact(1.0, s_i, f_i, eta)  # a ~ Q^(1/3): the 1 N contact gives the coefficient
    unit_o = hertz.point_contact(1.0, s_o, f_o, eta)
    k_b = hertz.series_constant(unit_i.stiffness, unit_o.stiffness)
    rows = [k_b, hertz.stress_coefficient(s_i, f_i, eta), hertz.stress_coefficient(s_o, f_o, eta),
            unit_i.semi_major, unit_o.semi_major]
    return [np.asarray(row, float) for row in rows]


def hertz_tables(bearing: BearingGeometry) -> tuple[np.ndarray, np.ndarray]:
    """Node angles and the tables of the kernel, each row with its slope.

    Returns
    -------
    alpha : ndarray, shape (n,)
        Node contact angles [rad].
    tables : ndarray, shape (5, 2, n)
        Rows :data:`~auxbearing.core.ballset.TABLE_NAMES`: K_b [N/m^1.5] (source paper Eq. 15), inner
        and outer stress coefficients C [Pa/N^(1/3)] with sigma_max = C Q^(1/3) (Eq. 4-8), inner and
        outer semi-major-axis coefficients [m/N^(1/3)] (Eq. 4); column 1 holds d/d alpha.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> alpha, tab = hertz_tables(get_bearing("QJ202"))
    >>> f"{np.interp(np.radians(35.0), alpha, tab[0, 0]):.4e}"
    '8.0514e+09'
    """
    alpha = np.linspace(0.0, _TABLE_MAX, TABLE_POINTS)
    mid = _exact_rows(bearing, alpha)
    plus = _exact_rows(bearing, alpha + _FD_STEP)
    minus = _exact_rows(bearing, alpha - _FD_STEP)
    tables = np.empty((len(mid), 2, TABLE_POINTS))
    for i, (value, hi, lo) in enumerate(zip(mid, plus, minus, strict=True)):
        tables[i, 0] = value
        tables[i, 1] = (hi - lo) / (2.0 * _FD_STEP)
    return alpha, tables


def ball_constant_table(bearing: BearingGeometry) -> tuple[np.ndarray, np.ndarray]:
    """Nodes in cos(alpha) and the kernel's K_b table on them (:func:`auxbearing.core.ballset.ball_constant`).

    Returns
    -------
    cosines : ndarray, shape (n,)
        cos(alpha) of the nodes, evenly spaced over [0, 1].
    table : ndarray, shape (2, n)
        K_b [N/m^1.5] (source paper Eq. 15) and its slope d/d cos(alpha): central differences, one-sided
        (second order) at cos(alpha) = 1, the end of the range.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> cosines, tab = ball_constant_table(get_bearing("QJ202"))
    >>> f"{np.interp(np.cos(np.radians(35.0)), cosines, tab[0]):.4e}"
    '8.0514e+09'
    """
    cosines = np.linspace(0.0, 1.0, TABLE_POINTS)
    def k_b(c):
        return _exact_rows(bearing, np.arccos(c))[kernel.K_B]
    value = k_b(cosines)
    h = _FD_STEP
    slope = (k_b(np.minimum(cosines + h, 1.0)) - k_b(cosines - h)) / (np.minimum(cosines + h, 1.0) - (cosines - h))
    slope[-1] = (3.0 * value[-1] - 4.0 * k_b(np.array([1.0 - h]))[0] + k_b(np.array([1.0 - 2.0 * h]))[0]) / (2.0 * h)
    return cosines, np.stack([value, slope])


@lru_cache(maxsize=64)
def _cached(bearing: BearingGeometry, ball_constant: float | None) -> BallSet:
    _, tables = hertz_tables(bearing)
    _, constant = ball_constant_table(bearing)
    if ball_constant is not None:  # a user's K_b holds at every angle; stresses stay Hertz
        tables[kernel.K_B, 0] = ball_constant
        tables[kernel.K_B, 1] = 0.0
        constant[0] = ball_constant
        constant[1] = 0.0
    z = bearing.ball_count
    azimuths = 2.0 * np.pi * np.arange(z) / z
    return BallSet(
        signs=np.asarray(bearing.axial_signs, float),
        cos_azimuth=np.cos(azimuths),
        sin_azimuth=np.sin(azimuths),
        curvature_distance=float(bearing.curvature_centre_distance),
        free_angle=float(bearing.contact_angle),
        cos_free_angle=math.cos(bearing.contact_angle),
        sin_free_angle=math.sin(bearing.contact_angle),
        clearance=float(bearing.diametral_clearance),
        moment_arm=float(bearing.inner_curvature_centre_radius),
        table_step=_TABLE_MAX / (TABLE_POINTS - 1),
        tables=tables,
        constant_step=1.0 / (TABLE_POINTS - 1),
        constant_table=constant,
    )


def ballset_params(bearing: BearingGeometry, ball_constant: float | None = None) -> BallSet:
    """The kernel's view of a bearing (cached per bearing).

    Parameters
    ----------
    bearing : BearingGeometry
    ball_constant : float, optional
        K_b [N/m^1.5] to use at every contact angle instead of the Hertz value (Eq. 15); stresses
        still come from Hertz.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> bs = ballset_params(get_bearing("QJ202"))
    >>> bs.cos_azimuth.size, bs.signs.size, round(bs.curvature_distance * 1e3, 4)
    (11, 2, 0.24)
    """
    if ball_constant is not None:
        ball_constant = float(ball_constant)
        if not math.isfinite(ball_constant) or ball_constant <= 0.0:
            raise ValueError(f"ball_constant = {ball_constant!r} N/m^1.5: must be > 0 and finite")
    return _cached(bearing, ball_constant)


class BallSetState(NamedTuple):
    """Ball-set state over displacement states ``(...)``, balls and pairs."""

    distance: np.ndarray  #: S, loaded curvature-centre distance [m], (..., Z, P)
    compression: np.ndarray  #: S - A [m] (negative: pair open), (..., Z, P)
    load: np.ndarray  #: contact-pair load Q [N], (..., Z, P)
    contact_angle: np.ndarray  #: loaded contact angle [rad], (..., Z, P)
    stress_inner: np.ndarray  #: Hertz max stress at the inner race [Pa], (..., Z, P)
    stress_outer: np.ndarray  #: Hertz max stress at the outer race [Pa], (..., Z, P)
    force: np.ndarray | None  #: (Fa, Fx, Fy, Mx, My) ON the inner ring [N, N m], (..., 5); None unless asked
    jacobian: np.ndarray | None  #: d force / d displacement, (..., 5, 5); None unless asked


def ballset_state(displacement, params: BallSet, clearance: float | None = None,
                  resultant: bool = True) -> BallSetState:
    """Ball-set model over many 5-DOF displacement states (source paper Eq. 10-16).

    Parameters
    ----------
    displacement : array_like, shape (..., 5)
        (delta_a, dx, dy, theta_x, theta_y) [m, m, m, rad, rad] of the inner ring.
    params : BallSet
        :func:`ballset_params`.
    clearance : float, optional
        Diametral clearance [m]; default the bearing's.
    resultant : bool
        Also the resultant on the inner ring and its Jacobian (``force``, ``jac``); False leaves them None.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> st = ballset_state([0.0, 10e-6, 0.0, 0.0, 0.0], ballset_params(get_bearing("QJ202")))
    >>> st.load.shape, bool(np.allclose(st.load[0, 0], st.load[0, 1]))
    ((11, 2), True)
    """
    u = np.asarray(displacement, float)
    lead = u.shape[:-1]
    flat = np.ascontiguousarray(u.reshape(-1, 5))
    n, z, p = flat.shape[0], params.cos_azimuth.size, params.signs.size
    per_pair = [np.empty((n, z, p)) for _ in range(6)]
    force = np.empty((n if resultant else 0, 5))
    jac = np.empty((n if resultant else 0, 5, 5))
    pd = params.clearance if clearance is None else float(clearance)
    load, angle, compression, distance, s_i, s_o = per_pair
    kernel.pair_states(flat, params, pd, load, angle, compression, distance, s_i, s_o, force, jac, resultant)
    shape = (*lead, z, p)
    return BallSetState(distance.reshape(shape), compression.reshape(shape), load.reshape(shape),
                        angle.reshape(shape), s_i.reshape(shape), s_o.reshape(shape),
                        force.reshape(*lead, 5) if resultant else None,
                        jac.reshape(*lead, 5, 5) if resultant else None)
