"""Files in and out: text in any encoding we can tell, NetCDF and JSON that carry units, inputs and version.

Output folders are written atomically: everything goes to a hidden sibling folder first and is
moved into place only when the job has finished, so a failed run leaves no half-written folder. A
run killed too hard to clean up (SIGKILL, out of memory) leaves its scratch folder behind; the next
run into the same folder removes it once the process that made it is gone.
"""

from __future__ import annotations

import codecs
import contextlib
import json
import math
import os
import shutil
import socket
import tempfile
import warnings
from collections.abc import Iterator
from pathlib import Path
from typing import TYPE_CHECKING

import numpy as np

from auxbearing import __version__
from auxbearing.common import interrupt
from auxbearing.common.errors import InputError

if TYPE_CHECKING:  # xarray is imported by the functions that write it, so reading a TOML file needs none
    import xarray as xr


class FileEncodingWarning(UserWarning):
    """A text file was not UTF-8 and was read in an encoding we had to assume."""


#: Byte-order marks, longest first (a UTF-32 LE mark begins like a UTF-16 LE one), with their encodings.
_BOMS = ((codecs.BOM_UTF32_LE, "utf-32"), (codecs.BOM_UTF32_BE, "utf-32"), (codecs.BOM_UTF8, "utf-8-sig"),
         (codecs.BOM_UTF16_LE, "utf-16"), (codecs.BOM_UTF16_BE, "utf-16"))
#: Share of NUL bytes in the odd (or even) positions that marks UTF-16 text without a byte-order mark:
#: text of Latin letters, digits and punctuation has a zero high byte in every character.
_UTF16_NUL_SHARE = 0.3
#: Share of control characters (other than tab, newline, carriage return, form feed) above which the
#: bytes are not text in any encoding.
_BINARY_CONTROL_SHARE = 0.01


def decode_text(data: bytes) -> tuple[str, str, bool]:
    """Text of a file's bytes, the encoding used and whether it had to be assumed.

    A byte-order mark or valid UTF-8 is certain; UTF-16 without a mark is told by its NUL bytes;
    anything else is read as Windows-1252 (ISO 8859-1 where Windows-1252 leaves a byte undefined),
    the usual encoding of files saved by Western-European Windows programs.

    Raises
    ------
    ValueError
        The bytes are not text (many control characters).

    Examples
    --------
    >>> decode_text("Prüfstand".encode("utf-8"))
    ('Prüfstand', 'UTF-8', False)
    >>> decode_text("Prüfstand".encode("latin-1"))
    ('Prüfstand', 'Windows-1252', True)
    >>> decode_text("x = 1".encode("utf-16-le"))
    ('x = 1', 'UTF-16-LE', True)
    """
    for bom, encoding in _BOMS:
        if data.startswith(bom):
            return _checked_text(data.decode(encoding), encoding.upper()), encoding.upper(), False
    if 0 not in data:  # NUL is valid UTF-8, but no text file holds one: it marks UTF-16 or binary data
        try:
            return _checked_text(data.decode("utf-8"), "UTF-8"), "UTF-8", False
        except UnicodeDecodeError:
            pass
    else:
        odd, even = data[1::2].count(0), data[0::2].count(0)
        half = len(data) // 2
        for share, encoding in ((odd, "utf-16-le"), (even, "utf-16-be")):
            if share >= _UTF16_NUL_SHARE * half and len(data) % 2 == 0:
                try:
                    return _checked_text(data.decode(encoding), encoding.upper()), encoding.upper(), True
                except UnicodeDecodeError:
                    break
        raise ValueError("holds NUL bytes: it is not a text file")
    try:
        return _checked_text(data.decode("cp1252"), "Windows-1252"), "Windows-1252", True
    except UnicodeDecodeError:
        return _checked_text(data.decode("latin-1"), "ISO-8859-1"), "ISO-8859-1", True


def _checked_text(text: str, encoding: str) -> str:
    control = sum(1 for ch in text if ord(ch) < 32 and ch not in "\t\n\r\f") + text.count("\x7f")
    if text and control > _BINARY_CONTROL_SHARE * len(text):
        raise ValueError(f"read as {encoding} it is mostly control characters: it is not a text file")
    return text


def existing_file(path: str | Path, field: str = "file") -> Path:
    """``path`` as a Path when it is a file; otherwise a one-line error naming ``field``."""
    if isinstance(path, str) and not path.strip():  # Path("") is ".", the current folder
        raise InputError.for_field(field, path, "is empty; give a file")
    path = Path(path)
    if path.is_dir():
        raise InputError.for_field(field, str(path), "is a folder, not a file")
    if not path.is_file():
        raise InputError.for_field(field, str(path), "not found")
    return path


def read_text(path: str | Path, field: str = "file") -> str:
    """A text file's content; one-line errors naming ``field`` and a warning when the encoding was assumed."""
    path = existing_file(path, field)
    try:
        text, encoding, assumed = decode_text(path.read_bytes())
    except ValueError as err:
        raise InputError.for_field(field, str(path), str(err)) from None
    if assumed:
        warnings.warn(FileEncodingWarning(f"{field} = '{path}': not UTF-8; read as {encoding} (save it as UTF-8 "
                                          "to be sure of its accented letters)"), stacklevel=2)
    return text


#: Deepest nesting of arrays and tables an input TOML file may have. A campaign's inputs are the deepest a
#: file of ours goes (``campaign`` > ``input`` > one input > its value: 4 levels, 6 with an inline bearing
#: and its material in a candidate); anything far deeper is not one of our files, and a parser or a copy
#: walking thousands of levels would run out of stack.
MAX_TOML_DEPTH = 16


def nesting_depth(data: object) -> int:
    """How many arrays and tables lie inside one another in ``data`` (a plain value is 0), without recursion.

    >>> nesting_depth({"a": [1, {"b": [2]}]}), nesting_depth(5)
    (4, 0)
    """
    deepest = 0
    stack = [(data, 0)]
    while stack:
        item, depth = stack.pop()
        if isinstance(item, dict):
            children = item.values()
        elif isinstance(item, list):
            children = item
        else:
            deepest = max(deepest, depth)
            continue
        deepest = max(deepest, depth + 1)
        stack.extend((child, depth + 1) for child in children)
    return deepest


def read_toml(path: str | Path, field: str = "file") -> dict:
    """A TOML file's tables; a missing file, a folder, bad syntax or a file nested too deeply is one line.

    A file nested thousands of levels deep exhausts the parser's stack (``RecursionError``) and one nested a
    few hundred levels would exhaust the next function that walks it: both are refused, naming the file.
    A file that is not UTF-8 is read in the encoding :func:`read_text` can tell, with a warning.
    """
    import tomllib

    text = read_text(path, field)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        raise InputError.for_field(field, str(path), f"is not valid TOML ({err})") from None
    except RecursionError:
        raise InputError.for_field(field, str(path), "is nested too deeply to read (arrays or tables inside one "
                                   f"another thousands of levels deep; our files need at most {MAX_TOML_DEPTH})"
                                   ) from None
    depth = nesting_depth(data)
    if depth > MAX_TOML_DEPTH:
        raise InputError.for_field(field, str(path), f"is nested {depth} levels deep (arrays or tables inside one "
                                   f"another); our files need at most {MAX_TOML_DEPTH}")
    return data


def provenance(inputs: dict | None = None) -> dict:
    """Attributes every file carries: the package version and the inputs of the run."""
    return {"auxbearing_version": __version__,
            "inputs": json.dumps(to_jsonable(inputs or {}), sort_keys=True, allow_nan=False)}


def save_dataset(ds: xr.Dataset, path: str | Path, inputs: dict | None = None) -> Path:
    """Write a Dataset to NetCDF with provenance attributes (attrs made NetCDF-safe)."""
    path = Path(path)
    out = ds.copy()
    out.attrs = {k: _netcdf_attr(v) for k, v in {**ds.attrs, **provenance(inputs)}.items()}
    for name in out.variables:
        out[name].attrs = {k: _netcdf_attr(v) for k, v in out[name].attrs.items()}
    try:
        with interrupt.deferred():  # a Ctrl-C inside the writer's close hangs it: honoured once the file is shut
            out.to_netcdf(path)
    except RuntimeError as err:  # the NetCDF/HDF5 library reports a full disk as "NetCDF: HDF error"
        free = shutil.disk_usage(path.parent).free
        raise OSError(None, f"the NetCDF library could not write it ({err}); {free / 1e6:.0f} MB free on that "
                            "disk; a full disk, a file-size limit or a quota?", str(path)) from None
    return path


def _netcdf_attr(value: object) -> object:
    if isinstance(value, bool):
        return int(value)
    if isinstance(value, (str, int, float, np.integer, np.floating)):
        return value
    return json.dumps(to_jsonable(value))


#: How an infinite number is written in JSON, which has no number for it. null would read as "missing", yet an
#: infinite life or a limit that is never reached is a finding; Python's ``float()`` reads these texts back.
INFINITY_TEXT = {math.inf: "inf", -math.inf: "-inf"}
_INFINITY_OF_TEXT = {text: value for value, text in INFINITY_TEXT.items()}


def to_jsonable(obj: object) -> object:
    """Numpy scalars/arrays and non-finite floats made JSON-safe: NaN becomes null, an infinity "inf" or "-inf".

    A key keeps its unit in its name ("drops_to_failure", "max_current_A"), so the text stands for the same
    quantity as a number would; :func:`from_jsonable` turns it back.

    >>> to_jsonable({"life": float("inf"), "margin": np.float64(-np.inf), "s0": float("nan"), "n": np.int64(3)})
    {'life': 'inf', 'margin': '-inf', 's0': None, 'n': 3}
    """
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
        if math.isnan(value):
            return None
        return INFINITY_TEXT.get(value, value)
    if isinstance(obj, (np.bool_,)):
        return bool(obj)
    return obj


def from_jsonable(obj: object) -> object:
    """What :func:`to_jsonable` wrote, with "inf" and "-inf" made floats again (null stays None).

    A text that is exactly "inf" or "-inf" is taken for the number wherever it stands, a name included.

    >>> from_jsonable({"life": "inf", "planes": [{"margin": "-inf", "name": "drive end"}], "s0": None})
    {'life': inf, 'planes': [{'margin': -inf, 'name': 'drive end'}], 's0': None}
    """
    if isinstance(obj, dict):
        return {k: from_jsonable(v) for k, v in obj.items()}
    if isinstance(obj, list):
        return [from_jsonable(v) for v in obj]
    if isinstance(obj, str) and obj in _INFINITY_OF_TEXT:
        return _INFINITY_OF_TEXT[obj]
    return obj


def dumps(obj: object) -> str:
    """JSON text of ``obj`` (indentation 2); a value JSON cannot hold raises rather than writing bare Infinity."""
    return json.dumps(to_jsonable(obj), indent=2, allow_nan=False)


def loads(text: str | bytes) -> object:
    """A JSON text this package wrote (:func:`dumps`, a file's ``summary`` attribute), infinities restored."""
    return from_jsonable(json.loads(text))


def write_json(obj: object, path: str | Path, inputs: dict | None = None) -> Path:
    """Write ``obj`` as JSON, with a ``provenance`` entry when it is a mapping."""
    path = Path(path)
    if isinstance(obj, dict):
        obj = {**obj, "provenance": {"auxbearing_version": __version__, "inputs": to_jsonable(inputs or {})}}
    path.write_text(dumps(obj) + "\n")
    return path


def trim_of(fig) -> dict:
    """Savefig's cropping for ``fig``: none for a figure laid out by its engine, else to the drawn extent.

    A constrained layout already fits the axes, legends and titles into the canvas; cropping to the tight
    box as well draws the figure twice (the blower's report figures: 20-58 % of their saving time).
    """
    return {} if fig.get_layout_engine() is not None else {"bbox_inches": "tight"}


def save_figure(fig, stem: str | Path, formats: tuple[str, ...] = ("png",)) -> list[Path]:
    """Save a matplotlib Figure as ``stem.<fmt>`` for each format; returns the paths."""
    paths = []
    for fmt in formats:
        path = Path(f"{stem}.{fmt}")
        fig.savefig(path, dpi=150, **trim_of(fig))
        paths.append(path)
    return paths


def check_output_dir(target: str | Path, field: str = "--out") -> Path:
    """``target`` as a Path if an output folder can be made there, else a one-line InputError.

    Called where the command line reads ``--out``, before any work, so that a bad folder never
    costs a finished computation; :func:`atomic_output_dir` checks again when it writes.
    """
    target = Path(target)
    if not str(target).strip():
        raise InputError.for_field(field, str(target), "is empty; give a folder name")
    if target.exists() and not target.is_dir():
        raise InputError.for_field(field, str(target), "exists and is not a folder; give a folder path")
    existing = next(p for p in (target.absolute(), *target.absolute().parents) if p.exists())
    if not existing.is_dir():
        raise InputError.for_field(field, str(target), f"'{existing}' is a file, so no folder can be made below it")
    if not os.access(existing, os.W_OK | os.X_OK):
        raise InputError.for_field(field, str(target), f"'{existing}' is not writable")
    return target


#: Marker of the scratch folder an :func:`atomic_output_dir` writes into: "<host> <process id>".
SCRATCH_OWNER = ".auxbearing-scratch"


def _scratch_prefix(target: Path) -> str:
    return f".{target.name}.partial-"


def _owner_is_gone(folder: Path) -> bool:
    """True when the process named in a scratch folder's marker no longer runs on this host."""
    try:
        host, pid = (folder / SCRATCH_OWNER).read_text().split()
        pid_number = int(pid)
    except (OSError, ValueError):
        return False  # no marker (not ours, or being made this instant): leave it
    return host == socket.gethostname() and not process_alive(pid_number)


def process_alive(pid: int) -> bool:
    """Whether a process of this host runs under ``pid`` (a live one of another user counts)."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    return True


def remove_stale_scratch(target: str | Path) -> list[Path]:
    """Remove the scratch folders of runs into ``target`` that were killed before they could clean up.

    Returns the folders removed. A folder whose run is still alive (another run into the same folder
    at this moment) is left alone.
    """
    target = Path(target)
    parent = target.absolute().parent
    if not parent.is_dir():
        return []
    removed = []
    for folder in parent.glob(_scratch_prefix(target) + "*"):
        if folder.is_dir() and _owner_is_gone(folder):
            shutil.rmtree(folder, ignore_errors=True)
            removed.append(folder)
    return removed


@contextlib.contextmanager
def atomic_output_dir(target: str | Path, field: str = "--out", owned: tuple[str, ...] = ()) -> Iterator[Path]:
    """Yield a scratch folder; on success its files replace those in ``target``, on error it vanishes.

    The scratch folder is a hidden sibling of ``target`` holding a marker with this process's id, so a
    later run can tell a killed run's leftovers (:func:`remove_stale_scratch`) from a running one's.
    ``owned``: glob patterns of the files the command writes; on success those in ``target`` that this run did
    not write (an earlier run's, of another machine or with more cases) are removed, so the folder holds one
    run; anything else in it is left alone.
    """
    target = check_output_dir(target, field)
    try:
        target.parent.mkdir(parents=True, exist_ok=True)
        remove_stale_scratch(target)
        scratch = Path(tempfile.mkdtemp(prefix=_scratch_prefix(target), dir=target.parent))
        (scratch / SCRATCH_OWNER).write_text(f"{socket.gethostname()} {os.getpid()}\n")
    except OSError as err:
        raise InputError.for_field(field, str(target), f"cannot create the output folder here ({err.strerror})"
                                   ) from None
    try:
        yield scratch
    except BaseException:
        shutil.rmtree(scratch, ignore_errors=True)
        raise
    (scratch / SCRATCH_OWNER).unlink()
    target.mkdir(exist_ok=True)
    written = {item.name for item in scratch.iterdir()}
    for pattern in owned:
        for old in target.glob(pattern):
            if old.name in written:
                continue
            if old.is_dir():
                shutil.rmtree(old)
            else:
                old.unlink()
    for item in scratch.iterdir():
        dest = target / item.name
        if dest.is_dir():
            shutil.rmtree(dest)
        elif dest.exists():
            dest.unlink()
        shutil.move(str(item), dest)
    scratch.rmdir()
