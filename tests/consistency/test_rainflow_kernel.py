"""The compiled rainflow count (auxbearing.core.fatigue.rainflow_turning_points) against the ``rainflow`` package.

Both implement ASTM E1049-85, 5.4.4; the package (a maintained reference, a test dependency) counts in a
Python loop, ours in a compiled one. Every cycle must agree exactly: range, mean, count, its two points, in
the same order, on histories with ties, plateaus, steps and the shapes a drop's raceway points see.
"""

import numpy as np
import pytest
import rainflow

from auxbearing.analysis.life import count_cycles


def _package(series):
    """What count_cycles returned when it called the package (the reference)."""
    x = np.asarray(series, dtype=float)
    index = np.flatnonzero(np.r_[True, np.diff(x) != 0.0])
    step = np.diff(x[index])
    index = index[np.r_[True, step[:-1] * step[1:] < 0.0, True]] if step.size else index
    cycles = np.array(list(rainflow.extract_cycles(x[index].tolist())), dtype=float).reshape(-1, 5)
    return {"ranges": cycles[:, 0], "means": cycles[:, 1], "counts": cycles[:, 2],
            "start": index[cycles[:, 3].astype(int)], "end": index[cycles[:, 4].astype(int)]}


def _histories():
    rng = np.random.default_rng(7)
    yield "white noise", rng.normal(size=5000)
    yield "rounded noise with ties", np.round(rng.normal(size=3000) * 3.0)
    yield "random walk", np.cumsum(rng.normal(size=4000))
    yield "pulse train (a raceway point over-rolled)", np.tile([0.0, 1.0, 0.0, 0.0, 2.5, 0.0], 300) * rng.uniform(
        0.5, 1.5, 1800)
    yield "up, plateau, down", np.r_[np.repeat(np.arange(20.0), 3), np.arange(19.0, -5.0, -1.0)]
    yield "growing then decaying swing", np.sin(np.linspace(0, 60, 3000)) * np.r_[np.linspace(0, 1, 1500),
                                                                                  np.linspace(1, 0, 1500)]
    yield "constant", np.full(10, 2.0)


@pytest.mark.parametrize(("name", "series"), list(_histories()), ids=[n for n, _ in _histories()])
def test_every_cycle_as_the_package_counts_it(name, series):
    ours, theirs = count_cycles(series), _package(series)
    assert ours["ranges"].size == theirs["ranges"].size, name
    for key in ("ranges", "means", "counts", "start", "end"):
        np.testing.assert_array_equal(ours[key], theirs[key], err_msg=f"{name}: {key}")


@pytest.mark.parametrize("series", [np.array([1.0, -1.0]), np.repeat(np.arange(50.0), 3)], ids=["two points", "ramp"])
def test_a_single_ramp_is_half_a_cycle(series):
    """A history with two turning points is half a cycle of its range (E1049 5.4.4: what is left counts half).

    The package counts nothing there (its reversal iterator never yields the last point of a two-point
    series); a raceway point's history always starts and ends at zero, so the drop's counts never meet it.
    """
    c = count_cycles(series)
    assert c["counts"].tolist() == [0.5]
    assert c["ranges"].tolist() == [abs(series[-1] - series[0])]
    assert c["start"].tolist() == [0] and series[c["end"][0]] == series[-1]
