"""The recommendation of verify (issue 15): a search in which no geometry passes recommends nothing.

The drops are replaced by a stand-in that always reports sustained backward whirl, as the vertical example
does at every point of its search, so the test needs no integration.
"""

from types import SimpleNamespace

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
        planes = [{"s0": 5.0, "backward_whirl_onset_ms": None, "shoulder_use": 0.5} for _ in machine.planes]
        return SimpleNamespace(summary={"verdict": "ok", "planes": planes})

    monkeypatch.setattr(auxbearing.analysis.drop, "run_machine", calm_drop)
    data, name, base = machine_table("paper_rig")
    rec = recommend(data, name, base, read_criteria(None), quick=True)
    assert rec["passes"] is True and rec["note"] is None and rec["worst_margin"] > 0.0


def _smooth_drop(machine, lean=False, **_):
    # s0 best near a 30 deg contact angle; no whirl; the excursion grows with the clearance
    angle = machine.planes[0].bearing.contact_angle
    s0 = 3.0 - 4.0 * (angle - 0.52) ** 2
    planes = [{"s0": s0, "backward_whirl_onset_ms": None, "shoulder_use": 0.5} for _ in machine.planes]
    excursion = 1.05 * max(p.radial_clearance for p in machine.planes)
    return SimpleNamespace(summary={"verdict": "ok", "planes": planes, "largest_excursion_m": excursion})


def test_the_full_search_polishes_the_grid_and_verifies_nothing_it_cannot_build(monkeypatch):
    monkeypatch.setattr(auxbearing.analysis.drop, "run_machine", _smooth_drop)
    data, name, base = machine_table("paper_rig")
    rec = recommend(data, name, base, read_criteria({"min_s0": 2.0}), quick=False)
    assert rec["passes"] and rec["evaluations"] > 27  # the 3x3x3 grid, then the Nelder-Mead polish
    assert rec["binding_criterion"] == "static safety factor s0 of every ball contact"
    assert 25.0 <= rec["contact_angle_deg"] <= 35.0
