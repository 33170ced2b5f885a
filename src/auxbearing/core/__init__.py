"""Pure kernels on SI floats and numpy arrays: no units, no I/O, no printing.

Every module here imports only numpy, numba and the standard library (a test checks it).

A compiled-kernel cache that cannot go stale: numba keys a cached function on its own source file, so a
kernel that inlines code from another core module (the drop inlines the ball-set pair kernel, the
integrator, the observer) would keep running old code after that module changed. So every core kernel
is cached under a folder named by a fingerprint of all core sources (their names, sizes and
modification times, which the import system has just looked at; no file is read or written here), the
numba version and the Python version. A change anywhere in the core, or a new installation, gives a new
folder and a recompilation of every kernel. The folder is ``__pycache__/kernels-<fingerprint>`` beside
the sources, or under ``NUMBA_CACHE_DIR`` when the user sets one; numba's own setting is restored once
the core is imported, so the user's own cached functions are not affected.
"""

from __future__ import annotations

import hashlib
import os
import sys

import numba

_HERE = os.path.dirname(os.path.abspath(__file__))


def source_fingerprint() -> str:
    """Short hash of the core sources' names, sizes and modification times, numba's and Python's versions."""
    digest = hashlib.sha256(f"{numba.__version__}|{sys.version}".encode())
    for entry in sorted(os.scandir(_HERE), key=lambda e: e.name):
        if entry.name.endswith(".py"):
            info = entry.stat()
            digest.update(f"{entry.name}:{info.st_size}:{info.st_mtime_ns}".encode())
    return digest.hexdigest()[:16]


def cache_folder() -> str:
    """Where this installation's kernels are cached (see the module docstring)."""
    base = os.environ.get("NUMBA_CACHE_DIR") or os.path.join(_HERE, "__pycache__")
    if not os.environ.get("NUMBA_CACHE_DIR") and not os.access(_HERE, os.W_OK):
        base = os.path.join(os.path.expanduser("~"), ".cache", "auxbearing")
    return os.path.join(base, f"kernels-{source_fingerprint()}")


_previous = numba.config.CACHE_DIR
numba.config.CACHE_DIR = cache_folder()
try:
    # numba picks the cache folder when a function is decorated, so every core module is imported now
    from auxbearing.core import (  # noqa: F401
        ballset,
        bearing_friction,
        drive,
        fatigue,
        hertz,
        integrate,
        machine,
        probes,
        rk4,
        spin,
        statics,
        thermal,
        watch,
    )
finally:
    numba.config.CACHE_DIR = _previous
