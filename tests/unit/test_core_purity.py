"""The core is pure (issue 10): importing any auxbearing.core module brings in nothing beyond numpy, numba
(with what numba itself loads) and the standard library, and no auxbearing module outside the core."""

import ast
import subprocess
import sys

import pytest

CORE = ("ballset", "bearing_friction", "drive", "fatigue", "hertz", "integrate", "machine", "probes", "statics",
        "thermal", "watch")

PROBE = """
import sys
import numpy, numba
before = set(sys.modules)
import auxbearing.core.{name}
new = set(sys.modules) - before
top = {{n: n.split('.')[0] for n in new}}
outside = sorted(n for n in new if top[n] not in sys.stdlib_module_names and top[n] != 'auxbearing')
ours = sorted(n for n in new if top[n] == 'auxbearing' and n != 'auxbearing' and not n.startswith('auxbearing.core'))
print(repr((outside, ours)))
"""


@pytest.mark.parametrize("name", CORE)
def test_core_module_imports_only_numpy_numba_and_the_standard_library(name):
    out = subprocess.run([sys.executable, "-c", PROBE.format(name=name)], capture_output=True, text=True, check=True)
    outside, ours = ast.literal_eval(out.stdout.strip().splitlines()[-1])
    assert outside == [], f"auxbearing.core.{name} imports {outside}"
    assert ours == [], f"auxbearing.core.{name} imports library modules {ours}"
