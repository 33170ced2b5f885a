"""Files out: NetCDF and JSON that carry their units, inputs and the package version.

Output folders are written atomically: everything goes to a hidden sibling folder first and is
moved into place only when the job has finished, so a failed run leaves no half-written folder.
"""

from __future__ import annotations

import contextlib
import json
import math
import os
import shutil
import tempfile
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import xarray as xr

from auxbearing import __version__
from auxbearing.errors import InputError


def provenance(inputs: dict | None = None) -> dict:
    """Attributes every file carries: the package version and the inputs of the run."""
    return {"auxbearing_version": __version__, "inputs": json.dumps(to_jsonable(inputs or {}), sort_keys=True)}


def save_dataset(ds: xr.Dataset, path: str | Path, inputs: dict | None = None) -> Path:
    """Write a Dataset to NetCDF with provenance attributes (attrs made NetCDF-safe)."""
    path = Path(path)
    out = ds.copy()
    out.attrs = {k: _netcdf_attr(v) for k, v in {**ds.attrs, **provenance(inputs)}.items()}
    for name in out.variables:
        out[name].attrs = {k: _netcdf_attr(v) for k, v in out[name].attrs.items()}
    out.to_netcdf(path)
    return path


def _netcdf_attr(value: object) -> object:
    if isinstance(value, bool):
        return int(value)
    if isinstance(value, (str, int, float, np.integer, np.floating)):
        return value
    return json.dumps(to_jsonable(value))


def to_jsonable(obj: object) -> object:
    """Numpy scalars/arrays and non-finite floats made JSON-safe (NaN becomes null)."""
    if isinstance(obj, dict):
        return {str(k): to_jsonable(v) for k, v in obj.items()}
    if isinstance(obj, (list, tuple)):
        return [to_jsonable(v) for v in obj]
    if isinstance(obj, np.ndarray):
        return to_jsonable(obj.tolist())
    if isinstance(obj, (np.integer,)):
        return int(obj)
    if isinstance(obj, (float, np.floating)):
        value = float(obj)
        return value if math.isfinite(value) else None
    if isinstance(obj, (np.bool_,)):
        return bool(obj)
    return obj


def dumps(obj: object) -> str:
    """JSON text of ``obj`` (indentation 2)."""
    return json.dumps(to_jsonable(obj), indent=2)


def write_json(obj: object, path: str | Path, inputs: dict | None = None) -> Path:
    """Write ``obj`` as JSON, with a ``provenance`` entry when it is a mapping."""
    path = Path(path)
    if isinstance(obj, dict):
        obj = {**obj, "provenance": {"auxbearing_version": __version__, "inputs": to_jsonable(inputs or {})}}
    path.write_text(dumps(obj) + "\n")
    return path


def save_figure(fig, stem: str | Path, formats: tuple[str, ...] = ("png",)) -> list[Path]:
    """Save a matplotlib Figure as ``stem.<fmt>`` for each format; returns the paths."""
    paths = []
    for fmt in formats:
        path = Path(f"{stem}.{fmt}")
        fig.savefig(path, dpi=150, bbox_inches="tight")
        paths.append(path)
    return paths


def check_output_dir(target: str | Path) -> Path:
    """``target`` as a Path if an output folder can be made there, else a one-line InputError.

    Called where the command line reads ``--out``, before any work, so that a bad folder never
    costs a finished computation; :func:`atomic_output_dir` checks again when it writes.
    """
    target = Path(target)
    if target.exists() and not target.is_dir():
        raise InputError(f"out = '{target}': exists and is not a folder; give a folder path")
    existing = next(p for p in (target, *target.parents) if p.exists())
    if not existing.is_dir():
        raise InputError(f"out = '{target}': '{existing}' is a file, so no folder can be made below it")
    if not os.access(existing, os.W_OK | os.X_OK):
        raise InputError(f"out = '{target}': '{existing}' is not writable")
    return target


@contextlib.contextmanager
def atomic_output_dir(target: str | Path) -> Iterator[Path]:
    """Yield a scratch folder; on success its files replace those in ``target``, on error it vanishes."""
    target = check_output_dir(target)
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        scratch = Path(tempfile.mkdtemp(prefix=f".{target.name}.", dir=target.parent))
    except OSError as err:
        raise InputError(f"out = '{target}': cannot create the output folder here ({err.strerror})") from None
    try:
        yield scratch
    except BaseException:
        shutil.rmtree(scratch, ignore_errors=True)
        raise
    target.mkdir(exist_ok=True)
    for item in scratch.iterdir():
        dest = target / item.name
        if dest.is_dir():
            shutil.rmtree(dest)
        elif dest.exists():
            dest.unlink()
        shutil.move(str(item), dest)
    scratch.rmdir()
