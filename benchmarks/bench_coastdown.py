"""Coast-down of the shipped blower (issue 13): wall time against simulated time, auto path beside full dynamics.

In one process, after a short run that compiles or loads the kernels:

1. ``run_coastdown(read_machine("blower"))`` (mode "auto": full dynamics in windows, the reduced model on
   settled stretches) from the drop speed to standstill, best of ``--repeats``: wall and CPU time against
   the simulated time (target: wall <= 0.1 x simulated on the 2-core machine). The progress callback
   (called after every window and stretch) splits the wall time into the drop with the first window,
   the other full-dynamics windows, the reduced stretches and what follows the last of them (fatigue,
   outputs), also by speed band;
2. the full-dynamics path, ``mode="full"``, on the first ``--full-duration`` seconds only: its wall time
   per simulated second, and that cost extrapolated (not run) to the auto run's time to standstill; a
   second estimate takes each speed band at the cost of the auto run's own windows in that band (the
   first seconds are at the drop speed, where the motion may cost less than at lower speeds).

    python benchmarks/bench_coastdown.py [--repeats 3] [--full-duration 2.0] [--machine blower]

``--every`` instead runs each shipped example and each of its ``[[candidate]]`` bearings once, auto to standstill
or to the limit that ends it, and prints a line per case: its end, simulated time, wall and CPU time,
simulated seconds per wall second (the verification issue's target: at least 20 in every whirl state), the
share of the simulated time spent in full-dynamics windows and what those windows cost per simulated second.

    python benchmarks/bench_coastdown.py --every
"""

from __future__ import annotations

import argparse
import math
import os
import re
import time
from itertools import pairwise

import numpy as np

from auxbearing.analysis.coastdown import run_coastdown
from auxbearing.machine.files import machine_names, machine_table, read_machine
from auxbearing.machine.judging import candidate_tables
from auxbearing.machine.model import machine_from_mapping

#: Speed bands of the split, as fractions of the drop speed.
BANDS = np.array([0.0, 0.25, 0.5, 0.75, 1.0 + 1e-9])


def load() -> str:
    one, five, fifteen = os.getloadavg()
    return f"load average {one:.2f} / {five:.2f} / {fifteen:.2f} (1/5/15 min) on {os.cpu_count()} cores"


class Split:
    """Wall and CPU time between progress calls, booked to windows or stretches by the run's own history.

    The coast-down calls the progress callback once after each window and each stretch, right after it adds
    that window's or stretch's row to its history (mode 0 or 1; the drop's end, mode 2, has no call), so the
    n-th call is the n-th such row. Booked by how far simulated time moved instead, a window the run lengthened
    (``coastdown_phases.WINDOW_GROWTH``: the paper rigs' swinging journals) would count as a stretch.

    Each call's status line carries the speed; the times are also binned by speed, in :data:`BANDS`
    fractions of the drop speed, so a cost per simulated second can be read per band.
    """

    def __init__(self, machine, until_stop: bool, duration: float | None) -> None:
        self.t_end = machine.coastdown.max_time if until_stop else duration
        self.rpm0 = abs(machine.rotor.speed) * 30.0 / math.pi
        self.calls: list[tuple[float, float, float, float]] = []  # wall clock, CPU clock, simulated time, rpm

    def __call__(self, fraction: float, status: str) -> None:
        # the status says the simulated time and the speed ("t = 12.34 s, 9000 rpm"); the fraction is the share
        # of the speed lost when running to standstill, not of the time
        found = re.search(r"([-+\d.]+) rpm", status)
        at = re.search(r"t = ([-+\d.eE]+) s", status)
        t = float(at.group(1)) if at else fraction * self.t_end
        self.calls.append((time.perf_counter(), time.process_time(), t,
                           abs(float(found.group(1))) if found else 0.0))

    def report(self, start: tuple[float, float], stop: tuple[float, float], modes: np.ndarray) -> dict:
        """(wall, CPU) [s] before the first call (the drop and the first window), in windows, stretches, after.

        ``modes``: the run's history modes. ``bands``: per speed band, [wall, CPU, simulated] of its windows, then
        of its stretches.
        """
        calls = self.calls
        kinds = [int(m) for m in modes if int(m) != 2]  # one per progress call, in order
        if len(kinds) != len(calls):
            raise RuntimeError(f"{len(calls)} progress calls against {len(kinds)} windows and stretches in the history")
        first, last = (calls[0][:2], calls[-1][:2]) if calls else (stop, stop)
        out = {"drop": np.subtract(first, start), "tail": np.subtract(stop, last), "windows": np.zeros(3),
               "stretches": np.zeros(3), "bands": np.zeros((len(BANDS) - 1, 6))}
        for ((w0, c0, t0, _), (w1, c1, t1, rpm)), kind in zip(pairwise(calls), kinds[1:], strict=True):
            window = kind == 0
            spent = np.array([w1 - w0, c1 - c0, t1 - t0])
            out["windows" if window else "stretches"] += spent
            band = min(max(int(np.searchsorted(BANDS, rpm / self.rpm0, side="right")) - 1, 0), len(BANDS) - 2)
            first_col = 0 if window else 3
            out["bands"][band, first_col:first_col + 3] += spent
        return out


def timed(machine, until_stop: bool, duration: float | None, mode: str):
    split = Split(machine, until_stop, duration)
    start = (time.perf_counter(), time.process_time())
    run = run_coastdown(machine, until_stop=until_stop, duration=duration, mode=mode, progress=split)
    stop = (time.perf_counter(), time.process_time())
    return stop[0] - start[0], stop[1] - start[1], run.summary, split.report(start, stop, run.history["mode"].values)


#: Simulated seconds per wall second every coast-down should reach (the verification issue's target).
TARGET_RATE = 20.0


def every_case():
    """(label, machine) of each shipped example, then each of its [[candidate]] bearings in its place."""
    for name in machine_names():
        data, _, base = machine_table(name)
        yield name, read_machine(name)
        for label, tables in candidate_tables(data, data.get("candidate", [])):
            yield f"{name} with {label}", machine_from_mapping(tables, f"{name} with {label}", base)


def every() -> None:
    """One auto run to its end per example and candidate: the rate against :data:`TARGET_RATE`, windows' share."""
    print(f"{'case':44s} {'end':>21s} {'simulated':>10s} {'wall':>7s} {'CPU':>7s} {'sim/wall':>8s} "
          f"{'windows':>8s} {'window cost':>12s}")
    for label, machine in every_case():
        wall, cpu, s, split = timed(machine, True, None, "auto")
        sim = s["simulated_s"]
        if s["drop_verdict"] != "ok":  # nothing after a drop that left the model's range
            print(f"{label[:44]:44s} no coast-down: its drop ended {s['drop_verdict'].replace('_', ' ')}")
            continue
        end = "standstill" if s["reached_standstill"] else s["verdict"].replace("_", " ")
        full = s["full_dynamics_s"]
        windows = split["windows"] + np.array([*split["drop"], 0.0])  # the drop and first window are windows too
        cost = f"{windows[0] / full:.2f} s/s" if full > 0.0 else "-"
        rate = sim / wall if wall > 0.0 else math.inf
        print(f"{label[:44]:44s} {end[:21]:>21s} {sim:8.2f} s {wall:5.2f} s {cpu:5.2f} s {rate:8.1f} "
              f"{100 * full / max(sim, 1e-300):7.1f}% {cost:>12s}" + ("" if rate >= TARGET_RATE else "  below target"))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--machine", default="blower")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--full-duration", type=float, default=2.0, help="simulated seconds of the full path [s]")
    parser.add_argument("--every", action="store_true", help="each shipped example and candidate once (docstring)")
    args = parser.parse_args()
    print(load())
    if args.every:
        run_coastdown(read_machine("paper_rig"), until_stop=False, duration=0.02)  # kernels compiled or loaded
        every()
        print(load())
        return
    machine = read_machine(args.machine)
    start = time.perf_counter()
    run_coastdown(machine, until_stop=False, duration=0.02)
    print(f"kernels compiled or loaded by a 20 ms run: {time.perf_counter() - start:.2f} s")

    best = (math.inf,)
    for _ in range(args.repeats):
        result = timed(machine, True, None, "auto")
        print(f"  auto run: wall {result[0]:.2f} s, CPU {result[1]:.2f} s")
        best = min(best, result, key=lambda r: r[0])
    wall, cpu, s, split = best
    sim = s["simulated_s"]
    print(f"\n{machine.name}, auto path, best of {args.repeats}: verdict {s['verdict']}, standstill reached: "
          f"{s['reached_standstill']}, {sim:.2f} s simulated ({s['full_dynamics_s']:.2f} s of it in "
          f"{s['windows']} full-dynamics windows, {s['reduced_model_s']:.2f} s in {s['reduced_stretches']} reduced "
          f"stretches), energy error {s['energy_balance_error']:.1e}")
    print(f"  wall {wall:.2f} s, CPU {cpu:.2f} s -> wall / simulated = {wall / sim:.3f} (target <= 0.1), "
          f"CPU / simulated = {cpu / sim:.3f}")
    w, st = split["windows"], split["stretches"]
    print(f"  by part, wall (CPU): drop and first window {split['drop'][0]:.2f} s ({split['drop'][1]:.2f} s); other "
          f"windows {w[0]:.2f} s ({w[1]:.2f} s) for {w[2]:.2f} s simulated; stretches {st[0]:.2f} s ({st[1]:.2f} s) "
          f"for {st[2]:.2f} s simulated; after the last {split['tail'][0]:.2f} s ({split['tail'][1]:.2f} s)")
    bands = split["bands"]
    for i in range(len(BANDS) - 1):
        ww, wc, ws, sw, sc, ss = bands[i]
        cost = f"{ww / ws:.1f} s wall, {wc / ws:.1f} s CPU per simulated second" if ws > 0.0 else "no window"
        print(f"    speed {100 * BANDS[i]:3.0f}-{min(100 * BANDS[i + 1], 100):3.0f} % of the drop speed: windows "
              f"{ww:.2f} s for {ws:.2f} s simulated ({cost}); stretches {sw:.2f} s ({sc:.2f} s CPU) for {ss:.2f} s "
              "simulated")

    f_wall, f_cpu, fs, f_split = timed(machine, False, args.full_duration, "full")
    fw = f_split["windows"]
    per_s = np.array([f_wall, f_cpu]) / fs["simulated_s"]
    window_per_s = fw[:2] / max(fw[2], 1e-300)
    print(f"\nfull dynamics (mode='full') on the first {fs['simulated_s']:.2f} s: wall {f_wall:.2f} s, CPU "
          f"{f_cpu:.2f} s -> {per_s[0]:.2f} s wall, {per_s[1]:.2f} s CPU per simulated second ({window_per_s[0]:.2f} s"
          f" wall, {window_per_s[1]:.2f} s CPU in its windows alone)")
    # fixed parts (drop, fatigue and outputs) once, then the windows' cost per simulated second for the rest
    estimate = np.array([f_wall, f_cpu]) + window_per_s * (sim - fs["simulated_s"])
    print(f"  extrapolated, not run: the full path to standstill ({sim:.1f} s) would take about "
          f"{estimate[0] / 60:.0f} min of wall ({estimate[1] / 60:.0f} min CPU) at this cost -> wall / simulated about "
          f"{estimate[0] / sim:.1f} (CPU {estimate[1] / sim:.1f}); the auto path is {estimate[0] / wall:.0f}x faster")
    # the first seconds are at the drop speed; the auto run's own windows give the cost at lower speeds
    sims = bands[:, 2] + bands[:, 5]
    by_band = []
    for j in range(2):
        rate = np.where(bands[:, 2] > 0.0, bands[:, j] / np.maximum(bands[:, 2], 1e-300), window_per_s[j])
        by_band.append(split["drop"][j] + split["tail"][j] + float(np.sum(rate * sims)))
    print(f"  extrapolated band by band (each speed band at the cost of the auto run's windows in it): about "
          f"{by_band[0] / 60:.0f} min wall ({by_band[1] / 60:.0f} min CPU) -> wall / simulated about "
          f"{by_band[0] / sim:.1f} (CPU {by_band[1] / sim:.1f})")
    print(load())


if __name__ == "__main__":
    main()
