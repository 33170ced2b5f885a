"""Bearing names that would be read as something else than written are refused, each with its own rule."""

import pytest

from auxbearing.bearings.catalogue import get_bearing
from auxbearing.common.errors import InputError


@pytest.mark.parametrize(("name", "rule"), [
    ("7208 DB medium heavy", "two preloads (medium, heavy)"),  # the last one won
    ("7208 DB light 500 N", "two preloads (light, 500 N)"),
    ("7208 DB DF", "two arrangements (DB, DF)"),  # a DF pair came out
    ("7208 BECBP/DBC", "a matched pair ('DBC') is not read from a maker's suffix"),  # each gave one row
    ("7208 BECBPDB", "a matched pair ('BECBPDB')"),
    ("7208 BECBP/2DB", "a matched pair ('2DB')"),
    ("7208 DBA", "a matched pair ('DBA')"),  # said only the 40 deg B design was in the catalogue
    ("7208 DB -3 um", "its preload '-3 um': must be a finite length >= 0 m"),  # quoted -3e-06
])
def test_a_name_read_otherwise_than_written_is_refused(name, rule):
    with pytest.raises(InputError) as err:
        get_bearing(name, "--candidates")
    assert str(err.value).startswith(f"--candidates = '{name}': ") and rule in str(err.value)


@pytest.mark.parametrize("name", ["7208 BECBP", "7208 BECBP/DB medium", "QJ208 N2MA", "6208 2RS1", "6208-2Z"])
def test_maker_codes_that_change_nothing_still_read(name):
    get_bearing(name)


def test_the_command_line_names_the_preloads_own_rule_not_no_such_bearing():
    from auxbearing.machine.judging import _check_bearing_name

    with pytest.raises(InputError, match=r"^--candidates = '7208 DB 5 kg': its preload '5 kg': must be light"):
        _check_bearing_name("7208 DB 5 kg", "--candidates")
    with pytest.raises(InputError, match="neither a catalogue bearing"):
        _check_bearing_name("7208X", "--candidates")


def test_a_candidate_without_a_name_is_refused():
    from auxbearing.machine.files import machine_table
    from auxbearing.machine.judging import candidate_tables

    data, _, _ = machine_table("blower")
    with pytest.raises(InputError, match=r"^candidate\.0\.name = ' ': must not be empty"):
        candidate_tables(data, [{"name": " ", "bearing": "6208"}])
