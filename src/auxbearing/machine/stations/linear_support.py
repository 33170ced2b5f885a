"""``[[linear_support]]``: a station with a linear 2x2 stiffness and damping.

Its kernel is :mod:`auxbearing.core.linear_support`. A seal, a squeeze-film damper or a bearing linearised
at its operating point, or an FE rotor model's own bearings kept beside its touchdown planes. The
coefficients are named as rotordynamic codes write them (k_xy: the force along x per displacement along y).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from auxbearing.common.params import Param, by_key
from auxbearing.core import linear_support as kernel
from auxbearing.machine.params import AXIAL_POSITION

KIND = kernel.NAME
_COEFFICIENTS = {"kxx": "direct stiffness along x", "kxy": "cross-coupled stiffness: force along x per "
                 "displacement along y", "kyx": "cross-coupled stiffness: force along y per displacement along x",
                 "kyy": "direct stiffness along y"}
_DAMPINGS = {"cxx": "direct damping along x", "cxy": "cross-coupled damping (x force per y velocity)",
             "cyx": "cross-coupled damping (y force per x velocity)", "cyy": "direct damping along y"}
PARAMS: tuple[Param, ...] = (
    Param(KIND, "position", "length", None, "mm", "finite", "Axial position of the station, " + AXIAL_POSITION,
          "required"),
    *(Param(KIND, key, "stiffness", 0.0, "N/m", "finite", text.capitalize(), "the machine's data")
      for key, text in _COEFFICIENTS.items()),
    *(Param(KIND, key, "damping", 0.0, "N*s/m", "nonnegative" if key in ("cxx", "cyy") else "finite",
            text.capitalize(), "the machine's data") for key, text in _DAMPINGS.items()),
)
TABLE = by_key(PARAMS, KIND)


@dataclass(frozen=True)
class LinearSupport:
    """A linear support (SI): F = -K u - C u' at its axial position."""

    name: str
    position: float
    kxx: float = 0.0
    kxy: float = 0.0
    kyx: float = 0.0
    kyy: float = 0.0
    cxx: float = 0.0
    cxy: float = 0.0
    cyx: float = 0.0
    cyy: float = 0.0
    KIND = KIND

    def row(self) -> tuple[float, ...]:
        """The kernel's row (:data:`auxbearing.core.linear_support.FIELDS`)."""
        return tuple(float(getattr(self, field)) for field in kernel.FIELDS)


def read(tables) -> tuple[LinearSupport, ...]:
    """The ``[[linear_support]]`` tables of a machine file (values with units)."""
    from auxbearing.machine.stations import read_tables

    return tuple(LinearSupport(name=name, **values)
                 for _, name, values, _ in read_tables(tables, KIND, TABLE, ("position",), "support"))


def pack(supports, modal, n_modes: int, machine=None) -> kernel.Params:
    """The kernel's parameters of the supports, with each elastic mode's shape at them (``modal``: None if rigid)."""
    values = np.array([s.row() for s in supports], float).reshape(len(supports), len(kernel.FIELDS))
    shape_x, shape_y = np.zeros((len(supports), n_modes)), np.zeros((len(supports), n_modes))
    if n_modes:
        for i, s in enumerate(supports):
            shape_x[i], shape_y[i] = modal.station_shapes(s.position, f"{KIND}.{i}.position")
    return kernel.Params(values, shape_x, shape_y)


def series(supports, journal, states=None, params=None, t=None, rotor_z=None) -> dict:
    """Each support's force on the rotor over a run, from the rotor axis there.

    ``journal(i, position)`` gives the axis' displacement and velocity arrays x, y, vx, vy on the run's grid at
    the i-th station of the kind.
    """
    if not supports:
        return {}
    fx, fy = [], []
    for i, s in enumerate(supports):
        x, y, vx, vy = journal(i, s.position)
        fx.append(-(s.kxx * x + s.kxy * y + s.cxx * vx + s.cxy * vy))
        fy.append(-(s.kyx * x + s.kyy * y + s.cyx * vx + s.cyy * vy))
    names = [s.name for s in supports]
    return {"support_force_x": (("time", "support"), np.stack(fx, axis=1), {"units": "N",
                                "long_name": "Linear support's force on the rotor, x"}),
            "support_force_y": (("time", "support"), np.stack(fy, axis=1), {"units": "N",
                                "long_name": "Linear support's force on the rotor, y"}),
            "support": ("support", names, {})}


def describe(s: LinearSupport) -> dict:
    """Inputs with units in the keys, for files and reports."""
    return {"kind": KIND, "name": s.name, "position_m": s.position,
            **{f"{k}_N_per_m": getattr(s, k) for k in _COEFFICIENTS},
            **{f"{k}_N_s_per_m": getattr(s, k) for k in _DAMPINGS}}
