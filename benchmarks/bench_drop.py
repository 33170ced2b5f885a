"""The paper's default drop (issue 10) against the code before the machine restructuring, start-up and CLI times.

1. A default ``run_drop("QJ202")`` (Table II, 0.15 s), best of ``--repeats`` after the kernels are
   loaded, in fresh processes of today's tree and of the tree at ``--old`` (default 3e5ee6b, the code
   before the machine restructuring; extracted with ``git archive`` into a temporary folder and run
   with it first on PYTHONPATH and its own numba cache). The two alternate ``--rounds`` times, so both
   see the same load; the best of all is kept. Target: today's at least 2x faster. The old code's
   recorded time (0.286 s, of which 0.037 s the integration) is printed beside it.
2. Compilation in a fresh process with an empty numba cache (``NUMBA_CACHE_DIR`` a new temporary
   folder), then the start-up of a second process that loads that cache: import, the drop kernels
   (``auxbearing.analysis.drop._warm_up``), the first ``run_drop`` after them (it compiles or loads what the
   outputs use), each as wall and CPU time of the process, and the whole process's wall time.
3. ``auxbearing --help`` and ``auxbearing drop --help``: wall time of the command, best of 5.

    python benchmarks/bench_drop.py [--old 3e5ee6b] [--repeats 3] [--rounds 2] [--no-old] [--no-compile]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import tarfile
import tempfile
import time
from io import BytesIO
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
#: The old code's default run_drop as recorded before the restructuring: total and integration [s].
RECORDED_OLD = (0.286, 0.037)

#: Times a default run_drop in a fresh process; the old tree had it in auxbearing.analysis.drop.
DROP_TIMER = """
import json, sys, time
import auxbearing
try:
    from auxbearing.planar.rig import run_drop
except ImportError:
    from auxbearing.planar.rig import run_drop
run_drop("QJ202")
best = None
for _ in range({repeats}):
    start = time.perf_counter()
    _, s = run_drop("QJ202")
    wall = time.perf_counter() - start
    if best is None or wall < best[0]:
        best = (wall, s["wall_time_s"], s["rhs_evaluations"], s["peak_contact_force_N"])
print(json.dumps({{"where": auxbearing.__file__, "best": best}}))
"""

#: Start-up of a process: import, the drop kernels, the first run_drop.
STARTUP_TIMER = """
import json, time
def now():
    return time.perf_counter(), time.process_time()
t0 = now()
from auxbearing.analysis import drop
from auxbearing.machine.pack import pack
from auxbearing.planar import rig
t1 = now()
drop._warm_up(pack(rig.paper_rig()))
t2 = now()
rig.run_drop("QJ202")
t3 = now()
print(json.dumps({name: (b[0] - a[0], b[1] - a[1]) for name, a, b in
                  (("import", t0, t1), ("kernels", t1, t2), ("first_run_drop", t2, t3))}))
"""


def load() -> str:
    one, five, fifteen = os.getloadavg()
    return f"load average {one:.2f} / {five:.2f} / {fifteen:.2f} (1/5/15 min) on {os.cpu_count()} cores"


def python_json(code: str, env: dict | None = None, cwd: str | None = None) -> tuple[dict, float]:
    """Run ``code`` in a fresh interpreter; its last output line as JSON and the process's wall time [s]."""
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, cwd=cwd)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        raise RuntimeError(done.stderr.strip().splitlines()[-1] if done.stderr.strip() else "failed")
    return json.loads(done.stdout.strip().splitlines()[-1]), wall


def old_tree(commit: str, into: str) -> str | None:
    """Extract ``src`` of ``commit`` into ``into`` (no worktree, nothing left in the repository); its path."""
    done = subprocess.run(["git", "-C", str(ROOT), "archive", "--format=tar", commit, "src"], capture_output=True)
    if done.returncode != 0:
        print(f"  (commit {commit} not available: {done.stderr.decode().strip()}; only the recorded time)")
        return None
    with tarfile.open(fileobj=BytesIO(done.stdout)) as tar:
        tar.extractall(into, filter="data")
    return os.path.join(into, "src")


def drop_versus_old(commit: str | None, repeats: int, rounds: int) -> None:
    """Default run_drop today against the old tree, alternating fresh processes."""
    print(f"\nDefault run_drop('QJ202'), 0.15 s simulated, best of {repeats} per process after the kernels load")
    with tempfile.TemporaryDirectory() as tmp:
        old_src = old_tree(commit, tmp) if commit else None
        old_env = None
        if old_src:
            old_env = {**os.environ, "PYTHONPATH": old_src, "NUMBA_CACHE_DIR": os.path.join(tmp, "numba")}
        new, old = [], []
        for _ in range(rounds):
            new.append(python_json(DROP_TIMER.format(repeats=repeats))[0]["best"])
            if old_env:
                out, _ = python_json(DROP_TIMER.format(repeats=repeats), old_env, tmp)
                if not out["where"].startswith(tmp):
                    raise RuntimeError(f"the old tree did not load: {out['where']}")
                old.append(out["best"])
    best_new = min(new)
    print(f"  today     : {best_new[0]:.3f} s (integration {best_new[1]:.3f} s, {best_new[2]} RHS evaluations, "
          f"peak {best_new[3]:.3f} N); all rounds: " + ", ".join(f"{r[0]:.3f}" for r in new))
    if old:
        best_old = min(old)
        print(f"  {commit:10s}: {best_old[0]:.3f} s (integration {best_old[1]:.3f} s, {best_old[2]} RHS evaluations, "
              f"peak {best_old[3]:.3f} N); all rounds: " + ", ".join(f"{r[0]:.3f}" for r in old))
        print(f"  speed-up today / {commit}: {best_old[0] / best_new[0]:.2f}x (target >= 2x); integration alone "
              f"{best_old[1] / best_new[1]:.2f}x")
    print(f"  recorded old time: {RECORDED_OLD[0]:.3f} s (integration {RECORDED_OLD[1]:.3f} s) -> "
          f"{RECORDED_OLD[0] / best_new[0]:.2f}x (target >= 2x)")


def startup() -> None:
    """Compile with an empty numba cache, then a second process that loads it."""
    with tempfile.TemporaryDirectory() as cache:
        env = {**os.environ, "NUMBA_CACHE_DIR": cache}
        print("\nStart-up (fresh processes, NUMBA_CACHE_DIR = a new empty folder)")
        for label in ("empty cache (compiles)", "second process (loads the cache)"):
            out, wall = python_json(STARTUP_TIMER, env)
            parts = ", ".join(f"{name} {w:.2f} s (CPU {c:.2f} s)" for name, (w, c) in out.items())
            print(f"  {label}: {parts}; whole process {wall:.2f} s")


def cli_help(tries: int = 5) -> None:
    """Wall time of the CLI's help screens, best of ``tries``."""
    exe = Path(sys.executable).with_name("auxbearing")
    print(f"\nCLI help, wall time of the whole command, best of {tries}")
    for args in (["--help"], ["drop", "--help"]):
        best = float("inf")
        for _ in range(tries):
            start = time.perf_counter()
            subprocess.run([str(exe), *args], capture_output=True, check=True)
            best = min(best, time.perf_counter() - start)
        print(f"  auxbearing {' '.join(args):12s}: {best:.3f} s")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--old", default="3e5ee6b", help="commit of the code before the machine restructuring")
    parser.add_argument("--no-old", action="store_true", help="compare with the recorded old time only")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--rounds", type=int, default=2, help="alternations of today's and the old process")
    parser.add_argument("--no-compile", action="store_true", help="skip the empty-cache start-up (about a minute)")
    args = parser.parse_args()
    print(load())
    drop_versus_old(None if args.no_old else args.old, args.repeats, args.rounds)
    if not args.no_compile:
        startup()
    cli_help()
    print(load())


if __name__ == "__main__":
    main()
