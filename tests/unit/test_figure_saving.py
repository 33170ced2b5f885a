"""Figures are saved whole: a constrained layout is kept as laid out, anything else is cropped to what it draws."""

import base64
import io

from matplotlib.figure import Figure
from PIL import Image

from auxbearing.common.io import trim_of
from auxbearing.report.html import figure_png_base64


def _legend_below(layout):
    fig = Figure(figsize=(4, 3), layout=layout)
    ax = fig.add_subplot()
    ax.plot([0, 1], [0, 1], label="a line")
    ax.legend(loc="upper center", bbox_to_anchor=(0.5, -0.15))
    return fig


def test_constrained_figure_is_saved_as_laid_out_and_others_are_cropped():
    assert trim_of(_legend_below("constrained")) == {}
    assert trim_of(_legend_below(None)) == {"bbox_inches": "tight"}


def test_constrained_figure_keeps_its_canvas_with_the_legend_inside():
    fig = _legend_below("constrained")
    png = Image.open(io.BytesIO(base64.b64decode(figure_png_base64(fig))))
    assert png.size == ((4 * 110), (3 * 110))  # the canvas at the report's 110 dpi, not cropped
    fig.canvas.draw()
    legend = fig.axes[0].get_legend().get_window_extent()
    assert legend.y0 >= 0.0 and legend.x0 >= 0.0 and legend.x1 <= fig.bbox.width  # drawn inside the canvas
