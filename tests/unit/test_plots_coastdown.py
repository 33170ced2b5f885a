"""Coast-down figures: the reduced model's stretches shaded, one band per stretch in one collection."""

import numpy as np
import xarray as xr
from matplotlib.collections import PolyCollection

from auxbearing.plots.coastdown import plot_speeds


def _history(modes):
    t = np.arange(len(modes), dtype=float)
    return xr.Dataset({"mode": ("time", np.array(modes)), "rotor_speed": ("time", 100.0 - t),
                       "race_speed": (("time", "plane"), np.column_stack([90.0 - t, 80.0 - t]))},
                      coords={"time": t, "plane": ["drive end", "non-drive end"]})


def test_each_stretch_is_one_band_over_the_axes_height():
    # records: the drop's end (2), windows (0), stretch ends (1): stretches over [1, 2], [3, 4] and [4, 5]
    fig = plot_speeds(_history([2, 0, 1, 0, 1, 1, 0]))
    ax = fig.axes[0]
    bands = [c for c in ax.collections if isinstance(c, PolyCollection)]
    assert len(bands) == 1 and not ax.patches
    spans = [(p.vertices[:, 0].min(), p.vertices[:, 0].max()) for p in bands[0].get_paths()]
    assert spans == [(1.0, 2.0), (3.0, 4.0), (4.0, 5.0)]
    assert ax.get_ylim()[0] > 0.0  # the bands (in axes height) leave the speed axis to the lines


def test_a_run_without_stretches_has_no_band():
    ax = plot_speeds(_history([2, 0, 0])).axes[0]
    assert not any(isinstance(c, PolyCollection) for c in ax.collections)
