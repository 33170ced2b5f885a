"""Every whole whirl window of a drop is judged, the last one too (core.watch.WINDOW_END_SLACK).

The windows' ends are summed one window at a time, so the last one can miss the run's end by round-off; before
the slack, a 200 ms blower drop in 10 ms windows closed 19 windows and left its last 10 ms out of the whirl verdict.
"""

import math

import pytest

from auxbearing.analysis.drop import run_machine, whirl_window
from auxbearing.machine.files import read_machine


@pytest.mark.parametrize("duration", ["20 ms", "60 ms", "180 ms"])  # 60 and 180 ms fell short before
def test_a_drop_lasting_whole_windows_closes_every_one(duration):
    machine = read_machine("blower").with_simulation(duration=duration, whirl_window="10 ms")
    summary = run_machine(machine, lean=True).summary
    windows = round(machine.simulation.duration / whirl_window(machine))
    for plane in summary["planes"]:
        assert len(plane["whirl_timeline"]) == windows, plane["name"]


def test_a_last_part_window_is_left_open():
    # 25 ms in 10 ms windows: two whole windows, and 5 ms that is no window's worth to judge
    machine = read_machine("blower").with_simulation(duration="25 ms", whirl_window="10 ms")
    summary = run_machine(machine, lean=True).summary
    assert [len(p["whirl_timeline"]) for p in summary["planes"]] == [math.floor(25 / 10)] * 2
