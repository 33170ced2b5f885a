"""Cold start (issue 21): the first drop after an install, with the kernel cache empty, both ways of installing.

Each way gets an empty kernel cache of its own (``NUMBA_CACHE_DIR`` set to a fresh folder, which
:mod:`auxbearing.core` honours), so the installed cache is neither used nor touched:

1. installed with pip only: the first ``auxbearing drop`` compiles what it runs (on two cores, through
   :mod:`auxbearing.analysis.first_compile`), then a second one loads it;
2. installed with the README's ``make``: its ``kernels`` step (the Makefile's recipe, run again here with
   ``make -B`` and the install step taken as done) compiles the kernels right after the install, two
   processes side by side; then the first ``auxbearing drop``.

Prints each wall time against the target (the first drop after the install within 30 s). Every drop is the
default one (the paper rig, 0.15 s) run from the command line in a scratch folder, imports included; nothing
is asserted. About five minutes on the 2-core machine. ``bench_drop.py`` splits a compilation from an empty cache
by stage (imports, the drop kernels, the outputs' kernels) inside one Python process.

With ``--without-helper`` the pip way's first drop runs once more from another empty cache with
:mod:`auxbearing.analysis.first_compile` switched off, and the ratio of the two is printed.

    python benchmarks/bench_cold_start.py [--skip-make] [--without-helper]
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

from auxbearing.analysis import first_compile

ROOT = Path(__file__).resolve().parents[1]
BIN = Path(sys.executable).parent
TARGET = 30.0  # [s] the first drop after the install


def timed(command: list[str], env: dict, cwd: Path) -> float:
    """Wall time of ``command`` [s]; a failing command stops the benchmark with its output."""
    start = time.perf_counter()
    done = subprocess.run(command, env=env, cwd=cwd, capture_output=True, text=True)
    wall = time.perf_counter() - start
    if done.returncode != 0:
        sys.exit(f"{' '.join(command)} failed ({done.returncode}):\n{done.stdout}\n{done.stderr}")
    return wall


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--skip-make", action="store_true", help="only the pip way")
    parser.add_argument("--without-helper", action="store_true",
                        help="also the pip way's first drop with the compile helper switched off (about 2 minutes)")
    args = parser.parse_args()
    drop = [str(BIN / "auxbearing"), "drop", "--quiet"]
    with tempfile.TemporaryDirectory() as scratch:
        scratch = Path(scratch)
        pip_cache, make_cache = scratch / "pip-cache", scratch / "make-cache"
        env = {**os.environ, "NUMBA_CACHE_DIR": str(pip_cache), "MPLBACKEND": "Agg"}
        cold = timed(drop, env, scratch)
        warm = timed(drop, env, scratch)
        print(f"installed with pip: first drop {cold:.1f} s (compiling), the next {warm:.1f} s; "
              f"target {TARGET:g} s for the first")
        if args.without_helper:
            alone = {**env, "NUMBA_CACHE_DIR": str(scratch / "alone-cache"), first_compile.ENV_SWITCH: "0"}
            single = timed(drop, alone, scratch)
            print(f"  the same without the compile helper ({first_compile.ENV_SWITCH}=0): {single:.1f} s, "
                  f"{single / cold:.2f} times the first drop with it")
        if args.skip_make:
            return
        env["NUMBA_CACHE_DIR"] = str(make_cache)
        venv = Path(sys.prefix).relative_to(ROOT) if Path(sys.prefix).is_relative_to(ROOT) else Path(".venv")
        stamps = [f"{venv}/.installed-stamp", f"{venv}/.kernels-stamp"]
        compile_s = timed(["make", "-B", "-o", stamps[0], stamps[1], f"VENV={venv}"], env, ROOT)
        first = timed(drop, env, scratch)
        print(f"installed with make: its kernels step {compile_s:.1f} s after the install, then the first drop "
              f"{first:.1f} s; target {TARGET:g} s for the first drop")


if __name__ == "__main__":
    main()
