"""Materials of balls, rings, shafts and housings, and the materials catalogue.

Elastic constants are required; mass and thermal properties (density, specific heat, thermal
conductivity, linear expansion coefficient) are optional and ``None`` when unknown. Catalogue
values are room-temperature data-sheet values; each entry names where they come from.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass
from functools import cache
from importlib import resources

from auxbearing.common.errors import InputError
from auxbearing.common.params import as_typed
from auxbearing.common.units import to_si


@dataclass(frozen=True)
class Material:
    """An isotropic linear-elastic material.

    Parameters
    ----------
    elastic_modulus : float
        Young's modulus E [Pa].
    poisson_ratio : float
        Poisson's ratio nu [-], in (-1, 0.5).
    name : str
        Display name.
    source : str
        Where the values come from.
    density : float, optional
        Mass density rho [kg/m^3].
    specific_heat : float, optional
        Specific heat capacity c_p [J/(kg K)].
    thermal_conductivity : float, optional
        Thermal conductivity k [W/(m K)].
    thermal_expansion : float, optional
        Linear thermal expansion coefficient alpha [1/K].

    Examples
    --------
    >>> steel = Material(207e9, 0.3, "GCr15")
    >>> f"{steel.compliance:.4e}"
    '4.3961e-12'
    >>> steel.density is None
    True
    >>> round(get_material("GCr15").thermal_diffusivity * 1e6, 2)
    12.56
    """

    elastic_modulus: float
    poisson_ratio: float
    name: str = "custom"
    source: str = "user input"
    density: float | None = None
    specific_heat: float | None = None
    thermal_conductivity: float | None = None
    thermal_expansion: float | None = None

    def __post_init__(self) -> None:
        check_positive("elastic_modulus", self.elastic_modulus)
        nu = self.poisson_ratio
        if not (isinstance(nu, (int, float)) and -1.0 < nu < 0.5):
            raise InputError.for_field("poisson_ratio", nu, "must lie in (-1, 0.5)")
        for key in _THERMAL_KEYS:
            value = getattr(self, key)
            if value is not None:
                check_positive(key, value)

    @property
    def compliance(self) -> float:
        """(1 - nu^2) / E [1/Pa], one body's term of Eq. 3 of the source paper."""
        return (1.0 - self.poisson_ratio**2) / self.elastic_modulus

    @property
    def has_thermal_data(self) -> bool:
        """True when density, specific heat, conductivity and expansion are all given."""
        return all(getattr(self, key) is not None for key in _THERMAL_KEYS)

    @property
    def thermal_diffusivity(self) -> float:
        """Thermal diffusivity k / (rho c_p) [m^2/s]; needs the thermal data.

        Definition as in Incropera et al., Fundamentals of Heat and Mass Transfer, 6th ed. (2007), Sec. 2.2.
        """
        self.require_thermal("thermal_diffusivity")
        return self.thermal_conductivity / (self.density * self.specific_heat)

    def require_thermal(self, purpose: str) -> None:
        """Raise a one-line error naming the first missing thermal property."""
        for key in _THERMAL_KEYS:
            if getattr(self, key) is None:
                raise InputError(
                    f"material {self.name}: {key} is not given but {purpose} needs it "
                    f"(add e.g. {key} = '{_EXAMPLE_THERMAL[key]}' to the material table)"
                )


#: Optional mass and thermal properties and the unit dimension each is read in.
_THERMAL_DIMENSIONS = {
    "density": "density",
    "specific_heat": "specific_heat",
    "thermal_conductivity": "thermal_conductivity",
    "thermal_expansion": "thermal_expansion",
}
_THERMAL_KEYS = tuple(_THERMAL_DIMENSIONS)
_EXAMPLE_THERMAL = {
    "density": "7810 kg/m^3",
    "specific_heat": "475 J/(kg*K)",
    "thermal_conductivity": "46.6 W/(m*K)",
    "thermal_expansion": "11.9e-6 1/K",
}


def check_positive(field: str, value: float) -> None:
    """Refuse NaN, infinite, zero and negative values with a one-line error."""
    if not isinstance(value, (int, float)) or isinstance(value, bool) or math.isnan(value):
        raise InputError.for_field(field, value, "must be a positive number")
    if math.isinf(value) or value <= 0.0:
        raise InputError.for_field(field, value, "must be a positive finite number")


@cache
def _catalogue() -> dict[str, dict]:
    text = resources.files("auxbearing.catalog").joinpath("materials.toml").read_text()
    return tomllib.loads(text)


def material_names() -> list[str]:
    """Names of the catalogue materials."""
    return list(_catalogue())


def get_material(name: str) -> Material:
    """Look a material up by name or alias (case-insensitive).

    Examples
    --------
    >>> get_material("AISI 52100").name
    'GCr15'
    >>> get_material("brass")
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: material = 'brass': unknown; catalogue names are GCr15, 42CrMo, ..., steel
    """
    wanted = name.strip().lower()
    for key, entry in _catalogue().items():
        if wanted == key.lower() or wanted in (a.lower() for a in entry.get("aliases", [])):
            return material_from_mapping(entry, key, entry["source"])
    raise InputError.for_field(
        "material", name, "unknown; catalogue names are " + ", ".join(_catalogue())
    )


_MATERIAL_KEYS = {"elastic_modulus", "poisson_ratio", "name", "source", "aliases", *_THERMAL_KEYS}


def material_from_mapping(data: dict, name: str, source: str, prefix: str = "") -> Material:
    """Build a :class:`Material` from a TOML table with units (``elastic_modulus = "207 GPa"``).

    Examples
    --------
    >>> m = material_from_mapping({"elastic_modulus": "200 GPa", "poisson_ratio": 0.3,
    ...                            "density": "7.85 g/cm^3"}, "housing", "user input")
    >>> round(m.density, 6), m.specific_heat
    (7850.0, None)
    """
    unknown = set(data) - _MATERIAL_KEYS
    if unknown:
        key = sorted(unknown)[0]
        raise InputError.for_field(
            prefix + key, data[key],
            "unknown key; allowed: elastic_modulus, poisson_ratio, name, " + ", ".join(_THERMAL_KEYS),
        )
    for key in ("elastic_modulus", "poisson_ratio"):
        if key not in data:
            raise InputError(f"{prefix}{key}: missing (a material needs elastic_modulus and poisson_ratio)")
    modulus = to_si(prefix + "elastic_modulus", data["elastic_modulus"], "pressure")
    nu = to_si(prefix + "poisson_ratio", data["poisson_ratio"], "dimensionless")
    optional = {
        key: to_si(prefix + key, data[key], dimension)
        for key, dimension in _THERMAL_DIMENSIONS.items()
        if key in data
    }
    try:
        return Material(modulus, nu, str(data.get("name", name)), source, **optional)
    except InputError as err:
        raise as_typed(err, data, prefix) from None
