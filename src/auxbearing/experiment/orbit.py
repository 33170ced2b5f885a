"""Measured rotor drops: pre-processing, contact force and ball stress from the orbit, whirl, impacts.

Source paper Sec. III (Fig. 12-13): the rotor spinning at 6000 rpm drops onto a QJ202 or a
7202, its orbit is recorded and "combined with the experimental results, the maximum stress in
the collision process is calculated" (1728 vs 2348 MPa). The paper does not say how; this
module is our reading, built on the same models as the drop simulation (Sec. II.D):

1. pre-processing (:func:`preprocess`): scaling, zero-phase low-pass, noise level, the moment
   of the drop, and the sensor offset = centre of the clearance circle (fitted from the orbit's
   outer envelope, or given);
2. orbit -> force -> stress (:func:`contact_from_orbit`): the journal's excursion beyond the
   clearance circle, e = |O| - s, is shared in series by the rotor/race line contact
   (F = K_l delta^(10/9), Eq. 19, Palmgren's K_l) and the ball set carrying the race
   (:func:`auxbearing.bearings.ballset.ballset_state`, Eq. 10-16 and 22, THE ball-set model of the
   simulation). The race displacement u is not measured: we take it quasi-static, u along the
   contact normal with K_l (e - u)^(10/9) = F_ball(u), solved per sample (safeguarded Newton). The
   race (12.5 g on a ball set of ~1e8 N/m) rings at ~10 kHz, above the ~2.5 kHz of an impact,
   so its inertia is a small correction; the line-contact damping C_l d(delta)/dt of Eq. 19 is
   added to the force from the filtered rate. Ball loads and the max ball stress (paper_notes item 9)
   follow from u through the same ball-set model;
3. whirl from the complex spectrum of x + i y
   (:func:`auxbearing.analysis.whirl.spectral_whirl`), impacts by counting
   contact episodes with hysteresis.

Readers: :mod:`auxbearing.experiment.io`. Fit of the uncertain parameters:
:mod:`auxbearing.experiment.fit`. Everything in one call:
:func:`auxbearing.experiment.run.run_experiment`. Report section:
:func:`auxbearing.paper.experiment_stage.experiment_stage`. Example data (SYNTHETIC):
:mod:`auxbearing.experiment.synth`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
import xarray as xr
from scipy import optimize

from auxbearing.analysis.whirl import spectral_whirl
from auxbearing.bearings.ballset import ballset_state
from auxbearing.bearings.ratings import ISO76_BALL_STRESS
from auxbearing.common.errors import InputError
from auxbearing.common.params import convert

#: Standard gravity [m/s^2], to back-date the drop from the first clear movement (free fall).
GRAVITY = 9.80665
#: Angular bins of the clearance-circle fit: the envelope point of each bin is its largest radius.
CIRCLE_BINS = 36
#: A bin belongs to the clearance circle when its envelope reaches this fraction of the largest.
ENVELOPE_FRACTION = 0.85
#: Opening stretch of a record whose median is taken as the levitated position [s], at least
#: :data:`OPENING_SAMPLES` samples: a fixed time, not a share of the record, so rest appended after the
#: drop (a longer record) never pushes the window past the drop.
OPENING_STRETCH = 1e-3
#: Fewest samples of the opening stretch (a median of fewer is at the mercy of the noise).
OPENING_SAMPLES = 16
#: Highest low-pass cutoff as a share of the sampling rate: a Butterworth designed at or past the Nyquist
#: frequency (0.5) is unstable, and just below it the forward-backward pass rings.
NYQUIST_SHARE = 0.45


@dataclass(frozen=True)
class Preprocessing:
    """How a measured record is prepared.

    Every length, time and frequency takes a string with a unit ("8 kHz", "5 ms", "31.7 um") or a
    number in SI units (Hz, s, m).

    Parameters
    ----------
    offset : "auto", "fit", "start" or (x0, y0)
        Sensor reading at the bearing centre: fitted as the centre of the clearance circle
        (``fit``), the levitated position before the drop (``start``: the AMB held the journal
        in the bearing centre, the paper's "the rotor falls from the center"), or given [m].
        ``auto``: ``start`` when the record has a levitated stretch, else ``fit``. The circle fit
        rides on the contact deflections, which are larger at the bottom, so with an orbit that
        only rattles in the bottom it is a few um off; prefer ``start`` or a given offset then.
    scale : float
        Factor applied to the displacement channels (sensor sensitivity correction) [-].
    cutoff : float, str or None
        -3 dB frequency of the zero-phase 4th-order Butterworth low-pass [Hz]; None: no filter.
    drop_time : float, str or None
        Moment of the drop in record time [s]; None: detected.
    clearance : float, str or None
        Radius of the clearance circle to impose in the offset fit [m] (an arc too short to fix
        the radius needs it); None: fitted with the centre.

    Examples
    --------
    >>> Preprocessing(cutoff="5 kHz", drop_time="5 ms").cutoff
    5000.0
    >>> Preprocessing(cutoff="-5 kHz")
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: cutoff = '-5 kHz': must be > 0 Hz
    """

    offset: str | tuple[float, float] = "auto"
    scale: float = 1.0
    cutoff: float | None = 8e3
    drop_time: float | None = None
    clearance: float | None = None
    #: each field as it was given, so that a check made later against the record quotes it as written
    typed: dict = field(default_factory=dict, init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        typed = {f: getattr(self, f) for f in ("offset", "scale", "cutoff", "drop_time", "clearance")}
        object.__setattr__(self, "typed", typed)
        if isinstance(self.offset, str):
            if self.offset not in ("auto", "fit", "start"):
                raise InputError.for_field("offset", self.offset,
                                           "must be 'auto', 'fit', 'start' or two lengths (x0, y0)")
        else:
            try:
                parts = tuple(self.offset)
            except TypeError:
                parts = ()
            if len(parts) != 2:
                raise InputError.for_field("offset", self.offset,
                                           "must be 'auto', 'fit', 'start' or two lengths (x0, y0)")
            object.__setattr__(self, "offset", tuple(convert("offset", v, "length") for v in parts))
        object.__setattr__(self, "scale", convert("scale", self.scale, "dimensionless"))
        if not self.scale > 0.0:
            raise InputError.for_field("scale", typed["scale"], "must be > 0")
        cutoff = self.cutoff
        if isinstance(cutoff, str) and cutoff.strip().lower() == "none":
            cutoff = None
        if cutoff is not None:
            cutoff = convert("cutoff", cutoff, "frequency")
            if not cutoff > 0.0:
                raise InputError.for_field("cutoff", typed["cutoff"], "must be > 0 Hz")
        object.__setattr__(self, "cutoff", cutoff)
        if self.drop_time is not None:
            object.__setattr__(self, "drop_time", convert("drop_time", self.drop_time, "time"))
        if self.clearance is not None:
            object.__setattr__(self, "clearance", convert("clearance", self.clearance, "length"))
            if not self.clearance > 0.0:
                raise InputError.for_field("clearance", typed["clearance"], "must be > 0 m")


def lowpass(values: np.ndarray, rate: float, cutoff: float | None, given: object = None) -> np.ndarray:
    """Zero-phase 4th-order Butterworth low-pass (forward-backward, so no delay) [same units].

    ``given`` is the cutoff as the user wrote it ("30 kHz"), for the refusal of one at or past
    :data:`NYQUIST_SHARE` of the sampling rate.

    Examples
    --------
    >>> t = np.arange(2000) / 50e3
    >>> y = lowpass(np.sin(2 * np.pi * 100 * t) + np.sin(2 * np.pi * 20e3 * t), 50e3, 5e3)
    >>> bool(np.abs(y - np.sin(2 * np.pi * 100 * t))[100:-100].max() < 1e-3)
    True
    """
    if cutoff is None:
        return np.asarray(values, float).copy()
    if cutoff >= NYQUIST_SHARE * rate:
        raise InputError.for_field("cutoff", f"{cutoff:g} Hz" if given is None else given,
                                   f"must be below {NYQUIST_SHARE:g} x the record's sampling rate of {rate:.5g} Hz, "
                                   f"i.e. below {NYQUIST_SHARE * rate:.5g} Hz")
    from scipy import signal  # imported here: it takes 1.7 s, and most runs never filter a record

    sos = signal.butter(4, cutoff, fs=rate, output="sos")
    return signal.sosfiltfilt(sos, values)


def noise_level(values: np.ndarray) -> float:
    """Std of white noise from the second differences, robust to the motion (MAD) [units of values].

    For white noise of std sigma the second difference has std sqrt(6) sigma; the median
    absolute deviation / 0.6745 estimates a std without being pulled by the impacts.

    Examples
    --------
    >>> rng = np.random.default_rng(1)
    >>> round(noise_level(np.linspace(0, 1, 20000) ** 2 + rng.normal(0, 0.01, 20000)), 3)
    0.01
    """
    d2 = np.diff(np.asarray(values, float), 2)
    return float(np.median(np.abs(d2 - np.median(d2))) / 0.6745 / math.sqrt(6.0))


def detect_drop(t: np.ndarray, x: np.ndarray, y: np.ndarray, noise: float) -> tuple[float, dict]:
    """Moment of the drop: the journal leaves its levitated position, back-dated by free fall.

    The first sample farther than d = max(10 noise, 2 um) from the median of the opening
    stretch (:data:`OPENING_STRETCH`) marks the movement; a journal starting from rest falls d in sqrt(2 d / g), so the
    drop is that much earlier. The unbalance adds a drift that makes the movement visible a
    little sooner, so the estimate is early by up to ~0.5 ms; the fit refines it.

    Returns
    -------
    drop_time : float
        [s] in record time.
    info : dict
        Levitated position (x, y) [m] and how the drop was found.
    """
    n0 = max(OPENING_SAMPLES, int(np.searchsorted(t, t[0] + OPENING_STRETCH)))
    x0, y0 = float(np.median(x[:n0])), float(np.median(y[:n0]))
    threshold = max(10.0 * noise, 2e-6)
    moved = np.nonzero(np.hypot(x - x0, y - y0) > threshold)[0]
    if moved.size == 0:
        raise InputError.for_field("measured record", f"{t.size} samples",
                                   f"the journal never moves more than {threshold * 1e6:.3g} um: no drop in it")
    first = int(moved[0])
    if first < 2 * n0:
        return float(t[0]), {"levitated_x_m": float(x[0]), "levitated_y_m": float(y[0]),
                             "drop_detection": "record starts at the drop (no levitated stretch)"}
    drop = float(t[first] - math.sqrt(2.0 * threshold / GRAVITY))
    pre = t < drop
    if not pre.any():  # a noisy record can back-date the drop to its first sample
        pre = t <= t[0]
    return max(drop, float(t[0])), {
        "levitated_x_m": float(np.median(x[pre])), "levitated_y_m": float(np.median(y[pre])),
        "drop_detection": f"first excursion > {threshold * 1e6:.3g} um at {t[first] * 1e3:.3f} ms, "
                          "back-dated by free fall"}


def fit_clearance_circle(x: np.ndarray, y: np.ndarray, centre: tuple[float, float],
                         radius: float | None = None) -> dict:
    """Centre (the sensor offset) and radius of the clearance circle from the orbit's outer envelope.

    The orbit (after the drop) is binned in :data:`CIRCLE_BINS` angles about the current
    centre; the largest radius of each bin is an envelope point, and bins whose envelope
    reaches :data:`ENVELOPE_FRACTION` of the largest lie on the wall. A geometric least-squares
    circle through them (Gauss-Newton, scipy ``least_squares``) moves the centre; five rounds.
    The envelope rides on the contact deflection (um), so the radius is the clearance plus
    a typical excursion and the centre is pulled a little toward the most-hit side (gravity).

    Returns
    -------
    dict
        ``centre`` (x0, y0) [m], ``radius`` [m], ``coverage_deg`` (angular span of the wall
        points), ``points`` (number), ``rms`` residual [m].
    """
    c = np.asarray(centre, float)
    r_fit = radius
    keep_x = keep_y = np.empty(0)
    for _ in range(5):
        dx, dy = x - c[0], y - c[1]
        r = np.hypot(dx, dy)
        k = np.minimum(((np.arctan2(dy, dx) + math.pi) / (2 * math.pi) * CIRCLE_BINS).astype(int), CIRCLE_BINS - 1)
        best = np.full(CIRCLE_BINS, -1)
        for b in range(CIRCLE_BINS):
            idx = np.nonzero(k == b)[0]
            if idx.size >= 3:
                best[b] = idx[np.argmax(r[idx])]
        used = best[best >= 0]
        env = r[used]
        wall = used[env >= ENVELOPE_FRACTION * env.max()] if env.size else used
        keep_x, keep_y = x[wall], y[wall]
        if wall.size < 3:
            break
        guess = float(np.mean(np.hypot(keep_x - c[0], keep_y - c[1])))
        if radius is None:
            res = optimize.least_squares(_circle_residuals, [c[0], c[1], guess], x_scale=[guess, guess, guess],
                                         args=(keep_x, keep_y, None))
            c, r_fit = res.x[:2], float(res.x[2])
        else:
            res = optimize.least_squares(_circle_residuals, c, x_scale=[radius, radius], args=(keep_x, keep_y, radius))
            c = res.x
    if keep_x.size < 3:
        raise InputError.for_field("offset", "fit", "the orbit touches the clearance wall in fewer than 3 directions; "
                                   "give the offset (x0, y0)")
    angles = np.sort(np.degrees(np.arctan2(keep_y - c[1], keep_x - c[0])))
    gaps = np.diff(np.r_[angles, angles[0] + 360.0])
    coverage = float(360.0 - gaps.max())
    if radius is None and coverage < 90.0:
        raise InputError.for_field("offset", "fit", f"the orbit touches only {coverage:.0f} deg of the clearance "
                                   "circle, too little to fit its radius; give the clearance or the offset")
    rms = float(np.sqrt(np.mean((np.hypot(keep_x - c[0], keep_y - c[1]) - r_fit) ** 2)))
    return {"centre": (float(c[0]), float(c[1])), "radius": float(r_fit), "coverage_deg": coverage,
            "points": int(keep_x.size), "rms": rms}


def _circle_residuals(p: np.ndarray, x: np.ndarray, y: np.ndarray, radius: float | None) -> np.ndarray:
    return np.hypot(x - p[0], y - p[1]) - (p[2] if radius is None else radius)


def preprocess(measured: xr.Dataset, options: Preprocessing | None = None) -> tuple[xr.Dataset, dict]:
    """Scale, filter, find the drop and the sensor offset; the orbit in the bearing frame.

    Parameters
    ----------
    measured : xarray.Dataset
        From :func:`auxbearing.experiment.io.read_measured`.
    options : Preprocessing, optional

    Returns
    -------
    orbit : xarray.Dataset
        Over ``time`` = record time - drop time [s]: ``x``, ``y`` journal centre relative to the
        fitted (or given) bearing centre, filtered [m]; ``x_raw``, ``y_raw`` the same unfiltered;
        ``speed`` [rad/s] if measured.
    info : dict
        Offset, circle fit, drop time, noise (raw and filtered), levitated position.
    """
    opt = options or Preprocessing()
    t = measured.time.values
    rate = float(measured.attrs.get("sampling_rate_Hz", 1.0 / np.median(np.diff(t))))
    xs = measured.x.values * opt.scale
    ys = measured.y.values * opt.scale
    given = opt.typed.get("cutoff")
    xf, yf = lowpass(xs, rate, opt.cutoff, given), lowpass(ys, rate, opt.cutoff, given)
    noise_raw = max(noise_level(xs), noise_level(ys))
    drop, info = detect_drop(t, xf, yf, max(noise_raw, 1e-9))
    if opt.drop_time is not None:
        # the last sample is excluded: a drop there leaves no orbit to analyse
        if not t[0] <= opt.drop_time < t[-1]:
            raise InputError.for_field("drop_time", opt.typed.get("drop_time", opt.drop_time),
                                       f"must lie in the record's time span [{t[0]:g}, {t[-1]:g}) s: at or after its "
                                       "first sample and before its last")
        drop = float(opt.drop_time)
        info["drop_detection"] = "given"
    pre = t < drop
    noise_filtered = float(max(np.std(xf[pre]), np.std(yf[pre]))) if pre.sum() >= 32 else noise_raw
    after = t >= drop
    circle = None
    method = opt.offset
    if method == "auto":
        method = "start" if pre.sum() >= 16 else "fit"
    if isinstance(method, str) and method == "fit":
        try:
            circle = fit_clearance_circle(xf[after], yf[after], (info["levitated_x_m"], info["levitated_y_m"]),
                                          opt.clearance)
        except InputError as err:
            if opt.offset != "auto":
                raise
            raise _auto_fell_back(err, t, xs, ys, noise_raw, opt) from None
        x0, y0 = circle["centre"]
    elif isinstance(method, str):
        if pre.sum() < 16:
            raise InputError.for_field("offset", "start", "the record has no levitated stretch before the drop; "
                                       "use 'fit' or give the offset")
        x0, y0 = info["levitated_x_m"], info["levitated_y_m"]
    else:
        x0, y0 = (float(v) for v in opt.offset)
    tau = t - drop
    data = {"x": ("time", xf - x0, {"units": "m", "long_name": "Journal centre x, bearing frame, filtered"}),
            "y": ("time", yf - y0, {"units": "m", "long_name": "Journal centre y, bearing frame, filtered"}),
            "x_raw": ("time", xs - x0, {"units": "m", "long_name": "Journal centre x, bearing frame, unfiltered"}),
            "y_raw": ("time", ys - y0, {"units": "m", "long_name": "Journal centre y, bearing frame, unfiltered"})}
    if "speed" in measured:
        data["speed"] = ("time", measured.speed.values, {"units": "rad/s", "long_name": "Rotor speed"})
    orbit = xr.Dataset(data, coords={"time": ("time", tau, {"units": "s", "long_name": "Time since the drop"})})
    info.update({
        "offset_x_m": x0, "offset_y_m": y0, "offset_method": method if isinstance(method, str) else "given",
        "circle": circle, "drop_time_s": drop, "sampling_rate_Hz": rate, "cutoff_Hz": opt.cutoff,
        "scale": opt.scale, "noise_raw_m": noise_raw, "noise_filtered_m": noise_filtered,
        "start_x_m": info["levitated_x_m"] - x0, "start_y_m": info["levitated_y_m"] - y0,
    })
    return orbit, info


def _auto_fell_back(err: InputError, t: np.ndarray, xs: np.ndarray, ys: np.ndarray, noise: float,
                    opt: Preprocessing) -> InputError:
    """The circle fit's refusal told as what 'auto' did: it found no levitated stretch, so it fitted.

    The person chose 'auto' (or left it), not 'fit', so the message names 'auto' and says why it fitted; when
    the unfiltered record does have a levitated stretch, the low-pass smeared it away and the cutoff is to blame.
    """
    cause = str(err).partition(": ")[2].split("; ")[0]
    smeared = ""
    if opt.cutoff is not None:
        raw_drop, _ = detect_drop(t, xs, ys, max(noise, 1e-9))
        if np.sum(t < raw_drop) >= 16:
            typed = opt.typed.get("cutoff", opt.cutoff)
            shown = typed if isinstance(typed, str) else f"{opt.cutoff:g} Hz"
            smeared = (f" (the unfiltered record has one: the low-pass cutoff of {shown} smears the drop back "
                       "over it)")
    return InputError.for_field(
        "offset", "auto", f"'auto' (the default) found no levitated stretch before the drop{smeared}, so it fell back "
        f"to fitting the offset to the orbit, but {cause}; give the offset as two lengths (x0, y0)"
        + (" or raise the cutoff" if smeared else ""))


def _ball_force_along(u: np.ndarray, nx: np.ndarray, ny: np.ndarray,
                      ball_params: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """F_b(u) = -F_ball(u n) . n [N] and its slope dF_b/du = -n . J n [N/m] (J: the ball set's Jacobian)."""
    disp = np.zeros((u.size, 5))
    disp[:, 1], disp[:, 2] = u * nx, u * ny
    state = ballset_state(disp, ball_params)
    jac = state.jacobian
    slope = -(nx * (jac[:, 1, 1] * nx + jac[:, 1, 2] * ny) + ny * (jac[:, 2, 1] * nx + jac[:, 2, 2] * ny))
    return -(state.force[:, 1] * nx + state.force[:, 2] * ny), slope


#: The root search stops where its step is below this share of the excursion (rounding of u is about 1e-16 of it).
_ROOT_STEP = 1e-13


def _race_displacement(e: np.ndarray, nx: np.ndarray, ny: np.ndarray, line_stiffness: float,
                       ball_params: np.ndarray, iterations: int) -> np.ndarray:
    """The root u in [0, e] of g(u) = K_l (e - u)^(10/9) - F_b(u) for each sample (Eq. 19 = Eq. 22 in series).

    g falls strictly from g(0) = K_l e^(10/9) > 0 to g(e) = -F_b(e) <= 0, so [0, e] brackets one root. Newton's
    steps are taken inside that bracket and replaced by a bisection step where they would leave it or shrink
    by less than half from the step before (the safeguarded Newton method, Press et al., Numerical Recipes,
    3rd ed. 2007, Sec. 9.4, ``rtsafe``): it converges whatever the start, and near the root quadratically, in
    6-7 ball-set evaluations where 60 steps of plain bisection were taken (the same u to 3e-16 of e).
    Samples that have converged leave the search, so each evaluation covers only those still moving.
    """
    lo, hi = np.zeros_like(e), e.copy()
    u = 0.5 * e
    last_step = e.copy()
    active = np.arange(e.size)
    for _ in range(iterations):
        if not active.size:
            break
        ua, ea = u[active], e[active]
        force, slope = _ball_force_along(ua, nx[active], ny[active], ball_params)
        gap = ea - ua
        g = line_stiffness * gap ** (10.0 / 9.0) - force
        dg = -(10.0 / 9.0) * line_stiffness * gap ** (1.0 / 9.0) - slope  # < 0: g falls
        below = g > 0.0  # the root lies above u
        lo_a = np.where(below, ua, lo[active])
        hi_a = np.where(below, hi[active], ua)
        with np.errstate(divide="ignore", invalid="ignore"):
            newton = ua - g / dg
        # a Newton step below the tolerance ends the search where it lands (it may round to u itself, which
        # must not be taken for a step leaving the bracket)
        converged = (g == 0.0) | (np.abs(newton - ua) <= _ROOT_STEP * ea)
        take = (np.isfinite(newton) & (newton > lo_a) & (newton < hi_a)
                & (np.abs(newton - ua) <= 0.5 * last_step[active]))
        nxt = np.where(converged, np.clip(newton, lo_a, hi_a), np.where(take, newton, 0.5 * (lo_a + hi_a)))
        nxt = np.where(g == 0.0, ua, nxt)
        lo[active], hi[active], u[active], last_step[active] = lo_a, hi_a, nxt, np.abs(nxt - ua)
        active = active[~(converged | (hi_a - lo_a <= _ROOT_STEP * ea))]
    return u


def contact_from_orbit(x: np.ndarray, y: np.ndarray, clearance: float, line_stiffness: float,
                       ball_params: np.ndarray, line_damping: float = 0.0, dt: float | None = None,
                       iterations: int = 60) -> dict:
    """Contact force, race displacement, ball loads and max ball stress from a journal orbit.

    The excursion beyond the clearance, e = sqrt(x^2 + y^2) - s (source paper Eq. 17 with the
    race centre unknown), is shared in series by the line contact and the ball set, quasi-static
    and along the contact normal n = (x, y)/|(x, y)|:

        K_l (e - u)^(10/9) = F_b(u),   F_b(u) = -F_ball(u n) . n    (Eq. 19 and Eq. 22)

    with F_ball the ball-set force of :func:`auxbearing.bearings.ballset.ballset_state` on the inner
    ring displaced by u n. The left side falls and the right side rises with u on [0, e], so
    [0, e] brackets the root, found by Newton's method kept inside the bracket (:func:`_race_displacement`).
    The contact force adds the line-contact damping of Eq. 19,
    C_l d(e - u)/dt (central differences), and is clipped at zero (a contact never pulls).

    Parameters
    ----------
    x, y : arrays
        Journal centre relative to the bearing centre [m].
    clearance : float
        s [m].
    line_stiffness : float
        K_l [N/m^(10/9)].
    ball_params : ndarray
        :func:`auxbearing.bearings.ballset.ballset_params` of the bearing.
    line_damping : float
        C_l [N s/m]; 0 gives the elastic force only.
    dt : float, optional
        Sample interval [s], needed when ``line_damping`` > 0.
    iterations : int
        Most steps of the root search (each a bisection step where Newton's would not do better; 60 are ample).

    Returns
    -------
    dict of arrays
        ``excursion`` e, ``line_penetration`` e - u, ``race_displacement`` u [m];
        ``elastic_force``, ``contact_force`` [N]; ``ball_load`` (n, Z, pairs) [N];
        ``max_ball_load`` [N]; ``max_ball_stress`` [Pa].

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> from auxbearing.bearings.ballset import ballset_params
    >>> out = contact_from_orbit(np.array([0.0]), np.array([-210e-6]), 200e-6, 1.463e9,
    ...                          ballset_params(get_bearing("QJ202")))
    >>> f, u = float(out["elastic_force"][0]), float(out["race_displacement"][0])
    >>> round(f), bool(abs(1.463e9 * (10e-6 - u) ** (10 / 9) / f - 1) < 1e-9)
    (593, True)
    """
    x = np.asarray(x, float)
    y = np.asarray(y, float)
    radius = np.hypot(x, y)
    excursion = radius - clearance
    n = x.size
    u = np.zeros(n)
    elastic = np.zeros(n)
    ball_load = np.zeros((n, *ballset_state(np.zeros(5), ball_params).load.shape))
    max_stress = np.zeros(n)
    touching = np.nonzero(excursion > 0.0)[0]
    if touching.size:
        e = excursion[touching]
        nx, ny = x[touching] / radius[touching], y[touching] / radius[touching]
        u[touching] = _race_displacement(e, nx, ny, line_stiffness, ball_params, iterations)
        elastic[touching] = line_stiffness * (e - u[touching]) ** (10.0 / 9.0)
        disp = np.zeros((touching.size, 5))
        disp[:, 1], disp[:, 2] = u[touching] * nx, u[touching] * ny
        state = ballset_state(disp, ball_params)
        ball_load[touching] = state.load
        max_stress[touching] = np.maximum(state.stress_inner, state.stress_outer).max(axis=(-2, -1))
    penetration = np.where(excursion > 0.0, excursion - u, 0.0)
    force = elastic.copy()
    if line_damping > 0.0:
        if dt is None:
            raise ValueError("dt is needed with line_damping > 0")
        rate = np.gradient(penetration, dt)
        force = np.where(excursion > 0.0, np.maximum(0.0, elastic + line_damping * rate), 0.0)
    return {"excursion": excursion, "line_penetration": penetration, "race_displacement": u,
            "elastic_force": elastic, "contact_force": force, "ball_load": ball_load,
            "max_ball_load": ball_load.reshape(n, -1).max(axis=1) if n else np.zeros(0),
            "max_ball_stress": max_stress}


def elastic_limit_excursion(direction: float, line_stiffness: float, ball_params: np.ndarray,
                            stress: float = ISO76_BALL_STRESS) -> float:
    """Excursion beyond the clearance [m] at which the contact puts its most loaded ball at ``stress``.

    The series split of :func:`contact_from_orbit` along the angle ``direction`` [rad], on a log grid of
    excursions from 1 nm to 10 mm (the stress rises with the excursion), interpolated in log-log.
    With the default, ISO 76's 4200 MPa, it is the deepest the journal can go beyond the clearance
    circle while the bearing stays within its static rating. Infinite if the grid never reaches it.

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> from auxbearing.bearings.ballset import ballset_params
    >>> round(elastic_limit_excursion(-np.pi / 2, 1.463e9, ballset_params(get_bearing("QJ202"))) * 1e6)
    79
    """
    e = np.geomspace(1e-9, 1e-2, 241)
    c = contact_from_orbit(e * math.cos(direction), e * math.sin(direction), 0.0, line_stiffness, ball_params)
    sigma = c["max_ball_stress"]
    if not sigma[-1] >= stress:
        return math.inf
    return float(np.exp(np.interp(math.log(stress), np.log(np.maximum(sigma, 1e-300)), np.log(e))))


def count_impacts(t: np.ndarray, excursion: np.ndarray, on: float, min_gap: float = 2e-4) -> dict:
    """Contact episodes of a sampled orbit: excursion above ``on``, ended below ``on``/2 (hysteresis).

    Two episodes closer than ``min_gap`` [s] count as one impact (a contact chattering within
    one collision). Returns the number of impacts, their start times [s] and the first one.

    Examples
    --------
    >>> t = np.arange(0, 0.01, 1e-5)
    >>> e = np.where((t % 0.004) < 0.0005, 2e-6, -1e-5)
    >>> count_impacts(t, e, 1e-6)["impacts"]
    3
    """
    starts: list[float] = []
    inside = False
    last_end = -math.inf
    for k in range(excursion.size):
        if not inside and excursion[k] > on:
            inside = True
            if not starts or t[k] - last_end > min_gap:
                starts.append(float(t[k]))
        elif inside and excursion[k] < 0.5 * on:
            inside = False
            last_end = float(t[k])
    return {"impacts": len(starts), "impact_times_s": starts, "first_impact_s": starts[0] if starts else None}


def orbit_features(orbit: xr.Dataset, clearance: float, line_stiffness: float, ball_params: np.ndarray,
                   line_damping: float, noise: float, spin: float) -> tuple[xr.Dataset, dict]:
    """Everything the orbit tells: force, stress, ball loads, impacts and whirl (after the drop).

    Parameters
    ----------
    orbit : xarray.Dataset
        From :func:`preprocess` (or a simulation put through the same steps).
    clearance, line_stiffness, ball_params, line_damping :
        As :func:`contact_from_orbit`.
    noise : float
        Noise of the filtered orbit [m]; an impact needs an excursion above max(4 noise, 0.5 um).
    spin : float
        Rotor spin [rad/s]; its sign defines forward whirl.

    Returns
    -------
    dataset : xarray.Dataset
        The orbit with ``excursion``, ``line_penetration``, ``race_displacement``,
        ``contact_force``, ``max_ball_load``, ``max_ball_stress`` and ``ball_load`` (time, ball, pair).
    summary : dict
        Peaks and their times, impacts, first impact, whirl (units in the keys). ``peak_excursion_um`` is
        the largest excursion beyond the clearance circle; an orbit that never gets beyond it has none
        (None, as have the peak times) and ``gap_to_clearance_um`` says how far inside it stays.
    """
    t = orbit.time.values
    after = t >= 0.0
    dt = float(np.median(np.diff(t)))
    c = contact_from_orbit(orbit.x.values, orbit.y.values, clearance, line_stiffness, ball_params,
                           line_damping, dt)
    ds = orbit.copy()
    units = {"excursion": ("m", "Journal excursion beyond the clearance circle, |O| - s"),
             "line_penetration": ("m", "Rotor/race line-contact penetration (quasi-static split)"),
             "race_displacement": ("m", "Inner race displacement in the ball set (quasi-static split)"),
             "contact_force": ("N", "Rotor/race contact force estimated from the orbit (Eq. 19)"),
             "max_ball_load": ("N", "Largest ball contact-pair load (shared ball-set model)"),
             "max_ball_stress": ("Pa", "Hertz max stress of the most loaded ball contact (paper_notes item 9)")}
    for name, (unit, long_name) in units.items():
        ds[name] = ("time", c[name], {"units": unit, "long_name": long_name})
    ds["ball_load"] = (("time", "ball", "pair"), c["ball_load"],
                       {"units": "N", "long_name": "Contact-pair load of each ball (shared ball-set model)"})
    on = max(4.0 * noise, 0.5e-6)
    impacts = count_impacts(t[after], c["excursion"][after], on)
    force, stress = np.where(after, c["contact_force"], 0.0), np.where(after, c["max_ball_stress"], 0.0)
    kf, ks = int(np.argmax(force)), int(np.argmax(stress))
    first = impacts["first_impact_s"]
    whirl = spectral_whirl(t, orbit.x.values, orbit.y.values, clearance, spin,
                         first if first is not None else t[-1] + 1.0)
    # an orbit that never gets beyond the clearance circle has no peak: its "time" would be the first sample
    # (before the drop) and its "excursion" a negative number; both are null, and how far the orbit stays
    # inside is stored under its own name
    reach = float(c["excursion"][after].max())
    summary = {
        "peak_contact_force_N": float(force[kf]),
        "peak_force_time_ms": float(t[kf] * 1e3) if force[kf] > 0.0 else None,
        "peak_ball_stress_MPa": float(stress[ks] / 1e6),
        "peak_stress_time_ms": float(t[ks] * 1e3) if stress[ks] > 0.0 else None,
        "peak_ball_load_N": float(c["max_ball_load"][after].max()),
        "peak_excursion_um": reach * 1e6 if reach > 0.0 else None,
        "gap_to_clearance_um": -reach * 1e6 if reach <= 0.0 else None,
        "impacts": impacts["impacts"], "impact_threshold_um": on * 1e6,
        "first_impact_ms": None if first is None else first * 1e3,
        "whirl": whirl["whirl"], "whirl_frequency_Hz": whirl["whirl_frequency_Hz"],
        "forward_power_fraction": whirl["forward_power_fraction"], "whirl_rms_um": whirl["whirl_rms_um"],
        "contact_fraction": float(np.mean(c["excursion"][after] > on)),
    }
    return ds, summary
