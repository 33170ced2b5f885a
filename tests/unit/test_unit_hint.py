"""A bare number's hint names the unit that makes it a plausible value, not always the same unit.

"ball_material.elastic_modulus = 310000: needs a unit, e.g. '310000 GPa'" suggested 310 TPa for a silicon
nitride written in MPa; the hint now takes, of the dimension's usual units, the one that puts the number nearest
the parameter's default (or the dimension's example value where there is none).
"""

import copy

import pytest

from auxbearing.bearings.materials import material_from_mapping
from auxbearing.common.errors import InputError
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping


@pytest.mark.parametrize(("modulus", "unit"), [(310000, "MPa"), (310, "GPa"), (3.1e11, "Pa")])
def test_a_bare_modulus_is_hinted_in_the_unit_it_was_written_in(modulus, unit):
    with pytest.raises(InputError, match=rf"^elastic_modulus = {modulus}: needs a unit, e\.g\. '{modulus} {unit}'$"):
        material_from_mapping({"elastic_modulus": modulus, "poisson_ratio": 0.27}, "Si3N4", "user input")


@pytest.mark.parametrize(("section", "key", "value", "unit"),
                         [("drop", "duration", 200, "ms"), ("drop", "duration", 0.2, "s"), ("rotor", "mass", 5, "kg")])
def test_a_bare_machine_value_is_hinted_near_its_default(section, key, value, unit):
    data, name, base = machine_table("blower")
    data = copy.deepcopy(data)
    data[section][key] = value
    with pytest.raises(InputError, match=rf"^{section}\.{key} = {value}: needs a unit, e\.g\. '{value} {unit}'$"):
        machine_from_mapping(data, name, base)
