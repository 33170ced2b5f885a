"""What a study stage hands to the report: figures, tables, data, claims, assumptions, warnings.

A study is written in one of two framings (:class:`Framing`): the paper's own case (QJ202 against
7202 on the paper's rig, captions and claims of the paper) or the user's bearings (captions read
from the user's bearings, rotor and drop; the paper's numbers only when asked for, and then
labelled as the paper's).
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

import xarray as xr
from matplotlib.figure import Figure as MplFigure

from auxbearing.report.claims import Assumption, Claim


@dataclass(frozen=True)
class Framing:
    """How a study section is written.

    Attributes
    ----------
    own : bool
        Captions, titles and file names come from the user's bearings, rotor and drop, not the
        paper's figure numbers and test rig.
    paper : bool
        The paper's claims, "Paper says" boxes and numbers are shown beside the results.
    """

    own: bool = False
    paper: bool = True

    @property
    def paper_label(self) -> str:
        """How the paper's numbers are named: plainly in the paper's study, as the paper's bearings otherwise."""
        return "Paper (its QJ202/7202)" if self.own else "Paper"


#: The paper's study: everything of the paper, as before.
PAPER_STUDY = Framing(own=False, paper=True)
#: A study of the user's own bearings, nothing of the paper.
OWN_STUDY = Framing(own=True, paper=False)
#: The user's bearings with the paper's QJ202/7202 numbers beside them (``paper_comparison = true``).
OWN_WITH_PAPER = Framing(own=True, paper=True)


@dataclass
class Figure:
    """A figure with its file stem, caption and what the paper says about it."""

    name: str
    caption: str
    figure: MplFigure
    paper_says: str = ""


@dataclass
class Section:
    """One stage's contribution to the report.

    ``paper`` is the paper's account of the stage (empty when the paper is not shown), ``about``
    what the stage computed on the bearings at hand, ``key_results`` rows of (quantity, value for
    the four-point bearing, value for the comparison bearing) for the report's summary, and
    ``warnings`` sentences on results outside the model's range (shown at the top of the report).
    """

    key: str
    title: str
    paper: str
    figures: list[Figure] = field(default_factory=list)
    tables: list[dict] = field(default_factory=list)
    datasets: dict[str, xr.Dataset] = field(default_factory=dict)
    claims: list[Claim] = field(default_factory=list)
    assumptions: list[Assumption] = field(default_factory=list)
    results: dict = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    about: str = ""
    key_results: list[list[str]] = field(default_factory=list)
    warnings: list[str] = field(default_factory=list)


def retitle(fig: MplFigure, title: str) -> MplFigure:
    """Give a figure a title of its own, dropping panel titles that name one of the paper's figures."""
    fig.suptitle(title)
    for ax in fig.axes:
        for loc in ("left", "center"):
            if ax.get_title(loc=loc).startswith("Fig."):
                ax.set_title("", loc=loc)
    return fig


def slug(name: str) -> str:
    """A file-name-safe lower-case form of a bearing name ("QJ202 with 25 deg" -> "qj202_with_25_deg")."""
    return re.sub(r"[^a-z0-9]+", "_", name.lower()).strip("_") or "bearing"
