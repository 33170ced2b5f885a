"""The geometry search and the campaign change a clearance at the journal: a seated journal radius follows it."""

import math

import numpy as np
import pytest

from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping
from auxbearing.verify.designs import _design_tables


@pytest.mark.parametrize("factor", [0.6, 1.0, 1.4])
def test_a_given_journal_radius_keeps_the_race_bore(factor):
    # the heavy rotor gives journal_radius = 19.85 mm with 0.15 mm of clearance in a 40 mm bore: before, every
    # search point above the file's clearance was refused ("the race bore would be 20.06 mm in radius")
    data, name, base = machine_table("heavy_fast_rotor")
    machine = machine_from_mapping(data, name, base)
    plane = machine.planes[0]
    x = np.array([plane.bearing.contact_angle, plane.bearing.inner_groove_ratio, factor])
    varied = machine_from_mapping(_design_tables(data, machine, x), name, base).planes[0]
    assert varied.radial_clearance == pytest.approx(factor * plane.radial_clearance, rel=1e-12)
    assert varied.journal_radius + varied.radial_clearance == pytest.approx(
        plane.journal_radius + plane.radial_clearance, rel=1e-12)
    assert math.isclose(plane.journal_radius + plane.radial_clearance, 0.5 * plane.bearing.bore, rel_tol=1e-9)


def test_the_campaign_derives_a_seated_journal_from_each_sampled_clearance():
    # the campaign spreads the clearance by the bore's and journal's fit tolerances; with the journal radius kept,
    # 56 of the heavy rotor's 128 drops were refused ("the race bore would be 20.01 mm in radius")
    from auxbearing.machine.judging import verify_settings
    from auxbearing.verify.cases import campaign_tables

    data, name, base = machine_table("heavy_fast_rotor")
    machine = machine_from_mapping(data, name, base)
    tables = campaign_tables(data, machine, verify_settings(data), 8, {})
    spread = next(i for i in tables["campaign"]["input"] if i["key"] == "touchdown.0.radial_clearance")
    assert "journal_radius" not in tables["touchdown"][0]
    tables["touchdown"][0]["radial_clearance"] = spread["high"]
    widest = machine_from_mapping(tables, name, base).planes[0]
    assert widest.radial_clearance > machine.planes[0].radial_clearance
    assert widest.journal_radius + widest.radial_clearance == pytest.approx(0.5 * widest.bearing.bore, rel=1e-12)
    tables["touchdown"][0]["radial_clearance"] = "0.15 mm"
    assert machine_from_mapping(tables, name, base).planes[0].journal_radius == pytest.approx(
        machine.planes[0].journal_radius, rel=1e-12)
