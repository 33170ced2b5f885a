"""The Campbell diagram of the linear model (analysis.modes) against closed forms.

Self-consistency with textbook algebra: a rigid rotor (m, J_t, J_p) on two isotropic linear supports of
stiffness k at +-a: translation at sqrt(2 k / m); tilt at w = (+-J_p W + sqrt((J_p W)^2 + 4 J_t K)) / (2 J_t)
with K = 2 k a^2, forward (+) rising and backward (-) falling with the spin W (Friswell et al. 2010, Sec. 3.5);
the free-free beam's bending frequencies when nothing holds it (Blevins' values are checked in
tests/validation/test_blevins_1979_free_free_beam.py).
"""

import copy
import math

import numpy as np
import pytest

from auxbearing.analysis.modes import campbell, linear_matrices, swing_stiffness
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping

K, A, M, JT, JP = 1.0e6, 0.15, 10.0, 0.2, 0.015


def _blower(supports=True):
    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    for key in ("criteria", "candidate", "amb", "scenario"):  # the rigid rotor on linear supports alone
        data.pop(key)
    if supports:
        data["linear_support"] = [{"position": f"{s * A} m", "kxx": f"{K} N/m", "kyy": f"{K} N/m"} for s in (-1, 1)]
    return machine_from_mapping(data, "blower", base)


def test_rigid_rotor_on_two_supports_whirls_as_the_closed_form():
    speeds = [0.0, 1000.0, 2000.0]
    d = campbell(_blower(), speeds)
    for i, w in enumerate(speeds):
        s = math.sqrt((JP * w) ** 2 + 8.0 * JT * K * A * A)
        expected = sorted([math.sqrt(2 * K / M)] * 2 + [(JP * w + s) / (2 * JT), (-JP * w + s) / (2 * JT)])
        assert d.frequencies[i] * 2 * math.pi == pytest.approx(expected, rel=1e-10)
    # at speed the tilt pair splits: the higher one whirls forward, the lower backward; translation is a pair
    assert list(d.whirl[-1]) == ["backward", "pair", "pair", "forward"]
    assert list(d.whirl[0]) == ["pair"] * 4


def test_critical_speeds_are_where_the_synchronous_line_meets_a_forward_mode():
    speeds = np.linspace(0.0, 1000.0, 201)
    crit = [c["speed_rpm"] for c in campbell(_blower(), speeds).critical_speeds()]
    translation = math.sqrt(2 * K / M) * 30 / math.pi  # the Jeffcott rotor's sqrt(k/m)
    # the forward tilt: J_t w^2 - J_p w^2 = K at w = W
    tilt = math.sqrt(2 * K * A * A / (JT - JP)) * 30 / math.pi
    assert sorted(crit) == pytest.approx(sorted([translation, translation, tilt]), rel=1e-4)


def test_in_contact_each_plane_is_a_spring_and_free_nothing_holds_the_blower():
    machine = _blower(supports=False)
    free = campbell(machine, [0.0])
    assert free.frequencies.shape[1] == 0  # a free rigid rotor: rigid-body motions only
    contact = campbell(machine, [0.0], "contact")
    assert all(k > 0.0 for k in contact.contact_stiffness)
    _, _, _, stiff, _ = linear_matrices(machine, "contact")
    assert np.allclose(stiff, stiff.T)
    # the rigid rotor on two equal planes at +-0.15 m: along the weight the contact springs, translation sqrt(2 k / m);
    # across it the swings, sqrt(2 k_s / m)
    k, swing = contact.contact_stiffness[0], swing_stiffness(machine, 0)
    assert sorted(contact.frequencies[0, [0, 2]]) == pytest.approx(
        [math.sqrt(2 * swing / M) / (2 * math.pi), math.sqrt(2 * k / M) / (2 * math.pi)], rel=1e-9)
    assert list(contact.whirl[0]) == ["planar"] * 4


def test_a_journal_resting_in_its_bore_swings_as_a_pendulum_of_the_clearance_and_the_unbalance_drives_it():
    machine = _blower(supports=False)
    plane = machine.planes[0]
    weight = 0.5 * M * machine.simulation.gravity
    assert swing_stiffness(machine, 0) < weight / plane.radial_clearance  # in series with ball set and mount
    # the simple pendulum of length c, sqrt(g / c) / (2 pi) = 40.7 Hz; the ball set and mount take 1 % off
    pendulum = math.sqrt(machine.simulation.gravity / plane.radial_clearance) / (2.0 * math.pi)
    speeds = np.linspace(0.0, 3000.0 * math.pi / 30.0, 61)
    contact = campbell(machine, speeds, "contact")
    assert contact.frequencies[0, 0] == pytest.approx(pendulum, rel=0.02)
    # a line orbit at every speed (a translation: the spin does not couple it), so the 1x line meets it at its
    # frequency; full dynamics loads the blower's journals more near that speed (analysis.coastdown)
    assert set(contact.whirl[:, 0]) == {"planar"}
    crit = min(c["speed_rpm"] for c in contact.critical_speeds())
    assert crit == pytest.approx(60.0 * contact.frequencies[0, 0], rel=1e-3)
