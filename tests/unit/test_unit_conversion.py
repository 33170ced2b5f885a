"""Converting a user's value to SI: the remembered conversions give what a fresh parse gives, errors included."""

import pytest

from auxbearing.common.errors import InputError
from auxbearing.common.params import _convert, convert


@pytest.mark.parametrize("value, dimension, expected", [
    ("0.2 mm", "length", 2e-4), ("10 mm/s", "velocity", 1e-2), ("100 Hz", "angular_speed", 628.3185307179587),
    (100.0, "angular_speed", 100.0), (3, "length", 3.0), ("20 degC", "temperature", 293.15),
])
def test_a_remembered_conversion_equals_a_fresh_one(value, dimension, expected):
    first = convert("field", value, dimension)
    again = convert("field", value, dimension)
    assert first == again == _convert("field", value, dimension, None) == pytest.approx(expected, rel=1e-12)


def test_an_error_names_the_field_it_was_asked_for_each_time():
    # the same bad text in two fields: each error names its own field (a failed conversion is not remembered)
    for field in ("rotor.mass", "touchdown.radial_clearance", "rotor.mass"):
        with pytest.raises(InputError, match=field.replace(".", r"\.")):
            convert(field, "5 kg", "length")


def test_a_number_in_another_default_unit_is_not_taken_for_the_same_conversion():
    assert convert("clearance", 0.2, "length", "mm") == pytest.approx(2e-4)
    assert convert("clearance", 0.2, "length") == 0.2


def test_a_temperature_below_absolute_zero_is_refused_in_terms_of_absolute_zero():
    # issue: '-273.15 degC' was refused as "must be > 0" while '-10 degC' passed, a rule a person reads in degC
    from auxbearing.common.errors import InputError
    from auxbearing.machine.model import machine_from_mapping

    data = {"rotor": {"mass": "10 kg", "polar_inertia": "0.015 kg*m^2", "speed": "3000 rpm"},
            "touchdown": [{"bearing": "QJ208", "radial_clearance": "0.15 mm"}],
            "coastdown": {"ambient_temperature": "-273.15 degC"}}
    with pytest.raises(InputError, match=r"^coastdown.ambient_temperature = '-273.15 degC': must be above absolute "
                                         r"zero \(0 K, -273.15 degC\)$"):
        machine_from_mapping(data)
    data["coastdown"]["ambient_temperature"] = "-10 degC"
    assert machine_from_mapping(data).coastdown.ambient_temperature == pytest.approx(263.15)
