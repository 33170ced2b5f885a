"""A matched pair's stress at rest counts its own preload as well as the clearance thermal growth closes."""

import pytest

from auxbearing.analysis.coastdown import rest_stress
from auxbearing.bearings.ballset import ballset_params
from auxbearing.machine.files import machine_table
from auxbearing.machine.judging import candidate_tables
from auxbearing.machine.model import machine_from_mapping


def _plane(bearing: str):
    data, name, base = machine_table("blower")
    ((_, tables),) = candidate_tables(data, [bearing])
    plane = machine_from_mapping(tables, name, base).planes[0]
    return plane, ballset_params(plane.bearing, plane.ball_constant)


def test_the_preload_of_a_pair_adds_to_the_closing_and_grows_with_the_class():
    stresses = {}
    for name in ("7208 DB light", "7208 DB 8 um", "7208 DB heavy"):
        plane, ballset = _plane(name)
        stresses[name] = (rest_stress(plane, ballset, 0.0), rest_stress(plane, ballset, -5.07e-6))
    # the preload alone stresses the balls, and more of it or a closed clearance more
    assert 0.0 < stresses["7208 DB light"][0] < stresses["7208 DB 8 um"][0] < stresses["7208 DB heavy"][0]
    assert all(closed > alone for alone, closed in stresses.values())
    # each row of an 8 um set is pushed 4 um into its balls
    assert _plane("7208 DB 8 um")[0].bearing_set.row_preload_displacement == pytest.approx(4e-6)


def test_a_single_row_is_stressed_at_rest_only_once_its_clearance_has_closed():
    plane, ballset = _plane("7208")
    assert rest_stress(plane, ballset, 5e-6) == 0.0 and rest_stress(plane, ballset, -5e-6) > 0.0


def test_a_machine_of_two_bearing_families_gets_no_geometry_search_and_says_why():
    import copy

    from auxbearing.verify.designs import search_refused

    data, name, base = machine_table("blower")
    assert search_refused(machine_from_mapping(data, name, base)) is None
    mixed = copy.deepcopy(data)
    mixed["touchdown"][0]["bearing"] = "6208"  # the non-drive end stays a QJ208
    reason = search_refused(machine_from_mapping(mixed, name, base))
    assert "different families (deep groove, four point)" in reason


def test_a_four_point_bearing_at_zero_degrees_is_refused():
    from auxbearing.bearings.catalogue import get_bearing
    from auxbearing.common.errors import InputError

    with pytest.raises(InputError, match="two contacts per ring coincide at 0 deg"):
        get_bearing("QJ202").with_changes(contact_angle=0.0)
