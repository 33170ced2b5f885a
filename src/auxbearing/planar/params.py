"""Inputs of the paper's planar drop: rotor and drop-case parameters in one table (SI inside).

Source paper Sec. II.D and Table II, read as docs/paper_notes.md says. Each parameter is a
:class:`~auxbearing.common.params.Param` row of :data:`PARAMETERS`; the dataclasses, their validation,
the TOML ``[rotor]`` / ``[drop]`` sections and the command-line options of ``auxbearing drop`` are
built from that table. The drop itself runs through the machine model
(:func:`auxbearing.planar.rig.run_drop` builds a one-plane :class:`~auxbearing.machine.model.Machine`).

Values the paper does not give, and what we set (see ``source`` of each row): clearance s and
rotor radius r (s = 0.2 mm, r = bore/2 - s), unbalance phase at the drop (0), K_l's contact
length (the bearing width, which reproduces the paper's K_l), the slip-velocity regularisation
of friction, gravity, and the integration tolerances.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, fields
from pathlib import Path

from auxbearing.common.errors import InputError
from auxbearing.common.params import Param, accept, by_key, check, convert, display_value, read_table, si_unit

__all__ = ["PARAMETERS", "DropCase", "Param", "Rotor", "check", "convert", "display_value", "from_mapping",
           "read_config"]

PARAMETERS: tuple[Param, ...] = (
    Param("rotor", "mass", "mass", 1.48, "kg", "positive", "Rotor mass m_r", "Table II"),
    Param("rotor", "polar_inertia", "inertia", 3.88e-4, "kg*m**2", "positive",
          "Polar moment of inertia of the rotor J_r about its mass centre", "Table II"),
    Param("rotor", "eccentricity", "length", 1e-5, "um", "nonnegative",
          "Unbalance eccentricity e of the mass centre", "Table II"),
    Param("rotor", "radius", "length", None, "mm", "optional_positive",
          "Journal radius r; default bore/2 - clearance", "not in the paper (paper_notes item 6)"),
    Param("drop", "clearance", "length", 2e-4, "mm", "positive",
          "Single-side radial clearance s between journal and inner race",
          "not in the paper; 0.2 mm plausible for a 15 mm journal (paper_notes item 6)"),
    Param("drop", "speed", "angular_speed", 6000.0 * math.pi / 30.0, "rpm", "finite",
          "Rotor spin speed at the drop (counter-clockwise positive)", "Sec. II.D (6000 rpm)"),
    Param("drop", "unbalance_phase", "angle", 0.0, "deg", "finite",
          "Angle of the unbalance from +x at the drop", "not in the paper (Sec. III names it a cause)"),
    Param("drop", "duration", "time", 0.15, "s", "positive", "Simulated time", "Sec. II.D"),
    Param("drop", "output_step", "time", 1e-5, "us", "positive", "Uniform output interval", "ours"),
    Param("drop", "race_mass", "mass", 0.0125, "kg", "positive", "Inner race mass m_b", "Table II"),
    Param("drop", "race_inertia", "inertia", 7.03e-7, "kg*m**2", "positive",
          "Inner race polar moment of inertia J_b", "Table II (printed as 'of rotor', paper_notes item 5)"),
    Param("drop", "line_stiffness", "line_stiffness", None, "N/m**(10/9)", "optional_positive",
          "Rotor/race line-contact constant K_l; default Palmgren with the bearing width",
          "Table II 1.468e9; Palmgren l = 11 mm gives 1.463e9"),
    Param("drop", "line_damping", "damping", 1000.0, "N*s/m", "nonnegative",
          "Rotor/race contact damping C_l", "Table II"),
    Param("drop", "ball_damping", "damping", 500.0, "N*s/m", "nonnegative",
          "Ball-set damping C_b on the race velocity", "Table II"),
    Param("drop", "ball_constant", "ball_constant", None, "N/m**1.5", "optional_positive",
          "Override of the ball contact constant K_b; default Hertz (Eq. 15)",
          "Table II's 5.42e5 is plausible only in N/mm^1.5 (paper_notes item 5)"),
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

_BY_SECTION = {s: by_key(PARAMETERS, s) for s in ("rotor", "drop")}


def _accept_all(obj: object, section: str) -> None:
    """Convert every field given as a string with a unit (or a quantity) to SI and check its rule."""
    for f in fields(obj):
        value = accept(_BY_SECTION[section][f.name], getattr(obj, f.name))
        object.__setattr__(obj, f.name, value)


@dataclass(frozen=True)
class Rotor:
    """The rotor that drops. Defaults: source paper Table II.

    Every field takes a string with a unit ("1.48 kg", "10 um") or a number in SI units.

    Parameters
    ----------
    mass : float or str
        m_r [kg].
    polar_inertia : float or str
        J_r about the mass centre [kg m^2].
    eccentricity : float or str
        Unbalance e [m].
    radius : float, str or None
        Journal radius r [m]; None: bore/2 - clearance.

    Examples
    --------
    >>> round(Rotor(eccentricity="10 um").eccentricity * 1e6, 9)
    10.0
    >>> Rotor(mass=-1.0)
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: rotor.mass = '-1 kg': must be > 0
    """

    mass: float = 1.48
    polar_inertia: float = 3.88e-4
    eccentricity: float = 1e-5
    radius: float | None = None

    def __post_init__(self) -> None:
        _accept_all(self, "rotor")

    def describe(self) -> dict:
        """Inputs with units in the keys."""
        return _describe(self, "rotor")


def _default(key: str) -> float | None:
    return _BY_SECTION["drop"][key].default


@dataclass(frozen=True)
class DropCase:
    """How the rotor drops and how the contact behaves. Defaults: Table II and docs/paper_notes.md.

    Every field takes a string with a unit ("0.2 mm", "6000 rpm") or a number in SI units
    (``speed=628.3`` is rad/s). See :data:`PARAMETERS` for the unit, rule and source of each field.

    Examples
    --------
    >>> round(DropCase(speed="6000 rpm").speed, 3)
    628.319
    >>> DropCase(sliding_friction=1.5)
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: drop.sliding_friction = 1.5: must lie in [0, 1]
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
        _accept_all(self, "drop")
        if self.output_step > self.duration:
            raise InputError.for_field("drop.output_step", display_value(_BY_SECTION["drop"]["output_step"],
                                                                         self.output_step),
                                       f"must not exceed drop.duration = {self.duration:g} s")
        if math.hypot(self.start_x, self.start_y) >= self.clearance:
            raise InputError(
                f"drop.start_x, drop.start_y = ({self.start_x * 1e3:g} mm, {self.start_y * 1e3:g} mm): the journal "
                f"must start inside the clearance circle |(x, y)| < {self.clearance * 1e3:g} mm")

    def describe(self) -> dict:
        """Inputs with units in the keys."""
        return _describe(self, "drop")


def _describe(obj: object, section: str) -> dict:
    out = {}
    for f in fields(obj):
        unit = si_unit(_BY_SECTION[section][f.name].dimension)
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
    auxbearing.common.errors.InputError: drop.clearence = '0.3 mm': unknown key; allowed keys: clearance, speed, ...
    """
    return read_table(data, _BY_SECTION[section], f"{section}." if prefix is None else prefix)


def read_config(path: str | Path) -> tuple:
    """The ``[bearing]``, ``[rotor]`` and ``[drop]`` tables of a TOML file (values with units).

    Returns the :class:`~auxbearing.bearings.geometry.BearingGeometry` (None when the file has no ``[bearing]``
    table) and the SI keyword
    arguments of :class:`Rotor` and :class:`DropCase`. Other tables are refused: a drop file
    holds these three only.
    """
    from auxbearing.bearings.geometry import bearing_from_mapping, read_toml

    data = read_toml(path)
    unknown = [k for k in data if k not in ("bearing", "rotor", "drop")]
    if unknown:
        raise InputError.for_field(f"{Path(path).name}: [{unknown[0]}]", "table",
                                   "unknown table; allowed tables: bearing, rotor, drop")
    bearing = bearing_from_mapping(data["bearing"], name=Path(path).stem) if "bearing" in data else None
    return bearing, from_mapping(data.get("rotor"), "rotor"), from_mapping(data.get("drop"), "drop")
