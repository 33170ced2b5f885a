"""Rotor drop onto the auxiliary bearing: compiled right-hand side and adaptive integration.

Source paper Sec. II.D (Eq. 17-26) read as ../shared/paper/NOTES.md ("How to read the drop
model"). Everything here is SI floats and numpy arrays, compiled with numba (``cache=True``).

State vector ``y`` (12 entries; rotor = journal centre O, race = inner-ring centre, both
relative to the fixed outer ring; gravity along -y; angles counter-clockwise)::

    0 x_r   1 y_r   2 theta_r   3 x_b   4 y_b   5 theta_b
    6 dx_r  7 dy_r  8 omega_r   9 dx_b 10 dy_b 11 omega_b

Model (free-body sketch: n is the unit vector from the race centre to the rotor centre,
t = z x n the counter-clockwise tangent):

* penetration delta = |O_r - O_b| - s (Eq. 17); the contact normal n comes from atan2 of the
  centre offset, i.e. the vector itself, which fixes the quadrant lost by Eq. 26's arctan
  (NOTES item 2);
* normal force F_n = max(0, K_l delta^(10/9) + C_l v_n) with v_n = (v_r - v_b) . n (Eq. 19-20),
  acting as -F_n n on the rotor (back toward the race centre) and +F_n n on the race;
* friction against the slip of the rotor surface over the race surface at the contact point,
  v_s = (v_r - v_b) . t + omega_r r - omega_b (r + s), F_t = -mu_1 F_n tanh(v_s / v_eps) along t
  on the rotor and the opposite on the race (Eq. 21 with the sign fixed, NOTES item 3). The
  tanh is the regularisation of sign(v_s): below v_eps the friction acts as a stiff viscous
  coupling, so it vanishes with the slip and lets the race roll with the rotor;
* rotor unbalance: mass centre G = O_r + e (cos theta_r, sin theta_r); Newton-Euler about G
  (J_r is the polar moment about G), so the unbalance enters through the exact kinematics of G
  instead of the centrifugal term of Eq. 25;
* ball set: F_e is the radial force of THE shared ball-set model (:mod:`auxbearing.core.ballset`,
  Eq. 22, which is the radial ball-set force, NOTES item 4; four-point and angular contact
  differ only through the geometry packed in its parameters, NOTES item 8). The right-hand
  side calls its force-only ``radial_force`` (zero axial and tilt displacement, the same pair
  loads as ``radial_support``, without the stresses); the outputs and the peak stress use
  ``radial_support`` (NOTES item 9). Plus isotropic viscous damping -C_b v_b. Eq. 23
  damps only the radial rate d|r_b|/dt, whose direction is undefined at the centre where the
  drop starts; for a ring carried all round by balls the isotropic form is the natural one;
* rolling resistance (Eq. 24): a tangential force mu_2 |F_e| tanh(omega_b R_i / v_eps) on the
  inner raceway against the race's spin, at the loaded zone (direction of -F_e) and the inner
  raceway radius R_i = (dm - D)/2, where balls touch the ring. Eq. 26 puts it at r + s and
  with a cos for a sin in its y line (NOTES item 1); here the sign follows the sketch.
"""

from __future__ import annotations

import hashlib
import inspect
import math
from pathlib import Path

import numpy as np
from numba import njit

from auxbearing.core import integrate as _ig
from auxbearing.core.ballset import radial_force, radial_support

# Parameter vector layout (filled by auxbearing.analysis.drop.build_model).
(P_MR, P_JR, P_E, P_MB, P_JB, P_R, P_S, P_KL, P_CL, P_CB, P_MU1, P_MU2, P_VEPS, P_G, P_RI,
 N_PARAMS) = range(16)
N_STATE = 12
#: Entries of the per-instant contact record of :func:`contact_state`.
CONTACT_FIELDS = ("penetration", "normal_force", "friction_force", "slip_velocity", "ball_force_x",
                  "ball_force_y", "max_ball_load", "max_ball_stress")
#: Entries of the statistics vector returned by :func:`integrate`.
STAT_FIELDS = ("h", "err_prev", "rejected_last", "steps", "rejected", "rhs_evals", "peak_force",
               "t_peak_force", "peak_stress", "t_peak_stress", "onsets", "t_first_contact",
               "prev_force", "prev_stress", "prev2_force", "prev2_stress", "prev_delta", "h_last",
               "peak_ball_load", "failed_at")
(S_H, S_ERRP, S_REJ, S_STEPS, S_REJECTED, S_NRHS, S_PF, S_TPF, S_PS, S_TPS, S_ONSETS, S_TFIRST,
 S_F1, S_S1, S_F0, S_S0, S_DELTA, S_HLAST, S_PQ, S_FAIL) = range(len(STAT_FIELDS))
#: Smallest step relative to the time scale of the run before the integration gives up
#: (a non-finite or exploding state); a contact onset needs about 1e-10 s at rtol = 1e-9.
MIN_STEP = 1e-14
#: Step ends whose largest ball load is below this fraction of the running peak load cannot
#: hold the peak stress (sigma ~ C(alpha) Q^(1/3) and C varies by far less than 1 - 0.7^(1/3)
#: over the loaded contact angles), so the stress is evaluated only on the others.
STRESS_CANDIDATE_LOAD = 0.7


@njit(cache=True)
def contact_state(y, p, bp):
    """Contact quantities at one state (source paper Eq. 17-24, corrected as the module says).

    Parameters
    ----------
    y : ndarray, shape (12,)
        State (see the module docstring) [m, rad, m/s, rad/s].
    p : ndarray
        Model parameters (``P_*`` layout) [SI].
    bp : ndarray
        Ball-set parameters of :func:`auxbearing.core.ballset.kernel_params`.

    Returns
    -------
    tuple of float
        penetration delta [m], normal force F_n [N], friction force on the rotor along t [N],
        slip velocity v_s [m/s], ball-set force on the race (x, y) [N], largest ball contact
        load [N], largest ball contact Hertz stress [Pa].
    """
    delta, fn, ft, vs, _, _ = _rotor_race(y, p)
    fex, fey, qmax, smax = radial_support(y[3], y[4], bp)
    return delta, fn, ft, vs, fex, fey, qmax, smax


@njit(cache=True)
def _rotor_race(y, p):
    """Rotor/race contact (Eq. 17, 19-21 corrected): delta, F_n, F_t, v_s and the normal n."""
    dx = y[0] - y[3]
    dy = y[1] - y[4]
    dist = math.sqrt(dx * dx + dy * dy)
    delta = dist - p[P_S]
    if delta <= 0.0:
        return delta, 0.0, 0.0, 0.0, 0.0, 0.0
    nx = dx / dist
    ny = dy / dist
    dvx = y[6] - y[9]
    dvy = y[7] - y[10]
    vn = dvx * nx + dvy * ny
    fn = max(0.0, p[P_KL] * delta ** (10.0 / 9.0) + p[P_CL] * vn)
    vs = -dvx * ny + dvy * nx + y[8] * p[P_R] - y[11] * (p[P_R] + p[P_S])
    ft = -p[P_MU1] * fn * math.tanh(vs / p[P_VEPS])
    return delta, fn, ft, vs, nx, ny


@njit(cache=True)
def rhs(y, p, bp, out):
    """Time derivative of the drop state, written into ``out`` (Eq. 25-26, corrected).

    Examples
    --------
    >>> import numpy as np
    >>> from auxbearing import get_bearing
    >>> from auxbearing.core.ballset import kernel_params
    >>> p = np.zeros(N_PARAMS); p[[P_MR, P_JR, P_MB, P_JB, P_R, P_S, P_VEPS, P_G]] = (
    ...     1.0, 1.0, 1.0, 1.0, 7.3e-3, 2e-4, 1e-2, 9.81)
    >>> d = np.zeros(12); rhs(np.zeros(12), p, kernel_params(get_bearing("QJ202")), d)
    >>> float(d[7]), float(d[10])  # free fall of the rotor; the race at rest in the centre
    (-9.81, -9.81)
    """
    _rhs(y, p, bp, out)


@njit(cache=True)
def _rhs(y, p, bp, out):
    """:func:`rhs` returning (delta, F_n, largest ball load) for bookkeeping.

    The ball-set force comes from ``radial_force`` of the shared model, the force-only form of
    ``radial_support`` (same pair loads), which the outputs use for the stress.
    """
    delta, fn, ft, _, nx, ny = _rotor_race(y, p)
    fex, fey, qmax = radial_force(y[3], y[4], bp)
    fcx = -fn * nx - ft * ny  # contact force ON the rotor (zero without contact)
    fcy = -fn * ny + ft * nx
    # rotor: Newton-Euler about the mass centre G = O + e (cos th, sin th)
    c = math.cos(y[2])
    s = math.sin(y[2])
    e = p[P_E]
    w = y[8]
    moment_g = p[P_R] * ft - e * (c * fcy - s * fcx)
    alpha = moment_g / p[P_JR]
    out[0] = y[6]
    out[1] = y[7]
    out[2] = w
    out[6] = fcx / p[P_MR] + e * (s * alpha + c * w * w)
    out[7] = fcy / p[P_MR] - p[P_G] - e * (c * alpha - s * w * w)
    out[8] = alpha
    # race: contact reaction, ball set, its damping, rolling resistance, gravity
    fx = -fcx + fex - p[P_CB] * y[9]
    fy = -fcy + fey - p[P_CB] * y[10]
    torque = -(p[P_R] + p[P_S]) * ft
    fe = math.sqrt(fex * fex + fey * fey)
    if fe > 0.0 and p[P_MU2] > 0.0:
        # loaded zone at -F_e/|F_e| from the race centre; tangent there is z x that direction
        ux = -fex / fe
        uy = -fey / fe
        roll = -p[P_MU2] * fe * math.tanh(y[11] * p[P_RI] / p[P_VEPS])
        fx += -roll * uy
        fy += roll * ux
        torque += p[P_RI] * roll
    out[3] = y[9]
    out[4] = y[10]
    out[5] = y[11]
    out[9] = fx / p[P_MB]
    out[10] = fy / p[P_MB] - p[P_G]
    out[11] = torque / p[P_JB]
    return delta, fn, qmax


@njit(cache=True)
def _force_at(coeff, theta, p, bp, tmp, which):
    _ig.dense_eval(coeff, theta, tmp)
    r = contact_state(tmp, p, bp)
    return r[1] if which == 0 else r[7]


@njit(cache=True)
def _refine_peak(coeff, p, bp, tmp, which):
    """Golden-section search of a contact-force or stress maximum inside one step (dense output)."""
    g = 0.5 * (math.sqrt(5.0) - 1.0)
    lo = 0.0
    hi = 1.0
    a = hi - g * (hi - lo)
    b = lo + g * (hi - lo)
    fa = _force_at(coeff, a, p, bp, tmp, which)
    fb = _force_at(coeff, b, p, bp, tmp, which)
    for _ in range(40):
        if fa >= fb:
            hi = b
            b = a
            fb = fa
            a = hi - g * (hi - lo)
            fa = _force_at(coeff, a, p, bp, tmp, which)
        else:
            lo = a
            a = b
            fa = fb
            b = lo + g * (hi - lo)
            fb = _force_at(coeff, b, p, bp, tmp, which)
    best = 0.5 * (lo + hi)
    return best, _force_at(coeff, best, p, bp, tmp, which)


@njit(cache=True)
def _onset(coeff, p, tmp):
    """Fraction of the step at which the penetration crosses zero (bisection on dense output)."""
    lo = 0.0
    hi = 1.0
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        _ig.dense_eval(coeff, mid, tmp)
        d = math.hypot(tmp[0] - tmp[3], tmp[1] - tmp[4]) - p[P_S]
        if d > 0.0:
            hi = mid
        else:
            lo = mid
    return hi


@njit(cache=True)
def _track_peaks(t, h, coeff, prev_coeff, p, bp, tmp, stats, fn, sn, delta):
    """Update onsets, first contact and exact peaks after an accepted step ending at t + h."""
    if delta > 0.0 and stats[S_DELTA] <= 0.0:
        stats[S_ONSETS] += 1.0
        if stats[S_TFIRST] < 0.0:
            stats[S_TFIRST] = t + _onset(coeff, p, tmp) * h
    stats[S_DELTA] = delta
    # a local maximum of the step-end sequence lies in one of the two last steps
    for which in range(2):
        i1 = S_F1 if which == 0 else S_S1
        i0 = S_F0 if which == 0 else S_S0
        ip = S_PF if which == 0 else S_PS
        it = S_TPF if which == 0 else S_TPS
        now = fn if which == 0 else sn
        last = stats[i1]
        if last > 0.0 and last >= now and last > stats[i0] and last > 0.9 * stats[ip]:
            th, v = _refine_peak(coeff, p, bp, tmp, which)
            if v > stats[ip]:
                stats[ip] = v
                stats[it] = t + th * h
            th, v = _refine_peak(prev_coeff, p, bp, tmp, which)
            if v > stats[ip]:
                stats[ip] = v
                stats[it] = t - stats[S_HLAST] + th * stats[S_HLAST]
        if last > stats[ip]:
            stats[ip] = last
            stats[it] = t
        if now > stats[ip]:
            stats[ip] = now
            stats[it] = t + h
        stats[i0] = last
        stats[i1] = now


@njit(cache=True)
def integrate(y, t0, t1, p, bp, rtol, atol, max_step, grid_dt, k_next, grid, stats):
    """Advance the drop from t0 to t1 with DOPRI5 and PI step control (``y`` updated in place).

    Dormand-Prince 5(4) with the fourth-order dense output and PI controller of
    :mod:`auxbearing.core.integrate`. Contact onset (where the damping term of Eq. 19 jumps by
    C_l v_n) and loss (continuous: the force is clipped at zero) are handled by the error
    control: a step across the jump fails the error test and shrinks, by at most 5x per
    attempt, until it ends just before the jump; the next step starts on the other side and the
    controller grows the step again by up to 10x per step. This costs a few tens of rejected
    steps per onset (default run: 358 rejected of 12,229 steps with 20 onsets) and cannot stall;
    a step-size underflow (only with a non-finite state) stops the loop and is reported.

    Parameters
    ----------
    y : ndarray, shape (12,)
        State at t0; overwritten with the state at t1.
    t0, t1 : float
        Start and end time [s]; the last step lands exactly on t1.
    p, bp : ndarray
        Model and ball-set parameters.
    rtol : float
        Relative tolerance [-].
    atol : ndarray, shape (12,)
        Absolute tolerance per state [SI].
    max_step : float
        Largest step [s]; keeps free flight from stepping over a whole contact.
    grid_dt : float
        Output interval [s]; output instant k is k * grid_dt.
    k_next : int
        Index of the next output instant to fill.
    grid : ndarray, shape (n_out, 12)
        Output states on the uniform grid (rows k_next... filled).
    stats : ndarray
        Step-size memory and running statistics (``STAT_FIELDS``), carried between calls.

    Returns
    -------
    int
        The new ``k_next``. When the step size underflows (a non-finite state), the loop stops
        and ``stats[S_FAIL]`` holds the time reached.
    """
    n = N_STATE
    k1 = np.empty(n)
    k2 = np.empty(n)
    k3 = np.empty(n)
    k4 = np.empty(n)
    k5 = np.empty(n)
    k6 = np.empty(n)
    k7 = np.empty(n)
    yt = np.empty(n)
    y1 = np.empty(n)
    err = np.empty(n)
    tmp = np.empty(n)
    coeff = np.empty((5, n))
    prev_coeff = np.zeros((5, n))
    prev_coeff[0, :] = y
    _rhs(y, p, bp, k1)
    stats[S_NRHS] += 1.0
    t = t0
    h = stats[S_H]
    n_out = grid.shape[0]
    end_slack = 1e-13 * max(1.0, abs(t1))  # a remainder below this is roundoff, not a step
    while t < t1:
        if t1 - t <= end_slack:
            t = t1
            break
        if h < MIN_STEP * max(1.0, t1):
            stats[S_FAIL] = t
            break
        h = min(h, max_step)
        h_proposed = h
        last = t + h >= t1 - end_slack
        if last:
            h = t1 - t
        for i in range(n):
            yt[i] = y[i] + h * _ig.A21 * k1[i]
        _rhs(yt, p, bp, k2)
        for i in range(n):
            yt[i] = y[i] + h * (_ig.A31 * k1[i] + _ig.A32 * k2[i])
        _rhs(yt, p, bp, k3)
        for i in range(n):
            yt[i] = y[i] + h * (_ig.A41 * k1[i] + _ig.A42 * k2[i] + _ig.A43 * k3[i])
        _rhs(yt, p, bp, k4)
        for i in range(n):
            yt[i] = y[i] + h * (_ig.A51 * k1[i] + _ig.A52 * k2[i] + _ig.A53 * k3[i] + _ig.A54 * k4[i])
        _rhs(yt, p, bp, k5)
        for i in range(n):
            yt[i] = y[i] + h * (_ig.A61 * k1[i] + _ig.A62 * k2[i] + _ig.A63 * k3[i] + _ig.A64 * k4[i]
                                + _ig.A65 * k5[i])
        _rhs(yt, p, bp, k6)
        for i in range(n):
            y1[i] = y[i] + h * (_ig.B1 * k1[i] + _ig.B3 * k3[i] + _ig.B4 * k4[i] + _ig.B5 * k5[i]
                                + _ig.B6 * k6[i])
        delta1, fn1, q1 = _rhs(y1, p, bp, k7)
        stats[S_NRHS] += 6.0
        for i in range(n):
            err[i] = h * (_ig.E1 * k1[i] + _ig.E3 * k3[i] + _ig.E4 * k4[i] + _ig.E5 * k5[i]
                          + _ig.E6 * k6[i] + _ig.E7 * k7[i])
        e_norm = _ig.error_norm(err, y, y1, rtol, atol)
        if not (e_norm <= 1.0):
            if not math.isfinite(e_norm):
                h *= _ig.MIN_FACTOR
            else:
                h *= _ig.next_step_factor(e_norm, stats[S_ERRP], True)
            stats[S_REJ] = 1.0
            stats[S_REJECTED] += 1.0
            continue
        # accepted
        _ig.dense_coefficients(y, y1, h, k1, k3, k4, k5, k6, k7, coeff)
        while k_next < n_out and k_next * grid_dt <= t + h + 1e-9 * grid_dt:
            theta = (k_next * grid_dt - t) / h
            _ig.dense_eval(coeff, min(1.0, max(0.0, theta)), tmp)
            for i in range(n):
                grid[k_next, i] = tmp[i]
            k_next += 1
        sigma1 = 0.0
        if q1 >= STRESS_CANDIDATE_LOAD * stats[S_PQ]:
            sigma1 = radial_support(y1[3], y1[4], bp)[3]
        stats[S_PQ] = max(stats[S_PQ], q1)
        _track_peaks(t, h, coeff, prev_coeff, p, bp, tmp, stats, fn1, sigma1, delta1)
        factor = _ig.next_step_factor(e_norm, stats[S_ERRP], stats[S_REJ] > 0.5)
        stats[S_ERRP] = max(e_norm, 1e-4)
        stats[S_REJ] = 0.0
        stats[S_STEPS] += 1.0
        stats[S_HLAST] = h
        t = t1 if last else t + h
        for i in range(n):
            y[i] = y1[i]
            k1[i] = k7[i]
            for j in range(5):
                prev_coeff[j, i] = coeff[j, i]
        # a step shortened to land on t1 says nothing about the step size the solution allows
        h = max(h * factor, h_proposed) if last else h * factor
    stats[S_H] = h
    return k_next


@njit(cache=True)
def grid_contact(states, p, bp):
    """:func:`contact_state` over the rows of ``states`` -> array (n, len(CONTACT_FIELDS))."""
    out = np.empty((states.shape[0], len(CONTACT_FIELDS)))
    for k in range(states.shape[0]):
        r = contact_state(states[k], p, bp)
        for j in range(len(CONTACT_FIELDS)):
            out[k, j] = r[j]
    return out


@njit(cache=True)
def ballset_strain_energy(dx, dy, bp, n_nodes):
    """Elastic energy stored in the ball set at race displacement (dx, dy) [J].

    U = -integral_0^1 F(t d) . d dt along the straight path from the centre (the ball-set
    force is conservative: sum of Hertz pairs Q = K_b delta^1.5, Eq. 22), by the composite
    midpoint rule on ``n_nodes`` panels refined by one Richardson step (error ~ n^-4 away from
    the pair onsets, enough for the energy test at n = 400).
    """
    total = 0.0
    coarse = 0.0
    for i in range(n_nodes):
        t = (i + 0.5) / n_nodes
        fx, fy, _, _ = radial_support(t * dx, t * dy, bp)
        total -= fx * dx + fy * dy
    for i in range(n_nodes // 2):
        t = (i + 0.5) / (n_nodes // 2)
        fx, fy, _, _ = radial_support(t * dx, t * dy, bp)
        coarse -= fx * dx + fy * dy
    fine = total / n_nodes
    return fine + (fine - coarse / (n_nodes // 2)) / 3.0


@njit(cache=True)
def mechanical_energy(states, p, bp, n_nodes):
    """Kinetic + gravity + contact strain energy at each row of ``states`` [J].

    Kinetic: rotor translation of the mass centre and spin about it, race translation and spin.
    Strain: line contact K_l delta^(19/9) 9/19 (integral of Eq. 19's elastic part) and the
    ball set (:func:`ballset_strain_energy`). Conserved when friction, damping and unbalance
    are off (energy test).
    """
    out = np.empty(states.shape[0])
    for k in range(states.shape[0]):
        y = states[k]
        e = p[P_E]
        vgx = y[6] - e * y[8] * math.sin(y[2])
        vgy = y[7] + e * y[8] * math.cos(y[2])
        kin = 0.5 * p[P_MR] * (vgx * vgx + vgy * vgy) + 0.5 * p[P_JR] * y[8] ** 2
        kin += 0.5 * p[P_MB] * (y[9] ** 2 + y[10] ** 2) + 0.5 * p[P_JB] * y[11] ** 2
        pot = p[P_MR] * p[P_G] * (y[1] + e * math.sin(y[2])) + p[P_MB] * p[P_G] * y[4]
        delta = math.hypot(y[0] - y[3], y[1] - y[4]) - p[P_S]
        if delta > 0.0:
            pot += p[P_KL] * 9.0 / 19.0 * delta ** (19.0 / 9.0)
        pot += ballset_strain_energy(y[3], y[4], bp, n_nodes)
        out[k] = kin + pot
    return out


def new_stats(h0: float) -> np.ndarray:
    """Fresh statistics vector for :func:`integrate` with first step ``h0`` [s]."""
    stats = np.zeros(len(STAT_FIELDS))
    stats[S_H] = h0
    stats[S_ERRP] = 1e-4
    stats[S_TFIRST] = -1.0
    stats[S_TPF] = -1.0
    stats[S_TPS] = -1.0
    stats[S_DELTA] = -1.0
    stats[S_FAIL] = -1.0
    return stats


def _cache_dir() -> Path:
    """Where numba keeps this module's cache (``__pycache__`` or under ``NUMBA_CACHE_DIR``)."""
    try:
        return Path(integrate._cache._cache_path)  # numba internals; fall back if they move
    except AttributeError:  # pragma: no cover
        return Path(__file__).parent / "__pycache__"


def invalidate_stale_cache(cache_dir: Path | None = None) -> bool:
    """Drop this module's numba cache when a compiled dependency changed since it was written.

    numba keys a cached function on its own file only; the drop kernels inline the ball-set
    model and the DOPRI5 helpers, so an edited ball-set model would otherwise run from a stale
    cache. A hash of those sources is kept beside the cache; returns True when files were dropped.
    """
    cache_dir = _cache_dir() if cache_dir is None else Path(cache_dir)
    try:
        digest = hashlib.sha256()
        for func in (radial_support, _ig.error_norm):
            digest.update(Path(inspect.getsourcefile(func.py_func)).read_bytes())
        stamp = cache_dir / "drop.dependency-stamp"
        if stamp.exists() and stamp.read_text() == digest.hexdigest():
            return False
        stale = list(cache_dir.glob("drop.*.nb[ic]"))
        for path in stale:
            path.unlink()
        cache_dir.mkdir(parents=True, exist_ok=True)
        stamp.write_text(digest.hexdigest())
        return bool(stale)
    except OSError:  # read-only install: nothing cached here to go stale
        return False


invalidate_stale_cache()
