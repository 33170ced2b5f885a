"""Stations beside the touchdown planes, one module per kind, found from the kernel's registry.

Each kind of :data:`auxbearing.core.machine.STATION_KINDS` has its module here under the kernel kind's
``NAME``, which is also its machine-file table (``[[linear_support]]``): its parameter rows (``PARAMS``), its
description (a frozen dataclass), ``read`` (the tables to descriptions), ``pack`` (descriptions to the kernel's
``Params``), ``series`` (its time series on a run's grid) and ``describe``. The machine, the file's checks,
the packing and the drop's outputs loop over :func:`kinds`; a new kind touches its kernel module, the
registry line in ``core/machine.py`` and its module here.
"""

from __future__ import annotations

import importlib

from auxbearing.core.machine import STATION_KINDS

#: The machine-file tables of the station kinds, in the registry's order.
TABLES = tuple(kind.NAME for kind in STATION_KINDS)


def kinds() -> tuple:
    """Each station kind's module here, in the registry's order."""
    return tuple(importlib.import_module(f"{__name__}.{name}") for name in TABLES)


def of_kind(stations, name: str) -> tuple:
    """The stations of one kind, in the order the file gave them."""
    return tuple(s for s in stations if s.KIND == name)


def each_table(tables, kind: str, default_name: str):
    """Each ``[[kind]]`` table as (where, name, a copy of its other keys): the list checked, one line an error.

    ``where`` is the key prefix of the table (``"amb.0."``); a table without ``name`` is called ``default_name``
    with its index.
    """
    from auxbearing.common.errors import InputError

    if tables is None:
        return
    if not isinstance(tables, list) or not all(isinstance(t, dict) for t in tables):
        raise InputError.for_field(kind, tables, f"give one [[{kind}]] table per station")
    for i, given in enumerate(tables):
        where = f"{kind}.{i}."
        given = dict(given)
        name = given.pop("name", f"{default_name} {i}")
        if not isinstance(name, str):
            raise InputError.for_field(where + "name", name, "must be text")
        yield where, name, given


def read_tables(tables, kind: str, table: dict, required: tuple[str, ...], default_name: str):
    """Each ``[[kind]]`` table as (where, name, SI values, its keys as given), every key checked (:func:`each_table`).

    ``required`` keys must be given.
    """
    from auxbearing.common.errors import InputError
    from auxbearing.common.params import read_table

    out = []
    for where, name, given in each_table(tables, kind, default_name):
        values = read_table(given, table, where)
        for key in required:
            if key not in values:
                raise InputError(f"{where}{key}: missing; every [[{kind}]] needs {', '.join(required)}")
        out.append((where, name, values, given))
    return out
