"""`[[linear_support]]` in a machine file: read with units, every bad value one line naming the key as written."""

import copy

import pytest

from auxbearing.common.errors import InputError
from auxbearing.machine.files import machine_table
from auxbearing.machine.model import machine_from_mapping


def _machine(*supports):
    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    data["linear_support"] = list(supports)
    return machine_from_mapping(data, "blower", base)


def test_a_support_is_read_with_its_units():
    m = _machine({"name": "seal", "position": "50 mm", "kxx": "2 N/um", "kxy": "-3e5 N/m", "cyy": "0.5 N*s/mm"})
    (seal,) = [s for s in m.stations if s.KIND == "linear_support"]
    assert (seal.name, seal.position, seal.kxx, seal.kxy, seal.cyy) == ("seal", 0.05, 2e6, -3e5, 500.0)
    described = [s for s in m.describe()["stations"] if s["kind"] == "linear_support"]
    assert described[0]["kxx_N_per_m"] == 2e6


@pytest.mark.parametrize(("table", "expected"), [
    ({"kxx": "1e6 N/m"}, "linear_support.0.position: missing"),
    ({"position": "0 m", "kxx": 1e6}, "linear_support.0.kxx = 1000000.0: needs a unit"),
    ({"position": "0 m", "cxx": "-5 N*s/m"}, "linear_support.0.cxx = '-5 N*s/m'"),
    ({"position": "0 m", "kzz": "1 N/m"}, "linear_support.0.kzz = '1 N/m': unknown key"),
    ({"position": "0 m", "kxx": "1 kg"}, "linear_support.0.kxx = '1 kg'"),
])
def test_bad_support_values_name_the_key(table, expected):
    with pytest.raises(InputError) as err:
        _machine(table)
    assert str(err.value).startswith(expected) and "\n" not in str(err.value)


def test_a_support_table_that_is_not_a_list_of_tables_is_refused():
    data, _, base = machine_table("blower")
    data = copy.deepcopy(data)
    data["linear_support"] = {"position": "0 m"}
    with pytest.raises(InputError, match="linear_support"):
        machine_from_mapping(data, "blower", base)
