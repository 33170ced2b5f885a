"""Data files: the materials and bearings catalogues, each entry with its source."""

from functools import cache
from importlib import resources


@cache
def bearing_table() -> dict[str, dict]:
    """The bearings catalogue as read from ``bearings.toml`` (values with units, not yet validated)."""
    import tomllib

    return tomllib.loads(resources.files(__name__).joinpath("bearings.toml").read_text(encoding="utf-8"))


def bearing_names() -> list[str]:
    """Names of the catalogue bearings (no unit library needed: the command line lists them in its help)."""
    return list(bearing_table())
