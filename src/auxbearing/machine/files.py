"""Machine files: the shipped examples by name, a user's TOML file, each read and checked whole.

:func:`read_machine` and :func:`machine_table` are what the analyses and the command line read machines
with; the check (:func:`auxbearing.machine.check.check_machine_document`) runs before anything is built.
"""

from __future__ import annotations

from functools import cache
from importlib import resources
from pathlib import Path

from auxbearing.common.errors import InputError
from auxbearing.machine.check import check_machine_document
from auxbearing.machine.model import Machine


@cache
def _catalogue_files() -> dict[str, str]:
    folder = resources.files("auxbearing.catalog").joinpath("machines")
    return {entry.name.removesuffix(".toml"): entry.read_text() for entry in folder.iterdir()
            if entry.name.endswith(".toml")}


def machine_names() -> list[str]:
    """Names of the example machines shipped in the catalogue."""
    return sorted(_catalogue_files())


def machine_document(spec: str | Path) -> tuple[dict, str, Path | None]:
    """The tables of a machine file or catalogue machine as read, unchecked; its name and folder."""
    import tomllib

    from auxbearing.common.io import existing_file, read_toml

    text = str(spec)
    if text in _catalogue_files():
        # the catalogue's folder, for the files a catalogue machine names (an elastic rotor's matrices)
        folder = resources.files("auxbearing.catalog").joinpath("machines")
        return tomllib.loads(_catalogue_files()[text]), text, Path(str(folder))
    if not text.strip():  # Path("") is the current folder
        raise InputError.for_field("machine", text, "is empty; give a machine file or a catalogue machine ("
                                   + ", ".join(machine_names()) + ")")
    path = Path(text)
    if not path.exists():
        raise InputError.for_field("machine", text, "neither a file nor a catalogue machine ("
                                   + ", ".join(machine_names()) + ")")
    existing_file(path, "machine")
    return read_toml(path, "machine"), path.stem, path.parent


def machine_table(spec: str | Path) -> tuple[dict, str, Path | None]:
    """The tables of a machine file or catalogue machine as read (values with units), its name and folder.

    The whole file is checked first (:func:`auxbearing.machine.check.check_machine_document`): a file any
    command refuses, every command refuses, before any work.
    """
    data, name, base = machine_document(spec)
    check_machine_document(data, name, base)
    return data, name, base


def read_machine(spec: str | Path) -> Machine:
    """A machine from a TOML file or a catalogue name (:func:`machine_names`), the whole file checked first."""
    data, name, base = machine_document(spec)
    return check_machine_document(data, name, base)
