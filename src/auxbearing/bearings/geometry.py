"""Ball bearing geometry: the types, their validation, derived quantities, catalogue and TOML.

Kernels take SI floats; this module is where a person's values become a validated,
immutable :class:`BearingGeometry`. Geometry follows Harris & Kotzalas, *Rolling Bearing
Analysis*, 5th ed. (2007), Essential Concepts, Ch. 2 ("ball bearing macrogeometry").
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from pathlib import Path

from auxbearing.bearings.materials import Material, check_positive, get_material, material_from_mapping
from auxbearing.catalog import bearing_names as bearing_names  # re-exported: the CLI and tests use it here
from auxbearing.common.errors import InputError
from auxbearing.common.params import as_typed
from auxbearing.common.units import to_si

#: Bearing types and the contact pairs a ball makes with the raceways. ``axial_signs`` is the
#: side of the raceway groove each pair's curvature centre lies on (+1 / -1), 0 for a
#: single-arc deep groove whose centres sit in the ring's mid-plane.
BEARING_TYPES: dict[str, dict] = {
    "four_point": {"axial_signs": (1.0, -1.0), "label": "four-point contact"},
    "angular_contact": {"axial_signs": (1.0,), "label": "angular contact"},
    "deep_groove": {"axial_signs": (0.0,), "label": "deep groove"},
}


#: Loosest groove radius over ball diameter taken [-]: ball bearings' grooves lie within about 0.505-0.57 (Harris &
#: Kotzalas 2007, Vol. 1, Ch. 2), and the source paper sweeps its Fig. 3 to 0.6.
MAX_GROOVE_RATIO = 0.6


@dataclass(frozen=True)
class BearingGeometry:
    """Internal geometry and materials of a ball bearing (all SI).

    Parameters
    ----------
    type : str
        ``four_point``, ``angular_contact`` or ``deep_groove``.
    ball_diameter : float
        D [m].
    pitch_diameter : float
        dm [m].
    ball_count : int
        Z [-], at least 3.
    inner_groove_ratio, outer_groove_ratio : float
        fi = ri/D, fo = ro/D [-], each > 0.5.
    contact_angle : float
        Free (nominal) contact angle alpha0 [rad] of the curvature-centre line, in [0, pi/2).
        Zero for a deep-groove bearing, whose working angle comes from clearance and load.
    diametral_clearance : float
        Pd [m], >= 0. Zero reproduces the source paper.
    ball_material, ring_material : Material
    name : str
    bore, outside_diameter, width : float or None
        Envelope [m]; optional.
    source : str
    rating_factor : float
        A maker's adjustment of ISO 281's b_m, multiplying the computed C [-]; 1 for the plain
        standard (see :mod:`auxbearing.bearings.series` for SKF's).

    Examples
    --------
    >>> from auxbearing import get_bearing
    >>> b = get_bearing("QJ202")
    >>> round(b.gamma, 5), round(b.curvature_centre_distance * 1e3, 4)
    (0.19274, 0.24)
    """

    type: str
    ball_diameter: float
    pitch_diameter: float
    ball_count: int
    inner_groove_ratio: float
    outer_groove_ratio: float
    contact_angle: float
    diametral_clearance: float
    ball_material: Material
    ring_material: Material
    name: str = "custom"
    bore: float | None = None
    outside_diameter: float | None = None
    width: float | None = None
    source: str = "user input"
    rating_factor: float = 1.0

    def __post_init__(self) -> None:
        if not isinstance(self.type, str) or self.type not in BEARING_TYPES:
            raise InputError.for_field("type", self.type, "must be one of " + ", ".join(BEARING_TYPES))
        check_positive("ball_diameter", self.ball_diameter)
        check_positive("pitch_diameter", self.pitch_diameter)
        z = self.ball_count
        if isinstance(z, bool) or not isinstance(z, int) or z < 3:
            raise InputError.for_field("ball_count", z, "must be a whole number >= 3")
        for key in ("inner_groove_ratio", "outer_groove_ratio"):
            ratio = getattr(self, key)
            check_positive(key, ratio)
            if ratio <= 0.5:
                raise InputError.for_field(
                    key, ratio, "must be > 0.5 (groove radius larger than ball radius)"
                )
            if ratio > MAX_GROOVE_RATIO:  # '52' for 0.52: a flat race, whose stresses would be printed as results
                raise InputError.for_field(
                    key, ratio, f"must be at most {MAX_GROOVE_RATIO:g} (groove radius over ball diameter, e.g. 0.52; "
                    "ball bearings' grooves lie within about 0.505-0.57)"
                )
        if self.pitch_diameter <= self.ball_diameter:
            raise InputError.for_field(
                "pitch_diameter", self.pitch_diameter,
                f"must exceed ball_diameter = {self.ball_diameter:g} m",
            )
        chord = self.pitch_diameter * math.sin(math.pi / z)
        if chord <= self.ball_diameter:
            raise InputError.for_field(
                "ball_count", z,
                f"balls overlap on the pitch circle: pitch_diameter*sin(pi/Z) = {chord * 1e3:.4g} mm "
                f"must exceed ball_diameter = {self.ball_diameter * 1e3:.4g} mm "
                f"(at most {max_ball_count(self.ball_diameter, self.pitch_diameter)} balls fit)",
            )
        angle = self.contact_angle
        if not isinstance(angle, (int, float)) or math.isnan(angle) or not 0.0 <= angle < math.pi / 2:
            raise InputError.for_field(
                "contact_angle", _deg(angle), "must lie in [0, 90) deg"
            )
        if self.type == "four_point" and angle == 0.0:
            raise InputError.for_field(
                "contact_angle", _deg(angle),
                "a four_point bearing's two contacts per ring coincide at 0 deg (each would carry half the load the "
                "one real contact carries): give its angle above 0 deg, or type deep_groove",
            )
        if self.type == "deep_groove" and angle != 0.0:
            raise InputError.for_field(
                "contact_angle", _deg(angle),
                "a deep_groove bearing has contact_angle 0 deg; its working angle follows from "
                "diametral_clearance and load (use angular_contact for a built-in angle)",
            )
        pd = self.diametral_clearance
        if not isinstance(pd, (int, float)) or math.isnan(pd) or pd < 0.0 or math.isinf(pd):
            raise InputError.for_field("diametral_clearance", pd, "must be >= 0 m and finite")
        if pd >= 2.0 * self.curvature_centre_distance * math.cos(angle):
            raise InputError.for_field(
                "diametral_clearance", pd,
                f"must be below 2 A cos(alpha) = {2e3 * self.curvature_centre_distance * math.cos(angle):.4g} mm "
                "or the ball is loose in every direction",
            )
        for key in ("bore", "outside_diameter", "width"):
            value = getattr(self, key)
            if value is not None:
                check_positive(key, value)
        check_positive("rating_factor", self.rating_factor)
        if self.bore is not None and self.bore >= self.inner_raceway_diameter:
            raise InputError.for_field(
                "bore", self.bore,
                f"must be below the inner raceway diameter {self.inner_raceway_diameter * 1e3:.4g} mm",
            )
        if self.outside_diameter is not None and self.outside_diameter <= self.outer_raceway_diameter:
            raise InputError.for_field(
                "outside_diameter", self.outside_diameter,
                f"must exceed the outer raceway diameter {self.outer_raceway_diameter * 1e3:.4g} mm",
            )

    # -- derived quantities (Harris & Kotzalas 2007, Essential Concepts, Ch. 2) -------------
    @property
    def axial_signs(self) -> tuple[float, ...]:
        """Groove side of each contact pair's curvature centre (see :data:`BEARING_TYPES`)."""
        return BEARING_TYPES[self.type]["axial_signs"]

    @property
    def contact_compliance(self) -> float:
        """Compliance sum eta = (1 - nu_ball^2)/E_ball + (1 - nu_ring^2)/E_ring [1/Pa] (source paper Eq. 3)."""
        return self.ball_material.compliance + self.ring_material.compliance

    @property
    def pairs_per_ball(self) -> int:
        """Contact pairs a ball can form: 2 for four-point, 1 otherwise."""
        return len(self.axial_signs)

    @property
    def gamma(self) -> float:
        """Gamma = D cos(alpha0) / dm [-] (Harris Eq. 2.27)."""
        return self.ball_diameter * math.cos(self.contact_angle) / self.pitch_diameter

    @property
    def curvature_centre_distance(self) -> float:
        """A = (fi + fo - 1) D [m], distance of the groove curvature centres (Eq. 9, source paper)."""
        return (self.inner_groove_ratio + self.outer_groove_ratio - 1.0) * self.ball_diameter

    @property
    def inner_curvature_centre_radius(self) -> float:
        """Radius of the locus of the inner groove curvature centres r_ic [m].

        r_ic = dm/2 + (fi - 0.5) D cos(alpha0) (Harris Eq. 3.xx, the moment arm of Eq. 14).
        """
        return 0.5 * self.pitch_diameter + (self.inner_groove_ratio - 0.5) * self.ball_diameter * math.cos(
            self.contact_angle
        )

    @property
    def inner_raceway_diameter(self) -> float:
        """Groove bottom diameter of the inner ring, di = dm - D [m]."""
        return self.pitch_diameter - self.ball_diameter

    @property
    def outer_raceway_diameter(self) -> float:
        """Groove bottom diameter of the outer ring, do = dm + D [m]."""
        return self.pitch_diameter + self.ball_diameter

    @property
    def free_contact_angle(self) -> float:
        """Contact angle [rad] when the ball just touches both races, Harris Eq. 2.11 for clearance.

        For four-point and angular-contact bearings this is the nominal angle with Pd = 0;
        with clearance it is arccos((A cos(alpha0) - Pd/2)/A) measured on the centre line
        after the ring has moved axially until the pair closes.
        """
        a = self.curvature_centre_distance
        radial = a * math.cos(self.contact_angle) - 0.5 * self.diametral_clearance
        return math.acos(radial / a)

    @property
    def ball_mass(self) -> float:
        """Mass of one ball, rho pi D^3 / 6 [kg]; needs the ball material's density.

        Examples
        --------
        >>> from auxbearing import get_bearing
        >>> round(get_bearing("6205").ball_mass * 1e3, 3), round(get_bearing("6205 hybrid").ball_mass * 1e3, 3)
        (2.055, 0.842)
        """
        density = self.ball_material.density
        if density is None:
            raise InputError(f"ball material {self.ball_material.name}: density is not given but the ball mass "
                             "needs it (add e.g. density = '7810 kg/m^3')")
        return density * math.pi * self.ball_diameter**3 / 6.0

    @property
    def is_hybrid(self) -> bool:
        """True when balls and rings are of different materials (ceramic balls in steel rings)."""
        return self.ball_material.name != self.ring_material.name and self.ball_material.elastic_modulus > \
            1.2 * self.ring_material.elastic_modulus

    @property
    def label(self) -> str:
        """Human-readable type."""
        return BEARING_TYPES[self.type]["label"]

    def with_changes(self, **changes) -> BearingGeometry:
        """A copy with some fields changed, validated again."""
        return replace(self, **changes)

    def to_table(self) -> dict[str, object]:
        """The bearing as a ``[bearing]`` TOML table with units (what :func:`bearing_from_mapping` reads back).

        Examples
        --------
        >>> from auxbearing import get_bearing
        >>> b = get_bearing("QJ202")
        >>> bearing_from_mapping(b.to_table(), name=b.name) == b
        True
        """
        def length(value: float) -> str:
            return f"{float(value)!r} m"

        table: dict[str, object] = {
            "type": self.type, "ball_diameter": length(self.ball_diameter),
            "pitch_diameter": length(self.pitch_diameter), "ball_count": self.ball_count,
            "inner_groove_ratio": self.inner_groove_ratio, "outer_groove_ratio": self.outer_groove_ratio,
            "contact_angle": f"{float(self.contact_angle)!r} rad",
            "diametral_clearance": length(self.diametral_clearance),
            "ball_material": _material_table(self.ball_material), "ring_material": _material_table(self.ring_material),
            "source": self.source,
        }
        for key in ("bore", "outside_diameter", "width"):
            if getattr(self, key) is not None:
                table[key] = length(getattr(self, key))
        if self.rating_factor != 1.0:
            table["rating_factor"] = self.rating_factor
        return table

    def describe(self) -> dict[str, object]:
        """Inputs with units, for files and reports."""
        out: dict[str, object] = {
            "name": self.name,
            "type": self.type,
            "ball_diameter_mm": self.ball_diameter * 1e3,
            "pitch_diameter_mm": self.pitch_diameter * 1e3,
            "ball_count": self.ball_count,
            "inner_groove_ratio": self.inner_groove_ratio,
            "outer_groove_ratio": self.outer_groove_ratio,
            "contact_angle_deg": _deg(self.contact_angle),
            "diametral_clearance_mm": self.diametral_clearance * 1e3,
            "ball_material": f"{self.ball_material.name} (E = {self.ball_material.elastic_modulus / 1e9:g} GPa, "
            f"nu = {self.ball_material.poisson_ratio:g})",
            "ring_material": f"{self.ring_material.name} (E = {self.ring_material.elastic_modulus / 1e9:g} GPa, "
            f"nu = {self.ring_material.poisson_ratio:g})",
            "source": self.source,
        }
        for key in ("bore", "outside_diameter", "width"):
            value = getattr(self, key)
            if value is not None:
                out[f"{key}_mm"] = value * 1e3
        if self.rating_factor != 1.0:
            out["rating_factor"] = self.rating_factor
        return out


def _material_table(material: Material) -> str | dict:
    """A catalogue name when the material is the catalogue's, otherwise its table with units."""
    from auxbearing.bearings.materials import material_names

    if material.name in material_names() and get_material(material.name) == material:
        return material.name
    table = {"name": material.name, "elastic_modulus": f"{float(material.elastic_modulus)!r} Pa",
             "poisson_ratio": material.poisson_ratio}
    for key, unit in (("density", "kg/m**3"), ("specific_heat", "J/(kg*K)"), ("thermal_conductivity", "W/(m*K)"),
                      ("thermal_expansion", "1/K")):
        if getattr(material, key, None) is not None:
            table[key] = f"{float(getattr(material, key))!r} {unit}"
    return table


def max_ball_count(ball_diameter: float, pitch_diameter: float) -> int:
    """Largest Z with dm sin(pi/Z) > D (balls do not overlap on the pitch circle)."""
    return int(math.pi / math.asin(min(1.0, ball_diameter / pitch_diameter)) - 1e-12)


def _deg(angle: object) -> object:
    return math.degrees(angle) if isinstance(angle, (int, float)) else angle


# -- reading bearings from TOML tables ----------------------------------------------------
_LENGTH_KEYS = ("ball_diameter", "pitch_diameter", "diametral_clearance")
_OPTIONAL_LENGTH_KEYS = ("bore", "outside_diameter", "width")
_RATIO_KEYS = ("inner_groove_ratio", "outer_groove_ratio")
_REQUIRED_KEYS = ("type", *_LENGTH_KEYS[:2], "ball_count", *_RATIO_KEYS, "contact_angle",
                  "diametral_clearance", "ball_material", "ring_material")
_ALLOWED_KEYS = (*_REQUIRED_KEYS, "name", "source", *_OPTIONAL_LENGTH_KEYS, "rating_factor", "estimated")


def bearing_from_mapping(data: dict, name: str | None = None, prefix: str = "bearing.") -> BearingGeometry:
    """Build a validated bearing from a ``[bearing]`` TOML table whose values carry units.

    Examples
    --------
    >>> table = {"type": "four_point", "ball_diameter": "6 mm", "pitch_diameter": "25.5 mm",
    ...          "ball_count": 11, "inner_groove_ratio": 0.49, "outer_groove_ratio": 0.52,
    ...          "contact_angle": "35 deg", "diametral_clearance": "0 mm",
    ...          "ball_material": "GCr15", "ring_material": "GCr15"}
    >>> try:
    ...     bearing_from_mapping(table)
    ... except InputError as err:
    ...     print(err)
    bearing.inner_groove_ratio = 0.49: must be > 0.5 (groove radius larger than ball radius)
    """
    if not isinstance(data, dict):
        raise InputError.for_field(prefix.rstrip("."), data, "must be a table of keys")
    unknown = [k for k in data if k not in _ALLOWED_KEYS]
    if unknown:
        raise InputError.for_field(
            prefix + unknown[0], data[unknown[0]], "unknown key; allowed keys: " + ", ".join(_ALLOWED_KEYS)
        )
    missing = [k for k in _REQUIRED_KEYS if k not in data]
    if missing:
        raise InputError(f"{prefix}{missing[0]}: missing; a bearing needs " + ", ".join(_REQUIRED_KEYS))
    kind = data["type"]
    if not isinstance(kind, str) or kind not in BEARING_TYPES:
        raise InputError.for_field(prefix + "type", kind, "must be one of " + ", ".join(BEARING_TYPES))
    count = data["ball_count"]
    if isinstance(count, bool) or not isinstance(count, int):
        raise InputError.for_field(prefix + "ball_count", count, "must be a whole number >= 3")
    for key in ("name", "source"):  # a table or a number here would be printed as the bearing's name
        if key in data and not isinstance(data[key], str):
            raise InputError.for_field(prefix + key, data[key], "must be text in quotes")
    estimated = data.get("estimated", [])
    if not isinstance(estimated, list) or any(k not in _ALLOWED_KEYS for k in estimated):
        raise InputError.for_field(prefix + "estimated", estimated, "must list the keys whose values are estimated, "
                                   "e.g. [\"ball_diameter\", \"ball_count\"]")
    values: dict[str, object] = {
        "type": kind,
        "ball_count": count,
        "name": str(data.get("name", name or "custom")),
        "source": str(data.get("source", "user input")),
        "contact_angle": to_si(prefix + "contact_angle", data["contact_angle"], "angle"),
        "ball_material": _material(data["ball_material"], prefix + "ball_material."),
        "ring_material": _material(data["ring_material"], prefix + "ring_material."),
    }
    for key in _LENGTH_KEYS:
        values[key] = to_si(prefix + key, data[key], "length")
    for key in _OPTIONAL_LENGTH_KEYS:
        if key in data:
            values[key] = to_si(prefix + key, data[key], "length")
    for key in _RATIO_KEYS:
        values[key] = to_si(prefix + key, data[key], "dimensionless")
    if "rating_factor" in data:
        values["rating_factor"] = to_si(prefix + "rating_factor", data["rating_factor"], "dimensionless")
    try:
        return BearingGeometry(**values)
    except InputError as err:
        raise as_typed(err, data, prefix) from None


def _material(value: object, prefix: str) -> Material:
    if isinstance(value, str):
        try:
            return get_material(value)
        except InputError as err:
            raise InputError(prefix.rstrip(".") + str(err).removeprefix("material")) from None
    if isinstance(value, dict):
        return material_from_mapping(value, str(value.get("name", "custom")), "user input", prefix)
    raise InputError.for_field(prefix.rstrip("."), value, "must be a catalogue name or a table")


def read_toml(path: str | Path, field: str = "file") -> dict:
    """Read a TOML file, turning a missing file, a folder, a syntax error or deep nesting into a one-line error.

    The one reader of TOML files (:func:`auxbearing.common.io.read_toml`), kept here under its old name.
    """
    from auxbearing.common.io import read_toml as read

    return read(path, field)
