"""Right-hand side of a machine touchdown: rigid rotor, any number of touchdown planes, races, mounts.

The source paper's drop (Sec. II.D, Eq. 17-26, read as docs/paper_notes.md items 1-9) is the
planar special case: one plane at the mass centre with tilt and axial motion locked. Everything is
SI; the packing of user inputs into the NamedTuples below happens in :mod:`auxbearing.machine.model`.

Rotor (a rigid body, small tilts; Friswell, Penny, Garvey & Lees, *Dynamics of Rotating Machines*,
2010, Sec. 3.5, Eq. 3.63-3.66 for the gyroscopic rigid rotor). Generalised coordinates are the
mass centre G, the tilts theta_p of the principal axis and the spin angle phi; the state holds the
*geometric* axis instead (its centre O in the mass-centre plane and its tilts theta_g), which is what
touches the bearings:

* static unbalance e at phase phi_e: G = O + e u(phi + phi_e), u(b) = (cos b, sin b);
* couple unbalance chi at phase phi_c: theta_p = theta_g + chi w(phi + phi_c), w(b) = (-sin b, cos b), so
  the principal axis leans towards u(phi + phi_c) at +z;
* m G'' = F,   J_t theta_px'' + J_p Omega theta_py' = M_x,   J_t theta_py'' - J_p Omega theta_px' = M_y,
  J_p Omega' = Q_phi (angular momentum about G, linear in the tilts; the gyroscopic terms do no work);
* a point of the journal at axial position a from G with lateral offset rho from the axis has
  P = O + a (theta_gy, -theta_gx) + rho (rho turning with phi), P_z = G_z + a + theta_px rho_y -
  theta_py rho_x. Its velocity is dP/dq q' and a force F there contributes F . dP/dq to the
  generalised forces (:func:`_apply_rotor`), so the power of every contact force equals its work
  on the coordinates and the energy audit closes to the integration error.

Touchdown plane k: the journal/race line contact (Eq. 17, 19-21 with paper_notes items 2-3: normal from
the centre offset, friction against the slip, regularised as tanh(|v| / v_eps) along the slip, which
here also has an axial part), the inner race (x, y, axial z when the plane catches axially, spin) on
THE ball-set model (:func:`auxbearing.core.ballset.accumulate`, Eq. 22 read as paper_notes item 4, with the
race tilt neglected: its tilt stiffness through the balls dwarfs the moment a line contact passes),
isotropic ball-set damping (Eq. 23), rolling resistance (Eq. 24 as paper_notes item 1 corrects it: a
tangential force mu_2 |F_e| at the inner raceway of the loaded zone), an outer ring that is either
fixed at the bearing centre or carried by a mount (stiffness with an optional dead band, damping, a
hard stop), and an optional axial face contact of a rotor collar on the race face (linear stiffness
and damping; friction against the local slip averaged over the face's mean circle, which turns an
axial load into a torque and a lateral force on the rotor: Wilkes et al., GT2013-94594).

Elastic rotor (:mod:`auxbearing.machine.structure`): a rotor given by its matrices is this rigid body plus its
free-free elastic modes, mass-normalised (:class:`Modes`, none for a rigid rotor). Each mode's coordinate eta_j
obeys eta_j'' + sum_l (D_jl + Omega Gm_jl) eta_l' - Omega (gt_xj theta_px' + gt_yj theta_py') + omega_j^2 eta_j
= sum_k phi_j(a_k) . F_k, the forces F_k at the stations projected on the mode's shape there; the rigid tilts
take the coupling -Omega gt eta' (the skew gyroscopic matrix of the whole structure, which does no work). The
modes are M-orthogonal to the rigid motions, so gravity, the unbalance of the rigid body and the process
forces (spread like the mass) do not load them; each station's journal moves by the modes' shapes there.

State layout (:func:`layout`, generated from the planes, modes and stations): the rotor's :data:`ROTOR_STATES`,
one block of :data:`PLANE_STATES` per plane, the modes' coordinates then their rates, each station kind's
STATES per station (:data:`STATION_KINDS`), then the bookkeeping integrals of work and heat that the energy
audit uses (:data:`LEDGER`, :data:`PLANE_LEDGER` per plane, the heat of the structure's damping when it has
modes, each station kind's LEDGER per station); these carry ``atol = inf`` so they never steer the step.
The kernels read the plane count from the packed planes' tuples (a compile-time constant: numba compiles one
specialisation per count, and :data:`MIN_PLANES` pads the common machines to one); modes and stations are
arrays, so any number of them shares one compiled kernel.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np
from numba import njit

from auxbearing.core import amb, linear_support, load
from auxbearing.core.ballset import accumulate
from auxbearing.core.bearing_friction import palmgren_viscous_torque
from auxbearing.core.uncounted import uncounted

#: Plane blocks a packed machine has at least: machines of one and two planes share one compiled kernel.
MIN_PLANES = 2
ROTOR_STATES = ("x", "y", "z", "tilt_x", "tilt_y", "spin_angle",
                "vx", "vy", "vz", "tilt_rate_x", "tilt_rate_y", "spin_speed")
PLANE_STATES = ("race_x", "race_y", "race_z", "race_angle", "race_vx", "race_vy", "race_vz", "race_speed",
                "ring_x", "ring_y", "ring_vx", "ring_vy")
#: Bookkeeping integrals [J]: work of process forces and torque, drag loss, energy stored in the ball sets;
#: then per plane the heat made at the journal/race and face contacts, inside the bearing (ball damping,
#: rolling resistance) and in the mount damper.
LEDGER = ("work_in", "drag_loss", "ballset_work")
PLANE_LEDGER = ("heat_contact", "heat_bearing", "heat_mount")
N_ROTOR = len(ROTOR_STATES)
N_PLANE = len(PLANE_STATES)

X, Y, Z, TX, TY, PHI, VX, VY, VZ, WX, WY, OMEGA = range(N_ROTOR)
RX, RY, RZ, RPSI, RVX, RVY, RVZ, ROMEGA, OX, OY, OVX, OVY = range(N_PLANE)
#: Offsets inside the ledger (:func:`ledger_at`); plane k's heat from ``L_HEAT + 3 k`` (contact, bearing, mount).
L_WORK_IN, L_DRAG_LOSS, L_BALLSET_WORK, L_HEAT = range(4)


@njit(cache=True, inline="always")
def ledger_at(n_planes, n_modes, n_station_states=0):
    """Index of the ledger in the state of a machine: its plane blocks, modes and stations' states."""
    return N_ROTOR + n_planes * N_PLANE + 2 * n_modes + n_station_states


#: Where each part of the modes' and stations' data starts in :attr:`Machine.extra` (:attr:`Machine.extra_at`),
#: after five counts: modes, linear supports, magnetic bearings, loads, the bearings' states. One flat array rather
#: than a struct of
#: arrays: every array a :class:`Machine` holds costs a reference-count update wherever it is passed.
EXTRA_FIELDS = ("modes", "supports", "bearings", "loads", "bearing_states", "stiffness", "damping", "gyroscopic",
                "tilt_gyroscopic", "shape_x", "shape_y", "unbalance_re", "unbalance_im", "support_values",
                "support_shape_x", "support_shape_y", "bearing_values", "bearing_shape_x", "bearing_shape_y",
                "bearing_sensor_x", "bearing_sensor_y", "bearing_controllers", "load_values", "load_shape_x",
                "load_shape_y")
(E_NM, E_NSUP, E_NAMB, E_NLOAD, E_NAMB_STATES, E_STIFF, E_DAMP, E_GYRO, E_TILT, E_SX, E_SY, E_URE, E_UIM, E_SUP,
 E_SUP_SX, E_SUP_SY, E_AMB, E_AMB_SX, E_AMB_SY, E_AMB_SSX, E_AMB_SSY, E_AMB_CTRL, E_LOAD, E_LOAD_SX,
 E_LOAD_SY) = range(len(EXTRA_FIELDS))


@njit(cache=True, inline="always")
def mode_count(m):
    """Elastic modes of the packed machine."""
    return m.extra_at[E_NM]


@njit(cache=True, inline="always")
def station_states_at(m):
    """First state of the stations' block (after the modes)."""
    return N_ROTOR + len(m.planes.active) * N_PLANE + 2 * m.extra_at[E_NM]


@njit(cache=True, inline="always")
def station_state_count(m):
    """States of every station of every kind (each kind's STATES per station, in :data:`STATION_KINDS` order)."""
    return m.extra_at[E_NAMB_STATES]


@njit(cache=True, inline="always")
def ledger_of(m):
    """Index of the ledger in the state of the packed machine ``m``."""
    return ledger_at(len(m.planes.active), m.extra_at[E_NM], station_state_count(m))


class Layout(NamedTuple):
    """Where each quantity sits in the state vector of a machine with ``planes`` plane blocks (:func:`layout`)."""

    planes: int
    size: int
    ledger_at: int
    work_in: int
    drag_loss: int
    ballset_work: int
    heat_at: int  #: + 3 k + (0 contact, 1 bearing, 2 mount)
    names: tuple  #: every state's name, in order
    modes: int = 0  #: elastic modes of the rotor
    modes_at: int = 0  #: first mode coordinate; their rates follow them
    structure_loss: int = -1  #: heat of the structure's damping (-1: a rigid rotor)
    stations: tuple = ()  #: stations of each kind of :data:`STATION_KINDS` beside the planes
    stations_at: int = 0  #: first ledger slot of those stations (each kind's LEDGER per station, kind by kind)
    station_states_at: tuple = ()  #: first state of each kind's block (each kind's STATES per station)
    station_spans: tuple = ()  #: per kind, each station's (first state, state count)

    def plane(self, k: int) -> int:
        """First index of plane k's block."""
        return N_ROTOR + k * N_PLANE

    def heat(self, k: int, source: int) -> int:
        """Index of plane k's heat from ``source`` (0 contact, 1 bearing, 2 mount)."""
        return self.heat_at + 3 * k + source


def layout(n_planes: int, n_modes: int = 0, stations: tuple = (), station_names: tuple = ()) -> Layout:
    """The state layout of a machine: plane blocks, elastic modes, stations of each kind (module docstring).

    ``station_names``: per kind, each station's state names when they are not the kind's STATES (a magnetic
    bearing with a state-space controller of its own order).
    """
    counts = tuple(stations) + (0,) * (len(STATION_KINDS) - len(stations))
    modal = (*(f"mode_{j}" for j in range(n_modes)), *(f"mode_rate_{j}" for j in range(n_modes)))
    names = (*ROTOR_STATES, *(f"{name}_{k}" for k in range(n_planes) for name in PLANE_STATES), *modal)
    state_blocks, spans = [], []
    for k, (kind, count) in enumerate(zip(STATION_KINDS, counts, strict=True)):
        state_blocks.append(len(names))
        own = station_names[k] if k < len(station_names) and station_names[k] else (kind.STATES,) * count
        kind_spans = []
        for i in range(count):
            kind_spans.append((len(names), len(own[i])))
            names += tuple(f"{name}_{i}" for name in own[i])
        spans.append(tuple(kind_spans))
    at = len(names)
    names += (*LEDGER, *(f"{name}_{k}" for k in range(n_planes) for name in PLANE_LEDGER),
              *(("structure_loss",) if n_modes else ()))
    stations_at = len(names)
    for kind, count in zip(STATION_KINDS, counts, strict=True):
        names += tuple(f"{name}_{i}" for i in range(count) for name in kind.LEDGER)
    return Layout(n_planes, len(names), at, at + L_WORK_IN, at + L_DRAG_LOSS, at + L_BALLSET_WORK, at + L_HEAT, names,
                  n_modes, N_ROTOR + n_planes * N_PLANE, stations_at - 1 if n_modes else -1, counts, stations_at,
                  tuple(state_blocks), tuple(spans))


def layout_of(m) -> Layout:
    """The state layout of a packed :class:`Machine`."""
    e = m.extra_at
    rows = m.extra[e[E_AMB]:e[E_AMB_SX]].reshape(e[E_NAMB], len(amb.FIELDS))
    bearings = tuple(amb.state_names(int(row[amb.P_ORDER]), row[amb.P_CONTROLLER_AT] < 0, row[amb.P_AXIAL] > 0.0)
                     for row in rows)
    return layout(len(m.planes.active), e[E_NM], (e[E_NSUP], e[E_NAMB], e[E_NLOAD]), ((), bearings, ()))

#: Points on the face's mean circle over which face friction is averaged (a regular polygon of 8
#: integrates the first harmonics of the slip field exactly).
FACE_POINTS = 8
#: Their directions (cos, sin of 2 pi i / FACE_POINTS), constants of the compiled code rather than libm calls at
#: every evaluation (a collar that carries a thrust touches its race face all the time).
FACE_COS = tuple(math.cos(2.0 * math.pi * i / FACE_POINTS) for i in range(FACE_POINTS))
FACE_SIN = tuple(math.sin(2.0 * math.pi * i / FACE_POINTS) for i in range(FACE_POINTS))
#: Per-plane quantities of :func:`plane_forces` (diagnostics for the observer and the outputs).
DIAG_FIELDS = ("penetration", "normal_force", "friction_force", "slip_velocity", "ball_force_x", "ball_force_y",
               "ball_force_axial", "max_ball_load", "axial_force", "axial_penetration", "mount_deflection",
               "face_torque")
(D_PEN, D_FN, D_FT, D_SLIP, D_BFX, D_BFY, D_BFZ, D_QMAX, D_FA, D_APEN, D_MOUNT, D_FACE_T) = range(len(DIAG_FIELDS))


class Rotor(NamedTuple):
    """Rotor parameters (SI)."""

    mass: float  #: m [kg]
    polar_inertia: float  #: J_p about the spin axis through G [kg m^2]
    transverse_inertia: float  #: J_t about a transverse axis through G [kg m^2]
    unbalance: float  #: e [m]
    unbalance_phase: float  #: phi_e [rad]
    couple_unbalance: float  #: chi [rad]
    couple_phase: float  #: phi_c [rad]
    gravity_x: float  #: gravitational acceleration components [m/s^2]
    gravity_y: float
    gravity_z: float
    force_x: float  #: constant process force at G [N]
    force_y: float
    force_z: float
    process_torque: float  #: constant spin torque on the rotor [N m]
    drag_constant: float  #: T0 of T = T0 + c1 Omega + c2 Omega^2 [N m]
    drag_viscous: float  #: c1 [N m s]
    drag_windage: float  #: c2 [N m s^2]
    drag_speed_scale: float  #: speed below which T0 is regularised as tanh(Omega / scale) [rad/s]
    tilt_free: bool  #: False locks the tilts (planar rotor)
    axial_free: bool  #: False locks G_z


class Planes(NamedTuple):
    """Touchdown-plane parameters, each a tuple of one float per plane block (SI).

    Tuples, not arrays: compiled code passes them by value, while each array of a struct costs a
    reference-count update wherever the struct is used (34 of them made half the right-hand side).
    """

    active: tuple  #: 1.0 for a plane in use
    position: tuple  #: axial position a of the plane from G [m]
    clearance: tuple  #: radial clearance s between journal and race bore [m]
    journal_radius: tuple  #: r [m]
    line_stiffness: tuple  #: K_l [N/m^(10/9)] (Eq. 19)
    line_damping: tuple  #: C_l [N s/m]
    sliding_friction: tuple  #: mu_1 [-]
    rolling_friction: tuple  #: mu_2 [-] (Eq. 24)
    slip_velocity: tuple  #: v_eps of the friction regularisation [m/s]
    race_mass: tuple  #: [kg]
    race_inertia: tuple  #: polar [kg m^2]
    raceway_radius: tuple  #: inner raceway radius R_i, where the balls touch the race [m]
    ball_damping: tuple  #: C_b [N s/m] (Eq. 23), on the race velocity relative to the ring
    race_axial_free: tuple  #: 1.0 when the race moves axially (the plane catches axially)
    ring_free: tuple  #: 1.0 when the outer ring sits in a compliant mount
    ring_mass: tuple  #: mass moving with the outer ring in the mount [kg]
    mount_stiffness: tuple  #: [N/m]
    mount_damping: tuple  #: [N s/m]
    mount_deadband: tuple  #: radial travel before the mount spring engages [m]
    stop_gap: tuple  #: radial travel to the hard stop [m] (inf: none)
    stop_stiffness: tuple  #: [N/m]
    stop_damping: tuple  #: [N s/m]
    centre_x: tuple  #: bearing centre (misalignment) [m]
    centre_y: tuple
    axial_clearance: tuple  #: collar-to-race-face clearance [m] (inf: no axial touchdown)
    face_plus: tuple  #: 1.0 when the rotor can push the race towards +z
    face_minus: tuple  #: 1.0 when the rotor can push the race towards -z
    face_stiffness: tuple  #: [N/m]
    face_damping: tuple  #: [N s/m]
    face_friction: tuple  #: [-]
    face_radius: tuple  #: mean radius of the contact annulus on the race face [m]
    pitch_diameter: tuple  #: d_m of the bearing [m]
    lubricant_viscosity: tuple  #: kinematic viscosity of the bearing's oil [m^2/s]
    viscous_factor: tuple  #: Palmgren's f_0 of the bearing's load-free torque [-] (0: none)
    rows: tuple  #: 1.0 for a single bearing, 2.0 for a matched pair (two identical rows on one race)
    facing_a: tuple  #: s of the pair's first row: +1 carries the race's axial load along +z, -1 along -z
    facing_b: tuple  #: s of the second row
    row_push: tuple  #: axial displacement of each row into its balls in the clamped, unloaded pair [m]


class Modes(NamedTuple):
    """The rotor's elastic free-free modes, mass-normalised (:func:`auxbearing.machine.structure.modal_rotor`).

    Arrays with ``n`` modes (``n = 0`` for a rigid rotor: every loop over them is empty).
    """

    stiffness: np.ndarray  #: (n,) omega_j^2 [1/s^2]
    damping: np.ndarray  #: (n, n) D = Phi^T C Phi + diag(2 zeta omega) [1/s]
    gyroscopic: np.ndarray  #: (n, n) Gm = Phi^T G Phi, times the spin speed [-]
    tilt_gyroscopic: np.ndarray  #: (2, n) gt: the rigid tilts' gyroscopic coupling to the modes [sqrt(kg) m]
    shape_x: np.ndarray  #: (plane blocks, n) each mode's x displacement at each plane [1/sqrt(kg)]
    shape_y: np.ndarray  #: (plane blocks, n) and its y displacement
    #: (n,) P_j = sum_i (phi_x - i phi_y)_ij U_i e^(i beta_i) of the unbalance planes, real and imaginary parts:
    #: the modal force of the unbalance is Re(P_j e^(i phi) (Omega^2 - i Omega')) [sqrt(kg) m]
    unbalance_re: np.ndarray
    unbalance_im: np.ndarray


def pack_extra(modes: Modes, stations: tuple) -> tuple[np.ndarray, tuple]:
    """(extra, extra_at) of a :class:`Machine`: the modes and each kind's parameters, flat (:data:`EXTRA_FIELDS`)."""
    supports, bearings, loads = stations
    parts = (modes.stiffness, modes.damping, modes.gyroscopic, modes.tilt_gyroscopic, modes.shape_x, modes.shape_y,
             modes.unbalance_re, modes.unbalance_im, supports.values, supports.shape_x, supports.shape_y,
             bearings.values, bearings.shape_x, bearings.shape_y, bearings.sensor_shape_x, bearings.sensor_shape_y,
             bearings.controllers, loads.values, loads.shape_x, loads.shape_y)
    offsets, at = [], 0
    for part in parts:
        offsets.append(at)
        at += np.asarray(part).size
    extra = np.concatenate([np.ascontiguousarray(part, float).ravel() for part in parts]) if at else np.zeros(0)
    counts = (modes.stiffness.shape[0], supports.values.shape[0], bearings.values.shape[0], loads.values.shape[0],
              bearings.state_count)
    return extra, tuple(int(v) for v in (*counts, *offsets))


def rigid_modes(n_planes: int) -> Modes:
    """No elastic mode: the rigid rotor."""
    return Modes(np.zeros(0), np.zeros((0, 0)), np.zeros((0, 0)), np.zeros((2, 0)), np.zeros((n_planes, 0)),
                 np.zeros((n_planes, 0)), np.zeros(0), np.zeros(0))


class Limits(NamedTuple):
    """Range limits of the model (:mod:`auxbearing.core.watch` stops a run that crosses one), SI; (2,) are tuples."""

    journal_force: tuple  #: (2,) journal/race contact force whose peak pressure reaches the material's limit [N]
    ball_stress: float  #: largest Hertz stress the elastic ball contact may mean [Pa]
    shoulder_angle_inner: tuple  #: (2,) groove arc from the bottom to the shoulder [rad]
    shoulder_angle_outer: tuple  #: (2,)
    groove_radius_inner: tuple  #: (2,) f_i D [m]
    groove_radius_outer: tuple  #: (2,)
    mount_travel: tuple  #: (2,) largest radial travel of the outer ring [m]
    race_axial_travel: tuple  #: (2,) largest axial travel of the race [m]
    energy_tolerance: float  #: energy gain, relative to the energy brought in, that counts as a run-away


class Machine(NamedTuple):
    """Everything :func:`rhs` and the observer need.

    ``scratch`` and ``last_diag`` are working memory: the right-hand side runs some 10^5 times a
    drop, and allocating its small arrays each time cost a fifth of it. They make a Machine a
    single-threaded object: give each thread its own (:func:`new_scratch`).
    """

    rotor: Rotor
    planes: Planes
    ballsets: tuple  #: one :class:`auxbearing.core.ballset.BallSet` per plane (a copy of plane 0 when inactive)
    ballset_clearance: np.ndarray  #: diametral clearance of each plane's bearing [m]
    limits: Limits
    scratch: np.ndarray  #: (:data:`SCRATCH`,) generalised forces, ball-set displacement and resultant
    jac_stub: np.ndarray  #: (1, 1): the Jacobian argument of the ball-set kernel, unused here
    last_diag: np.ndarray  #: (planes, len(DIAG_FIELDS)): each plane's diagnostics at the last rhs call
    extra: np.ndarray  #: the modes' and stations' data, flat (:func:`pack_extra`, :data:`EXTRA_FIELDS`)
    extra_at: tuple  #: counts and offsets into ``extra`` (ints, :data:`EXTRA_FIELDS`)


#: The station kinds beside the touchdown planes, in the order of their states and ledger slots. A kind is a
#: module like :mod:`auxbearing.core.linear_support` (NAME, FIELDS, STATES, LEDGER, Params, force, energy),
#: registered here and called in :func:`_stations` and :func:`energy`; its machine-file table, description and
#: packing are one module of :mod:`auxbearing.machine.stations`.
STATION_KINDS = (linear_support, amb, load)


#: Working memory of :func:`rhs`: generalised forces (6), ball-set displacement (5) and resultant (5), the
#: base's d'Alembert field (2, :func:`frame_field`), then the modal forces (one per mode).
_Q, _DISP, _FORCE, _BASE, _QM = 0, 6, 11, 16, 18
SCRATCH = 18


def new_scratch(n_planes: int, n_modes: int = 0) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Fresh (scratch, jac_stub, last_diag) for a :class:`Machine` of ``n_planes`` plane blocks and ``n_modes``."""
    return np.zeros(SCRATCH + n_modes), np.zeros((1, 1)), np.zeros((n_planes, len(DIAG_FIELDS)))


# ----------------------------------------------------------------------------- rotor kinematics
@njit(cache=True, inline="always")
def rotor_kinematics(y, rotor):
    """(e u', chi w', theta_p, theta_p') at the state: what maps coordinates to points (module docstring).

    Returns a tuple: eu'_x, eu'_y, chi w_x, chi w_y, chi w'_x, chi w'_y, theta_px, theta_py,
    theta_px', theta_py' [m, rad, rad/s].
    """
    be = y[PHI] + rotor.unbalance_phase
    bc = y[PHI] + rotor.couple_phase
    e = rotor.unbalance
    chi = rotor.couple_unbalance
    eux, euy = -e * math.sin(be), e * math.cos(be)  # e u'
    cwx, cwy = -chi * math.sin(bc), chi * math.cos(bc)  # chi w
    cwpx, cwpy = -chi * math.cos(bc), -chi * math.sin(bc)  # chi w'
    om = y[OMEGA]
    return (eux, euy, cwx, cwy, cwpx, cwpy, y[TX] + cwx, y[TY] + cwy, y[WX] + cwpx * om, y[WY] + cwpy * om)


@njit(cache=True, inline="always")
def _point_velocity(y, kin, a, rho_x, rho_y):
    """Velocity of the rotor's material point at axial station a, lateral offset rho from the axis."""
    om = y[OMEGA]
    vx = y[VX] + a * y[WY] - om * rho_y
    vy = y[VY] - a * y[WX] + om * rho_x
    # d/dt of theta_px rho_y - theta_py rho_x with rho turning at Omega
    vz = y[VZ] + kin[8] * rho_y - kin[9] * rho_x + om * (kin[6] * rho_x + kin[7] * rho_y)
    return vx, vy, vz


@njit(cache=True, inline="always")
def _apply_rotor(q, kin, a, rho_x, rho_y, fx, fy, fz):
    """Add F . dP/dq of a force F at the point (a, rho) to the generalised forces q = (G, theta_p, phi)."""
    q[0] += fx
    q[1] += fy
    q[2] += fz
    q[3] += -a * fy + rho_y * fz
    q[4] += a * fx - rho_x * fz
    q[5] += (fx * (-kin[0] - a * kin[5] - rho_y) + fy * (-kin[1] + a * kin[4] + rho_x)
             + fz * (kin[6] * rho_x + kin[7] * rho_y))


@njit(cache=True, inline="always")
def journal_point(y, m, k):
    """Plane k's journal axis point (x, y) and the velocity the elastic modes add there (x, y) [m, m/s]."""
    a = m.planes.position[k]
    jx = y[X] + a * y[TY]
    jy = y[Y] - a * y[TX]
    evx = 0.0
    evy = 0.0
    nm = m.extra_at[E_NM]
    if nm > 0:
        at = N_ROTOR + len(m.planes.active) * N_PLANE
        ox = m.extra_at[E_SX] + k * nm
        oy = m.extra_at[E_SY] + k * nm
        for j in range(nm):
            jx += m.extra[ox + j] * y[at + j]
            jy += m.extra[oy + j] * y[at + j]
            evx += m.extra[ox + j] * y[at + nm + j]
            evy += m.extra[oy + j] * y[at + nm + j]
    return jx, jy, evx, evy


@njit(cache=True, inline="always")
def _apply_modes(m, k, fx, fy):
    """Add a lateral force at plane k to the modal forces (its projection on each mode's shape there)."""
    nm = m.extra_at[E_NM]
    _apply_shapes(m, m.extra_at[E_SX] + k * nm, m.extra_at[E_SY] + k * nm, fx, fy)


@njit(cache=True, inline="always")
def _apply_shapes(m, ox, oy, fx, fy):
    """Add a lateral force to the modal forces through the shapes stored at ``ox``, ``oy`` of ``m.extra``."""
    for j in range(m.extra_at[E_NM]):
        m.scratch[_QM + j] += m.extra[ox + j] * fx + m.extra[oy + j] * fy


@njit(cache=True, inline="always")
def station_point(y, m, a, ox, oy):
    """The rotor axis at axial position a, bent by the shapes at ``ox``, ``oy`` of ``m.extra`` [m, m/s].

    Returns x, y and their velocities.
    """
    jx = y[X] + a * y[TY]
    jy = y[Y] - a * y[TX]
    vx = y[VX] + a * y[WY]
    vy = y[VY] - a * y[WX]
    nm = m.extra_at[E_NM]
    at = N_ROTOR + len(m.planes.active) * N_PLANE
    for j in range(nm):
        jx += m.extra[ox + j] * y[at + j]
        jy += m.extra[oy + j] * y[at + j]
        vx += m.extra[ox + j] * y[at + nm + j]
        vy += m.extra[oy + j] * y[at + nm + j]
    return jx, jy, vx, vy


@njit(cache=True, inline="always")
def stations_ledger(m):
    """First ledger slot of the stations beside the planes (after the planes' heats and the structure's loss)."""
    return ledger_of(m) + L_HEAT + 3 * len(m.planes.active) + (1 if m.extra_at[E_NM] > 0 else 0)


@uncounted
def _stations(t, y, m, kin, q, out):
    """Forces of every station beside the touchdown planes on the rotor, and their ledger rates.

    Called, not inlined: a machine without such stations runs only the empty loops.
    """
    at = stations_ledger(m)
    e, nm = m.extra_at, m.extra_at[E_NM]
    width = len(linear_support.FIELDS)
    for i in range(e[E_NSUP]):
        row = m.extra[e[E_SUP] + i * width:e[E_SUP] + (i + 1) * width]
        ox, oy = e[E_SUP_SX] + i * nm, e[E_SUP_SY] + i * nm
        jx, jy, vx, vy = station_point(y, m, row[0], ox, oy)
        fx, fy, taken = linear_support.force(row, jx, jy, vx, vy)
        _apply_rotor(q, kin, row[0], 0.0, 0.0, fx, fy, 0.0)
        _apply_shapes(m, ox, oy, fx, fy)
        out[at + i] = taken
    at += e[E_NSUP] * len(linear_support.LEDGER)
    states = station_states_at(m)
    width = len(amb.FIELDS)
    for i in range(e[E_NAMB]):
        row = m.extra[e[E_AMB] + i * width:e[E_AMB] + (i + 1) * width]
        b = states + int(row[amb.P_STATES_AT])
        controllers = m.extra[e[E_AMB_CTRL]:e[E_LOAD]]
        # a bearing that has failed for good and whose field is gone neither pushes nor changes: skipped (the
        # shipped machines' bearings fail at the drop with no decay time, so every drop and coast-down but a
        # scenario's runs without them)
        if amb.dead(row, t, row[amb.P_FAIL_X]) and (row[amb.P_AXIAL] > 0.0 or amb.dead(row, t, row[amb.P_FAIL_Y])):
            continue
        if row[amb.P_AXIAL] > 0.0:
            fz = amb.axis(row, t, row[amb.P_FAIL_X], row[amb.P_SENSOR_FAIL_X], y[Z], y[Z], y, out, b, controllers)
            _apply_rotor(q, kin, row[amb.P_POS], 0.0, 0.0, 0.0, 0.0, fz)
            out[at + i] = -fz * y[VZ]
            continue
        ox, oy = e[E_AMB_SX] + i * nm, e[E_AMB_SY] + i * nm
        jx, jy, vx, vy = station_point(y, m, row[amb.P_POS], ox, oy)
        sx, sy, _, _ = station_point(y, m, row[amb.P_SENSOR], e[E_AMB_SSX] + i * nm, e[E_AMB_SSY] + i * nm)
        fx = amb.axis(row, t, row[amb.P_FAIL_X], row[amb.P_SENSOR_FAIL_X], jx, sx, y, out, b, controllers)
        fy = amb.axis(row, t, row[amb.P_FAIL_Y], row[amb.P_SENSOR_FAIL_Y], jy, sy, y, out,
                      b + 2 + int(row[amb.P_ORDER]), controllers)
        _apply_rotor(q, kin, row[amb.P_POS], 0.0, 0.0, fx, fy, 0.0)
        _apply_shapes(m, ox, oy, fx, fy)
        out[at + i] = -(fx * vx + fy * vy)
    at += e[E_NAMB] * len(amb.LEDGER)
    width = len(load.FIELDS)
    bx, by = m.scratch[_BASE], m.scratch[_BASE + 1]
    for i in range(e[E_NLOAD]):
        row = m.extra[e[E_LOAD] + i * width:e[E_LOAD] + (i + 1) * width]
        if row[load.P_KIND] == load.K_BASE:
            if bx != 0.0 or by != 0.0:
                out[at + i] = -_field_power(y, m, kin, row, t)
            continue
        ox, oy = e[E_LOAD_SX] + i * nm, e[E_LOAD_SY] + i * nm
        fx, fy = load.force(row, t, y[PHI], y[OMEGA])
        if fx == 0.0 and fy == 0.0:
            continue
        jx, jy, vx, vy = station_point(y, m, row[load.P_POS], ox, oy)
        _apply_rotor(q, kin, row[load.P_POS], 0.0, 0.0, fx, fy, 0.0)
        _apply_shapes(m, ox, oy, fx, fy)
        out[at + i] = -(fx * vx + fy * vy)


@njit(cache=True, inline="always")
def frame_field(t, m):
    """The base's d'Alembert field at t into the scratch (:mod:`auxbearing.core.load`): it joins gravity."""
    bx, by = 0.0, 0.0
    e = m.extra_at
    width = len(load.FIELDS)
    for i in range(e[E_NLOAD]):
        fx, fy = load.base_field(m.extra[e[E_LOAD] + i * width:e[E_LOAD] + (i + 1) * width], t)
        bx += fx
        by += fy
    m.scratch[_BASE], m.scratch[_BASE + 1] = bx, by


@njit(cache=True, inline="always")
def _field_power(y, m, kin, row, t):
    """Power of one base-acceleration row's field on every body: rotor, races, free outer rings [W]."""
    fx, fy = load.base_field(row, t)
    om = y[OMEGA]
    px = m.rotor.mass * (y[VX] + kin[0] * om)
    py = m.rotor.mass * (y[VY] + kin[1] * om)
    p = m.planes
    for k in range(len(p.active)):
        if p.active[k] <= 0.0:
            continue
        b = N_ROTOR + k * N_PLANE
        px += p.race_mass[k] * y[b + RVX]
        py += p.race_mass[k] * y[b + RVY]
        if p.ring_free[k] > 0.0:
            px += p.ring_mass[k] * y[b + OVX]
            py += p.ring_mass[k] * y[b + OVY]
    return fx * px + fy * py


@njit(cache=True, inline="always")
def _friction(mu_fn, vx, vy, vz, v_eps):
    """Regularised Coulomb friction against a slip vector: -mu F_n tanh(|v|/v_eps) v/|v| (paper_notes item 3)."""
    speed = math.sqrt(vx * vx + vy * vy + vz * vz)
    if speed == 0.0 or mu_fn == 0.0:
        return 0.0, 0.0, 0.0
    scale = -mu_fn * math.tanh(speed / v_eps) / speed
    return scale * vx, scale * vy, scale * vz


# ----------------------------------------------------------------------------- one plane
@njit(cache=True, inline="always")
def row_displacement(m, k, j, dz, dx, dy):
    """Race displacement (axial, x, y) relative to the ring in the own coordinates of row j of plane k.

    A matched pair (:mod:`auxbearing.bearings.duplex`: row maps M_k with the race tilt neglected, so the rows'
    axial offsets from the set's centre drop out) turns a row that faces -z end for end, (dz, dx, dy) ->
    (-dz, dx, -dy), and pushes each row its share of the preload into its balls. A single bearing is its own
    row 0.
    """
    p = m.planes
    if p.rows[k] <= 1.0:
        return dz, dx, dy
    s = p.facing_a[k] if j == 0 else p.facing_b[k]
    return s * dz + p.row_push[k], dx, s * dy


@uncounted
def _pair_reaction(k, dz, dx, dy, m, disp, force):
    """Axial and radial force of both rows of a matched pair on the race [N], and their largest ball load.

    Called, not inlined: the ball-set kernel inlined twice more into every right-hand side made each cold
    compile longer for the single bearings that never take this branch.

    Each row on the one ball-set kernel at its own displacement (:func:`row_displacement`); its force comes back
    through the same map (M_k^T f_k), as the pair's statics do
    (:func:`auxbearing.bearings.duplex_statics.set_reaction`).
    """
    p = m.planes
    fa = fx = fy = 0.0
    qmax = 0.0
    for j in range(2):
        s = p.facing_a[k] if j == 0 else p.facing_b[k]
        for i in range(5):
            disp[i] = 0.0
            force[i] = 0.0
        disp[0], disp[1], disp[2] = row_displacement(m, k, j, dz, dx, dy)
        q, _ = accumulate(disp, m.ballsets[k], m.ballset_clearance[k], force, m.jac_stub, False, False)
        fa += s * force[0]
        fx += force[1]
        fy += s * force[2]
        qmax = max(qmax, q)
    return fa, fx, fy, qmax


@njit(cache=True, inline="always")
def journal_gap(jx, jy, rx, ry, s):
    """Journal centre less race centre (dx, dy), their distance and its excess over the clearance s [m]."""
    dx = jx - rx
    dy = jy - ry
    dist = math.sqrt(dx * dx + dy * dy)
    return dx, dy, dist, dist - s


@njit(cache=True, inline="always")
def ring_travel(ox, oy, p, k):
    """Outer ring of plane k off its mount's centre (x, y) and its distance from it [m]."""
    ux, uy = ox - p.centre_x[k], oy - p.centre_y[k]
    return ux, uy, math.sqrt(ux * ux + uy * uy)


@njit(cache=True, inline="always")
def plane_forces(k, y, m, kin, q, out, diag):
    """Forces of touchdown plane k (module docstring).

    Adds to the rotor's generalised forces ``q``, writes the plane's derivatives and heat rates into
    ``out`` and the plane's :data:`DIAG_FIELDS` into ``diag``.
    """
    p = m.planes
    b = N_ROTOR + k * N_PLANE
    heat = ledger_of(m) + L_HEAT + 3 * k
    a = p.position[k]
    r = p.journal_radius[k]
    s = p.clearance[k]
    veps = p.slip_velocity[k]
    # journal axis point, with the velocity the elastic modes add to every point of the journal's section
    jx, jy, evx, evy = journal_point(y, m, k)
    rx, ry, rz = y[b + RX], y[b + RY], y[b + RZ]
    rvx, rvy, rvz, rw = y[b + RVX], y[b + RVY], y[b + RVZ], y[b + ROMEGA]
    fx_r = 0.0  # forces and torque ON the race
    fy_r = 0.0
    fz_r = 0.0
    t_r = 0.0
    for i in range(len(DIAG_FIELDS)):
        diag[i] = 0.0
    # --- journal/race line contact (Eq. 17, 19-21, corrected)
    dx, dy, dist, delta = journal_gap(jx, jy, rx, ry, s)
    diag[D_PEN] = delta
    if delta > 0.0:
        nx = dx / dist
        ny = dy / dist
        rho_x, rho_y = r * nx, r * ny
        vpx, vpy, vpz = _point_velocity(y, kin, a, rho_x, rho_y)
        vpx += evx
        vpy += evy
        arm = r + s  # race material point at the bore, where the journal touches it
        vqx = rvx - rw * arm * ny
        vqy = rvy + rw * arm * nx
        dvx = vpx - vqx
        dvy = vpy - vqy
        dvz = vpz - rvz
        vn = dvx * nx + dvy * ny
        elastic = p.line_stiffness[k] * delta ** (10.0 / 9.0)
        fn = max(0.0, elastic + p.line_damping[k] * vn)
        sx = dvx - vn * nx  # slip: the relative velocity in the tangent plane
        sy = dvy - vn * ny
        ffx, ffy, ffz = _friction(p.sliding_friction[k] * fn, sx, sy, dvz, veps)
        cfx = -fn * nx + ffx  # on the rotor
        cfy = -fn * ny + ffy
        _apply_rotor(q, kin, a, rho_x, rho_y, cfx, cfy, ffz)
        _apply_modes(m, k, cfx, cfy)
        fx_r -= cfx
        fy_r -= cfy
        fz_r -= ffz
        t_r -= arm * (nx * cfy - ny * cfx)
        out[heat] += (fn - elastic) * vn - (ffx * sx + ffy * sy + ffz * dvz)
        diag[D_FN] = fn
        diag[D_FT] = -ny * ffx + nx * ffy
        diag[D_SLIP] = -ny * sx + nx * sy
    # --- axial face contact of a rotor collar on the race face
    # the rotor's axial displacement against the race's (both from their positions at the drop); the
    # plane's axial station a does not enter: the tilts move the journal axis point laterally only
    zeta = y[Z] - rz
    gap_plus = zeta - p.axial_clearance[k]
    gap_minus = -zeta - p.axial_clearance[k]
    side = 0.0
    pen = 0.0
    if p.face_plus[k] > 0.0 and gap_plus > 0.0:
        side, pen = 1.0, gap_plus
    elif p.face_minus[k] > 0.0 and gap_minus > 0.0:
        side, pen = -1.0, gap_minus
    diag[D_APEN] = max(gap_plus if p.face_plus[k] > 0.0 else -np.inf, gap_minus if p.face_minus[k] > 0.0 else -np.inf)
    if side != 0.0:
        rho_cx, rho_cy = rx - jx, ry - jy  # the face annulus is centred on the race
        _, _, vcz = _point_velocity(y, kin, a, rho_cx, rho_cy)
        pen_rate = side * (vcz - rvz)
        elastic = p.face_stiffness[k] * pen
        fa = max(0.0, elastic + p.face_damping[k] * pen_rate)
        _apply_rotor(q, kin, a, rho_cx, rho_cy, 0.0, 0.0, -side * fa)
        fz_r += side * fa
        out[heat] += (fa - elastic) * pen_rate
        diag[D_FA] = side * fa
        mu_share = p.face_friction[k] * fa / FACE_POINTS
        rf = p.face_radius[k]
        torque = 0.0
        for i in range(FACE_POINTS):
            ox, oy = rf * FACE_COS[i], rf * FACE_SIN[i]
            vax, vay, _ = _point_velocity(y, kin, a, rho_cx + ox, rho_cy + oy)
            slip_x = vax + evx - (rvx - rw * oy)
            slip_y = vay + evy - (rvy + rw * ox)
            gx, gy, _ = _friction(mu_share, slip_x, slip_y, 0.0, veps)
            _apply_rotor(q, kin, a, rho_cx + ox, rho_cy + oy, gx, gy, 0.0)
            _apply_modes(m, k, gx, gy)
            fx_r -= gx
            fy_r -= gy
            t_r -= ox * gy - oy * gx
            torque += ox * gy - oy * gx
            out[heat] -= gx * slip_x + gy * slip_y
        diag[D_FACE_T] = torque
    # --- ball set (Eq. 22), its damping (Eq. 23) and rolling resistance (Eq. 24, corrected)
    ox_, oy_ = y[b + OX], y[b + OY]
    ovx, ovy = y[b + OVX], y[b + OVY]
    disp = m.scratch[_DISP:_DISP + 5]
    force = m.scratch[_FORCE:_FORCE + 5]
    for i in range(5):
        disp[i] = 0.0
        force[i] = 0.0
    if p.rows[k] > 1.0:
        faz, fex, fey, qmax = _pair_reaction(k, rz, rx - ox_, ry - oy_, m, disp, force)
    else:
        disp[0] = rz
        disp[1] = rx - ox_
        disp[2] = ry - oy_
        qmax, _ = accumulate(disp, m.ballsets[k], m.ballset_clearance[k], force, m.jac_stub, False, False)
        faz, fex, fey = force[0], force[1], force[2]
    fez = faz if p.race_axial_free[k] > 0.0 else 0.0
    diag[D_BFX], diag[D_BFY], diag[D_BFZ], diag[D_QMAX] = fex, fey, faz, qmax
    cb = p.ball_damping[k]
    relx, rely, relz = rvx - ovx, rvy - ovy, rvz
    dampx, dampy, dampz = -cb * relx, -cb * rely, -cb * relz
    fx_r += fex + dampx
    fy_r += fey + dampy
    fz_r += fez + dampz
    out[heat + 1] += cb * (relx * relx + rely * rely + relz * relz)
    out[ledger_of(m) + L_BALLSET_WORK] -= fex * relx + fey * rely + fez * relz
    ring_fx = -fex - dampx
    ring_fy = -fey - dampy
    fe = math.sqrt(fex * fex + fey * fey)
    mu2 = p.rolling_friction[k]
    spin_sign = math.tanh(rw * p.raceway_radius[k] / veps)  # sign(omega_race), regularised like friction
    if fe > 0.0 and mu2 > 0.0:
        ux = -fex / fe  # the loaded zone: where the ball set pushes back from
        uy = -fey / fe
        roll = -mu2 * fe * spin_sign
        fx_r -= roll * uy
        fy_r += roll * ux
        t_r += p.raceway_radius[k] * roll
        ring_fx += roll * uy
        ring_fy -= roll * ux
        out[heat + 1] -= roll * (-uy * relx + ux * rely + p.raceway_radius[k] * rw)
    # the bearing's torque that no radial force explains: rolling resistance of an axial load (same
    # mu_2) and Palmgren's load-free viscous torque M_0 (Harris & Kotzalas 2007, Ch. 10)
    torque = mu2 * abs(fez) * p.raceway_radius[k]
    if p.viscous_factor[k] > 0.0:
        torque += palmgren_viscous_torque(p.lubricant_viscosity[k], rw, p.pitch_diameter[k], p.viscous_factor[k])
    if torque > 0.0:
        t_r -= torque * spin_sign
        out[heat + 1] += torque * spin_sign * rw
    # --- race equations
    g = m.rotor
    mr = p.race_mass[k]
    out[b + RX] = rvx
    out[b + RY] = rvy
    out[b + RPSI] = rw
    out[b + RVX] = fx_r / mr + g.gravity_x + m.scratch[_BASE]
    out[b + RVY] = fy_r / mr + g.gravity_y + m.scratch[_BASE + 1]
    out[b + ROMEGA] = t_r / p.race_inertia[k]
    if p.race_axial_free[k] > 0.0:
        out[b + RZ] = rvz
        out[b + RVZ] = fz_r / mr + g.gravity_z
    # --- outer ring in its mount
    if p.ring_free[k] > 0.0:
        ux_, uy_, travel = ring_travel(ox_, oy_, p, k)
        diag[D_MOUNT] = travel
        spring = p.mount_stiffness[k] * max(0.0, travel - p.mount_deadband[k])
        stop = 0.0
        if travel > p.stop_gap[k]:
            stop_rate = (ux_ * ovx + uy_ * ovy) / travel
            stop_elastic = p.stop_stiffness[k] * (travel - p.stop_gap[k])
            stop = max(0.0, stop_elastic + p.stop_damping[k] * stop_rate)
            out[heat + 2] += (stop - stop_elastic) * stop_rate
        if travel > 0.0:
            ring_fx -= (spring + stop) * ux_ / travel
            ring_fy -= (spring + stop) * uy_ / travel
        cm = p.mount_damping[k]
        ring_fx -= cm * ovx
        ring_fy -= cm * ovy
        out[heat + 2] += cm * (ovx * ovx + ovy * ovy)
        out[b + OX] = ovx
        out[b + OY] = ovy
        out[b + OVX] = ring_fx / p.ring_mass[k] + g.gravity_x + m.scratch[_BASE]
        out[b + OVY] = ring_fy / p.ring_mass[k] + g.gravity_y + m.scratch[_BASE + 1]


@uncounted
def plane_forces_once(k, y, m, kin, q, out, diag):
    """:func:`plane_forces` compiled once as a function of its own, for the observer and the outputs.

    The right-hand side inlines :func:`plane_forces` (it is called about ten times per step); everything
    else calls this copy, which keeps the compile time down.
    """
    plane_forces(k, y, m, kin, q, out, diag)


# ----------------------------------------------------------------------------- the machine
@uncounted
def _modal_rates(y, m, kin, om, spin_acc, q, out, n_planes, nm, ledger):
    """The elastic modes' rates (module docstring), their damping's heat, and their gyroscopic moment on the tilts.

    The unbalance planes' rotating forces load the modes (their rigid-body part is the rotor's static and couple
    unbalance, exact in the kinematics); their reaction on the spin is neglected and their work on the modes
    is booked as work brought in, so the energy audit still closes. Called, not inlined: a rigid rotor never
    takes it, and the right-hand side compiles for both.
    """
    e, x = m.extra_at, m.extra
    at = N_ROTOR + n_planes * N_PLANE
    tilt = m.rotor.tilt_free
    loss = 0.0
    c, s = math.cos(y[PHI]), math.sin(y[PHI])
    unbalance_work = 0.0
    for j in range(nm):
        rate = y[at + nm + j]
        real = x[e[E_URE] + j] * c - x[e[E_UIM] + j] * s
        imag = x[e[E_URE] + j] * s + x[e[E_UIM] + j] * c
        push = om * om * real + spin_acc * imag
        unbalance_work += push * rate
        acc = m.scratch[_QM + j] + push - x[e[E_STIFF] + j] * y[at + j]
        for i in range(nm):
            other = y[at + nm + i]
            acc -= (x[e[E_DAMP] + j * nm + i] + om * x[e[E_GYRO] + j * nm + i]) * other
            loss += rate * x[e[E_DAMP] + j * nm + i] * other
        if tilt:
            gx, gy = x[e[E_TILT] + j], x[e[E_TILT] + nm + j]
            acc += om * (gx * kin[8] + gy * kin[9])
            q[3] -= om * gx * rate
            q[4] -= om * gy * rate
        out[at + j] = rate
        out[at + nm + j] = acc
    out[ledger + L_HEAT + 3 * n_planes] = loss
    out[ledger + L_WORK_IN] += unbalance_work


@uncounted
def rhs(t, y, m, out):
    """dy/dt of the machine (module docstring); ledger rates included.

    Examples
    --------
    >>> from auxbearing.planar.rig import paper_rig
    >>> from auxbearing.machine.pack import pack
    >>> from auxbearing.core.machine import VY
    >>> import numpy as np
    >>> model = pack(paper_rig())
    >>> d = np.zeros(model.y0.size); rhs(0.0, model.y0, model.machine, d)
    >>> round(float(d[VY]), 5)  # the journal centre falls freely at the start
    -9.80665
    """
    for i in range(out.size):
        out[i] = 0.0
    rotor = m.rotor
    kin = rotor_kinematics(y, rotor)
    q = m.scratch[_Q:_Q + 6]  # generalised forces on G (3), theta_p (2), phi
    for i in range(6):
        q[i] = 0.0
    nm = m.extra_at[E_NM]
    for j in range(nm):
        m.scratch[_QM + j] = 0.0
    frame_field(t, m)
    n_planes = len(m.planes.active)
    for k in range(n_planes):
        if m.planes.active[k] > 0.0:
            plane_forces(k, y, m, kin, q, out, m.last_diag[k])
    if m.extra_at[E_NSUP] > 0 or m.extra_at[E_NAMB] > 0 or m.extra_at[E_NLOAD] > 0:
        _stations(t, y, m, kin, q, out)
    om = y[OMEGA]
    mass = rotor.mass
    vgx = y[VX] + kin[0] * om
    vgy = y[VY] + kin[1] * om
    q[0] += rotor.force_x
    q[1] += rotor.force_y
    q[2] += rotor.force_z
    drag = -(rotor.drag_constant * math.tanh(om / rotor.drag_speed_scale) + rotor.drag_viscous * om
             + rotor.drag_windage * om * abs(om))
    q[5] += drag + rotor.process_torque
    ledger = ledger_of(m)
    out[ledger + L_WORK_IN] = (rotor.force_x * vgx + rotor.force_y * vgy + rotor.force_z * y[VZ]
                               + rotor.process_torque * om)
    out[ledger + L_DRAG_LOSS] = -drag * om
    spin_acc = q[5] / rotor.polar_inertia
    # mass centre, then the geometric centre O = G - e u (module docstring)
    gx = q[0] / mass + rotor.gravity_x + m.scratch[_BASE]
    gy = q[1] / mass + rotor.gravity_y + m.scratch[_BASE + 1]
    be = y[PHI] + rotor.unbalance_phase
    e = rotor.unbalance
    ux, uy = math.cos(be), math.sin(be)
    out[X] = y[VX]
    out[Y] = y[VY]
    out[PHI] = om
    out[VX] = gx + e * ux * om * om - kin[0] * spin_acc
    out[VY] = gy + e * uy * om * om - kin[1] * spin_acc
    out[OMEGA] = spin_acc
    if rotor.axial_free:
        out[Z] = y[VZ]
        out[VZ] = q[2] / mass + rotor.gravity_z
    if nm > 0:
        _modal_rates(y, m, kin, om, q[5] / rotor.polar_inertia, q, out, n_planes, nm, ledger)
    if rotor.tilt_free:
        jt = rotor.transverse_inertia
        gyro = rotor.polar_inertia * om
        apx = (q[3] - gyro * kin[9]) / jt
        apy = (q[4] + gyro * kin[8]) / jt
        out[TX] = y[WX]
        out[TY] = y[WY]
        # theta_g = theta_p - chi w: chi w'' = -chi w
        out[WX] = apx + kin[2] * om * om - kin[4] * spin_acc
        out[WY] = apy + kin[3] * om * om - kin[5] * spin_acc


@njit(cache=True, inline="always")
def energy(y, m):
    """Mechanical energy at a state [J]: kinetic, gravity, and the elastic energy of the contacts and mounts.

    Kinetic energy of the rotor in the form the equations conserve (m |G'|^2 + J_t |theta_p'|^2 +
    J_p Omega^2 + |eta'|^2)/2 with the modes' strain energy omega_j^2 eta_j^2 / 2, plus races (translation, spin)
    and outer rings. Elastic: the line contacts (9/19) K_l delta^(19/9) (integral of Eq. 19's elastic part),
    the axial faces, the mount springs and stops. The ball sets' energy is the ledger entry ``ballset_work``
    (work done on them).
    """
    rotor = m.rotor
    p = m.planes
    kin = rotor_kinematics(y, rotor)
    om = y[OMEGA]
    vgx = y[VX] + kin[0] * om
    vgy = y[VY] + kin[1] * om
    kinetic = 0.5 * rotor.mass * (vgx * vgx + vgy * vgy + y[VZ] * y[VZ]) + 0.5 * rotor.polar_inertia * om * om
    if rotor.tilt_free:
        kinetic += 0.5 * rotor.transverse_inertia * (kin[8] * kin[8] + kin[9] * kin[9])
    e = rotor.unbalance
    be = y[PHI] + rotor.unbalance_phase
    gx_, gy_ = y[X] + e * math.cos(be), y[Y] + e * math.sin(be)
    potential = -rotor.mass * (rotor.gravity_x * gx_ + rotor.gravity_y * gy_ + rotor.gravity_z * y[Z])
    e = m.extra_at
    nm = e[E_NM]
    at = N_ROTOR + len(p.active) * N_PLANE
    for j in range(nm):
        kinetic += 0.5 * y[at + nm + j] ** 2
        potential += 0.5 * m.extra[e[E_STIFF] + j] * y[at + j] ** 2
    width = len(linear_support.FIELDS)
    for i in range(e[E_NSUP]):
        row = m.extra[e[E_SUP] + i * width:e[E_SUP] + (i + 1) * width]
        jx, jy, _, _ = station_point(y, m, row[0], e[E_SUP_SX] + i * nm, e[E_SUP_SY] + i * nm)
        potential += linear_support.energy(row, jx, jy)
    for k in range(len(p.active)):
        if p.active[k] <= 0.0:
            continue
        b = N_ROTOR + k * N_PLANE
        mr = p.race_mass[k]
        kinetic += 0.5 * mr * (y[b + RVX] ** 2 + y[b + RVY] ** 2 + y[b + RVZ] ** 2)
        kinetic += 0.5 * p.race_inertia[k] * y[b + ROMEGA] ** 2
        potential -= mr * (rotor.gravity_x * y[b + RX] + rotor.gravity_y * y[b + RY] + rotor.gravity_z * y[b + RZ])
        jx, jy, _, _ = journal_point(y, m, k)
        dist = math.hypot(jx - y[b + RX], jy - y[b + RY])
        delta = dist - p.clearance[k]
        if delta > 0.0:
            potential += p.line_stiffness[k] * 9.0 / 19.0 * delta ** (19.0 / 9.0)
        zeta = y[Z] - y[b + RZ]
        plus = zeta - p.axial_clearance[k]
        minus = -zeta - p.axial_clearance[k]
        if p.face_plus[k] > 0.0 and plus > 0.0:
            potential += 0.5 * p.face_stiffness[k] * plus * plus
        if p.face_minus[k] > 0.0 and minus > 0.0:
            potential += 0.5 * p.face_stiffness[k] * minus * minus
        if p.ring_free[k] > 0.0:
            mo = p.ring_mass[k]
            kinetic += 0.5 * mo * (y[b + OVX] ** 2 + y[b + OVY] ** 2)
            potential -= mo * (rotor.gravity_x * y[b + OX] + rotor.gravity_y * y[b + OY])
            travel = math.hypot(y[b + OX] - p.centre_x[k], y[b + OY] - p.centre_y[k])
            potential += 0.5 * p.mount_stiffness[k] * max(0.0, travel - p.mount_deadband[k]) ** 2
            if travel > p.stop_gap[k]:
                potential += 0.5 * p.stop_stiffness[k] * (travel - p.stop_gap[k]) ** 2
    return kinetic, potential


@njit(cache=True, inline="always")
def energy_balance(y, m, e0):
    """Energy in, energy accounted for and their scale [J].

    In: e0 (mechanical energy at the start) + work of the process forces. Accounted: mechanical energy
    now + energy stored in the ball sets + heat + drag loss. Scale: the sum of the magnitudes of every
    term, so the relative error means something when the start energy is near zero (a rotor at rest).
    """
    kinetic, potential = energy(y, m)
    ledger = ledger_of(m)
    heat = 0.0
    for i in range(ledger + L_HEAT, y.size):
        heat += y[i]
    work_in, ballset, drag = y[ledger + L_WORK_IN], y[ledger + L_BALLSET_WORK], y[ledger + L_DRAG_LOSS]
    energy_in = e0 + work_in
    accounted = kinetic + potential + ballset + drag + heat
    scale = abs(e0) + abs(work_in) + kinetic + abs(potential) + abs(ballset) + abs(drag) + abs(heat)
    return energy_in, accounted, scale
