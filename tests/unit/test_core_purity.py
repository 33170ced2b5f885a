"""The core is pure (issue 10): importing any auxbearing.core module brings in nothing beyond numpy, numba
(with what numba itself loads) and the standard library, and no auxbearing module outside the core."""

import ast
import subprocess
import sys

CORE = ("ballset", "bearing_friction", "drive", "fatigue", "hertz", "integrate", "machine", "probes", "statics",
        "thermal", "watch")

# One interpreter imports the core modules in turn; a module brought in is charged to the first core module
# whose import loaded it. Whatever a core module loads is then among the modules charged to it or to a core
# module imported before it, all of which are checked, so one process tests every module's imports.
PROBE = """
import sys
import numpy, numba
charged = {{}}
for name in {names!r}:
    before = set(sys.modules)
    __import__('auxbearing.core.' + name)
    charged[name] = sorted(set(sys.modules) - before)
print(repr(charged))
"""


def _charged_imports():
    out = subprocess.run([sys.executable, "-c", PROBE.format(names=CORE)], capture_output=True, text=True, check=True)
    return ast.literal_eval(out.stdout.strip().splitlines()[-1])


def test_core_modules_import_only_numpy_numba_and_the_standard_library():
    charged = _charged_imports()
    assert sorted(charged) == sorted(CORE)
    for name, new in charged.items():
        top = {n: n.split(".")[0] for n in new}
        outside = [n for n in new if top[n] not in sys.stdlib_module_names and top[n] != "auxbearing"]
        # the package itself and its import hook for the old module paths (standard library only) come first
        ours = [n for n in new if top[n] == "auxbearing" and n not in ("auxbearing", "auxbearing._moved")
                and not n.startswith("auxbearing.core")]
        assert outside == [], f"auxbearing.core.{name} imports {outside}"
        assert ours == [], f"auxbearing.core.{name} imports library modules {ours}"
