"""Dimensions and their SI units, as plain text: what help texts and parameter tables need without pint.

The unit library is imported only where a value is converted (:mod:`auxbearing.common.units`); the
tables here let ``--help`` and the parameter tables (:mod:`auxbearing.common.params`) name units without it.
"""

from __future__ import annotations

import math

#: SI unit of each dimension (the unit library is imported only when a value is converted, so that
#: ``--help`` texts built from these tables need none).
SI_UNITS: dict[str, str] = {
    "length": "m", "angle": "rad", "force": "N", "pressure": "Pa", "moment": "N*m", "mass": "kg",
    "inertia": "kg*m**2", "time": "s", "angular_speed": "rad/s", "damping": "N*s/m", "density": "kg/m**3",
    "specific_heat": "J/(kg*K)", "thermal_conductivity": "W/(m*K)", "thermal_expansion": "1/K", "temperature": "K",
    "power": "W", "thermal_conductance": "W/K", "heat_transfer_coefficient": "W/(m**2*K)",
    "dynamic_viscosity": "Pa*s", "kinematic_viscosity": "m**2/s", "dimensionless": "",
}
#: Display units of the tables as multiples of SI (exact), for help texts without the unit library.
_DISPLAY_SCALE = {"mm": 1e3, "um": 1e6, "us": 1e6, "ms": 1e3, "deg": 180.0 / math.pi, "rpm": 30.0 / math.pi,
                  "mrad": 1e3, "MPa": 1e-6, "mm/s": 1e3, "kN": 1e-3, "GPa": 1e-9, "degC": None}

#: Units beyond :data:`SI_UNITS` that the dynamics need: (SI unit, examples).
EXTRA_UNITS = {
    "line_stiffness": ("N/m**(10/9)", "N/m**(10/9)"),
    "ball_constant": ("N/m**1.5", "N/m**1.5, N/mm**1.5"),
    "velocity": ("m/s", "m/s, mm/s"),
    "acceleration": ("m/s**2", "m/s**2"),
    "area": ("m**2", "mm**2, cm**2, m**2"),
    "voltage": ("V", "V"),
    "inductance": ("H", "H, mH"),
    "stiffness": ("N/m", "N/m, N/mm"),
    "torque_per_speed": ("N*m*s", "N*m*s, N*m/rpm"),
    "torque_per_speed2": ("N*m*s**2", "N*m*s**2, N*m/rpm**2"),
    "frequency": ("Hz", "Hz, kHz"),
    "unbalance": ("kg*m", "g*mm, kg*m"),
    "current": ("A", "A, mA"),
    "current_stiffness": ("N/A", "N/A"),
    "current_per_length": ("A/m", "A/m, A/mm"),
    "current_per_length_time": ("A/(m*s)", "A/(m*s), A/(mm*s)"),
    "current_time_per_length": ("A*s/m", "A*s/m, A*ms/mm"),
}

def with_article(noun: str) -> str:
    """The noun with its indefinite article ("an angular speed", "a length").

    >>> with_article("angular speed"), with_article("length")
    ('an angular speed', 'a length')
    """
    return ("an " if noun[:1].lower() in "aeiou" else "a ") + noun
