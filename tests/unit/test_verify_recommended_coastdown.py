"""The recommended geometry's coast-down runs only when its drops and campaign fail nothing.

A geometry that already fails its own verification is withdrawn whatever its coast-down would show, so that run
(the blower's dearest) is left out, in a fixed order: drops and campaign first. The runs are stand-ins here; the
judging is the verification's own, on criteria given by the stand-in judge.
"""

from pathlib import Path
from types import SimpleNamespace

from auxbearing.verify import run as verify_run
from auxbearing.verify.cases import Cases
from auxbearing.verify.criteria import Criterion


def _criterion(name: str, passed) -> Criterion:
    return Criterion(name=name, required=1.0, found=2.0 if passed else 0.5, margin=1.0 if passed else -0.5,
                     passed=passed, unit="", kind="lower", origin="test", evidence=f"{name} evidence")


class _Runs:
    """Stand-ins for the cluster's runs, recording what the verification asked for."""

    def __init__(self, campaign_passes: bool) -> None:
        self.campaign_passes = campaign_passes
        self.asked: list[str] = []

    def install(self, monkeypatch) -> None:
        monkeypatch.setattr(verify_run, "recommended_tables", lambda *args: {})
        monkeypatch.setattr(verify_run, "plan_cases", lambda *args: Cases(machine=None))
        monkeypatch.setattr(verify_run, "submit_cases", self.submit_cases)
        monkeypatch.setattr(verify_run, "submit_coastdown", self.submit_coastdown)
        monkeypatch.setattr(verify_run, "run_campaign_of", lambda *args: self.asked.append("campaign"))
        monkeypatch.setattr(verify_run, "collect_cases", self.collect)
        monkeypatch.setattr(verify_run, "judge", self.judge)
        monkeypatch.setattr(verify_run, "_design", self.design)

    def submit_cases(self, cases, executor, lean=False, coastdown=True):
        self.asked.append("drops and coast-down" if coastdown else "drops")
        return {}

    def submit_coastdown(self, cases, executor, futures, lean=False):
        self.asked.append("coast-down")
        futures["coast-down"] = "run"

    def collect(self, cases, futures):
        if "coast-down" in futures:
            cases.coastdown = "collected"
        return cases

    def judge(self, cases, criteria):
        out = [_criterion("static safety factor s0 of every ball contact", True),
               _criterion("probability of backward whirl over the drop conditions, 95 % bound", self.campaign_passes)]
        temperature = None if cases.coastdown is None else True
        return [*out, _criterion("peak bearing temperature", temperature)]

    def design(self, cases, criteria):
        judged = self.judge(cases, criteria)
        if cases.partial_coastdown:
            judged = [c._replace(passed=None) if c.name == "peak bearing temperature" else c for c in judged]
        verdict = "fail" if any(c.passed is False for c in judged) else (
            "incomplete" if any(c.passed is None for c in judged) else "pass")
        return {"verdict": verdict, "worst_margin": min(c.margin for c in judged), "criteria": judged}


def _verify(monkeypatch, campaign_passes: bool):
    runs = _Runs(campaign_passes)
    runs.install(monkeypatch)
    rec = {"passes": True, "note": None}
    verify_run._verify_recommendation(rec, {}, "machine", None, {"min_s0": 1.0, "max_backward_whirl_probability": 0.05},
                                      False, 8, Path("."), SimpleNamespace(priority=1, client=None), None,
                                      lambda text: runs.asked.append(text))
    return rec, runs.asked


def test_a_geometry_its_campaign_fails_is_withdrawn_without_its_coast_down(monkeypatch):
    rec, asked = _verify(monkeypatch, campaign_passes=False)
    assert "coast-down" not in asked and asked.index("drops") < asked.index("campaign")
    assert rec["passes"] is False and rec["verification"]["verdict"] == "fail"
    assert rec["note"].startswith("the search's best geometry passes the drop criteria but fails its own "
                                  "verification: fails on probability of backward whirl")
    assert rec["note"].endswith("its coast-down was not run, since nothing it could show changes that")
    temperature = next(c for c in rec["verification"]["criteria"] if c["name"] == "peak bearing temperature")
    assert temperature["pass"] is None


def test_a_geometry_that_fails_nothing_runs_its_coast_down_after_the_campaign(monkeypatch):
    rec, asked = _verify(monkeypatch, campaign_passes=True)
    assert asked.index("campaign") < asked.index("coast-down")
    assert rec["passes"] is True and rec["verification"]["verdict"] == "pass" and rec["note"] is None
