"""The envelope a drop's time series are drawn from (auxbearing.plots._axes.envelope)."""

import numpy as np
import xarray as xr

from auxbearing.plots._axes import ENVELOPE_COLUMNS, envelope
from auxbearing.plots.drop import plot_contact_force


def _series(n=20_001, seed=3):
    rng = np.random.default_rng(seed)
    t = np.linspace(0.0, 0.2, n)
    return t, np.cumsum(rng.normal(size=n)) + 50.0 * (rng.random(n) > 0.999)


def test_every_runs_extremes_and_both_ends_are_kept_in_order():
    t, y = _series()
    tx, yx = envelope(t, y)
    assert tx.size <= 2 * ENVELOPE_COLUMNS + 2 < t.size
    assert np.all(np.diff(tx) > 0.0)  # a subset of the samples, in their order
    assert set(tx.tolist()) <= set(t.tolist())
    assert (tx[0], tx[-1], yx[0], yx[-1]) == (t[0], t[-1], y[0], y[-1])
    assert yx.max() == y.max() and yx.min() == y.min()
    # every run of consecutive samples keeps its own extremes: the drawn stroke of each pixel column is whole
    run = -(-t.size // ENVELOPE_COLUMNS)
    kept = dict(zip(tx.tolist(), yx.tolist(), strict=True))
    for start in range(0, t.size, run):
        part = slice(start, start + run)
        assert kept[t[part][np.argmax(y[part])]] == y[part].max()
        assert kept[t[part][np.argmin(y[part])]] == y[part].min()


def test_a_short_series_or_one_with_a_gap_is_drawn_whole():
    t, y = _series(n=2 * ENVELOPE_COLUMNS)
    assert envelope(t, y)[0].size == t.size
    t, y = _series()
    y[100] = np.nan
    assert envelope(t, y)[0].size == t.size


def test_the_collision_force_figure_keeps_the_peak():
    t, y = _series()
    ds = xr.Dataset({"normal_force": (("time", "plane"), np.abs(y)[:, None])}, coords={"time": t, "plane": ["DE"]})
    ds.attrs["summary"] = "{}"
    line = plot_contact_force(ds).axes[0].lines[0]
    assert line.get_ydata().size < t.size
    assert line.get_ydata().max() == np.abs(y).max()
