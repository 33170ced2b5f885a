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
