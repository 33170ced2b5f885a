"""Units at the boundary: parse user values with pint, hand SI floats to the kernels.

Kernels never see pint. Every value a person types passes through :func:`to_si`, which names
the field in its error. A plain number is accepted only where the caller says which unit it
means (``default_unit``); TOML values with a dimension must spell their unit ("6 mm").
"""

from __future__ import annotations

import math
import re
from numbers import Real

import pint

from auxbearing.common.dimensions import EXTRA_UNITS as _EXTRA_UNITS
from auxbearing.common.dimensions import SI_UNITS as _SI_UNITS
from auxbearing.common.dimensions import with_article
from auxbearing.common.errors import InputError

ureg = pint.UnitRegistry()
ureg.define("rpm = revolution / minute")
ureg.define("rps = revolution / second")
Quantity = ureg.Quantity

#: SI unit of each physical dimension the package reads (one table, kept in :mod:`auxbearing.common.params`).
SI_UNITS = _SI_UNITS


def to_si(field: str, value: object, dimension: str, default_unit: str | None = None) -> float:
    """Convert a user value to a float in the SI unit of ``dimension``.

    Parameters
    ----------
    field : str
        Name shown in an error message (a TOML key or a command-line option).
    value : str, int, float or pint.Quantity
        ``"6 mm"``, ``"1 kN"``, ``"35 deg"``, a Quantity, or a plain number.
    dimension : str
        A key of :data:`SI_UNITS`.
    default_unit : str, optional
        Unit of a plain number. Without it a plain number is refused for dimensioned fields.

    Returns
    -------
    float
        The value in SI units (m, rad, N, Pa, ...).

    Examples
    --------
    >>> to_si("ball_diameter", "6 mm", "length")
    0.006
    >>> round(to_si("contact_angle", "35 deg", "angle"), 6)
    0.610865
    >>> to_si("ball_load", 1000, "force", default_unit="N")
    1000.0
    >>> round(to_si("ambient_temperature", "20 degC", "temperature"), 2)
    293.15
    >>> to_si("ball_diameter", "6 kg", "length")
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: ball_diameter = '6 kg': unit kilogram is not a length (use e.g. m, mm, um)
    """
    si = SI_UNITS[dimension]
    if isinstance(value, bool):
        raise InputError.for_field(field, value, f"must be {_a(dimension)}")
    if isinstance(value, Real):
        if dimension == "dimensionless":
            quantity = Quantity(float(value), "")
        elif default_unit is not None:
            quantity = Quantity(float(value), default_unit)
        else:
            raise InputError.for_field(field, value, f"needs a unit, e.g. '{value} {unit_hint(value, dimension)}'")
    elif isinstance(value, (pint.Quantity, str)):
        quantity = parse_quantity(field, value, dimension, default_unit)
    else:
        raise InputError.for_field(field, value, f"must be {_a(dimension)}")
    try:
        magnitude = float(quantity.to(si).magnitude)
    except pint.DimensionalityError:
        raise InputError.for_field(
            field,
            value,
            f"unit {quantity.units} is not {_a(dimension)} "
            f"(use e.g. {_examples(dimension)})",
        ) from None
    except (OverflowError, TypeError, ValueError):  # "10**400 N": pint evaluates a huge integer
        raise InputError.for_field(field, value, "is not a finite number") from None
    if math.isnan(magnitude) or math.isinf(magnitude):
        raise InputError.for_field(field, value, "must be a finite number")
    return magnitude


def parse_quantity(field: str, value: object, dimension: str, default_unit: str | None = None) -> pint.Quantity:
    """A string or quantity as a pint Quantity; a frequency given for an angular speed is revolutions.

    pint treats the radian as dimensionless, so "100 Hz" would convert to 100 rad/s; for a speed of
    rotation Hz (and rps) means revolutions per second, which is what a person who types it means.

    Examples
    --------
    >>> round(to_si("speed", "100 Hz", "angular_speed"), 4)  # 100 revolutions per second
    628.3185
    >>> to_si("ball_load", "10**400 N", "force")
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: ball_load = '10**400 N': is not a finite number
    """
    quantity = value if isinstance(value, pint.Quantity) else _parse_string(field, str(value), dimension, default_unit)
    if dimension == "angular_speed" and "hertz" in str(quantity.units):
        quantity = quantity * ureg.Quantity(1.0, "revolution")
    return quantity


#: Text pint would read otherwise than a person meant: a decimal comma or a thousands separator ("1,5" is 15 to
#: pint), numbers side by side ("2 3 s", "1 000 s") or a number after the unit ("13 um 2" is 26 um), which pint
#: multiplies, and a tolerance ("±5 um", read as +5 um). An exponent is written after ^ or ** ("N/m^1.5").
_AMBIGUOUS = re.compile(r",|±|\d\s+[-+]?\d[\d.]*(?:[eE][-+]?\d+)?(?=\s|$|[A-Za-z])"
                        r"|[A-Za-z)\]]\s+[-+]?\.?\d")


def ambiguous(text: str) -> bool:
    """Whether pint would read ``text`` otherwise than a person meant (:data:`_AMBIGUOUS`).

    >>> ambiguous("13 um 2"), ambiguous("2 3 s"), ambiguous("1,5 s"), ambiguous("1e5 N/m^1.5")
    (True, True, True, False)
    """
    return bool(_AMBIGUOUS.search(text))


def _parse_string(field: str, text: str, dimension: str, default_unit: str | None) -> pint.Quantity:
    if ambiguous(text):
        raise InputError.for_field(field, text, "one number with a decimal point and its unit, such as "
                                                f"'{_example_value(dimension)}' (no commas, no spaces inside it)")
    try:
        parsed = ureg.Quantity(text.strip())
    except pint.OffsetUnitCalculusError:
        # "20 degC" is read by pint as 20 * degC, which it refuses for offset scales
        parsed = _offset_quantity(field, text, dimension)
    except Exception:  # pint raises several unrelated types for malformed text
        raise InputError.for_field(
            field, text, f"cannot read it as {_a(dimension)} such as "
            f"'{_example_value(dimension)}'"
        ) from None
    try:
        if not isinstance(parsed, pint.Quantity):  # pint returns a bare number for "5"
            parsed = Quantity(float(parsed), "")
        parsed = Quantity(float(parsed.magnitude), parsed.units)  # a huge integer overflows here, not later
    except (OverflowError, TypeError, ValueError):
        raise InputError.for_field(field, text, "is not a finite number") from None
    if parsed.dimensionless and dimension != "dimensionless" and str(parsed.units) == "dimensionless":
        if default_unit is None:
            raise InputError.for_field(
                field, text, f"needs a unit, e.g. '{text.strip()} {unit_hint(float(parsed.magnitude), dimension)}'"
            )
        parsed = Quantity(float(parsed.magnitude), default_unit)
    return parsed


_NUMBER_AND_UNIT = re.compile(r"^\s*([-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?)\s*(.+?)\s*$")


def _offset_quantity(field: str, text: str, dimension: str) -> pint.Quantity:
    """A number followed by one offset unit ("20 degC"), built without pint's multiplication."""
    match = _NUMBER_AND_UNIT.match(text)
    try:
        return Quantity(float(match.group(1)), match.group(2))
    except Exception:  # no match, or a unit pint does not know
        raise InputError.for_field(
            field, text, f"cannot read it as {_a(dimension)} such as '{_example_value(dimension)}'"
        ) from None


_EXAMPLES = {
    "length": ("m, mm, um", "mm", "6 mm"),
    "angle": ("deg, rad", "deg", "35 deg"),
    "force": ("N, kN", "N", "1000 N"),
    "pressure": ("Pa, MPa, GPa", "GPa", "207 GPa"),
    "moment": ("N*m, N*mm", "N*m", "2 N*m"),
    "mass": ("kg, g", "kg", "1.48 kg"),
    "inertia": ("kg*m**2", "kg*m**2", "3.88e-4 kg*m**2"),
    "time": ("s, ms", "s", "0.15 s"),
    "angular_speed": ("rpm, rad/s", "rpm", "6000 rpm"),
    "damping": ("N*s/m", "N*s/m", "1000 N*s/m"),
    "density": ("kg/m^3, g/cm^3", "kg/m^3", "7810 kg/m^3"),
    "specific_heat": ("J/(kg*K), J/(g*K)", "J/(kg*K)", "475 J/(kg*K)"),
    "thermal_conductivity": ("W/(m*K)", "W/(m*K)", "46.6 W/(m*K)"),
    "thermal_expansion": ("1/K, um/(m*K)", "1/K", "11.9e-6 1/K"),
    "temperature": ("K, degC, degF", "degC", "20 degC"),
    "power": ("W, kW", "W", "150 W"),
    "thermal_conductance": ("W/K", "W/K", "0.5 W/K"),
    "heat_transfer_coefficient": ("W/(m^2*K)", "W/(m^2*K)", "10 W/(m^2*K)"),
    "dynamic_viscosity": ("Pa*s, mPa*s", "mPa*s", "20 mPa*s"),
    "kinematic_viscosity": ("mm^2/s, cSt", "mm^2/s", "32 mm^2/s"),
    "dimensionless": ("a plain number", "", "0.52"),
}


def _describe(dimension: str) -> str:
    return "plain number" if dimension == "dimensionless" else dimension.replace("_", " ")


def _a(dimension: str) -> str:
    """The dimension with its article ("an angle", "a length")."""
    return with_article(_describe(dimension))


def _entry(dimension: str) -> tuple[str, str, str]:
    """(examples, unit of a plain number, example value); the dynamics' extra dimensions have them too."""
    if dimension in _EXAMPLES:
        return _EXAMPLES[dimension]
    si, examples = _EXTRA_UNITS[dimension]
    return examples, si, f"1 {si}"


def _examples(dimension: str) -> str:
    return _entry(dimension)[0]


def _example_unit(dimension: str) -> str:
    return _entry(dimension)[1]


def _example_value(dimension: str) -> str:
    return _entry(dimension)[2]


def unit_hint(number: float, dimension: str, typical: float | None = None, also: str | None = None) -> str:
    """The unit a bare ``number`` most likely meant, for the hint of a refusal.

    Of the dimension's usual units, the one that puts the number nearest (by ratio) to a typical value.
    ``typical``: that value in SI (a parameter's default); without it, the dimension's example value ("207 GPa"
    for a pressure). ``also``: one more unit to consider (a parameter's display unit). Offset scales
    (temperatures) and numbers that are not positive take the dimension's plain unit: no ratio to compare.

    Examples
    --------
    >>> unit_hint(310000, "pressure"), unit_hint(310, "pressure")   # a modulus written in MPa, in GPa
    ('MPa', 'GPa')
    >>> unit_hint(0.2, "length", typical=0.2e-3), unit_hint(200, "length", typical=0.2e-3)
    ('mm', 'um')
    """
    plain = _example_unit(dimension)
    if dimension == "temperature" or not (math.isfinite(number) and number > 0.0):
        return plain
    si = _SI_UNITS[dimension] if dimension in _SI_UNITS else _EXTRA_UNITS[dimension][0]
    if typical is None or not (math.isfinite(typical) and typical > 0.0):
        example = _example_value(dimension)
        typical = float(parse_quantity("example", example, dimension).to(si).magnitude)
    units = [u.strip() for u in _examples(dimension).split(",")] + ([also] if also else [])
    best, off = plain, math.inf
    for unit in dict.fromkeys(u for u in units if u):
        try:
            value = float(Quantity(number, unit).to(si).magnitude)
        except Exception:  # a unit text pint does not read as such ("a plain number")
            continue
        distance = abs(math.log10(value / typical)) if value > 0.0 else math.inf
        if distance < off - 1e-12:
            best, off = unit, distance
    return best
