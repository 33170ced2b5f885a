"""Invariants of the ball-set model and the static equilibrium (hypothesis)."""

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st

from auxbearing import get_bearing
from auxbearing.analysis.statics import solve_cases
from auxbearing.bearings import ballset as bs

QJ202 = get_bearing("QJ202")
BEARINGS = {
    "QJ202": QJ202,
    "QJ202+Pd": QJ202.with_changes(diametral_clearance=12e-6),
    "7202": get_bearing("7202"),
    "209": get_bearing("209"),
}
PARAMS = {name: bs.ballset_params(b) for name, b in BEARINGS.items()}
RIC = {name: b.inner_curvature_centre_radius for name, b in BEARINGS.items()}

forces = st.floats(-3000.0, 3000.0)
moments = st.floats(-10.0, 10.0)
displacements = st.floats(-30e-6, 30e-6)
tilts = st.floats(-2e-3, 2e-3)


@settings(max_examples=40, deadline=None)
@given(name=st.sampled_from(["QJ202", "QJ202+Pd", "209"]), fa=forces, fx=forces, fy=forces, mx=moments, my=moments)
def test_equilibrium_residual_within_envelope(name, fa, fx, fy, mx, my):
    """Every load in |F| <= 3 kN, |M| <= 10 N m converges and the ball forces balance it to 1e-9."""
    p = PARAMS[name]
    load = np.array([fa, fx, fy, mx, my])
    sol = solve_cases(load, p)
    force = bs.ballset_state(sol.displacement[0], p).force
    w = np.array([1, 1, 1, 1 / RIC[name], 1 / RIC[name]])
    ref = np.max(np.abs(load) * w)
    assert np.max(np.abs(load + force) * w) <= 1e-9 * ref + 1e-12


@settings(max_examples=40, deadline=None)
@given(fa=st.floats(200.0, 3000.0), fx=forces, fy=forces, mx=st.floats(-2.0, 2.0), my=st.floats(-2.0, 2.0))
def test_angular_contact_equilibrium_with_axial_load(fa, fx, fy, mx, my):
    """A single angular-contact bearing pressed by Fa >= 200 N carries the rest of the envelope."""
    p = PARAMS["7202"]
    load = np.array([fa, fx, fy, mx, my])
    sol = solve_cases(load, p)
    assert sol.relative_residual[0] <= 1e-9


@settings(max_examples=30, deadline=None)
@given(fa=st.floats(1.0, 3000.0), fr=st.floats(0.0, 3000.0), m=moments)
def test_mirror_symmetry_swaps_four_point_pairs(fa, fr, m):
    """Fa -> -Fa (and the moment's axial sense) swaps pair 1 and pair 2 of a four-point bearing."""
    p = PARAMS["QJ202"]
    a = solve_cases([fa, fr, 0.0, 0.0, m], p).displacement[0]
    b = solve_cases([-fa, fr, 0.0, 0.0, -m], p).displacement[0]
    np.testing.assert_allclose(b[[0, 4]], -a[[0, 4]], rtol=1e-7, atol=1e-14)
    np.testing.assert_allclose(b[1], a[1], rtol=1e-7, atol=1e-14)
    sa, sb = bs.ballset_state(a, p), bs.ballset_state(b, p)
    np.testing.assert_allclose(sb.load[:, ::-1], sa.load, rtol=1e-6, atol=1e-9 * sa.load.max())
    np.testing.assert_allclose(sb.contact_angle[:, ::-1], sa.contact_angle, rtol=1e-7)


@settings(max_examples=30, deadline=None)
@given(name=st.sampled_from(["QJ202", "7202", "209"]), f1=st.floats(50.0, 3000.0), ratio=st.floats(1.05, 3.0))
def test_stiffness_grows_with_load(name, f1, ratio):
    """Hertz Q ~ delta^1.5: the radial stiffness dFr/d(delta_r) rises with radial load."""
    p = PARAMS[name]
    free = (False, True, True, False, False)  # ring axially located and square: pure radial stiffness
    k = []
    for fr in (f1, f1 * ratio):
        u = solve_cases([0.0, fr, 0.0, 0.0, 0.0], p, free=free).displacement[0]
        k.append(-bs.ballset_state(u, p).jacobian[1, 1])
    assert k[1] > k[0] > 0.0


@settings(max_examples=30, deadline=None)
@given(fa=forces, fr=forces, m=moments, dfa=st.floats(-1.0, 1.0), dfr=st.floats(-1.0, 1.0))
def test_solution_is_continuous_in_the_load(fa, fr, m, dfa, dfr):
    """A 1 N change of load moves the ring by a bounded amount (no jumps between branches)."""
    p = PARAMS["QJ202"]
    a = solve_cases([fa, fr, 0.0, 0.0, m], p).displacement[0]
    b = solve_cases([fa + dfa, fr + dfr, 0.0, 0.0, m], p).displacement[0]
    scale = np.array([1, 1, 1, RIC["QJ202"], RIC["QJ202"]])
    # bound: 1 N on a near-unloaded four-point ring still moves it < 3 um (Hertz at a single pair)
    assert np.max(np.abs(b - a) * scale) < 3e-6


@settings(max_examples=40, deadline=None)
@given(name=st.sampled_from(sorted(BEARINGS)), a=displacements, x=displacements, y=displacements, tx=tilts, ty=tilts,
       c=st.floats(1.1, 4.0))
def test_loads_never_negative_and_follow_compression(name, a, x, y, tx, ty, c):
    """Q >= 0; Q > 0 only where S > A; moving further into the contact never lowers a pair load."""
    p = PARAMS[name]
    s = bs.ballset_state([a, x, y, tx, ty], p)
    assert np.all(s.load >= 0.0)
    assert np.all(s.load[s.compression <= 0.0] == 0.0)
    assert np.all(s.compression[s.load > 0.0] > 0.0)  # (Q may underflow to 0 at S - A ~ 1e-250 m)
    pd = BEARINGS[name].diametral_clearance
    radial = bs.ballset_state([0.0, pd / 2 + 1e-6, 0.0, 0.0, 0.0], p).load[0]
    radial_more = bs.ballset_state([0.0, c * (pd / 2 + 1e-6), 0.0, 0.0, 0.0], p).load[0]
    assert np.all(radial_more >= radial)
