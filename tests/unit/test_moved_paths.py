"""Module paths from before the rooms stay importable (auxbearing._moved), the issue interfaces' among them."""

import pytest

import auxbearing


def test_the_life_interface_of_the_bearings_issue():
    from auxbearing.life import dynamic_load_rating

    assert dynamic_load_rating(auxbearing.get_bearing("7208")) == pytest.approx(34.5e3, rel=0.01)


def test_old_paths_find_names_where_they_live_now():
    import auxbearing.drop as old_drop
    from auxbearing.coastdown import run_coastdown
    from auxbearing.statics import safety_factor

    from auxbearing.analysis.drop import run_machine
    from auxbearing.machine import Machine, read_machine
    from auxbearing.planar.rig import run_drop

    assert old_drop.run_machine is run_machine and old_drop.run_drop is run_drop
    assert callable(run_coastdown) and isinstance(read_machine("paper_rig"), Machine)
    assert float(safety_factor(2100e6)) == pytest.approx(8.0)


def test_a_name_that_never_existed_is_an_attribute_error():
    import auxbearing.drop as old_drop

    with pytest.raises(AttributeError):
        old_drop.no_such_name  # noqa: B018
