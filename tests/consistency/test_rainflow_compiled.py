"""The compiled rainflow counter of auxbearing.core.fatigue counts exactly as the maintained ``rainflow``
package (both ASTM E1049-85 5.4.4) on random histories, cycle by cycle: range, mean, count and the two
reversals (on a plateau the package names its last sample, we its first: the same value). The package
skips a history of only two turning points (no reversal in between); the standard counts it as a half
cycle, and so does ours."""

import numpy as np
import pytest
import rainflow

from auxbearing.life import count_cycles


def _package(x):
    rows = list(rainflow.extract_cycles(np.asarray(x).tolist()))
    return sorted((x[r[3]], x[r[4]], r[2], r[0], r[1]) for r in rows)


@pytest.mark.parametrize("seed", range(20))
def test_same_cycles_as_the_rainflow_package(seed):
    rng = np.random.default_rng(seed)
    n = int(rng.integers(3, 2000))
    x = np.round(rng.normal(size=n).cumsum() if seed % 2 else rng.normal(size=n), 3)  # with repeated values
    ours = count_cycles(x)
    mine = sorted(zip(x[ours["start"]].tolist(), x[ours["end"]].tolist(), ours["counts"].tolist(),
                      ours["ranges"].tolist(), ours["means"].tolist(), strict=True))
    theirs = _package(x)
    assert len(mine) == len(theirs)
    for a, b in zip(mine, theirs, strict=True):
        assert a[:3] == tuple(b[:3])
        assert a[3:] == pytest.approx(b[3:], abs=1e-12)


def test_a_single_ramp_is_half_a_cycle():
    c = count_cycles([0.0, 5.0, 5.0])
    assert c["ranges"].tolist() == [5.0] and c["counts"].tolist() == [0.5]
