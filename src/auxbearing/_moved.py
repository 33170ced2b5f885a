"""The module paths of auxbearing before its rooms (docs/architecture.md), kept importable.

``import auxbearing.drop``, ``from auxbearing.life import dynamic_load_rating`` and the like still work: each
old path is a module whose names are looked up, on first use, in the modules that hold them now (listed
in :data:`MOVED`, searched in order). New code imports from the rooms; these paths stay for scripts and
notebooks written against earlier versions. The new modules are loaded by name only when a name is asked
for, so no room imports another through here.
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import sys
import types

#: Old path (under ``auxbearing.``) -> the modules that now hold its names, searched in order.
MOVED: dict[str, tuple[str, ...]] = {
    "errors": ("common.errors",), "units": ("common.units",), "params": ("common.params", "common.dimensions"),
    "unit_csv": ("common.unit_csv",), "io": ("common.io",),
    "bearing": ("bearings.geometry", "bearings.catalogue"), "ballset": ("bearings.ballset",),
    "materials": ("bearings.materials",),
    "machine_kernel": ("machine.pack",), "machine_check": ("machine.check", "machine.combinations"),
    "machine_keys": ("report.machine_file",), "machine_params": ("machine.params",),
    "contact": ("analysis.contact",), "statics": ("analysis.statics", "bearings.ratings"),
    "static_cases": ("analysis.static_cases",),
    "drop": ("analysis.drop", "planar.rig", "planar.params"), "drop_params": ("planar.params",),
    "coastdown": ("analysis.coastdown",), "coastdown_phases": ("analysis.coastdown_phases",),
    "coastdown_life": ("analysis.coastdown_life",), "thermal": ("analysis.thermal",),
    "life": ("analysis.life", "bearings.ratings"), "whirl": ("analysis.whirl",),
}


class _Moved(types.ModuleType):
    """An old module path: its attributes come from the modules that hold them now."""

    def __init__(self, name: str, homes: tuple[str, ...]) -> None:
        super().__init__(name, f"Moved: its names now live in {', '.join('auxbearing.' + h for h in homes)}.")
        self.__homes = homes

    def __getattr__(self, attribute: str):
        if attribute.startswith("__"):
            raise AttributeError(attribute)
        for home in self.__homes:
            module = importlib.import_module(f"auxbearing.{home}")
            if hasattr(module, attribute):
                return getattr(module, attribute)
        raise AttributeError(f"module {self.__name__!r} has no attribute {attribute!r}")

    def __dir__(self):
        names = set()
        for home in self.__homes:
            names |= set(dir(importlib.import_module(f"auxbearing.{home}")))
        return sorted(names)


class _Finder(importlib.abc.MetaPathFinder, importlib.abc.Loader):
    """Finds ``auxbearing.<old path>`` and makes it a :class:`_Moved` module."""

    def find_spec(self, fullname, path=None, target=None):
        package, _, old = fullname.partition(".")
        if package == "auxbearing" and old in MOVED:
            return importlib.machinery.ModuleSpec(fullname, self)
        return None

    def create_module(self, spec):
        return _Moved(spec.name, MOVED[spec.name.partition(".")[2]])

    def exec_module(self, module) -> None:
        return None


def install() -> None:
    """Put the finder on ``sys.meta_path`` once."""
    if not any(isinstance(f, _Finder) for f in sys.meta_path):
        sys.meta_path.append(_Finder())
