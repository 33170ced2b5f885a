"""Quasi-static load distribution: loads with units in, xarray Dataset out (source paper Sec. II.C).

The public layer over :mod:`auxbearing.core.ballset` (the one ball-set model) and
:mod:`auxbearing.core.statics` (batched Newton-Raphson). Conventions (module docstring of
``core.ballset``): loads (Fa, Fx, Fy, Mx, My) act ON the inner ring; the paper's planar
(Fa, Fr, M) is Fx = Fr, My = -M, so M > 0 tilts the ring the way Eq. 10 adds r_ic theta cos(phi)
to pair 1. Moment arm r_ic = inner groove curvature-centre radius (Harris).

Axial boundary condition (docs/paper_notes.md, "How to read the static model"): ``axial_condition``
``"free"`` solves Eq. 14/16 with the axial load given; ``"located"`` holds the ring at zero
axial displacement and reports the axial reaction of its locating shoulder. A single
angular-contact bearing with a free ring cannot carry a radial load or a moment without an
axial load pressing its balls into their contact side; such loads are refused with an
:class:`~auxbearing.common.errors.InputError`, as are equilibria whose balls would have to run past
the groove bottom (loaded contact angle <= 0). ``tilt`` ``"free"`` (the paper: M given) or
``"fixed"`` (ring kept square by its shaft; the moment reaction is reported).

Static safety factor: ISO 76:2006 defines the basic static load rating C0 as the load giving
4200 MPa at the centre of the most heavily loaded contact of a ball bearing (other than
self-aligning), and s0 = C0 / P0. Hertz point contact gives sigma_max ~ Q^(1/3) (source paper
Eq. 4-8), so with every ball load scaled together s0 = (4200 MPa / sigma_max)^3. That is this
derivation, not a formula printed in ISO 76.
"""

from __future__ import annotations

import json
import math
from collections.abc import Callable, Sequence

import numpy as np
import xarray as xr

from auxbearing import __version__
from auxbearing.bearings import ballset
from auxbearing.bearings.catalogue import load_bearing
from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.bearings.ratings import ISO76_BALL_STRESS, safety_factor
from auxbearing.common.errors import ConvergenceError, InputError
from auxbearing.common.io import to_jsonable
from auxbearing.common.units import to_si, ureg
from auxbearing.core import statics as kernel
from auxbearing.core.ballset import BallSet
from auxbearing.core.statics import CONVERGED, DEFAULT_MAX_ITER, DEFAULT_TOL, STATUS_TEXT, StaticSolution

#: Stribeck's Q_max = 4.37 Fr / (Z cos alpha) for zero clearance, point contact: Stribeck (1901),
#: Harris & Kotzalas (2007) Essential Concepts Ch. 7; NSK CAT. E728g Sec. 5.1, Eq. (4).
STRIBECK_CONSTANT = 4.37
#: J_r(0.5) = 0.2288: Sjovall radial integral at load zone epsilon = 0.5, point contact
#: (Harris & Kotzalas 2007 Table 7.1; NSK CAT. E728g Sec. 5.1 Table 1).
SJOVALL_JR_HALF = 0.2288
#: Ring displacement into the balls, as a fraction of the ball diameter, past which no contact law of the ball
#: set means anything: at the 6000 MPa where elastic Hertz values stop (the machine model's
#: drop.ball_stress_limit) a steel ball's approach to both races together is 1.6 % of D (our Hertz, Eq. 4-8,
#: for QJ202, 209 and 218 alike), so 10 % is several times beyond any elastic contact.
SINK_LIMIT_FRACTION = 0.1
#: Ring displacement, as a fraction of the ball diameter, beyond the elastic approach at 6000 MPa (1.6 % of D):
#: a result that sinks so far is worth a warning.
SINK_WARNING_FRACTION = 0.02
AXIAL_CONDITIONS = ("free", "located")
TILT_CONDITIONS = ("free", "fixed")
LOAD_KEYS = ("axial", "force_x", "force_y", "moment_x", "moment_y")
_LOAD_DIMS = ("force", "force", "force", "moment", "moment")
_LOAD_UNITS = ("N", "N", "N", "N*m", "N*m")


def solve_cases(
    loads: np.ndarray,
    params: BallSet,
    free: tuple[bool, ...] = (True,) * 5,
    tol: float = DEFAULT_TOL,
    max_iter: int = DEFAULT_MAX_ITER,
    initial: np.ndarray | None = None,
    raise_on_failure: bool = True,
) -> StaticSolution:
    """Equilibrium displacement of the inner ring for a batch of 5-DOF load cases.

    Solves load + F(u) = 0 with F the ball-set resultant (source paper Eq. 14 and 16 in 5 DOF,
    Harris & Kotzalas 2007 Advanced Concepts Eq. 1.35-1.39) by the compiled damped Newton of
    :func:`auxbearing.core.statics.solve_batch`.

    Parameters
    ----------
    loads : array_like, shape (n, 5) or (5,)
        (Fa, Fx, Fy, Mx, My) applied to the inner ring [N, N m].
    params : BallSet
        :func:`auxbearing.bearings.ballset.ballset_params`.
    free : tuple of 5 bool
        DOFs the ring may move in; a fixed DOF stays at zero and carries a reaction.
    tol : float
        Converged when the max residual [N] <= tol * the largest applied load component [N]
        (moments divided by r_ic).
    max_iter : int
    initial : array_like, shape (n, 5), optional
        Start instead of the rigid-ring estimate.
    raise_on_failure : bool
        Raise :class:`ConvergenceError` on the first case that did not converge.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> sol = solve_cases([[500.0, 1000.0, 0.0, 0.0, 0.0]], ballset.ballset_params(get_bearing("QJ202")))
    >>> bool(sol.relative_residual[0] <= 1e-9), round(float(sol.displacement[0, 1]) * 1e6, 2)
    (True, 12.5)
    """
    loads = np.atleast_2d(np.asarray(loads, dtype=float))
    if loads.ndim != 2 or loads.shape[1] != 5:
        raise ValueError(f"loads shape {loads.shape}: must be (n, 5)")
    # a subnormal load (below 2.2e-308 N) cannot be resolved by any displacement: it is no load at all
    loads = np.where(np.abs(loads) < np.finfo(float).tiny, 0.0, loads)
    free_arr = np.asarray(free, dtype=np.bool_)
    use_guess = initial is not None
    guesses = np.atleast_2d(np.asarray(initial, float)) if use_guess else np.zeros((1, 5))
    u, res, its, status = kernel.solve_batch(loads, free_arr, params, guesses, use_guess, tol, max_iter)
    w = np.array([1.0, 1.0, 1.0, 1.0 / params.moment_arm, 1.0 / params.moment_arm])
    ref = np.max(np.abs(loads) * w, axis=1)
    rel = np.divide(res, ref, out=np.zeros_like(res), where=ref > 0.0)
    if raise_on_failure and np.any(status != CONVERGED):
        i = int(np.flatnonzero(status != CONVERGED)[0])
        load_text = ", ".join(f"{v:.6g}" for v in loads[i])
        raise ConvergenceError(
            f"static equilibrium not reached for load case {i} (Fa, Fx, Fy, Mx, My) = ({load_text}) "
            f"[N, N m]: {STATUS_TEXT[int(status[i])]}; relative residual {rel[i]:.3g} > {tol:g}",
            float(res[i]), int(its[i]), i,
        )
    return StaticSolution(u, res, rel, its, status)


def radial_approach(params: BallSet, load: float, tol: float = DEFAULT_TOL) -> float:
    """Radial displacement [m] of an inner ring held axially and square under a radial load ``load`` [N] along +x.

    The same equilibrium as ``solve_cases([[0, load, 0, 0, 0]], params, free=(False, True, True, False,
    False))`` (source paper Eq. 14 and 16): the ball azimuths are symmetric about x, so y stays at zero and
    load + F_x(dx) = 0 is one equation in dx, solved here by Newton's method inside a bracket (bisection where
    a Newton step leaves it) on :func:`auxbearing.bearings.ballset.ballset_state`. That is the kernel a drop's
    outputs compile anyway; the batch solver took 24 s more to compile on a first drop after an install.
    Converged when |load + F_x| <= ``tol`` * load, as the batch solver; NaN when no displacement carries it.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> params = ballset.ballset_params(get_bearing("QJ202"))
    >>> sol = solve_cases([[0.0, 1000.0, 0.0, 0.0, 0.0]], params, free=(False, True, True, False, False))
    >>> bool(abs(radial_approach(params, 1000.0) / sol.displacement[0, 1] - 1.0) < 1e-9)
    True
    """
    def residual(dx: float) -> tuple[float, float]:
        state = ballset.ballset_state([0.0, dx, 0.0, 0.0, 0.0], params)
        return load + float(state.force[1]), float(state.jacobian[1, 1])

    return falling_root(residual, 0.5 * max(params.clearance, 0.0) + 1e-7, tol * load)


def falling_root(residual, start: float, tol: float) -> float:
    """The x > 0 where ``residual(x)`` = (g, dg/dx) crosses zero, g falling from g(0) > 0 as x grows; NaN: none.

    The bracket grows by doubling from ``start`` until g < 0, then Newton's method inside it, bisecting where a step
    leaves it (scipy has no bracketed method that uses the Jacobian): brentq took 2.3-2.6 ms a ball-set solve over
    the catalogue against 0.3 ms, flat across the clearance. It starts from the bracket's far end, whose residual
    the search has just evaluated; converged at |g| <= ``tol``.
    """
    low, high = 0.0, start
    for _ in range(60):
        g, slope = residual(high)
        if g < 0.0:
            break
        low, high = high, 2.0 * high
    else:
        return math.nan
    x = high
    for _ in range(200):
        if abs(g) <= tol:
            return x
        if g > 0.0:
            low = x
        else:
            high = x
        step = x - g / slope if slope < 0.0 else math.nan
        x = step if low < step < high else 0.5 * (low + high)
        if high - low <= 1e-15 * high:
            return x
        g, slope = residual(x)
    return math.nan


#: Largest neglected second-order tilt displacement r_ic theta^2 / 2, as a fraction of the largest
#: pair compression, before a result is flagged: the ball-set kinematics are linear in the tilt.
SMALL_TILT_LIMIT = 0.01


def stress_warning(max_stress: float) -> str | None:
    """A sentence when sigma_max exceeds ISO 76's 4200 MPa (s0 < 1), else None.

    Above it the raceway deforms permanently (ISO 76:2006 defines 4200 MPa as the stress that
    leaves a permanent deformation of 1e-4 D), so the elastic Hertz values are upper-bound
    estimates, not predictions.

    >>> stress_warning(2000e6) is None
    True
    >>> stress_warning(4500e6)[:40]
    'max contact stress 4500 MPa exceeds the '
    """
    if not max_stress > ISO76_BALL_STRESS:
        return None
    s0 = float(safety_factor(max_stress))
    return (f"max contact stress {max_stress / 1e6:.0f} MPa exceeds the {ISO76_BALL_STRESS / 1e6:.0f} MPa of ISO 76 "
            f"(s0 = {s0:.3g} < 1): the raceways deform permanently and the elastic Hertz values are estimates only")


def validity_warnings(ds: xr.Dataset, case: int = 0) -> list[str]:
    """What makes one load case of :func:`load_distribution` leave the model's range, as sentences.

    Two limits: the ISO 76 stress (:func:`stress_warning`) and the small-tilt kinematics of
    :mod:`auxbearing.core.ballset`, whose curvature-centre distance is linear in the tilt; the
    neglected term r_ic theta^2 / 2 is compared with the largest pair compression.

    >>> validity_warnings(load_distribution("QJ202", radial=1000, moment=5))
    []
    """
    return validity_warnings_all(ds.isel(case=[case]))[0]


def validity_warnings_all(ds: xr.Dataset) -> list[list[str]]:
    """:func:`validity_warnings` of every case at once (a table of 10^5 cases in a fraction of a second).

    >>> validity_warnings_all(load_distribution("QJ202", radial=[1000, 1e5]))[1][0][:30]
    'max contact stress 8690 MPa ex'
    """
    stress = ds["max_stress"].values
    tilt = np.hypot(ds["tilt_x"].values, ds["tilt_y"].values)
    neglected = ds.attrs["moment_arm_m"] * tilt**2 / 2.0
    compression = ds["compression"].values.reshape(stress.size, -1).max(axis=1)
    out: list[list[str]] = [[] for _ in range(stress.size)]
    for i in np.flatnonzero(stress > ISO76_BALL_STRESS):
        out[i].append(stress_warning(float(stress[i])))
    for i in np.flatnonzero(neglected > SMALL_TILT_LIMIT * compression):
        out[i].append(f"tilt {tilt[i] * 1e3:.3g} mrad is beyond the model's small-tilt kinematics: the neglected "
                      f"r_ic theta^2/2 = {neglected[i] * 1e6:.3g} um is "
                      f"{100 * neglected[i] / max(compression[i], 1e-300):.3g} % of the largest compression "
                      f"({compression[i] * 1e6:.3g} um)")
    return out


def stribeck_discrete_constant(ball_count: int) -> float:
    """Z / sum(cos^2.5 phi_j) over the loaded half, a ball on the load line (rigid rings, Pd = 0).

    The exact form of Stribeck's Q_max = k Fr / (Z cos alpha) for Z balls before his large-Z
    approximation k = 4.37 (Harris & Kotzalas 2007 Eq. 7.xx: Fr = Q_max sum cos^2.5 phi cos alpha).

    Examples
    --------
    >>> round(stribeck_discrete_constant(11), 4)
    4.3639
    """
    phi = 2.0 * np.pi * np.arange(ball_count) / ball_count
    c = np.cos(phi)
    return float(ball_count / np.sum(np.where(c > 0.0, c, 0.0) ** 2.5))


def _ball_constant(value: object) -> float | None:
    if value is None:
        return None
    from auxbearing.common.params import convert

    # a plain number is in N/m**1.5, as drop's --ball-constant reads it
    magnitude = convert("ball_constant", value, "ball_constant", "N/m**1.5")
    if not math.isfinite(magnitude) or magnitude <= 0.0:
        raise InputError.for_field("ball_constant", value, "must be > 0 N/m^1.5 and finite")
    return magnitude


def sink_estimate(bearing: BearingGeometry, loads: np.ndarray, ball_constant: object = None) -> np.ndarray:
    """Rough ring displacement into the balls [m] of each (Fa, Fx, Fy, Mx, My) load case, before any solve.

    The loads are lumped into P = |Fr| + |Fa| + 2 |M| / dm [N], the largest ball load taken from
    Stribeck, Q = 4.37 P / Z (:data:`STRIBECK_CONSTANT`), and the approach from the ball constant of
    source paper Eq. 15, delta = (Q / K_b)^(2/3). Good to a factor of about two: enough to refuse loads
    no elastic contact can carry (:data:`SINK_LIMIT_FRACTION`), not a result.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> b = get_bearing("QJ202")
    >>> [f"{d * 1e6:.3g}" for d in sink_estimate(b, np.array([[0, 1000, 0, 0, 0], [0, 1000, 0, 0, 0]]))]
    ['13.5', '13.5']
    >>> f"{sink_estimate(b, np.array([[0, 1000, 0, 0, 0]]), '1 N/m**1.5')[0]:.2g}"
    '54'
    """
    from auxbearing.analysis.contact import ball_constant as hertz_ball_constant

    loads = np.atleast_2d(np.asarray(loads, dtype=float))
    k = _ball_constant(ball_constant)
    k = float(hertz_ball_constant(bearing)) if k is None else k
    lumped = (np.hypot(loads[:, 1], loads[:, 2]) + np.abs(loads[:, 0])
              + 2.0 * np.hypot(loads[:, 3], loads[:, 4]) / bearing.pitch_diameter)
    return (STRIBECK_CONSTANT * lumped / bearing.ball_count / k) ** (2.0 / 3.0)


def sink_culprit(bearing: BearingGeometry, load: np.ndarray, ball_constant: object = None) -> int | None:
    """The input of one (Fa, Fx, Fy, Mx, My) case that :func:`sink_estimate` finds sinking the rings.

    None when a ``ball_constant`` override is given and the Hertz constant would carry the case within
    :data:`SINK_LIMIT_FRACTION` (the override is what is wrong); else the column with the largest share of
    the lumped load P = |Fr| + |Fa| + 2 |M| / dm.

    >>> from auxbearing import get_bearing
    >>> b = get_bearing("QJ202")
    >>> sink_culprit(b, [100.0, 0.0, 0.0, 0.0, -1e6]), sink_culprit(b, [0.0, 1000.0, 0.0, 0.0, 0.0], "1 N/m**1.5")
    (4, None)
    """
    row = np.asarray(load, dtype=float)
    if ball_constant is not None and sink_estimate(bearing, row)[0] <= SINK_LIMIT_FRACTION * bearing.ball_diameter:
        return None
    arm = 2.0 / bearing.pitch_diameter
    return int(np.argmax(np.abs(row) * np.array([1.0, 1.0, 1.0, arm, arm])))


def refuse_sinking(bearing, loads, ball_constant, blame) -> None:
    """Refuse load cases no elastic contact can carry, before any solve.

    The estimate is :func:`sink_estimate`.

    ``blame(k)`` says which input of case k to name.
    """
    sink = sink_estimate(bearing, loads, ball_constant)
    limit = SINK_LIMIT_FRACTION * bearing.ball_diameter
    worst = int(np.argmax(sink))
    if sink[worst] > limit:
        raise InputError(f"{blame(worst)}: the rings would move about {sink[worst] * 1e3:.3g} mm into the balls "
                         f"(ball diameter {bearing.ball_diameter * 1e3:g} mm), beyond {SINK_LIMIT_FRACTION:.0%} of a "
                         "ball where no contact law of the ball set holds; no result follows (a steel ball constant "
                         "is about 1e10 N/m**1.5)")


def _refuse_sinking(bearing: BearingGeometry, loads: np.ndarray, ball_constant: object,
                    named: Callable[[int, int | None], tuple[str, object]]) -> None:
    """The command line's refusal of loads no elastic contact carries, naming the API's own argument."""

    def blame(k: int) -> str:
        column = sink_culprit(bearing, loads[k], ball_constant)
        if column is None:
            return f"ball_constant = {ball_constant!r}"
        name, value = named(k, column)
        return f"{name} = {value!r}"

    refuse_sinking(bearing, loads, ball_constant, blame)


def _load_array(field: str, value: object, dimension: str, unit: str) -> tuple[np.ndarray, Callable[[int], object]]:
    """Loads in SI from a number, a string with a unit, a Quantity or a 1-D sequence of any of them.

    Also returns, for error messages, the value of case k as the user gave it (a single value stands for
    every case, as it broadcasts).
    """
    if isinstance(value, (str, ureg.Quantity)) or np.ndim(value) == 0:
        return np.atleast_1d(to_si(field, value, dimension, unit)), lambda k: _as_typed(value, unit)
    try:
        arr = np.asarray(value, dtype=float)  # the common case, 10^5 numbers of a loads file, at once
    except (TypeError, ValueError):  # strings with units or Quantities among them: each through to_si
        items = list(value) if np.ndim(np.asarray(value, dtype=object)) == 1 else None
        if items is None:
            raise InputError.for_field(field, value, "must be a load or a 1-D sequence of loads") from None
        arr = np.array([to_si(f"{field}[{i}]", v, dimension, unit) for i, v in enumerate(items)], dtype=float)
        return arr, lambda k: _as_typed(items[k if len(items) > 1 else 0], unit)
    if arr.ndim != 1 or not np.all(np.isfinite(arr)):
        raise InputError.for_field(field, value, "must be a finite number or a 1-D sequence of them")
    return arr, lambda k: _as_typed(arr[k if arr.size > 1 else 0], unit)


def _as_typed(value: object, unit: str) -> object:
    """One load as the user wrote it: a string or Quantity unchanged, a plain number with its unit."""
    if isinstance(value, (str, ureg.Quantity)):
        return value
    return f"{float(value) + 0.0:g} {unit}"  # + 0.0: never "-0 N"


def _choice(field: str, value: str, allowed: Sequence[str]) -> str:
    if value not in allowed:
        raise InputError.for_field(field, value, "must be one of " + ", ".join(allowed))
    return value


def solve_loads(
    bearing: BearingGeometry | str,
    loads: np.ndarray,
    *,
    axial_condition: str = "free",
    tilt: str = "free",
    ball_constant: object = None,
    tol: float = DEFAULT_TOL,
    case_names: Sequence[str] | None = None,
) -> xr.Dataset:
    """Load distribution for 5-DOF load cases (SI) on one bearing (source paper Eq. 10-16).

    Parameters
    ----------
    bearing : BearingGeometry or str
        A bearing, catalogue name or TOML path.
    loads : array_like, shape (n, 5) or (5,)
        (Fa, Fx, Fy, Mx, My) on the inner ring [N, N, N, N m, N m].
    axial_condition : {"free", "located"}
    tilt : {"free", "fixed"}
    ball_constant : float or str, optional
        K_b override [N/m^1.5] or with units ("5.42e5 N/mm**1.5").
    tol : float
        Relative residual tolerance of the solver.
    case_names : sequence of str, optional
        How errors name each case ("line 7" of a loads file); default "load case i" when
        there is more than one case.

    Returns
    -------
    xarray.Dataset
        See :func:`load_distribution`.

    Raises
    ------
    InputError
        Bad options; loads no equilibrium of the bearing carries; loads that would sink the rings further
        into the balls than :data:`SINK_LIMIT_FRACTION` of a ball (estimated by :func:`sink_estimate`
        before any solve), where no contact law of the ball set holds. Errors name the case
        (``case_names``) and the load column (``axial``, ``force_x``, ...) or ``ball_constant``.
    """
    loads = np.atleast_2d(np.asarray(loads, dtype=float))
    if loads.ndim != 2 or loads.shape[1] != 5 or not np.all(np.isfinite(loads)):
        raise InputError.for_field("loads", loads.shape, "must be finite (Fa, Fx, Fy, Mx, My) rows")
    units = ("N", "N", "N", "N*m", "N*m")

    def typed(k: int, column: int | None) -> tuple[str, object]:
        if column is None:
            return "loads", [float(v) + 0.0 for v in loads[k]]
        return LOAD_KEYS[column], f"{float(loads[k, column]) + 0.0:g} {units[column]}"

    return _solve_loads(bearing, loads, axial_condition, tilt, ball_constant, tol, case_names, typed)


def _solve_loads(bearing, loads: np.ndarray, axial_condition: str, tilt: str, ball_constant: object, tol: float,
                 case_names: Sequence[str] | None, typed: Callable[[int, int | None], tuple[str, object]],
                 contact_side_column: int | None = None) -> xr.Dataset:
    """:func:`solve_loads` of checked (n, 5) loads.

    ``typed(k, column)`` is input ``column`` of case k (the whole case for None) as the caller's user wrote
    it, (name, value); ``contact_side_column`` the input blamed when balls would leave their contact side.
    """
    bearing = load_bearing(bearing)
    _choice("axial_condition", axial_condition, AXIAL_CONDITIONS)
    _choice("tilt", tilt, TILT_CONDITIONS)
    if case_names is None:
        case_names = [f"load case {i}" for i in range(loads.shape[0])] if loads.shape[0] > 1 else [""]
    elif len(case_names) != loads.shape[0]:
        raise InputError.for_field("case_names", len(case_names), f"must name each of the {loads.shape[0]} cases")
    where = [f" ({name})" if name else "" for name in case_names]

    def named(k: int, column: int | None) -> tuple[str, object]:
        name, value = typed(k, column)
        return name + where[k], value

    k_override = _ball_constant(ball_constant)
    _refuse_sinking(bearing, loads, ball_constant, named)
    params = ballset.ballset_params(bearing, k_override)
    free = (axial_condition == "free", True, True, tilt == "free", tilt == "free")
    one_sided = all(s > 0.0 for s in bearing.axial_signs)
    if one_sided and free[0]:
        others = np.abs(loads[:, 1:]).max(axis=1) > 0.0
        needs = (others & (loads[:, 0] <= 0.0)) | (loads[:, 0] < 0.0)
        if np.any(needs):
            i = int(np.flatnonzero(needs)[0])
            if others[i]:
                rule = (f"a single {bearing.label} bearing with a free ring needs an axial load > 0 N pressing the "
                        "balls into their contact side to carry a radial load or moment; give one")
            else:
                rule = (f"a single {bearing.label} bearing with a free ring carries axial load in one direction "
                        "only (> 0 N, pressing the balls into their contact side): a negative one pulls the ring "
                        "off its balls and no equilibrium follows; reverse it")
            raise InputError.for_field(*named(i, 0), rule + ", or hold the ring axially (axial_condition='located'; "
                                       "on the command line --axial-condition located) to get the axial reaction")
    try:
        sol = solve_cases(loads, params, free=free, tol=tol)
    except ConvergenceError as err:
        if err.case is None or not case_names[err.case]:
            raise
        raise ConvergenceError(f"{case_names[err.case]}: {err.message}", err.residual, err.iterations,
                               err.case) from None
    ds = _dataset(bearing, params, loads, sol, axial_condition, tilt, tol, k_override)
    if one_sided:
        bad = (ds["load"] > 0.0) & (ds["contact_angle"] <= 0.0)
        if bool(bad.any()):
            i = int(np.flatnonzero(bad.any(("ball", "pair")).values)[0])
            raise InputError.for_field(
                *named(i, contact_side_column),
                f"no equilibrium on the contact side of this {bearing.label} bearing: the balls would run past "
                "the groove bottom (loaded contact angle <= 0); raise the axial load or locate the ring axially",
            )
    return ds


def load_distribution(
    bearing: BearingGeometry | str,
    axial: object = 0.0,
    radial: object = 0.0,
    moment: object = 0.0,
    *,
    axial_condition: str = "free",
    tilt: str = "free",
    ball_constant: object = None,
    tol: float = DEFAULT_TOL,
    case_names: Sequence[str] | None = None,
) -> xr.Dataset:
    """The paper's planar load distribution under (Fa, Fr, M), batched (source paper Eq. 14, 16).

    Parameters
    ----------
    bearing : BearingGeometry or str
    axial, radial : float, str or sequence
        Fa, Fr [N]: a number in N, a string with a unit ("1 kN") or a 1-D sequence in N.
        Sequences broadcast against each other into load cases.
    moment : float, str or sequence
        M [N m] tilting the ring in the plane of the radial load (My = -M, see module docstring).
    axial_condition, tilt, ball_constant, tol, case_names
        As :func:`solve_loads`.

    Returns
    -------
    xarray.Dataset
        Dims ``case``, ``ball``, ``pair``. Applied loads, ring displacements, per ball and
        pair the load, compression, loaded contact angle and inner/outer max stress; per case
        max contact load, max stress, s0, residual, iterations, support reactions. SI units in
        attrs.

    A matched set ("7208 DB", or a :class:`~auxbearing.bearings.duplex.DuplexSet`) is solved with both
    rows by :func:`auxbearing.bearings.duplex_statics.load_distribution` (dims ``case``, ``row``,
    ``ball``, ``pair``).

    Examples
    --------
    >>> ds = load_distribution("QJ202", axial="500 N", radial=1000)
    >>> round(float(ds.max_contact_load[0]), 1), round(float(ds.max_stress[0]) / 1e6)
    (274.8, 2005)
    """
    fa, typed_fa = _load_array("axial", axial, "force", "N")
    fr, typed_fr = _load_array("radial", radial, "force", "N")
    mm, typed_mm = _load_array("moment", moment, "moment", "N*m")
    bearing = load_bearing(bearing, sets=True)
    if not isinstance(bearing, BearingGeometry):  # a duplex set: both rows through the same kernel
        from auxbearing.bearings import duplex_statics

        if axial_condition != "free" or ball_constant is not None:
            raise InputError.for_field("axial_condition" if axial_condition != "free" else "ball_constant",
                                       axial_condition if axial_condition != "free" else ball_constant,
                                       f"not available for a matched set ({bearing.name}): its rows locate "
                                       "the shaft axially, with Hertz K_b")
        return duplex_statics.load_distribution(bearing, fa, fr, mm, tilt=tilt, tol=tol)
    try:
        fa, fr, mm = np.broadcast_arrays(fa, fr, mm)
    except ValueError:
        raise InputError.for_field(
            "loads", (fa.size, fr.size, mm.size), "axial, radial, moment lengths must broadcast") from None
    loads = np.zeros((fa.size, 5))
    loads[:, 0], loads[:, 1], loads[:, 4] = fa, fr, -mm
    columns = (("axial", typed_fa), ("radial", typed_fr), ("radial", typed_fr), ("moment", typed_mm),
               ("moment", typed_mm))

    def typed(k: int, column: int | None) -> tuple[str, object]:
        name, value = columns[0 if column is None else column]
        return name, value(k)

    # balls pushed off their contact side: the axial load is what presses them into it
    ds = _solve_loads(bearing, loads, axial_condition, tilt, ball_constant, tol, case_names, typed,
                      contact_side_column=0)
    ds["radial_load"] = ("case", fr.astype(float), {"units": "N", "long_name": "Radial load Fr (along +x)"})
    ds["moment"] = ("case", mm.astype(float), {"units": "N*m", "long_name": "Moment M of source paper Eq. 14"})
    # 0.0 - x: an untilted ring stores 0, not the -0 that negating gives
    ds["tilt"] = ("case", 0.0 - ds["tilt_y"].values, {"units": "rad", "long_name": "Tilt theta of source paper Eq. 10"})
    ds["radial_displacement"] = ("case", ds["displacement_x"].values,
                                 {"units": "m", "long_name": "Radial displacement along the radial load"})
    return ds


_PER_PAIR = {
    "load": ("N", "Contact-pair load Q = K_b (S - A)^1.5"),
    "compression": ("m", "Curvature-centre approach S - A (negative: pair open)"),
    "contact_angle": ("rad", "Loaded contact angle (positive on the pair's own groove side)"),
    "max_stress_inner": ("Pa", "Hertz max stress at the inner race"),
    "max_stress_outer": ("Pa", "Hertz max stress at the outer race"),
    "curvature_centre_distance": ("m", "Loaded curvature-centre distance S (Eq. 10-11)"),
}
_DISP = (("axial_displacement", "m", "Axial displacement delta_a of the inner ring"),
         ("displacement_x", "m", "Displacement of the inner ring along x"),
         ("displacement_y", "m", "Displacement of the inner ring along y"),
         ("tilt_x", "rad", "Tilt of the inner ring about x"),
         ("tilt_y", "rad", "Tilt of the inner ring about y"))
_LOADS = (("axial_load", "N", "Applied axial load Fa (+z)"), ("force_x", "N", "Applied force Fx"),
          ("force_y", "N", "Applied force Fy"), ("moment_x", "N*m", "Applied moment Mx"),
          ("moment_y", "N*m", "Applied moment My"))


def _dataset(bearing, params, loads, sol, axial_condition, tilt, tol, k_override) -> xr.Dataset:
    state = ballset.ballset_state(sol.displacement, params)
    n, z, p = state.load.shape
    per_pair = {
        "load": state.load, "compression": state.compression, "contact_angle": state.contact_angle,
        "max_stress_inner": state.stress_inner, "max_stress_outer": state.stress_outer,
        "curvature_centre_distance": state.distance,
    }
    data = {name: (("case", "ball", "pair"), value, {"units": _PER_PAIR[name][0], "long_name": _PER_PAIR[name][1]})
            for name, value in per_pair.items()}
    for i, (name, unit, long_name) in enumerate(_DISP):
        data[name] = ("case", sol.displacement[:, i], {"units": unit, "long_name": long_name})
    for i, (name, unit, long_name) in enumerate(_LOADS):
        data[name] = ("case", loads[:, i], {"units": unit, "long_name": long_name})
    max_stress = np.maximum(state.stress_inner, state.stress_outer).max(axis=(1, 2))
    reaction = -(loads + state.force)  # what the supports of fixed DOFs carry; ~0 in free DOFs
    free = (axial_condition == "free", True, True, tilt == "free", tilt == "free")
    for i, name, unit, long_name in ((0, "axial_reaction", "N", "Axial reaction of the locating shoulder"),
                                     (3, "moment_reaction_x", "N*m", "Moment reaction about x of the shaft"),
                                     (4, "moment_reaction_y", "N*m", "Moment reaction about y of the shaft")):
        data[name] = ("case", np.zeros(n) if free[i] else reaction[:, i], {"units": unit, "long_name": long_name})
    data.update(
        max_contact_load=("case", state.load.max(axis=(1, 2)),
                          {"units": "N", "long_name": "Largest contact-pair load"}),
        max_stress=("case", max_stress, {"units": "Pa", "long_name": "Largest Hertz max stress, inner or outer race"}),
        safety_factor_s0=("case", np.where(max_stress > 0.0, safety_factor(max_stress), np.nan),
                          {"units": "1", "long_name": "Static safety factor (4200 MPa / sigma_max)^3, ISO 76:2006",
                           "comment": "NaN (no value) where no contact carries load: no stress, so no s0"}),
        residual=("case", sol.residual, {"units": "N", "long_name": "Max equilibrium residual, moments / r_ic"}),
        relative_residual=("case", sol.relative_residual, {"units": "1", "long_name": "Residual / largest load"}),
        iterations=("case", sol.iterations, {"units": "1", "long_name": "Newton iterations"}),
    )
    coords = {
        "case": np.arange(n),
        "ball": np.arange(z),
        "pair": np.arange(1, p + 1),
        "azimuth": ("ball", np.arctan2(params.sin_azimuth, params.cos_azimuth) % (2.0 * np.pi),
                    {"units": "rad", "long_name": "Position angle phi_j from +x"}),
    }
    ds = xr.Dataset(data, coords=coords)
    ds.attrs.update(
        title=f"Quasi-static load distribution, {bearing.name} ({bearing.label})",
        bearing=json.dumps(to_jsonable(bearing.describe()), allow_nan=False),  # an infinity "inf", as in every file
        axial_condition=axial_condition,
        tilt_condition=tilt,
        moment_arm_m=params.moment_arm,
        moment_arm="inner groove curvature-centre radius r_ic (Harris)",
        tolerance=tol,
        ball_constant="Hertz K_b(alpha), Eq. 15" if k_override is None else f"{k_override:.6g} N/m^1.5 (user)",
        model="source paper Eq. 9-16 in 5 DOF (auxbearing.core.ballset); Hertz K_b(alpha) by Eq. 15",
        auxbearing_version=__version__,
    )
    return ds


def planar_components(ds: xr.Dataset) -> tuple[np.ndarray, np.ndarray]:
    """Radial displacement [m] and tilt [rad] of every case as signed numbers in the plane of its load.

    :func:`load_distribution` defines them (``radial_displacement`` along +x, the radial load's axis;
    ``tilt`` theta of source paper Eq. 10, -tilt_y) and they are returned as they are. For 5-DOF cases
    (:func:`solve_loads`) the same convention is carried over: the axis is that of the radial force (Fx, Fy),
    or, with none, the one in whose plane the moment (Mx, My) tilts the ring, with no load at all +x; it is
    pointed along +x (along +y when it is the y axis), so a case that is planar reads exactly as
    :func:`load_distribution` gives it. The tilt is then taken about the axis at -90 deg from it, as theta
    = -tilt_y is for +x. A magnitude (hypot) would drop the sign of a load along -x.

    >>> r, t = planar_components(solve_loads("QJ202", [[0.0, -500.0, 0.0, 0.0, 0.0]]))
    >>> round(float(r[0]) * 1e6, 4), float(t[0]) + 0.0
    (-7.3633, 0.0)
    """
    if "radial_displacement" in ds and "tilt" in ds:
        return ds["radial_displacement"].values, ds["tilt"].values
    fx, fy = ds["force_x"].values, ds["force_y"].values
    mx, my = ds["moment_x"].values, ds["moment_y"].values
    by_force = (fx != 0.0) | (fy != 0.0)
    # the moment (0, -M) of load_distribution tilts the ring in the x-z plane: its axis (M, 0) is (-My, Mx)
    ux = np.where(by_force, fx, -my)
    uy = np.where(by_force, fy, mx)
    norm = np.hypot(ux, uy)
    safe = np.where(norm > 0.0, norm, 1.0)
    ux = np.where(norm > 0.0, ux / safe, 1.0)
    uy = np.where(norm > 0.0, uy / safe, 0.0)
    flip = (ux < 0.0) | ((ux == 0.0) & (uy < 0.0))
    ux, uy = np.where(flip, -ux, ux), np.where(flip, -uy, uy)
    radial = ds["displacement_x"].values * ux + ds["displacement_y"].values * uy
    tilt = ds["tilt_x"].values * uy - ds["tilt_y"].values * ux
    return radial, tilt


def summary(ds: xr.Dataset, case: int = 0) -> dict:
    """One load case in display units: the mapping printed by ``auxbearing static --json``.

    Displacement and tilt are signed, as :func:`planar_components` gives them; ``safety_factor_s0`` is None
    when no contact carries load (no stress, so no s0).

    Examples
    --------
    >>> s = summary(load_distribution("QJ202", axial=500, radial=1000))
    >>> sorted(s)[:3], len(s["balls"]), len(s["balls"][0]["pairs"])
    (['axial_displacement_um', 'balls', 'max_contact_load_N'], 11, 2)
    """
    c = ds.isel(case=case)
    radial, tilt = (float(v[0]) for v in planar_components(ds.isel(case=[case])))
    balls = []
    for j in range(c.sizes["ball"]):
        b = c.isel(ball=j)
        balls.append({
            "azimuth_deg": math.degrees(float(b["azimuth"])),
            "pairs": [{
                "load_N": float(b["load"][k]),
                "contact_angle_deg": math.degrees(float(b["contact_angle"][k])),
                "max_stress_inner_MPa": float(b["max_stress_inner"][k]) / 1e6,
                "max_stress_outer_MPa": float(b["max_stress_outer"][k]) / 1e6,
            } for k in range(c.sizes["pair"])],
        })
    s0 = float(c["safety_factor_s0"])
    # what the supports of a located ring or a square-held one carry; a ring free in both has none, and keeps the
    # keys the static issue named
    held = {}
    if ds.attrs.get("axial_condition") == "located":
        held["axial_reaction_N"] = float(c["axial_reaction"]) + 0.0
    if ds.attrs.get("tilt_condition") == "fixed":
        held["moment_reaction_Nm"] = [float(c["moment_reaction_x"]) + 0.0, float(c["moment_reaction_y"]) + 0.0]
    # + 0.0 turns a negative zero into zero; an unloaded ring has no stress, so no s0 (None)
    return {
        "axial_displacement_um": float(c["axial_displacement"]) * 1e6 + 0.0,
        "radial_displacement_um": radial * 1e6 + 0.0,
        "tilt_mrad": tilt * 1e3 + 0.0,
        "max_contact_load_N": float(c["max_contact_load"]),
        "max_stress_MPa": float(c["max_stress"]) / 1e6,
        "safety_factor_s0": s0 if math.isfinite(s0) else None,
        "residual_N": float(c["residual"]),
        "balls": balls,
        **held,
    }


def stribeck_comparison(
    bearing: BearingGeometry | str, radial_loads: Sequence[float] = (250.0, 1000.0, 4000.0)
) -> xr.Dataset:
    """Max ball load under pure radial load against Stribeck's Q_max = 4.37 Fr / (Z cos alpha).

    The ball load is the sum of the ball's pair normal loads (one pair, or both pairs of a
    four-point ball). A single angular-contact bearing is solved axially located and square.
    Reports k = Q_max Z cos(alpha) / Fr with the free angle alpha0 and with the loaded angle of
    the most loaded ball, beside 4.37 (NSK CAT. E728g Eq. 4) and the discrete rigid-ring value
    of :func:`stribeck_discrete_constant`.
    """
    bearing = load_bearing(bearing)
    one_sided = all(v > 0.0 for v in bearing.axial_signs)
    ds = load_distribution(bearing, radial=np.asarray(radial_loads, float),
                           axial_condition="located" if one_sided else "free", tilt="fixed" if one_sided else "free")
    ball_load = ds["load"].sum("pair")
    top = ball_load.argmax("ball")
    q_max = ball_load.isel(ball=top)
    alpha = ds["contact_angle"].isel(ball=top, pair=0)
    z = bearing.ball_count
    fr = ds["radial_load"]
    out = xr.Dataset({
        "max_ball_load": (q_max.dims, q_max.values, {"units": "N", "long_name": "Sum of pair loads, most loaded ball"}),
        "loaded_contact_angle": (alpha.dims, alpha.values, {"units": "rad"}),
        "k_nominal": (fr.dims, (q_max * z * math.cos(bearing.contact_angle) / fr).values,
                      {"units": "1", "long_name": "Q_max Z cos(alpha0) / Fr"}),
        "k_loaded": (fr.dims, (q_max * z * np.cos(alpha) / fr).values,
                     {"units": "1", "long_name": "Q_max Z cos(alpha loaded) / Fr"}),
    }, coords={"radial_load": ("case", fr.values, {"units": "N"})})
    out.attrs.update(stribeck_constant=STRIBECK_CONSTANT, discrete_constant=stribeck_discrete_constant(z),
                     bearing=bearing.name, source="Stribeck (1901); NSK CAT. E728g Sec. 5.1 Eq. (4)")
    return out
