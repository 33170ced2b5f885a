"""A matched pair's heat: Palmgren's load-free torque of both its rows, and a thermal network of both rows.

M_0 = 1e-7 f_0 (nu n)^(2/3) d_m^3 is one bearing's torque (Harris & Kotzalas 2007, Essential Concepts, Ch. 10): a
back-to-back pair of 7208s turns two bearings' oil. Before, the pair's plane got one row's M_0 (212.5 W at the blower's
drop speed, against 396 W for two rows) and its heat went into one row's balls and rings.
"""

import pytest

from auxbearing.analysis.coastdown import _static_share, plane_network
from auxbearing.analysis.coastdown_phases import _viscous
from auxbearing.analysis.thermal import BALLS, INNER_RACE, OUTER_RACE
from auxbearing.core.bearing_friction import palmgren_viscous_torque
from auxbearing.machine.pack import pack
from tests.consistency.test_duplex_plane import _blower


def test_a_pair_turns_two_rows_of_oil():
    single, pair = _blower("7208").planes[0], _blower("7208 DB").planes[0]
    speed = 1884.0
    one_row = palmgren_viscous_torque(pair.lubricant_viscosity, speed, pair.bearing.pitch_diameter,
                                      pair.viscous_factor)
    assert one_row > 0.0
    assert _viscous(pair, speed) == pytest.approx(2.0 * one_row) and _viscous(single, speed) == pytest.approx(one_row)
    packed = pack(_blower("7208 DB")).machine.planes
    assert packed.viscous_factor[0] == pytest.approx(2.0 * pair.viscous_factor)


def test_a_pair_s_network_holds_both_rows():
    single_machine, pair_machine = _blower("7208"), _blower("7208 DB")
    single = plane_network(single_machine, 0, _static_share(single_machine, 0) / 15)
    pair = plane_network(pair_machine, 0, _static_share(pair_machine, 0) / 30)
    assert pair.masses[BALLS] == pytest.approx(2.0 * single.masses[BALLS])
    for ring in (INNER_RACE, OUTER_RACE):  # no spacer: twice the width
        assert pair.masses[ring] == pytest.approx(2.0 * single.masses[ring])
    # twice the contacts, each at half the load: more conductance than one row's, less than twice
    assert single.conductances[INNER_RACE, BALLS] < pair.conductances[INNER_RACE, BALLS] < (
        2.0 * single.conductances[INNER_RACE, BALLS])
