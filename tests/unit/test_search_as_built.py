"""The geometry search weighs the bearing as it stands with the points it runs: none better, none recommended.

Before, the as-built point was judged only after the best point was chosen, so a grid point with a smaller worst
drop margin than the design's could be recommended (the report then showed both margins side by side).
"""

import copy
from types import SimpleNamespace

from auxbearing.machine.files import machine_document
from auxbearing.machine.judging import read_criteria
from auxbearing.verify.designs import recommend
from tests.cli.test_verify_review_round4 import _Stub as _Drops  # every drop of the search gives one summary


def _summary(s0: float) -> dict:
    return {"verdict": "ok", "largest_excursion_m": 0.1e-3,
            "planes": [{"s0": s0, "whirl": "forward", "backward_whirl_onset_ms": None, "max_excursion_um": 100.0}] * 2}


def _search(grid_s0: float, built_s0: float) -> dict:
    data, name, base = machine_document("blower")
    data = copy.deepcopy(data)
    data.pop("candidate")
    built = SimpleNamespace(result=lambda: _summary(built_s0))
    return recommend(data, name, base, read_criteria(data["criteria"]), quick=True, executor=_Drops(_summary(grid_s0)),
                     as_built=built)


def test_a_search_that_finds_nothing_better_than_the_bearing_as_built_recommends_nothing():
    """Every point run reaches s0 2.2 (+10 % on the 2 required); the design's own drop s0 50, its worst margin the air
    gap's +21 %."""
    rec = _search(2.2, 50.0)
    assert rec["passes"] is False and rec["worst_margin"] <= rec["as_is"]
    assert rec["note"].startswith("the bearing as built is the best geometry of the")
    assert "no change is recommended" in rec["note"]


def test_a_better_point_is_still_recommended():
    rec = _search(50.0, 2.2)
    assert rec["passes"] is True and rec["worst_margin"] > rec["as_is"] and rec["note"] is None
