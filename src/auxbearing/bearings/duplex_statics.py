"""Quasi-static equilibrium of a duplex set: both rows through the one ball-set kernel.

The shaft (both inner rings, clamped) moves by u = (delta_a, dx, dy, theta_x, theta_y) at the
set's centre against the housing (both outer rings). Row k sees M_k u plus its preload push
(:mod:`auxbearing.bearings.duplex`), the kernel :func:`auxbearing.core.ballset.accumulate` returns
that row's reaction f_k and stiffness J_k in the row's own coordinates, and the set's reaction is
sum M_k^T f_k with stiffness sum M_k^T J_k M_k. Equilibrium load + F(u) = 0 is solved by damped
Newton-Raphson with a backtracking line search on the residual norm, as for one bearing
(:mod:`auxbearing.core.statics`; Harris & Kotzalas 2007, Advanced Concepts Ch. 1), on rows scaled
to newtons (moments over the row's r_ic) and unknowns to metres.
"""

from __future__ import annotations

import math

import numpy as np

from auxbearing.bearings.duplex import DuplexSet
from auxbearing.common.errors import ConvergenceError, InputError

DEFAULT_TOL = 1e-9
MAX_ITER = 200


def _params(pair: DuplexSet):
    from auxbearing.bearings.ballset import ballset_params

    return ballset_params(pair.row)


def set_reaction(pair: DuplexSet, u, with_jac: bool = True):
    """Reaction of both rows ON the shaft [N, N m] at displacement ``u``, its Jacobian, and the row displacements.

    Returns
    -------
    force : ndarray (5,)
    jac : ndarray (5, 5)
        d force / d u.
    row_disp : list of ndarray (5,)
        Each row's own displacement (preload push included).

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> f, _, _ = set_reaction(get_bearing("7208 DB"), np.zeros(5))
    >>> bool(np.allclose(f, 0.0, atol=1e-6))   # the two preloads cancel
    True
    """
    from auxbearing.core.ballset import accumulate

    params = _params(pair)
    u = np.asarray(u, float)
    force = np.zeros(5)
    jac = np.zeros((5, 5))
    rows = []
    push = pair.row_preload_displacement
    for k in range(2):
        m = pair.row_map(k)
        uk = m @ u
        uk[0] += push
        fk = np.zeros(5)
        jk = np.zeros((5, 5))
        accumulate(uk, params, pair.row.diametral_clearance, fk, jk, with_jac, False)
        force += m.T @ fk
        if with_jac:
            jac += m.T @ jk @ m
        rows.append(uk)
    return force, jac, rows


def _scales(pair: DuplexSet):
    ric = _params(pair).moment_arm
    return np.array([1.0, 1.0, 1.0, 1.0 / ric, 1.0 / ric]), np.array([1.0, 1.0, 1.0, ric, ric])


def _start(pair: DuplexSet, load: np.ndarray, free: np.ndarray, w: np.ndarray, xs: np.ndarray) -> np.ndarray:
    """A start along the load: the distance where the set's reaction along it balances the load (1-D)."""
    direction = np.where(free, load * w, 0.0)
    norm = float(np.linalg.norm(direction))
    if norm == 0.0:
        return np.zeros(5)
    phys = direction / norm / xs

    def along(tau):
        f, _, _ = set_reaction(pair, tau * phys, with_jac=False)
        return -float((direction / norm) @ (f * w))

    lo, hi = 0.0, 1e-9
    while along(hi) < norm and hi < pair.row.curvature_centre_distance:
        lo, hi = hi, 2.0 * hi
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        if along(mid) < norm:
            lo = mid
        else:
            hi = mid
    return 0.5 * (lo + hi) * phys


def solve_set(pair: DuplexSet, load, free=(True,) * 5, tol: float = DEFAULT_TOL) -> dict:
    """Equilibrium of the set under ``load`` = (Fa, Fx, Fy, Mx, My) on the shaft [N, N m].

    Parameters
    ----------
    pair : DuplexSet
    load : array_like (5,)
    free : sequence of 5 bool
        DOFs the shaft may move in; a fixed one reports its reaction.
    tol : float
        Converged when the scaled residual is below tol times the largest load (or 1e-9 N).

    Returns
    -------
    dict
        ``displacement`` (5,), ``row_displacement`` (2, 5) in each row's coordinates, ``residual`` [N],
        ``iterations``, ``reaction`` (5,) of fixed DOFs.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> sol = solve_set(get_bearing("7208 DB"), [2000.0, 0.0, 0.0, 0.0, 0.0])
    >>> round(float(sol["displacement"][0]) * 1e6, 2), bool(sol["residual"] < 1e-3)
    (8.37, True)
    """
    load = np.asarray(load, float).reshape(5)
    free = np.asarray(free, bool)
    if not np.all(np.isfinite(load)):
        raise InputError.for_field("loads", load.tolist(), "must be finite")
    w, xs = _scales(pair)
    ref = max(float(np.max(np.abs(load * w))), 1e-300)
    goal = max(tol * ref, 1e-9)
    u = _start(pair, load, free, w, xs) if pair.preload_offset == 0.0 else np.zeros(5)
    f, jac, _ = set_reaction(pair, u)
    r = np.where(free, (load + f) * w, 0.0)
    mu = 0.0
    for it in range(MAX_ITER):
        res = float(np.max(np.abs(r)))
        mat = -jac * w[:, None] / xs[None, :]
        scale = max(float(np.max(np.abs(mat))), 1.0)
        for i in range(5):
            if not free[i]:
                mat[i, :] = 0.0
                mat[:, i] = 0.0
                mat[i, i] = scale
            elif mu > 0.0:
                mat[i, i] += mu * scale
        try:
            y = np.linalg.solve(mat, r)
        except np.linalg.LinAlgError:
            mu = max(10.0 * mu, 1e-6)
            continue
        size = float(np.max(np.abs(u * xs)))
        if res <= goal and float(np.max(np.abs(y))) <= 1e-6 * size + 1e-18:
            return _result(pair, load, free, u, res, it)
        cap = min(1.0, pair.row.curvature_centre_distance / max(float(np.max(np.abs(y))), 1e-300))
        t = cap
        merit = float(np.linalg.norm(r))
        for _ in range(40):
            trial = u + t * y / xs
            f_t, jac_t, _ = set_reaction(pair, trial)
            r_t = np.where(free, (load + f_t) * w, 0.0)
            if float(np.linalg.norm(r_t)) <= (1.0 - 1e-4 * t) * merit:
                break
            t *= 0.5
        else:
            if res <= goal:
                return _result(pair, load, free, u, res, it)
            mu = max(10.0 * mu, 1e-6)
            if mu > 1e6:
                break
            continue
        u, f, jac, r = trial, f_t, jac_t, r_t
        mu = 0.1 * mu if mu > 1e-9 else 0.0
    raise ConvergenceError(f"{pair.name}: no equilibrium found for load {load.tolist()} "
                           f"(residual {float(np.max(np.abs(r))):.3g} N)", float(np.max(np.abs(r))), MAX_ITER)


def _result(pair, load, free, u, res, it) -> dict:
    f, _, rows = set_reaction(pair, u, with_jac=False)
    reaction = np.where(free, 0.0, -(load + f))
    return {"displacement": u, "row_displacement": np.array(rows), "residual": res, "iterations": it,
            "reaction": reaction}


def load_distribution(pair: DuplexSet, axial=0.0, radial=0.0, moment=0.0, tilt: str = "free",
                      tol: float = DEFAULT_TOL):
    """Load distribution of both rows under (Fa, Fr, M) on the shaft, one case per broadcast value.

    Loads as :func:`auxbearing.analysis.statics.load_distribution` (Fx = Fr, My = -M); numbers in N and N m.

    Returns
    -------
    xarray.Dataset
        Dims ``case``, ``row``, ``ball``, ``pair``: per ball the contact load, loaded angle and inner /
        outer stress of each row; per case the shaft's displacements, each row's axial load (along its
        own contact side) and radial load, largest contact load and stress, s0 (ISO 76, 4200 MPa).

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> ds = load_distribution(get_bearing("7208 DB"), axial=[0.0, 300.0, 3000.0])
    >>> [[round(v) for v in case] for case in ds.row_axial_load.values]   # lift-off above about 2.8 x preload
    [[241, 241], [407, 107], [3000, 0]]
    """
    import xarray as xr

    from auxbearing import __version__
    from auxbearing.bearings.ballset import ballset_state
    from auxbearing.bearings.ratings import safety_factor

    fa, fr, mm = np.broadcast_arrays(*(np.atleast_1d(np.asarray(v, float)) for v in (axial, radial, moment)))
    if tilt not in ("free", "fixed"):
        raise InputError.for_field("tilt", tilt, "must be free or fixed")
    free = (True, True, True, tilt == "free", tilt == "free")
    params = _params(pair)
    n, z = fa.size, pair.row.ball_count
    disp = np.zeros((n, 5))
    row_disp = np.zeros((n, 2, 5))
    residual = np.zeros(n)
    for i in range(n):
        sol = solve_set(pair, [fa[i], fr[i], 0.0, 0.0, -mm[i]], free, tol)
        disp[i], row_disp[i], residual[i] = sol["displacement"], sol["row_displacement"], sol["residual"]
    state = ballset_state(row_disp, params)  # (n, 2, Z, P) from the kernel's array face
    p = state.load.shape[-1]
    row_force = -state.force  # (n, 2, 5): load each row carries, in its own coordinates
    max_stress = np.maximum(state.stress_inner, state.stress_outer).max(axis=(1, 2, 3))
    dims = ("case", "row", "ball", "pair")
    ds = xr.Dataset(
        {
            "load": (dims, state.load, {"units": "N", "long_name": "Contact-pair load"}),
            "contact_angle": (dims, state.contact_angle, {"units": "rad"}),
            "max_stress_inner": (dims, state.stress_inner, {"units": "Pa"}),
            "max_stress_outer": (dims, state.stress_outer, {"units": "Pa"}),
            "axial_displacement": ("case", disp[:, 0], {"units": "m"}),
            "radial_displacement": ("case", disp[:, 1], {"units": "m"}),
            "tilt": ("case", -disp[:, 4], {"units": "rad"}),
            "row_axial_load": (("case", "row"), row_force[:, :, 0],
                               {"units": "N", "long_name": "Axial load of each row on its contact side"}),
            "row_radial_load": (("case", "row"), np.hypot(row_force[:, :, 1], row_force[:, :, 2]),
                                {"units": "N"}),
            "max_contact_load": ("case", state.load.max(axis=(1, 2, 3)), {"units": "N"}),
            "max_stress": ("case", max_stress, {"units": "Pa"}),
            # as a single bearing's (analysis.statics): no loaded contact, no stress, so no s0 (never inf)
            "safety_factor_s0": ("case", np.where(max_stress > 0.0, safety_factor(max_stress), np.nan),
                                 {"units": "1", "comment": "NaN (no value) where no contact carries load"}),
            "residual": ("case", residual, {"units": "N"}),
            "axial_load": ("case", fa, {"units": "N"}),
            "radial_load": ("case", fr, {"units": "N"}),
            "moment": ("case", mm, {"units": "N*m"}),
        },
        coords={"case": np.arange(n), "row": np.arange(2), "ball": np.arange(z), "pair": np.arange(1, p + 1),
                "row_position": ("row", np.array(pair.row_positions), {"units": "m"}),
                "row_facing": ("row", np.array(pair.row_facings))},
    )
    ds.attrs.update(title=f"Quasi-static load distribution, {pair.name} ({pair.label})",
                    preload=pair.preload, preload_force_N=pair.preload_force,
                    model="two rows of the ball-set model (auxbearing.core.ballset) on one rigid shaft",
                    auxbearing_version=__version__)
    if not math.isfinite(float(ds.max_stress.max())):
        raise ConvergenceError(f"{pair.name}: non-finite stresses", math.inf, 0)
    return ds
