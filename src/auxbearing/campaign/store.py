"""The campaign store: one Zarr group (written through xarray) holding every sample's inputs and outputs.

Layout: dimensions ``sample`` (every run of the design), ``input`` and ``plane``. The design
(``unit``: point in the unit hypercube; ``value``: SI input values) is written whole when the store
is made; every output variable exists from the start, chunked along ``sample`` by the batch size,
and a batch of results is written into its region as it arrives, the outputs first and its
``completed`` flags last, so a sample flagged complete is complete on disk. Attributes carry the
campaign (its description and fingerprint), the verdict and whirl codes and the units.

The store is made in a hidden sibling folder and renamed into place, so a store either exists with
its design or does not exist. Zarr format 2 is used: its fixed-width text arrays (the per-sample
reason) are specified, where format 3 has no stable text type yet.

One writer per store: a campaign holds the store's lock (:func:`store_lock`, a hidden file beside the
store naming the host and process that hold it) from before the store is made until its last batch
is written. A second writer is refused in one line naming the store; a lock whose process has ended on
this host (a campaign killed before it could clean up) is taken over with a note. A store that cannot be
read (metadata that is not JSON, a chunk cut short, an array missing) is one line naming the store.
"""

from __future__ import annotations

import contextlib
import json
import os
import shutil
import socket
import struct
import tempfile
import uuid
import warnings
from collections.abc import Iterator
from datetime import UTC, datetime
from pathlib import Path

import numpy as np

from auxbearing.campaign.config import Campaign
from auxbearing.campaign.evaluate import COASTDOWN_LIMITS, OUT_OF_RANGE, TIMING, VERDICTS, WHIRL_CODES, output_variables
from auxbearing.campaign.sampling import Design
from auxbearing.common.errors import InputError
from auxbearing.common.io import loads, process_alive, to_jsonable

ZARR_FORMAT = 2
#: Attribute that marks a campaign store (its value is the campaign's fingerprint).
MARK = "auxbearing_campaign"
#: Rows per chunk of the design arrays (written once; large chunks mean few files).
DESIGN_CHUNK = 4096


def _conversion(si: str, unit: str) -> tuple[str, float, float]:
    """(unit, scale, offset) with value in ``unit`` = scale * SI value + offset; the SI unit where none is given.

    The offset is that of a temperature shown in degC: 300 K is 26.85 degC, not 300 times a factor.
    """
    from auxbearing.common.units import Quantity

    if not unit or unit == si or not si:
        return si, 1.0, 0.0
    zero = float(Quantity(0.0, si).to(unit).magnitude)
    return unit, float(Quantity(1.0, si).to(unit).magnitude) - zero, zero


def _display(param) -> tuple[str, float]:
    """Display unit of an input and the factor from a difference in SI to one in it (1 when it has none)."""
    from auxbearing.common.params import si_unit

    unit, scale, _ = _conversion(si_unit(param.dimension), param.display_unit)
    return unit, scale


def input_display(ds, j: int) -> tuple[str, float, float]:
    """Input ``j`` of a store as a person reads it: (display unit, scale, offset) from its SI value.

    Taken from the store's unit coordinates, so a store written before the offset was known reads right too.
    """
    si = str(ds["input_unit"].values[j]) if "input_unit" in ds.coords else ""
    unit = str(ds["input_display_unit"].values[j]) if "input_display_unit" in ds.coords else ""
    if not si:
        return unit, float(ds["input_display_scale"].values[j]) if "input_display_scale" in ds.coords else 1.0, 0.0
    return _conversion(si, unit)


def _template(campaign: Campaign, design: Design):
    import dask.array as da
    import xarray as xr

    from auxbearing import __version__

    runs, batch = campaign.runs, campaign.batch_size
    planes = len(campaign.plane_names)
    sample_vars, plane_vars = output_variables(campaign.analysis)
    data = {}
    for name, (dtype, unit, long_name) in sample_vars.items():
        fill = "" if dtype.startswith("<U") else (0 if dtype == "i1" else np.nan)
        data[name] = ("sample", da.full(runs, fill, dtype=dtype, chunks=batch),
                      {"units": unit, "long_name": long_name})
    for name, (dtype, unit, long_name) in plane_vars.items():
        fill = 0 if dtype == "i1" else np.nan
        data[name] = (("sample", "plane"), da.full((runs, planes), fill, dtype=dtype, chunks=(batch, planes)),
                      {"units": unit, "long_name": long_name})
    data["completed"] = ("sample", da.zeros(runs, dtype="i1", chunks=batch),
                         {"long_name": "1 once the sample's record is written"})
    data["unit"] = (("sample", "input"), design.unit, {"long_name": "Design point in the unit hypercube"})
    data["value"] = (("sample", "input"), design.values,
                     {"long_name": "Input value in SI (unit in the input_unit coordinate)"})
    display = [_display(i.param) for i in campaign.inputs]
    coords = {"sample": np.arange(runs), "input": list(campaign.keys), "plane": list(campaign.plane_names),
              "input_unit": ("input", [i.unit for i in campaign.inputs]),
              "input_display_unit": ("input", [d[0] for d in display]),
              "input_display_scale": ("input", [d[1] for d in display])}
    ds = xr.Dataset(data, coords=coords)
    ds.attrs.update({
        MARK: campaign.fingerprint(), "title": f"Drop campaign: {campaign.name}",
        "campaign": described(campaign), "verdicts": list(VERDICTS),
        "out_of_range_verdicts": list(OUT_OF_RANGE), "coastdown_limit_verdicts": list(COASTDOWN_LIMITS),
        "whirl_classes": list(WHIRL_CODES), "timing": list(TIMING),
        "analysis": campaign.analysis, "sampler": campaign.sampler, "seed": campaign.seed,
        "samples": campaign.samples, "runs": runs, "batch_size": batch, "second_order": int(campaign.second_order),
        "required_s0": campaign.required_s0, "whirl_map": list(campaign.whirl_map or []),
        "notes": list(campaign.notes), "auxbearing_version": __version__,
        "created": datetime.now(UTC).isoformat(timespec="seconds")})
    encoding = {name: {"_FillValue": None} for name, v in ds.data_vars.items() if v.dtype.kind in "iU"}
    rows = min(runs, DESIGN_CHUNK)
    encoding.update(unit={"chunks": (rows, len(campaign.inputs))}, value={"chunks": (rows, len(campaign.inputs))})
    return ds, encoding


def described(campaign: Campaign) -> str:
    """The campaign's description as the store's ``campaign`` attribute holds it (JSON; an infinity is "inf").

    Bare ``Infinity`` is no JSON: a reader other than Python's would refuse the store's metadata.
    """
    return json.dumps(to_jsonable(campaign.describe()), default=str, allow_nan=False)


def create_store(path: str | Path, campaign: Campaign, design: Design) -> Path:
    """Make the store of a campaign at ``path`` (which must not exist): design written, outputs empty.

    An error names the store, never the hidden folder it is made in.
    """
    path = Path(path)
    ds, encoding = _template(campaign, design)
    try:
        path.parent.mkdir(parents=True, exist_ok=True)
        scratch = Path(tempfile.mkdtemp(prefix=f".{path.name}.", dir=path.parent))
    except OSError as err:
        raise InputError(f"store = '{path}': cannot be made here ({err.strerror or err})") from None
    try:
        # metadata consolidated once: the arrays and attributes are fixed here and batches only fill chunks, so
        # xarray.open_zarr on a store, finished or not, reads it without a warning and without listing every array
        ds.to_zarr(scratch / "store.zarr", mode="w-", compute=False, consolidated=True, zarr_format=ZARR_FORMAT,
                   encoding=encoding)
        os.rename(scratch / "store.zarr", path)
    except OSError as err:
        reason = "it appeared while this one was being made" if path.exists() else (err.strerror or str(err))
        raise InputError(f"store = '{path}': cannot be made ({reason})") from None
    finally:
        shutil.rmtree(scratch, ignore_errors=True)
    return path


def _damaged(path: Path, what: str, err: BaseException) -> InputError:
    reason = " ".join(f"{type(err).__name__}: {err}".split())[:160]
    return InputError(f"store = '{path}': {what} cannot be read ({reason}): the store is damaged (a file cut short "
                      "or changed, a copy that did not finish?); run the campaign again into a new --out")


@contextlib.contextmanager
def reading(path: str | Path, what: str = "its data") -> Iterator[None]:
    """Turn whatever a damaged store makes zarr, numcodecs or xarray raise into one line naming the store."""
    try:
        yield
    except (InputError, KeyboardInterrupt, MemoryError):
        raise
    except Exception as err:  # several libraries, many types: a bad chunk, bad metadata, a missing array
        raise _damaged(Path(path), what, err) from None


#: Blosc's chunk header: 16 bytes, the compressed size of the chunk (header included) a uint32 little-endian at
#: byte 12 (c-blosc, README_HEADER.rst). A chunk file shorter than that size was cut short; blosc would decode
#: it from memory past the file's end without a word.
BLOSC_HEADER, BLOSC_CBYTES_AT = 16, 12
#: zarr writes a chunk to ``<key>.<random hex>.partial`` and renames it (zarr.storage's atomic write); a process
#: killed in between leaves that file behind. It is no chunk: zarr reads the key alone, and the batch it belonged
#: to was never marked complete, so a resume writes it again.
ZARR_PARTIAL = ".partial"


def check_chunks(path: str | Path) -> None:
    """Refuse a store with a blosc chunk file cut short (a full disk, a copy that did not finish).

    A write that a killed process left unfinished (:data:`ZARR_PARTIAL`) is not a chunk and is passed over.
    """
    path = Path(path)
    for meta in sorted(path.glob("*/.zarray")):
        name = meta.parent.name
        with reading(path, f"the array {name!r}"):
            spec = json.loads(meta.read_bytes())
            if (spec.get("compressor") or {}).get("id") != "blosc":
                continue
            for chunk in sorted(meta.parent.iterdir()):
                if chunk.name.startswith(".") or chunk.name.endswith(ZARR_PARTIAL):
                    continue
                with chunk.open("rb") as handle:
                    head = handle.read(BLOSC_HEADER)
                size = chunk.stat().st_size
                expected = struct.unpack_from("<I", head, BLOSC_CBYTES_AT)[0] if len(head) == BLOSC_HEADER else None
                if expected != size:
                    raise InputError(f"store = '{path}': the array {name!r} has a chunk cut short ({chunk.name}: "
                                     f"{size} bytes of {expected or 'at least 16'}): the store is damaged (a full "
                                     "disk, a copy that did not finish?); run the campaign again into a new --out")


#: Outputs recorded since stores were first made: a store from before lacks them. Its results are still read (the
#: statistics leave the figure out), but no run is added to it (its new samples would record what its old ones lack).
LATER_OUTPUTS = ("max_excursion", "max_bearing_excursion")


def check_arrays(path: str | Path, ds, attrs: dict, reading: bool = False) -> None:
    """Refuse a store that lacks an array every campaign store of its analysis has (``reading``: or had)."""
    sample, plane = output_variables(attrs.get("analysis", "drop"))
    for name in (*sample, *plane, "completed", "unit", "value"):
        if reading and name in LATER_OUTPUTS:
            continue
        if name not in ds.variables:
            raise InputError(f"store = '{path}': the array {name!r} is missing: the store is damaged (a folder "
                             "deleted or a copy that did not finish?) or was made by an auxbearing that did not "
                             "record it; run the campaign again into a new --out")


def read_attrs(path: str | Path) -> dict:
    """The attributes of a campaign store; a one-line error when ``path`` is none or they cannot be read."""
    path = Path(path)
    meta = path / ".zattrs"
    if not path.exists():
        raise InputError(f"store = '{path}': does not exist; give the folder `auxbearing campaign --out` wrote")
    if not meta.is_file():
        raise InputError(f"store = '{path}': not a campaign store (no Zarr attributes); give the folder "
                         "`auxbearing campaign --out` wrote")
    try:
        attrs = json.loads(meta.read_bytes())
    except (ValueError, OSError) as err:  # not JSON, not UTF-8 (a ValueError too), unreadable
        raise _damaged(path, "its metadata (.zattrs)", err) from None
    if not isinstance(attrs, dict):
        raise InputError(f"store = '{path}': its metadata (.zattrs) is not a table of attributes: the store is "
                         "damaged; run the campaign again into a new --out")
    if MARK not in attrs:
        raise InputError(f"store = '{path}': a Zarr group but not a campaign store")
    return attrs


def _differences(attrs: dict, campaign: Campaign) -> str:
    """What the store's campaign and this one set differently, as a person compares two files (the keys)."""
    try:
        stored = loads(attrs.get("campaign", "{}"))
    except (TypeError, ValueError):
        stored = {}
    now = loads(described(campaign))
    keys = [k for k in now if k not in ("name", "base") and stored.get(k) != now[k]]
    if not keys:
        return f"fingerprint {attrs[MARK]}, this file gives {campaign.fingerprint()}"
    # batch_size changes no result but the store's layout: its chunks are one batch each
    return "it differs in " + ", ".join("tables (the machine and its settings)" if k == "tables" else
                                        "batch_size (the store's chunks are its batches)" if k == "batch_size" else k
                                        for k in keys)


def prepare_store(path: str | Path, campaign: Campaign, design: Design) -> bool:
    """Make the store, or check that an existing one holds this campaign; True when it was made."""
    path = Path(path)
    if not path.exists():
        create_store(path, campaign, design)
        return True
    if not path.is_dir():
        raise InputError(f"out = '{path}': exists and is not a folder")
    if not any(path.iterdir()):
        path.rmdir()
        create_store(path, campaign, design)
        return True
    attrs = read_attrs(path)
    if attrs[MARK] != campaign.fingerprint():
        raise InputError(f"out = '{path}': holds another campaign ({_differences(attrs, campaign)}); give a new "
                         "--out to start afresh, or the store's own settings to resume it")
    check_chunks(path)
    with reading(path, "its design"):
        stored = open_store(path)
        check_arrays(path, stored, attrs)
        same = stored.sizes.get("sample") == campaign.runs and np.array_equal(stored["unit"].values, design.unit)
    if not same:
        raise InputError(f"out = '{path}': its samples differ from those this campaign gives now (another "
                         "scipy or SALib version?); give a new --out")
    _judge_as_now(path, attrs, campaign)
    return False


#: Settings that judge a store's runs and change none of them: a resume takes the campaign file's values.
JUDGING_ATTRS = ("required_s0", "whirl_map")


def _judge_as_now(path: Path, attrs: dict, campaign: Campaign) -> None:
    """Store the campaign file's judging settings (:data:`JUDGING_ATTRS`), so its statistics use what it says."""
    now = {"required_s0": campaign.required_s0, "whirl_map": list(campaign.whirl_map or [])}
    if all(attrs.get(k) == v for k, v in now.items()):
        return
    import zarr

    zarr.open_group(str(path), mode="r+").attrs.update(now)


def open_store(path: str | Path):
    """The store as a lazy :class:`xarray.Dataset` read by zarr in this process.

    No Dask arrays (``chunks=None``): a read must not become tasks on whatever cluster a Dask client in
    this process has made the default (a verification's, busy with its runs), nor depend on a global
    ``dask.config`` that concurrent campaigns would set and reset under each other.
    """
    import xarray as xr

    return xr.open_zarr(Path(path), consolidated=False, chunks=None)


def load_results(path: str | Path):
    """The store read into memory (after :func:`read_attrs` checks it is one); a damaged store is one line.

    The line names the store and, when one array is at fault, that array.
    """
    attrs = read_attrs(path)
    check_chunks(path)
    with reading(path, "its arrays"):
        ds = open_store(path)
    check_arrays(path, ds, attrs, reading=True)
    for name in [*ds.coords, *ds.data_vars]:
        with reading(path, f"the array {name!r}"):
            ds[name].load()
    return ds


def completed(path: str | Path) -> np.ndarray:
    """Boolean per sample: its record is in the store."""
    with reading(path, "its completed flags"):
        return open_store(path)["completed"].values.astype(bool)


def pending_batches(path: str | Path, runs: int, batch: int) -> list[tuple[int, int]]:
    """(start, stop) of every batch with a sample not yet complete, in design order."""
    done = completed(path)
    return [(a, min(a + batch, runs)) for a in range(0, runs, batch) if not done[a:a + batch].all()]


def write_batch(path: str | Path, start: int, arrays: dict[str, np.ndarray]) -> None:
    """Write one batch's outputs into its region of the store, then flag its samples complete.

    The arrays go straight into the store's zarr arrays: the template gives them no encoding beyond a
    NaN fill for floats (no scale, offset or CF time), so xarray's region write, which costs the client
    about three times as much CPU (64 against 22 ms a batch of 8, measured), adds nothing.
    """
    import zarr

    group = zarr.open_group(str(path), mode="r+")
    n = len(arrays["verdict"])
    for name, values in arrays.items():
        group[name][start:start + n] = values
    group["completed"][start:start + n] = np.ones(n, dtype="i1")


# ----------------------------------------------------------------------------- one writer per store
class StoreLockNote(UserWarning):
    """A campaign took over the lock of a store whose writer had ended without releasing it."""


def lock_path(path: str | Path) -> Path:
    """The lock file of a store: a hidden sibling, so it exists before the store does."""
    path = Path(path)
    return path.parent / f".{path.name}.lock"


def _lock_owner(lock: Path) -> tuple[str, int, str] | None:
    """(host, process id, since) written in a lock file; None when it holds no such line."""
    try:
        host, pid, since = [*lock.read_text().split(), ""][:3]
        return host, int(pid), since
    except (OSError, ValueError, UnicodeDecodeError):
        return None


@contextlib.contextmanager
def store_lock(path: str | Path) -> Iterator[Path]:
    """Hold the lock of the store at ``path`` while writing it (module docstring); yields the lock file.

    The lock is a file beside the store holding "<host> <process id> <since>", made whole in a hidden
    file first and linked into place (a link fails when the name exists, so of two campaigns starting
    together exactly one gets the lock). Held by a live process, or by any process of another host (whose
    life this host cannot see), the store is refused in one line naming it. Held by a process of this
    host that has ended, it is taken over with a :class:`StoreLockNote`.
    """
    path = Path(path)
    lock = lock_path(path)
    host = socket.gethostname()
    mine = f"{host} {os.getpid()} {datetime.now(UTC).isoformat(timespec='seconds')}\n"
    try:
        lock.parent.mkdir(parents=True, exist_ok=True)
    except OSError as err:
        raise InputError(f"store = '{path}': cannot be made here ({err.strerror or err})") from None
    for _ in range(5):
        draft = lock.parent / f".{path.name}.lock-{uuid.uuid4().hex}"
        try:
            draft.write_text(mine)
            try:
                os.link(draft, lock)
                break
            except FileExistsError:
                pass
        except OSError as err:
            raise InputError(f"store = '{path}': cannot take its lock ({err.strerror or err})") from None
        finally:
            draft.unlink(missing_ok=True)
        owner = _lock_owner(lock)
        if owner is not None and (owner[0] != host or process_alive(owner[1])):
            where = "this host" if owner[0] == host else f"host {owner[0]}"
            since = f" since {owner[2]}" if owner[2] else ""
            hint = "" if owner[0] == host else (f"; if that process has ended, delete the lock file '{lock}' by "
                                                "hand (a process of another host cannot be seen from here)")
            raise InputError(f"store = '{path}': another campaign is writing it (process {owner[1]} on {where}"
                             f"{since}); wait for it to finish, or give another --out{hint}")
        # the writer has ended without releasing it (killed), or the file is not a lock of ours: move it
        # aside (a rename succeeds for one of two campaigns doing this at once), then try again
        stale = lock.parent / f".{path.name}.stale-{uuid.uuid4().hex}"
        try:
            os.rename(lock, stale)
        except FileNotFoundError:
            continue
        stale.unlink(missing_ok=True)
        what = (f"process {owner[1]} on this host, which has ended" if owner is not None
                else "a lock file that names no process")
        warnings.warn(StoreLockNote(f"store = '{path}': took over the lock of {what} (a campaign stopped before it "
                                    "could release it); its complete batches are kept"), stacklevel=3)
    else:
        raise InputError(f"store = '{path}': could not take its lock after 5 tries; another campaign keeps taking "
                         "it")
    try:
        yield lock
    finally:
        if lock.is_file() and lock.read_text() == mine:
            lock.unlink(missing_ok=True)
