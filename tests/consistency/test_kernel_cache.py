"""The compiled-kernel cache cannot go stale (issue 10): after an edit of the ball-set pair kernel in a
copy of the package, the static solver, which inlines that kernel from another core module, returns the
new physics at once, with no cache deleted by hand.

The edit doubles the Hertz constant K_b(alpha) and its derivative in ``pair``: under the same radial load
the radial displacement shrinks by about 2^(-2/3) = 0.63 (Q ~ K delta^1.5, source paper Eq. 15; not
exactly, since the loaded contact angles move with the displacement). Each run compiles the static
kernels into the copy's own cache folder (tens of seconds).
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import auxbearing

RUN = """
from auxbearing import get_bearing
from auxbearing.analysis.statics import load_distribution
ds = load_distribution(get_bearing("QJ202"), radial=1000.0)
print(repr(float(ds.radial_displacement[0])))
"""
ORIGINAL = "    k, dk = ball_constant(bs, r / s_len)\n"
EDITED = ORIGINAL + "    k, dk = 2.0 * k, 2.0 * dk\n"


def _displacement(src: Path) -> float:
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    env["PYTHONPATH"] = str(src)
    out = subprocess.run([sys.executable, "-c", RUN], capture_output=True, text=True, env=env, cwd=src,
                         timeout=600)
    assert out.returncode == 0, out.stderr[-2000:]
    return float(out.stdout.strip().splitlines()[-1])


@pytest.mark.slow
def test_an_edited_kernel_is_recompiled_everywhere_it_is_inlined(tmp_path):
    package = Path(auxbearing.__file__).parent
    src = tmp_path / "src"
    shutil.copytree(package, src / "auxbearing", ignore=shutil.ignore_patterns("__pycache__", "*.nbi", "*.nbc"))
    before = _displacement(src)
    again = _displacement(src)  # from the copy's cache
    kernel = src / "auxbearing" / "core" / "ballset.py"
    text = kernel.read_text()
    assert text.count(ORIGINAL) == 1
    kernel.write_text(text.replace(ORIGINAL, EDITED))
    after = _displacement(src)
    assert again == before
    assert after / before == pytest.approx(2.0 ** (-2.0 / 3.0), rel=0.02)
    folders = list((src / "auxbearing" / "core" / "__pycache__").glob("kernels-*"))
    assert len(folders) == 2  # one per version of the core's sources
