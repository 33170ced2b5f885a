"""The observer's shortcut in a coast-down's windows never hides a range limit.

Where no peak is wanted, the observer skips the contact-by-contact evaluation of the ball stresses and of the
contact ellipses' reach towards the groove shoulders when :func:`auxbearing.core.probes.limits_out_of_reach`
says neither limit can be reached from the largest ball load and the ring's displacement. Checked here on the
states of real drops (a four-point bearing, a matched angular-contact pair and the heavy rotor whose ellipse runs
over the shoulder), with the limits set at, just above and just below what each state actually reaches: whenever
the shortcut answers "out of reach", the contacts stay below both limits.
"""

import numpy as np
import pytest

from auxbearing.analysis.drop import integrate_machine
from auxbearing.core.machine import D_QMAX
from auxbearing.core.probes import ball_extremes, limits_out_of_reach, plane_diagnostics
from tests.consistency.test_coastdown_reduced import _machine

#: Each limit at this multiple of what the state reaches: 1 at the limit, below 1 past it.
SCALES = (0.5, 0.9, 0.99, 1.0, 1.01, 1.05, 1.2, 2.0, 5.0)


@pytest.mark.parametrize("case", ["blower", "blower:7208 DB light", "heavy_fast_rotor"])
def test_out_of_reach_only_when_no_contact_reaches_a_limit(case):
    machine = _machine(case)
    run = integrate_machine(machine, 0.03, 1e-4, None)
    m = run.model.machine
    out_of_reach = checked = 0
    for y in run.grid[:: max(1, run.grid.shape[0] // 60)]:
        for k in range(len(machine.planes)):
            qmax = plane_diagnostics(y, m, k)[D_QMAX]
            stress, use = ball_extremes(y, m, k, np.empty(0))
            if qmax <= 0.0:
                continue
            for scale in SCALES:
                limits = m.limits._replace(
                    ball_stress=scale * stress,
                    shoulder_angle_inner=tuple(scale * use * a for a in m.limits.shoulder_angle_inner),
                    shoulder_angle_outer=tuple(scale * use * a for a in m.limits.shoulder_angle_outer))
                scaled = m._replace(limits=limits)
                reached_stress, reached_use = ball_extremes(y, scaled, k, np.empty(0))
                checked += 1
                if limits_out_of_reach(y, scaled, k, qmax, np.full(4, -1.0)):
                    out_of_reach += 1
                    assert reached_stress < limits.ball_stress and reached_use < 1.0, (case, k, scale)
    assert checked > 100
    assert out_of_reach > 0  # the shortcut does answer on some states
