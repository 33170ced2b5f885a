"""Rotor and drop-case parameters: one table of names, units, defaults and rules (SI inside).

Source paper Sec. II.D and Table II, read as ../shared/paper/NOTES.md says. Each parameter is
declared once in :data:`PARAMETERS`; the dataclasses, their validation, the TOML ``[rotor]`` /
``[drop]`` sections and the command-line options are all built from that table, so a new
parameter is one row, not an edit in four places.

Values the paper does not give, and what we set (see ``source`` of each row): clearance s and
rotor radius r (s = 0.2 mm, r = bore/2 - s), unbalance phase at the drop (0), K_l's contact
length (the bearing width, which reproduces the paper's K_l), the slip-velocity regularisation
of friction, gravity, and the integration tolerances.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from pathlib import Path
from typing import NamedTuple

import pint

from auxbearing.bearing import BearingGeometry, bearing_from_mapping, read_toml
from auxbearing.errors import InputError
from auxbearing.units import SI_UNITS, Quantity, to_si, ureg

#: Units beyond :data:`auxbearing.units.SI_UNITS` that the drop needs: (SI unit, examples).
_EXTRA_UNITS = {
    "line_stiffness": ("N/m**(10/9)", "N/m**(10/9)"),
    "ball_constant": ("N/m**1.5", "N/m**1.5, N/mm**1.5"),
    "velocity": ("m/s", "m/s, mm/s"),
    "acceleration": ("m/s**2", "m/s**2"),
}


class Param(NamedTuple):
    """One parameter: where it lives, its unit, default, rule and source."""

    section: str  #: "rotor" or "drop"
    key: str  #: TOML key and dataclass field
    dimension: str  #: key of SI_UNITS or of _EXTRA_UNITS
    default: float | None  #: SI default; None means derived (see help)
    display_unit: str  #: unit for plain command-line numbers and help texts
    rule: str  #: positive | nonnegative | unit_interval | finite | tolerance | optional_positive
    help: str
    source: str


PARAMETERS: tuple[Param, ...] = (
    Param("rotor", "mass", "mass", 1.48, "kg", "positive", "Rotor mass m_r", "Table II"),
    Param("rotor", "polar_inertia", "inertia", 3.88e-4, "kg*m**2", "positive",
          "Polar moment of inertia of the rotor J_r about its mass centre", "Table II"),
    Param("rotor", "eccentricity", "length", 1e-5, "um", "nonnegative",
          "Unbalance eccentricity e of the mass centre", "Table II"),
    Param("rotor", "radius", "length", None, "mm", "optional_positive",
          "Journal radius r; default bore/2 - clearance", "not in the paper (NOTES item 6)"),
    Param("drop", "clearance", "length", 2e-4, "mm", "positive",
          "Single-side radial clearance s between journal and inner race",
          "not in the paper; 0.2 mm plausible for a 15 mm journal (NOTES item 6)"),
    Param("drop", "speed", "angular_speed", 6000.0 * math.pi / 30.0, "rpm", "finite",
          "Rotor spin speed at the drop (counter-clockwise positive)", "Sec. II.D (6000 rpm)"),
    Param("drop", "unbalance_phase", "angle", 0.0, "deg", "finite",
          "Angle of the unbalance from +x at the drop", "not in the paper (Sec. III names it a cause)"),
    Param("drop", "duration", "time", 0.15, "s", "positive", "Simulated time", "Sec. II.D"),
    Param("drop", "output_step", "time", 1e-5, "us", "positive", "Uniform output interval", "issue 4"),
    Param("drop", "race_mass", "mass", 0.0125, "kg", "positive", "Inner race mass m_b", "Table II"),
    Param("drop", "race_inertia", "inertia", 7.03e-7, "kg*m**2", "positive",
          "Inner race polar moment of inertia J_b", "Table II (printed as 'of rotor', NOTES item 5)"),
    Param("drop", "line_stiffness", "line_stiffness", None, "N/m**(10/9)", "optional_positive",
          "Rotor/race line-contact constant K_l; default Palmgren with the bearing width",
          "Table II 1.468e9; Palmgren l = 11 mm gives 1.463e9"),
    Param("drop", "line_damping", "damping", 1000.0, "N*s/m", "nonnegative",
          "Rotor/race contact damping C_l", "Table II"),
    Param("drop", "ball_damping", "damping", 500.0, "N*s/m", "nonnegative",
          "Ball-set damping C_b on the race velocity", "Table II"),
    Param("drop", "ball_constant", "ball_constant", None, "N/m**1.5", "optional_positive",
          "Override of the ball contact constant K_b; default Hertz (Eq. 15)",
          "Table II's 5.42e5 is plausible only in N/mm^1.5 (NOTES item 5)"),
    Param("drop", "sliding_friction", "dimensionless", 0.2, "", "unit_interval",
          "Rotor/race sliding friction coefficient mu_1", "Table II"),
    Param("drop", "rolling_friction", "dimensionless", 0.01, "", "unit_interval",
          "Rolling resistance coefficient of the race mu_2", "Table II"),
    Param("drop", "slip_velocity", "velocity", 1e-2, "mm/s", "positive",
          "Regularisation v_eps of sign(slip) in the friction law, tanh(v/v_eps)",
          "ours: 0.2 % of the journal surface speed; results insensitive (tests)"),
    Param("drop", "gravity", "acceleration", 9.80665, "m/s**2", "nonnegative",
          "Gravitational acceleration (along -y)", "standard gravity"),
    Param("drop", "rtol", "dimensionless", 1e-6, "", "tolerance",
          "Relative tolerance of the adaptive integration", "ours (converged, tests)"),
    Param("drop", "atol", "dimensionless", 1e-6, "", "tolerance",
          "Absolute tolerance, as a fraction of each state's scale (s, 1 rad, sqrt(2 g s), spin)", "ours"),
    Param("drop", "max_step", "time", 5e-5, "us", "positive",
          "Largest integration step (free flight must not step over a contact)",
          "ours: 1/8 of the 0.4 ms contact period"),
    Param("drop", "start_x", "length", 0.0, "mm", "finite", "Journal centre x at the drop", "Sec. II.D (centre)"),
    Param("drop", "start_y", "length", 0.0, "mm", "finite", "Journal centre y at the drop", "Sec. II.D (centre)"),
)

_BY_SECTION = {s: {p.key: p for p in PARAMETERS if p.section == s} for s in ("rotor", "drop")}


def convert(field: str, value: object, dimension: str, default_unit: str | None = None) -> float:
    """A user value in the SI unit of ``dimension`` (also the drop's extra dimensions).

    Examples
    --------
    >>> f"{convert('ball_constant', '5.42e5 N/mm**1.5', 'ball_constant'):.4g}"
    '1.714e+10'
    >>> convert("slip_velocity", "10 mm/s", "velocity")
    0.01
    """
    if dimension in SI_UNITS:
        return to_si(field, value, dimension, default_unit)
    unit, examples = _EXTRA_UNITS[dimension]
    if isinstance(value, bool):
        raise InputError.for_field(field, value, f"must be a number with a unit such as {examples}")
    try:
        if isinstance(value, (int, float)):
            if default_unit is None:
                raise InputError.for_field(field, value, f"needs a unit, e.g. '{value} {unit}'")
            quantity = Quantity(float(value), default_unit)
        elif isinstance(value, str):
            quantity = ureg.Quantity(value.strip())
            if not isinstance(quantity, pint.Quantity) or quantity.dimensionless:
                if default_unit is None:
                    raise InputError.for_field(field, value, f"needs a unit, e.g. '{value} {unit}'")
                quantity = Quantity(float(getattr(quantity, "magnitude", quantity)), default_unit)
        elif isinstance(value, pint.Quantity):
            quantity = value
        else:
            raise InputError.for_field(field, value, f"must be a number with a unit such as {examples}")
        magnitude = float(quantity.to(unit).magnitude)
    except InputError:
        raise
    except pint.DimensionalityError:
        raise InputError.for_field(field, value,
                                   f"unit is not a {dimension.replace('_', ' ')} (use {examples})") from None
    except Exception:  # pint raises several unrelated types for malformed text
        raise InputError.for_field(field, value, f"cannot read it as a value such as '1 {unit}'") from None
    if not math.isfinite(magnitude):
        raise InputError.for_field(field, value, "must be a finite number")
    return magnitude


def check(param: Param, value: object, field: str | None = None) -> None:
    """Apply the parameter's rule; InputError names the field, the value and the rule."""
    name = field or f"{param.section}.{param.key}"
    if value is None:
        if param.rule == "optional_positive":
            return
        raise InputError.for_field(name, value, "is required")
    if isinstance(value, bool) or not isinstance(value, (int, float)) or math.isnan(value):
        raise InputError.for_field(name, value, f"must be a number in {param.display_unit or 'SI'}")
    shown = display_value(param, value)
    if math.isinf(value):
        raise InputError.for_field(name, shown, "must be finite")
    rule = param.rule
    if rule in ("positive", "optional_positive") and value <= 0.0:
        raise InputError.for_field(name, shown, "must be > 0")
    if rule == "nonnegative" and value < 0.0:
        raise InputError.for_field(name, shown, "must be >= 0")
    if rule == "unit_interval" and not 0.0 <= value <= 1.0:
        raise InputError.for_field(name, shown, "must lie in [0, 1]")
    if rule == "tolerance" and not 0.0 < value <= 1e-2:
        raise InputError.for_field(name, shown, "must lie in (0, 0.01]")


def display_value(param: Param, value: float) -> object:
    """The value in the parameter's display unit, as a user would have typed it."""
    if not param.display_unit:
        return value
    si = SI_UNITS.get(param.dimension) or _EXTRA_UNITS[param.dimension][0]
    try:
        return f"{Quantity(value, si).to(param.display_unit).magnitude:.6g} {param.display_unit}"
    except pint.DimensionalityError:  # pragma: no cover - table consistency is tested
        return value


@dataclass(frozen=True)
class Rotor:
    """The rotor that drops (SI). Defaults: source paper Table II.

    Parameters
    ----------
    mass : float
        m_r [kg].
    polar_inertia : float
        J_r about the mass centre [kg m^2].
    eccentricity : float
        Unbalance e [m].
    radius : float or None
        Journal radius r [m]; None: bore/2 - clearance.

    Examples
    --------
    >>> Rotor(mass=-1.0)
    Traceback (most recent call last):
    ...
    auxbearing.errors.InputError: rotor.mass = '-1 kg': must be > 0
    """

    mass: float = 1.48
    polar_inertia: float = 3.88e-4
    eccentricity: float = 1e-5
    radius: float | None = None

    def __post_init__(self) -> None:
        for f in fields(self):
            check(_BY_SECTION["rotor"][f.name], getattr(self, f.name))

    def describe(self) -> dict:
        """Inputs with units in the keys."""
        return _describe(self, "rotor")


def _default(key: str) -> float | None:
    return _BY_SECTION["drop"][key].default


@dataclass(frozen=True)
class DropCase:
    """How the rotor drops and how the contact behaves (SI). Defaults: Table II and NOTES.md.

    See :data:`PARAMETERS` for the unit, rule and source of each field.

    Examples
    --------
    >>> DropCase(sliding_friction=1.5)
    Traceback (most recent call last):
    ...
    auxbearing.errors.InputError: drop.sliding_friction = 1.5: must lie in [0, 1]
    """

    clearance: float = _default("clearance")
    speed: float = _default("speed")
    unbalance_phase: float = _default("unbalance_phase")
    duration: float = _default("duration")
    output_step: float = _default("output_step")
    race_mass: float = _default("race_mass")
    race_inertia: float = _default("race_inertia")
    line_stiffness: float | None = None
    line_damping: float = _default("line_damping")
    ball_damping: float = _default("ball_damping")
    ball_constant: float | None = None
    sliding_friction: float = _default("sliding_friction")
    rolling_friction: float = _default("rolling_friction")
    slip_velocity: float = _default("slip_velocity")
    gravity: float = _default("gravity")
    rtol: float = _default("rtol")
    atol: float = _default("atol")
    max_step: float = _default("max_step")
    start_x: float = 0.0
    start_y: float = 0.0

    def __post_init__(self) -> None:
        for f in fields(self):
            check(_BY_SECTION["drop"][f.name], getattr(self, f.name))
        if self.output_step > self.duration:
            raise InputError.for_field("drop.output_step", self.output_step,
                                       f"must not exceed drop.duration = {self.duration:g} s")
        if self.duration / self.output_step > 2e7:
            raise InputError.for_field("drop.output_step", self.output_step,
                                       "gives more than 2e7 output instants; use a coarser grid")
        if math.hypot(self.start_x, self.start_y) >= self.clearance:
            raise InputError.for_field(
                "drop.start_x, drop.start_y", (self.start_x, self.start_y),
                f"the journal must start inside the clearance circle |(x, y)| < {self.clearance * 1e3:g} mm")

    def describe(self) -> dict:
        """Inputs with units in the keys."""
        return _describe(self, "drop")


def _describe(obj: object, section: str) -> dict:
    out = {}
    for f in fields(obj):
        param = _BY_SECTION[section][f.name]
        unit = SI_UNITS.get(param.dimension, _EXTRA_UNITS.get(param.dimension, ("",))[0])
        suffix = f"_{unit}".replace("**", "^").replace("*", "_").replace("/", "_per_") if unit else ""
        out[f"{f.name}{suffix}"] = getattr(obj, f.name)
    return out


def from_mapping(data: dict | None, section: str, prefix: str | None = None) -> dict:
    """SI keyword arguments for :class:`Rotor` or :class:`DropCase` from a TOML table with units.

    Examples
    --------
    >>> from_mapping({"clearance": "0.3 mm", "sliding_friction": 0.1}, "drop")
    {'clearance': 0.0003, 'sliding_friction': 0.1}
    >>> from_mapping({"clearence": "0.3 mm"}, "drop")
    Traceback (most recent call last):
    ...
    auxbearing.errors.InputError: drop.clearence = '0.3 mm': unknown key; allowed keys: clearance, speed, ...
    """
    table = _BY_SECTION[section]
    prefix = f"{section}." if prefix is None else prefix
    if data is None:
        return {}
    if not isinstance(data, dict):
        raise InputError.for_field(section, data, "must be a table of keys")
    out = {}
    for key, value in data.items():
        if key not in table:
            raise InputError.for_field(prefix + key, value, "unknown key; allowed keys: " + ", ".join(table))
        param = table[key]
        out[key] = convert(prefix + key, value, param.dimension)
        check(param, out[key], prefix + key)
    return out


def read_config(path: str | Path) -> tuple[BearingGeometry | None, dict, dict]:
    """The ``[bearing]``, ``[rotor]`` and ``[drop]`` tables of a TOML file (values with units).

    Returns the bearing (None when the file has no ``[bearing]`` table) and the SI keyword
    arguments of :class:`Rotor` and :class:`DropCase`. Other tables are left to other commands.
    """
    data = read_toml(path)
    bearing = bearing_from_mapping(data["bearing"], name=Path(path).stem) if "bearing" in data else None
    return bearing, from_mapping(data.get("rotor"), "rotor"), from_mapping(data.get("drop"), "drop")
