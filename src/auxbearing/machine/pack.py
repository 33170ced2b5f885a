"""A machine packed for the compiled kernels (:func:`pack`).

Plane parameters and range limits become tuples of floats, with the rotor, the ball sets, the initial
state and the per-state absolute tolerances, as :mod:`auxbearing.core.machine` takes them.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from auxbearing.bearings.ballset import ballset_params
from auxbearing.core import integrate as ig
from auxbearing.core import machine as cm
from auxbearing.core.hertz import journal_contact, journal_force_at_pressure
from auxbearing.machine.model import DRAG_SPEED_SCALE, JOURNAL_COMPLIANCE, Machine, TouchdownPlane
from auxbearing.machine.stations import kinds as station_kinds
from auxbearing.machine.stations import of_kind

#: A race's velocities are held to this multiple of the rotor's velocity scale (the speed of a fall through the
#: clearance). The race is light and rides on stiff contacts (ball set, journal, collar): it rings at 10-50 kHz
#: (``benchmarks/bench_step_floor.py``), so a position held to its scale moves at up to that frequency times it,
#: some 300 times the rotor's velocity scale. Held at the rotor's scale, the race's velocities chose the step:
#: the blower's drop took 18 894 steps, 10 290 with them left out of the error norm. At 10 times the scale the
#: paper rig takes 8 823 steps instead of 12 211, the blower 13 394, the compressor 13 922 instead of 16 586, the
#: vertical machine 36 372 instead of 42 271, the heavy rotor 16 920 instead of 17 975. The peaks of the paper rig,
#: the blower and the compressor are the same to five digits; their final contact force, one instant of the race
#: ringing, moves by up to 2.5e-4. The chaotic drops move within their own tolerance scatter: the vertical
#: machine's lower-plane peak force 4770 -> 4781 N, where tolerances ten and a hundred times tighter give 4827 and
#: 4838 N; the heavy rotor's 44 690 -> 45 401 N against 44 611 and 44 578 N, its stop 66.864 -> 66.850 ms, its
#: whirl the same. A verification's convergence run tightens these tolerances with the rest.
RACE_VELOCITY_SCALE = 10.0


class KernelModel(NamedTuple):
    """A machine packed for the compiled kernels."""

    machine: cm.Machine
    y0: np.ndarray
    settings: ig.Settings
    energy0: float  #: mechanical energy at the start [J]
    layout: cm.Layout  #: where each quantity sits in the state
    modes: cm.Modes  #: the rotor's elastic modes as packed (flat in ``machine.extra`` for the kernels)
    stations: tuple  #: each station kind's parameters as packed (also flat in ``machine.extra``)
    #: a levitated start: (state indices, complex amplitudes Y of its steady unbalance orbit y = y_s + Re(Y e^(i phi)),
    #: None if the levitation is unstable, the least damped eigenvalue of the linearised levitated machine [1/s])
    orbit: tuple | None = None


def plane_blocks(planes) -> int:
    """Plane blocks a machine is packed with: its planes, at least :data:`auxbearing.core.machine.MIN_PLANES`."""
    return max(len(planes), cm.MIN_PLANES)



def _plane_arrays(planes: tuple[TouchdownPlane, ...]) -> cm.Planes:
    n = plane_blocks(planes)

    def arr(get, fill=0.0):
        # tuples of floats, not arrays: the compiled code passes them by value, while every use of a
        # struct of arrays there costs a reference-count update per array (about 0.5 us a call with 34)
        out = [fill] * n
        for k, p in enumerate(planes):
            out[k] = float(get(p))
        return tuple(out)

    def mount(get, fill=0.0):
        return arr(lambda p: get(p.mount) if p.mount is not None else fill, fill)

    return cm.Planes(
        active=arr(lambda p: 1.0), position=arr(lambda p: p.position), clearance=arr(lambda p: p.radial_clearance, 1.0),
        journal_radius=arr(lambda p: p.journal_radius, 1.0), line_stiffness=arr(lambda p: p.line_stiffness),
        line_damping=arr(lambda p: p.line_damping), sliding_friction=arr(lambda p: p.sliding_friction),
        rolling_friction=arr(lambda p: p.rolling_friction), slip_velocity=arr(lambda p: p.slip_velocity, 1.0),
        race_mass=arr(lambda p: p.race_mass, 1.0), race_inertia=arr(lambda p: p.race_inertia, 1.0),
        raceway_radius=arr(lambda p: 0.5 * p.bearing.inner_raceway_diameter, 1.0),
        ball_damping=arr(lambda p: p.ball_damping), race_axial_free=arr(lambda p: float(p.catches_axially)),
        ring_free=arr(lambda p: float(p.mount is not None)), ring_mass=mount(lambda m: m.mount_mass, 1.0),
        mount_stiffness=mount(lambda m: m.mount_stiffness), mount_damping=mount(lambda m: m.mount_damping),
        mount_deadband=mount(lambda m: m.mount_deadband),
        stop_gap=mount(lambda m: m.mount_stop if m.mount_stop is not None else np.inf, np.inf),
        stop_stiffness=mount(lambda m: m.stop_stiffness or 0.0), stop_damping=mount(lambda m: m.stop_damping),
        centre_x=arr(lambda p: p.misalignment[0]), centre_y=arr(lambda p: p.misalignment[1]),
        axial_clearance=arr(lambda p: p.axial_clearance if p.catches_axially else np.inf, np.inf),
        face_plus=arr(lambda p: float(p.catches_axially and p.axial_direction in ("both", "+z"))),
        face_minus=arr(lambda p: float(p.catches_axially and p.axial_direction in ("both", "-z"))),
        face_stiffness=arr(lambda p: p.face_stiffness), face_damping=arr(lambda p: p.face_damping),
        face_friction=arr(lambda p: p.face_friction), face_radius=arr(lambda p: p.face_radius, 1.0),
        pitch_diameter=arr(lambda p: p.bearing.pitch_diameter, 1.0),
        rows=arr(lambda p: p.rows, 1.0),
        facing_a=arr(lambda p: p.bearing_set.row_facings[0] if p.bearing_set else 1.0, 1.0),
        facing_b=arr(lambda p: p.bearing_set.row_facings[1] if p.bearing_set else 1.0, 1.0),
        row_push=arr(lambda p: p.bearing_set.row_preload_displacement if p.bearing_set else 0.0),
        lubricant_viscosity=arr(lambda p: p.lubricant_viscosity), viscous_factor=arr(lambda p: p.set_viscous_factor),
    )


def journal_contact_length(plane: TouchdownPlane) -> float:
    """Length of the journal/race contact [m]: the bearing's width (two ball diameters when it gives none)."""
    b = plane.bearing
    return b.width if b.width is not None else 2.0 * b.ball_diameter


def journal_pressure(plane: TouchdownPlane, force: float) -> tuple[float, float]:
    """Contact half-angle [rad] and peak pressure [Pa] of the journal in its race at ``force`` [N].

    The conformal contact of :func:`auxbearing.core.hertz.journal_contact` (Persson's pin in a hole), the force
    spread over :func:`journal_contact_length`.
    """
    return journal_contact(float(force), journal_contact_length(plane),
                           plane.bearing.ring_material.compliance + JOURNAL_COMPLIANCE, plane.radial_clearance,
                           plane.journal_radius)


def _limits(machine: Machine) -> cm.Limits:
    sim = machine.simulation
    n = plane_blocks(machine.planes)
    journal_force = np.full(n, np.inf)
    shoulder_i, shoulder_o = np.full(n, np.pi), np.full(n, np.pi)
    groove_i, groove_o = np.ones(n), np.ones(n)
    travel, axial = np.full(n, np.inf), np.full(n, np.inf)
    for k, p in enumerate(machine.planes):
        b = p.bearing
        journal_force[k] = journal_force_at_pressure(p.journal_pressure_limit, journal_contact_length(p),
                                                     b.ring_material.compliance + JOURNAL_COMPLIANCE,
                                                     p.radial_clearance, p.journal_radius)
        for ratio, angle_out, groove_out in ((b.inner_groove_ratio, shoulder_i, groove_i),
                                              (b.outer_groove_ratio, shoulder_o, groove_o)):
            groove = ratio * b.ball_diameter
            groove_out[k] = groove
            angle_out[k] = math.acos(max(-1.0, 1.0 - p.shoulder_height / groove))
        if p.mount is not None:
            travel[k] = p.mount.mount_travel
        axial[k] = b.curvature_centre_distance
    def floats(a):
        return tuple(float(v) for v in a)

    return cm.Limits(floats(journal_force), sim.ball_stress_limit, floats(shoulder_i),
                     floats(shoulder_o), floats(groove_i), floats(groove_o), floats(travel), floats(axial),
                     sim.energy_tolerance)


def _modes(machine: Machine, blocks: int) -> cm.Modes:
    """The rotor's elastic modes as the kernel takes them, with their shapes at each plane (none: rigid)."""
    modal = machine.modal()
    if modal is None or modal.n_modes == 0:
        return cm.rigid_modes(blocks)
    shape_x, shape_y = np.zeros((blocks, modal.n_modes)), np.zeros((blocks, modal.n_modes))
    for k, p in enumerate(machine.planes):
        shape_x[k], shape_y[k] = modal.station_shapes(p.position, f"touchdown.{k}.position")
    push = np.zeros(modal.n_modes, complex)  # P_j of the unbalance planes (core.machine.Modes)
    for i, (position, amount, phase) in enumerate(machine.rotor.unbalance_planes):
        px, py = modal.station_shapes(position, f"unbalance.{i}.position")
        push += (px - 1j * py) * amount * np.exp(1j * phase)
    return cm.Modes(modal.frequencies ** 2, np.ascontiguousarray(modal.modal_damping),
                    np.ascontiguousarray(modal.modal_gyroscopic), np.ascontiguousarray(modal.tilt_gyroscopic),
                    shape_x, shape_y, push.real.copy(), push.imag.copy())


def _levitate(machine: Machine, modal, layout: cm.Layout, y0: np.ndarray) -> None:
    """Start a machine whose magnetic bearings work past the drop from its levitated static state."""
    from auxbearing.machine.stations import amb

    bearings = of_kind(machine.stations, amb.KIND)
    if not bearings or not machine.active_scenario().levitated:
        return
    held = amb.levitated_state(machine, modal, bearings)
    q = held["q"]
    # at the levitated place itself: rotor.start_x / start_y are added after the steady orbit (_start_offset), which
    # linearises the machine here; at the offset a coil's current may sit at its limit (a saturated loop has no gain)
    y0[cm.X], y0[cm.Y], y0[cm.TX], y0[cm.TY] = q[0], q[1], q[2], q[3]
    y0[cm.Z] = held["z"]  # an axial bearing holds the thrust
    y0[layout.modes_at:layout.modes_at + layout.modes] = q[4:]
    spans = layout.station_spans[cm.STATION_KINDS.index(cm.amb)]
    for (at, width), states in zip(spans, held["states"], strict=True):
        y0[at:at + width] = states


def _amb_tolerances(machine: Machine, layout: cm.Layout, atol: np.ndarray, length: float) -> None:
    """Error scales of the magnetic bearings' states: the clearance for the sensor, the rotor's weight for the coil."""
    from auxbearing.machine.stations import amb

    if not machine.active_scenario().levitated:
        return  # failed at the drop: their frozen states stay out of the step's error norm, as if absent
    spans = layout.station_spans[cm.STATION_KINDS.index(cm.amb)]
    weight = max(machine.rotor.mass * machine.simulation.gravity, 1.0)
    for (block, _), b in zip(spans, of_kind(machine.stations, amb.KIND), strict=True):
        current = machine.simulation.atol * weight / b.current_stiffness
        for axis in ((block,) if b.axial else (block, block + 2 + b.order)):
            atol[axis] = length
            if b.controller is None:
                atol[axis + 1] = length * 1e-2
            else:  # a controller state's error moves the current by |C_j| times it
                gain = np.maximum(np.abs(np.asarray(b.controller[2], float)), 1e-300)
                atol[axis + 1:axis + 1 + b.order] = current / gain
            atol[axis + 1 + b.order] = current


def pack(machine: Machine) -> KernelModel:
    """The machine as :mod:`auxbearing.core.machine` takes it: parameters, initial state, tolerances, energy."""
    r = machine.rotor
    sim = machine.simulation
    g = sim.gravity
    gravity = (0.0, -g, 0.0) if machine.orientation == "horizontal" else (0.0, 0.0, -g)
    planes = machine.planes
    lever = max((abs(p.position) for p in planes), default=0.0)
    rotor = cm.Rotor(
        mass=r.mass, polar_inertia=r.polar_inertia, transverse_inertia=r.transverse_inertia or 1.0,
        unbalance=r.unbalance, unbalance_phase=r.unbalance_phase, couple_unbalance=r.couple_unbalance,
        couple_phase=r.unbalance_phase + r.couple_unbalance_phase, gravity_x=gravity[0], gravity_y=gravity[1],
        gravity_z=gravity[2], force_x=r.side_force_x, force_y=r.side_force_y, force_z=r.axial_force,
        process_torque=machine.coastdown.process_torque, drag_constant=machine.coastdown.drag_torque,
        drag_viscous=machine.coastdown.viscous_drag, drag_windage=machine.coastdown.windage_drag,
        drag_speed_scale=DRAG_SPEED_SCALE,
        tilt_free=machine.tilt_free, axial_free=machine.axial_free)
    ballsets = [ballset_params(p.bearing, p.ball_constant) for p in planes]
    n = plane_blocks(planes)
    while len(ballsets) < n:
        ballsets.append(ballsets[0])
    clearance = np.zeros(n)
    for k, p in enumerate(planes):
        clearance[k] = p.bearing.diametral_clearance
    modes = _modes(machine, n)
    nm = modes.stiffness.shape[0]
    modal = machine.modal()
    stations = tuple(kind.pack(of_kind(machine.stations, kind.KIND), modal, nm, machine) for kind in station_kinds())
    core = cm.Machine(rotor, _plane_arrays(planes), tuple(ballsets), clearance, _limits(machine),
                      *cm.new_scratch(n, nm), *cm.pack_extra(modes, stations))
    layout = cm.layout_of(core)
    y0 = np.zeros(layout.size)
    y0[cm.OMEGA] = r.speed
    y0[cm.X], y0[cm.Y] = r.start_x, r.start_y
    _levitate(machine, modal, layout, y0)
    for k, p in enumerate(planes):
        b = cm.N_ROTOR + k * cm.N_PLANE
        y0[b + cm.OX], y0[b + cm.OY] = p.misalignment
    # error scales: clearance for positions, the speed of a fall through it for velocities
    s = min(p.radial_clearance for p in planes)
    v = max(math.sqrt(2.0 * g * s), 1e-3)
    w = max(abs(r.speed), 1.0)
    length = max(lever, 1e-3)
    rotor_scale = (s, s, s, s / length, s / length, 1.0, v, v, v, v / length, v / length, w)
    free = (True, True, machine.axial_free, machine.tilt_free, machine.tilt_free, True,
            True, True, machine.axial_free, machine.tilt_free, machine.tilt_free, True)
    atol = np.full(layout.size, np.inf)
    for i in range(cm.N_ROTOR):
        if free[i]:
            atol[i] = sim.atol * rotor_scale[i]
    race_v = RACE_VELOCITY_SCALE * v
    for k, p in enumerate(planes):
        b = cm.N_ROTOR + k * cm.N_PLANE
        for i, sc in ((cm.RX, s), (cm.RY, s), (cm.RPSI, 1.0), (cm.RVX, race_v), (cm.RVY, race_v), (cm.ROMEGA, w)):
            atol[b + i] = sim.atol * sc
        if p.catches_axially:
            atol[b + cm.RZ] = sim.atol * s
            atol[b + cm.RVZ] = sim.atol * race_v
        if p.mount is not None:
            for i, sc in ((cm.OX, s), (cm.OY, s), (cm.OVX, v), (cm.OVY, v)):
                atol[b + i] = sim.atol * sc
    if nm:
        # a mode's coordinate is in m sqrt(kg): scaled by its largest displacement at a plane
        reach = np.maximum(np.abs(modes.shape_x).max(axis=0), np.abs(modes.shape_y).max(axis=0))
        reach = np.maximum(reach, 1e-300)
        atol[layout.modes_at:layout.modes_at + nm] = sim.atol * s / reach
        atol[layout.modes_at + nm:layout.modes_at + 2 * nm] = sim.atol * v / reach
    _amb_tolerances(machine, layout, atol, sim.atol * s)
    orbit = _levitated_orbit(machine, core, layout, y0, atol)
    _start_offset(machine, y0)
    settings = ig.Settings(sim.rtol, atol, sim.max_step, 1e-14, 20000, sim.output_step)
    kinetic, potential = cm.energy(y0, core)
    return KernelModel(core, y0, settings, kinetic + potential, layout, modes, stations, orbit)


def _start_offset(machine: Machine, y0: np.ndarray) -> None:
    """Move a levitated start by rotor.start_x / start_y from its levitated place (on its orbit): a disturbance.

    Added after :func:`_levitated_orbit`, whose Jacobian must be the levitated machine's: taken at the offset
    state, where the sensor's state still reads the levitated place, the blower's 50 um start made the PID's
    derivative of the reading k_d w_s 50 um = 12 x 2 pi 5000 x 5e-5 = 18.8 A, past its 5 A limit; a clipped command
    has no gain, and the open-loop magnet's sqrt(2 k_s / m) = +200 1/s read as an unstable levitation. A drop
    from the centre has its start set already (:func:`pack`).
    """
    from auxbearing.machine.stations import amb

    if of_kind(machine.stations, amb.KIND) and machine.active_scenario().levitated:
        y0[cm.X] += machine.rotor.start_x
        y0[cm.Y] += machine.rotor.start_y


def _levitated_orbit(machine: Machine, core: cm.Machine, layout: cm.Layout, y0: np.ndarray,
                     atol: np.ndarray) -> tuple | None:
    """Put a levitated, spinning start on its steady unbalance orbit (:mod:`auxbearing.machine.levitation`)."""
    from auxbearing.machine.levitation import orbit_states, steady_orbit

    if not of_kind(machine.stations, "amb") or not machine.active_scenario().levitated:
        return None
    axial = any(b.axial for b in of_kind(machine.stations, "amb")) and machine.axial_free
    states = orbit_states(layout, machine.tilt_free, axial)
    amplitudes, least = steady_orbit(core, y0, states, atol[states] / machine.simulation.atol)
    if amplitudes is not None:  # an unstable levitation has no steady orbit: the run starts from the statics
        y0[states] += amplitudes.real
    return states, amplitudes, least
