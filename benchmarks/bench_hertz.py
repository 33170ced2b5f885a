"""Vectorised exact ellipticity solve against a per-contact scipy root-finding loop.

The baseline is how a user would first write it: for each contact, scipy.optimize.brentq on
F(kappa) = [(kappa^2+1)E - 2K]/[(kappa^2-1)E] with scipy.special.ellipk/ellipe. Both run in
this process on the same 10^5 curvature differences; the loop runs on a subset and is scaled
per contact (said in the output). Prints both times, the ratio and the largest relative difference.

Run: .venv/bin/python benchmarks/bench_hertz.py [N]
"""

import sys
import time

import numpy as np
from scipy.optimize import brentq
from scipy.special import ellipe, ellipk

from auxbearing.core.hertz import ellipticity


def residual(kappa: float, f: float) -> float:
    m = 1.0 - 1.0 / kappa**2
    e = ellipe(m)
    return ((kappa**2 + 1.0) * e - 2.0 * ellipk(m)) / ((kappa**2 - 1.0) * e) - f


def loop_solve(f_values: np.ndarray) -> np.ndarray:
    return np.array([brentq(residual, 1.0 + 1e-9, 1e4, args=(f,), xtol=1e-15, rtol=4 * np.finfo(float).eps)
                     for f in f_values])


def main(n: int = 100_000, loop_n: int = 5_000) -> None:
    rng = np.random.default_rng(1)
    f_values = rng.uniform(0.5, 0.995, n)  # the range of ball-raceway contacts
    ellipticity(f_values[:10])  # warm-up (imports, caches)
    t0 = time.perf_counter()
    kappa, _, _ = ellipticity(f_values)
    t_vec = time.perf_counter() - t0
    sub = f_values[:loop_n]
    t0 = time.perf_counter()
    kappa_loop = loop_solve(sub)
    t_loop = (time.perf_counter() - t0) * n / loop_n
    diff = np.max(np.abs(kappa[:loop_n] / kappa_loop - 1.0))
    print(f"contacts: {n}")
    print(f"vectorised exact solve : {t_vec * 1e3:9.1f} ms  ({t_vec / n * 1e9:.0f} ns per contact)")
    print(f"scipy brentq loop      : {t_loop * 1e3:9.1f} ms  (timed on {loop_n}, scaled to {n})")
    print(f"ratio                  : {t_loop / t_vec:9.1f} x")
    print(f"max relative difference in kappa: {diff:.2e}")


if __name__ == "__main__":
    main(int(sys.argv[1]) if len(sys.argv) > 1 else 100_000)
