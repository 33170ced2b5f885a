"""Where a plot draws: the caller's axes or figure, or a fresh one (never pyplot).

A single-panel plot takes ``ax=None`` and starts with :func:`axes_for`; a multi-panel plot
takes ``fig=None``, starts with :func:`figure_for` and draws each panel with the
single-panel functions into its own axes.
"""

from __future__ import annotations

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
