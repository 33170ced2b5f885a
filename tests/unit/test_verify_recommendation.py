"""The recommendation of verify (issue 15): a search in which no geometry passes recommends nothing.

The drops are replaced by a stand-in that always reports sustained backward whirl, as the vertical example
does at every point of its search, so the test needs no integration.
"""

from types import SimpleNamespace

import numpy as np
import pytest

import auxbearing.analysis.drop
from auxbearing.machine.files import machine_table
from auxbearing.machine.judging import read_criteria
from auxbearing.verify.designs import recommend


def _whirling_drop(machine, lean=False, **_):
    planes = [{"s0": 5.0, "backward_whirl_onset_ms": 30.0, "shoulder_use": 0.5} for _ in machine.planes]
    return SimpleNamespace(summary={"verdict": "ok", "planes": planes})


def test_no_passing_geometry_is_no_recommendation(monkeypatch):
    monkeypatch.setattr(auxbearing.analysis.drop, "run_machine", _whirling_drop)
    data, name, base = machine_table("paper_rig")
    rec = recommend(data, name, base, read_criteria(None), quick=True)
    assert rec["passes"] is False and rec["worst_margin"] == -1.0
    assert rec["note"].startswith("no four point geometry within these ranges passes the drop's criteria")
    assert "backward whirl" in rec["note"] and f"all {rec['evaluations']} points fail" in rec["note"]


def test_a_passing_geometry_is_recommended_without_a_note(monkeypatch):
    def calm_drop(machine, lean=False, **_):
        # s0 grows with the contact angle: a steeper geometry than the rig's 35 deg beats the bearing as built (a
        # search that finds nothing better than it recommends nothing)
        s0 = 5.0 + machine.planes[0].bearing.contact_angle
        planes = [{"s0": s0, "backward_whirl_onset_ms": None, "shoulder_use": 0.5} for _ in machine.planes]
        return SimpleNamespace(summary={"verdict": "ok", "planes": planes})

    monkeypatch.setattr(auxbearing.analysis.drop, "run_machine", calm_drop)
    data, name, base = machine_table("paper_rig")
    rec = recommend(data, name, base, read_criteria(None), quick=True)
    assert rec["passes"] is True and rec["note"] is None and rec["worst_margin"] > 0.0


def _smooth_drop(machine, lean=False, **_):
    # s0 best at a 22.9 deg contact angle (0.40 rad), between the grid's 15 and 30 deg; no whirl; the excursion
    # grows with the clearance
    angle = machine.planes[0].bearing.contact_angle
    s0 = 3.0 - 4.0 * (angle - 0.40) ** 2
    excursion = 1.05 * max(p.radial_clearance for p in machine.planes)
    planes = [{"s0": s0, "backward_whirl_onset_ms": None, "shoulder_use": 0.5, "max_excursion_um": excursion * 1e6}
              for _ in machine.planes]
    return SimpleNamespace(summary={"verdict": "ok", "planes": planes, "largest_excursion_m": excursion})


def test_the_full_search_polishes_the_grid_and_verifies_nothing_it_cannot_build(monkeypatch):
    monkeypatch.setattr(auxbearing.analysis.drop, "run_machine", _smooth_drop)
    data, name, base = machine_table("paper_rig")
    rec = recommend(data, name, base, read_criteria({"min_s0": 2.0}), quick=False)
    # the 3x3x3 grid, the polish's drops (at most 12) and the file's own geometry
    assert 27 < rec["evaluations"] <= 27 + 12 + 1
    assert rec["binding_criterion"] == "static safety factor s0 of every ball contact"
    # the grid's best is 30 deg (s0 2.939); the polish moves a quarter of the range's grid step at a time
    assert abs(rec["contact_angle_deg"] - 22.9) <= 1.0
    assert rec["margins"]["static safety factor s0 of every ball contact"] > 0.4995


def test_the_polish_runs_each_round_side_by_side_and_never_a_point_twice():
    from auxbearing.verify.designs import POLISH_POINTS, _polish

    bounds = np.array([[0.0, 1.0], [0.0, 1.0], [2.0, 2.0]])  # the third variable fixed
    submitted, rounds = [], []

    def launch(x):
        submitted.append(tuple(np.round(x, 9)))
        return x, None

    def judged(x, _):
        rounds.append(len(submitted))
        worst = -((x[0] - 0.3) ** 2) - ((x[1] - 0.9) ** 2)
        point = {"x": x, "worst": worst, "margins": {"m": worst}}
        evaluated.append(point)
        return point

    evaluated = [{"x": np.array([a, b, 2.0]), "worst": w, "margins": {"m": w}}
                 for a in (0.0, 0.5, 1.0) for b in (0.0, 0.5, 1.0) for w in [-((a - 0.3) ** 2) - ((b - 0.9) ** 2)]]
    grid = list(evaluated)
    best = _polish(max(grid, key=lambda p: p["worst"]), bounds, 0.25, evaluated, launch, judged)
    assert len(submitted) == len(set(submitted)) <= POLISH_POINTS
    assert not set(submitted) & {tuple(np.round(p["x"], 9)) for p in grid}
    assert all(x[2] == 2.0 for x in submitted)
    # the first round's three points (the fourth, past the bound, is the centre) all went out before one was judged
    assert rounds[:3] == [3, 3, 3]
    assert abs(best["x"][0] - 0.3) <= 0.0625 and abs(best["x"][1] - 0.9) <= 0.0625


def test_a_tie_on_the_smallest_margin_goes_to_the_larger_next_one():
    from auxbearing.verify.designs import TIE_MARGIN, best_of, better

    def point(*margins):
        return {"worst": min(margins), "margins": {f"c{i}": m for i, m in enumerate(margins)}}

    # the air-gap margin (0.55) depends on the clearance alone: the s0 and seal margins decide
    first, second = point(0.55, 22.6, 0.73), point(0.55, 18.0, 0.81)
    assert better(second, first) and not better(first, second)
    assert best_of([first, second, point(0.55 - 0.5 * TIE_MARGIN, 30.0, 0.9)]) is not first
    assert better(point(0.56, 1.0, 0.6), point(0.55, 20.0, 0.9))  # the smallest margin first
    assert not better(point(0.55, 22.6, 0.73), point(0.55, 22.6, 0.73))  # equal: the earlier point stays
    assert best_of([]) is None


def test_the_bearing_as_it_stands_goes_out_with_the_grid(monkeypatch):
    """Its margin is reported beside the recommendation; its drop runs beside the grid's, not after the polish."""
    from auxbearing.verify.cases import Immediate

    monkeypatch.setattr(auxbearing.analysis.drop, "run_machine", _smooth_drop)

    class Recording(Immediate):
        def __init__(self):
            self.submitted, self.first_asked = 0, None

        def submit(self, fn, *args, **kwargs):
            self.submitted += 1
            done = super().submit(fn, *args, **kwargs)
            owner = self

            class Asked:
                def result(self):
                    if owner.first_asked is None:
                        owner.first_asked = owner.submitted
                    return done.result()
            return Asked()

    executor = Recording()
    data, name, base = machine_table("paper_rig")
    rec = recommend(data, name, base, read_criteria({"min_s0": 2.0}), quick=False, executor=executor)
    assert executor.first_asked == 27 + 1  # the 3x3x3 grid and the bearing as it stands
    from auxbearing.machine.files import read_machine

    angle = read_machine("paper_rig").planes[0].bearing.contact_angle
    assert rec["as_is"] == pytest.approx((3.0 - 4.0 * (angle - 0.40) ** 2) / 2.0 - 1.0)  # the stand-in's s0 margin


def test_points_the_air_gap_already_rules_out_are_not_run(monkeypatch):
    """The air-gap margin is known before a drop: a point it keeps below the best point run is left out."""
    import auxbearing.verify.designs as designs

    monkeypatch.setattr(auxbearing.analysis.drop, "run_machine", _smooth_drop)
    data, name, base = machine_table("paper_rig")
    criteria = read_criteria({"min_s0": 2.0, "amb_air_gap": "0.5 mm"})
    rec = recommend(data, name, base, criteria, quick=False)
    low = rec["bounds"]["clearance_factor"][0]
    # the smallest clearance's margin against the air gap binds there; the larger clearances' are already below it
    assert rec["binding_criterion"] == "touchdown clearance against the magnetic air gap"
    assert all(p["clearance_factor"] == pytest.approx(low) for p in rec["points"])
    assert rec["left_out"] >= 18 and rec["evaluations"] <= 9 + 12
    monkeypatch.setattr(designs, "cannot_beat", lambda bound, best: False)
    whole = recommend(data, name, base, criteria, quick=False)
    assert whole["left_out"] == 0 and whole["evaluations"] >= 27
    assert rec["worst_margin"] >= whole["worst_margin"] - designs.TIE_MARGIN
    assert rec["clearance_factor"] == pytest.approx(whole["clearance_factor"])


def test_the_bearing_as_built_is_judged_on_the_drop_it_is_given(monkeypatch):
    """The verification hands the search its own drop of the design: it is not run a second time."""
    from auxbearing.machine.files import read_machine
    from auxbearing.verify.cases import Immediate

    monkeypatch.setattr(auxbearing.analysis.drop, "run_machine", _smooth_drop)

    class Counting(Immediate):
        submitted = 0

        def submit(self, fn, *args, **kwargs):
            self.submitted += 1
            return super().submit(fn, *args, **kwargs)

    given = _smooth_drop(read_machine("paper_rig")).summary
    data, name, base = machine_table("paper_rig")
    alone, handed = Counting(), Counting()
    ran = recommend(data, name, base, read_criteria({"min_s0": 2.0}), executor=alone)
    reused = recommend(data, name, base, read_criteria({"min_s0": 2.0}), executor=handed,
                       as_built=SimpleNamespace(result=lambda: given))
    assert alone.submitted == ran["evaluations"] + 1 and handed.submitted == reused["evaluations"]
    assert reused["as_is"] == ran["as_is"]
