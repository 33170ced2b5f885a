"""CSV tables whose header carries the units: ``time [s], x [um], y [um]``.

One reader for every table a user hands in (a measured drop, a list of load cases), so the
rules and the error messages are the same everywhere: each column of interest names its unit
in brackets (or the caller passes it as an option), values become SI floats through
:func:`auxbearing.common.units.to_si`, and every problem is an :class:`InputError` of one line naming
the file, the column and the file line.
"""

from __future__ import annotations

import io
import math
import re
from pathlib import Path
from typing import NamedTuple

import numpy as np

from auxbearing.common.errors import InputError
from auxbearing.common.units import to_si

_HEADER = re.compile(r"^\s*([A-Za-z_][\w\-]*)\s*(?:\[([^\]]*)\])?\s*$")
_WHITESPACE_HEADER_FIELD = re.compile(r"[^\s\[\]]+(?:\s*\[[^\]]*\])?")
_MISSING = ("", "nan", "na", "null", "none")
#: Largest magnitude of a value in SI. A double holds up to 1.8e308, but the arithmetic after reading squares
#: values (hypotenuses, energies, Hertz's cube roots of squares): 1e150 keeps such a square finite, and no
#: force, length, time or speed a person measures comes near it.
MAX_MAGNITUDE = 1e150


class Column(NamedTuple):
    """A column the caller reads: its dimension (a key of :data:`auxbearing.common.units.SI_UNITS`)."""

    dimension: str
    required: bool
    example_unit: str  #: shown in the error for a column without a unit


class UnitTable(NamedTuple):
    """What :func:`read_unit_csv` found."""

    data: dict[str, np.ndarray]  #: column name -> values in SI
    lines: list[int]  #: file line of each row
    header: list[str]  #: the header fields as written
    header_line: int
    meta: dict[str, str]  #: ``# key = value`` comment lines


def unit_scale(column: str, unit: str, dimension: str) -> float:
    """SI value of one ``unit`` of ``column``; the error names the column.

    >>> unit_scale("x", "um", "length")
    1e-06
    """
    return to_si(f"column {column!r} unit", f"1 {unit}", dimension)


def read_unit_csv(path: str | Path, columns: dict[str, Column], *, file_field: str = "file",
                  aliases: dict[str, str] | None = None, units: dict[str, str] | None = None,
                  delimiter: str | None = None, unknown: str = "ignore", max_rows: int | None = None,
                  budget_name: str = "max_rows") -> UnitTable:
    """Read a CSV whose header names each column with its unit.

    Parameters
    ----------
    path : path
        The file, in UTF-8 or an encoding :func:`auxbearing.common.io.read_text` can tell (with a warning).
        Blank lines are skipped; lines starting with ``#`` are comments, and ``# key = value``
        comments are returned as metadata.
    columns : dict
        Column name (lower case) -> :class:`Column`.
    file_field : str
        How the error for a missing file names it ("measured file").
    aliases : dict, optional
        Other names of a column (lower case), e.g. ``{"t": "time"}``.
    units : dict, optional
        Unit of a column whose header has none; a header unit must agree with it.
    delimiter : str, optional
        Field separator; default a comma if the header has one, else a semicolon, else whitespace.
    unknown : {"ignore", "error"}
        What a header column that is not in ``columns`` does.
    max_rows : int, optional
        Budget of data rows; a longer file is refused (naming ``budget_name``) before any value is converted.

    Raises
    ------
    InputError
        Missing file or header, a column twice, an unknown column (with ``unknown="error"``),
        a missing or wrong unit, a missing or non-numeric value, a row with the wrong field count,
        more rows than ``max_rows``.
    """
    from auxbearing.common.io import read_text

    path = Path(path)
    text_of_file = read_text(path, file_field)
    aliases = aliases or {}

    def canonical(name: str) -> str | None:
        key = name.strip().lower()
        key = aliases.get(key, key)
        return key if key in columns else None

    units = {(canonical(k) or k): v for k, v in (units or {}).items()}
    meta: dict[str, str] = {}
    header: list[str] | None = None
    header_line = 0
    rows: list[list[str]] = []
    lines: list[int] = []
    with io.StringIO(text_of_file, newline=None) as handle:
        for number, line in enumerate(handle, start=1):
            text = line.strip()
            if not text:
                continue
            if text.startswith("#"):
                key, sep, value = text.lstrip("#").partition("=")
                if sep and key.strip():
                    meta[key.strip()] = value.strip()
                continue
            if header is None:
                if delimiter is None:
                    delimiter = "," if "," in text else (";" if ";" in text else None)
                # Whitespace-separated headers keep "name [unit]" together, even with a space before "[".
                header = ([h.strip() for h in text.split(delimiter)] if delimiter
                          else _WHITESPACE_HEADER_FIELD.findall(text))
                header_line = number
                continue
            fields = [f.strip() for f in (text.split(delimiter) if delimiter else text.split())]
            if len(fields) != len(header):
                raise InputError(f"{path.name}: line {number}: {len(fields)} fields, the header (line "
                                 f"{header_line}) has {len(header)}")
            rows.append(fields)
            lines.append(number)
            if max_rows is not None and len(rows) > max_rows:
                raise InputError(f"{file_field} = '{path}': more than {max_rows} rows (line {number}): beyond the "
                                 f"budget {budget_name} {max_rows}; split the file or raise {budget_name}")
    if header is None:
        example = ", ".join(f"{n} [{c.example_unit}]" for n, c in columns.items() if c.required) or \
            ", ".join(f"{n} [{c.example_unit}]" for n, c in columns.items())
        raise InputError.for_field(file_field, str(path), f"has no header line such as '{example}'")
    found: dict[str, tuple[int, float]] = {}
    for index, label in enumerate(header):
        match = _HEADER.match(label)
        name = match.group(1) if match else label
        key = canonical(name)
        if key is None:
            if unknown == "error":
                raise InputError(f"{path.name}: column {label!r} (line {header_line}): unknown; allowed: "
                                 + ", ".join([*columns, *aliases]))
            continue
        if key in found:
            raise InputError(f"{path.name}: column {label!r}: channel {key!r} appears twice in the header")
        dimension = columns[key].dimension
        unit = (match.group(2) or "").strip() if match else ""
        option = units.get(key)
        if option and unit and unit_scale(label, unit, dimension) != unit_scale(label, option, dimension):
            raise InputError(f"{path.name}: column {label!r}: header unit {unit!r} contradicts the option {option!r}")
        unit = unit or option or ""
        if not unit:
            raise InputError(f"{path.name}: column {label!r} (line {header_line}) has no unit: write e.g. "
                             f"'{name} [{columns[key].example_unit}]' or give it as an option")
        try:
            found[key] = (index, unit_scale(label, unit, dimension))
        except InputError as err:
            raise InputError(f"{path.name}: {err}") from None
    for key, column in columns.items():
        if column.required and key not in found:
            raise InputError(f"{path.name}: no {key!r} column in the header (line {header_line}); "
                             f"found {', '.join(header)}")
    data = {}
    for key, (index, scale) in found.items():
        values = np.empty(len(rows))
        for k, row in enumerate(rows):
            text = row[index]
            if text.lower() in _MISSING:
                raise InputError(f"{path.name}: column {header[index]!r}, line {lines[k]}: missing value")
            try:
                values[k] = float(text)
            except ValueError:
                raise InputError(f"{path.name}: column {header[index]!r}, line {lines[k]}: "
                                 f"{text!r} is not a number") from None
            if not math.isfinite(values[k]):
                raise InputError(f"{path.name}: column {header[index]!r}, line {lines[k]}: {text!r} is not finite")
        with np.errstate(over="ignore"):
            data[key] = values * scale
        beyond = np.nonzero(~(np.abs(data[key]) <= MAX_MAGNITUDE))[0]
        if beyond.size:
            k = int(beyond[0])
            raise InputError(f"{path.name}: column {header[index]!r}, line {lines[k]}: {rows[k][index]!r} is beyond "
                             f"any value auxbearing computes with (at most {MAX_MAGNITUDE:g} in SI units)")
    return UnitTable(data, lines, header, header_line, meta)
