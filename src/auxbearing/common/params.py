"""Parameter tables: one row per input (key, dimension, default, display unit, rule, help, source).

Model objects, their TOML tables and the command-line options are all generated from such tables, so
a new input is one row. Values arrive as strings with units ("0.2 mm", "6000 rpm"), pint quantities
or plain numbers; a plain number is SI (the message says so) except on the command line, where it is
in the row's display unit.
"""

from __future__ import annotations

import difflib
import functools
import math
import re
from typing import NamedTuple

from auxbearing.common.dimensions import _DISPLAY_SCALE, EXTRA_UNITS, SI_UNITS, with_article
from auxbearing.common.errors import InputError

RULES = ("positive", "nonnegative", "unit_interval", "fraction", "finite", "tolerance", "optional_positive",
         "optional_nonnegative", "count", "optional_count", "temperature_rise", "service_temperature")
#: Where a temperature of a bearing or of its surroundings can lie [K], the ``service_temperature`` rule: from
#: -73 degC, the cold end of the widest-range aircraft greases (MIL-PRF-23827 Type I: -73 to 121 degC), to
#: 350 degC, the highest heat-stabilisation class makers give bearing rings (S4). Beyond either end a value is a
#: slip ("1 K", "20 delta_degC") or a machine this model does not describe: its material data are room-temperature
#: values and its convection is air's at 300 K, far from a bearing immersed in a cryogen or past its tempering.
SERVICE_TEMPERATURE = (200.15, 623.15)
SERVICE_TEMPERATURE_TEXT = "-73 degC to 350 degC (200.15 K to 623.15 K)"
#: A temperature difference's unit (pint's ``delta_degC``, ``Δcelsius``, ...): pint converts "250 delta_degC" to
#: 250 K, which a temperature would then read as -23 degC.
_DIFFERENCE_UNIT = re.compile(r"delta|\u0394", re.IGNORECASE)
#: How close (difflib's ratio) a mistyped key must be to an allowed one to be suggested.
SUGGESTION_CUTOFF = 0.6


def did_you_mean(key: str, allowed) -> str:
    """``"; did you mean mount_damping?"`` for the allowed key closest to a mistyped one, or ``""``.

    >>> did_you_mean("mount_dampng", ["mount_damping", "mount_mass"])
    '; did you mean mount_damping?'
    >>> did_you_mean("colour", ["mass"])
    ''
    """
    close = difflib.get_close_matches(str(key), [str(a) for a in allowed], n=1, cutoff=SUGGESTION_CUTOFF)
    return f"; did you mean {close[0]}?" if close else ""


def unknown(field: str, value: object, key: str, allowed, what: str = "key") -> InputError:
    """The one-line error of an unknown key (or table): the allowed list and the closest allowed name.

    >>> str(unknown("rotor.mas", "2 kg", "mas", ["mass", "speed"]))
    "rotor.mas = '2 kg': unknown key; allowed keys: mass, speed; did you mean mass?"
    """
    allowed = [str(a) for a in allowed]
    return InputError.for_field(field, value, f"unknown {what}; allowed {what}s: " + ", ".join(allowed)
                                + did_you_mean(key, allowed))


class Param(NamedTuple):
    """One input: where it lives, its unit, default, rule and source."""

    section: str  #: TOML table ("rotor", "drop", "touchdown", ...)
    key: str  #: TOML key and dataclass field
    dimension: str  #: key of SI_UNITS or of EXTRA_UNITS
    default: float | None  #: SI default; None means derived or absent (see help)
    display_unit: str  #: unit of plain command-line numbers and help texts
    rule: str  #: one of :data:`RULES`
    help: str
    source: str


def si_unit(dimension: str) -> str:
    """SI unit of a dimension."""
    return SI_UNITS[dimension] if dimension in SI_UNITS else EXTRA_UNITS[dimension][0]


def convert(field: str, value: object, dimension: str, default_unit: str | None = None) -> float:
    """A user value in the SI unit of ``dimension``; a plain number is taken in ``default_unit`` or SI.

    Examples
    --------
    >>> f"{convert('ball_constant', '5.42e5 N/mm**1.5', 'ball_constant'):.4g}"
    '1.714e+10'
    >>> convert("slip_velocity", "10 mm/s", "velocity")
    0.01
    >>> convert("speed", 100.0, "angular_speed")  # a plain number is SI: rad/s
    100.0
    """
    if isinstance(value, (str, int, float)) and not isinstance(value, bool):
        return _convert_plain(field, value, dimension, default_unit)
    return _convert(field, value, dimension, default_unit)


#: pint parses a quantity's text in about half a millisecond; a verification reads its machine file and each
#: candidate's variant some forty times over (255 conversions a read of the blower), and parsing was 85 % of
#: a read's 63 ms. The same text in the same field always gives the same number (or the same error, which
#: is not cached), so conversions of plain values are remembered.
_CONVERSIONS_REMEMBERED = 8192


@functools.lru_cache(maxsize=_CONVERSIONS_REMEMBERED)
def _convert_plain(field: str, value, dimension: str, default_unit: str | None) -> float:
    return _convert(field, value, dimension, default_unit)


def _convert(field: str, value: object, dimension: str, default_unit: str | None) -> float:
    import pint

    from auxbearing.common.units import Quantity, parse_quantity

    if isinstance(value, bool) or not isinstance(value, (int, float, str, pint.Quantity)):
        if not si_unit(dimension):  # a count or a ratio has no unit to name
            raise InputError.for_field(field, value, "must be a plain number")
        raise InputError.for_field(field, value, f"must be a number with a unit such as {_examples(dimension)}")
    unit = si_unit(dimension)
    if isinstance(value, (int, float)):
        quantity = Quantity(float(value), default_unit or unit)
    else:
        quantity = parse_quantity(field, value, dimension, default_unit or unit)
    try:
        magnitude = float(quantity.to(unit).magnitude)
    except pint.DimensionalityError:
        raise InputError.for_field(field, value, f"unit {quantity.units} is not "
                                                 f"{with_article(dimension.replace('_', ' '))} "
                                                 f"(use e.g. {_examples(dimension)})") from None
    except (OverflowError, ValueError, TypeError):
        raise InputError.for_field(field, value, "is not a finite number") from None
    if not math.isfinite(magnitude):
        raise InputError.for_field(field, value, "must be a finite number")
    return magnitude


def _examples(dimension: str) -> str:
    from auxbearing.common.units import _EXAMPLES

    return _EXAMPLES[dimension][0] if dimension in _EXAMPLES else EXTRA_UNITS[dimension][1]


def display_value(param: Param, value: float) -> object:
    """The value in the parameter's display unit, as a user would type it (SI when it has none)."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        return value
    if math.isinf(value):
        return "no limit"  # a guard switched off, as a person says it (not "inf s")
    unit = param.display_unit or si_unit(param.dimension)
    if not unit:
        # a count or a whole ratio reads as an integer (50000000, not 50000000.0)
        return int(value) if float(value).is_integer() and abs(value) < 1e15 else value
    if unit == si_unit(param.dimension):
        return f"{value:.6g} {unit}"
    if _DISPLAY_SCALE.get(unit) is not None:
        return f"{value * _DISPLAY_SCALE[unit]:.6g} {unit}"
    from auxbearing.common.units import Quantity

    return f"{Quantity(value, si_unit(param.dimension)).to(unit).magnitude:.6g} {unit}"


def check(param: Param, value: object, field: str | None = None, typed: object = None) -> None:
    """Apply the row's rule; the InputError names the field, the value and the rule.

    The value is shown as typed (``typed``) when given, else as a person reads it in the row's display unit.
    """
    name = field or f"{param.section}.{param.key}"
    if value is None:
        if param.rule.startswith("optional"):
            return
        raise InputError.for_field(name, value, "is required")
    if isinstance(value, bool) or not isinstance(value, (int, float)) or math.isnan(value):
        raise InputError.for_field(name, value if typed is None else typed,
                                   f"must be a number in {param.display_unit or 'SI units'}")
    shown = display_value(param, value) if typed is None else typed
    if math.isinf(value):
        raise InputError.for_field(name, shown, "must be finite")
    rule = param.rule
    if rule in ("positive", "optional_positive") and value <= 0.0:
        # a temperature is held in kelvin: "> 0" would read as above 0 degC to a person who typed degC
        raise InputError.for_field(name, shown, "must be above absolute zero (0 K, -273.15 degC)"
                                   if param.dimension == "temperature" else "must be > 0")
    if rule in ("nonnegative", "optional_nonnegative") and value < 0.0:
        raise InputError.for_field(name, shown, "must be >= 0")
    if rule == "unit_interval" and not 0.0 <= value <= 1.0:
        raise InputError.for_field(name, shown, "must lie in [0, 1]")
    if rule == "fraction" and not 0.0 < value <= 1.0:
        raise InputError.for_field(name, shown, "must lie in (0, 1]")
    if rule == "tolerance" and not 0.0 < value <= 1e-2:
        raise InputError.for_field(name, shown, "must lie in (0, 0.01]")
    # the ends themselves, typed in degC, land a rounding either side of their kelvin values
    if rule == "service_temperature" and not SERVICE_TEMPERATURE[0] - 1e-9 <= value <= SERVICE_TEMPERATURE[1] + 1e-9:
        raise InputError.for_field(name, shown, "must be above absolute zero (0 K, -273.15 degC)" if value <= 0.0 else
                                   f"must lie within {SERVICE_TEMPERATURE_TEXT}, the service range of bearing "
                                   "greases and heat-stabilised bearing steel")
    if rule == "temperature_rise" and not 0.0 <= value <= 10.0:  # "0.05 degC" reads as 273.2 K: refused here
        raise InputError.for_field(name, shown, "must be a temperature rise in K within [0, 10]")
    if rule in ("count", "optional_count") and (value != int(value) or value < 1):
        raise InputError.for_field(name, shown, "must be a whole number >= 1")


def accept(param: Param, value: object, field: str | None = None) -> float | None:
    """A value given to the Python API (string with unit, quantity or SI number), converted and checked."""
    name = field or f"{param.section}.{param.key}"
    if value is None:
        check(param, None, name)
        return None
    refuse_difference(param, value, name)
    si = value if isinstance(value, (int, float)) and not isinstance(value, bool) else convert(
        name, value, param.dimension)
    si = float(si) if not isinstance(si, bool) else si
    check(param, si, name)
    return si


def read_table(data: object, table: dict[str, Param], prefix: str) -> dict[str, float]:
    """SI values of a TOML table whose values carry units; unknown keys refused with the allowed list.

    Examples
    --------
    >>> rows = {"mass": Param("rotor", "mass", "mass", 1.0, "kg", "positive", "Rotor mass", "-")}
    >>> read_table({"mass": "2 kg"}, rows, "rotor.")
    {'mass': 2.0}
    >>> read_table({"mas": "2 kg"}, rows, "rotor.")
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: rotor.mas = '2 kg': unknown key; allowed keys: mass; did you mean mass?
    """
    if data is None:
        return {}
    if not isinstance(data, dict):
        raise InputError.for_field(prefix.rstrip("."), data, "must be a table of keys")
    out = {}
    for key, value in data.items():
        if key not in table:
            raise unknown(prefix + key, value, key, table)
        param = table[key]
        if param.rule in ("count", "optional_count") and isinstance(value, str) and _bare_number(value) is None:
            # a count has no unit to read ("10 drops" is no dimensionless quantity to pint)
            raise InputError.for_field(prefix + key, value, "must be a plain number, e.g. 10")
        # a number, or a number in quotes ("25"), is no quantity: read as SI it made 25 degC 25 K
        number = value if isinstance(value, (int, float)) and not isinstance(value, bool) else _bare_number(value)
        if number is not None and param.dimension not in ("dimensionless",) and si_unit(param.dimension):
            from auxbearing.common.units import unit_hint

            # the unit that puts the number nearest the default, where there is one (a modulus of 210000 is MPa)
            hint = (unit_hint(float(number), param.dimension, param.default, param.display_unit)
                    if param.default else param.display_unit or si_unit(param.dimension))
            raise InputError.for_field(prefix + key, value, f"needs a unit, e.g. '{str(value).strip()} {hint}'")
        refuse_difference(param, value, prefix + key)
        out[key] = convert(prefix + key, value, param.dimension)
        check(param, out[key], prefix + key, value)
    return out


def refuse_difference(param: Param, value: object, field: str) -> None:
    """Refuse a temperature difference ("20 delta_degC") where a temperature is meant.

    pint reads a difference unit as kelvin, so "250 delta_degC" would pass as -23 degC; a rise
    (``temperature_rise``) is a difference and keeps taking one.

    >>> row = Param("coastdown", "t", "temperature", 293.15, "degC", "service_temperature", "", "")
    >>> refuse_difference(row, "20 delta_degC", "t")
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: t = '20 delta_degC': is a temperature difference; give a temperature, e.g. ...
    >>> refuse_difference(row, "20 degC", "t")
    """
    if param.rule != "service_temperature" or isinstance(value, (bool, int, float)):
        return
    units = value if isinstance(value, str) else str(getattr(value, "units", ""))
    if _DIFFERENCE_UNIT.search(units):
        raise InputError.for_field(field, value if isinstance(value, str) else str(value),
                                   "is a temperature difference; give a temperature, e.g. '20 degC'")


def _bare_number(value: object) -> float | None:
    """The number a text holds with nothing else ("25", " 1e3 "), else None.

    >>> _bare_number("25"), _bare_number("25 degC"), _bare_number(3.0)
    (25.0, None, None)
    """
    if not isinstance(value, str):
        return None
    try:
        return float(value.strip())
    except ValueError:
        return None


def by_key(rows: tuple[Param, ...], section: str) -> dict[str, Param]:
    """The rows of one section, by key."""
    return {p.key: p for p in rows if p.section == section}


_FIELD_VALUE_RULE = re.compile(r"^(?P<field>[^=]+?) = (?P<value>.*?): (?P<rule>.*)$", re.DOTALL)


def as_typed(err: InputError, typed: dict, prefix: str = "") -> InputError:
    """The error of a check made on SI values, told again with the key's prefix and the value as typed.

    Checks run on converted numbers ("-0.006"); a person wrote "-6 mm". The field of the message is
    looked up in ``typed`` (the table as read); an error about another field keeps its value.

    Examples
    --------
    >>> str(as_typed(InputError("ball_diameter = -0.006: must be > 0"), {"ball_diameter": "-6 mm"}, "bearing."))
    "bearing.ball_diameter = '-6 mm': must be > 0"
    """
    text = str(err)
    match = _FIELD_VALUE_RULE.match(text)
    if match is not None:
        key = match["field"].removeprefix(prefix)
        if key in typed:
            return InputError.for_field(prefix + key, typed[key], match["rule"])
    return err if text.startswith(prefix) else InputError(prefix + text)
