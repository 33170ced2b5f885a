"""The convergence evidence of a verdict that rests on a run leaving the model's range.

The heavy rotor's drop at the maximum speed stops when a ball contact ellipse runs over the groove shoulder
(66.87 ms as shipped); the same drop with tolerances ten times tighter must stop the same way at nearly the
same time, and the evidence must say which run, what stopped it and by how much the time moved.
"""

import pytest

from auxbearing.machine.files import machine_table
from auxbearing.machine.judging import read_criteria
from auxbearing.verify.cases import Immediate, collect_cases, plan_cases, submit_cases
from auxbearing.verify.convergence import convergence
from auxbearing.verify.judge import judge


@pytest.mark.slow
def test_a_stop_that_governs_is_run_again_tighter():
    data, name, base = machine_table("heavy_fast_rotor")
    cases = plan_cases(data, name, base, quick=False)
    collect_cases(cases, submit_cases(cases, Immediate()))
    judged = judge(cases, read_criteria(data.get("criteria")))
    found = convergence(cases, judged)
    assert found["criterion"].startswith("no run leaves the model's range")
    assert found["case"] in cases.drops and found["quantity"].startswith("time of the stop (contact ellipse")
    assert found["verdict"] == "contact_ellipse_over_shoulder"
    assert found["as_run"] == pytest.approx(found["tightened"], rel=0.01)
    assert found["settled"] is True and "moves" in found["note"]
