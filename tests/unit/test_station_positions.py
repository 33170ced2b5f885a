"""Every ``position`` of a machine file tells the user where it is measured from and which way is positive.

The kernels place planes, stations, loads and unbalance planes by their distance from the rotor's mass centre
along the spin axis; a rotor of matrices keeps its model's coordinates, which the reader moves to the mass centre.
The help text (and docs/machine_file.md, made from it) says so, with the direction of +z.
"""

from __future__ import annotations

import copy

import pytest

from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping
from auxbearing.machine.params import TOUCHDOWN, UNBALANCE
from auxbearing.machine.scenario import DOC_PARAMS
from auxbearing.machine.stations import kinds


def _position_rows():
    rows = [*UNBALANCE, *TOUCHDOWN, *DOC_PARAMS]
    for kind in kinds():
        rows += kind.PARAMS
    return [p for p in rows if p.key == "position"]


def test_there_is_a_position_in_every_table_that_places_something_on_the_rotor():
    assert {p.section for p in _position_rows()} == {"unbalance", "touchdown", "scenario", "amb", "linear_support",
                                                      "load"}


@pytest.mark.parametrize("row", _position_rows(), ids=lambda p: p.section)
def test_a_position_says_its_origin_its_direction_and_the_matrices_exception(row):
    assert "from the rotor's mass centre along the spin axis z" in row.help
    assert "positive towards +z" in row.help and "counter-clockwise" in row.help and "vertical machine" in row.help
    assert "rotor.matrices" in row.help and "nodes" in row.help


def test_a_sensor_position_is_measured_like_the_actuators():
    from auxbearing.machine.stations.amb import TABLE

    assert "same origin and in the same direction as position" in TABLE["sensor_position"].help


def test_a_rigid_rotor_places_its_planes_from_the_mass_centre():
    # the nearer plane to the mass centre carries the larger share of the weight: 0.3 / 0.4 of it at -0.1 m
    data, name, base = machine_table("paper_rig_two_planes")
    data = copy.deepcopy(data)
    data["touchdown"][0]["position"], data["touchdown"][1]["position"] = "-100 mm", "300 mm"
    machine = machine_from_mapping(data, name, base)
    assert [p.position for p in machine.planes] == pytest.approx([-0.1, 0.3])
    assert machine.rest_share(0) == pytest.approx(0.75)


@pytest.mark.slow  # reads the compressor's matrices
def test_a_rotor_of_matrices_keeps_its_own_frame_moved_to_the_mass_centre():
    data, name, base = machine_table("compressor")
    machine = machine_from_mapping(data, name, base)
    written = [float(t["position"].removesuffix(" mm")) * 1e-3 for t in data["touchdown"]]
    centre = written[0] - machine.planes[0].position
    assert centre == pytest.approx(0.3954, abs=1e-4)  # the file's comment: the mass centre is at 395.4 mm
    assert [p.position for p in machine.planes] == pytest.approx([w - centre for w in written])
