"""Duplex sets against the single row's statics and closed forms (consistency checks).

* A back-to-back pair without preload under pure axial load: one row carries it, exactly as the single
  bearing's statics (auxbearing.analysis.statics) solve it; with preload, above lift-off, the same with the
  shaft's displacement shifted by the preload push.
* Under pure radial load: the set equals twice one row at the preload's axial displacement.
* The preload from an axial offset against Harris & Kotzalas (2007, Ch. 7): delta_a = A sin(alpha -
  alpha0)/cos(alpha), F_a = Z K(alpha) delta_n^1.5 sin(alpha), delta_n = A (cos(alpha0)/cos(alpha) - 1).
* Back-to-back is stiffer in tilt than face-to-face (wider load-line spread); the pair's C is 2^0.7 C.
"""

import math

import numpy as np
import pytest

from auxbearing import get_bearing
from auxbearing.analysis.life import dynamic_load_rating, static_load_rating
from auxbearing.analysis.statics import load_distribution
from auxbearing.bearings.ballset import ballset_params, hertz_tables
from auxbearing.bearings.duplex import duplex_set, offset_for_preload, row_axial_force
from auxbearing.bearings.duplex_statics import load_distribution as set_distribution
from auxbearing.bearings.duplex_statics import set_reaction, solve_set
from auxbearing.core.ballset import accumulate


def test_unpreloaded_db_under_axial_load_is_one_row():
    row = get_bearing("7208")
    pair = duplex_set(row, "DB", preload="none")
    single = load_distribution(row, axial=[500.0, 3000.0])
    both = set_distribution(pair, axial=[500.0, 3000.0])
    np.testing.assert_allclose(both.axial_displacement.values, single.axial_displacement.values, rtol=1e-6)
    np.testing.assert_allclose(both.row_axial_load.values[:, 0], [500.0, 3000.0], rtol=1e-8)
    np.testing.assert_allclose(both.row_axial_load.values[:, 1], 0.0, atol=1e-9)
    np.testing.assert_allclose(both.max_contact_load.values, single.max_contact_load.values, rtol=1e-6)


def test_preloaded_db_above_lift_off_is_one_row_shifted():
    row = get_bearing("7208")
    pair = duplex_set(row, "DB", preload="medium")
    fa = 4000.0  # far above lift-off (about 2.8 x preload)
    single = load_distribution(row, axial=fa)
    both = set_distribution(pair, axial=fa)
    shift = pair.row_preload_displacement
    assert float(both.row_axial_load[0, 1]) == pytest.approx(0.0, abs=1e-9)
    assert float(both.axial_displacement[0]) == pytest.approx(float(single.axial_displacement[0]) - shift, rel=1e-6)


def test_db_under_radial_load_is_twice_a_row_at_the_preload_shift():
    row = get_bearing("7208")
    pair = duplex_set(row, "DB", preload="light")
    fr = 3000.0
    ds = set_distribution(pair, radial=fr)
    dx = float(ds.radial_displacement[0])
    assert float(ds.tilt[0]) == pytest.approx(0.0, abs=1e-12)
    force = np.zeros(5)
    accumulate(np.array([pair.row_preload_displacement, dx, 0.0, 0.0, 0.0]), ballset_params(row), 0.0, force,
               np.zeros((5, 5)), False, False)
    assert -2.0 * force[1] == pytest.approx(fr, rel=1e-7)
    np.testing.assert_allclose(ds.row_radial_load.values[0], [0.5 * fr, 0.5 * fr], rtol=1e-7)


@pytest.mark.parametrize("offset", [2e-6, 8e-6, 20e-6])
def test_preload_from_offset_against_harris_closed_form(offset):
    row = get_bearing("7208")
    big_a, alpha0, z = row.curvature_centre_distance, row.contact_angle, row.ball_count
    delta_a = 0.5 * offset
    # delta_a = A sin(alpha - alpha0)/cos(alpha): solve for the loaded angle
    lo, hi = alpha0, alpha0 + 0.5
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if big_a * math.sin(mid - alpha0) / math.cos(mid) < delta_a else (lo, mid)
    alpha = 0.5 * (lo + hi)
    nodes, tables = hertz_tables(row)
    k = float(np.interp(alpha, nodes, tables[0, 0]))
    delta_n = big_a * (math.cos(alpha0) / math.cos(alpha) - 1.0)
    closed = z * k * delta_n**1.5 * math.sin(alpha)
    pair = duplex_set(row, "DB", preload=f"{offset * 1e6} um")
    assert pair.preload_force == pytest.approx(closed, rel=1e-5)
    assert offset_for_preload(row, closed) == pytest.approx(offset, rel=1e-6)


def test_unloaded_pair_balances_and_db_is_stiffer_in_tilt():
    db, df = get_bearing("7208 DB"), get_bearing("7208 DF")
    force, _, rows = set_reaction(db, np.zeros(5))
    np.testing.assert_allclose(force, 0.0, atol=1e-6)
    assert row_axial_force(db.row, rows[0][0]) == pytest.approx(db.preload_force)
    tilt_db = abs(solve_set(db, [0, 0, 0, 0, 50.0])["displacement"][3])
    tilt_df = abs(solve_set(df, [0, 0, 0, 0, 50.0])["displacement"][3])
    assert tilt_db < 0.5 * tilt_df


def test_pair_ratings():
    assert dynamic_load_rating("7208 DB") == pytest.approx(2**0.7 * dynamic_load_rating("7208"))
    assert static_load_rating("7208 DT") == pytest.approx(2 * static_load_rating("7208"))
