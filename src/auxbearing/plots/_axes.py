"""Where a plot draws: the caller's axes or figure, or a fresh one (never pyplot).

A single-panel plot takes ``ax=None`` and starts with :func:`axes_for`; a multi-panel plot
takes ``fig=None``, starts with :func:`figure_for` and draws each panel with the
single-panel functions into its own axes.
"""

from __future__ import annotations

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure, SubFigure


def axes_for(ax: Axes | None, size: tuple[float, float] = (6, 4)) -> tuple[Figure | SubFigure, Axes]:
    """The caller's axes and its figure, or a new figure of ``size`` [in] with one axes.

    Examples
    --------
    >>> fig, ax = axes_for(None, (3, 2))
    >>> axes_for(ax)[0] is fig, fig.get_size_inches().tolist()
    (True, [3.0, 2.0])
    """
    if ax is not None:
        return ax.figure, ax
    fig = Figure(figsize=size, layout="constrained")
    return fig, fig.add_subplot()


def figure_for(fig: Figure | SubFigure | None, size: tuple[float, float]) -> Figure | SubFigure:
    """The caller's (sub)figure, or a new constrained-layout figure of ``size`` [in].

    Examples
    --------
    >>> mine = Figure()
    >>> figure_for(mine, (3, 2)) is mine, figure_for(None, (3, 2)).get_size_inches().tolist()
    (True, [3.0, 2.0])
    """
    return fig if fig is not None else Figure(figsize=size, layout="constrained")


#: Columns a time series is reduced to before it is drawn (:func:`envelope`): about twice the widest figure's
#: pixels (11 in at the report's 110 dpi), so that the drawn line is the same to the pixel.
ENVELOPE_COLUMNS = 2000


def envelope(x, y, columns: int = ENVELOPE_COLUMNS):
    """``(x, y)`` reduced to each of ``columns`` consecutive runs' smallest and largest value, in their order.

    A drop's series hold 20 000 samples or more, where a figure is about 1 000 pixels wide: drawn whole, each
    pixel column gets some 20 segments that end up as one vertical stroke from the column's lowest to its highest
    value, and the legend's search for the emptiest corner walks every vertex. The envelope keeps those two values
    of every run, so the line looks the same, its peaks are exact, and drawing it costs a tenth. A series with a
    gap (NaN) or shorter than two columns comes back as it is.

    Examples
    --------
    >>> x = np.arange(10.0); y = np.array([0, 5, 1, 2, -3, 4, 0, 1, 9, 2.0])
    >>> [v.tolist() for v in envelope(x, y, columns=2)]
    [[0.0, 1.0, 4.0, 6.0, 8.0, 9.0], [0.0, 5.0, -3.0, 0.0, 9.0, 2.0]]
    """
    x, y = np.asarray(x), np.asarray(y)
    n = y.size
    if n <= 2 * columns or not np.isfinite(y).all():
        return x, y
    run = -(-n // columns)  # ceil
    padded = np.concatenate([y, np.full(run * columns - n, y[-1])]).reshape(columns, run)
    start = np.arange(columns) * run
    low = np.minimum(start + padded.argmin(axis=1), n - 1)
    high = np.minimum(start + padded.argmax(axis=1), n - 1)
    # sorted: each run's two in their order, and the ends, so that the line spans the same axis
    keep = np.unique(np.concatenate([[0, n - 1], low, high]))
    return x[keep], y[keep]
