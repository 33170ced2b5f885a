"""auxbearing: design of auxiliary (touchdown) ball bearings for active-magnetic-bearing machines.

The public API takes values with units (strings such as ``"6 mm"`` or pint quantities, or plain numbers
in SI), validates them, and calls SI kernels in :mod:`auxbearing.core`. The names below are loaded on
first use, so ``import auxbearing`` (and the pure core under it) pulls in no unit or I/O library.
"""

from importlib import import_module
from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("auxbearing")
except PackageNotFoundError:  # running from a source tree without installation
    __version__ = "0.0.0+unknown"

_LAZY = {
    "BearingGeometry": "auxbearing.bearings.geometry",
    "bearing_from_mapping": "auxbearing.bearings.geometry",
    "get_bearing": "auxbearing.bearings.catalogue",
    "load_bearing": "auxbearing.bearings.catalogue",
    "ConvergenceError": "auxbearing.common.errors",
    "InputError": "auxbearing.common.errors",
    "Material": "auxbearing.bearings.materials",
    "get_material": "auxbearing.bearings.materials",
    "Machine": "auxbearing.machine.model",
    "read_machine": "auxbearing.machine.files",
    "run_machine": "auxbearing.analysis.drop",
    "run_drop": "auxbearing.planar.rig",
}

__all__ = ["__version__", *sorted(_LAZY)]

# the module paths before the rooms (auxbearing.drop, auxbearing.life, ...) stay importable
from auxbearing._moved import install as _install_moved  # noqa: E402

_install_moved()


def __getattr__(name: str):
    """Load a public name from its module on first use (PEP 562)."""
    if name in _LAZY:
        value = getattr(import_module(_LAZY[name]), name)
        globals()[name] = value
        return value
    raise AttributeError(f"module 'auxbearing' has no attribute {name!r}")
