"""Whirl as a timeline: each window of a run classified none / forward / backward rolling / dry whip.

The observer of the drop (:mod:`auxbearing.core.watch`) integrates, per plane and window, how far the
journal turned about the bearing centre, its mean radius, the contact time, the mean contact force
and the spin speeds. Here each window is judged:

* ``none``: the journal is not running round the clearance (contact less than half the window, a
  mean radius below half the clearance, or less than :data:`MIN_ARC` of net turning in the window):
  rest, bouncing, or rocking in the bottom;
* ``forward``: it runs round with the spin;
* ``backward_rolling``: it runs round against the spin at the speed of rolling without slip on the
  race, w_roll = ((r + s) w_race - r Omega) / s (the contact's slip velocity set to zero: Jiang, J.
  Vib. Acoust. 129 (2007), dry-friction backward whirl; docs/machine_model_sources.md Sec. 1);
* ``dry_whip``: it runs round against the spin while slipping, locked near the natural frequency of
  the rotor on its contact system, w_c = sqrt(k / m) with k the contact, ball-set and mount
  stiffnesses in series at the window's mean force and m the rotor mass on the plane plus the race
  (Jiang & Ulbrich, J. Vib. Acoust. 127 (2005): dry whip is a resonance at a negative natural
  frequency of the coupled rotor/stator system);
* ``backward``: against the spin, neither of the two.

Thresholds (ours, stated because the literature gives none): :data:`MIN_ARC`,
:data:`ROLLING_BAND`, :data:`WHIP_BAND`; a whirl is *sustained* once it lasts :data:`SUSTAINED`
windows in a row.
"""

from __future__ import annotations

import math

import numpy as np

from auxbearing.core.watch import WHIRL_FIELDS

CLASSES = ("none", "forward", "backward_rolling", "dry_whip", "backward")
BACKWARD = ("backward_rolling", "dry_whip", "backward")
#: Net turning about the bearing centre within a window below this is no whirl (a rotor rocking in the
#: bottom turns back and forth) [rad]: half a revolution.
MIN_ARC = math.pi
#: Backward whirl within this relative band of the no-slip speed is rolling.
ROLLING_BAND = 0.2
#: Slipping backward whirl within this relative band of w_c is dry whip.
WHIP_BAND = 0.35
#: Windows in a row that make a whirl sustained.
SUSTAINED = 3

_F = {name: i for i, name in enumerate(WHIRL_FIELDS)}


def classify_window(record: np.ndarray, clearance: float, journal_radius: float, natural: float) -> str:
    """Class of one window (module docstring).

    Parameters
    ----------
    record : ndarray
        One window of one plane, columns :data:`auxbearing.core.watch.WHIRL_FIELDS`.
    clearance, journal_radius : float
        s and r [m].
    natural : float
        w_c [rad/s] (:func:`natural_frequency`): the line contact at the window's mean force in series with the
        support, whose ball set the drop takes at a fixed load near its rating (max(100 N, 50 Z N)), not at the
        window's force.

    Examples
    --------
    >>> rec = np.array([-900.0, 2e-4, 1.0, 600.0, 0.0, 10e-3, 50.0])  # backward, far slower than rolling
    >>> classify_window(rec, 2e-4, 7.3e-3, 1000.0)
    'dry_whip'
    """
    whirl = record[_F["whirl_speed"]]
    spin = record[_F["spin_speed"]]
    if (record[_F["contact_fraction"]] < 0.5 or record[_F["mean_radius"]] < 0.5 * clearance
            or abs(whirl) * record[_F["duration"]] < MIN_ARC):
        return "none"
    if spin == 0.0:  # a rotor that does not turn: a whirl is neither with nor against its spin
        return "none"
    if whirl * spin > 0.0:
        return "forward"
    rolling = ((journal_radius + clearance) * record[_F["race_speed"]] - journal_radius * spin) / clearance
    if rolling * spin < 0.0 and abs(abs(whirl) - abs(rolling)) <= ROLLING_BAND * abs(rolling):
        return "backward_rolling"
    if natural > 0.0 and abs(abs(whirl) - natural) <= WHIP_BAND * natural:
        return "dry_whip"
    return "backward"


def natural_frequency(force: float, line_stiffness: float, support_stiffness: float, mass: float) -> float:
    """w_c = sqrt(k / m) [rad/s] of the rotor on its contact system at a mean contact force [N].

    The line contact's tangent stiffness at F is (10/9) F / delta with delta = (F / K_l)^(9/10)
    (Eq. 19); it acts in series with ``support_stiffness`` (ball set and mount) [N/m].

    >>> round(natural_frequency(100.0, 1.463e9, 2e7, 1.5), 1)
    3539.9
    """
    if force <= 0.0 or mass <= 0.0:
        return 0.0
    delta = (force / line_stiffness) ** 0.9
    k_line = 10.0 / 9.0 * force / delta
    k = 1.0 / (1.0 / k_line + 1.0 / support_stiffness) if support_stiffness > 0.0 else k_line
    return math.sqrt(k / mass)


#: The whirl of a run that closed no whirl window.
UNCLASSIFIED = "not classified"


def timeline(records: np.ndarray, window: float, clearance: float, journal_radius: float,
             natural: np.ndarray) -> dict:
    """Classes over the windows of one plane, the onset of sustained backward whirl, and the end state.

    Returns
    -------
    dict
        ``classes`` (list), ``window_s``, ``whirl_speed_rad_s`` (list), ``backward_whirl_onset_ms``
        (start of the first run of :data:`SUSTAINED` backward windows, None if none), ``whirl`` (the
        class that holds over the last :data:`SUSTAINED` windows, else the last window's),
        ``backward_at_end`` (bool), ``whirl_frequency_Hz`` of the final state.
    """
    classes = [classify_window(r, clearance, journal_radius, w) for r, w in zip(records, natural, strict=True)]
    onset = None
    run = 0
    for i, c in enumerate(classes):
        run = run + 1 if c in BACKWARD else 0
        if run == SUSTAINED and onset is None:
            onset = (i - SUSTAINED + 1) * window
    tail = classes[-SUSTAINED:]
    # a run shorter than one whirl window (drop.whirl_window) closes none: its whirl is unknown, not "none"
    final = tail[-1] if tail else UNCLASSIFIED
    if tail and len(set(tail)) == 1:
        final = tail[0]
    speed = records[-1, _F["whirl_speed"]] if len(records) else 0.0
    return {"classes": classes, "window_s": window, "whirl_speed_rad_s": [float(r[_F["whirl_speed"]]) for r in records],
            "backward_whirl_onset_ms": None if onset is None else onset * 1e3, "whirl": final,
            "backward_at_end": final in BACKWARD,
            "whirl_frequency_Hz": None if final in ("none", UNCLASSIFIED) else abs(float(speed)) / (2.0 * math.pi)}


def spectral_whirl(t: np.ndarray, x: np.ndarray, y: np.ndarray, clearance: float, spin: float = 1.0,
                 start: float = 0.0, min_amplitude: float = 0.05) -> dict:
    """Whirl direction and frequency of a whole orbit record from its complex spectrum z = x + i y.

    For measured orbits, which come without the simulation's window records: the direction of a
    record as a whole (a simulated run is judged window by window, :func:`timeline`).

    Power at positive frequencies is counter-clockwise motion of the journal centre, at negative
    frequencies clockwise; forward whirl turns with the spin. The mean position (the rotor
    sitting in the bottom of the clearance) is removed and a Hann window applied. The whirl is
    ``forward`` or ``backward`` when at least 2/3 of the orbit's spectral power turns one way and
    the rms orbit exceeds ``min_amplitude`` x clearance; otherwise ``none`` (rest, bouncing, or
    rocking in the bottom, whose spectrum is symmetric).

    Parameters
    ----------
    t, x, y : arrays
        Uniform time [s] and journal centre [m].
    clearance : float
        s [m].
    spin : float
        Spin speed (its sign defines forward).
    start : float
        Analyse t >= start [s] (e.g. the first impact).
    min_amplitude : float
        Smallest rms orbit, as a fraction of the clearance, that counts as whirl.

    Examples
    --------
    >>> t = np.arange(0, 0.1, 1e-4)
    >>> w = spectral_whirl(t, 2e-4 * np.cos(-2 * np.pi * 50 * t), 2e-4 * np.sin(-2 * np.pi * 50 * t), 2e-4)
    >>> w["whirl"], w["whirl_frequency_Hz"]
    ('backward', 50.0)
    """
    keep = t >= start
    z = x[keep] + 1j * y[keep]
    if spin < 0:  # mirror the orbit so that positive frequencies always mean "with the spin"
        z = np.conj(z)
    out = {"whirl": "none", "whirl_frequency_Hz": None, "whirl_rms_um": 0.0, "forward_power_fraction": None}
    if z.size < 16:
        return out
    z = z - z.mean()
    rms = float(np.sqrt(np.mean(np.abs(z) ** 2)))
    spectrum = np.fft.fft(z * np.hanning(z.size))
    freq = np.fft.fftfreq(z.size, t[1] - t[0])
    power = np.abs(spectrum) ** 2
    fwd, bwd = power[freq > 0].sum(), power[freq < 0].sum()
    frac = float(fwd / (fwd + bwd)) if fwd + bwd > 0 else 0.5
    out.update(whirl_rms_um=rms * 1e6, forward_power_fraction=frac)
    if rms < min_amplitude * clearance or 1.0 / 3.0 < frac < 2.0 / 3.0:
        return out
    side = freq > 0 if frac >= 2.0 / 3.0 else freq < 0
    peak = np.argmax(np.where(side, power, -1.0))
    out.update(whirl="forward" if frac >= 2.0 / 3.0 else "backward", whirl_frequency_Hz=float(abs(freq[peak])))
    return out
