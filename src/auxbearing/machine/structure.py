"""The rotor as a linear structure: mass, stiffness, damping and gyroscopic matrices over its nodes.

A rotor is given by its matrices over four lateral degrees of freedom per node, in the order
(x, y, theta_x, theta_y) with the machine's signs: a node at axial position z of a rotor tilted rigidly by
(theta_x, theta_y) about its mass centre z_G moves by x = (z - z_G) theta_y, y = -(z - z_G) theta_x, and

    M q'' + (C + Omega G) q' + K q = f,

with G skew, G[theta_x, theta_y] = +J_p for a disk of polar inertia J_p (the signs of the kernel's rigid
rotor, Friswell, Penny, Garvey & Lees, *Dynamics of Rotating Machines*, 2010, Eq. 3.63-3.66). The shaft is
free-free: its touchdown planes, bearings and seals are stations, not terms of K.

The kernels take the structure as a rigid body (mass, J_t, J_p about the mass centre: the rigid rotor the
drop has always integrated, with its exact unbalance kinematics) plus the structure's free-free elastic modes,
mass-normalised, which are M-orthogonal to the rigid motions (modal superposition about the mean axes of a
free-free body: Shabana, *Dynamics of Multibody Systems*, 3rd ed. 2005, Ch. 5, the floating frame of
reference; modal reduction of rotors in Friswell et al. 2010, Ch. 6). The two parts couple only through
the gyroscopic matrix and through the forces at the stations. The rigid rotor of a machine file is the
structure of one node with no elastic mode (:func:`rigid_structure`); :func:`beam_structure` builds a stepped
Euler-Bernoulli shaft with disks.

Here: SI floats and numpy arrays; units are read at the machine file's boundary.
"""

from __future__ import annotations

import copy
import math
import zipfile
import zlib
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from scipy.linalg import eigh

from auxbearing.common.errors import InputError

DOFS_PER_NODE = 4
#: Offsets of a node's degrees of freedom in its block of four.
UX, UY, TX, TY = range(DOFS_PER_NODE)
#: Largest distance between a station and the node it is put on [m].
NODE_TOLERANCE = 1e-6
#: A negative eigenvalue of K or of C's symmetric part no larger than this fraction of the largest one's size is
#: round-off (a free-free K has four zero eigenvalues, its rigid motions; float32 exports reach about 4e-11).
SEMI_DEFINITE_TOLERANCE = 1e-8
#: The matrices of a structure, by field, with the array names a .npz file gives them.
MATRICES = {"mass": "M", "stiffness": "K", "gyroscopic": "G", "damping": "C"}
#: Lateral rigid motions of a free-free rotor: two translations and two tilts (:meth:`RotorStructure.rigid_modes`).
RIGID_MOTIONS = 4
#: A generalised eigenvalue of (K, M) beyond the four rigid motions counts as zero (a mechanism) when it is below this
#: many times the largest of the four rigid ones: those are zero in exact arithmetic, so their size is this K and M's
#: round-off (about 1e-16 of the largest eigenvalue in double precision, 1e-10 for a float32 export; the lowest
#: elastic mode of a 1000-node shaft sits at 5e-12).
MECHANISM_FACTOR = 100.0
#: ... and in any case below this fraction of the largest eigenvalue (the round-off floor of double precision).
MECHANISM_FLOOR = 1e-13


@dataclass(frozen=True, eq=False)
class RotorStructure:
    """A free-free rotor's matrices (SI) over ``4 len(nodes)`` degrees of freedom (module docstring)."""

    mass: np.ndarray  #: M [kg, kg m, kg m^2]
    stiffness: np.ndarray  #: K [N/m, N, N m]
    gyroscopic: np.ndarray  #: G, multiplied by the spin speed [kg m^2]
    nodes: np.ndarray  #: axial position of each node [m], in the structure's own frame
    damping: np.ndarray | None = None  #: C [N s/m, ...] (internal damping of the shaft; None: none)
    source: str = "matrices"
    #: the machine file's key the matrices come from, named in an error with the value as written (``given``)
    key: str = "rotor.matrices"
    given: str | None = None  #: the key's value as the user wrote it (None: ``source``)

    def __post_init__(self) -> None:
        n = DOFS_PER_NODE * len(self.nodes)
        given = {name: getattr(self, name) for name in MATRICES if getattr(self, name) is not None}
        for name, value in given.items():
            value = np.asarray(value)
            if np.iscomplexobj(value) or not np.issubdtype(value.dtype, np.number):
                raise self.refuse(MATRICES[name], "must hold real numbers")
            value = value.astype(float)
            if value.ndim != 2 or value.shape[0] != value.shape[1]:
                raise self.refuse(MATRICES[name], f"has shape {value.shape}: it must be a square {n} x {n} matrix, "
                                  "four lateral DOFs per node")
            if not np.all(np.isfinite(value)):
                raise self.refuse(MATRICES[name], "must hold finite numbers only")
            given[name] = value
        sizes = {value.shape[0] for value in given.values()}
        if len(sizes) == 1 and n not in sizes:
            # the matrices agree with each other, so the node list is the likelier mistake
            size = sizes.pop()
            raise self.refuse("nodes", f"holds {len(self.nodes)} nodes: the node list and the matrices disagree, the "
                              f"matrices are {size} x {size}, four lateral DOFs per node for "
                              f"{size / DOFS_PER_NODE:g} nodes")
        for name, value in given.items():
            if value.shape != (n, n):
                raise self.refuse(MATRICES[name], f"has shape {value.shape}: it must be {n} x {n}, four lateral DOFs "
                                  f"per node of the {len(self.nodes)} nodes")
            object.__setattr__(self, name, value)
        if not np.allclose(self.mass, self.mass.T, rtol=1e-9, atol=0.0):
            raise self.refuse("M", "must be symmetric")
        if not np.allclose(self.stiffness, self.stiffness.T, rtol=1e-9, atol=1e-12 * np.abs(self.stiffness).max()):
            raise self.refuse("K", "must be symmetric")
        if not np.allclose(self.gyroscopic, -self.gyroscopic.T, atol=1e-12 * max(np.abs(self.gyroscopic).max(), 1.0)):
            raise self.refuse("G", "must be skew-symmetric (G = -G^T)")
        try:
            # the modal split factors M by Cholesky (scipy's eigh): a matrix it cannot factor has no modes
            np.linalg.cholesky(self.mass)
        except np.linalg.LinAlgError:
            raise self.refuse("M", f"must be symmetric positive definite ({_spectrum(self.mass)})") from None
        if not _semi_definite(self.stiffness):
            raise self.refuse("K", f"must be symmetric positive semi-definite ({_spectrum(self.stiffness)})")
        if self.damping is not None:
            # only the symmetric part dissipates; a skew part is a circulatory or gyroscopic term
            symmetric = 0.5 * (self.damping + self.damping.T)
            if not _semi_definite(symmetric):
                raise self.refuse("C", f"must be positive semi-definite ({_spectrum(symmetric)} for (C + C^T) / 2)")

    @property
    def written(self) -> str:
        """The matrices' key's value as the user wrote it (the file's name), for a message."""
        return self.source if self.given is None else self.given

    def refuse(self, array: str, rule: str) -> InputError:
        """The one-line error of a bad array: the key and file as written, then the array inside it.

        >>> s = rigid_structure(10.0, 0.2, 0.1)
        >>> str(s.with_key("rotor.matrices", "shaft.npz").refuse("C", "must be positive semi-definite"))
        "rotor.matrices = 'shaft.npz': its array 'C' must be positive semi-definite"
        """
        return InputError.for_field(self.key, self.written, f"its array {array!r} {rule}")

    def with_key(self, key: str, given: str | None) -> RotorStructure:
        """The same matrices, named in errors as the machine file's ``key = given`` (no check made again)."""
        named = copy.copy(self)
        object.__setattr__(named, "key", key)
        object.__setattr__(named, "given", given)
        return named

    def mass_centre(self) -> tuple[float, float]:
        """(mass [kg], axial position of the mass centre in the structure's frame [m]), from M alone."""
        origin = self.rigid_modes(0.0)
        mass = float(origin[:, 0] @ self.mass @ origin[:, 0])
        if not mass > 0.0:
            raise self.refuse("M", f"gives the rotor a mass of {mass:g} kg: it must be positive")
        return mass, float(origin[:, 0] @ self.mass @ origin[:, 3]) / mass

    def nodes_at(self, positions) -> list[int]:
        """Indices of the nodes nearest ``positions`` from the mass centre [m], each once, in order."""
        nodes = self.nodes - self.mass_centre()[1]
        return sorted({int(np.argmin(np.abs(nodes - p))) for p in positions})

    def rigid_modes(self, centre: float) -> np.ndarray:
        """(4n, 4): translations x, y and tilts theta_x, theta_y about the axial position ``centre`` (columns)."""
        n = len(self.nodes)
        r = np.zeros((DOFS_PER_NODE * n, 4))
        arm = self.nodes - centre
        r[UX::4, 0] = 1.0
        r[UY::4, 1] = 1.0
        r[UY::4, 2] = -arm
        r[TX::4, 2] = 1.0
        r[UX::4, 3] = arm
        r[TY::4, 3] = 1.0
        return r


def _semi_definite(matrix: np.ndarray) -> bool:
    """True when the symmetric ``matrix`` has no eigenvalue below round-off of its largest (SEMI_DEFINITE_TOLERANCE)."""
    values = np.linalg.eigvalsh(matrix)
    return values.size == 0 or values[0] >= -SEMI_DEFINITE_TOLERANCE * np.abs(values).max()


def _spectrum(matrix: np.ndarray) -> str:
    """The smallest and largest eigenvalues of a symmetric matrix, for a message."""
    values = np.linalg.eigvalsh(matrix)
    return f"eigenvalues from {values[0]:.4g} to {values[-1]:.4g}"


@dataclass(frozen=True, eq=False)
class ModalRotor:
    """A structure split for the kernels: its rigid body and its elastic free-free modes (module docstring)."""

    mass: float  #: [kg]
    transverse_inertia: float  #: J_t about the mass centre [kg m^2]
    polar_inertia: float  #: J_p [kg m^2]
    centre: float  #: axial position of the mass centre in the structure's frame [m]
    frequencies: np.ndarray  #: (n_modes,) free-free natural frequencies at rest [rad/s]
    shapes: np.ndarray  #: (4 n_nodes, n_modes) mass-normalised mode shapes [1/sqrt(kg)]
    modal_damping: np.ndarray  #: (n_modes, n_modes) Phi^T C Phi + diag(2 zeta omega) [1/s]
    modal_gyroscopic: np.ndarray  #: (n_modes, n_modes) Phi^T G Phi [-]
    tilt_gyroscopic: np.ndarray  #: (2, n_modes) R_tilt^T G Phi: the rigid tilts' coupling to the modes [sqrt(kg) m]
    nodes: np.ndarray  #: node positions from the mass centre [m]
    #: of the modes, the last ``residual`` are the static correction's Ritz vectors (:func:`modal_rotor`), not
    #: natural modes of the free shaft: their frequencies lie above the cut and are not reported as the rotor's
    residual: int = 0

    @property
    def natural(self) -> int:
        """Natural (free-free) modes kept, before the static correction's vectors."""
        return self.n_modes - self.residual

    @property
    def n_modes(self) -> int:
        """Elastic modes kept."""
        return len(self.frequencies)

    def node_at(self, position: float, key: str) -> int:
        """Index of the node at ``position`` from the mass centre [m]; ``key`` names the input for the error.

        The error names the position as a file gives it: in the matrices' own node coordinates.
        """
        i = int(np.argmin(np.abs(self.nodes - position)))
        if abs(self.nodes[i] - position) > NODE_TOLERANCE:
            raise InputError.for_field(key, f"{(position + self.centre) * 1e3:.6g} mm", "must sit on a node of the "
                                       f"rotor's matrices (nearest: {(self.nodes[i] + self.centre) * 1e3:.6g} mm)")
        return i

    def station_shapes(self, position: float, key: str) -> tuple[np.ndarray, np.ndarray]:
        """Each mode's x and y displacement at the node at ``position`` from the mass centre."""
        i = self.node_at(position, key)
        return self.shapes[DOFS_PER_NODE * i + UX], self.shapes[DOFS_PER_NODE * i + UY]


def rigid_structure(mass: float, transverse_inertia: float, polar_inertia: float) -> RotorStructure:
    """The rigid rotor as matrices: one node at the mass centre, no stiffness (it has no elastic mode)."""
    m = np.diag([mass, mass, transverse_inertia, transverse_inertia])
    g = np.zeros((4, 4))
    g[TX, TY], g[TY, TX] = polar_inertia, -polar_inertia
    return RotorStructure(m, np.zeros((4, 4)), g, np.zeros(1), source="rigid rotor")


def modal_rotor(structure: RotorStructure, max_frequency: float = math.inf, damping_ratio: float = 0.0,
                correction_nodes=()) -> ModalRotor:
    """Rigid body and elastic modes of a free-free structure up to ``max_frequency`` [rad/s] (module docstring).

    The four rigid motions are the kernel's rotor; a mode is kept with its degenerate partner (an axisymmetric
    shaft has each bending mode twice, in x and in y), so the cut never splits a pair. ``damping_ratio`` adds
    modal viscous damping 2 zeta omega to the structure's own C. With ``correction_nodes`` (node indices: where
    the stations push) the kept modes are followed by the static correction's Ritz vectors
    (:func:`_static_correction`), so a force at those nodes bends the shaft with its whole flexibility.
    """
    s = structure
    m_mat, k_mat = s.mass, s.stiffness
    mass, centre = s.mass_centre()
    rigid = s.rigid_modes(centre)
    rigid_mass = rigid.T @ m_mat @ rigid
    jt = 0.5 * (rigid_mass[2, 2] + rigid_mass[3, 3])
    jp = float(rigid[:, 2] @ s.gyroscopic @ rigid[:, 3])
    _check_inertias(s, float(jt), jp)
    if np.abs(k_mat @ rigid).max() > 1e-6 * max(np.abs(k_mat).max(), 1.0):
        raise s.refuse("K", "ties the rotor to the ground: give the free-free shaft (its bearings are stations)")
    n = m_mat.shape[0]
    if n > RIGID_MOTIONS:
        values, vectors = eigh(k_mat, m_mat)
        _check_mechanism(s, values)
        values, vectors = values[4:], vectors[:, 4:]  # the four rigid motions: K r = 0
        omega = np.sqrt(np.clip(values, 0.0, None))
        keep = int(np.searchsorted(omega, max_frequency, side="right"))
        while 0 < keep < len(omega) and omega[keep] <= omega[keep - 1] * (1.0 + 1e-6):
            keep += 1
        extra_omega, extra = np.zeros(0), np.zeros((n, 0))
        if len(correction_nodes) and keep < len(omega):
            extra_omega, extra = _static_correction(_clean(vectors[:, keep:], rigid, rigid_mass, m_mat),
                                                    omega[keep:], correction_nodes, m_mat, k_mat)
        omega, phi = omega[:keep], _clean(vectors[:, :keep], rigid, rigid_mass, m_mat)
        residual = len(extra_omega)
        omega, phi = np.concatenate([omega, extra_omega]), np.hstack([phi, extra])
    else:
        omega, phi, residual = np.zeros(0), np.zeros((n, 0)), 0
    damping = np.diag(2.0 * damping_ratio * omega)
    if s.damping is not None:
        damping = damping + phi.T @ s.damping @ phi
    return ModalRotor(mass, float(jt), jp, centre, omega, phi, damping, phi.T @ s.gyroscopic @ phi,
                      rigid[:, 2:].T @ s.gyroscopic @ phi, s.nodes - centre, residual)


def _check_inertias(s: RotorStructure, jt: float, jp: float) -> None:
    """Refuse matrices whose rigid body no body can be: J_p < 0, or J_p above 2 J_t.

    J_p = sum of m r^2 over the rotor's mass about the spin axis, so it is not negative for any body (G holds +J_p
    of each disk at [theta_x, theta_y]; a G of the opposite sign convention gives it negative). J_p = 0 is a
    structure without gyroscopic terms (a beam analysed at rest): its modes stand, but it is no rotor to spin
    (:func:`check_spinning`). The perpendicular-axis theorem bounds J_p by the transverse moment: with the spin axis
    z, J_p = int(x^2 + y^2) dm and 2 J_t = int(x^2 + z^2) dm + int(y^2 + z^2) dm = J_p + 2 int z^2 dm, so
    J_p <= 2 J_t, equal for a flat disc (for a body of any shape, I_1 <= I_2 + I_3).
    """
    if jp < 0.0:
        raise _no_polar_inertia(s, jp)
    if jp > 2.0 * jt * (1.0 + 1e-6):
        raise s.refuse("G", f"gives a polar inertia J_p = {jp:.4g} kg*m**2, {jp / jt:.3g} times the transverse "
                       f"inertia J_t = {jt:.4g} kg*m**2 that 'M' gives; no body has J_p above 2 J_t (the "
                       "perpendicular-axis theorem: J_p = 2 J_t - 2 int z^2 dm)")


def _no_polar_inertia(s: RotorStructure, jp: float) -> InputError:
    return s.refuse("G", f"gives a polar inertia <= 0 (J_p = {jp:.4g} kg*m**2, G[theta_x, theta_y] summed over the "
                    "nodes); a rotor's J_p, the sum of m r^2 about its axis, is positive, and G holds +J_p of each "
                    "disk at [theta_x, theta_y]: a G of the opposite sign convention must be negated")


def check_spinning(structure: RotorStructure, body: ModalRotor) -> None:
    """Refuse a structure as a machine's rotor when its G gives no polar inertia (J_p = 0, as G = 0 gives).

    A spinning rotor's gyroscopic moment J_p Omega and its spin equation J_p dOmega/dt = torque need J_p > 0:
    every body with mass off its axis has it (J_p = sum of m r^2). :func:`modal_rotor` itself takes J_p = 0 (a
    beam's modes at rest); a machine's rotor does not.
    """
    if not body.polar_inertia > 0.0:
        raise _no_polar_inertia(structure, body.polar_inertia)


def _check_mechanism(s: RotorStructure, values: np.ndarray) -> None:
    """Refuse a K with more zero eigenvalues than the four rigid motions of a free-free lateral rotor.

    The rigid motions (x, y translations, theta_x, theta_y tilts) are K's only zero-energy motions in a connected
    shaft; a further one is a mechanism (a node left unconnected, a hinge, K = 0): it has no restoring force, and
    its "mode" at 0 Hz would be taken as an elastic one. ``values`` are the generalised eigenvalues of (K, M),
    ascending; the four lowest are the rigid motions, and their size (zero in exact arithmetic) is the round-off
    against which a further eigenvalue counts as zero (:data:`MECHANISM_FACTOR`, :data:`MECHANISM_FLOOR`).
    """
    top = float(np.abs(values).max())
    noise = float(np.abs(values[:RIGID_MOTIONS]).max())
    zero = max(MECHANISM_FACTOR * noise, MECHANISM_FLOOR * top)
    count = int(np.sum(values <= zero))
    if count > RIGID_MOTIONS:
        raise s.refuse("K", f"has {count} zero eigenvalues (rigid motions): a free-free lateral rotor has four (two "
                       f"translations, two tilts), so {count - RIGID_MOTIONS} more are a mechanism, motions no "
                       "stiffness resists (an unconnected node, a hinge, a K of zeros)")


def _clean(phi: np.ndarray, rigid: np.ndarray, rigid_mass: np.ndarray, m_mat: np.ndarray) -> np.ndarray:
    """Modes cleaned of any rigid part (round-off), then mass-normalised again."""
    phi = phi - rigid @ np.linalg.solve(rigid_mass, rigid.T @ m_mat @ phi)
    return phi / np.sqrt(np.einsum("ij,ij->j", phi, m_mat @ phi))


def _static_correction(dropped: np.ndarray, omega: np.ndarray, nodes, m_mat: np.ndarray, k_mat: np.ndarray
                       ) -> tuple[np.ndarray, np.ndarray]:
    """Ritz vectors that carry the flexibility of the modes left out, for forces at ``nodes`` (x and y each).

    A unit force at a station's DOF d deflects the free-free shaft, beyond its rigid (inertia-relief) motion, by
    sum over all elastic modes of phi_j phi_j[d] / omega_j^2; the kept modes carry their part, and the residual
    psi_d = sum over the modes left out of phi_j phi_j[d] / omega_j^2 is the static correction (the residual
    flexibility attachment modes, Craig & Kurdila, *Fundamentals of Structural Dynamics*, 2nd ed. 2006,
    Sec. 17.4; used as extra Ritz vectors, the modal truncation augmentation of Dickens, Nakagawa & Wittbrodt,
    Computers & Structures 62 (1997) 985-998). The psi span a subspace M- and K-orthogonal to the rigid body and
    to the kept modes; solving K and M on it gives vectors of the same kind as the modes (mass-normalised,
    uncoupled), so the kernels take them as further modes. Their frequencies lie above the cut. A static force at
    the nodes is then resolved exactly, whatever the cut. Returns (frequencies [rad/s], vectors (4n, p)).
    """
    omega = np.where(omega > 0.0, omega, np.inf)
    dofs = sorted({DOFS_PER_NODE * int(i) + w for i in nodes for w in (UX, UY)})
    psi = dropped @ (dropped[dofs].T / omega[:, None] ** 2)
    # an M-orthonormal basis of their span (vectors that repeat another's direction are dropped)
    gram = psi.T @ m_mat @ psi
    size, turn = eigh(0.5 * (gram + gram.T))
    keep = size > 1e-10 * size.max()
    basis = psi @ (turn[:, keep] / np.sqrt(size[keep]))
    stiff = basis.T @ k_mat @ basis
    values, vectors = eigh(0.5 * (stiff + stiff.T))
    ritz = basis @ vectors
    return np.sqrt(np.clip(values, 0.0, None)), ritz


# ----------------------------------------------------------------------------- a shaft built here
def _beam_element(length: float, ei: float, rho_a: float) -> tuple[np.ndarray, np.ndarray]:
    """Euler-Bernoulli element in one lateral plane, DOFs (w1, w1', w2, w2'): stiffness and consistent mass.

    The Hermite-cubic element (Przemieniecki, *Theory of Matrix Structural Analysis*, 1968: its beam stiffness
    and consistent mass; the rotor form in Friswell et al. 2010, Ch. 5), without rotary inertia.
    """
    L = length
    k = ei / L**3 * np.array([[12, 6 * L, -12, 6 * L], [6 * L, 4 * L * L, -6 * L, 2 * L * L],
                              [-12, -6 * L, 12, -6 * L], [6 * L, 2 * L * L, -6 * L, 4 * L * L]])
    m = rho_a * L / 420.0 * np.array([[156, 22 * L, 54, -13 * L], [22 * L, 4 * L * L, 13 * L, -3 * L * L],
                                      [54, 13 * L, 156, -22 * L], [-13 * L, -3 * L * L, -22 * L, 4 * L * L]])
    return k, m


def beam_structure(nodes, outer_diameters, density: float, youngs_modulus: float, inner_diameters=None,
                   disks=(), rotary_inertia: bool = True) -> RotorStructure:
    """A stepped shaft of Euler-Bernoulli elements between ``nodes`` [m] with rigid disks on nodes.

    ``outer_diameters`` (and ``inner_diameters``) give each element's section; ``disks`` are
    (node index, mass, J_t, J_p). In the x-z plane w = x and w' = theta_y; in the y-z plane w = y and
    w' = -theta_x (module docstring's signs). With ``rotary_inertia`` each element's transverse and polar
    inertia is lumped half on each of its nodes (the polar part gives the shaft's gyroscopic terms).
    """
    nodes = np.asarray(nodes, float)
    n = len(nodes)
    outer = np.broadcast_to(np.asarray(outer_diameters, float), (n - 1,))
    inner = np.zeros(n - 1) if inner_diameters is None else np.broadcast_to(np.asarray(inner_diameters, float),
                                                                             (n - 1,))
    size = DOFS_PER_NODE * n
    m_mat, k_mat, g_mat = np.zeros((size, size)), np.zeros((size, size)), np.zeros((size, size))
    for e in range(n - 1):
        L = nodes[e + 1] - nodes[e]
        area = math.pi / 4.0 * (outer[e] ** 2 - inner[e] ** 2)
        second = math.pi / 64.0 * (outer[e] ** 4 - inner[e] ** 4)
        ke, me = _beam_element(L, youngs_modulus * second, density * area)
        for w, slope, sign in ((UX, TY, 1.0), (UY, TX, -1.0)):
            dofs = [4 * e + w, 4 * e + slope, 4 * (e + 1) + w, 4 * (e + 1) + slope]
            t = np.diag([1.0, sign, 1.0, sign])  # the plane's slope w' in the node's rotation
            idx = np.ix_(dofs, dofs)
            k_mat[idx] += t @ ke @ t
            m_mat[idx] += t @ me @ t
        if rotary_inertia:
            for node in (e, e + 1):
                half_t = 0.5 * density * second * L
                m_mat[4 * node + TX, 4 * node + TX] += half_t
                m_mat[4 * node + TY, 4 * node + TY] += half_t
                g_mat[4 * node + TX, 4 * node + TY] += 2.0 * half_t
                g_mat[4 * node + TY, 4 * node + TX] -= 2.0 * half_t
    for node, mass, jt, jp in disks:
        i = 4 * int(node)
        m_mat[i + UX, i + UX] += mass
        m_mat[i + UY, i + UY] += mass
        m_mat[i + TX, i + TX] += jt
        m_mat[i + TY, i + TY] += jt
        g_mat[i + TX, i + TY] += jp
        g_mat[i + TY, i + TX] -= jp
    return RotorStructure(m_mat, k_mat, g_mat, nodes, source="beam")


def read_structure(spec: str, base: Path | None, field: str) -> RotorStructure:
    """A rotor's matrices from a ``.npz`` file (relative to ``base``): arrays M, K, G, nodes and optionally C (SI).

    ``nodes`` are the axial positions of the nodes [m]; the matrices run over four DOFs per node in the order
    and with the signs of the module docstring. ``field`` names the key in an error.
    """
    path = Path(spec) if base is None or Path(spec).is_absolute() else base / spec
    if not path.is_file():
        raise InputError.for_field(field, spec, "no such file (a .npz of the arrays M, K, G, nodes and optionally C)")
    unreadable = "cannot be read as an .npz file (numpy.savez's zip of arrays)"
    try:
        size = path.stat().st_size
        path.open("rb").close()
    except OSError as err:
        raise InputError.for_field(field, spec, f"cannot be read ({_one_line(err)})") from None
    if not size:
        raise InputError.for_field(field, spec, f"{unreadable}: the file is empty")
    if not zipfile.is_zipfile(path):
        # np.load would go on to try .npy and pickle, and blame those
        raise InputError.for_field(field, spec, f"{unreadable}: it is not a zip archive, or not a whole one")
    try:
        with np.load(path, allow_pickle=False) as arrays:
            data = {name: np.asarray(arrays[name]) for name in arrays.files}
    except (OSError, ValueError, EOFError, zipfile.BadZipFile, zlib.error) as err:
        raise InputError.for_field(field, spec, f"{unreadable}: {_one_line(err)}") from None
    for name in ("M", "K", "G", "C", "nodes"):
        value = data.get(name)
        if value is None:
            continue
        if np.iscomplexobj(value) or not np.issubdtype(value.dtype, np.number):
            raise InputError.for_field(field, spec, f"its array {name!r} must hold real numbers (it holds "
                                       f"{value.dtype})")
        data[name] = value.astype(float)
    for name in ("M", "K", "G", "nodes"):
        if name not in data:
            raise InputError.for_field(field, spec, f"has no array {name!r} (it holds {sorted(data)}); give M, K, G, "
                                       "nodes and optionally C")
    nodes = data["nodes"]
    if nodes.ndim != 1 or len(nodes) < 1 or not np.all(np.isfinite(nodes)) or np.any(np.diff(nodes) <= 0.0):
        raise InputError.for_field(field, spec, "its 'nodes' must be axial positions in metres, strictly increasing")
    return RotorStructure(data["M"], data["K"], data["G"], nodes, data.get("C"), source=path.name, key=field,
                          given=spec)


def _one_line(err: Exception) -> str:
    return " ".join(str(err).split()) or type(err).__name__
