"""The verification takes its drop at the maximum speed from the coast-down (auxbearing.verify.cases.submit_cases):
the coast-down's drop must be the run run_machine makes of the same machine, to the last digit (its timings aside)."""

import copy
import json

import numpy as np
import xarray as xr

from auxbearing.analysis.coastdown import run_coastdown
from auxbearing.analysis.drop import run_machine
from auxbearing.machine.files import machine_table
from auxbearing.verify.cases import MAX_SPEED, Immediate, collect_cases, plan_cases, submit_cases

#: What a run measures of the computer, not of the machine.
TIMINGS = ("wall_time_s", "compile_or_cache_load_s")


def _physics(summary: dict) -> str:
    return json.dumps({k: v for k, v in summary.items() if k not in TIMINGS}, sort_keys=True, default=str)


def test_the_coastdowns_drop_is_the_drop_at_the_maximum_speed():
    data, name, base = machine_table("blower")
    machine = plan_cases(data, name, base, quick=True).machines[MAX_SPEED]
    alone = run_machine(machine)
    within = run_coastdown(machine, until_stop=False, duration=machine.simulation.duration).drop
    assert _physics(within.summary) == _physics(alone.summary)
    assert _physics(json.loads(within.dataset.attrs["summary"])) == _physics(alone.summary)
    xr.testing.assert_identical(within.dataset.drop_attrs(), alone.dataset.drop_attrs())


class _Counting(Immediate):
    def __init__(self):
        self.calls = []

    def submit(self, fn, *args, **kwargs):
        self.calls.append(fn.__name__)
        return super().submit(fn, *args, **kwargs)


def test_a_verification_runs_the_drop_at_the_maximum_speed_once(monkeypatch):
    import auxbearing.verify.cases as vc

    data, name, base = machine_table("paper_rig")
    cases = plan_cases(data, name, base, quick=True)
    monkeypatch.setattr(vc, "QUICK_COASTDOWN", float(cases.machine.simulation.duration))
    executor = _Counting()
    collected = collect_cases(cases, submit_cases(cases, executor))
    assert executor.calls.count("run_machine") == len(cases.machines) - 1
    assert list(collected.drops) == list(cases.machines)
    assert collected.drops[MAX_SPEED] is collected.coastdown.drop
    assert np.isfinite(collected.drops[MAX_SPEED].summary["planes"][0]["peak_contact_force_N"])


def test_a_coastdown_shorter_than_the_drop_leaves_the_drop_its_own_run():
    data, name, base = machine_table("paper_rig")
    data = copy.deepcopy(data)
    data.setdefault("coastdown", {})["max_time"] = "1 ms"
    cases = plan_cases(data, name, base, quick=True)
    executor = _Counting()
    collected = collect_cases(cases, submit_cases(cases, executor))
    assert executor.calls.count("run_machine") == len(cases.machines)
    assert collected.drops[MAX_SPEED] is not collected.coastdown.drop
    assert collected.drops[MAX_SPEED].summary["duration_s"] == cases.machine.simulation.duration


def test_lean_cases_are_judged_as_the_full_ones(monkeypatch):
    """A candidate's and the recommended geometry's cases come back lean (summaries, no drop time series): the
    judged criteria, the drop and coast-down tables are those of the full runs."""
    import auxbearing.verify.cases as vc
    from auxbearing.machine.judging import read_criteria
    from auxbearing.verify.run import _design

    data, name, base = machine_table("paper_rig")
    monkeypatch.setattr(vc, "QUICK_COASTDOWN", 0.2)
    criteria = read_criteria(data.get("criteria"))
    judged = {}
    for lean in (False, True):
        cases = plan_cases(data, name, base, quick=True)
        judged[lean] = _design(collect_cases(cases, submit_cases(cases, Immediate(), lean=lean)), criteria)
    full, lean = judged[False], judged[True]
    assert [c.as_json() for c in lean["criteria"]] == [c.as_json() for c in full["criteria"]]
    for rows in ("drop_rows", "coastdown_rows", "scenario_rows"):
        assert lean[rows] == full[rows]
    for case, run in lean["cases"].drops.items():
        assert "ball" not in run.dataset.dims
        assert run.dataset.nbytes < 0.25 * full["cases"].drops[case].dataset.nbytes  # 0.92 of 4.0 MB here
