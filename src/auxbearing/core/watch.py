"""The machine drop's observer and compiled driver: peaks, impacts, whirl windows, range limits.

:func:`observe` runs after every accepted step of :func:`auxbearing.core.integrate.dopri5`:

* exact peaks of the line-contact force, the ball stress and the axial face force per plane: a
  local maximum of the step-end sequence lies in one of the last two steps and is refined by a
  golden-section search on their dense output;
* contact onsets (impacts) and the first contact time, by bisection on the dense output;
* whirl windows: per plane, the turning of the journal about the bearing centre, its mean radius,
  the contact time, the mean contact force and the spin speeds, integrated over windows of fixed
  length (bounded memory, whatever the run's length) and classified by :mod:`auxbearing.analysis.whirl`;
* the model's range, :class:`~auxbearing.core.machine.Limits` (a run that leaves it stops; the
  code, plane, time and value are kept): a journal contact force whose peak pressure passes the journal
  and race material's limit (the conformal contact of :func:`auxbearing.core.hertz.journal_contact`),
  ball stress beyond the elastic-contact limit, a contact ellipse running over the groove
  shoulder, a mount beyond its travel, a race running off its balls axially, and more energy in the
  machine than was brought in (a numerical run-away).
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from auxbearing.core import integrate as ig
from auxbearing.core import probes
from auxbearing.core.machine import (
    D_BFX,
    D_BFY,
    D_FA,
    D_FN,
    D_MOUNT,
    D_PEN,
    D_QMAX,
    DIAG_FIELDS,
    N_PLANE,
    N_ROTOR,
    OMEGA,
    ROMEGA,
    RZ,
    energy_balance,
)
from auxbearing.core.probes import ball_extremes, orbit
from auxbearing.core.uncounted import uncounted

#: Stop codes of :func:`observe` (0: none).
JOURNAL_PRESSURE, BALL_STRESS, SHOULDER, MOUNT_TRAVEL, AXIAL_RUNAWAY, ENERGY_GAIN = range(1, 7)
STOP_NAMES = {JOURNAL_PRESSURE: "journal_contact_overstress", BALL_STRESS: "ball_stress_beyond_elastic",
              SHOULDER: "contact_ellipse_over_shoulder", MOUNT_TRAVEL: "mount_beyond_travel",
              AXIAL_RUNAWAY: "race_runs_off_axially", ENERGY_GAIN: "energy_gain"}
#: Step ends whose largest ball load is below this fraction of the running peak load cannot hold the
#: peak stress (sigma ~ C(alpha) Q^(1/3) and C varies by far less than 1 - 0.7^(1/3) over the loaded
#: contact angles), so the stresses are evaluated only on the others.
STRESS_CANDIDATE_LOAD = 0.7
#: Columns of a whirl-window record. ``orbit_speed_sq`` is the mean square of the journal centre's speed in its
#: bore [m^2/s^2]: how much the journal moves (rattle, swing, whirl), which a coast-down's reduced stretch
#: freezes (:func:`auxbearing.analysis.coastdown_phases.motion_steady`). ``mean_cube_bearing_load`` is the time
#: mean of the cube of the bearing's radial load [N^3], the ball set's reaction on the race (the journal's impacts
#: reach it through the race's inertia), from which a coast-down's window takes the mean load of a varying load
#: (:mod:`auxbearing.analysis.coastdown_life`).
WHIRL_FIELDS = ("whirl_speed", "mean_radius", "contact_fraction", "spin_speed", "race_speed", "duration",
                "mean_normal_force", "mean_axial_force", "orbit_speed_sq", "mean_cube_bearing_load")
_FORCE, _STRESS, _AXIAL = range(3)
#: A whirl window closes at the step that reaches its end to within this share of a window. Its end is added up
#: window by window, so a run whose last step lands on the end of its last window (a 200 ms drop in 10 ms windows)
#: could fall short of it by round-off (0.2 against 0.20000000000000004) and leave that window unjudged: the
#: blower's drops closed 19 of their 20.
WINDOW_END_SLACK = 1e-9


class Watch(NamedTuple):
    """The observer's memory (arrays, updated in place)."""

    peak: np.ndarray  #: (3, planes): largest line force [N], ball stress [Pa], |axial force| [N]; per plane
    peak_time: np.ndarray  #: (3, planes) [s]
    peak_load: np.ndarray  #: (planes,) largest ball-pair load [N]
    shoulder_use: np.ndarray  #: (planes,) largest (alpha + a/r) / shoulder angle seen
    history: np.ndarray  #: (3, planes, 2): quantity, plane, (value a step back, value now)
    prev_coeff: np.ndarray  #: (5, n) dense output of the previous step
    prev_h: np.ndarray  #: (1,)
    in_contact: np.ndarray  #: (planes,)
    onsets: np.ndarray  #: (planes,)
    first_contact: np.ndarray  #: (planes,) [s], -1 before
    stop: np.ndarray  #: (4,) code, plane, time [s], value
    energy_in0: np.ndarray  #: (1,) mechanical energy at the start [J]
    energy_error: np.ndarray  #: (2,) largest |accounted - in| / scale seen, and the last one (see energy_balance)
    window: np.ndarray  #: (1,) length of a whirl window [s]
    window_count: np.ndarray  #: (1,) int64, closed windows
    window_end: np.ndarray  #: (1,) end time of the open window [s]
    whirl_acc: np.ndarray  #: (planes, len(WHIRL_FIELDS)) running integrals of the open window
    whirl: np.ndarray  #: (n_windows, planes, len(WHIRL_FIELDS)) closed windows
    searches: np.ndarray  #: (2,) int64: peak refinements and contact-onset searches made (cost bookkeeping)
    tmp: np.ndarray  #: (n,) working state for the dense-output searches
    diags: np.ndarray  #: (planes, len(DIAG_FIELDS)) each plane's diagnostics at the step's end
    reach: np.ndarray  #: (planes, 4) bounds of the stress and semi-major-axis tables, -1 until needed
    #: (1,) 1: track and refine the peaks (a drop reports them); 0: do not (a coast-down's windows, which report
    #: none), and evaluate the ball contacts only when a range limit is within reach (:func:`observe`)
    track_peaks: np.ndarray
    work: np.ndarray  #: (n,) working memory of the searches' plane forces (:class:`~auxbearing.core.probes.Probe`)
    work_q: np.ndarray  #: (6,) and of their generalised forces
    work_diag: np.ndarray  #: (len(DIAG_FIELDS),) and of their diagnostics


def new_watch(n_states: int, n_planes: int, window: float, n_windows: int, energy0: float) -> Watch:
    """A fresh observer memory: ``n_planes`` plane blocks, room for ``n_windows`` whirl windows of ``window`` s."""
    two = n_planes  # plane blocks of the packed machine (its tuples' length)
    n_fields = len(WHIRL_FIELDS)
    return Watch(np.zeros((3, two)), np.zeros((3, two)), np.zeros(two), np.zeros(two), np.zeros((3, two, 2)),
                 np.zeros((5, n_states)), np.zeros(1), np.zeros(two), np.zeros(two), np.full(two, -1.0),
                 np.zeros(4), np.full(1, energy0), np.zeros(2), np.full(1, window), np.zeros(1, np.int64),
                 np.full(1, window), np.zeros((two, n_fields)), np.zeros((max(n_windows, 1), two, n_fields)),
                 np.zeros(2, np.int64), np.zeros(n_states), np.zeros((two, len(DIAG_FIELDS))), np.full((two, 4), -1.0),
                 np.ones(1), np.zeros(n_states), np.zeros(6), np.zeros(len(DIAG_FIELDS)))


@njit(cache=True, inline="always")
def _track_peak(w, what, k, value, t, h, coeff, probe, tmp):
    """Exact peak of one quantity: refine when the step-end sequence turned down (module docstring)."""
    last = w.history[what, k, 1]
    before = w.history[what, k, 0]
    if last > 0.0 and last >= value and last > before and last > 0.9 * w.peak[what, k]:
        arg = 3 * k + what
        w.searches[0] += 1
        th, v = ig.dense_max(probes.refine_target, coeff, probe, tmp, arg)
        if v > w.peak[what, k]:
            w.peak[what, k] = v
            w.peak_time[what, k] = t + th * h
        th, v = ig.dense_max(probes.refine_target, w.prev_coeff, probe, tmp, arg)
        if v > w.peak[what, k]:
            w.peak[what, k] = v
            w.peak_time[what, k] = t - w.prev_h[0] + th * w.prev_h[0]
    if last > w.peak[what, k]:
        w.peak[what, k] = last
        w.peak_time[what, k] = t
    if value > w.peak[what, k]:
        w.peak[what, k] = value
        w.peak_time[what, k] = t + h
    w.history[what, k, 0] = last
    w.history[what, k, 1] = value


@njit(cache=True, inline="always")
def _stop(w, code, k, t, value):
    w.stop[0] = code
    w.stop[1] = k
    w.stop[2] = t
    w.stop[3] = value
    return code


@njit(cache=True, inline="always")
def _whirl_step(w, y0, y1, m, t, h, diags):
    """Add one step to the open whirl window of every active plane; close the window when it ends."""
    n_planes = len(m.planes.active)
    for k in range(n_planes):
        if m.planes.active[k] <= 0.0:
            continue
        b = N_ROTOR + k * N_PLANE
        x0, y0_ = orbit(y0, m, k)
        x1, y1_ = orbit(y1, m, k)
        turn = math.atan2(x0 * y1_ - y0_ * x1, x0 * x1 + y0_ * y1_)  # small per step
        acc = w.whirl_acc[k]
        acc[0] += turn
        acc[1] += math.hypot(x1, y1_) * h
        if diags[k, D_PEN] > 0.0:
            acc[2] += h
        acc[3] += y1[OMEGA] * h
        acc[4] += y1[b + ROMEGA] * h
        acc[5] += h
        acc[6] += diags[k, D_FN] * h
        acc[7] += abs(diags[k, D_FA]) * h
        if h > 0.0:  # (step's displacement / h)^2 over h
            acc[8] += ((x1 - x0) ** 2 + (y1_ - y0_) ** 2) / h
        acc[9] += math.hypot(diags[k, D_BFX], diags[k, D_BFY]) ** 3 * h
    if t + h >= w.window_end[0] - WINDOW_END_SLACK * w.window[0]:
        i = w.window_count[0]
        if i < w.whirl.shape[0]:
            for k in range(n_planes):
                acc = w.whirl_acc[k]
                span = acc[5]
                if span > 0.0:
                    w.whirl[i, k, 0] = acc[0] / span
                    w.whirl[i, k, 1] = acc[1] / span
                    w.whirl[i, k, 2] = acc[2] / span
                    w.whirl[i, k, 3] = acc[3] / span
                    w.whirl[i, k, 4] = acc[4] / span
                    w.whirl[i, k, 5] = span
                    w.whirl[i, k, 6] = acc[6] / span
                    w.whirl[i, k, 7] = acc[7] / span
                    w.whirl[i, k, 8] = acc[8] / span
                    w.whirl[i, k, 9] = acc[9] / span
                for j in range(acc.size):
                    acc[j] = 0.0
            w.window_count[0] = i + 1
        w.window_end[0] += w.window[0]


@uncounted
def observe(t, h, y0, y1, coeff, m, w):
    """After each accepted step from t to t + h: peaks, onsets, whirl windows, range (module docstring).

    The plane diagnostics at y1 are those of the right-hand side's last call: DOPRI5 evaluates it at
    (t + h, y1) last (first same as last), and the searches below call it again, so they are copied first.
    """
    tmp = w.tmp
    lim = m.limits
    diags = w.diags
    probe = probes.Probe(m, w.work, w.work_q, w.work_diag, w.reach)
    n_planes = len(m.planes.active)
    for k in range(n_planes):
        for i in range(diags.shape[1]):
            diags[k, i] = m.last_diag[k, i] if m.planes.active[k] > 0.0 else 0.0
    code = 0
    for k in range(n_planes):
        if m.planes.active[k] <= 0.0:
            continue
        diag = diags[k]
        if diag[D_PEN] > 0.0 and w.in_contact[k] <= 0.0:
            w.onsets[k] += 1.0
            if w.first_contact[k] < 0.0:
                w.searches[1] += 1
                w.first_contact[k] = t + ig.dense_root(probes.gap, coeff, probe, tmp, k) * h
        w.in_contact[k] = 1.0 if diag[D_PEN] > 0.0 else 0.0
        peaks = w.track_peaks[0] > 0.0
        if peaks:
            _track_peak(w, _FORCE, k, diag[D_FN], t, h, coeff, probe, tmp)
        stress = 0.0
        # without peaks to track the contacts are evaluated only when the largest ball load could bring a range
        # limit within reach
        if diag[D_QMAX] >= STRESS_CANDIDATE_LOAD * w.peak_load[k] and (
                peaks or not probes.limits_out_of_reach(y1, m, k, diag[D_QMAX], w.reach[k])):
            stress, use = ball_extremes(y1, m, k, w.reach[k])
            w.shoulder_use[k] = max(w.shoulder_use[k], use)
            if use > 1.0 and code == 0:
                code = _stop(w, SHOULDER, k, t + h, use)
        w.peak_load[k] = max(w.peak_load[k], diag[D_QMAX])
        if peaks:
            _track_peak(w, _STRESS, k, stress, t, h, coeff, probe, tmp)
            _track_peak(w, _AXIAL, k, abs(diag[D_FA]), t, h, coeff, probe, tmp)
        if code == 0:
            if diag[D_FN] > lim.journal_force[k]:
                code = _stop(w, JOURNAL_PRESSURE, k, t + h, diag[D_FN])
            elif stress > lim.ball_stress:
                code = _stop(w, BALL_STRESS, k, t + h, stress)
            elif diag[D_MOUNT] > lim.mount_travel[k]:
                code = _stop(w, MOUNT_TRAVEL, k, t + h, diag[D_MOUNT])
            elif abs(y1[N_ROTOR + k * N_PLANE + RZ]) > lim.race_axial_travel[k]:
                code = _stop(w, AXIAL_RUNAWAY, k, t + h, y1[N_ROTOR + k * N_PLANE + RZ])
    _whirl_step(w, y0, y1, m, t, h, diags)
    energy_in, accounted, scale = energy_balance(y1, m, w.energy_in0[0])
    error = (accounted - energy_in) / max(scale, 1e-300)
    w.energy_error[1] = error
    w.energy_error[0] = max(w.energy_error[0], abs(error))
    if code == 0 and error > lim.energy_tolerance:
        code = _stop(w, ENERGY_GAIN, -1, t + h, error)
    for i in range(coeff.shape[0]):
        for j in range(coeff.shape[1]):
            w.prev_coeff[i, j] = coeff[i, j]
    w.prev_h[0] = h
    return code
