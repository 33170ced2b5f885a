"""What a study stage hands to the report: figures, tables, data, claims, assumptions."""

from __future__ import annotations

from dataclasses import dataclass, field

import xarray as xr
from matplotlib.figure import Figure as MplFigure

from auxbearing.paper.claims import Assumption, Claim


@dataclass
class Figure:
    """A figure with its file stem, caption and what the paper says about it."""

    name: str
    caption: str
    figure: MplFigure
    paper_says: str = ""


@dataclass
class Section:
    """One stage's contribution to the report."""

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
