"""The machine model against its own derivations (issue 12's validation list).

Not published numbers: identities the equations must satisfy. The paper's planar drop as the
symmetric two-plane machine; the free gyroscopic rotor (nutation at J_p Omega / J_t, Friswell et al.,
Dynamics of Rotating Machines, 2010, Sec. 3.5); the lever rule and the static solver at rest; a
four-point plane under thrust against the static solver; a mount's rest deflection m g / k and its
damped free vibration (single-degree-of-freedom oscillator); the energy audit of every run.
"""

import math

import numpy as np
import pytest

from auxbearing.analysis.drop import run_machine
from auxbearing.analysis.statics import solve_cases
from auxbearing.bearings.ballset import ballset_params
from auxbearing.core import drive
from auxbearing.core import integrate as ig
from auxbearing.core import machine as cm
from auxbearing.core import watch as cw
from auxbearing.machine.files import machine_names, read_machine
from auxbearing.machine.model import machine_from_mapping
from auxbearing.machine.pack import pack

G = 9.80665


def _machine(rotor: dict, planes: list[dict], drop: dict | None = None, orientation="horizontal"):
    return machine_from_mapping({"machine": {"name": "test", "orientation": orientation}, "rotor": rotor,
                                 "touchdown": planes, "drop": drop or {}})


def _integrate(km, y, t_end, n_out=0, out_step=1.0):
    memory = ig.new_memory(0.0, 1e-7, y.size)
    grid = np.empty((n_out, y.size))
    if n_out:
        grid[0] = y
        memory.next_output[0] = 1
    watch = cw.new_watch(y.size, len(km.machine.planes.active), 1.0, 2, km.energy0)
    settings = km.settings._replace(output_step=out_step, step_budget=10**9)
    status = drive.advance(km.machine, watch, y, t_end, settings, memory, grid)
    return status, grid


@pytest.mark.slow
def test_symmetric_two_plane_rotor_is_the_planar_drop_at_each_plane():
    one = run_machine(read_machine("paper_rig")).summary["planes"][0]
    two = run_machine(read_machine("paper_rig_two_planes")).summary["planes"]
    for plane in two:
        for key in ("peak_contact_force_N", "peak_ball_stress_MPa", "first_impact_ms"):
            assert plane[key] == pytest.approx(one[key], rel=1e-4), key
        # the force at the end is one instant of the race ringing on its contacts, whose velocity the integration
        # holds to pack.RACE_VELOCITY_SCALE times the rotor's scale: the two runs (different step sequences) end
        # 3.4e-4 apart (11.3698 and 11.3736 N) about the value tolerances ten times tighter give both (11.3707 N)
        assert plane["final_contact_force_N"] == pytest.approx(one["final_contact_force_N"], rel=1e-3)


def test_free_rotor_nutates_at_jp_omega_over_jt_and_keeps_energy_and_momentum():
    """No contact, no gravity: theta_dot turns at J_p Omega / J_t; L = (J_t theta_dot_x + J_p Omega theta_y,
    J_t theta_dot_y - J_p Omega theta_x) and the kinetic energy stay constant."""
    m = _machine({"mass": "3 kg", "polar_inertia": "0.004 kg*m^2", "transverse_inertia": "0.01 kg*m^2",
                  "speed": "6000 rpm"},
                 [{"bearing": "QJ202", "position": "-80 mm", "radial_clearance": "2 mm", "journal_radius": "5 mm"},
                  {"bearing": "QJ202", "position": "80 mm", "radial_clearance": "2 mm", "journal_radius": "5 mm"}],
                 {"gravity": "0 m/s^2", "rtol": 1e-10, "atol": 1e-10})
    km = pack(m)
    y = km.y0.copy()
    y[cm.WX] = 0.02  # rad/s: a small knock
    omega = y[cm.OMEGA]
    rate = 0.004 * omega / 0.01
    period = 2 * math.pi / rate
    n = 201
    status, grid = _integrate(km, y, period, n, period / (n - 1))
    assert status == ig.FINISHED
    np.testing.assert_allclose(grid[-1, [cm.WX, cm.WY]], [0.02, 0.0], atol=1e-8)  # one turn of theta_dot
    angle = np.unwrap(np.arctan2(grid[:, cm.WY], grid[:, cm.WX]))
    assert angle[-1] - angle[0] == pytest.approx(2 * math.pi, rel=1e-6)
    lx = 0.01 * grid[:, cm.WX] + 0.004 * omega * grid[:, cm.TY]
    ly = 0.01 * grid[:, cm.WY] - 0.004 * omega * grid[:, cm.TX]
    np.testing.assert_allclose(lx, lx[0], atol=1e-12 * 0.004 * omega)
    np.testing.assert_allclose(ly, ly[0], atol=1e-12 * 0.004 * omega)
    energy = 0.5 * 0.01 * (grid[:, cm.WX] ** 2 + grid[:, cm.WY] ** 2)
    np.testing.assert_allclose(energy, energy[0], rtol=1e-9)


@pytest.mark.slow
def test_rotor_at_rest_shares_its_weight_by_the_lever_rule_and_sags_as_statics_says():
    """Mass centre at a = 0.05 m from plane 0 and 0.15 m from plane 1 of a 4 kg rotor with no spin: the
    planes carry 3/4 and 1/4 of its weight; each race sits where the static solver puts it under that
    contact force plus its own weight."""
    planes = [{"name": "near", "bearing": "QJ202", "position": "-50 mm", "radial_clearance": "0.2 mm"},
              {"name": "far", "bearing": "QJ202", "position": "150 mm", "radial_clearance": "0.2 mm"}]
    m = _machine({"mass": "4 kg", "polar_inertia": "1e-3 kg*m^2", "transverse_inertia": "0.02 kg*m^2",
                  "speed": "0 rpm"}, planes, {"duration": "0.4 s", "output_step": "1 ms"})
    run = run_machine(m)
    assert run.summary["verdict"] == "ok"
    weight = 4 * G
    shares = (0.75, 0.25)
    for k, plane in enumerate(run.summary["planes"]):
        assert plane["final_contact_force_N"] == pytest.approx(shares[k] * weight, rel=2e-3)
        race = m.planes[k].race_mass * G
        sol = solve_cases([[0.0, 0.0, -(shares[k] * weight + race), 0.0, 0.0]], ballset_params(m.planes[k].bearing),
                          free=(False, True, True, False, False))
        assert float(run.dataset.race_y.isel(plane=k).values[-1]) == pytest.approx(sol.displacement[0, 2], rel=2e-3)


@pytest.mark.slow
@pytest.mark.parametrize("thrust", [500.0, -500.0])
def test_four_point_plane_under_thrust_settles_with_the_static_axial_displacement(thrust):
    m = _machine({"mass": "2 kg", "polar_inertia": "1e-3 kg*m^2", "speed": "0 rpm", "axial_force": f"{thrust} N"},
                 [{"bearing": "QJ202", "radial_clearance": "0.2 mm", "axial_clearance": "1 um"}],
                 {"gravity": "0 m/s^2", "duration": "0.3 s", "output_step": "1 ms"})
    run = run_machine(m)
    plane = run.summary["planes"][0]
    assert run.summary["verdict"] == "ok"
    assert plane["final_axial_force_N"] == pytest.approx(thrust, rel=1e-3)
    sol = solve_cases([[thrust, 0.0, 0.0, 0.0, 0.0]], ballset_params(m.planes[0].bearing),
                      free=(True, False, False, False, False))
    assert float(run.dataset.race_z.isel(plane=0).values[-1]) == pytest.approx(sol.displacement[0, 0], rel=1e-3)


def test_mount_rest_deflection_and_damped_free_vibration():
    """An outer ring m1 on a mount k, c carrying the race m2 on its ball set (the journal far away): the ring
    rests at (m1 + m2) g / k and vibrates in the lower mode of the two-mass system (the ball set's tangent
    stiffness at the race weight couples the masses) at w_d = w_1 sqrt(1 - zeta^2), with the log decrement
    2 pi zeta / sqrt(1 - zeta^2) of zeta = c / (2 sqrt(k (m1 + m2)))."""
    k, c, ring = 2e6, 60.0, 0.3
    m = _machine({"mass": "1 kg", "polar_inertia": "1e-4 kg*m^2", "speed": "0 rpm"},
                 [{"bearing": "QJ208", "radial_clearance": "19 mm", "journal_radius": "1 mm", "race_mass": "0.1 kg",
                   "mount_stiffness": f"{k} N/m", "mount_damping": f"{c} N*s/m", "mount_mass": f"{ring} kg",
                   "ball_damping": "0 N*s/m", "rolling_friction": 0.0}],
                 {"duration": "0.05 s", "output_step": "20 us", "rtol": 1e-9, "atol": 1e-9})
    run = run_machine(m)
    assert run.summary["verdict"] == "ok" and run.summary["planes"][0]["impacts"] == 0
    mass = ring + 0.1
    ball = solve_cases([[0.0, 0.0, -0.1 * G, 0.0, 0.0]], ballset_params(m.planes[0].bearing),
                       free=(False, True, True, False, False)).displacement[0, 2]
    k_ball = 1.5 * 0.1 * G / abs(ball)  # tangent of F ~ u^1.5: dF/du = 1.5 F / u
    stiffness = np.array([[k + k_ball, -k_ball], [-k_ball, k_ball]])
    w_1 = math.sqrt(min(np.linalg.eigvals(np.linalg.solve(np.diag([ring, 0.1]), stiffness)).real))
    ring_y = run.dataset.ring_y.isel(plane=0).values
    t = run.dataset.time.values
    rest = -mass * G / k
    # oscillation of the ring about its rest position
    x = ring_y - rest
    crossings = t[1:][np.diff(np.sign(x)) > 0]
    w_d = 2 * math.pi / np.mean(np.diff(crossings))
    zeta = c / (2 * math.sqrt(k * mass))
    assert w_d == pytest.approx(w_1 * math.sqrt(1 - zeta**2), rel=0.01)
    peaks = [x[i] for i in range(1, x.size - 1) if x[i] > x[i - 1] and x[i] >= x[i + 1] and x[i] > 0]
    decrement = math.log(peaks[0] / peaks[4]) / 4
    assert decrement == pytest.approx(2 * math.pi * zeta / math.sqrt(1 - zeta**2), rel=0.05)
    assert float(np.mean(ring_y[-200:])) == pytest.approx(rest, rel=0.02)


@pytest.mark.parametrize("name", [n for n in machine_names() if n != "heavy_fast_rotor"])
def test_energy_audit_closes_on_every_example(name):
    summary = run_machine(read_machine(name), duration=0.05).summary
    assert abs(summary["energy_balance_error"]) < 1e-6
    assert summary["largest_energy_error"] < 1e-6


def test_heavy_fast_rotor_stops_with_its_cause():
    summary = run_machine(read_machine("heavy_fast_rotor")).summary
    # the journal contact stays within its material's limit (a conformal contact at ~200 MPa); the balls run
    # over the groove shoulder under backward whirl, a physical end of the bearing's range
    assert summary["verdict"] == "contact_ellipse_over_shoulder"
    assert "QJ208" in summary["reason"] and "ms" in summary["reason"]
    plane = summary["planes"][0]
    # a failing run still reports what the model saw up to its stop
    assert plane["peak_ball_stress_MPa"] > 3000.0 and plane["s0"] is not None
    assert 100.0 < plane["peak_journal_pressure_MPa"] < 4000.0
    assert plane["peaks_cover"].startswith("the run up to its stop")


@pytest.mark.slow
def test_whirl_verdict_of_a_settled_run_does_not_change_when_extended():
    machine = read_machine("paper_rig")
    short = run_machine(machine, duration=0.15).summary["planes"][0]
    long = run_machine(machine, duration=0.3).summary["planes"][0]
    assert short["whirl"] == long["whirl"]
    assert short["backward_whirl_onset_ms"] == long["backward_whirl_onset_ms"]
