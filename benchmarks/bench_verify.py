"""The whole verification of the shipped blower against one blower drop, with the cluster's two workers and one.

In one process, after a short drop that compiles or loads the kernels:

1. one 0.2 s drop of the blower (``run_machine``), best of three, before and after each verification: the
   mean of the two is the unit the target is counted in (the verification within 150 of these drops' wall
   time; the machine's speed drifts by 20-30 % over minutes);
2. ``verify("blower")`` on a local cluster of ``--workers`` (default 2, then 1: the cases side by side
   against one after another on the same code), each with its wall time, the CPU time of this process and
   of its worker processes, the wall time between consecutive progress messages, and the workers' time split
   by case from the cluster's task stream: each coast-down, the convergence re-run, each campaign (named by
   its store), the drops, the geometry search's points, the kernel loading and the design's report figures
   (drawn on the cluster at the end of the runs, so the wall time is what the command line waits for but
   the writing of the files), with how busy the workers were over the run. The verdict is printed too: it
   must not change with the number of workers;
3. the drops each campaign ran (read from its store) and their wall time in units: the whirl criterion's
   statistics set how many there are, and each is a unit drop without its time series, so their count over the
   workers is a floor under the verification's units that no kernel speed-up or schedule moves.

    python benchmarks/bench_verify.py [--quick] [--design-alone] [--workers 2 --workers 1] [--machine blower]

A full blower verification takes 70-85 s a run on the 2-core machine with two workers, the design alone
39-48 s; ``--quick`` measures the quick verification instead.
"""

from __future__ import annotations

import argparse
import os
import resource
import tempfile
import time
from itertools import pairwise
from pathlib import Path

from auxbearing.analysis.drop import run_machine
from auxbearing.machine.files import read_machine
from auxbearing.verify.run import verify


def load() -> str:
    one, five, fifteen = os.getloadavg()
    return f"load average {one:.2f} / {five:.2f} / {fifteen:.2f} (1/5/15 min) on {os.cpu_count()} cores"


def one_drop(machine_name: str) -> float:
    machine = read_machine(machine_name)
    run_machine(machine, duration=0.01)  # kernels compiled or loaded
    best = float("inf")
    for _ in range(3):
        start = time.perf_counter()
        run_machine(machine, duration=0.2)
        best = min(best, time.perf_counter() - start)
    return best


def children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def _case_of(key: str, stores: dict) -> str:
    """The case a task of the verification belongs to, from its key (function name or campaign tag)."""
    if key.startswith("campaign-"):
        return f"campaign {stores.get(key.split('-')[1], key.split('-')[1])}"
    kind = key.split("-")[0]
    if kind.endswith("_figures"):  # the design's report figures, drawn on the cluster at the end of the runs
        return "report figures"
    return {"_coastdown_task": "coast-downs (design, candidates, recommended geometry)",
            "run_coastdown": "convergence re-run (coast-down)", "run_machine": "drops (cases, scenarios)",
            "_point_summary": "geometry search", "warm_up": "kernel loading", "_load_kernels": "kernel loading",
            "evaluate_batch": "campaign batches"}.get(kind, kind)


def _stores(out: Path) -> dict:
    """Campaign fingerprint -> store name, for naming the campaign tasks."""
    import json

    names = {}
    for attrs in out.glob("*.zarr/.zattrs"):
        tag = json.loads(attrs.read_text()).get("auxbearing_campaign")
        if tag:
            names[tag] = attrs.parent.name
    return names


def one_verification(machine_name: str, workers: int, quick: bool, alone: bool = False) -> dict:
    from distributed import get_task_stream

    from auxbearing.campaign.run import _client

    phases: list[tuple[float, str]] = []
    client, cluster = _client(None, workers)
    try:
        cpu0, child0, wall0 = time.process_time(), children_cpu(), time.perf_counter()
        with tempfile.TemporaryDirectory() as out, get_task_stream(client) as stream:
            result = verify(machine_name, Path(out), [] if alone else None, quick=quick,
                            with_recommendation=not alone, scheduler=client.scheduler.address,
                            progress=lambda text: phases.append((time.perf_counter(), text)))
            stores = _stores(Path(out))
            campaign_drops = _campaign_drops(Path(out))
        wall = time.perf_counter() - wall0
        workers_cpu = children_cpu() - child0
    finally:
        client.close()
        cluster.close()
    marks = [(t - wall0, text) for t, text in phases] + [(wall, "end")]
    split = [(text, later - t) for (t, text), (later, _) in pairwise(marks)]
    cases: dict[str, list] = {}
    for task in stream.data:
        key = task["key"] if isinstance(task["key"], str) else str(task["key"])
        compute = sum(s["stop"] - s["start"] for s in task["startstops"] if s["action"] == "compute")
        entry = cases.setdefault(_case_of(key, stores), [0, 0.0])
        entry[0] += 1
        entry[1] += compute
    return {"wall": wall, "cpu": time.process_time() - cpu0, "workers_cpu": workers_cpu, "workers": workers,
            "verdict": result["verdict"], "reason": result["reason"], "split": split, "cases": cases,
            "campaign_drops": campaign_drops}


def _campaign_drops(out: Path) -> dict:
    """Store name -> (drops run, their summed wall time [s]), from each campaign store's samples."""
    import zarr

    runs = {}
    for path in sorted(out.glob("*.zarr")):
        group = zarr.open(str(path), mode="r")
        ran = group["verdict"][:] > 0  # 0: a sample not run (the campaign stopped once decided)
        runs[path.name] = (int(ran.sum()), float(group["sample_time"][:][ran].sum()))
    return runs


def floor_lines(run: dict, unit: float) -> list[str]:
    """What the campaigns' drops alone cost, in units: a lower bound no scheduling or kernel speed-up moves.

    A campaign drop is the same 0.2 s drop as the unit (lean: no time series), and the number of them is set by
    the whirl criterion's statistics (a design passes only after enough drops without whirl for the bound to fall
    under the limit), so their share of the verification cannot fall below their count over the workers.
    """
    drops = sum(n for n, _ in run["campaign_drops"].values())
    seconds = sum(t for _, t in run["campaign_drops"].values())
    per_store = ", ".join(f"{name.removesuffix('.zarr')} {n}" for name, (n, _) in run["campaign_drops"].items())
    lines = [f"  campaign drops run: {drops} ({per_store}), {seconds:.1f} s of the workers = {seconds / unit:.0f} "
             f"units, {seconds / unit / run['workers']:.0f} units of wall on {run['workers']} worker(s) at the least"]
    coast = sum(sec for case, (_, sec) in run["cases"].items() if "coast-down" in case)
    lines.append(f"  coast-downs and the convergence re-run: {coast:.1f} s of the workers = {coast / unit:.0f} units, "
                 f"{coast / unit / run['workers']:.0f} units of wall")
    return lines


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--machine", default="blower")
    parser.add_argument("--quick", action="store_true", help="the quick verification instead of the full one")
    parser.add_argument("--design-alone", action="store_true",
                        help="the design only: no candidate, no search (--candidates none --no-recommendation)")
    parser.add_argument("--workers", type=int, action="append", help="cluster sizes to compare (default 2, 1)")
    args = parser.parse_args()
    print(load())
    drop = one_drop(args.machine)
    print(f"one 0.2 s {args.machine} drop: {drop:.3f} s wall (best of 3)")
    runs = {}
    for workers in args.workers or [2, 1]:
        run = runs[workers] = one_verification(args.machine, workers, args.quick, args.design_alone)
        # this machine's speed drifts by 20-30 % over minutes: the unit is the drop measured before and after
        after = one_drop(args.machine)
        unit = 0.5 * (drop + after)
        print(f"\none 0.2 s {args.machine} drop after it: {after:.3f} s wall (best of 3); the unit below is "
              f"their mean, {unit:.3f} s")
        options = (" --quick" if args.quick else "") + (" --candidates none --no-recommendation" if args.design_alone
                                                         else "")
        print(f"verify --machine {args.machine}{options} on {workers} worker(s): "
              f"{run['wall']:.1f} s wall = {run['wall'] / unit:.0f} drops (target: 150), CPU {run['cpu']:.1f} s "
              f"here + {run['workers_cpu']:.1f} s in the workers; {run['verdict'].upper()}: {run['reason']}")
        drop = after
        for text, seconds in run["split"]:
            print(f"  {seconds:8.1f} s  {text}")
        busy = sum(seconds for _, seconds in run["cases"].values())
        print(f"  the workers' time by case ({busy:.1f} s computing, busy {100 * busy / (workers * run['wall']):.0f} % "
              "of the run):")
        for case, (tasks, seconds) in sorted(run["cases"].items(), key=lambda item: -item[1][1]):
            if seconds >= 0.05:
                print(f"  {seconds:8.1f} s  {100 * seconds / busy:5.1f} %  {tasks:4d} tasks  {case}")
        print("\n".join(floor_lines(run, unit)))
        print(load())
    if len(runs) > 1:
        (a, ra), (b, rb) = list(runs.items())[:2]
        print(f"\n{a} workers against {b}: wall ratio {rb['wall'] / ra['wall']:.2f}; verdicts "
              f"{'the same' if ra['verdict'] == rb['verdict'] else 'DIFFER'} ({ra['verdict']}, {rb['verdict']})")


if __name__ == "__main__":
    main()
