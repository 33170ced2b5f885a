"""A stretch across which the bearing load steps is charged from loads measured inside it, not as a linear change.

coastdown_phases.StretchEnd charges a stretch by Palmgren-Miner with the load linear in the revolutions between
its ends (stretch_load). Where the two ends differ by more than STEP_LOAD in the load's cube, the motion changed
its kind inside the stretch (the 7208 DB pair's non-drive end: 99 N to 70 N within 250 rpm), and the stretch is
measured inside at halved segments. Here a load that steps from 100 N to 70 N a fifth of the way down stands in
for the measurements; the damage of the exact step is 0.2 x 100^3 + 0.8 x 70^3 per revolution.
"""

import pytest

from auxbearing.analysis.coastdown_phases import STEP_PROBES, StretchEnd, stretch_load


class _Window:
    def __init__(self, load):
        self.load, self.state = load, "rolling"


def _stepping(where: float, calls: list):
    def inside(share):
        calls.append(share)
        return [1000.0 * share], [100.0 if share < where else 70.0]
    return inside


def test_a_stretch_across_a_load_step_is_charged_from_inside():
    calls = []
    overrolling = [[(1000.0, 100.0)]]
    StretchEnd([_Window(100.0)], [0], _stepping(0.2, calls)).close([_Window(70.0)], overrolling)
    exact = (0.2 * 100.0**3 + 0.8 * 70.0**3) ** (1.0 / 3.0)
    linear = stretch_load(100.0, 70.0)
    charged = overrolling[0][0][1]
    assert len(calls) == STEP_PROBES and overrolling[0][0][0] == 1000.0
    assert abs(linear / exact - 1.0) > 0.07  # 86.3 N against 79.7 N: the linear rule's error, in the load
    assert charged == pytest.approx(exact, rel=0.02)


def test_a_stretch_whose_load_hardly_changes_is_not_measured_inside():
    calls = []
    overrolling = [[(1000.0, 100.0)]]
    StretchEnd([_Window(100.0)], [0], _stepping(0.2, calls)).close([_Window(97.0)], overrolling)
    assert calls == [] and overrolling[0][0][1] == pytest.approx(stretch_load(100.0, 97.0))


def test_a_probe_that_leaves_the_range_keeps_the_linear_rule():
    overrolling = [[(1000.0, 100.0)]]
    StretchEnd([_Window(100.0)], [0], lambda share: None).close([_Window(70.0)], overrolling)
    assert overrolling[0][0][1] == pytest.approx(stretch_load(100.0, 70.0))
