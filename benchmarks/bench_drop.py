"""Rotor drop: our compiled DOPRI5 against scipy.integrate.solve_ivp (RK45) on the same model.

Both integrate the same 12-state model (auxbearing.core.drop) with the same tolerances
(rtol and the same per-state atol vector), the same step cap and the same ball-set model: the
baseline right-hand side is numpy, with the ball-set force vectorised over balls and pairs from
the shared model's packed parameters and K_b(alpha) table. Both use the Dormand-Prince 5(4)
pair and the same error norm; scipy's step controller is the plain I-controller, ours the PI
controller.

Prints wall times, RHS evaluation counts, the ratio (target >= 100x), the peak collision force
of each (target: within 1 %), and the compile time measured in a fresh process with an empty
numba cache and the start-up of a second process that loads the cached machine code.

    python benchmarks/bench_drop.py [--bearing QJ202 --bearing 7202] [--duration 0.15] [--rtol 1e-6]
"""

from __future__ import annotations

import argparse
import math
import os
import subprocess
import sys
import tempfile
import time

import numpy as np
from scipy.integrate import solve_ivp

from auxbearing import get_bearing
from auxbearing import drop as ad
from auxbearing.core import ballset
from auxbearing.core import drop as cd


def make_numpy_rhs(model: ad.DropModel):
    """The drop right-hand side in numpy (same equations as auxbearing.core.drop.rhs)."""
    p = model.params
    head = ballset.unpack(model.ballset)
    cphi = np.cos(head["azimuths"])[:, None]
    sphi = np.sin(head["azimuths"])[:, None]
    signs = head["signs"][None, :]
    sigma = np.where(signs != 0.0, signs, 1.0)
    big_a = head["curvature_centre_distance"]
    a = signs * big_a * math.sin(head["contact_angle"])
    r0 = big_a * math.cos(head["contact_angle"]) - 0.5 * head["diametral_clearance"]
    m_r, j_r, e, m_b, j_b, r, s, k_l, c_l, c_b, mu1, mu2, v_eps, g, r_i = p[:cd.N_PARAMS]

    def support(xb, yb):
        radial = r0 + xb * cphi + yb * sphi
        length = np.sqrt(a * a + radial * radial)
        delta = np.maximum(length - big_a, 0.0)
        k_b = ballset._table_np(model.ballset, 0, np.abs(np.arctan2(sigma * a, radial)))[0]
        fr = -k_b * delta**1.5 * radial / length
        return float(np.sum(fr * cphi)), float(np.sum(fr * sphi))

    def rhs(t, y):
        out = np.empty(12)
        dx, dy = y[0] - y[3], y[1] - y[4]
        dist = math.hypot(dx, dy)
        fcx = fcy = ft = 0.0
        if dist - s > 0.0:
            nx, ny = dx / dist, dy / dist
            dvx, dvy = y[6] - y[9], y[7] - y[10]
            fn = max(0.0, k_l * (dist - s) ** (10.0 / 9.0) + c_l * (dvx * nx + dvy * ny))
            vs = -dvx * ny + dvy * nx + y[8] * r - y[11] * (r + s)
            ft = -mu1 * fn * math.tanh(vs / v_eps)
            fcx, fcy = -fn * nx - ft * ny, -fn * ny + ft * nx
        c, sn, w = math.cos(y[2]), math.sin(y[2]), y[8]
        alpha = (r * ft - e * (c * fcy - sn * fcx)) / j_r
        out[0:3] = y[6:9]
        out[6] = fcx / m_r + e * (sn * alpha + c * w * w)
        out[7] = fcy / m_r - g - e * (c * alpha - sn * w * w)
        out[8] = alpha
        fex, fey = support(y[3], y[4])
        fx, fy = -fcx + fex - c_b * y[9], -fcy + fey - c_b * y[10]
        torque = -(r + s) * ft
        fe = math.hypot(fex, fey)
        if fe > 0.0 and mu2 > 0.0:
            roll = -mu2 * fe * math.tanh(y[11] * r_i / v_eps)
            fx += roll * fey / fe
            fy += -roll * fex / fe
            torque += r_i * roll
        out[3:6] = y[9:12]
        out[9] = fx / m_b
        out[10] = fy / m_b - g
        out[11] = torque / j_b
        return out

    return rhs


def normal_force(states: np.ndarray, model: ad.DropModel) -> np.ndarray:
    return cd.grid_contact(np.ascontiguousarray(states), model.params, model.ballset)[:, 1]


def compile_times() -> tuple[float, float]:
    """Seconds to compile in a fresh process with an empty cache, and to start from the cache."""
    code = ("import time; t = time.perf_counter(); from auxbearing import drop as ad; "
            "m = ad.build_model(ad.load_bearing('QJ202'), ad.Rotor(), ad.DropCase()); "
            "t1 = time.perf_counter(); ad._warm_up(m); print(time.perf_counter() - t1)")
    with tempfile.TemporaryDirectory() as cache:
        env = {**os.environ, "NUMBA_CACHE_DIR": cache}
        first = float(subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                                     check=True).stdout.split()[-1])
        second = float(subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                                      check=True).stdout.split()[-1])
    return first, second


def bench(name: str, duration: float, rtol: float) -> None:
    """Time one bearing both ways and print the comparison."""
    bearing = get_bearing(name)
    case = ad.DropCase(duration=duration, rtol=rtol, atol=rtol)
    model = ad.build_model(bearing, ad.Rotor(), case)
    ad._warm_up(model)  # compile or load from cache before timing

    # ours: the compiled stepping loop alone (what run_drop times as wall_time_s), best of 3
    n_out = math.floor(case.duration / case.output_step + 1e-9) + 1
    best = math.inf
    for _ in range(3):
        grid = np.empty((n_out, 12))
        grid[0] = model.y0
        y = model.y0.copy()
        stats = cd.new_stats(1e-6)
        start = time.perf_counter()
        cd.integrate(y, 0.0, case.duration, model.params, model.ballset, case.rtol, model.atol, case.max_step,
                     case.output_step, 1, grid, stats)
        best = min(best, time.perf_counter() - start)
    st = dict(zip(cd.STAT_FIELDS, stats, strict=True))
    ours_peak = st["peak_force"]

    # baseline: solve_ivp RK45 with the numpy RHS, same tolerances and step cap
    rhs = make_numpy_rhs(model)
    start = time.perf_counter()
    sol = solve_ivp(rhs, (0.0, case.duration), model.y0, method="RK45", rtol=case.rtol, atol=model.atol,
                    max_step=case.max_step, first_step=1e-6)
    base_time = time.perf_counter() - start
    base_peak = float(normal_force(sol.y.T, model).max())

    print(f"Rotor drop on {bearing.name} ({bearing.label}), {case.duration:g} s, rtol = atol = {case.rtol:g} "
          f"(scaled), max step {case.max_step * 1e6:g} us")
    print(f"  {'':26s}{'wall [s]':>12s}{'RHS evals':>12s}{'steps':>10s}{'peak force [N]':>16s}")
    print(f"  {'auxbearing (numba DOPRI5)':26s}{best:12.4f}{int(st['rhs_evals']):12d}{int(st['steps']):10d}"
          f"{ours_peak:16.2f}")
    print(f"  {'scipy solve_ivp RK45':26s}{base_time:12.4f}{sol.nfev:12d}{sol.t.size - 1:10d}{base_peak:16.2f}")
    print(f"  speed-up: {base_time / best:.0f}x (target >= 100x); per RHS evaluation "
          f"{base_time / sol.nfev * 1e6:.1f} us vs {best / st['rhs_evals'] * 1e6:.2f} us")
    print(f"  peak force difference: {100 * (ours_peak / base_peak - 1):+.3f} % (target within 1 %; scipy's "
          "peak is sampled at its step points)")


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--bearing", action="append", help="catalogue bearing (repeatable); default QJ202 and 7202")
    parser.add_argument("--duration", type=float, default=0.15)
    parser.add_argument("--rtol", type=float, default=1e-6)
    parser.add_argument("--no-compile", action="store_true", help="skip the fresh-process compile timing")
    args = parser.parse_args()
    for name in args.bearing or ["QJ202", "7202"]:
        bench(name, args.duration, args.rtol)
    if not args.no_compile:
        first, second = compile_times()
        print(f"compile in a fresh process with an empty numba cache: {first:.1f} s; "
              f"second process loading the cache: {second:.2f} s")


if __name__ == "__main__":
    main()
