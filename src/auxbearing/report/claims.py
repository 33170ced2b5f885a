"""Claims of the source paper, checked against our numbers; and the assumptions we had to make.

Each stage of the study returns :class:`Claim` rows (what the paper says, what we get, a verdict
and a sentence of why) and :class:`Assumption` rows (a parameter the paper does not give, the
value we chose, why).
"""

from __future__ import annotations

from dataclasses import asdict, dataclass

HOLDS = "holds"
DOES_NOT_HOLD = "does not hold"
CANNOT_CHECK = "cannot be checked"
VERDICTS = (HOLDS, DOES_NOT_HOLD, CANNOT_CHECK)


@dataclass(frozen=True)
class Claim:
    """One quantitative or qualitative claim of the paper and our verdict on it."""

    section: str
    statement: str
    paper: str
    ours: str
    verdict: str
    why: str

    def __post_init__(self) -> None:
        if self.verdict not in VERDICTS:
            raise ValueError(f"verdict = {self.verdict!r}: must be one of {VERDICTS}")

    def as_dict(self) -> dict:
        """Plain mapping for JSON."""
        return asdict(self)


@dataclass(frozen=True)
class Assumption:
    """A parameter the paper does not give (or gives wrongly) and the value the study uses."""

    parameter: str
    value: str
    why: str

    def as_dict(self) -> dict:
        """Plain mapping for JSON."""
        return asdict(self)


def within(ours: float, paper: float, rel: float) -> str:
    """``holds`` when |ours/paper - 1| <= rel, else ``does not hold``."""
    return HOLDS if abs(ours / paper - 1.0) <= rel else DOES_NOT_HOLD
