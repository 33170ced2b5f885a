"""The kernels compiled without reference counting leak nothing (:mod:`auxbearing.core.uncounted`).

A function compiled without the counting that took a new array from a callee would never free it. Every
call of the compiled driver is wrapped here and numba's own allocation statistics (``NUMBA_NRT_STATS``,
set before numba is imported, hence the fresh process) are read around it: whatever the driver allocates
it frees before it returns. Run on drops that take every branch of the right-hand side and the observer:
one plane and two, compliant mounts and an axial face, the magnetic bearings' stations, a matched pair of
rows, an elastic rotor, a stop on a range limit with its peak refinements, and a coast-down's windows (their own
driver, ``drive.advance_window``).
"""

import json
import os
import subprocess
import sys

import pytest

SCRIPT = r"""
import json
from numba.core.runtime import rtsys
from auxbearing.analysis import drop
from auxbearing.analysis.coastdown import run_coastdown
from auxbearing.core import drive
from tests.consistency.test_coastdown_reduced import _machine

calls = []


def counting(original):
    def counted(*args):
        before = rtsys.get_allocation_stats()
        status = original(*args)
        after = rtsys.get_allocation_stats()
        calls.append(((after.alloc - before.alloc) - (after.free - before.free), after.alloc - before.alloc))
        return status
    return counted


drive.advance = counting(drive.advance)
drive.advance_window = counting(drive.advance_window)  # the coast-down's windows (auxbearing.core.rk4)
for case in ("paper_rig", "blower", "blower:7208 DB light", "compressor", "heavy_fast_rotor"):
    drop.run_machine(_machine(case), "20 ms")
run_coastdown(_machine("paper_rig"), until_stop=False, duration="0.3 s")
print(json.dumps({"calls": len(calls), "unfreed": sum(c[0] for c in calls), "worst": max(c[0] for c in calls),
                  "allocated": sum(c[1] for c in calls)}))
"""


# a fresh process that imports the package and runs five drops: 3.6 s, the quick loop's longest test
@pytest.mark.slow
def test_the_driver_frees_all_it_allocates():
    env = {**os.environ, "NUMBA_NRT_STATS": "1"}
    done = subprocess.run([sys.executable, "-c", SCRIPT], capture_output=True, text=True, env=env, timeout=600,
                          cwd=os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
    assert done.returncode == 0, done.stderr[-2000:]
    result = json.loads(done.stdout.strip().splitlines()[-1])
    assert result["calls"] > 5 and result["allocated"] > 0  # the statistics are on: the driver's own arrays
    assert result["unfreed"] == 0 and result["worst"] == 0, result
