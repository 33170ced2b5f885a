"""The compiled-kernel cache cannot go stale (issue 10): after an edit of the ball-set pair kernel in a
copy of the package, the static solver's residual, which inlines that kernel from another core module, returns
the new physics at once, with no cache deleted by hand.

The edit doubles the Hertz constant K_b(alpha) and its derivative in ``pair``. At a fixed ring displacement the
contact geometry (and so each ball's deflection and angle) does not depend on K_b, so every ball load
Q = K_b delta^1.5 (source paper Eq. 15) and the ring's reaction exactly double. The residual alone is compiled
(a few seconds in the copy's own cache folder); the whole solver took a minute of the suite for the same check.
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import auxbearing

RUN = """
import numpy as np
from auxbearing import get_bearing
from auxbearing.bearings.ballset import ballset_params
from auxbearing.core.statics import _residual
u = np.array([0.0, 50e-6, 0.0, 0.0, 0.0])  # radially well past the clearance, so balls bear load
r, _, _ = _residual(u, np.zeros(5), np.ones(5, dtype=np.bool_), ballset_params(get_bearing("QJ202")), np.ones(5),
                    np.zeros(5), np.zeros((5, 5)), False)
print(repr(float(r[1])))
"""
ORIGINAL = "    k, dk = ball_constant(bs, r / s_len)\n"
EDITED = ORIGINAL + "    k, dk = 2.0 * k, 2.0 * dk\n"


def _radial_reaction(src: Path) -> float:
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
    before = _radial_reaction(src)
    again = _radial_reaction(src)  # from the copy's cache
    kernel = src / "auxbearing" / "core" / "ballset.py"
    text = kernel.read_text()
    assert text.count(ORIGINAL) == 1
    kernel.write_text(text.replace(ORIGINAL, EDITED))
    after = _radial_reaction(src)
    assert again == before
    assert before != 0.0
    assert after / before == pytest.approx(2.0, rel=1e-12)
    folders = list((src / "auxbearing" / "core" / "__pycache__").glob("kernels-*"))
    assert len(folders) == 2  # one per version of the core's sources
