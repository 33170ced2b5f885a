"""Drops: run a machine from the moment its magnetic bearings let go, and summarise what happened.

One code path: :func:`run_machine` integrates any :class:`~auxbearing.machine.model.Machine` with the
generic compiled integrator (:func:`auxbearing.core.integrate.dopri5`) on the machine right-hand
side (:mod:`auxbearing.core.machine`) and its observer (:mod:`auxbearing.core.watch`).
:func:`run_drop` is the source paper's planar drop (Sec. II.D, Eq. 17-26, Table II, read as
docs/paper_notes.md items 1-9), built as a one-plane machine with tilt and axial motion locked.

A run ends with a verdict: ``ok``, or the limit it crossed (the model's range, a budget, a failed
integration). Peaks from outside the model's range are not reported as results.
"""

from __future__ import annotations

import json
import math
import time
from collections.abc import Callable
from typing import NamedTuple

import numpy as np
import xarray as xr

from auxbearing import __version__
from auxbearing.analysis.dead_bearings import lighter_model, restored
from auxbearing.analysis.first_compile import compile_side_by_side, first_call_state
from auxbearing.analysis.scenario_outcome import outcome
from auxbearing.analysis.whirl import natural_frequency, timeline
from auxbearing.bearings.ballset import ballset_state
from auxbearing.bearings.ratings import ISO76_BALL_STRESS, safety_factor
from auxbearing.common import interrupt
from auxbearing.common.errors import ConvergenceError, InputError
from auxbearing.common.io import to_jsonable
from auxbearing.common.params import convert
from auxbearing.core import drive, probes
from auxbearing.core import integrate as ig
from auxbearing.core import machine as cm
from auxbearing.core import watch as cw
from auxbearing.machine.model import Machine
from auxbearing.machine.pack import journal_pressure, pack
from auxbearing.machine.scenario import breakpoints
from auxbearing.machine.stations import kinds as station_kinds
from auxbearing.machine.stations import of_kind

__all__ = ["MachineRun", "journal_orbit", "planar_view", "run_machine", "static_safety_factor", "whirl_window"]

#: Verdicts besides the limits of :data:`auxbearing.core.watch.STOP_NAMES`.
OK, STEP_BUDGET, WALL_BUDGET, INTEGRATION_FAILED = "ok", "step_budget", "wall_time_budget", "integration_failed"
#: Ball-set arrays (time x ball x pair) are kept while they stay below this many numbers per plane.
MAX_BALL_SERIES = 2e7


class MachineRun(NamedTuple):
    """The result of :func:`run_machine`."""

    dataset: xr.Dataset  #: time series, per plane where it applies (units in attrs)
    summary: dict  #: verdict, peaks, whirl, budgets, energy audit (units in the keys)


def static_safety_factor(max_stress: float) -> float | None:
    """s0 = (4200 MPa / sigma_max)^3 (ISO 76 with Hertz sigma ~ Q^(1/3)) for JSON: None without contact.

    >>> round(static_safety_factor(2100e6), 3)
    8.0
    """
    return float(safety_factor(max_stress)) if max_stress > 0.0 else None


_WARM: set = set()


def _warm_up(model) -> float:
    """Compile (or load from the disk cache) the kernels once per process; seconds spent."""
    key = ("machine", len(model.machine.planes.active))  # one specialisation per plane count
    if key in _WARM:
        return 0.0
    start = time.perf_counter()
    compile_side_by_side(model, _first_call)
    _WARM.add(key)
    return time.perf_counter() - start


def _first_call(model) -> None:
    """The integrator's and the probes' first call: compiles them, or loads them from the disk cache."""
    y, watch = first_call_state(model)
    memory = ig.new_memory(0.0, 1e-7, y.size)
    drive.advance(model.machine, watch, y, 1e-6, model.settings, memory, np.empty((0, y.size)))
    probes.series(np.zeros((1, y.size)), model.machine, True)


def whirl_window(machine: Machine) -> float:
    """Length of a whirl window [s]: ``drop.whirl_window``, or 3 spin periods at the drop and at least 5 ms."""
    if machine.simulation.whirl_window is not None:
        return machine.simulation.whirl_window
    return max(5e-3, 3.0 * 2.0 * math.pi / max(abs(machine.rotor.speed), 1.0))


def _output_step(machine: Machine, duration: float) -> tuple[float, bool]:
    sim = machine.simulation
    wanted = math.floor(duration / sim.output_step + 1e-9) + 1
    if wanted <= sim.max_output_points:
        return sim.output_step, False
    return duration / (sim.max_output_points - 1), True


class Integration(NamedTuple):
    """What :func:`integrate_machine` leaves: the packed model, output grid, observer, integrator memory, state."""

    model: object
    grid: np.ndarray
    watch: cw.Watch
    memory: ig.Memory
    y: np.ndarray
    verdict: str
    wall: float
    compile_s: float
    output_step: float
    decimated: bool


class DriverState(NamedTuple):
    """What :func:`auxbearing.core.drive.advance` works on, fresh at the drop."""

    settings: ig.Settings
    grid: np.ndarray  #: output rows, the first one the state at the drop
    y: np.ndarray
    memory: ig.Memory
    watch: cw.Watch


def start_driver(machine: Machine, model, duration: float, out_step: float) -> DriverState:
    """The driver's arrays for a run of ``duration`` with output every ``out_step`` (``model``: pack(machine))."""
    n_out = math.floor(duration / out_step + 1e-9) + 1
    grid = np.empty((n_out, model.y0.size))
    grid[0] = model.y0
    y = model.y0.copy()
    memory = ig.new_memory(0.0, min(1e-6, machine.simulation.max_step), y.size)
    memory.next_output[0] = 1
    window = whirl_window(machine)
    watch = cw.new_watch(y.size, len(model.machine.planes.active), window, math.ceil(duration / window) + 1,
                         model.energy0)
    return DriverState(model.settings._replace(output_step=out_step), grid, y, memory, watch)


def integrate_machine(machine: Machine, duration: float, output_step: float | None,
                      progress: Callable[[float, str], None] | None) -> Integration:
    """Run the compiled driver from the drop in slices of the step budget, checking the budgets between slices."""
    sim = machine.simulation
    model = pack(machine)
    # magnetic bearings dead from the start (failed at the drop, no decay) run outside the state vector: the
    # same run to the bit, without their frozen states in every stage (analysis.dead_bearings)
    light = lighter_model(machine, model, 0.0)
    run_model = model if light is None else light
    compile_s = _warm_up(run_model)
    if output_step is None:
        out_step, decimated = _output_step(machine, duration)
    else:
        out_step, decimated = output_step, False
    settings, grid, y, memory, watch = start_driver(machine, run_model, duration, out_step)
    verdict = OK
    wall = 0.0
    stops = [t for t in breakpoints(machine) if t < duration] + [duration]
    while True:
        interrupt.check()  # before every chunk: a Ctrl-C that a library swallowed still stops the run
        start = time.perf_counter()
        status = drive.advance(run_model.machine, watch, y, stops[0], settings, memory, grid)
        wall += time.perf_counter() - start
        if status == ig.FINISHED and len(stops) > 1:
            stops.pop(0)  # a scenario's or a load's time reached: on to the next
            continue
        if status == ig.FINISHED:
            break
        if status == ig.STOPPED:
            verdict = cw.STOP_NAMES[int(watch.stop[0])]
            break
        if status == ig.STEP_UNDERFLOW:
            verdict = INTEGRATION_FAILED
            break
        attempts = int(memory.steps[0] + memory.rejected[0])
        if attempts >= sim.max_steps:
            verdict = STEP_BUDGET
            break
        if wall >= sim.max_wall_time:
            verdict = WALL_BUDGET
            break
        if progress is not None:
            progress(memory.t[0] / duration, f"t = {memory.t[0] * 1e3:.1f} ms of {duration * 1e3:.0f} ms, "
                                             f"{attempts} steps, {wall:.1f} s")
    if progress is not None:
        progress(1.0, "done")
    grid = grid[: int(memory.next_output[0])]
    if light is not None:  # back in the machine's own layout, the bearings frozen where they started
        grid, y = restored(model, light, grid, model.y0), restored(model, light, y, model.y0)
        rates = restored(model, light, memory.derivative, np.zeros(model.y0.size))  # frozen: no rate
        memory = memory._replace(derivative=rates)
    return Integration(model, grid, watch, memory, y, verdict, wall, compile_s, out_step, decimated)


def as_machine(machine) -> Machine:
    """A :class:`~auxbearing.machine.model.Machine` as given, or read from a TOML path or an example machine's name."""
    if isinstance(machine, Machine):
        return machine
    from auxbearing.machine.files import read_machine

    return read_machine(machine)


#: The longest simulated time a run takes [s], as the command line's --duration (about 11.6 days).
LONGEST_RUN = 1e6


def simulated_time(value, field: str = "duration") -> float:
    """A simulated time from a number (s) or a string with a unit ("50 ms") [s], in (0, :data:`LONGEST_RUN`]."""
    if isinstance(value, str):
        try:  # a quoted number has no unit: "0.2" may be ms or s to whoever wrote it
            float(value.strip())
        except ValueError:
            pass
        else:
            raise InputError.for_field(field, value, f"needs a unit, e.g. '{value.strip()} s'")
    seconds = convert(field, value, "time")
    if not (math.isfinite(seconds) and 0.0 < seconds <= LONGEST_RUN):
        raise InputError.for_field(field, value, f"must lie in (0, {LONGEST_RUN:g}] s")
    return seconds


def run_machine(machine: Machine | str, duration: float | str | None = None,
                progress: Callable[[float, str], None] | None = None, lean: bool = False) -> MachineRun:
    """Integrate a machine's touchdown and summarise it (module docstring).

    Parameters
    ----------
    machine : Machine or str
        A machine, or the path of a machine TOML file or an example machine's name (``auxbearing machines``).
    duration : float or str, optional
        Simulated time (a number in s or a string with a unit, "50 ms"); default ``machine.simulation.duration``.
    progress : callable, optional
        Called with (fraction done, a short status line) after every slice of 20 000 steps.
    lean : bool
        Keep only what the summary needs (campaigns): no per-ball arrays, no stress time series and of the contact
        diagnostics only the penetration and the mount's travel over time (:func:`machine_dataset`).

    Returns
    -------
    MachineRun
    """
    machine = as_machine(machine)
    if duration is not None:
        given, duration = duration, simulated_time(duration)
        if duration < machine.simulation.output_step:  # as a file's drop.duration is (Simulation)
            raise InputError.for_field("duration", given, "shorter than drop.output_step = "
                                       f"{machine.simulation.output_step:g} s")
    else:
        duration = machine.simulation.duration
    run = integrate_machine(machine, duration, None, progress)
    ds = machine_dataset(machine, run.model, run.grid, run.output_step, lean)
    summary = machine_summary(machine, run, ds, duration)
    ds.attrs["summary"] = json.dumps(to_jsonable(summary))
    return MachineRun(ds, summary)


def journal_orbit(machine: Machine, duration: float, output_step: float) -> np.ndarray:
    """Journal axis (x, y) at the mass-centre plane on the grid k * output_step (no outputs built) [m].

    For fits that run many short simulations; a run that does not end ``ok`` raises
    :class:`~auxbearing.common.errors.ConvergenceError` (a failed simulation is never padded and fitted).
    """
    run = integrate_machine(machine, duration, output_step, None)
    if run.verdict != OK:
        raise ConvergenceError(f"simulation of {machine.name} ended with {run.verdict} at "
                               f"t = {run.memory.t[0] * 1e3:.4g} ms", float("nan"), int(run.memory.steps[0]))
    return run.grid[:, [cm.X, cm.Y]]


# ----------------------------------------------------------------------------- outputs
_ROTOR_SERIES = {  # state column: (name, unit, long name)
    cm.X: ("rotor_x", "m", "Journal axis x at the mass-centre plane"),
    cm.Y: ("rotor_y", "m", "Journal axis y at the mass-centre plane"),
    cm.Z: ("rotor_z", "m", "Rotor axial position"),
    cm.TX: ("tilt_x", "rad", "Journal axis tilt about x"),
    cm.TY: ("tilt_y", "rad", "Journal axis tilt about y"),
    cm.PHI: ("rotor_angle", "rad", "Rotor spin angle"),
    cm.VX: ("rotor_vx", "m/s", "Journal axis velocity x"),
    cm.VY: ("rotor_vy", "m/s", "Journal axis velocity y"),
    cm.OMEGA: ("rotor_speed", "rad/s", "Rotor spin speed"),
}
_PLANE_SERIES = {
    cm.RX: ("race_x", "m", "Inner race centre x"),
    cm.RY: ("race_y", "m", "Inner race centre y"),
    cm.RZ: ("race_z", "m", "Inner race axial position"),
    cm.RPSI: ("race_angle", "rad", "Inner race spin angle"),
    cm.RVX: ("race_vx", "m/s", "Inner race velocity x"),
    cm.RVY: ("race_vy", "m/s", "Inner race velocity y"),
    cm.ROMEGA: ("race_speed", "rad/s", "Inner race spin speed"),
    cm.OX: ("ring_x", "m", "Outer ring centre x"),
    cm.OY: ("ring_y", "m", "Outer ring centre y"),
}
_DIAG_SERIES = {
    "penetration": ("m", "Journal/race penetration delta (Eq. 17); negative: gap"),
    "normal_force": ("N", "Journal/race collision (normal) force F_n1 (Eq. 19)"),
    "friction_force": ("N", "Friction on the journal along the CCW tangent (Eq. 21 corrected)"),
    "slip_velocity": ("m/s", "Slip of the journal surface over the race, along the tangent"),
    "ball_force_x": ("N", "Ball-set force on the race x (Eq. 22)"),
    "ball_force_y": ("N", "Ball-set force on the race y (Eq. 22)"),
    "ball_force_axial": ("N", "Ball-set force on the race along z"),
    "max_ball_load": ("N", "Largest ball contact-pair load"),
    "axial_force": ("N", "Axial force of the rotor collar on the race face (+z)"),
    "axial_penetration": ("m", "Collar/race-face penetration; negative: gap"),
    "mount_deflection": ("m", "Radial travel of the outer ring in its mount"),
    "face_torque": ("N*m", "Face-friction torque on the rotor"),
}


def journal_centres(machine: Machine, model, grid: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Each plane's journal centre (x, y) on a grid of states [m]: the rigid rotor's axis plus its bending there."""
    positions = np.array([p.position for p in machine.planes])
    x = grid[:, [cm.X]] + positions * grid[:, [cm.TY]]
    y = grid[:, [cm.Y]] - positions * grid[:, [cm.TX]]
    layout, modes = model.layout, model.modes
    if layout.modes:
        eta = grid[:, layout.modes_at:layout.modes_at + layout.modes]
        x = x + eta @ modes.shape_x[:len(positions)].T
        y = y + eta @ modes.shape_y[:len(positions)].T
    return x, y


def axis_at(model, grid: np.ndarray, position: float, shape_x, shape_y) -> tuple[np.ndarray, ...]:
    """The rotor axis at an axial position on a grid of states: x, y, vx, vy [m, m/s], bending included."""
    x = grid[:, cm.X] + position * grid[:, cm.TY]
    y = grid[:, cm.Y] - position * grid[:, cm.TX]
    vx = grid[:, cm.VX] + position * grid[:, cm.WY]
    vy = grid[:, cm.VY] - position * grid[:, cm.WX]
    layout = model.layout
    if layout.modes:
        n, at = layout.modes, layout.modes_at
        x, y = x + grid[:, at:at + n] @ shape_x, y + grid[:, at:at + n] @ shape_y
        vx, vy = vx + grid[:, at + n:at + 2 * n] @ shape_x, vy + grid[:, at + n:at + 2 * n] @ shape_y
    return x, y, vx, vy


#: The contact diagnostics a lean run keeps over time (:func:`auxbearing.core.probes.contact_series`), and those it
#: keeps at the last instant only, as ``<name>_at_end`` (the summary's final forces).
LEAN_SERIES = ("penetration", "mount_deflection")
LEAN_AT_END = ("normal_force", "axial_force")


def _needs_force_series(machine: Machine) -> bool:
    """Whether the summary reads the contact force over time: a scenario from levitation finds its touchdowns so."""
    return bool(of_kind(machine.stations, "amb")) and machine.active_scenario().levitated


def _at_end(ds: xr.Dataset, name: str, k: int) -> float:
    """A contact diagnostic of plane ``k`` at the end of the run, from its series or a lean run's last instant."""
    series = ds.variables
    return float(series[name].values[-1, k] if name in series else series[f"{name}_at_end"].values[k])


def machine_dataset(machine: Machine, model, grid: np.ndarray, out_step: float, lean: bool = False) -> xr.Dataset:
    """The time series of a run on its output grid (units in attrs).

    ``lean``: no per-ball arrays, no stress series and, unless a scenario from levitation needs the contact force
    over time, of the contact diagnostics only :data:`LEAN_SERIES` over time and :data:`LEAN_AT_END` at the end.
    """
    n = grid.shape[0]
    n_planes = len(machine.planes)
    t = np.arange(n) * out_step
    data = {}
    for col, (name, unit, long_name) in _ROTOR_SERIES.items():
        data[name] = ("time", grid[:, col], {"units": unit, "long_name": long_name})
    planes = np.stack([grid[:, cm.N_ROTOR + k * cm.N_PLANE: cm.N_ROTOR + (k + 1) * cm.N_PLANE]
                       for k in range(n_planes)], axis=1)
    for col, (name, unit, long_name) in _PLANE_SERIES.items():
        data[name] = (("time", "plane"), planes[:, :, col], {"units": unit, "long_name": long_name})
    journal_x, journal_y = journal_centres(machine, model, grid)
    data["journal_x"] = (("time", "plane"), journal_x, {"units": "m", "long_name": "Journal centre x at the plane"})
    data["journal_y"] = (("time", "plane"), journal_y, {"units": "m", "long_name": "Journal centre y at the plane"})
    layout = model.layout
    if layout.modes:
        data["mode"] = (("time", "mode"), grid[:, layout.modes_at:layout.modes_at + layout.modes],
                        {"units": "m*kg**0.5", "long_name": "Elastic mode coordinate (mass-normalised shape)"})
    for k, (kind, params) in enumerate(zip(station_kinds(), model.stations, strict=True)):
        def axis(i, position, params=params):
            return axis_at(model, grid, position, params.shape_x[i], params.shape_y[i])

        def states(i, k=k):
            at, width = layout.station_spans[k][i]
            return grid[:, at:at + width]
        data.update(kind.series(of_kind(machine.stations, kind.KIND), axis, states, params, t, grid[:, cm.Z]))
    # per-ball states where they fit the memory cap; their largest stress is the plane's, so the
    # diagnostics need to evaluate the ball stresses only for planes without them
    states = {}
    for k, plane in enumerate(machine.planes):
        bs = model.machine.ballsets[k]
        if lean or n * bs.cos_azimuth.size * bs.signs.size > MAX_BALL_SERIES:
            continue
        b = cm.N_ROTOR + k * cm.N_PLANE
        race = (grid[:, b + cm.RZ] if plane.catches_axially else np.zeros(n), grid[:, b + cm.RX] - grid[:, b + cm.OX],
                grid[:, b + cm.RY] - grid[:, b + cm.OY])
        rows = []
        for row in range(plane.rows):  # a matched pair's rows side by side along the pair axis
            disp = np.zeros((n, 5))
            disp[:, 0], disp[:, 1], disp[:, 2] = cm.row_displacement.py_func(model.machine, k, row, *race)
            rows.append(ballset_state(disp, bs, model.machine.ballset_clearance[k], resultant=False))
        states[k] = rows[0] if len(rows) == 1 else _stack_rows(rows)
    if lean and not _needs_force_series(machine):
        # the summary reads the contact's geometry over time and the forces at the end only
        geometry = probes.contact_series(grid, model.machine)[:, :n_planes]
        last = probes.series(grid[-1:], model.machine, False)[0, :n_planes]
        for i, name in enumerate(LEAN_SERIES):
            unit, long_name = _DIAG_SERIES[name]
            data[name] = (("time", "plane"), geometry[:, :, i], {"units": unit, "long_name": long_name})
        for name in LEAN_AT_END:
            unit, long_name = _DIAG_SERIES[name]
            data[f"{name}_at_end"] = ("plane", last[:, cm.DIAG_FIELDS.index(name)].copy(),
                                      {"units": unit, "long_name": f"{long_name}, at the end of the run"})
        diag = None
    else:
        diag = probes.series(grid, model.machine, not lean and len(states) < n_planes)[:, :n_planes]
        for i, name in enumerate(cm.DIAG_FIELDS):
            unit, long_name = _DIAG_SERIES[name]
            data[name] = (("time", "plane"), diag[:, :, i], {"units": unit, "long_name": long_name})
    if not lean:
        stress = diag[:, :, len(cm.DIAG_FIELDS)].copy()
        for k, st in states.items():
            stress[:, k] = np.maximum(st.stress_inner.max(axis=(1, 2)), st.stress_outer.max(axis=(1, 2)))
        data["max_ball_stress"] = (("time", "plane"), stress,
                                   {"units": "Pa", "long_name": "Hertz max stress of the most loaded ball contact"})
    coords = {"time": ("time", t, {"units": "s", "long_name": "Time since the drop"}),
              "plane": ("plane", [p.name for p in machine.planes])}
    if states:
        # every plane's balls on one (time, plane, ball, pair) grid, NaN where a plane has fewer balls or pairs
        # (a matched pair's two rows sit side by side along pair) or kept none
        balls = max(st.load.shape[1] for st in states.values())
        pairs = max(st.load.shape[2] for st in states.values())
        arrays = {name: np.full((n, n_planes, balls, pairs), np.nan)
                  for name in ("load", "stress_inner", "stress_outer")}
        for k, st in states.items():
            for name, values in arrays.items():
                values[:, k, :st.load.shape[1], :st.load.shape[2]] = getattr(st, name)
        dims = ("time", "plane", "ball", "pair")
        data["ball_load"] = (dims, arrays["load"], {"units": "N", "long_name": "Contact-pair load"})
        for race in ("inner", "outer"):
            data[f"stress_{race}"] = (dims, arrays[f"stress_{race}"],
                                      {"units": "Pa", "long_name": f"Hertz max stress, {race} race"})
    ds = xr.Dataset(data, coords=coords)
    ds.attrs.update(title=f"Touchdown of {machine.name}", auxbearing_version=__version__,
                    model="rigid rotor on touchdown planes (auxbearing.core.machine); source paper Sec. II.D "
                          "corrected per docs/paper_notes.md as its planar case",
                    machine=json.dumps(to_jsonable(machine.describe())))
    return ds


def _stack_rows(rows):
    """The ball states of a matched pair's two rows as one, the rows' contact pairs side by side."""
    first = rows[0]
    return first._replace(**{name: np.concatenate([getattr(r, name) for r in rows], axis=2)
                             for name in ("distance", "compression", "load", "contact_angle", "stress_inner",
                                          "stress_outer")})


def _support_stiffness(plane) -> float:
    """Radial stiffness of ball set and mount in series near the rated load [N/m] (for the whip frequency)."""
    from auxbearing.analysis.statics import radial_approach
    from auxbearing.bearings.ballset import ballset_params

    bs = plane.bearing
    load = max(100.0, 0.05 * bs.ball_count * 1e3)
    dx = radial_approach(ballset_params(bs, plane.ball_constant), load)
    # a ball set that cannot carry the load radially alone (NaN) gives no estimate
    k_ball = 1.5 * load / dx if dx > 0.0 else 0.0
    if plane.mount is not None and k_ball > 0.0:
        return 1.0 / (1.0 / k_ball + 1.0 / plane.mount.mount_stiffness)
    return k_ball


def _plane_mass(machine: Machine, k: int) -> float:
    """Mass a plane carries at rest [kg], for the whirl's natural frequency: its race and its share of the rotor."""
    return machine.rotor.mass * machine.rest_share(k) + machine.planes[k].race_mass


def machine_summary(machine: Machine, run: Integration, ds: xr.Dataset, duration: float) -> dict:
    """Verdict, peaks, whirl, budgets and energy audit of a run (keys in :func:`run_machine`)."""
    model, watch, memory, verdict = run.model, run.watch, run.memory, run.verdict
    stop = watch.stop
    t_end = float(memory.t[0])
    reason = None
    if verdict == OK:
        pass
    elif verdict in cw.STOP_NAMES.values():
        k = int(stop[1])
        where = machine.planes[k].name if k >= 0 else "the machine"
        reason = _stop_sentence(verdict, where, float(stop[2]), float(stop[3]), machine, k)
    elif verdict == STEP_BUDGET:
        reason = (f"the step budget drop.max_steps = {machine.simulation.max_steps:.3g} was used up at "
                  f"t = {t_end * 1e3:.2f} ms; raise it to go on")
    elif verdict == WALL_BUDGET:
        reason = (f"the wall-time budget drop.max_wall_time = {machine.simulation.max_wall_time:g} s was used up "
                  f"at t = {t_end * 1e3:.2f} ms; raise it to go on")
    else:
        reason = f"the integration could not go on at t = {t_end * 1e3:.4g} ms (step size underflow)"
    valid = verdict == OK
    seen = verdict != INTEGRATION_FAILED
    planes = []
    n_windows = int(watch.window_count[0])
    series = ds.variables  # read as arrays: a Dataset per plane costs as much as the rest of the summary

    def of_plane(name: str, k: int) -> np.ndarray:
        return series[name].values[:, k]

    time_s = series["time"].values
    for k, plane in enumerate(machine.planes):
        records = watch.whirl[:n_windows, k]
        support = _support_stiffness(plane)
        mass = _plane_mass(machine, k)
        natural = np.array([natural_frequency(r[6], plane.line_stiffness, support, mass) for r in records])
        whirl = timeline(records, whirl_window(machine), plane.radial_clearance, plane.journal_radius,
                         natural)
        peak_stress = float(watch.peak[1, k])
        first = float(watch.first_contact[k])
        pen = of_plane("penetration", k)
        after = time_s >= (first if first >= 0.0 else np.inf)
        rotor_surface = series["rotor_speed"].values * plane.journal_radius
        race_surface = of_plane("race_speed", k) * (plane.journal_radius + plane.radial_clearance)
        spin = machine.rotor.speed
        rolling = (np.abs(rotor_surface) > 0) & (race_surface * np.sign(spin) >= 0.95 * np.abs(rotor_surface))
        spun = np.nonzero(rolling)[0]
        angle, pressure = journal_pressure(plane, float(watch.peak[0, k]))
        planes.append({
            "name": plane.name, "bearing": plane.unit.name, "type": plane.unit.type,
            # peaks up to the end of the run, also of one that stopped at a limit or a budget: they are what the
            # model saw inside its range (the verdict says whether the run finished); a failed integration has none
            "peak_contact_force_N": float(watch.peak[0, k]) if seen else None,
            "peak_ball_stress_MPa": peak_stress / 1e6 if seen else None,
            "s0": static_safety_factor(peak_stress) if seen else None,
            "peak_journal_pressure_MPa": pressure / 1e6 if seen else None,
            "journal_contact_half_angle_deg": math.degrees(angle) if seen else None,
            "final_contact_force_N": _at_end(ds, "normal_force", k),
            "peak_axial_force_N": float(watch.peak[2, k]) if seen else None,
            "final_axial_force_N": _at_end(ds, "axial_force", k),
            "whirl": whirl["whirl"], "backward_whirl_onset_ms": whirl["backward_whirl_onset_ms"],
            "backward_whirl_at_end": whirl["backward_at_end"], "whirl_frequency_Hz": whirl["whirl_frequency_Hz"],
            "whirl_timeline": whirl["classes"], "whirl_window_ms": whirl_window(machine) * 1e3,
            "first_impact_ms": first * 1e3 if first >= 0.0 else None, "impacts": int(watch.onsets[k]),
            "largest_bounce_um": float(max(0.0, -pen[after].min())) * 1e6 if after.any() else 0.0,
            "contact_fraction": float(np.mean(pen[after] > 0.0)) if after.any() else 0.0,
            "race_spin_up_ms": float(time_s[spun[0]] * 1e3) if spun.size else None,
            "final_race_speed_rad_s": float(of_plane("race_speed", k)[-1]),
            "peak_ball_load_N": float(watch.peak_load[k]) if seen else None,
            "shoulder_use": float(watch.shoulder_use[k]), "peaks_cover": "the whole run" if valid else
            f"the run up to its stop at {t_end * 1e3:.2f} ms",
            "peak_force_time_ms": float(watch.peak_time[0, k]) * 1e3,
            "peak_stress_time_ms": float(watch.peak_time[1, k]) * 1e3,
            "max_mount_deflection_um": float(np.max(of_plane("mount_deflection", k))) * 1e6,
            # from the machine's axis, where its seals and magnetic bearings are centred: not from the outer ring,
            # which moves on a compliant mount (the blower's by 25 um) while the seals stay in the housing
            "max_excursion_um": float(np.max(np.hypot(of_plane("journal_x", k), of_plane("journal_y", k)))) * 1e6,
            "line_stiffness_N_per_m10_9": plane.line_stiffness,
            "defaults_used": list(plane.defaults),
        })
    energy_in, accounted, scale = cm.energy_balance(run.y, model.machine, model.energy0)
    out = {
        "machine": machine.name, "verdict": verdict, "reason": reason, "simulated_s": t_end,
        "duration_s": duration, "wall_time_s": run.wall, "compile_or_cache_load_s": run.compile_s,
        "steps": int(memory.steps[0]), "rejected_steps": int(memory.rejected[0]),
        "rhs_evaluations": int(memory.evaluations[0]),
        "energy_balance_error": float((accounted - energy_in) / max(scale, 1e-300)),
        "largest_energy_error": float(watch.energy_error[0]),
        "final_rotor_speed_rad_s": float(series["rotor_speed"].values[-1]) + 0.0, "planes": planes,  # no -0.0
        "largest_excursion_m": max(p["max_excursion_um"] for p in planes) * 1e-6,
        "output_step_s": run.output_step, "output_decimated": run.decimated,
    }
    bearings = of_kind(machine.stations, "amb")
    if bearings:
        out["scenario"] = outcome(machine, ds, planes)
        if run.model.orbit is not None:
            out["scenario"]["levitation"] = _levitation(run.model.orbit[2])
        out["amb"] = _amb_summary(machine, model, run.grid, bearings)
    return out


def _levitation(least: complex) -> dict:
    """The levitated machine's stability from its least damped eigenvalue.

    :func:`auxbearing.machine.levitation.steady_orbit` sets a real part that is zero to the computation's precision
    to exactly 0. An undamped mode is told apart from a growing one: neither holds the rotor, but a rate of
    "+0.00 1/s" read as a growth would be rounding noise reported as a result.
    """
    hz = abs(least.imag) / (2.0 * math.pi)
    if least.real < 0.0:
        note = "the levitated machine, linearised at its speed, is stable; the run starts on its steady unbalance orbit"
    elif least.real == 0.0:
        note = (f"the levitated machine is NOT HELD at its speed: a mode near {hz:.1f} Hz is undamped (its rate is "
                "zero to the computation's precision: the bearings neither damp nor restore it); the run starts from "
                "the levitated statics")
    else:
        note = (f"the levitated machine is UNSTABLE at its speed: a mode near {hz:.1f} Hz grows at {least.real:+.3g} "
                "1/s (the controller does not hold it); the run starts from the levitated statics")
    return {"stable": least.real < 0.0, "undamped": least.real == 0.0, "least_damped_mode_Hz": hz,
            "least_damped_rate_per_s": least.real, "note": note}


def _amb_summary(machine: Machine, model, grid: np.ndarray, bearings) -> list[dict]:
    """Each magnetic bearing: the levitated static offset and current there (before any scenario), its peak current.

    A radial bearing also gets the rotor's largest excursion from the machine's axis at its actuator over the run
    (``max_excursion_um``, on the output grid, bending included; None for an axial bearing).

    The offset is the linear statics' (:func:`auxbearing.machine.stations.amb.levitated_state`), before any
    disturbance the run starts with.
    """
    from auxbearing.machine.stations.amb import levitated_state

    spans = model.layout.station_spans[cm.STATION_KINDS.index(cm.amb)]
    params = model.stations[cm.STATION_KINDS.index(cm.amb)]
    held = levitated_state(machine, machine.modal(), bearings)
    out = []
    for i, b in enumerate(bearings):
        excursion = None
        if not b.axial and len(grid):
            # the rotor axis at the actuator, bending included: where the stator's air gap is (judge._air_gap)
            x, y, _, _ = axis_at(model, grid, b.position, params.shape_x[i], params.shape_y[i])
            excursion = float(np.hypot(x, y).max()) * 1e6
        block, axes = spans[i][0], (1 if b.axial else 2)
        columns = [block + k * (2 + b.order) + 1 + b.order for k in range(axes)]
        currents = np.sqrt((grid[:, columns] ** 2).sum(axis=1))
        axis_peak = float(np.abs(grid[:, columns]).max()) if len(grid) else 0.0
        levitated = np.asarray(held["states"][i])[[c - block for c in columns]]
        out.append({"name": b.name, "axis": "axial" if b.axial else "radial",
                    "levitated_offset_um": held["offsets"][i] * 1e6,
                    "levitated_orbit_um": _orbit_at_sensor(model, b, i) * 1e6,
                    "levitated_current_A": float(np.sqrt((levitated ** 2).sum())),
                    "peak_current_A": float(currents.max()) if len(currents) else 0.0,
                    "peak_axis_current_A": axis_peak,
                    "max_excursion_um": excursion,
                    "max_current_A": b.current_limit(),  # inf if none: "inf" in JSON (common.io)
                    "closed_loop_stiffness_N_per_m": b.closed_loop_stiffness() if b.controller is None else None})
    return out


def _orbit_at_sensor(model, bearing, i: int) -> float:
    """Radius of the levitated start's steady unbalance orbit at a bearing's sensor [m] (0 without one)."""
    if model.orbit is None or model.orbit[1] is None or bearing.axial:
        return 0.0
    states, amplitudes, _ = model.orbit
    full = np.zeros(model.y0.size, complex)
    full[states] = amplitudes
    a = bearing.sensor
    params = model.stations[cm.STATION_KINDS.index(cm.amb)]
    modes = full[model.layout.modes_at:model.layout.modes_at + model.layout.modes]
    x = full[cm.X] + a * full[cm.TY] + modes @ params.sensor_shape_x[i]
    y = full[cm.Y] - a * full[cm.TX] + modes @ params.sensor_shape_y[i]
    phase = np.exp(1j * np.linspace(0.0, 2.0 * np.pi, 361))
    return float(np.max(np.hypot((x * phase).real, (y * phase).real)))


def _stop_sentence(verdict: str, where: str, t: float, value: float, machine: Machine, k: int) -> str:
    when = f"at t = {t * 1e3:.3f} ms"
    if verdict == "journal_contact_overstress":
        plane = machine.planes[k]
        angle, pressure = journal_pressure(plane, value)
        return (f"{where}: the journal/race contact force reached {value:.4g} N {when}, a peak contact pressure of "
                f"{pressure / 1e6:.0f} MPa (contact half-angle {math.degrees(angle):.0f} deg), beyond the "
                f"{plane.journal_pressure_limit / 1e6:.0f} MPa the journal and race surfaces carry without permanent "
                "set (touchdown.journal_pressure_limit): the touchdown contact is overloaded")
    if verdict == "ball_stress_beyond_elastic":
        return (f"{where}: a ball contact reached {value / 1e6:.0f} MPa {when}, beyond "
                f"{machine.simulation.ball_stress_limit / 1e6:.0f} MPa where elastic Hertz values stop meaning "
                f"anything (ISO 76 allows {ISO76_BALL_STRESS / 1e6:.0f} MPa)")
    if verdict == "contact_ellipse_over_shoulder":
        return (f"{where}: a ball contact ellipse ran over the groove shoulder {when} "
                f"(contact angle plus half the ellipse {value:.2f} x the shoulder angle)")
    if verdict == "mount_beyond_travel":
        return f"{where}: the outer ring moved {value * 1e6:.0f} um in its mount {when}, beyond its travel"
    if verdict == "race_runs_off_axially":
        return (f"{where}: the inner race moved {value * 1e6:.1f} um axially {when}, off its balls: the bearing "
                "cannot carry the axial load that way (an angular-contact bearing catches one direction only)")
    return f"the machine gained energy ({value:.2e} of what went in) {when}: a numerical run-away, not a result"


# ----------------------------------------------------------------------------- the paper's planar drop
def planar_view(ds: xr.Dataset) -> xr.Dataset:
    """A one-plane run's Dataset without the plane dimension.

    Per-plane variables are over time only; the ball arrays ``ball_load``, ``stress_inner`` and ``stress_outer``
    over (time, ball, pair).
    """
    out = ds.isel(plane=0, drop=True)
    out.attrs["plane_name"] = str(ds.plane.values[0])
    return out


def plane_ball_arrays(ds: xr.Dataset, k: int, balls: int, pairs: int) -> dict | None:
    """Plane k's ball arrays (``ball_load``, ``stress_inner``, ``stress_outer``) over (time, ball, pair).

    Cut to the plane's own ``balls`` and ``pairs`` (a run pads every plane to the largest); None when the run
    kept none for it.
    """
    if "stress_inner" not in ds or not np.isfinite(ds.stress_inner.values[:1, k]).any():
        return None
    return {name: ds[name].values[:, k, :balls, :pairs] for name in ("ball_load", "stress_inner", "stress_outer")}
