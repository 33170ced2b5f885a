"""Distributions of the uncertain inputs of a campaign, read from ``[[campaign.input]]`` tables.

Each distribution maps a point ``u`` of the unit interval to a value through its inverse cumulative
distribution function (the quantile function), so any design on the unit hypercube (Sobol, Latin
hypercube, plain random, Saltelli) becomes a sample of the inputs. Parameters carry units and are
held in SI.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from auxbearing.common.errors import InputError
from auxbearing.common.params import SERVICE_TEMPERATURE, Param, check, convert, si_unit

#: Parameter keys of each kind (besides ``key`` and ``distribution``), in the order they are held.
KINDS: dict[str, tuple[str, ...]] = {
    "uniform": ("low", "high"),
    "normal": ("mean", "std"),
    "lognormal": ("mean", "std"),
    "truncated_normal": ("mean", "std", "low", "high"),
    "list": ("values",),
}
#: Other spellings a person may write for a kind.
ALIASES = {"truncated normal": "truncated_normal", "truncnorm": "truncated_normal", "values": "list",
           "log-normal": "lognormal", "gaussian": "normal"}
#: Points of the unit interval are kept this far from 0 and 1, so that unbounded quantile functions
#: stay finite (the spacing of doubles just below 1).
UNIT_MARGIN = 2.0**-53


@dataclass(frozen=True)
class Distribution:
    """A distribution of one input: its kind and its SI parameters (see :data:`KINDS`)."""

    kind: str
    params: tuple[float, ...]

    def ppf(self, u: np.ndarray) -> np.ndarray:
        """Values at the points ``u`` of the unit interval (the quantile function).

        The lognormal takes the mean m and standard deviation s of the quantity itself:
        sigma^2 = ln(1 + s^2/m^2), mu = ln m - sigma^2/2, from its mean exp(mu + sigma^2/2) and variance
        (exp(sigma^2) - 1) exp(2 mu + sigma^2) (Johnson, Kotz & Balakrishnan, Continuous Univariate
        Distributions, Vol. 1, 2nd ed., 1994, Ch. 14).

        Examples
        --------
        >>> Distribution("uniform", (0.0, 2.0)).ppf(np.array([0.25, 0.5])).tolist()
        [0.5, 1.0]
        >>> round(float(Distribution("normal", (0.2, 0.03)).ppf(np.array([0.975]))[0]), 4)
        0.2588
        >>> Distribution("list", (1.0, 2.0, 5.0)).ppf(np.array([0.1, 0.5, 0.99])).tolist()
        [1.0, 2.0, 5.0]
        """
        from scipy import stats

        u = np.clip(np.asarray(u, dtype=float), UNIT_MARGIN, 1.0 - UNIT_MARGIN)
        p = self.params
        if self.kind == "uniform":
            return p[0] + (p[1] - p[0]) * u
        if self.kind == "normal":
            return stats.norm.ppf(u, loc=p[0], scale=p[1])
        if self.kind == "lognormal":
            sigma, mu = _lognormal(p[0], p[1])
            return stats.lognorm.ppf(u, s=sigma, scale=math.exp(mu))
        if self.kind == "truncated_normal":
            mean, std, low, high = p
            return stats.truncnorm.ppf(u, (low - mean) / std, (high - mean) / std, loc=mean, scale=std)
        values = np.asarray(p)
        return values[np.minimum((u * len(values)).astype(int), len(values) - 1)]

    def support(self) -> tuple[float, float]:
        """Smallest and largest value the distribution can give (infinite when unbounded)."""
        p = self.params
        if self.kind in ("uniform",):
            return p[0], p[1]
        if self.kind == "truncated_normal":
            return p[2], p[3]
        if self.kind == "list":
            return min(p), max(p)
        if self.kind == "lognormal":
            return 0.0, math.inf
        return -math.inf, math.inf

    def median(self) -> float:
        """The value at u = 1/2."""
        return float(self.ppf(np.array([0.5]))[0])

    def mass_outside(self, low: float, high: float) -> float:
        """Probability of a value below ``low`` or above ``high``."""
        from scipy import stats

        p = self.params
        if self.kind == "normal":
            return float(stats.norm.cdf(low, p[0], p[1]) + stats.norm.sf(high, p[0], p[1]))
        if self.kind == "lognormal":
            sigma, mu = _lognormal(p[0], p[1])
            dist = stats.lognorm(s=sigma, scale=math.exp(mu))
            return float(dist.cdf(low) + dist.sf(high)) if low > 0.0 else float(dist.sf(high))
        lo, hi = self.support()
        return 0.0 if low <= lo and hi <= high else 1.0

    def describe(self) -> dict:
        """The kind and SI parameters by name, for files."""
        if self.kind == "list":
            return {"distribution": "list", "values": list(self.params)}
        return {"distribution": self.kind, **dict(zip(KINDS[self.kind], self.params, strict=True))}


def _lognormal(mean: float, std: float) -> tuple[float, float]:
    """(sigma, mu) of ln X for a lognormal X of the given mean and standard deviation."""
    sigma2 = math.log1p((std / mean) ** 2)
    return math.sqrt(sigma2), math.log(mean) - 0.5 * sigma2


def _number(field: str, value: object, param: Param) -> float:
    """One distribution parameter in SI; a plain number is refused where the input has a unit."""
    unit = si_unit(param.dimension)
    if isinstance(value, (int, float)) and not isinstance(value, bool) and unit and param.dimension != "dimensionless":
        raise InputError.for_field(field, value,
                                   f"needs a unit, e.g. '{value} {param.display_unit or unit}'")
    return convert(field, value, param.dimension)


def distribution_from_table(table: dict, param: Param, where: str) -> Distribution:
    """A :class:`Distribution` from one ``[[campaign.input]]`` table, every parameter checked.

    ``where`` names the table in messages (``campaign.input.0``); ``param`` is the machine input it
    varies, whose dimension gives the units and whose rule bounds a distribution with a bounded support.

    Examples
    --------
    >>> from auxbearing.machine.params import TABLES
    >>> d = distribution_from_table({"distribution": "uniform", "low": "0 deg", "high": "360 deg"},
    ...                             TABLES["rotor"]["unbalance_phase"], "campaign.input.0")
    >>> d.kind, round(d.params[1], 4)
    ('uniform', 6.2832)
    >>> distribution_from_table({"distribution": "normal", "mean": 0.2, "std": -0.1},
    ...                         TABLES["touchdown"]["sliding_friction"], "campaign.input.1")
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: campaign.input.1.std = -0.1: must be > 0
    """
    raw_kind = table.get("distribution")
    if not isinstance(raw_kind, str):
        raise InputError.for_field(where + ".distribution", raw_kind, "give one of " + ", ".join(KINDS))
    kind = ALIASES.get(raw_kind.strip().lower(), raw_kind.strip().lower())
    if kind not in KINDS:
        raise InputError.for_field(where + ".distribution", raw_kind, "unknown distribution; use one of "
                                   + ", ".join(KINDS))
    names = KINDS[kind]
    for key in table:
        if key not in ("key", "distribution", *names):
            raise InputError.for_field(f"{where}.{key}", table[key], f"unknown key for a {kind} distribution; "
                                       "allowed keys: " + ", ".join(names))
    for key in names:
        if key not in table:
            raise InputError(f"{where}.{key}: missing; a {kind} distribution needs " + ", ".join(names))
    if kind == "list":
        values = table["values"]
        if not isinstance(values, list) or not values:
            raise InputError.for_field(where + ".values", values, "must be a non-empty list of values")
        numbers = tuple(_number(f"{where}.values.{i}", v, param) for i, v in enumerate(values))
        for i, v in enumerate(numbers):
            check(param, v, f"{where}.values.{i}")
        return Distribution(kind, numbers)
    if param.dimension == "temperature" and isinstance(table.get("std"), str) and "deg" in table["std"]:
        # "5 degC" would be read as a temperature (278 K), not as a spread of 5 K
        raise InputError.for_field(where + ".std", table["std"], "a spread of temperature is given in K")
    numbers = {key: _number(f"{where}.{key}", table[key], param) for key in names}
    if "std" in numbers and not numbers["std"] > 0.0:
        raise InputError.for_field(where + ".std", table["std"], "must be > 0")
    if "low" in numbers and not numbers["low"] < numbers["high"]:
        raise InputError.for_field(where + ".high", table["high"], f"must be above low = {table['low']!r}")
    if kind == "lognormal" and not numbers["mean"] > 0.0:
        raise InputError.for_field(where + ".mean", table["mean"], "must be > 0 for a lognormal")
    # the ends of a bounded support must obey the input's rule; an unbounded one is judged by its mean
    for key in ("low", "high") if "low" in numbers else ("mean",):
        check(param, numbers[key], f"{where}.{key}")
    return Distribution(kind, tuple(numbers[k] for k in names))


#: Rules of :mod:`auxbearing.common.params` as intervals a sampled value must lie in.
RULE_RANGES = {"positive": (0.0, math.inf), "optional_positive": (0.0, math.inf),
               "nonnegative": (0.0, math.inf), "optional_nonnegative": (0.0, math.inf), "unit_interval": (0.0, 1.0),
               "tolerance": (0.0, 1e-2), "fraction": (0.0, 1.0), "temperature_rise": (0.0, 10.0),
               # padded as check pads it: "-73 degC" converts to 200.14999999999998 K, which the rule accepts
               "service_temperature": (SERVICE_TEMPERATURE[0] - 1e-9, SERVICE_TEMPERATURE[1] + 1e-9)}


def share_outside_rule(distribution: Distribution, param: Param) -> float:
    """Probability that a sample breaks the input's rule (such samples become ``invalid_input`` records)."""
    low, high = RULE_RANGES.get(param.rule, (-math.inf, math.inf))
    return distribution.mass_outside(low, high)
