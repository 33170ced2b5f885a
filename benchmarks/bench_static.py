"""Batched static solver versus a per-case scipy.optimize loop on the same equations, in one run.

    .venv/bin/python benchmarks/bench_static.py [--cases 10000] [--subset 300] [--bearing QJ202]

Both sides solve load + F_ballset(u) = 0 for the inner-ring displacement u under 5-DOF loads
(Fa, Fx, Fy, Mx, My) drawn uniformly from |F| <= 3 kN, |M| <= 10 N m. They share the ball-set
model, its analytic Jacobian, the scaling (moments / r_ic, tilts * r_ic) and the rigid-ring start
(auxbearing.core.statics.initial_guess):

* ours: auxbearing.analysis.statics.solve_cases, the library's batched solve (compiled damped
  Newton over all cases in one call, core.statics.solve_batch);
* peer: scipy.optimize.root(method="hybr", jac=True) looping over the cases, once with the
  public numpy ball-set face (auxbearing.bearings.ballset.ballset_state: force and Jacobian) as
  the right-hand side, and once with the compiled ball-set sum (auxbearing.core.ballset.accumulate)
  so that only scipy's own per-case overhead remains. The peer runs on the first ``--subset``
  cases; its time per case is also scaled to ``--cases`` (stated in the output).

Timings are printed, never asserted. Answers are compared on the subset: per case
max |u_ours - u_scipy| (tilts scaled to m) relative to max |u_ours|, worst case reported.
"""

from __future__ import annotations

import argparse
import time

import numpy as np
from scipy import optimize

from auxbearing.analysis.statics import solve_cases
from auxbearing.bearings.ballset import ballset_params, ballset_state
from auxbearing.bearings.catalogue import load_bearing
from auxbearing.core.ballset import accumulate
from auxbearing.core.statics import initial_guess


def make_loads(n: int, seed: int = 0) -> np.ndarray:
    rng = np.random.default_rng(seed)
    loads = np.empty((n, 5))
    loads[:, :3] = rng.uniform(-3000.0, 3000.0, (n, 3))
    loads[:, 3:] = rng.uniform(-10.0, 10.0, (n, 2))
    return loads


def scipy_loop(loads, params, kind):
    ric = params.moment_arm
    w = np.array([1.0, 1.0, 1.0, 1.0 / ric, 1.0 / ric])
    xs = np.array([1.0, 1.0, 1.0, ric, ric])
    free = np.ones(5, dtype=np.bool_)

    def numpy_form(y, load):
        s = ballset_state(y / xs, params)
        return (load + s.force) * w, s.jacobian * w[:, None] / xs[None, :]

    def compiled_form(y, load):
        force, jac = np.zeros(5), np.zeros((5, 5))
        accumulate(y / xs, params, params.clearance, force, jac, True, False)
        return (load + force) * w, jac * w[:, None] / xs[None, :]

    fun = numpy_form if kind == "numpy" else compiled_form
    out = np.empty_like(loads)
    failures = 0
    for i, load in enumerate(loads):
        y0 = initial_guess(load, free, params) * xs
        sol = optimize.root(fun, y0, args=(load,), jac=True, method="hybr", options={"xtol": 1e-12})
        failures += not sol.success
        out[i] = sol.x / xs
    return out, failures


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--cases", type=int, default=10_000)
    parser.add_argument("--subset", type=int, default=300)
    parser.add_argument("--bearing", default="QJ202")
    args = parser.parse_args()
    params = ballset_params(load_bearing(args.bearing))
    loads = make_loads(args.cases)
    ric = params.moment_arm
    xs = np.array([1.0, 1.0, 1.0, ric, ric])

    solve_cases(loads[:10], params)  # compile / load the numba cache outside the timing
    scipy_loop(loads[:3], params, "numpy")
    scipy_loop(loads[:3], params, "compiled")

    t0 = time.perf_counter()
    ours = solve_cases(loads, params)
    t_ours = time.perf_counter() - t0
    per_ours = t_ours / args.cases

    sub = loads[: args.subset]
    print(f"bearing {args.bearing}: {args.cases} load cases, |F| <= 3 kN, |M| <= 10 N m")
    print(f"batched Newton (auxbearing): {t_ours:.3f} s for {args.cases} cases = {per_ours * 1e6:.1f} us/case, "
          f"max relative residual {ours.relative_residual.max():.2e}, mean {ours.iterations.mean():.1f} iterations")
    for kind in ("numpy", "compiled"):
        t0 = time.perf_counter()
        peer, failures = scipy_loop(sub, params, kind)
        t_peer = time.perf_counter() - t0
        per_peer = t_peer / args.subset
        diff = np.max(np.abs(peer - ours.displacement[: args.subset]) * xs, axis=1)
        size = np.max(np.abs(ours.displacement[: args.subset]) * xs, axis=1)
        rel = float(np.max(diff / size))
        print(f"scipy.optimize.root hybr, {kind} residual: {t_peer:.2f} s for {args.subset} cases = "
              f"{per_peer * 1e6:.0f} us/case -> {per_peer * args.cases:.1f} s scaled to {args.cases} cases; "
              f"{failures} not successful")
        print(f"  ratio per case: {per_peer / per_ours:.0f}x   max relative difference of answers: {rel:.2e}")


if __name__ == "__main__":
    main()
