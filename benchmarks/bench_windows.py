"""The coast-down windows' integrator against Dormand-Prince on the same windows, as ratios.

A coast-down's full-dynamics windows integrate with the classical RK4 (:mod:`auxbearing.core.rk4`, through
``drive.advance_window``) because their Dormand-Prince steps sat on the stability bound. In one process, for each
shipped example whose drop stays in range, this benchmark runs its coast-down to a time in it, keeps the state
and integrator memory at the start of the last window, and integrates that window again with both compiled
drivers from the same state, the same tolerances and the same observer: right-hand-side evaluations, steps,
rejections and wall time (best of ``--repeats``), Dormand-Prince over RK4. The evaluations count what the method
does and do not depend on the machine; the wall time is this machine's.

    python benchmarks/bench_windows.py [--repeats 5] [--machine NAME:TIME ...]
"""

from __future__ import annotations

import argparse
import os
import time

import numpy as np

from auxbearing.analysis import coastdown
from auxbearing.core import drive
from auxbearing.core import integrate as ig
from auxbearing.machine.files import read_machine

#: (example, seconds into its coast-down): the blower on its collar with its clearances closed, the compressor
#: on its way to its run-away, the vertical rotor whirling under a preload, the paper rig's journal swinging.
WINDOWS = (("blower", 20.0), ("compressor", 20.0), ("vertical", 6.0), ("paper_rig", 5.0),
           ("paper_rig_two_planes", 5.0))


def last_window(name: str, at: float):
    """(machine struct, observer, state, end time, settings, memory) at the start of the last window before ``at``."""
    seen = []
    advance = drive.advance_window

    def watched(core, watch, y, t_end, settings, memory, grid):
        seen.append((core, watch, y.copy(), t_end, settings, [a.copy() for a in memory]))
        return advance(core, watch, y, t_end, settings, memory, grid)

    drive.advance_window = watched
    try:
        coastdown.run_coastdown(read_machine(name), until_stop=False, duration=at)
    finally:
        drive.advance_window = advance
    return seen[-1]


def run(driver, case, repeats: int) -> tuple[float, int, int, int]:
    """(best wall [s], evaluations, steps, rejected steps) of ``driver`` over the window."""
    core, watch, y0, t_end, settings, saved = case
    best = float("inf")
    for _ in range(repeats):
        memory = ig.Memory(*[a.copy() for a in saved])
        y = y0.copy()
        start = time.perf_counter()
        driver(core, watch, y, t_end, settings, memory, np.empty((0, y.size)))
        best = min(best, time.perf_counter() - start)
    return (best, int(memory.evaluations[0] - saved[6][0]), int(memory.steps[0] - saved[4][0]),
            int(memory.rejected[0] - saved[5][0]))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeats", type=int, default=5)
    parser.add_argument("--machine", action="append", default=[], help="NAME:TIME, repeatable (default: the examples)")
    args = parser.parse_args()
    cases = [(m.partition(":")[0], float(m.partition(":")[2] or 5.0)) for m in args.machine] or WINDOWS
    one, five, fifteen = os.getloadavg()
    print(f"load average {one:.2f} / {five:.2f} / {fifteen:.2f} (1/5/15 min) on {os.cpu_count()} cores")
    print(f"{'window':32s} {'method':8s} {'evaluations':>11s} {'steps':>7s} {'rejected':>8s} {'wall':>9s}")
    for name, at in cases:
        case = last_window(name, at)
        span = case[3] - float(case[5][0][0])
        rows = {label: run(driver, case, args.repeats)
                for label, driver in (("RK4", drive.advance_window), ("DOPRI5", drive.advance))}
        for label, (wall, evals, steps, rejected) in rows.items():
            print(f"{name + f' at {at:g} s ({span * 1e3:.0f} ms)':32s} {label:8s} {evals:11d} {steps:7d} {rejected:8d} "
                  f"{wall * 1e3:7.2f} ms")
        (w_rk, e_rk, *_), (w_dp, e_dp, *_) = rows["RK4"], rows["DOPRI5"]
        print(f"{'':32s} DOPRI5 / RK4: evaluations {e_dp / e_rk:.2f}, wall {w_dp / w_rk:.2f}")


if __name__ == "__main__":
    main()
