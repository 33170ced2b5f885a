"""Run every benchmark in one process, each against its peer baseline, and print the ratios.

Run: make bench   (or .venv/bin/python benchmarks/run.py)
"""

import runpy
import sys
from pathlib import Path

HERE = Path(__file__).parent
BENCHMARKS = ("bench_hertz.py", "bench_static.py", "bench_drop.py")


def main() -> None:
    for name in BENCHMARKS:
        path = HERE / name
        print(f"\n=== {name} ===", flush=True)
        saved = sys.argv
        sys.argv = [str(path)]
        try:
            runpy.run_path(str(path), run_name="__main__")
        finally:
            sys.argv = saved


if __name__ == "__main__":
    main()
