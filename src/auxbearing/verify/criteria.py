"""The criteria a touchdown-bearing design is judged by: each with a value a user can set and a stated default.

ISO 14839-5:2022 lays out what a touchdown-bearing verification covers (load requirements, sizing,
simulation of the touchdown events, failure modes); its acceptance values are the purchaser's. The
``[criteria]`` table of a machine file sets them; :data:`CRITERIA` lists each key's default and where
it comes from. Margins: for a lower bound (found >= required) ``found / required - 1``, for an upper
bound ``1 - found / required``; a yes/no criterion has no margin. A criterion whose input is missing
(the magnetic air gap, a seal clearance) is listed as not checked, never as passed.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from auxbearing.params import Param, by_key, read_table

CRITERIA: tuple[Param, ...] = (
    Param("criteria", "min_s0", "dimensionless", 1.0, "", "positive",
          "Smallest static safety factor s0 of any ball contact in any drop",
          "ISO 76:2006: s0 = C0/P0, and 1 loads a contact to 4200 MPa (a permanent set of 1e-4 D); makers ask 1.5-2 "
          "or more under shock, so raise it for your machine"),
    Param("criteria", "max_temperature", "temperature", 393.15, "degC", "positive",
          "Hottest bearing part over the coast-down",
          "ours: 120 degC, the heat-stabilisation limit makers state for standard through-hardened bearing steel; "
          "check your bearing's and its lubricant's"),
    Param("criteria", "max_preload_stress", "pressure", 4200e6, "MPa", "positive",
          "Ball stress at rest of the preload a closing internal clearance makes", "ISO 76:2006 (4200 MPa at rest)"),
    Param("criteria", "required_drops", "dimensionless", None, "", "optional_positive",
          "Drops (each with its coast-down) the bearings must survive; default life.required_drops",
          "the machine file's life.required_drops (itself an assumption unless you set it)"),
    Param("criteria", "amb_air_gap", "length", None, "mm", "optional_positive",
          "Radial air gap of the magnetic bearings; without it the air-gap criterion is not checked", "user input"),
    Param("criteria", "air_gap_fraction", "dimensionless", 0.5, "", "unit_interval",
          "Largest touchdown clearance (with thermal growth) as a fraction of the magnetic air gap",
          "ours: common practice of about half the air gap; not a clause we could read in ISO 14839-5"),
    Param("criteria", "seal_clearance", "length", None, "mm", "optional_positive",
          "Radial clearance of the tightest seal; the journal's largest excursion must stay inside it", "user input"),
    Param("criteria", "max_backward_whirl_probability", "dimensionless", 0.05, "", "unit_interval",
          "Largest probability of sustained backward whirl over the campaign's uncertain drop conditions", "ours"),
)
TABLE = by_key(CRITERIA, "criteria")


class Criterion(NamedTuple):
    """One judged criterion."""

    name: str
    required: object  #: the limit, as a number in ``unit`` or a text
    found: object  #: what the cases gave
    margin: float | None  #: relative margin (module docstring); None for yes/no and unchecked criteria
    passed: bool | None  #: None: not checked
    unit: str
    kind: str  #: "lower", "upper", "yes/no" or "not checked"
    origin: str  #: where the required value comes from
    evidence: str  #: which case and what it showed

    def as_json(self) -> dict:
        """The ``verify.json`` entry: name, required, found, margin, pass (and unit, kind, origin, evidence)."""
        return {"name": self.name, "required": self.required, "found": self.found, "margin": self.margin,
                "pass": self.passed, "unit": self.unit, "kind": self.kind, "origin": self.origin,
                "evidence": self.evidence}


def read_criteria(data: dict | None) -> dict:
    """The ``[criteria]`` table in SI (unknown keys refused with the list), defaults filled in."""
    given = read_table(data, TABLE, "criteria.")
    return {p.key: given.get(p.key, p.default) for p in CRITERIA} | {"given": sorted(given)}


def origin(key: str, criteria: dict) -> str:
    """Where a criterion's value comes from: the user's file, or the default's stated source."""
    return "your [criteria] table" if key in criteria["given"] else TABLE[key].source


def lower_bound(name: str, found: float | None, required: float, unit: str, origin_text: str,
                evidence: str) -> Criterion:
    """A lower bound: found >= required, margin found/required - 1."""
    if found is None or (isinstance(found, float) and math.isnan(found)):
        return Criterion(name, required, None, None, False, unit, "lower", origin_text, evidence)
    margin = found / required - 1.0 if required else math.inf
    return Criterion(name, required, found, margin, bool(found >= required), unit, "lower", origin_text, evidence)


def upper_bound(name: str, found: float | None, required: float, unit: str, origin_text: str,
                evidence: str) -> Criterion:
    """An upper bound: found <= required, margin 1 - found/required."""
    if found is None or (isinstance(found, float) and math.isnan(found)):
        return Criterion(name, required, None, None, False, unit, "upper", origin_text, evidence)
    margin = 1.0 - found / required if required else -math.inf
    return Criterion(name, required, found, margin, bool(found <= required), unit, "upper", origin_text, evidence)


def yes_no(name: str, required: str, found: str, passed: bool, origin_text: str, evidence: str) -> Criterion:
    """A criterion that holds or does not (no margin)."""
    return Criterion(name, required, found, None, bool(passed), "", "yes/no", origin_text, evidence)


def not_checked(name: str, why: str, origin_text: str) -> Criterion:
    """A criterion the file gives no input for: listed, never counted as passed."""
    return Criterion(name, None, None, None, None, "", "not checked", origin_text, why)


def worst_margin(criteria: list[Criterion]) -> float:
    """The smallest margin of the checked criteria (a failed yes/no criterion counts as -1, a passed one as +1)."""
    values = []
    for c in criteria:
        if c.passed is None:
            continue
        if c.margin is None:
            values.append(1.0 if c.passed else -1.0)
        else:
            values.append(c.margin)
    return min(values) if values else math.nan
