"""The observer's largest ball stress and shoulder use skip contacts that cannot win, and find the same maxima.

:func:`auxbearing.core.probes.ball_extremes` with the coefficient tables' bounds evaluates a contact only when
its load could beat the largest stress or shoulder use found so far. Checked on the states of real drops (a
four-point bearing with a zero and a positive clearance, a matched angular-contact pair, the heavy rotor whose
ellipse runs over the shoulder, the paper rig): both maxima equal those of the evaluation of every contact, to
the last bit.
"""

import numpy as np
import pytest

from auxbearing.analysis.drop import integrate_machine
from auxbearing.core.probes import ball_extremes
from tests.consistency.test_coastdown_reduced import _machine


@pytest.mark.parametrize("case", ["paper_rig", "blower", "blower:7208 DB light", "heavy_fast_rotor"])
def test_pruned_maxima_equal_every_contact_evaluated(case):
    machine = _machine(case)
    run = integrate_machine(machine, 0.03, 1e-4, None)
    m = run.model.machine
    bounds = np.full((len(machine.planes), 4), -1.0)
    loaded = 0
    for y in run.grid:
        for k in range(len(machine.planes)):
            every = ball_extremes(y, m, k, np.empty(0))
            pruned = ball_extremes(y, m, k, bounds[k])
            assert pruned == every, (case, k)
            loaded += every[0] > 0.0
    assert loaded > 50
