"""A rotor from ROSS (the open Python rotordynamics package, ``pip install auxbearing[ross]``).

ROSS builds a rotor of shaft, disk and bearing elements and gives its matrices over six degrees of freedom per
node, (x, y, z, alpha, beta, theta), with alpha the rotation about x and beta about y in the same senses as
this project's theta_x and theta_y (beta = dx/dz, alpha = -dy/dz) and the same M q'' + (C + Omega G) q' + K q = f.
The free-free structure is the rotor's shaft and disks alone (a ROSS rotor built again without its bearings);
its lateral rows and columns (x, y, alpha, beta of every node) are :class:`~.structure.RotorStructure`'s. The
rotor's bearings and seals are dropped or kept as ``[[linear_support]]`` stations at their nodes, with their
coefficients at the machine's speed (ROSS interpolates speed-dependent ones).

ROSS is imported only here, and only when a rotor comes from it: it is an optional extra, slow to import.
"""

from __future__ import annotations

import contextlib
import io
import os
import sys
import warnings
from pathlib import Path

import numpy as np

from auxbearing.common.errors import InputError
from auxbearing.machine.stations.linear_support import LinearSupport
from auxbearing.machine.structure import RotorStructure

#: ROSS's degrees of freedom per node, and where the lateral ones sit among them.
ROSS_DOFS = 6
LATERAL = (0, 1, 3, 4)
BEARINGS = ("keep", "drop")


def import_ross():
    """The ``ross`` module, imported without a word on stdout.

    ROSS imports ccp, which probes for REFPROP on import and prints its findings from compiled code straight onto
    file descriptor 1 (and warns). A command's stdout must hold its own output alone (``--json`` is parsed), and
    this project never uses REFPROP, so that notice is dropped: Python's and the C library's stdout both go to
    the null device for the import.
    """
    if "ross" in sys.modules:
        return sys.modules["ross"]
    if sys.stdout is not None:
        sys.stdout.flush()
    try:
        saved = os.dup(1)
    except OSError:  # no descriptor 1 at all: nothing to keep clean
        saved = None
    try:
        with open(os.devnull, "w") as sink, contextlib.redirect_stdout(io.StringIO()), warnings.catch_warnings():
            warnings.filterwarnings("ignore", category=UserWarning, module=r"ccp(\.|$)")
            if saved is not None:
                os.dup2(sink.fileno(), 1)
            try:
                import ross
            finally:
                _flush_c_stdout()
    finally:
        if saved is not None:
            os.dup2(saved, 1)
            os.close(saved)
    return ross


def _flush_c_stdout() -> None:
    # the C library buffers a pipe's output: unflushed, the notice would come out once descriptor 1 is back
    import ctypes

    with contextlib.suppress(OSError, AttributeError, TypeError):
        ctypes.CDLL(None).fflush(None)


def lateral_indices(n_nodes: int) -> np.ndarray:
    """Indices of x, y, alpha, beta of every node in ROSS's six-per-node ordering."""
    return np.array([ROSS_DOFS * n + d for n in range(n_nodes) for d in LATERAL])


def structure_from_ross(rotor, source: str = "ROSS rotor") -> RotorStructure:
    """The free-free structure of a ``ross.Rotor``: its shaft and disks, without its bearings and seals."""
    ross = import_ross()
    free = ross.Rotor(rotor.shaft_elements, rotor.disk_elements, [])
    nodes = np.asarray(rotor.nodes_pos, float)
    pick = np.ix_(lateral_indices(len(nodes)), lateral_indices(len(nodes)))
    damping = np.asarray(free.C(0.0), float)[pick]
    return RotorStructure(np.asarray(free.M(0.0), float)[pick], np.asarray(free.K(0.0), float)[pick],
                          np.asarray(free.G(), float)[pick], nodes, damping if np.any(damping) else None,
                          source=source)


def _coefficient(element, name: str, speed: float) -> float:
    interpolated = getattr(element, f"{name}_interpolated", None)
    if callable(interpolated):
        return float(np.asarray(interpolated(abs(speed))).reshape(-1)[0])
    return float(np.asarray(getattr(element, name)).reshape(-1)[0])


def supports_from_ross(rotor, speed: float) -> tuple[LinearSupport, ...]:
    """The rotor's bearings and seals as linear supports at their nodes, at ``speed`` [rad/s] (SI, file frame)."""
    nodes = np.asarray(rotor.nodes_pos, float)
    out = []
    for i, b in enumerate(rotor.bearing_elements):
        values = {name: _coefficient(b, name, speed)
                  for name in ("kxx", "kxy", "kyx", "kyy", "cxx", "cxy", "cyx", "cyy")}
        tag = getattr(b, "tag", None) or f"ROSS bearing {i}"
        out.append(LinearSupport(name=str(tag), position=float(nodes[int(b.n)]), **values))
    return tuple(out)


def read_ross_file(spec: str, base: Path | None, field: str):
    """A ``ross.Rotor`` from a file ROSS saved (``Rotor.save``), relative to ``base``; ``field`` names the key."""
    path = Path(spec) if base is None or Path(spec).is_absolute() else base / spec
    if not path.is_file():
        raise InputError.for_field(field, spec, "no such file (a rotor saved by ROSS's Rotor.save)")
    try:
        ross = import_ross()
    except ImportError:
        raise InputError.for_field(field, spec, "needs ROSS: pip install 'auxbearing[ross]'") from None
    try:
        return ross.Rotor.load(str(path))
    except Exception as err:  # ROSS raises what its file reader meets
        raise InputError.for_field(field, spec, f"ROSS could not read it ({type(err).__name__}: {err})") from None
