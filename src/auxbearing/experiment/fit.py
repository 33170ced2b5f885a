"""A measured drop against the simulation: fit of the uncertain parameters, and the simulation seen as measured.

The paper (Sec. III) blames the gap between its measured and simulated stress partly on "the
angle of imbalance eccentricity at the moment of dropping" and on unknown parameters. Here the
simulation of :mod:`auxbearing.analysis.drop` (:func:`~auxbearing.analysis.drop.journal_orbit` and
:func:`run_drop`) is made to match the measurement by least squares:

* parameters: sliding friction mu_1, clearance s, unbalance phase at the drop, and (nuisance)
  a shift of the drop moment;
* residuals ("orbit features"): the journal orbit x(t), y(t) over the opening window of the
  drop (default 12 ms, which must reach a few ms past the first impact: the free fall, whose
  curve fixes the unbalance phase and the drop moment; the first impact, whose time and depth
  fix the clearance; the rebound, whose direction fixes the friction), the simulation put
  through the same zero-phase filter, each residual divided by the noise of the filtered
  measurement. Later the drop becomes a chaotic rattle in which a tiny change moves every
  impact, and every later impact also carries the errors of the parameters the fit holds
  fixed (damping, rolling friction): on the synthetic examples a 20 ms window biases mu_1 by
  -7 % against -2 % for 12 ms;
* solver: scipy ``least_squares`` (trust-region reflective) from the best point of a coarse
  grid over phase and clearance, with a central-difference Jacobian at fixed steps;
* uncertainty: covariance s^2 (J^T J)^-1 with s^2 the reduced chi-square, inflated by the
  integrated autocorrelation time of the residuals (the filter makes neighbouring samples
  dependent, so the samples are fewer independent observations than they look).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from dataclasses import dataclass, field, replace

import numpy as np
import xarray as xr
from scipy import optimize

from auxbearing.analysis.drop import journal_orbit
from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.common.errors import InputError
from auxbearing.common.params import convert
from auxbearing.experiment.orbit import lowpass
from auxbearing.planar.params import DropCase, Rotor
from auxbearing.planar.rig import planar_machine, run_drop

#: Fitted parameters: (name, unit shown, factor SI -> shown, central-difference step [SI]).
FIT_PARAMETERS = (
    ("sliding_friction", "", 1.0, 4e-3),
    ("clearance", "um", 1e6, 0.2e-6),
    ("unbalance_phase", "deg", 180.0 / math.pi, 0.02),
    ("drop_time_shift", "ms", 1e3, 4e-6),
)


@dataclass(frozen=True)
class FitOptions:
    """How the fit is run.

    Parameters
    ----------
    window : float or str
        Length of the fitted stretch after the drop: a string with a unit ("12 ms") or seconds.
    max_evaluations : int
        Cap on the solver's residual evaluations (each is one short simulation), a whole number >= 5.
    phase_grid : int
        Phases tried in the coarse start grid, spread evenly around the circle: a whole number >= 1.

    Examples
    --------
    >>> FitOptions(window="14 ms").window
    0.014
    >>> FitOptions(phase_grid=0)
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: phase_grid = 0: must be a whole number >= 1
    """

    window: float = 12e-3
    max_evaluations: int = 40
    phase_grid: int = 8
    #: each field as it was given, so that a check made later against the record quotes it as written
    typed: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        object.__setattr__(self, "typed", {"window": self.window, "max_evaluations": self.max_evaluations,
                                           "phase_grid": self.phase_grid})
        window = convert("window", self.window, "time")
        if not 2e-3 <= window <= 0.2:
            raise InputError.for_field("window", self.typed["window"], "must lie in [2, 200] ms")
        object.__setattr__(self, "window", window)
        object.__setattr__(self, "max_evaluations", _count("max_evaluations", self.max_evaluations, 5))
        object.__setattr__(self, "phase_grid", _count("phase_grid", self.phase_grid, 1))


def _count(name: str, value: object, least: int) -> int:
    """A whole number of at least ``least``; 40.0 is taken as 40, 5.5 or True is refused."""
    if isinstance(value, bool) or not isinstance(value, (int, float, str)):
        raise InputError.for_field(name, value, f"must be a whole number >= {least}")
    number = convert(name, value, "dimensionless")
    if number != int(number) or number < least:
        raise InputError.for_field(name, value, f"must be a whole number >= {least}")
    return int(number)


def simulate_states(bearing: BearingGeometry, rotor: Rotor, case: DropCase, duration: float,
                    step: float) -> np.ndarray:
    """Journal centre (x, y) on the grid k * step, 0 <= k * step <= duration (short runs for the fit) [m].

    The one drop driver (:func:`auxbearing.analysis.drop.journal_orbit`) without the Dataset that
    :func:`run_drop` builds; a simulation that fails raises instead of being padded and fitted.
    """
    return journal_orbit(planar_machine(bearing, rotor, replace(case, duration=duration)), duration, step)


def sample_like(states: np.ndarray, step: float, tau: np.ndarray, start: tuple[float, float]) -> np.ndarray:
    """Simulated (x, y) at times ``tau`` since the drop: the start position before it, linear between grid points."""
    grid_t = np.arange(states.shape[0]) * step
    out = np.empty((tau.size, 2))
    for j in range(2):
        out[:, j] = np.interp(tau, grid_t, states[:, j], left=start[j], right=states[-1, j])
    return out


class _Problem:
    """Residuals of the measured opening orbit against simulations, with a cache per parameter set."""

    def __init__(self, orbit: xr.Dataset, bearing, rotor, case, info, options: FitOptions):
        tau = orbit.time.values
        self.dt = float(np.median(np.diff(tau)))
        self.rate = 1.0 / self.dt
        self.cutoff = info["cutoff_Hz"]
        lead = min(1e-3, max(0.0, -tau[0]))
        # a tail beyond the window lets the zero-phase filter see the same signal on both sides
        tail = 3e-3
        keep = (tau >= -lead) & (tau <= options.window + tail)
        self.tau = tau[keep]
        self.fitted = self.tau <= options.window
        self.measured = np.stack([orbit.x.values[keep], orbit.y.values[keep]], axis=1)[self.fitted]
        self.sigma = max(info["noise_filtered_m"], 2e-8)
        # the race bore is fixed: a trial clearance moves the journal radius with it (r = bore/2 - s)
        if bearing.bore is not None and rotor.radius is not None:
            rotor = replace(rotor, radius=None)
        self.bearing, self.rotor, self.case = bearing, rotor, case
        self.start = (info["start_x_m"], info["start_y_m"])
        self.duration = options.window + tail + 2e-3
        self.step = 0.5 * self.dt
        self.cache: dict[tuple, np.ndarray] = {}
        self.evaluations = 0

    def case_for(self, p: np.ndarray) -> DropCase:
        return replace(self.case, sliding_friction=float(p[0]), clearance=float(p[1]), unbalance_phase=float(p[2]),
                       start_x=self.start[0], start_y=self.start[1])

    def orbit(self, p: np.ndarray) -> np.ndarray:
        key = (float(p[0]), float(p[1]), float(p[2]))
        if key not in self.cache:
            if len(self.cache) > 64:
                self.cache.clear()
            self.cache[key] = simulate_states(self.bearing, self.rotor, self.case_for(p), self.duration, self.step)
            self.evaluations += 1
        sim = sample_like(self.cache[key], self.step, self.tau - p[3], self.start)
        filtered = np.stack([lowpass(sim[:, j], self.rate, self.cutoff) for j in range(2)], axis=1)
        return filtered[self.fitted]

    def residuals(self, p: np.ndarray) -> np.ndarray:
        return ((self.orbit(p) - self.measured) / self.sigma).ravel(order="F")

    def jacobian(self, p: np.ndarray) -> np.ndarray:
        cols = []
        for j, (*_, h) in enumerate(FIT_PARAMETERS):
            up, down = p.copy(), p.copy()
            up[j] += h
            down[j] -= h
            cols.append((self.residuals(up) - self.residuals(down)) / (2.0 * h))
        return np.stack(cols, axis=1)


def _start_point(problem: _Problem, case: DropCase, options: FitOptions) -> np.ndarray:
    """Best of a coarse grid: phases around the circle, clearances below the largest early radius."""
    radius = np.hypot(problem.measured[:, 0], problem.measured[:, 1]).max()
    clearances = [radius * (1.0 - 0.025 * k) for k in range(4)]
    best, best_cost = None, math.inf
    for s in clearances:
        for k in range(options.phase_grid):
            p = np.array([case.sliding_friction, s, 2 * math.pi * k / options.phase_grid, 0.0])
            cost = float(np.sum(problem.residuals(p) ** 2))
            if cost < best_cost:
                best, best_cost = p, cost
    return best


def integrated_autocorrelation(residuals: np.ndarray, max_lag: int = 200) -> float:
    """Tau_int = 1 + 2 sum_k rho_k over lags until rho first drops below 0.05 (Sokal's window, simplified).

    Examples
    --------
    >>> rng = np.random.default_rng(0)
    >>> round(integrated_autocorrelation(rng.normal(size=20000)), 1)
    1.0
    """
    r = residuals - residuals.mean()
    var = float(np.dot(r, r))
    if var == 0.0:
        return 1.0
    tau = 1.0
    for k in range(1, min(max_lag, r.size // 4)):
        rho = float(np.dot(r[:-k], r[k:])) / var
        if rho < 0.05:
            break
        tau += 2.0 * rho
    return tau


def fit_parameters(orbit: xr.Dataset, info: dict, bearing: BearingGeometry, rotor: Rotor, case: DropCase,
                   options: FitOptions | None = None) -> dict:
    """Least-squares fit of friction, clearance, unbalance phase and drop moment to the opening orbit.

    Parameters
    ----------
    orbit, info :
        From :func:`auxbearing.experiment.orbit.preprocess`.
    bearing, rotor, case :
        The simulated case; its other parameters stay fixed.
    options : FitOptions, optional

    Returns
    -------
    dict
        ``parameters``: per parameter the value, standard error and start (SI and shown units);
        ``case``: the fitted DropCase; ``drop_time_s``: the refined drop moment; the residual
        (rms [um], reduced chi-square), the autocorrelation inflation, the correlation matrix,
        the number of simulations and the solver's message.
    """
    options = options or FitOptions()
    if orbit.time.values[-1] < options.window:
        raise InputError.for_field("window", options.typed.get("window", options.window),
                                   f"longer than the record after the drop ({orbit.time.values[-1] * 1e3:.3g} ms)")
    problem = _Problem(orbit, bearing, rotor, case, info, options)
    radius = np.hypot(problem.measured[:, 0], problem.measured[:, 1])
    tau = problem.tau[problem.fitted]
    if tau[int(np.argmax(radius))] > options.window - 1e-3:
        raise InputError.for_field("window", options.typed.get("window", options.window),
                                   "ends before the first impact has rebounded (the orbit is still moving out at its "
                                   "end); make it longer")
    p0 = _start_point(problem, case, options)
    lower = [0.0, 0.5 * p0[1], p0[2] - math.pi, -1e-3]
    upper = [1.0, 1.5 * p0[1], p0[2] + math.pi, 1e-3]
    scale = np.array([0.05, 5e-6, 0.2, 1e-4])
    res = optimize.least_squares(problem.residuals, p0, jac=problem.jacobian, bounds=(lower, upper), x_scale=scale,
                                 method="trf", max_nfev=options.max_evaluations)
    jac = problem.jacobian(res.x)
    m, n = jac.shape
    chi2 = float(np.sum(res.fun ** 2))
    reduced = chi2 / max(m - n, 1)
    inflation = 0.5 * (integrated_autocorrelation(res.fun[: m // 2]) + integrated_autocorrelation(res.fun[m // 2:]))
    try:
        cov = np.linalg.inv(jac.T @ jac) * reduced * inflation
    except np.linalg.LinAlgError:
        cov = np.full((n, n), np.nan)
    std = np.sqrt(np.clip(np.diag(cov), 0.0, None))
    with np.errstate(invalid="ignore", divide="ignore"):
        corr = cov / np.outer(std, std)
    x = res.x.copy()
    x[2] = math.remainder(x[2], 2.0 * math.pi)
    params = {}
    for j, (name, unit, factor, _) in enumerate(FIT_PARAMETERS):
        params[name] = {"value": float(x[j]), "std": float(std[j]), "start": float(p0[j]),
                        "unit": unit or "-", "value_shown": float(x[j] * factor), "std_shown": float(std[j] * factor)}
    return {
        "quality": fit_quality(res.x, lower, upper, reduced, scale),
        "parameters": params,
        "case": problem.case_for(x),
        "drop_time_s": info["drop_time_s"] + float(x[3]),
        "residual_rms_um": float(np.sqrt(np.mean(res.fun ** 2)) * problem.sigma * 1e6),
        "reduced_chi_square": reduced,
        "autocorrelation_inflation": inflation,
        "correlation": {"names": [p[0] for p in FIT_PARAMETERS], "matrix": np.nan_to_num(corr).tolist()},
        "window_ms": options.window * 1e3,
        "samples": int(m),
        "simulations": problem.evaluations,
        "success": bool(res.status > 0),
        "message": str(res.message),
        "fitted_orbit": (problem.tau[problem.fitted], problem.orbit(res.x), problem.measured),
    }


#: A reduced chi-square this many times the one of a model that explains the record to its noise (1) says the model
#: does not: the synthetic reference records fit at 50 (their noise correlated by the filter); a journal that rises
#: against gravity fitted at 6.6e5.
POOR_FIT = 1000.0


def fit_quality(x, lower, upper, reduced: float, scale) -> list[str]:
    """Why a converged fit is no result to sign: parameters on their bounds, a residual far above the noise.

    A parameter within a hundredth of its scale of a bound was stopped there, not found (a least-squares minimum
    inside the bounds has a zero gradient; on a bound it need not: Nocedal & Wright, Numerical Optimization, 2nd
    ed., 2006, Sec. 12.1).
    """
    notes = []
    for j, (name, unit, factor, _) in enumerate(FIT_PARAMETERS):
        for bound, side in ((lower[j], "lower"), (upper[j], "upper")):
            if abs(x[j] - bound) <= 0.01 * scale[j]:
                notes.append(f"{name} stopped on its {side} bound ({bound * factor:.4g} {unit or ''}".rstrip()
                             + "): the data do not hold it inside the range the fit may search")
    if reduced > POOR_FIT:
        notes.append(f"the residual is {math.sqrt(reduced):.3g} times the noise (reduced chi-square {reduced:.3g}): "
                     "the model does not explain this record (sensor axes, signs or offsets?)")
    return notes


def simulate_like_measurement(bearing, rotor, case, orbit: xr.Dataset, cutoff: float | None,
                              progress: Callable[[float], None] | None = None) -> tuple[xr.Dataset, dict, xr.Dataset]:
    """Run the full simulation of ``case`` and also show it as the sensors would (sampled, filtered).

    Returns the simulation Dataset and summary of :func:`run_drop` and an orbit Dataset on the
    measured time grid (``x``, ``y`` filtered with ``cutoff``), ready for
    :func:`auxbearing.experiment.orbit.orbit_features`.
    """
    tau = orbit.time.values
    dt = float(np.median(np.diff(tau)))
    duration = float(tau[-1])
    sim_case = replace(case, duration=duration, output_step=0.5 * dt)
    ds, summary = run_drop(bearing, rotor, sim_case, progress=progress)
    states = np.stack([ds.rotor_x.values, ds.rotor_y.values], axis=1)
    xy = sample_like(states, 0.5 * dt, tau, (case.start_x, case.start_y))
    seen = xr.Dataset({"x": ("time", lowpass(xy[:, 0], 1.0 / dt, cutoff), {"units": "m"}),
                       "y": ("time", lowpass(xy[:, 1], 1.0 / dt, cutoff), {"units": "m"})},
                      coords={"time": ("time", tau, {"units": "s", "long_name": "Time since the drop"})})
    return ds, summary, seen
