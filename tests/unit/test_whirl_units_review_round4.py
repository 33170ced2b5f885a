"""A review's small finds in the whirl classification and the unit messages."""

import numpy as np
import pytest

from auxbearing.analysis.whirl import classify_window
from auxbearing.common.errors import InputError
from auxbearing.common.units import to_si
from auxbearing.core.watch import WHIRL_FIELDS


def _record(whirl: float, spin: float) -> np.ndarray:
    values = {"whirl_speed": whirl, "mean_radius": 2e-4, "contact_fraction": 1.0, "spin_speed": spin,
              "race_speed": 0.0, "duration": 10e-3, "mean_force": 50.0}
    return np.array([values.get(name, 0.0) for name in WHIRL_FIELDS])


@pytest.mark.parametrize("whirl", [500.0, -500.0])
def test_a_whirl_of_a_rotor_that_does_not_turn_is_neither_forward_nor_backward(whirl):
    """Both directions were 'backward' at spin 0, and counted as backward whirl."""
    assert classify_window(_record(whirl, 0.0), 2e-4, 7.3e-3, 1000.0) == "none"
    assert classify_window(_record(whirl, 100.0), 2e-4, 7.3e-3, 1000.0) == ("forward" if whirl > 0 else "backward")


def test_a_plain_number_is_asked_for_in_words():
    with pytest.raises(InputError, match=r"^poisson_ratio = True: must be a plain number$"):
        to_si("poisson_ratio", True, "dimensionless")


def test_a_coast_down_window_is_judged_on_the_clearance_it_ran_with():
    """The no-slip whirl speed ((r + s) w_race - r Omega) / s of the grown geometry, not the built one's: a bore
    opened by a third rolls the journal round it at a speed the built clearance puts outside its band."""
    from auxbearing.analysis.coastdown_phases import plane_window
    from auxbearing.machine.files import read_machine

    machine = read_machine("blower")
    plane = machine.planes[0]
    r, s = plane.journal_radius, 1.35 * plane.radial_clearance
    spin, race = 1000.0, 400.0
    rolling = ((r + s) * race - r * spin) / s
    values = {"whirl_speed": rolling, "mean_radius": s, "contact_fraction": 1.0, "spin_speed": spin,
              "race_speed": race, "duration": 0.05, "mean_normal_force": 50.0}
    records = np.array([[values.get(name, 0.0) for name in WHIRL_FIELDS]])
    grown = plane_window(machine, 0, records, 0, (0.0, 0.0, 0.0), (r, s))
    built = plane_window(machine, 0, records, 0, (0.0, 0.0, 0.0))
    assert grown.whirl_classes == ("backward_rolling",) and grown.state == "whirling"
    assert built.whirl_classes != ("backward_rolling",)
