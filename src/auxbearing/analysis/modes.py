"""The machine's damped natural frequencies against speed: a Campbell diagram of the model the drop integrates.

The linear model is the kernel's rotor (:mod:`auxbearing.core.machine`): the rigid body's translations and
tilts about the mass centre (x, y, theta_x, theta_y) and the structure's kept elastic modes, with

    M q'' + (C + Omega G) q' + K q = 0,

M = diag(m, m, J_t, J_t, 1, ...), G the skew gyroscopic matrix (J_p between the tilts, gt between tilts and
modes, Gm between modes), K = diag(0, 0, 0, 0, omega_j^2) plus the stations' stiffness, C the modes'
damping plus the stations' damping. A station at axial position a moves by b_x q along x and b_y q along y,
b_x = (1, 0, 0, a, phi_x(a)), b_y = (0, 1, -a, 0, phi_y(a)); its 2x2 stiffness S adds b^T S b to K
(Friswell, Penny, Garvey & Lees, *Dynamics of Rotating Machines*, 2010, Ch. 3 and 6 for the assembly and the
whirl directions). Two states of the touchdown planes are shown:

* free: the rotor levitated, the journals clear of their races; the linear supports and the radial magnetic
  bearings hold it, each bearing a spring k(w) and a damper c(w) at the actuator driven by its sensor
  (:meth:`~auxbearing.machine.stations.amb.MagneticBearing.spring_and_damper`, ideal sensor and amplifier): the
  PD law's k_i k_p - k_s and k_i k_d (the integral action left out), or a state-space controller's (a filtered
  derivative, or matrices) k_i Re C(i w) - k_s and k_i Im C(i w) / w, evaluated at each mode's own damped
  frequency (:func:`campbell`). An axial (thrust) bearing acts along the spin axis and is left out. A rotor held by
  nothing has its rigid-body modes at zero, and its nutation J_p Omega / J_t at speed;
* in contact: each plane carrying its share W of the weight at rest in the bottom of its bore, undamped. Along
  the weight (y) the journal/race line contact's tangent stiffness (10/9) F / delta at that load (Eq. 19) in
  series with the ball set's and the mount's (:func:`auxbearing.analysis.whirl.natural_frequency`); the ball set
  (one row, or both rows of a matched pair with its preload) is linearised under W (:func:`ball_set_stiffness`).
  Across it (x) the journal's centre runs on an arc of the radial clearance c, so the weight restores a sideways
  shift with W / c: the simple pendulum of length c, omega^2 = g / c (Thomson & Dahleh, *Theory of Vibration with
  Applications*, 5th ed., 1998, Ch. 2, free vibration), in series with the ball set and mount
  (:func:`swing_stiffness`; the race's turning as the journal rolls on it is left out: a 0.07 kg race adds
  about 1 % to the blower's 5 kg a plane). Full dynamics finds these swings: the blower's coast-down loads its
  journals more near once and twice its 40.3 Hz (:mod:`auxbearing.analysis.coastdown`). A plane that carries
  no weight at rest adds nothing: a vertical machine rests on no plane, so in contact its rotor is held by the
  linear supports alone (no mode if it has none).

A mode whirls forward when its orbit turns with the spin, backward when against it (at the station of its
largest motion); one whose orbit there is nearly a line (:data:`PLANAR`, a plane swinging across its weight
while the other direction sits on its contact) is "planar", and the unbalance drives it like a forward one.
Two modes of one eigenvalue (no spin, or no gyroscopic coupling) are a "pair": the eigensolver returns them
in any mix, and either whirl direction is a combination of them. A mode that grows (Re lambda > 0, a negative
damping ratio, e.g. under a cross-coupled seal) is kept and reported (:meth:`Campbell.unstable`), and so is a
root that diverges without oscillating (lambda real and positive: a negative net stiffness), at 0 Hz with whirl
"none"; stable non-oscillating roots are no modes and are left out.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import eig

from auxbearing.common.errors import InputError
from auxbearing.machine.model import Machine
from auxbearing.machine.stations import of_kind

#: Frequencies below this are rigid-body motions of a free rotor, not modes [Hz].
RIGID_BELOW = 1e-3
#: Two frequencies this close (relative) are one pair of modes (module docstring).
PAIR_TOLERANCE = 1e-8
#: An orbit whose turning 2 |Im(conj(x) y)| / (|x|^2 + |y|^2) is below this is a line: the mode is "planar" (a
#: circle gives 1). A plane's pendulum swing in contact is a line at rest and stays below 0.03 up to the blower's and
#: the compressor's top speeds; the spin turns the compressor's bending modes into orbits of 0.64-0.96 by 4000 rpm.
PLANAR = 0.05
STATES = ("free", "contact")
#: A damping ratio this close to zero is neutral, not growing: the contact state is undamped, and its roots' real
#: parts are the eigensolver's rounding (1e-13 or so of |lambda|), of either sign.
NEUTRAL = 1e-8


@dataclass(frozen=True)
class Campbell:
    """Damped natural frequencies against speed (SI inside, Hz and rpm in :meth:`as_dict`)."""

    machine: str
    state: str  #: "free" or "contact"
    speeds: np.ndarray  #: (n,) spin speeds [rad/s]
    frequencies: np.ndarray  #: (n, modes) damped natural frequencies [Hz], ascending at each speed
    damping_ratios: np.ndarray  #: (n, modes) [-]
    whirl: np.ndarray  #: (n, modes) "forward", "backward", "planar" or "pair" (module docstring)
    contact_stiffness: tuple  #: each plane's linearised stiffness in contact [N/m] (0: free or not loaded)
    #: (n, modes) growth rates Re(lambda) [1/s]: positive for a mode that grows (an unstable one)
    growth_rates: np.ndarray | None = None
    #: modes whose frequency-dependent bearings did not settle at their frequency (:func:`campbell`), summed over speeds
    unsettled: int = 0

    def growing(self) -> np.ndarray:
        """(n, modes) True where a mode grows: a damping ratio below -:data:`NEUTRAL` (an empty cell does not)."""
        return np.nan_to_num(self.damping_ratios, nan=0.0) < -NEUTRAL

    def unstable(self) -> list[dict]:
        """Every mode that grows at a speed: speed [rpm], mode (column), frequency [Hz], damping ratio, rate [1/s]."""
        out = []
        for i, j in zip(*np.nonzero(self.growing()), strict=True):
            out.append({"speed_rpm": abs(float(self.speeds[i])) * 30.0 / math.pi, "mode": int(j),
                        "frequency_Hz": float(self.frequencies[i, j]),
                        "damping_ratio": float(self.damping_ratios[i, j]),
                        "growth_rate_per_s": None if self.growth_rates is None else float(self.growth_rates[i, j]),
                        "oscillating": self.whirl[i, j] != "none"})
        return out

    def critical_speeds(self) -> list[dict]:
        """Where the synchronous excitation (1x) crosses a mode it drives (forward, planar or a pair) [rpm]."""
        out = []
        excitation = np.abs(self.speeds) / (2.0 * math.pi)
        for j in range(self.frequencies.shape[1]):
            driven = np.isin(self.whirl[:, j], ("forward", "planar", "pair"))  # not backward, a divergence or none
            gap = np.where(driven, self.frequencies[:, j] - excitation, np.nan)
            for i in range(len(gap) - 1):
                a, b = gap[i], gap[i + 1]
                if np.isfinite(a) and np.isfinite(b) and a * b <= 0.0 and a != b:
                    w = self.speeds[i] + (self.speeds[i + 1] - self.speeds[i]) * a / (a - b)
                    out.append({"speed_rpm": abs(w) * 30.0 / math.pi, "mode": j})
        return out

    def as_dict(self) -> dict:
        """Plain numbers with their units in the keys (JSON)."""
        return {"machine": self.machine, "state": self.state,
                "speeds_rpm": (self.speeds * 30.0 / math.pi).tolist(),
                "frequencies_Hz": _listed(self.frequencies), "damping_ratios": _listed(self.damping_ratios),
                "growth_rates_per_s": None if self.growth_rates is None else _listed(self.growth_rates),
                "whirl": [[w or None for w in row] for row in self.whirl.tolist()],
                "contact_stiffness_N_per_m": list(self.contact_stiffness),
                "critical_speeds": self.critical_speeds(), "unstable": self.unstable(),
                "unsettled_modes": self.unsettled}


def _listed(values: np.ndarray) -> list:
    """Rows of numbers for JSON, an empty cell (NaN: no such mode at that speed) as None."""
    return [[None if not math.isfinite(v) else float(v) for v in row] for row in np.asarray(values, float).tolist()]


def station_rows(machine: Machine, position: float, key: str) -> tuple[np.ndarray, np.ndarray]:
    """b_x and b_y of a station at ``position`` from the mass centre (module docstring)."""
    modal = machine.modal()
    n = 0 if modal is None else modal.n_modes
    bx, by = np.zeros(4 + n), np.zeros(4 + n)
    bx[0], bx[3] = 1.0, position
    by[1], by[2] = 1.0, -position
    if n:
        bx[4:], by[4:] = modal.station_shapes(position, key)
    return bx, by


def _resting(machine: Machine, k: int) -> tuple[float, float, float]:
    """Plane k at rest: its share W of the weight [N] and its support's tangent stiffness along and across W [N/m].

    The support is the plane's ball set (a single row or both rows of a matched pair, preload included) linearised
    under W, in series with its mount (:func:`ball_set_stiffness`); (0, 0, 0) when the plane carries no weight (a
    vertical machine, or a plane the lever rule leaves unloaded): the plane then adds nothing in contact.
    """
    weight = machine.rest_share(k) * machine.rotor.mass * machine.simulation.gravity
    if machine.orientation == "vertical" or weight <= 0.0:
        return 0.0, 0.0, 0.0
    plane = machine.planes[k]
    along, across = ball_set_stiffness(plane, weight)
    mount = plane.mount.mount_stiffness if plane.mount is not None else math.inf
    return weight, _series(along, mount), _series(across, mount)


def _series(a: float, b: float) -> float:
    """Two springs in series [N/m]; an infinite one is rigid, a zero one carries nothing."""
    if a <= 0.0 or b <= 0.0:
        return 0.0
    return 1.0 / (1.0 / a + 1.0 / b)


def ball_set_stiffness(plane, load: float) -> tuple[float, float]:
    """Tangent radial stiffness of the plane's ball set under a radial ``load`` [N], along and across it [N/m].

    The inner ring (of a matched pair: both inner rings, clamped) is held axially and square and pushed along the
    load until the ball set's reaction balances it (source paper Eq. 14 and 16, the same equilibrium as
    :func:`auxbearing.analysis.statics.radial_approach`); the stiffness is minus the reaction's Jacobian there,
    d F / d u, the linearisation of the load-deflection curve about that point (Harris & Kotzalas, *Rolling
    Bearing Analysis*, 5th ed., 2007, Advanced Concepts Ch. 1, bearing stiffness). A pair's rows are placed as in
    :mod:`auxbearing.bearings.duplex_statics` (each row's map M_k and its preload push, reaction sum M_k^T f_k and
    Jacobian sum M_k^T J_k M_k), with the plane's ball constant as the drop uses it. A preloaded pair is stiff at
    zero load; a tandem pair or a row with clearance is not, and its stiffness comes from the load alone.
    """
    from auxbearing.bearings.ballset import ballset_params, ballset_state

    pair = plane.bearing_set
    params = ballset_params(plane.bearing, plane.ball_constant)
    clearance = plane.bearing.diametral_clearance
    if pair is None:
        maps, push = [np.eye(5)], 0.0
    else:
        maps, push = [pair.row_map(0), pair.row_map(1)], pair.row_preload_displacement

    def reaction(dx: float) -> tuple[float, np.ndarray]:
        u = np.array([0.0, dx, 0.0, 0.0, 0.0])
        rows = np.array([m @ u for m in maps])
        rows[:, 0] += push
        st = ballset_state(rows, params, clearance)
        jac = sum(m.T @ st.jacobian[i] @ m for i, m in enumerate(maps))
        force = sum(m.T @ st.force[i] for i, m in enumerate(maps))
        return float(force[1]), jac

    if load <= 0.0:
        _, jac = reaction(0.0)
        return max(-float(jac[1, 1]), 0.0), max(-float(jac[2, 2]), 0.0)
    # load + F_x(dx) = 0: F_x falls from 0 as dx grows, the root found as radial_approach finds it
    from auxbearing.analysis.statics import falling_root

    def residual(dx: float) -> tuple[float, float]:
        force, jac = reaction(dx)
        return load + force, float(jac[1, 1])

    dx = falling_root(residual, 0.5 * max(clearance, 0.0) + 1e-7, 1e-10 * load)
    if not math.isfinite(dx):
        return 0.0, 0.0  # no displacement carries the load: no stiffness to give
    _, jac = reaction(dx)
    return max(-float(jac[1, 1]), 0.0), max(-float(jac[2, 2]), 0.0)


def contact_stiffness(machine: Machine, k: int, resting: tuple[float, float, float] | None = None) -> float:
    """Plane k's linearised stiffness in contact under its share of the weight at rest [N/m] (0: unloaded).

    ``resting``: :func:`_resting` of the plane, when the caller has it.
    """
    from auxbearing.analysis.whirl import natural_frequency

    force, support, _ = resting or _resting(machine, k)
    if force <= 0.0:
        return 0.0
    # natural_frequency returns sqrt(k / m): with m = 1 its square is the series stiffness
    return natural_frequency(force, machine.planes[k].line_stiffness, support, 1.0) ** 2


def swing_stiffness(machine: Machine, k: int, resting: tuple[float, float, float] | None = None) -> float:
    """Plane k's stiffness across its weight at rest [N/m]: W / c in series with ball set and mount (0: unloaded).

    The journal's centre in the bottom of its bore runs on an arc of the radial clearance c; a sideways shift x
    lifts the weight W by x^2 / (2 c), a potential W x^2 / (2 c) (module docstring). ``resting`` as for
    :func:`contact_stiffness`.
    """
    # the support along the load stands in for the one across it: softer across (1.29e7 against 1.48e7 N/m with the
    # blower's mount, at its 49 N), which would take 0.16 % off a swing that the pendulum W / c (3.3e5 N/m) sets
    weight, support, _ = resting or _resting(machine, k)
    if weight <= 0.0:
        return 0.0
    pendulum = weight / machine.planes[k].radial_clearance
    return pendulum if support <= 0.0 else 1.0 / (1.0 / pendulum + 1.0 / support)


def linear_matrices(machine: Machine, state: str = "free", frequency: float | None = None) -> tuple[np.ndarray, ...]:
    """(M, C, G, K) of the linear model (module docstring) and each plane's contact stiffness.

    ``frequency``: where the magnetic bearings' controllers are evaluated [rad/s] (:func:`amb_matrices`); None: the
    machine's running speed. Only a state-space controller depends on it; :func:`campbell` evaluates each mode at its
    own frequency.
    """
    mass, damp, gyro, stiff, springs = _passive_matrices(machine, state)
    if state == "free":
        amb_stiff, amb_damp = amb_matrices(machine, machine.rotor.speed if frequency is None else frequency)
        stiff, damp = stiff + amb_stiff, damp + amb_damp
    return mass, damp, gyro, stiff, springs


def _passive_matrices(machine: Machine, state: str) -> tuple[np.ndarray, ...]:
    """(M, C, G, K) and the planes' contact stiffness without the magnetic bearings (:func:`linear_matrices`)."""
    if state not in STATES:
        raise InputError.for_field("state", state, f"must be one of {', '.join(STATES)}")
    r = machine.rotor
    modal = machine.modal()
    n = 0 if modal is None else modal.n_modes
    jt = r.transverse_inertia or 0.0
    size = 4 + n
    mass = np.diag([r.mass, r.mass, jt, jt, *np.ones(n)])
    gyro, stiff, damp = np.zeros((size, size)), np.zeros((size, size)), np.zeros((size, size))
    gyro[2, 3], gyro[3, 2] = r.polar_inertia, -r.polar_inertia
    if n:
        gyro[2:4, 4:], gyro[4:, 2:4] = modal.tilt_gyroscopic, -modal.tilt_gyroscopic.T
        gyro[4:, 4:] = modal.modal_gyroscopic
        stiff[4:, 4:] = np.diag(modal.frequencies ** 2)
        damp[4:, 4:] = modal.modal_damping
    if not machine.tilt_free:  # one plane: the planar rotor, tilts locked
        for i in (2, 3):
            mass[i, i], gyro[i, :], gyro[:, i] = 1.0, 0.0, 0.0
            stiff[i, i] = 1.0  # a locked tilt: a unit spring on a unit inertia, dropped from the results below
    for i, s in enumerate(of_kind(machine.stations, "linear_support")):
        bx, by = station_rows(machine, s.position, f"linear_support.{i}.position")
        b = np.vstack([bx, by])
        stiff += b.T @ np.array([[s.kxx, s.kxy], [s.kyx, s.kyy]]) @ b
        damp += b.T @ np.array([[s.cxx, s.cxy], [s.cyx, s.cyy]]) @ b
    springs = []
    for k, plane in enumerate(machine.planes):
        resting = _resting(machine, k) if state == "contact" else (0.0, 0.0, 0.0)
        spring = contact_stiffness(machine, k, resting)
        springs.append(spring)
        if spring > 0.0:  # along the weight (y) the contact, across it (x) the swing on the bore's arc
            bx, by = station_rows(machine, plane.position, f"touchdown.{k}.position")
            stiff += swing_stiffness(machine, k, resting) * np.outer(bx, bx) + spring * np.outer(by, by)
    return mass, damp, gyro, stiff, tuple(springs)


def _radial_ambs(machine: Machine) -> list:
    """(index, bearing) of the magnetic bearings that hold the rotor laterally.

    An axial (thrust) bearing acts along the spin axis on the rotor's axial position: it carries no lateral load
    and has no place in this lateral model (its own axial mode is not among these modes).
    """
    return [(i, s) for i, s in enumerate(of_kind(machine.stations, "amb")) if not s.axial]


def frequency_dependent(machine: Machine) -> bool:
    """Whether a radial magnetic bearing's spring and damper depend on the frequency (a state-space controller)."""
    return any(s.controller is not None for _, s in _radial_ambs(machine))


def amb_matrices(machine: Machine, frequency: float) -> tuple[np.ndarray, np.ndarray]:
    """The radial magnetic bearings' stiffness and damping matrices with each controller evaluated at ``frequency``.

    Each bearing is its spring k(w) and damper c(w) at the actuator, driven by the sensor's reading
    (:meth:`auxbearing.machine.stations.amb.MagneticBearing.spring_and_damper`, ideal sensor and amplifier), less
    the bias flux's negative stiffness k_s at the actuator [rad/s in, N/m and N s/m in the matrices].
    """
    size = mass_size(machine)
    stiff, damp = np.zeros((size, size)), np.zeros((size, size))
    for i, s in _radial_ambs(machine):
        b = np.vstack(station_rows(machine, s.position, f"amb.{i}.position"))
        sensor = np.vstack(station_rows(machine, s.sensor, f"amb.{i}.sensor_position"))
        spring, damper = s.spring_and_damper(frequency)
        stiff += (spring + s.position_stiffness) * b.T @ sensor - s.position_stiffness * b.T @ b
        damp += damper * b.T @ sensor
    return stiff, damp


def mass_size(machine: Machine) -> int:
    """Coordinates of the linear model: the four rigid-body ones and the kept elastic modes."""
    modal = machine.modal()
    return 4 + (0 if modal is None else modal.n_modes)


#: Most speeds a diagram is computed at (each is one eigenproblem of the linear model).
MAX_SPEEDS = 1000


def spin_speeds(speeds, field: str = "speeds") -> np.ndarray:
    """Spin speeds [rad/s] from numbers in rad/s, strings with units, or one text listing them.

    The text has one unit at its end ("0, 9000, 18000 rpm"; rpm when none is given), as the command line reads
    it. ``field`` names the speeds in an error.

    >>> spin_speeds("0, 9000 rpm").round(1).tolist(), spin_speeds([0.0, "100 rad/s"]).tolist()
    ([0.0, 942.5], [0.0, 100.0])
    """
    from auxbearing.common.units import to_si

    if isinstance(speeds, str):
        parts = [p.strip() for p in speeds.split(",") if p.strip()]
        unit = parts[-1].split()[-1] if parts and len(parts[-1].split()) > 1 else "rpm"
        items, default = [p if len(p.split()) > 1 else f"{p} {unit}" for p in parts], "rpm"
    else:
        items, default = list(np.atleast_1d(np.asarray(speeds, dtype=object)).ravel()), "rad/s"
    values = []
    for item in items:
        try:
            values.append(to_si(field, item, "angular_speed", default))
        except InputError as err:  # named with the whole list as given
            raise InputError.for_field(field, speeds, f"{item!r}: {str(err).split(': ', 1)[-1]}") from None
    if not values or len(values) > MAX_SPEEDS:
        raise InputError.for_field(field, speeds, f"give 1 to {MAX_SPEEDS} speeds, e.g. '0, 9000, 18000 rpm'")
    if not all(0.0 <= v < 1e6 for v in values):
        raise InputError.for_field(field, speeds, "each speed must be at least 0 and below 1e6 rad/s")
    return np.array(sorted(values))


#: Where the iteration of frequency-dependent bearings starts when the machine runs slower [Hz]: a magnetic
#: bearing's rigid-body modes sit in the tens of hertz, and there a PID's integral (which a low start would weight
#: by 1 / w^2) no longer swamps its damper.
SEED_BELOW = 50.0
#: A mode's frequency has settled when one more evaluation of the bearings at it moves it by less than this
#: (relative); at most MAX_ITERATIONS evaluations a mode.
SETTLED = 1e-9
MAX_ITERATIONS = 50
#: Settled frequencies this close (relative) are one fixed point (both modes of a pair settle on it).
SAME_FIXED_POINT = 1e-6


@dataclass(frozen=True)
class _Root:
    """One eigenvalue kept for the diagram and its coordinates' part of the eigenvector."""

    value: complex  #: lambda [1/s]
    shape: np.ndarray  #: q (the model's coordinates)

    @property
    def oscillating(self) -> bool:
        return self.value.imag / (2.0 * math.pi) >= RIGID_BELOW


def campbell(machine: Machine, speeds, state: str = "free") -> Campbell:
    """Damped natural frequencies of ``machine`` at each spin speed in ``speeds`` (module docstring).

    ``speeds``: numbers in rad/s, strings with units, or one text as the command line takes (:func:`spin_speeds`).

    Every root of the linear model is kept that is a mode (an oscillating root below the static correction's cut,
    stable or growing) or that diverges without oscillating (a real root lambda > 0, shown at 0 Hz with damping
    ratio -1: a static instability such as a negative net stiffness); stable non-oscillating roots (an overdamped
    motion) and a free rotor's rigid-body motions are left out.

    Magnetic bearings whose controller is a state space (a filtered derivative, or a controller given as matrices)
    have a spring and damper that change with frequency: each mode's are evaluated at that mode's own damped
    frequency, by fixed-point iteration (evaluate the bearings at the mode's frequency, solve, take the mode nearest
    the last one, repeat until its frequency settles): the usual treatment of frequency-dependent bearing and seal
    coefficients in rotordynamics (Friswell, Penny, Garvey & Lees, *Dynamics of Rotating Machines*, 2010, Ch. 5;
    Schweitzer & Maslen, *Magnetic Bearings*, 2009, the bearing as a dynamic stiffness at the whirl
    frequency). The iteration starts from the modes with the bearings at the running speed (at least
    :data:`SEED_BELOW`); a root that diverges without oscillating has no frequency of its own and is taken from that
    start. A PID without derivative filter is a frequency-independent spring and damper: no iteration.
    """
    speeds = spin_speeds(speeds)
    mass, passive_damp, gyro, passive_stiff, springs = _passive_matrices(machine, state)
    held = state == "free" and bool(_radial_ambs(machine))
    varying = held and frequency_dependent(machine)
    if held and not varying:  # the PD law: the same spring and damper at every frequency
        amb_stiff, amb_damp = amb_matrices(machine, machine.rotor.speed)
        passive_stiff, passive_damp = passive_stiff + amb_stiff, passive_damp + amb_damp
    size = mass.shape[0]
    locked = () if machine.tilt_free else (2, 3)
    spin = 1.0 if machine.rotor.speed >= 0.0 else -1.0
    rows = [station_rows(machine, p.position, f"touchdown.{k}.position") for k, p in enumerate(machine.planes)]
    rows += [station_rows(machine, a, "station") for a in _stations_positions(machine)]
    above = _natural_below(machine)
    inverse = np.linalg.inv(mass)

    def roots(omega: float, frequency: float | None = None) -> list[_Root]:
        """The kept roots at spin ``omega`` with the bearings evaluated at ``frequency`` [rad/s]."""
        stiff, damp = passive_stiff, passive_damp
        if frequency is not None:
            amb_stiff, amb_damp = amb_matrices(machine, frequency)
            stiff, damp = stiff + amb_stiff, damp + amb_damp
        a = np.block([[np.zeros((size, size)), np.eye(size)],
                      [-inverse @ stiff, -inverse @ (damp + omega * gyro)]])
        values, vectors = eig(a)
        kept = []
        for lam, vec in zip(values, vectors.T, strict=True):
            if lam.imag < 0.0:
                continue  # the conjugate of a kept root
            q = vec[:size]
            if locked and np.abs(q[list(locked)]).max() > 0.5 * np.abs(q).max():
                continue  # the locked tilts' stand-in springs
            hz = lam.imag / (2.0 * math.pi)
            if hz < RIGID_BELOW:
                # not oscillating: a free rotor's rigid motions (|lambda| ~ 0) and overdamped decays are left out,
                # a divergence is kept
                if lam.real > 2.0 * math.pi * RIGID_BELOW:
                    kept.append(_Root(complex(lam), q))
                continue
            if hz > above:
                continue  # above the cut, the static correction's vectors
            kept.append(_Root(complex(lam), q))
        return kept

    seed = max(abs(machine.rotor.speed), 2.0 * math.pi * SEED_BELOW)
    freqs, ratios, rates, forwards, unsettled = [], [], [], [], 0
    for omega in speeds:
        if varying:
            found, missed = _self_consistent(roots, omega, seed)
            unsettled += missed
        else:
            found = roots(omega)
        f, z, g, fw = [], [], [], []
        for root in found:
            lam, q = root.value, root.shape
            f.append(max(lam.imag, 0.0) / (2.0 * math.pi) if root.oscillating else 0.0)
            z.append(-lam.real / abs(lam))
            g.append(lam.real)
            if not root.oscillating:
                fw.append("none")  # no whirl: the rotor moves off without turning
                continue
            x = np.array([bx @ q for bx, _ in rows])
            y = np.array([by @ q for _, by in rows])
            at = int(np.argmax(np.abs(x) ** 2 + np.abs(y) ** 2))
            # x = Re(X e^(i w t)), y = Re(Y e^(i w t)): Y = -i X turns from +x to +y, with a spin about +z
            turn = spin * np.imag(np.conj(x[at]) * y[at])
            if 2.0 * abs(turn) < PLANAR * (abs(x[at]) ** 2 + abs(y[at]) ** 2):
                fw.append("planar")
            else:
                fw.append("forward" if turn < 0.0 else "backward")
        order = np.argsort(f, kind="stable")
        f, fw = np.array(f, float)[order], np.array(fw, dtype=object)[order]
        lams = np.array([root.value for root in found], complex)[order]
        for j in range(len(f) - 1):
            # one eigenvalue twice (its growth too): a cross-coupled support splits forward and backward whirl at one
            # frequency into a decaying and a growing mode, which are no pair
            if (fw[j] != "none" and fw[j + 1] != "none"
                    and abs(lams[j + 1] - lams[j]) <= PAIR_TOLERANCE * abs(lams[j + 1])):
                fw[j] = fw[j + 1] = "pair"
        freqs.append(f)
        ratios.append(np.array(z, float)[order])
        rates.append(np.array(g, float)[order])
        forwards.append(fw)
    # as many columns as the speed with the most modes: a mode that exists at some speeds only (a divergence, a
    # mode crossing the static correction's cut) is shown where it exists, the other speeds' cells left empty (NaN)
    width = max(len(f) for f in freqs)

    def padded(values, fill):
        return [list(v) + [fill] * (width - len(v)) for v in values]

    return Campbell(machine.name, state, np.asarray(speeds, float),
                    np.array(padded(freqs, math.nan), float).reshape(len(speeds), width),
                    np.array(padded(ratios, math.nan), float).reshape(len(speeds), width),
                    np.array(padded(forwards, ""), dtype=object).reshape(len(speeds), width),
                    springs, np.array(padded(rates, math.nan), float).reshape(len(speeds), width), unsettled)


def _self_consistent(roots, omega: float, seed: float) -> tuple[list[_Root], int]:
    """The roots at spin ``omega`` whose bearings are evaluated at their own damped frequency (:func:`campbell`).

    ``roots(omega, frequency)`` solves the model with the bearings at ``frequency`` [rad/s]. Returns the roots and
    how many modes did not settle within :data:`MAX_ITERATIONS` (each kept as its last iterate).
    """
    cache: dict[float, list[_Root]] = {}

    def solve(w: float) -> list[_Root]:
        if w not in cache:
            cache[w] = roots(omega, w)
        return cache[w]

    start = solve(seed)
    settled, last = [], []
    for root in (r for r in start if r.oscillating):
        current, w = root, root.value.imag
        for _ in range(MAX_ITERATIONS):
            modes = [r for r in solve(w) if r.oscillating]
            if not modes:
                break  # the mode became a non-oscillating root at its own frequency: nothing to settle
            # the same mode is the one of the most similar shape (modal assurance criterion); its frequency may have
            # moved past another mode's
            current = max(modes, key=lambda r, last=current: (round(_similarity(r.shape, last.shape), 9),
                                                               -abs(r.value - last.value)))
            if abs(current.value.imag - w) <= SETTLED * w:
                settled.append(w)
                break
            w = current.value.imag
        else:
            last.append(current)
    found = []
    settled.sort()
    for k, w in enumerate(settled):
        if k and w - settled[k - 1] <= SAME_FIXED_POINT * w:
            continue  # the same fixed point reached from another start (the other mode of a pair)
        found += [r for r in solve(w) if r.oscillating and abs(r.value.imag - w) <= SAME_FIXED_POINT * w]
    found += last
    found += [r for r in start if not r.oscillating]
    return found, len(last)


def _similarity(a: np.ndarray, b: np.ndarray) -> float:
    """The modal assurance criterion |a^H b|^2 / (|a|^2 |b|^2) of two shapes (1: the same shape, 0: orthogonal).

    Allemang & Brown, "A correlation coefficient for modal vector analysis", 1st IMAC, 1982.
    """
    return float(abs(np.vdot(a, b)) ** 2 / max(np.vdot(a, a).real * np.vdot(b, b).real, 1e-300))


def _natural_below(machine: Machine) -> float:
    """Frequency [Hz] above which an eigenvalue is the static correction's, not a mode of the rotor.

    Halfway between the highest natural mode kept and the lowest correction vector (both at rest, free): the
    cut itself would split a kept pair that sits on it, or drop a kept mode that the spin lifts past it.
    """
    modal = machine.modal()
    if modal is None or not modal.residual:
        return math.inf
    top = float(modal.frequencies[:modal.natural].max()) if modal.natural else 0.0
    return 0.5 * (top + float(modal.frequencies[modal.natural:].min())) / (2.0 * math.pi)


def _stations_positions(machine: Machine) -> list[float]:
    return [s.position for s in machine.stations]
