"""auxbearing: design of auxiliary (touchdown) ball bearings for active-magnetic-bearing machines.

The public API takes values with units (strings such as ``"6 mm"`` or pint quantities),
validates them, and calls SI kernels in :mod:`auxbearing.core`.
"""

from importlib.metadata import PackageNotFoundError, version

try:
    __version__ = version("auxbearing")
except PackageNotFoundError:  # running from a source tree without installation
    __version__ = "0.0.0+unknown"

from auxbearing.bearing import BearingGeometry, bearing_from_mapping, get_bearing, load_bearing
from auxbearing.errors import ConvergenceError, InputError
from auxbearing.materials import Material, get_material

__all__ = [
    "BearingGeometry",
    "ConvergenceError",
    "InputError",
    "Material",
    "__version__",
    "bearing_from_mapping",
    "get_bearing",
    "get_material",
    "load_bearing",
]
