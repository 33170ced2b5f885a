"""The levitated machine's steady unbalance orbit: where a scenario's run starts.

The magnetic bearings hold the rotor about its levitated statics (:func:`auxbearing.machine.stations.amb.
levitated_state`); spinning at Omega with its unbalance, it settles on a harmonic orbit y(t) = y_s + Re(Y e^(i phi)),
phi = Omega t the spin angle. Rather than wait for it (the controllers' integral action takes tenths of a second
to settle), the run starts on it. Y is the forced response of the model linearised about the statics:
(i Omega I - A) Y = B, with A the Jacobian of the kernel's own right-hand side in the states the orbit moves (the
rotor's lateral motion, its elastic modes, the bearings' sensors, controllers and coils; the races are clear of
the journal and the spin is held) and B the first harmonic of its forcing in the spin angle, both by central
differences of :func:`auxbearing.core.machine.rhs` (the Jacobian averaged over four spin angles, so the
unbalance's small parametric terms, e times a force, do not bias it). The model's own equations, not a second
derivation of them: sensor and amplifier lags, any controller, the circuit's force law at its bias, the
gyroscopic and elastic couplings all come in as the drop integrates them.
"""

from __future__ import annotations

import math

import numpy as np

from auxbearing.core import machine as cm

#: Central differences step, as a share of each state's error scale's unit (clearance, fall speed, ...).
STEP = 1e-6
#: A growth rate this share of the system's fastest rate (its largest |eigenvalue|) or less is zero to the
#: precision the Jacobian is known to: each central difference carries a rounding error of about eps / STEP
#: (2e-10 of the entry, Press et al., Numerical Recipes, 3rd ed., 2007, Sec. 5.7) and the eigenvalues of a
#: non-normal matrix move by its eigenvector condition number times that (Bauer-Fike theorem; here tens to
#: hundreds), so a smaller real part has no sign worth reporting: an undamped (neutral) mode, neither growing
#: nor decaying.
NEUTRAL = 1e-7
PHASES = (0.0, 0.5 * math.pi, math.pi, 1.5 * math.pi)


def orbit_states(layout: cm.Layout, tilt_free: bool, axial: bool = False) -> np.ndarray:
    """Indices of the states a levitated unbalance orbit moves.

    The axial motion too where a thrust bearing holds it: that bearing's loop closes through it.
    """
    rotor = ([cm.X, cm.Y, cm.VX, cm.VY] + ([cm.TX, cm.TY, cm.WX, cm.WY] if tilt_free else [])
             + ([cm.Z, cm.VZ] if axial else []))
    modes = list(range(layout.modes_at, layout.modes_at + 2 * layout.modes))
    bearings = [at + j for at, width in layout.station_spans[cm.STATION_KINDS.index(cm.amb)] for j in range(width)]
    return np.array(sorted(rotor + modes + bearings), dtype=int)


def steady_orbit(core: cm.Machine, y0: np.ndarray, states: np.ndarray,
                 scales: np.ndarray) -> tuple[np.ndarray | None, complex]:
    """(Y, s): the harmonic orbit about ``y0`` and the least damped eigenvalue s of the levitated machine.

    Y is complex, over ``states``; s is in 1/s of the model linearised at ``y0``, its real part set to exactly 0
    when it is zero to the computation's precision (:data:`NEUTRAL`); Y is None unless s decays (Re s >= 0, a
    growing or an undamped mode: no steady orbit to start on). ``scales``: each state's unit for the difference
    steps. ``y0`` holds the statics and the spin speed.
    """
    omega = float(y0[cm.OMEGA])
    out = np.zeros(y0.size)

    def rate(y, phi):
        y = y.copy()
        y[cm.PHI] = phi
        cm.rhs(0.0, y, core, out)
        return out[states].copy()

    n = states.size
    jac = np.zeros((n, n))
    for phi in PHASES:
        for j, s in enumerate(states):
            h = STEP * scales[j]
            up, down = y0.copy(), y0.copy()
            up[s] += h
            down[s] -= h
            jac[:, j] += (rate(up, phi) - rate(down, phi)) / (2.0 * h)
    jac /= len(PHASES)
    eigenvalues = np.linalg.eigvals(jac)
    least = complex(eigenvalues[np.argmax(eigenvalues.real)])
    if abs(least.real) <= NEUTRAL * float(np.abs(eigenvalues).max()):
        least = complex(0.0, least.imag)  # its sign is rounding noise: neither a growth nor a decay to report
    if least.real >= 0.0:
        return None, least
    f = [rate(y0, phi) for phi in PHASES]
    forcing = 0.5 * (f[0] - f[2]) - 0.5j * (f[1] - f[3])  # b(phi) = Re(B e^(i phi))
    return np.linalg.solve(1j * omega * np.eye(n) - jac, forcing), least
