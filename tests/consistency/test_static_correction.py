"""The static correction of the modal reduction (machine.structure.modal_rotor) against the full matrices.

A free-free shaft pushed at its stations deflects, beyond its rigid (inertia-relief) motion, by the sum over
all its elastic modes of phi phi^T f / omega^2. With the kept modes followed by the static correction's Ritz
vectors for forces at those stations, the reduced model gives that deflection exactly whatever the cut; with the
modes alone it misses the part of the modes left out. Self-consistency: the reference is the same matrices'
complete eigen-expansion.
"""

import numpy as np
import pytest
from scipy.linalg import eigh

from auxbearing.machine.structure import beam_structure, modal_rotor

NODES = np.linspace(-0.4, 0.4, 33)
STATIONS = (2, 12, 24, 31)  # node indices where stations push


def _shaft():
    return beam_structure(NODES, 0.05, 7850.0, 2.1e11, disks=((28, 6.0, 0.02, 0.03),))


def _elastic_deflection(shaft, force):
    """sum over every elastic mode of phi phi^T f / omega^2 (the four rigid motions left out)."""
    values, vectors = eigh(shaft.stiffness, shaft.mass)
    return vectors[:, 4:] @ ((vectors[:, 4:].T @ force) / values[4:])


def _reduced_deflection(body, force):
    return body.shapes @ ((body.shapes.T @ force) / body.frequencies**2)


def _station_forces(seed):
    rng = np.random.default_rng(seed)
    force = np.zeros(4 * len(NODES))
    for i in STATIONS:
        force[4 * i:4 * i + 2] = rng.normal(0.0, 100.0, 2)  # x and y at the station
    return force


@pytest.mark.parametrize("cut_hz", [500.0, 1500.0, 4000.0])
def test_a_static_force_at_the_stations_is_resolved_exactly_at_any_cut(cut_hz):
    shaft = _shaft()
    corrected = modal_rotor(shaft, 2 * np.pi * cut_hz, correction_nodes=STATIONS)
    plain = modal_rotor(shaft, 2 * np.pi * cut_hz)
    assert corrected.residual == 2 * len(STATIONS) and corrected.natural == plain.n_modes
    for seed in range(3):
        force = _station_forces(seed)
        exact = _elastic_deflection(shaft, force)
        scale = np.abs(exact).max()
        assert np.abs(_reduced_deflection(corrected, force) - exact).max() < 1e-8 * scale
        assert np.abs(_reduced_deflection(plain, force) - exact).max() > 1e-3 * scale  # what the cut leaves out


def test_the_correction_vectors_are_modes_of_the_same_kind_and_leave_the_kept_ones_alone():
    shaft = _shaft()
    corrected = modal_rotor(shaft, 2 * np.pi * 1500.0, correction_nodes=STATIONS)
    plain = modal_rotor(shaft, 2 * np.pi * 1500.0)
    phi, omega = corrected.shapes, corrected.frequencies
    assert np.allclose(phi.T @ shaft.mass @ phi, np.eye(corrected.n_modes), atol=1e-9)
    stiffness = phi.T @ shaft.stiffness @ phi
    assert np.allclose(stiffness, np.diag(omega**2), atol=1e-9 * omega.max() ** 2)
    assert np.abs(shaft.rigid_modes(corrected.centre).T @ shaft.mass @ phi).max() < 1e-9  # no rigid motion
    assert np.array_equal(omega[:corrected.natural], plain.frequencies)
    assert np.array_equal(phi[:, :corrected.natural], plain.shapes)
    assert omega[corrected.natural:].min() > plain.frequencies.max()  # above the cut
