"""The rotor axis' orbit anywhere along the rotor (the report's orbits at the stations and at mid-span) is the
journal's orbit where a touchdown plane sits: rigid motion and, on an elastic rotor, its modes' shapes there."""

import numpy as np
import pytest

from auxbearing.analysis.drop import run_machine
from auxbearing.machine.files import read_machine
from auxbearing.plots.drop import axis_orbit, orbit_positions


@pytest.mark.parametrize("name", ["blower", "compressor"])
def test_the_axis_at_a_plane_is_that_planes_journal(name):
    machine = read_machine(name)
    ds = run_machine(machine, duration=0.01).dataset
    for k, plane in enumerate(machine.planes):
        x, y = axis_orbit(machine, ds, plane.position)
        assert np.max(np.abs(x - ds.journal_x.values[:, k])) < 1e-12
        assert np.max(np.abs(y - ds.journal_y.values[:, k])) < 1e-12
    places = dict(orbit_positions(machine))
    assert "mid-span" in places and all(s.name in places for s in machine.stations
                                        if s.KIND == "amb" and not s.axial)
