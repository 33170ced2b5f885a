"""Drop campaigns: throughput on one and two Dask workers, the campaign's overhead, a 1000-drop run, memory.

In one run, on the paper-rig campaign (examples/campaign_paper_rig.toml):

1. bare: ``run_machine(machine, lean=True)`` on the machines of the first N samples, one after the
   other in this process (machines built beforehand) -> seconds per drop;
2. the same N samples as a campaign on a local cluster of 1 worker, then of 2 workers -> drops per
   second from the first task to the last stored record (cluster start-up and kernel loading are
   reported apart); scaling = (2-worker rate) / (1-worker rate) (target >= 1.7);
   overhead = (1-worker seconds per drop) / (bare seconds per drop) - 1 (target < 5 %). Measured
   minutes apart it carries whatever else the machine ran meanwhile, so it is also measured in two
   parts that each compare times taken side by side: evaluate_sample against run_machine alternating
   sample by sample, and the worker's time per sample against the evaluate_sample time it recorded;
3. a 1000-drop campaign, local cluster sized to the cores, timed end to end as the command runs it
   (target < 2 min on the 2-core machine), with the resident memory of this process and of the
   workers sampled while it runs (target: flat).

    python benchmarks/bench_campaign.py [--samples 128] [--big 1000] [--config FILE]
"""

from __future__ import annotations

import argparse
import os
import tempfile
import threading
import time
from pathlib import Path

import numpy as np

from auxbearing.analysis.drop import run_machine
from auxbearing.bearings.geometry import read_toml
from auxbearing.campaign.config import apply_sample, campaign_from_mapping
from auxbearing.campaign.evaluate import evaluate_sample, warm_up
from auxbearing.campaign.run import cores, run_campaign
from auxbearing.campaign.sampling import design
from auxbearing.campaign.store import load_results
from auxbearing.machine.model import machine_from_mapping

HERE = Path(__file__).resolve().parent
DEFAULT_CONFIG = HERE.parent / "examples" / "campaign_paper_rig.toml"


def campaign_of(config: Path, samples: int):
    data = read_toml(config)
    data["campaign"]["samples"] = samples
    return campaign_from_mapping(data, config.stem, config.parent)


def machines_of(campaign):
    points = design(campaign)
    return points.values, [machine_from_mapping(apply_sample(campaign.tables, campaign.inputs, row), campaign.name)
                           for row in points.values]


def bare_seconds_per_drop(campaign) -> float:
    _, machines = machines_of(campaign)
    run_machine(machines[0], lean=True)  # kernels loaded before the clock starts
    start = time.perf_counter()
    for machine in machines:
        run_machine(machine, lean=True)
    return (time.perf_counter() - start) / len(machines)


def sample_overhead(campaign) -> float:
    """evaluate_sample (machine from the tables, run, record) against run_machine on a prebuilt machine,
    alternating sample by sample so that other load on the machine hits both alike."""
    values, machines = machines_of(campaign)
    bare = full = 0.0
    for row, machine in zip(values, machines, strict=True):
        start = time.perf_counter()
        run_machine(machine, lean=True)
        middle = time.perf_counter()
        evaluate_sample(campaign, row)
        full += time.perf_counter() - middle
        bare += middle - start
    return full / bare - 1.0


class ProcessWatch:
    """Resident memory [MB] and CPU time [s] of this process and of its children (the local cluster's
    workers), sampled in a thread; CPU time of a child is kept from its last sample after it ends."""

    def __init__(self, every: float = 0.25) -> None:
        import psutil

        self.me = psutil.Process(os.getpid())
        self.every = every
        self.samples: list[tuple[float, float, float]] = []  # (time, this process, children) memory
        self.child_cpu: dict[int, float] = {}
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._loop, daemon=True)

    def _loop(self) -> None:
        import psutil

        start = time.perf_counter()
        while not self._stop.is_set():
            children = 0.0
            for child in self.me.children(recursive=True):
                try:
                    children += child.memory_info().rss
                    cpu = child.cpu_times()
                    self.child_cpu[child.pid] = cpu.user + cpu.system
                except psutil.Error:
                    pass
            self.samples.append((time.perf_counter() - start, self.me.memory_info().rss / 1e6, children / 1e6))
            self._stop.wait(self.every)

    def own_cpu(self) -> float:
        cpu = self.me.cpu_times()
        return cpu.user + cpu.system

    def __enter__(self) -> ProcessWatch:
        self.cpu_start = self.own_cpu()
        self._thread.start()
        return self

    def __exit__(self, *exc) -> None:
        self._stop.set()
        self._thread.join()
        self.cpu = self.own_cpu() - self.cpu_start  # includes the sampling thread's own small share


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--samples", type=int, default=128, help="samples of the scaling/overhead runs")
    parser.add_argument("--big", type=int, default=1000, help="drops of the end-to-end run")
    parser.add_argument("--config", type=Path, default=DEFAULT_CONFIG)
    args = parser.parse_args()
    print(f"cores {cores()}, load average {os.getloadavg()[0]:.2f} (other processes compete for the cores)")
    small = campaign_of(args.config, args.samples)
    warm_up(small)
    bare = bare_seconds_per_drop(small)
    print(f"bare run_machine(lean=True): {bare * 1e3:.1f} ms per drop ({1 / bare:.2f} drops/s), "
          f"{args.samples} samples of {args.config.name}")
    rates, dispatch = {}, {}
    with tempfile.TemporaryDirectory() as tmp:
        cpu = {}
        for workers in (1, 2):
            with ProcessWatch() as watch:
                result = run_campaign(small, Path(tmp) / f"w{workers}.zarr", workers=workers)
            cpu[workers] = (watch.cpu / result["new"], sum(watch.child_cpu.values()) / result["new"])
            rates[workers] = result["drops_per_second"]
            ds = load_results(Path(tmp) / f"w{workers}.zarr")
            in_worker = float(ds["sample_time"].mean())
            busy = result["run_s"] * workers / result["new"]
            dispatch[workers] = busy / in_worker - 1.0
            print(f"{workers} worker(s): {result['drops_per_second']:.2f} drops/s over {result['run_s']:.1f} s "
                  f"(start-up {result['startup_s']:.1f} s, kernel load {result['warm_up_s']:.2f} s per worker); "
                  f"per sample: {1e3 * in_worker:.1f} ms in evaluate_sample, {1e3 * busy:.1f} ms of worker time")
        overhead = (1.0 / rates[1]) / bare - 1.0
        scaling = rates[2] / rates[1]
        building = sample_overhead(small)
        total = (1.0 + building) * (1.0 + dispatch[1]) - 1.0
        print(f"overhead of the campaign per sample, 1 worker against bare, measured apart: {100 * overhead:+.1f} %")
        print(f"overhead measured side by side: machine from the tables and record {100 * building:+.1f} %, "
              f"Dask and store (worker time over evaluate_sample) {100 * dispatch[1]:+.1f} %, together "
              f"{100 * total:+.1f} %  (target < 5 %)")
        print(f"scaling 2 workers / 1 worker: {scaling:.2f}x  (target >= 1.7x)")
        client, worker = cpu[2]
        print(f"CPU per drop with 2 workers: {1e3 * worker:.0f} ms in the workers (with their start-up), "
              f"{1e3 * client:.1f} ms in this process (scheduler, store writes); on 2 idle cores that "
              f"caps the scaling at about 2 w / (w + c) = {2 * worker / (worker + client):.2f}x")
        big = campaign_of(args.config, args.big)
        with ProcessWatch(every=0.5) as memory:
            start = time.perf_counter()
            result = run_campaign(big, Path(tmp) / "big.zarr")
            wall = time.perf_counter() - start
        print(f"{args.big}-drop campaign on {result['workers']} workers: {wall:.1f} s end to end "
              f"({result['drops_per_second']:.2f} drops/s while running; start-up {result['startup_s']:.1f} s)"
              f"  (target < 120 s)")
        trace = np.array(memory.samples)
        running = trace[trace[:, 0] > result["startup_s"]]
        if len(running) >= 4:
            quarter, last = running[len(running) // 4], running[-2]
            print(f"memory, client / workers [MB]: at 25 % {quarter[1]:.0f} / {quarter[2]:.0f}, near the end "
                  f"{last[1]:.0f} / {last[2]:.0f} (growth {last[1] - quarter[1]:+.0f} / {last[2] - quarter[2]:+.0f})")


if __name__ == "__main__":
    main()
