"""What a machine file says once and means: the geometry search of a design on a matched pair keeps the pair
(issue: every search point of a '7208 DB' design was one row without preload), and keys that contradict or are
ignored by the rest of the file are refused."""

import math

import pytest

from auxbearing.common.errors import InputError
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping
from auxbearing.verify.designs import recommended_tables

REC = {"contact_angle_deg": 30.0, "inner_groove_ratio": 0.52, "clearance_factor": 1.0}


def _on(bearing: str, preload: str | None = None):
    data, name, base = machine_table("blower")
    for plane in data["touchdown"]:
        plane["bearing"] = bearing
        plane["axial_room"] = "40 mm"
        if preload is not None:
            plane["preload"] = preload
    return data, name, base


@pytest.mark.parametrize(("bearing", "preload", "kept"), [
    ("7208 DB", None, "light"), ("7208 DF medium", None, "medium"), ("7208 DB", "500 N", "500 N"),
    ("7208 DB", "8 um", "8 um offset"),
])
def test_the_recommended_geometry_of_a_pair_is_a_pair_of_the_new_rows(bearing, preload, kept):
    data, name, base = _on(bearing, preload)
    design = machine_from_mapping(data, name, base)
    machine = machine_from_mapping(recommended_tables(data, name, base, REC), name, base)
    for before, after in zip(design.planes, machine.planes, strict=True):
        pair = after.bearing_set
        assert pair is not None and pair.arrangement == before.bearing_set.arrangement and after.rows == 2
        assert pair.preload == kept
        assert after.bearing.contact_angle == pytest.approx(math.radians(30.0))
        if kept.endswith("offset"):
            assert pair.preload_offset == pytest.approx(before.bearing_set.preload_offset, rel=1e-12)


def test_an_inline_row_with_an_arrangement_is_checked_as_a_pair():
    data, name, base = _on("7208 DB")
    recommended = recommended_tables(data, name, base, REC)
    recommended["touchdown"][0]["bearing"]["arrangement"] = "XY"
    with pytest.raises(InputError, match=r"^touchdown.0.bearing.arrangement = 'XY': must be one of DB, DF, DT"):
        machine_from_mapping(recommended, name, base)
    data, name, base = machine_table("blower")  # its QJ208 is a four-point bearing
    data["touchdown"][0]["bearing"] = {**machine_from_mapping(data, name, base).planes[0].bearing.to_table(),
                                       "arrangement": "DB"}
    with pytest.raises(InputError, match=r"^touchdown.0.bearing.arrangement = 'DB': a matched pair needs an "
                                         r"angular-contact row"):
        machine_from_mapping(data, name, base)


def test_a_preload_given_twice_is_refused():
    # issue: bearing = "7208 DB medium" with preload = "heavy" quietly ran heavy
    data, name, base = _on("7208 DB medium", "heavy")
    with pytest.raises(InputError, match=r"^touchdown.0.preload = 'heavy': the bearing's name gives its preload "
                                         r"already \('7208 DB medium'\); give it once"):
        machine_from_mapping(data, name, base)


@pytest.mark.parametrize(("key", "value"), [("modal_damping", 0.02), ("max_mode_frequency", "2 kHz"),
                                            ("reduction", "modal")])
def test_keys_of_an_elastic_rotor_on_a_rigid_one_are_refused(key, value):
    # issue: they were quietly dropped, as if the rotor bent with them
    data, name, base = machine_table("blower")
    data["rotor"][key] = value
    with pytest.raises(InputError, match=rf"^rotor.{key} = .*: applies to a rotor given by its matrices"):
        machine_from_mapping(data, name, base)
