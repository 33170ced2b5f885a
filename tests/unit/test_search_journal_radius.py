"""The geometry search changes a clearance at the journal: a journal radius given in the file follows it."""

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
