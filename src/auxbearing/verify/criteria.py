"""The criteria a touchdown-bearing design is judged by: each with a value a user can set and a stated default.

ISO 14839-5:2022 lays out what a touchdown-bearing verification covers (load requirements, sizing,
simulation of the touchdown events, failure modes); its acceptance values are the purchaser's. The
``[criteria]`` table of a machine file sets them; :data:`CRITERIA` lists each key's default and where
it comes from.

Margins are in each criterion's own physical sense (:data:`MARGINS` says which for each):

* a load, stress, count or probability that must stay under a limit: the share of the limit still unused,
  ``1 - found / limit`` (a ratio scale: zero means nothing);
* one that must reach a value (s0, drops to failure): how far above it, ``found / required - 1``;
* a temperature: the share of the allowed rise above ambient still unused,
  ``(T_allowed - T_found) / (T_allowed - T_ambient)`` (a Celsius value is on an offset scale, so a percentage
  of it means nothing);
* a yes/no criterion has no margin.

A criterion whose input is missing (the magnetic air gap, a seal clearance) or whose run did not finish is
listed as not checked, never as passed; a verification with any criterion not checked is INCOMPLETE.
"""

from __future__ import annotations

import math
from typing import NamedTuple

from auxbearing.analysis.whirl import BACKWARD
from auxbearing.machine.judging import CRITERIA_TABLE as TABLE


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


def temperature_bound(name: str, found: float | None, allowed: float, ambient: float, origin_text: str,
                      evidence: str) -> Criterion:
    """A temperature that must stay under ``allowed`` [degC]; margin: the unused share of the rise above ambient."""
    if found is None or (isinstance(found, float) and math.isnan(found)):
        return Criterion(name, allowed, None, None, False, "°C", "temperature", origin_text, evidence)
    margin = (allowed - found) / (allowed - ambient) if allowed > ambient else -math.inf
    return Criterion(name, allowed, found, margin, bool(found <= allowed), "°C", "temperature", origin_text, evidence)


#: How each kind of criterion's margin is measured (the report's and verify.json's legend).
MARGINS = {
    "lower": "found / required - 1: how far above the required value",
    "upper": "1 - found / limit: the share of the limit still unused",
    "temperature": "(T_allowed - T_found) / (T_allowed - T_ambient): the share of the allowed rise above ambient "
                   "still unused",
    "yes/no": "none (holds or not)",
    "not checked": "none: nothing in the file to check it against (a criterion of another kind that a cut run "
                   "left open keeps that kind's margin, for what the run found, and counts neither way)",
}


def worst_margin(criteria: list[Criterion]) -> float:
    """The smallest margin of the checked criteria that have one (NaN when none has)."""
    values = [c.margin for c in criteria if c.passed is not None and c.margin is not None]
    return min(values) if values else math.nan


#: The verdicts of a verification.
PASS, FAIL, INCOMPLETE = "pass", "fail", "incomplete"


def overall_verdict(criteria: list[Criterion]) -> str:
    """FAIL if a criterion fails; INCOMPLETE if none fails but one is not checked; PASS only when all hold."""
    if any(c.passed is False for c in criteria):
        return FAIL
    if any(c.passed is None for c in criteria):
        return INCOMPLETE
    return PASS


def ranking_key(criteria: list[Criterion]) -> tuple:
    """Sort key of a design: fewer failing criteria first, then fewer unchecked, then the larger worst margin.

    Designs alike in all three (a --quick look, whose cut runs check nothing that has a margin) go by the margins
    their unchecked findings show, worst first (a margin they all share, such as a small campaign's, decides
    nothing).
    """
    margin = worst_margin(criteria)
    shown = sorted(c.margin for c in criteria if c.passed is None and c.margin is not None)
    return (sum(c.passed is False for c in criteria), sum(c.passed is None for c in criteria),
            -margin if math.isfinite(margin) else math.inf, tuple(-m for m in shown))


def whirls_backward(plane: dict) -> bool:
    """Whether a drop's plane (its summary) shows sustained backward whirl or dry whip.

    Either a backward whirl sustained from some time on, or a final whirl class that is backward (rolling whirl or
    dry whip). The verdict and the geometry search both use it; the campaign counts a drop whose whirl was
    classified by the same test (:func:`auxbearing.campaign.evaluate._record_from_summary`), so none of the three
    can call a drop whirl-free that another counts as whirling.

    >>> whirls_backward({"backward_whirl_onset_ms": None, "whirl": "dry_whip"})
    True
    >>> whirls_backward({"backward_whirl_onset_ms": None, "whirl": "forward"})
    False
    """
    return plane.get("backward_whirl_onset_ms") is not None or plane.get("whirl") in BACKWARD


def whirl_fails_whatever_follows(whirled: int, ended_ok: int, left: int, limit: float) -> bool:
    """True when the whirl criterion fails however the drops still to run end.

    The criterion fails when the campaign's estimate exceeds the limit (and so does the upper bound above it;
    an estimate within the limit under a bound beyond it is "not checked"). The smallest estimate the whole
    campaign can still give counts every drop left as ending ok without whirl: whirled / (ended_ok + left).
    Once that exceeds the limit, the rest cannot change the outcome, only narrow the interval.
    """
    return ended_ok + left > 0 and whirled / (ended_ok + left) > limit
