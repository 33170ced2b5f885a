"""A linear support (a station kind beside the touchdown planes) against the closed form of a Jeffcott rotor.

Self-consistency with textbook algebra, not published numbers. A rigid rotor of mass m held at its mass
centre by a support of direct stiffness k, damping c and cross-coupled stiffness q (k_xy = q, k_yx = -q)
obeys m z'' + c z' + (k - i q) z = F in z = x + i y; its two roots lambda (np.roots) give the whirl frequency
and the growth or decay rate of the orbit about its static point. The forward whirl goes unstable once q
exceeds c sqrt(k/m) (the cross-coupling's classic threshold). The touchdown plane's clearance is 5 mm, so
the journal never touches it.
"""

import copy

import numpy as np
import pytest

from auxbearing.analysis.drop import run_machine
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping
from auxbearing.machine.pack import pack

MASS, K, C = 10.0, 1.0e6, 200.0


def _held_rotor(cross: float, duration="0.6 s"):
    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    for key in ("criteria", "candidate", "amb", "scenario"):
        data.pop(key)
    data["rotor"] = {"mass": f"{MASS} kg", "polar_inertia": "0.015 kg*m^2", "speed": "0 rpm", "start_x": "0.1 mm"}
    plane = data["touchdown"][0]
    plane.update(position="0 m", radial_clearance="5 mm")
    plane.pop("axial_clearance", None)
    data["touchdown"] = [plane]
    data["linear_support"] = [{"name": "seal", "position": "0 m", "kxx": f"{K} N/m", "kyy": f"{K} N/m",
                               "kxy": f"{cross} N/m", "kyx": f"{-cross} N/m", "cxx": f"{C} N*s/m",
                               "cyy": f"{C} N*s/m"}]
    data["drop"] = {"duration": duration}
    return machine_from_mapping(data, "held rotor", base)


def _growth_rate(run, cross: float) -> tuple[float, float]:
    """(fitted growth rate of the orbit about the static point [1/s], the forward root's own)."""
    ds = run.dataset
    z = ds["journal_x"].values[:, 0] + 1j * ds["journal_y"].values[:, 0]
    static = -1j * MASS * 9.80665 / (K - 1j * cross)
    t = ds["time"].values
    late = t > 0.3 * t[-1]  # the backward root has died away
    slope = np.polyfit(t[late], np.log(np.abs(z[late] - static)), 1)[0]
    roots = np.roots([MASS, C, K - 1j * cross])
    forward = roots[np.argmax(roots.imag)]
    return slope, forward.real


@pytest.mark.parametrize("ratio", [0.5, 1.5])
def test_cross_coupling_past_c_omega_n_makes_the_forward_whirl_grow(ratio):
    cross = ratio * C * np.sqrt(K / MASS)
    run = run_machine(_held_rotor(cross))
    assert run.summary["verdict"] == "ok"
    assert run.summary["planes"][0]["impacts"] == 0
    fitted, theory = _growth_rate(run, cross)
    assert np.sign(fitted) == np.sign(ratio - 1.0)
    assert fitted == pytest.approx(theory, rel=0.01)  # measured: -4.993 against -4.998, +4.9908 against +4.9907


def test_the_support_books_the_work_of_its_cross_coupling_and_damping():
    machine = _held_rotor(0.5 * C * np.sqrt(K / MASS), duration="0.2 s")
    model = pack(machine)
    assert model.layout.stations == (1, 0, 0)  # one linear support, no magnetic bearing, no load
    assert model.layout.names[model.layout.stations_at] == "support_loss_0"
    run = run_machine(machine)
    assert abs(run.summary["largest_energy_error"]) < 1e-6
    # the force series is the support's law on the journal's motion there
    ds = run.dataset
    fx = ds["support_force_x"].values[:, 0]
    x, y = ds["journal_x"].values[:, 0], ds["journal_y"].values[:, 0]
    vx = ds["rotor_vx"].values
    q = 0.5 * C * np.sqrt(K / MASS)
    assert fx == pytest.approx(-(K * x + q * y + C * vx), rel=1e-9, abs=1e-9)
    assert list(ds["support"].values) == ["seal"]
