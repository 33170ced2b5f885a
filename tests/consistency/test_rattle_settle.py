"""Stretches that carry a rattle leave it RATTLE_SETTLE of full dynamics to forget the last handover.

Each handover of a stretch kicks a rattling journal, and the kick takes 0.15-0.2 s to die out; with 30 ms between
handovers the kicks piled up and the 7208 DB pair's non-drive end read its load 2 % high (damage per drop +3.4 %
against full dynamics). The run's history gives each window's and stretch's end time and mode: between two
stretches of the pair's rattle (its first 12 s) run at least RATTLE_SETTLE of windows, and where they agree, no more.
"""

from itertools import pairwise

import numpy as np
import pytest

from auxbearing.analysis.coastdown import RATTLE_SETTLE, run_coastdown
from auxbearing.machine.files import machine_table
from auxbearing.machine.judging import candidate_tables
from auxbearing.machine.model import machine_from_mapping


def _full_between_stretches(settle_time: str | None = None) -> list[float]:
    """Full dynamics between consecutive stretches over the 7208 DB pair's first 12 s [s]."""
    data, name, base = machine_table("blower")
    (label, data), = candidate_tables(data, ["7208 DB light"])
    data = {k: v for k, v in data.items() if k not in ("criteria", "candidate")}
    if settle_time is not None:
        data["coastdown"] = {**data.get("coastdown", {}), "settle_time": settle_time}
    run = run_coastdown(machine_from_mapping(data, f"{name} with {label}", base), duration=12.0)
    history = run.history
    times, modes = history["time"].values, history["mode"].values
    ends = [i for i in range(1, len(times)) if modes[i] == 1]  # each stretch's row; its start is the row before
    assert len(ends) >= 6, "the pair's rattle should be carried by stretches from about 4 s on"
    return [times[b - 1] - times[a] for a, b in pairwise(ends)]


@pytest.mark.slow  # 12 s of the pair's coast-down: several seconds
def test_stretches_of_a_rattle_are_spaced_by_its_settling_time():
    full_between = _full_between_stretches()
    assert min(full_between) >= RATTLE_SETTLE - 1e-9
    # the rule holds the stretches back no further than it says: the pair's windows agree by then
    assert np.median(full_between) < RATTLE_SETTLE + 0.005


@pytest.mark.slow
def test_a_longer_settle_time_is_followed_by_the_windows_that_judge_not_by_a_fresh_start():
    """coastdown.settle_time past RATTLE_SETTLE: its windows are not judged, the three after it are, and no more."""
    full_between = _full_between_stretches("150 ms")
    assert min(full_between) >= 0.15 + 0.03 - 1e-9
    assert np.median(full_between) < 0.15 + 0.03 + 0.005
