"""Run every benchmark, each in a process of its own that compares ours with its peer and prints the ratios.

Run: make bench   (or .venv/bin/python benchmarks/run.py [--only NAME ...] [--skip NAME ...])

A benchmark that fails is reported and the others still run; the exit status says whether all passed.
Speeds are measured and printed, never asserted. The whole set takes roughly 40-60 minutes on the
2-core machine (the two blower verifications, the campaign's 1000 drops, the blower's coast-down and the
empty-cache compilation take most of it).
"""

import argparse
import os
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).parent
BENCHMARKS = ("bench_hertz.py", "bench_static.py", "bench_machine.py", "bench_drop.py", "bench_coastdown.py",
              "bench_windows.py", "bench_campaign.py", "bench_verify.py", "bench_stations.py", "bench_cold_start.py")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--only", action="append", default=[], help="run only these (repeatable), e.g. bench_drop")
    parser.add_argument("--skip", action="append", default=[], help="leave these out (repeatable)")
    args = parser.parse_args()
    wanted = [n for n in BENCHMARKS if (HERE / n).exists()]
    if args.only:
        wanted = [n for n in wanted if n.removesuffix(".py") in {o.removesuffix(".py") for o in args.only}]
    wanted = [n for n in wanted if n.removesuffix(".py") not in {s.removesuffix(".py") for s in args.skip}]
    failed = []
    for name in wanted:
        print(f"\n=== {name} ===", flush=True)
        start = time.perf_counter()
        code = subprocess.run([sys.executable, str(HERE / name)], cwd=HERE.parent).returncode
        print(f"=== {name}: {'ok' if code == 0 else f'FAILED (exit {code})'} in {time.perf_counter() - start:.0f} s, "
              f"load average {os.getloadavg()[0]:.2f} ===", flush=True)
        if code != 0:
            failed.append(name)
    if failed:
        print("\nfailed: " + ", ".join(failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
