"""How the dents of successive drops add up: the setting, its reading from a machine file, its effect."""

import pytest

from auxbearing import get_bearing
from auxbearing.analysis.life import _drops_until_a_spot_fills, dent_per_drop
from auxbearing.common.errors import InputError
from auxbearing.machine.model import machine_from_mapping

MACHINE = {"machine": {"name": "m"}, "rotor": {"mass": "1.48 kg", "polar_inertia": "3.88e-4 kg*m^2",
                                               "speed": "6000 rpm"},
           "touchdown": [{"name": "QJ202", "bearing": "QJ202", "radial_clearance": "0.2 mm"}]}


def test_spread_dents_need_more_drops_on_the_rotating_race_only():
    same = dent_per_drop(1000.0, get_bearing("QJ202"))
    spread = dent_per_drop(1000.0, get_bearing("QJ202"), "spread")
    assert spread["inner"]["drops_to_dent_limit"] > 10 * same["inner"]["drops_to_dent_limit"]
    assert spread["outer"]["drops_to_dent_limit"] == same["outer"]["drops_to_dent_limit"]
    assert spread["drops_to_dent_limit"] >= same["drops_to_dent_limit"]
    assert "spread" in spread["assumption"] and "same spot" in same["assumption"]


def test_a_spot_fills_sooner_with_fewer_spots_and_fewer_hits():
    assert _drops_until_a_spot_fills(1.0, 500.0) == 1.0
    assert _drops_until_a_spot_fills(4.0, 100.0) < _drops_until_a_spot_fills(4.0, 1000.0)
    assert _drops_until_a_spot_fills(3.0, 100.0) < _drops_until_a_spot_fills(6.0, 100.0)


def test_the_setting_is_read_from_the_life_table_and_a_bad_value_refused():
    machine = machine_from_mapping({**MACHINE, "life": {"dent_accumulation": "spread"}})
    assert machine.life.dent_accumulation == "spread"
    assert machine_from_mapping(MACHINE).life.dent_accumulation == "same_spot"
    with pytest.raises(InputError, match=r"life\.dent_accumulation"):
        machine_from_mapping({**MACHINE, "life": {"dent_accumulation": "anywhere"}})
