"""Elastic materials of balls and rings, and the materials catalogue."""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass
from functools import cache
from importlib import resources

from auxbearing.errors import InputError
from auxbearing.units import to_si


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

    Examples
    --------
    >>> steel = Material(207e9, 0.3, "GCr15")
    >>> f"{steel.compliance:.4e}"
    '4.3961e-12'
    """

    elastic_modulus: float
    poisson_ratio: float
    name: str = "custom"
    source: str = "user input"

    def __post_init__(self) -> None:
        check_positive("elastic_modulus", self.elastic_modulus)
        nu = self.poisson_ratio
        if not (isinstance(nu, (int, float)) and -1.0 < nu < 0.5):
            raise InputError.for_field("poisson_ratio", nu, "must lie in (-1, 0.5)")

    @property
    def compliance(self) -> float:
        """(1 - nu^2) / E [1/Pa], one body's term of Eq. 3 of the source paper."""
        return (1.0 - self.poisson_ratio**2) / self.elastic_modulus


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
    auxbearing.errors.InputError: material = 'brass': unknown; catalogue names are GCr15, 42CrMo, M50, Si3N4
    """
    wanted = name.strip().lower()
    for key, entry in _catalogue().items():
        if wanted == key.lower() or wanted in (a.lower() for a in entry.get("aliases", [])):
            return material_from_mapping(entry, key, entry["source"])
    raise InputError.for_field(
        "material", name, "unknown; catalogue names are " + ", ".join(_catalogue())
    )


_MATERIAL_KEYS = {"elastic_modulus", "poisson_ratio", "name", "source", "aliases"}


def material_from_mapping(data: dict, name: str, source: str, prefix: str = "") -> Material:
    """Build a :class:`Material` from a TOML table with units (``elastic_modulus = "207 GPa"``)."""
    unknown = set(data) - _MATERIAL_KEYS
    if unknown:
        key = sorted(unknown)[0]
        raise InputError.for_field(
            prefix + key, data[key], "unknown key; allowed: elastic_modulus, poisson_ratio, name"
        )
    for key in ("elastic_modulus", "poisson_ratio"):
        if key not in data:
            raise InputError(f"{prefix}{key}: missing (a material needs elastic_modulus and poisson_ratio)")
    modulus = to_si(prefix + "elastic_modulus", data["elastic_modulus"], "pressure")
    nu = to_si(prefix + "poisson_ratio", data["poisson_ratio"], "dimensionless")
    try:
        return Material(modulus, nu, str(data.get("name", name)), source)
    except InputError as err:
        raise InputError(prefix + str(err)) from None
