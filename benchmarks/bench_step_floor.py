"""What sets the integration step in contact: the stiffest mode of each example machine against the steps taken.

The drops are integrated explicitly with Dormand & Prince's 5(4) pair (:mod:`auxbearing.core.integrate`), the
coast-downs' full-dynamics windows with the classical fourth-order Runge-Kutta method (:mod:`auxbearing.core.rk4`),
chosen there because these steps sat on the Dormand-Prince stability bound. An explicit method's step h is
bounded by stability: h lambda must stay inside the method's stability region for every eigenvalue lambda of the
right-hand side's Jacobian, whatever the tolerances. This benchmark shows, for each shipped example, where that
bound lies and how close the steps come:

1. the drop is run to its end (or to its stop) twice, the second run 10 ms shorter; the difference of the
   accepted steps gives the mean step over the drop's last 10 ms, where the journals are in contact;
2. at the final state the Jacobian of :func:`auxbearing.core.machine.rhs` over the mechanical states (rotor,
   planes, modes, stations; not the energy ledger) is taken by central differences, and its eigenvalues found;
3. for the stiffest few, the largest stable step along each eigenvalue's direction in the complex plane,
   r(theta) / |lambda|, where r(theta) is the boundary of |R(z)| <= 1 of the method's propagated solution
   (Dormand-Prince's fifth-order one for a drop, RK4's for a window), R(z) = 1 + z b^T (I - z A)^-1 1 (Hairer &
   Wanner, Solving Ordinary Differential Equations II, 2nd ed., Sect. IV.2; the tableaus as in the two modules),
   found by bisection along the ray;
4. the states that carry each mode (the eigenvector's largest entries, positions scaled by |lambda| so that a
   displacement and a velocity count alike).

Nothing is asserted; the figures go into the performance notes (what a faster coast-down would have to change).

    python benchmarks/bench_step_floor.py [--machine NAME ...] [--modes 3]
"""

from __future__ import annotations

import argparse
import os

import numpy as np

from auxbearing.analysis.drop import integrate_machine
from auxbearing.core import integrate as ig
from auxbearing.core import machine as cm
from auxbearing.machine.files import read_machine

EXAMPLES = ("paper_rig", "paper_rig_two_planes", "blower", "compressor", "vertical", "heavy_fast_rotor")
#: Coast-downs sampled (example, simulated seconds): the blower once its drive end rides on the collar and its
#: clearances have closed, the vertical machine once thermal growth has preloaded its bearings.
COASTDOWNS = (("blower", 20.0), ("vertical", 6.0))
#: Length of the drop's end over which the mean step is measured [s].
TAIL = 0.01


def dopri_tableau() -> tuple[np.ndarray, np.ndarray]:
    """(A, b) of the Dormand-Prince 5(4) pair's propagated solution, from the integrator's own constants."""
    a = np.zeros((7, 7))
    a[1, 0] = ig.A21
    a[2, :2] = ig.A31, ig.A32
    a[3, :3] = ig.A41, ig.A42, ig.A43
    a[4, :4] = ig.A51, ig.A52, ig.A53, ig.A54
    a[5, :5] = ig.A61, ig.A62, ig.A63, ig.A64, ig.A65
    b = np.array([ig.B1, 0.0, ig.B3, ig.B4, ig.B5, ig.B6, 0.0])
    a[6, :] = b  # first same as last: the seventh stage is the next step's first
    return a, b


def rk4_tableau() -> tuple[np.ndarray, np.ndarray]:
    """(A, b) of the classical fourth-order method the coast-down's windows use (:mod:`auxbearing.core.rk4`)."""
    a = np.zeros((4, 4))
    a[1, 0] = a[2, 1] = 0.5
    a[3, 2] = 1.0
    return a, np.array([1.0, 2.0, 2.0, 1.0]) / 6.0


def stability_radius(theta: float, a: np.ndarray, b: np.ndarray) -> float:
    """Largest r with |R(r e^{i theta})| <= 1 on the whole segment from 0 (bisection after a scan)."""
    one = np.ones(len(b))

    def amplification(r: float) -> float:
        z = r * np.exp(1j * theta)
        return abs(1.0 + z * b @ np.linalg.solve(np.eye(len(b)) - z * a, one))

    grid = np.linspace(1e-3, 6.0, 1200)
    unstable = next((r for r in grid if amplification(r) > 1.0 + 1e-12), None)
    if unstable is None:
        return grid[-1]
    lo, hi = unstable - grid[1] + grid[0], unstable
    for _ in range(60):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if amplification(mid) <= 1.0 + 1e-12 else (lo, mid)
    return lo


def state_names(layout) -> list[str]:
    names = list(cm.ROTOR_STATES)
    for k in range(layout.planes):
        names += [f"{n}[{k}]" for n in cm.PLANE_STATES]
    rest = layout.ledger_at - len(names)
    return names + [f"mode/station {i}" for i in range(rest)]


def jacobian(y: np.ndarray, core, t: float, n: int) -> np.ndarray:
    """Central differences of the right-hand side over the first n states."""
    jac = np.zeros((n, n))
    plus, minus = np.zeros(y.size), np.zeros(y.size)
    for j in range(n):
        d = 1e-7 * max(abs(y[j]), 1e-3) if j in (cm.PHI,) else 1e-9 * max(1.0, abs(y[j]))
        yp, ym = y.copy(), y.copy()
        yp[j] += d
        ym[j] -= d
        cm.rhs(t, yp, core, plus)
        cm.rhs(t, ym, core, minus)
        jac[:, j] = (plus[:n] - minus[:n]) / (2.0 * d)
    return jac


def drop_end(name: str):
    """(title, machine struct, state, t, mean step, layout) at the end of the example's drop."""
    machine = read_machine(name)
    full = integrate_machine(machine, machine.simulation.duration, None, None)
    end = float(full.memory.t[0])  # a drop that stopped ends earlier
    shorter = integrate_machine(machine, max(end - TAIL, 0.5 * end), None, None)
    steps = int(full.memory.steps[0] - shorter.memory.steps[0])
    span = end - float(shorter.memory.t[0])
    title = (f"{name}, end of the drop: verdict {full.verdict} at t = {end * 1e3:.1f} ms; mean step over its last "
             f"{span * 1e3:.1f} ms {span / max(steps, 1) * 1e6:.2f} us ({steps} steps)")
    return title, full.model.machine, full.y, end, span / max(steps, 1), full.model.layout


def coastdown_window(name: str, at: float):
    """The same at the last full-dynamics window before ``at`` seconds of the example's coast-down.

    The windows are taken from the driver as the coast-down calls it (the clearances of the moment, thermal
    growth included, live only in the run's own machine struct).
    """
    from auxbearing.analysis import coastdown
    from auxbearing.core import drive

    seen = []
    advance = drive.advance_window  # the windows' own integrator (auxbearing.core.rk4)

    def watched(core, watch, y, t_end, settings, memory, grid):
        t0, steps = float(memory.t[0]), int(memory.steps[0])
        status = advance(core, watch, y, t_end, settings, memory, grid)
        seen.append((core, y.copy(), float(memory.t[0]), float(memory.t[0]) - t0, int(memory.steps[0]) - steps))
        return status

    drive.advance_window = watched
    try:
        run = coastdown.run_coastdown(read_machine(name), until_stop=False, duration=at)
    finally:
        drive.advance_window = advance
    core, y, t, span, steps = seen[-1]
    layout = coastdown.cm.layout_of(core)
    title = (f"{name}, coast-down window ending at t = {t:.2f} s ({run.summary['verdict']}): mean step "
             f"{span / max(steps, 1) * 1e6:.2f} us ({steps} steps in {span * 1e3:.0f} ms)")
    return title, core, y, t, span / max(steps, 1), layout


def analyse(case, modes: int, a: np.ndarray, b: np.ndarray) -> None:
    title, core, y, end, mean_step, layout = case
    n = layout.ledger_at
    names = state_names(layout)
    jac = jacobian(y, core, end, n)
    values, vectors = np.linalg.eig(jac)
    order = np.argsort(-np.abs(values))
    print("\n" + title)
    seen = 0
    for i in order:
        lam = values[i]
        if lam.imag < 0.0:
            continue  # one of each conjugate pair
        theta = float(np.angle(lam))
        limit = stability_radius(theta, a, b) / abs(lam)
        scale = np.array([abs(lam) if k < n and not _is_rate(names[k]) else 1.0 for k in range(n)])
        weight = np.abs(vectors[:, i]) * scale
        weight /= weight.max()
        carriers = ", ".join(f"{names[k]} {weight[k]:.2f}" for k in np.argsort(-weight)[:4])
        print(f"  lambda {lam.real:11.4g} {lam.imag:+11.4g}i  |lambda| {abs(lam):9.3g} 1/s  stable step "
              f"{limit * 1e6:7.2f} us  ({mean_step / limit:.2f} of it taken)  carried by {carriers}")
        seen += 1
        if seen >= modes:
            break


def _is_rate(name: str) -> bool:
    return any(tag in name for tag in ("vx", "vy", "vz", "_rate", "speed")) or name.startswith("v")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--machine", action="append", default=[], help="example machine (repeatable)")
    parser.add_argument("--modes", type=int, default=3, help="stiffest modes shown per machine")
    args = parser.parse_args()
    a, b = dopri_tableau()
    window_a, window_b = rk4_tableau()
    for title, (ta, tb) in (("Dormand-Prince 5(4), propagated solution (drops)", (a, b)),
                            ("classical RK4 (coast-down windows)", (window_a, window_b))):
        print(f"{title}: stability boundary on the negative real axis {stability_radius(np.pi, ta, tb):.3f}, "
              f"on the imaginary axis {stability_radius(np.pi / 2, ta, tb):.3f}")
    one, five, fifteen = os.getloadavg()
    print(f"load average {one:.2f} / {five:.2f} / {fifteen:.2f} on {os.cpu_count()} cores (timing-free benchmark)")
    for name in args.machine or EXAMPLES:
        analyse(drop_end(name), args.modes, a, b)
    for name, at in COASTDOWNS:
        if not args.machine or name in args.machine:
            analyse(coastdown_window(name, at), args.modes, window_a, window_b)


if __name__ == "__main__":
    main()
