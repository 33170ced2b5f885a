"""The study's TOML configuration: every section optional, defaults are the paper's.

```toml
[study]
title = "My auxiliary bearing study"
ball_load = "1000 N"                      # contact study load on one ball
contact_angles = ["10 deg", "75 deg", "1 deg"]   # start, stop, step
groove_ratios = [0.505, 0.6, 0.0025]             # start, stop, step
paper_comparison = false  # true: the paper's QJ202/7202 numbers beside your bearings' results

[bearing]                 # the four-point bearing: a full [bearing] table, or
catalogue = "QJ202"       # a catalogue entry
[comparison_bearing]      # the angular-contact bearing it is compared with
catalogue = "7202"

[rotor]                   # rotor and drop case: see `auxbearing drop --help`
[drop]
```

The static stage always runs the paper's load grid (Fig. 6-8) and the experiment stage the shipped
SYNTHETIC records, so a ``[static]`` or ``[experiment]`` table would be read by nothing: it is refused
rather than ignored.

A file whose ``[bearing]``, ``[comparison_bearing]``, ``[rotor]`` or ``[drop]`` differs from the paper's
is a study of the user's own bearings (:attr:`StudyConfig.own_bearings`): its report speaks of those
bearings only, unless ``paper_comparison = true``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, fields
from pathlib import Path

import numpy as np

from auxbearing.bearings.catalogue import get_bearing
from auxbearing.bearings.geometry import BearingGeometry, bearing_from_mapping, read_toml
from auxbearing.common.errors import InputError
from auxbearing.common.units import to_si

SECTIONS = ("study", "bearing", "comparison_bearing", "rotor", "drop")
#: Tables a study file might be expected to take but that no stage reads, with the reason.
UNREAD_SECTIONS = {
    "static": "the static stage runs the paper's load grid of Fig. 6-8 on the two bearings",
    "experiment": "the experiment stage runs the shipped SYNTHETIC drop records",
}
#: Bearing type each bearing table of a study must have (the paper compares these two kinds).
BEARING_TYPES = {"bearing": "four_point", "comparison_bearing": "angular_contact"}
STUDY_KEYS = ("title", "ball_load", "contact_angles", "groove_ratios", "paper_comparison")
DEFAULT_TITLE = "auxbearing study: four-point-contact auxiliary bearings"


@dataclass(frozen=True)
class StudyConfig:
    """Validated study inputs (SI)."""

    bearing: BearingGeometry
    comparison: BearingGeometry
    title: str = DEFAULT_TITLE
    ball_load: float = 1000.0
    contact_angles_deg: tuple[float, float, float] = (10.0, 75.0, 1.0)
    groove_ratios: tuple[float, float, float] = (0.505, 0.6, 0.0025)
    sections: dict = field(default_factory=dict)  # raw [rotor] and [drop] tables (checked when read)
    source: str = "defaults (the paper)"
    paper_comparison: bool = False  # the paper's numbers beside a study of the user's own bearings

    @property
    def own_bearings(self) -> bool:
        """True when the bearings, rotor or drop differ from the paper's (a study of the user's own bearings)."""
        from auxbearing.planar.params import DropCase, Rotor, from_mapping

        base = default_config()
        if self.bearing != base.bearing or self.comparison != base.comparison:
            return True
        rotor = Rotor(**from_mapping(self.sections.get("rotor"), "rotor"))
        case = DropCase(**from_mapping(self.sections.get("drop"), "drop"))
        return not (_same(rotor, Rotor()) and _same(case, DropCase()))

    def framing(self):
        """How the report is written: the paper's study, the user's own bearings, or those with the paper's numbers."""
        from auxbearing.report.model import OWN_STUDY, OWN_WITH_PAPER, PAPER_STUDY

        if not self.own_bearings:
            return PAPER_STUDY
        return OWN_WITH_PAPER if self.paper_comparison else OWN_STUDY

    def angle_grid(self) -> np.ndarray:
        """Contact angles of the sweep [deg] (never past the stop)."""
        from auxbearing.analysis.contact import sweep_grid

        return sweep_grid(*self.contact_angles_deg)

    def ratio_grid(self) -> np.ndarray:
        """Groove ratios of the sweep [-] (never past the stop)."""
        from auxbearing.analysis.contact import sweep_grid

        return sweep_grid(*self.groove_ratios)

    def describe(self) -> dict:
        """Inputs for files and the report."""
        return {
            "config": self.source,
            "title": self.title,
            "ball_load_N": self.ball_load,
            "contact_angles_deg": list(self.contact_angles_deg),
            "groove_ratios": list(self.groove_ratios),
            "own_bearings": self.own_bearings,
            "paper_comparison": self.paper_comparison,
            "four_point_bearing": self.bearing.describe(),
            "angular_contact_bearing": self.comparison.describe(),
            **{name: table for name, table in self.sections.items()},
        }


def default_config() -> StudyConfig:
    """The paper's study: QJ202 against 7202, Table I and Table II."""
    return StudyConfig(bearing=get_bearing("QJ202"), comparison=get_bearing("7202"))


def load_study_config(path: str | Path | None, field: str = "file") -> StudyConfig:
    """Read and validate a study TOML file; ``None`` gives :func:`default_config`.

    Every table is checked here, before any stage runs; ``field`` names the file in an error
    (``--config`` on the command line).
    """
    if path is None:
        return default_config()
    data = read_toml(path, field)
    for name, value in data.items():
        if name in UNREAD_SECTIONS:
            raise InputError.for_field(f"[{name}]", "table", f"not read by a study ({UNREAD_SECTIONS[name]}); "
                                                            "remove it")
        if name not in SECTIONS:
            raise InputError.for_field(f"[{name}]", "table", "unknown section; allowed: " + ", ".join(SECTIONS))
        if not isinstance(value, dict):
            raise InputError.for_field(name, value, f"must be a table ([{name}]), not a single value")
    study = data.get("study", {})
    bad = [k for k in study if k not in STUDY_KEYS]
    if bad:
        raise InputError.for_field(f"study.{bad[0]}", study[bad[0]], "unknown key; allowed: " + ", ".join(STUDY_KEYS))
    base = default_config()
    bearing = _bearing(data.get("bearing"), base.bearing, "bearing")
    comparison = _bearing(data.get("comparison_bearing"), base.comparison, "comparison_bearing")
    ball_load = to_si("study.ball_load", study.get("ball_load", "1000 N"), "force")
    if ball_load <= 0:
        raise InputError.for_field("study.ball_load", study["ball_load"], "must be > 0 N")
    angles = _triple("study.contact_angles", study.get("contact_angles"), "angle", base.contact_angles_deg, deg=True)
    if angles[0] < 0 or angles[1] >= 90:
        raise InputError.for_field("study.contact_angles", study["contact_angles"], "must lie in [0, 90) deg")
    ratios = _triple("study.groove_ratios", study.get("groove_ratios"), "dimensionless", base.groove_ratios)
    if ratios[0] <= 0.5:
        raise InputError.for_field("study.groove_ratios", study["groove_ratios"], "must start above 0.5")
    _check_hertz_range(study, bearing, comparison, ball_load, angles, ratios)
    sections = {name: data[name] for name in ("rotor", "drop") if name in data}
    _check_drop_tables(sections)
    paper_comparison = study.get("paper_comparison", False)
    if not isinstance(paper_comparison, bool):
        raise InputError.for_field("study.paper_comparison", paper_comparison, "must be true or false")
    return StudyConfig(bearing=bearing, comparison=comparison, title=str(study.get("title", DEFAULT_TITLE)),
                       ball_load=ball_load, contact_angles_deg=angles, groove_ratios=ratios,
                       sections=sections, source=str(path), paper_comparison=paper_comparison)


def _check_hertz_range(study: dict, bearing: BearingGeometry, comparison: BearingGeometry, ball_load: float,
                       angles: tuple[float, float, float], ratios: tuple[float, float, float]) -> None:
    """Refuse a contact stage with no Hertz result in it, as ``auxbearing contact`` refuses one contact.

    The stage computes one ball of each bearing, the four-point bearing's geometry as an angular-contact one
    (Fig. 4) and a map over the angle and ratio grids; any contact ellipse as large as the ball is outside Hertz
    theory (:func:`auxbearing.analysis.contact.ellipse_checks`). Checked on the grid by
    :func:`~auxbearing.analysis.contact.grid_refusal`, which blames the grid the largest ellipse comes from:
    the angles (or the load) when the bearing's own groove ratio already fails at the largest angle, else
    the ratios; of those, the first the file gives.
    """
    from auxbearing.analysis.contact import OutsideHertz, ball_contact, grid_refusal, sweep_grid, type_comparison

    load_text = study.get("ball_load", "1000 N")
    for name, check in ((bearing.name, lambda: ball_contact(bearing, ball_load)),
                        (comparison.name, lambda: ball_contact(comparison, ball_load)),
                        (f"{bearing.name} as angular contact, Fig. 4", lambda: type_comparison(bearing, ball_load))):
        try:
            check()
        except OutsideHertz as err:
            raise InputError.for_field("study.ball_load", load_text, f"{err.reason} (bearing {name})") from None
    angle_grid, ratio_grid = sweep_grid(*angles), sweep_grid(*ratios)
    reason = grid_refusal(bearing, ball_load, angle_grid, ratio_grid)
    if reason is None:
        return
    # at the bearing's own groove ratio the angles (or the load) go too far; else only the ratios reach it
    at_own_ratio = grid_refusal(bearing, ball_load, angle_grid, [bearing.inner_groove_ratio]) is not None
    order = ("contact_angles", "ball_load", "groove_ratios") if at_own_ratio else (
        "groove_ratios", "contact_angles", "ball_load")
    key = next((k for k in order if k in study), None)
    rule = f"{reason} (bearing {bearing.name}, ball load {ball_load:g} N)"
    if key is None:  # the paper's sweep and load: the bearing's own geometry is what leaves Hertz theory
        raise InputError.for_field("bearing", bearing.name, rule + " over the study's default contact sweep")
    raise InputError.for_field(f"study.{key}", study[key], rule)


def _same(a: object, b: object) -> bool:
    """Two Rotor or DropCase values alike field by field (a value read with units may differ in the last bit)."""
    for f in fields(a):
        x, y = getattr(a, f.name), getattr(b, f.name)
        if (x is None) != (y is None) or (x is not None and not math.isclose(x, y, rel_tol=1e-12, abs_tol=0.0)):
            return False
    return True


def _check_drop_tables(sections: dict) -> None:
    """The [rotor] and [drop] tables as the drop stage will read them, checked now (not after an hour of stages)."""
    from auxbearing.planar.params import DropCase, Rotor, from_mapping

    Rotor(**from_mapping(sections.get("rotor"), "rotor"))
    DropCase(**from_mapping(sections.get("drop"), "drop"))


def _bearing(table: dict | None, default: BearingGeometry, prefix: str) -> BearingGeometry:
    if table is None:
        return default
    if not isinstance(table, dict):
        raise InputError.for_field(prefix, table, "must be a table")
    if set(table) == {"catalogue"}:
        spec = table["catalogue"]
        bearing = get_bearing(str(spec), f"{prefix}.catalogue")
    else:
        spec = "table"
        bearing = bearing_from_mapping(table, name=prefix, prefix=f"{prefix}.")
    kind = BEARING_TYPES[prefix]
    if bearing.type != kind:
        where = f"{prefix}.catalogue" if spec != "table" else f"{prefix}.type"
        raise InputError.for_field(where, spec if spec != "table" else bearing.type,
                                   f"is a {bearing.type} bearing; a study compares a four_point [bearing] with an "
                                   "angular_contact [comparison_bearing]")
    return bearing


def _triple(field_name, value, dimension, default, deg=False) -> tuple[float, float, float]:
    if value is None:
        return default
    if not isinstance(value, list) or len(value) != 3:
        raise InputError.for_field(field_name, value, "must be a list [start, stop, step]")
    numbers = [to_si(f"{field_name}[{i}]", v, dimension) for i, v in enumerate(value)]
    if deg:
        numbers = [float(np.degrees(v)) for v in numbers]
    start, stop, step = numbers
    if step <= 0 or stop < start:
        raise InputError.for_field(field_name, value, "needs start <= stop and step > 0")
    if (stop - start) / step > 2000:
        raise InputError.for_field(field_name, value, "more than 2000 grid points; take a larger step")
    return (start, stop, step)
