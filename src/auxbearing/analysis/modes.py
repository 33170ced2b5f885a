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

* free: the rotor levitated, the journals clear of their races; the linear supports and the magnetic bearings
  hold it, each bearing as its controller's ideal PD law, a spring k_i k_p - k_s and a damper k_i k_d at the
  actuator (the sensor's and amplifier's lags and the integral action left out: exact well below their
  bandwidths). A rotor held by nothing has its rigid-body modes at zero, and its nutation J_p Omega / J_t at speed;
* in contact: each plane carrying its share W of the weight at rest in the bottom of its bore, undamped. Along
  the weight (y) the journal/race line contact's tangent stiffness (10/9) F / delta at that load (Eq. 19) in
  series with the ball set's and the mount's (:func:`auxbearing.analysis.whirl.natural_frequency`). Across it
  (x) the journal's centre runs on an arc of the radial clearance c, so the weight restores a sideways shift
  with W / c: the simple pendulum of length c, omega^2 = g / c (Thomson & Dahleh, *Theory of Vibration with
  Applications*, 5th ed., 1998, Ch. 2, free vibration), in series with the ball set and mount
  (:func:`swing_stiffness`; the race's turning as the journal rolls on it is left out: a 0.07 kg race adds
  about 1 % to the blower's 5 kg a plane). Full dynamics finds these swings: the blower's coast-down loads its
  journals more near once and twice its 40.3 Hz (:mod:`auxbearing.analysis.coastdown`). A vertical machine
  rests on no plane, so nothing is added.

A mode whirls forward when its orbit turns with the spin, backward when against it (at the station of its
largest motion); one whose orbit there is nearly a line (:data:`PLANAR`, a plane swinging across its weight
while the other direction sits on its contact) is "planar", and the unbalance drives it like a forward one.
Two modes of equal frequency (no spin, or no gyroscopic coupling) are a "pair": the eigensolver returns them
in any mix, and either whirl direction is a combination of them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
from scipy.linalg import eig

from auxbearing.common.errors import InputError
from auxbearing.machine.model import Machine
from auxbearing.machine.stations import kinds as station_kinds
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

    def critical_speeds(self) -> list[dict]:
        """Where the synchronous excitation (1x) crosses a mode it drives (forward, planar or a pair) [rpm]."""
        out = []
        excitation = np.abs(self.speeds) / (2.0 * math.pi)
        for j in range(self.frequencies.shape[1]):
            gap = np.where(self.whirl[:, j] != "backward", self.frequencies[:, j] - excitation, np.nan)
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
                "frequencies_Hz": self.frequencies.tolist(), "damping_ratios": self.damping_ratios.tolist(),
                "whirl": self.whirl.tolist(),
                "contact_stiffness_N_per_m": list(self.contact_stiffness),
                "critical_speeds": self.critical_speeds()}


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


def _resting(machine: Machine, k: int) -> tuple[float, float]:
    """Plane k's share W of the weight at rest [N] and its ball set and mount in series [N/m]; (0, 0) when unloaded."""
    from auxbearing.analysis.drop import _support_stiffness

    weight = machine.rest_share(k) * machine.rotor.mass * machine.simulation.gravity
    if machine.orientation == "vertical" or weight <= 0.0:
        return 0.0, 0.0
    return weight, _support_stiffness(machine.planes[k])


def contact_stiffness(machine: Machine, k: int, resting: tuple[float, float] | None = None) -> float:
    """Plane k's linearised stiffness in contact under its share of the weight at rest [N/m] (0: unloaded).

    ``resting``: :func:`_resting` of the plane, when the caller has it.
    """
    from auxbearing.analysis.whirl import natural_frequency

    force, support = resting or _resting(machine, k)
    if force <= 0.0:
        return 0.0
    # natural_frequency returns sqrt(k / m): with m = 1 its square is the series stiffness
    return natural_frequency(force, machine.planes[k].line_stiffness, support, 1.0) ** 2


def swing_stiffness(machine: Machine, k: int, resting: tuple[float, float] | None = None) -> float:
    """Plane k's stiffness across its weight at rest [N/m]: W / c in series with ball set and mount (0: unloaded).

    The journal's centre in the bottom of its bore runs on an arc of the radial clearance c; a sideways shift x
    lifts the weight W by x^2 / (2 c), a potential W x^2 / (2 c) (module docstring). ``resting`` as for
    :func:`contact_stiffness`.
    """
    weight, support = resting or _resting(machine, k)
    if weight <= 0.0:
        return 0.0
    pendulum = weight / machine.planes[k].radial_clearance
    return pendulum if support <= 0.0 else 1.0 / (1.0 / pendulum + 1.0 / support)


def linear_matrices(machine: Machine, state: str = "free") -> tuple[np.ndarray, ...]:
    """(M, C, G, K) of the linear model (module docstring) and each plane's contact stiffness."""
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
    for kind in station_kinds():
        for i, s in enumerate(of_kind(machine.stations, kind.KIND)):
            bx, by = station_rows(machine, s.position, f"{kind.KIND}.{i}.position")
            b = np.vstack([bx, by])
            if kind.KIND == "linear_support":
                stiff += b.T @ np.array([[s.kxx, s.kxy], [s.kyx, s.kyy]]) @ b
                damp += b.T @ np.array([[s.cxx, s.cxy], [s.cyx, s.cyy]]) @ b
            elif kind.KIND == "amb" and state == "free":
                sx, sy = station_rows(machine, s.sensor, f"{kind.KIND}.{i}.sensor_position")
                sensor = np.vstack([sx, sy])
                spring, damper = s.spring_and_damper(machine.rotor.speed)
                stiff += (spring + s.position_stiffness) * b.T @ sensor - s.position_stiffness * b.T @ b
                damp += damper * b.T @ sensor
    springs = []
    for k, plane in enumerate(machine.planes):
        resting = _resting(machine, k) if state == "contact" else (0.0, 0.0)
        spring = contact_stiffness(machine, k, resting)
        springs.append(spring)
        if spring > 0.0:  # along the weight (y) the contact, across it (x) the swing on the bore's arc
            bx, by = station_rows(machine, plane.position, f"touchdown.{k}.position")
            stiff += swing_stiffness(machine, k, resting) * np.outer(bx, bx) + spring * np.outer(by, by)
    return mass, damp, gyro, stiff, tuple(springs)


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


def campbell(machine: Machine, speeds, state: str = "free") -> Campbell:
    """Damped natural frequencies of ``machine`` at each spin speed in ``speeds`` (module docstring).

    ``speeds``: numbers in rad/s, strings with units, or one text as the command line takes (:func:`spin_speeds`).
    """
    speeds = spin_speeds(speeds)
    mass, damp, gyro, stiff, springs = linear_matrices(machine, state)
    size = mass.shape[0]
    locked = () if machine.tilt_free else (2, 3)
    spin = 1.0 if machine.rotor.speed >= 0.0 else -1.0
    rows = [station_rows(machine, p.position, f"touchdown.{k}.position") for k, p in enumerate(machine.planes)]
    rows += [station_rows(machine, a, "station") for a in _stations_positions(machine)]
    freqs, ratios, forwards = [], [], []
    above = _natural_below(machine)
    inverse = np.linalg.inv(mass)
    for omega in speeds:
        a = np.block([[np.zeros((size, size)), np.eye(size)],
                      [-inverse @ stiff, -inverse @ (damp + omega * gyro)]])
        values, vectors = eig(a)
        f, z, fw = [], [], []
        for lam, vec in zip(values, vectors.T, strict=True):
            if lam.imag <= 0.0:
                continue
            q = vec[:size]
            if locked and np.abs(q[list(locked)]).max() > 0.5 * np.abs(q).max():
                continue  # the locked tilts' stand-in springs
            hz = lam.imag / (2.0 * math.pi)
            if hz < RIGID_BELOW or hz > above:
                continue  # a free rotor's rigid motions; above the cut, the static correction's vectors
            x = np.array([bx @ q for bx, _ in rows])
            y = np.array([by @ q for _, by in rows])
            at = int(np.argmax(np.abs(x) ** 2 + np.abs(y) ** 2))
            f.append(hz)
            z.append(-lam.real / abs(lam))
            # x = Re(X e^(i w t)), y = Re(Y e^(i w t)): Y = -i X turns from +x to +y, with a spin about +z
            turn = spin * np.imag(np.conj(x[at]) * y[at])
            if 2.0 * abs(turn) < PLANAR * (abs(x[at]) ** 2 + abs(y[at]) ** 2):
                fw.append("planar")
            else:
                fw.append("forward" if turn < 0.0 else "backward")
        order = np.argsort(f)
        f, fw = np.array(f)[order], np.array(fw, dtype=object)[order]
        for j in range(len(f) - 1):
            if f[j + 1] - f[j] <= PAIR_TOLERANCE * f[j + 1]:
                fw[j] = fw[j + 1] = "pair"
        freqs.append(f)
        ratios.append(np.array(z)[order])
        forwards.append(fw)
    width = min(len(f) for f in freqs)
    return Campbell(machine.name, state, np.asarray(speeds, float), np.array([f[:width] for f in freqs]),
                    np.array([z[:width] for z in ratios]), np.array([list(w[:width]) for w in forwards], dtype=object),
                    springs)


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
