"""Measured rotor drops in: CSV and NetCDF readers with the checks a test-rig file needs.

A measured drop is the journal centre (x, y) recorded by two displacement sensors over time,
optionally with the rotor speed (source paper Sec. III, Fig. 13). Both readers return the same
:class:`xarray.Dataset` in SI units (time [s], x and y [m], speed [rad/s]) so the rest of the
pipeline never sees a unit. Every problem with the file is an :class:`InputError` of one line
naming the column and the file line (CSV) or the index (NetCDF).

CSV format (see docs/experiment.md)::

    # lines starting with '#' are comments; '# key = value' lines become metadata
    time [s], x [um], y [um], speed [rpm]
    0.000000, 12.31, -4.02, 6000.2

The unit of each column is written in brackets in the header or given as an option
(``units={"x": "um"}``); a column without a unit is refused. Names are matched without
regard to case; ``t`` is an alias of ``time``, ``omega`` and ``rpm`` of ``speed``.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import xarray as xr

from auxbearing.common.dimensions import with_article
from auxbearing.common.errors import InputError
from auxbearing.common.io import existing_file
from auxbearing.common.unit_csv import MAX_MAGNITUDE, Column, read_unit_csv, unit_scale

#: Dimension of each channel (keys of :data:`auxbearing.common.units.SI_UNITS`), required or not.
CHANNELS = {"time": ("time", True), "x": ("length", True), "y": ("length", True),
            "speed": ("angular_speed", False)}
_ALIASES = {"t": "time", "omega": "speed", "rpm": "speed", "spin": "speed"}
_CSV_COLUMNS = {name: Column(dimension, required, {"time": "s", "speed": "rpm"}.get(name, "um"))
                for name, (dimension, required) in CHANNELS.items()}
#: Fewest samples a drop record must have.
MIN_SAMPLES = 64
#: Largest relative spread of the sampling interval accepted as uniform sampling.
UNIFORM_TOLERANCE = 0.01
#: Slowest sampling that can still see an impact: the rotor/race contact lasts about 0.2 ms
#: (half the ~0.4 ms contact period, paper_notes item 7), so below 5 kHz an impact is one sample or none.
MIN_SAMPLING_RATE = 5e3
#: Span of a drop record (the larger peak-to-peak of x and y) [m]: the journal crosses its clearance circle,
#: so it spans about twice the radial clearance plus the contact deflections. Touchdown clearances run from
#: some 10 um on small spindles to about 1 mm on large machines; a record outside 1 um - 20 mm is not a drop
#: in the unit its columns name (a factor of 1000 either way is the usual slip: um written as mm).
ORBIT_SPAN = (1e-6, 20e-3)
#: A typical span [m] (the source paper's rig: 0.2 mm clearance), against which another unit is suggested.
TYPICAL_SPAN = 0.4e-3
#: A drop moves the journal from its levitated spot by more than this many times its jitter there (the
#: factor on the noise the drop detection uses, :func:`auxbearing.experiment.orbit.detect_drop`).
DROP_TO_JITTER = 10.0
#: Length units a sensor's column is written in, with their size in metres.
LENGTH_UNITS = {"m": 1.0, "mm": 1e-3, "um": 1e-6, "nm": 1e-9}


def channel_name(name: str) -> str | None:
    """The channel a column or variable name means (aliases and case resolved), or None.

    >>> channel_name("RPM"), channel_name("q")
    ('speed', None)
    """
    key = name.strip().lower()
    key = _ALIASES.get(key, key)
    return key if key in CHANNELS else None


_channel = channel_name


def read_csv(path: str | Path, units: dict[str, str] | None = None, delimiter: str | None = None,
             field: str = "measured file") -> xr.Dataset:
    """Read a measured drop from a CSV file and check it.

    Parameters
    ----------
    path : path
        The file (format in the module docstring).
    units : dict, optional
        Unit of a channel (``{"x": "um", "time": "ms"}``) when the header has none; a unit in
        the header wins only when it agrees, otherwise the option is an error.
    delimiter : str, optional
        Field separator; default: a comma if the header has one, else whitespace.
    field : str
        How an error names the file (``--measured`` on the command line).

    Returns
    -------
    xarray.Dataset
        ``x``, ``y`` [m] (and ``speed`` [rad/s]) over ``time`` [s]; attrs: ``source_file``,
        ``sampling_rate_Hz`` and every ``# key = value`` comment of the file.

    Raises
    ------
    InputError
        One line naming the column and the file line: missing file or header, unknown or
        missing unit, a field that is not a number, a missing value, time not increasing,
        non-uniform or too slow sampling, too few samples.
    """
    table = read_unit_csv(path, _CSV_COLUMNS, file_field=field, aliases=_ALIASES, units=units,
                          delimiter=delimiter)
    written, labels = {}, {}
    for label in table.header:
        head, _, unit = label.partition("[")
        channel = _channel(head)
        if channel is not None:
            written[channel] = unit.rstrip("] ").strip() or (units or {}).get(channel, "")
            labels[channel] = label  # errors quote the header as written ('time [ms]'), as the reader's own do
    return _checked(table.data, [f"line {n}" for n in table.lines], Path(path).name, labels, table.meta, written)


def read_netcdf(path: str | Path, units: dict[str, str] | None = None, field: str = "measured file") -> xr.Dataset:
    """Read a measured drop from NetCDF: variables ``x``, ``y`` (optional ``speed``) over ``time``.

    Units come from each variable's ``units`` attribute (and the time coordinate's), or from
    ``units``; a NetCDF time coordinate decoded to dates is refused (store seconds).

    Returns and raises as :func:`read_csv`; rows are named by their index along ``time``.
    """
    path = existing_file(path, field)
    try:
        raw = xr.load_dataset(path, decode_times=False)
    except Exception as err:  # netCDF4/h5py raise several unrelated types for a bad file
        reason = " ".join(str(err).split())[:200]
        raise InputError.for_field(field, str(path), f"is not a readable NetCDF file ({reason})") from None
    units = {(_channel(k) or k): v for k, v in (units or {}).items()}
    names = {(_channel(str(k)) or str(k)): str(k) for k in [*raw.data_vars, *raw.coords]}
    data: dict[str, np.ndarray] = {}
    written: dict[str, str] = {}
    for channel, (dimension, required) in CHANNELS.items():
        if channel not in names:
            if required:
                raise InputError(f"{path.name}: no {channel!r} variable; found {', '.join(map(str, raw.variables))}")
            continue
        var = raw[names[channel]]
        if var.ndim != 1:
            raise InputError(f"{path.name}: variable {names[channel]!r} has dims {var.dims}; it must be 1-D over time")
        unit = str(var.attrs.get("units", "")).strip() or units.get(channel, "")
        if not unit:
            raise InputError(f"{path.name}: variable {names[channel]!r} has no 'units' attribute; give its unit "
                             "as an option")
        values = np.asarray(var.values, float)
        bad = np.nonzero(~np.isfinite(values))[0]
        if bad.size:
            raise InputError(f"{path.name}: variable {names[channel]!r}, index {bad[0]}: missing value")
        try:
            scale = unit_scale(names[channel], unit, dimension)
        except InputError:
            raise InputError(f"{path.name}: variable {names[channel]!r}: units {unit!r} is not "
                             f"{with_article(dimension.replace('_', ' '))} (store seconds for time, lengths such as "
                             "um for x and y)") from None
        with np.errstate(over="ignore"):
            data[channel] = values * scale
        beyond = np.nonzero(~(np.abs(data[channel]) <= MAX_MAGNITUDE))[0]
        if beyond.size:
            raise InputError(f"{path.name}: variable {names[channel]!r}, index {beyond[0]}: {values[beyond[0]]:g} "
                             f"{unit} is beyond any value auxbearing computes with (at most {MAX_MAGNITUDE:g} in SI)")
        written[channel] = unit
    sizes = {c: v.size for c, v in data.items()}
    if len(set(sizes.values())) != 1:
        raise InputError(f"{path.name}: channels have different lengths {sizes}")
    meta = {str(k): str(v) for k, v in raw.attrs.items()}
    return _checked(data, [f"index {k}" for k in range(sizes["time"])], path.name,
                    {c: names[c] for c in data}, meta, written)


def read_measured(path: str | Path, units: dict[str, str] | None = None, field: str = "measured file") -> xr.Dataset:
    """A measured drop from ``.nc`` / ``.nc4`` / ``.cdf`` (NetCDF) or any other file as CSV.

    ``field`` names the file in an error (``--measured`` on the command line).
    """
    suffix = Path(path).suffix.lower()
    if suffix in (".nc", ".nc4", ".cdf", ".netcdf"):
        return read_netcdf(path, units, field)
    return read_csv(path, units, field=field)


def _orbit_span(data: dict[str, np.ndarray], name: str, labels: dict, written: dict) -> None:
    """Refuse a record whose orbit no touchdown clearance allows, naming the unit it would fit (module constants)."""
    span = max(float(np.ptp(data["x"])), float(np.ptp(data["y"])))
    if ORBIT_SPAN[0] <= span <= ORBIT_SPAN[1]:
        return
    columns = f"{labels.get('x', 'x')!r}, {labels.get('y', 'y')!r}"
    if span < ORBIT_SPAN[0]:
        _refuse_without_drop(data, name, columns, span)
    size = "more" if span > ORBIT_SPAN[1] else "less"
    text = (f"{name}: columns {columns}: the journal moves over {span * 1e3:.4g} mm, {size} than a drop's orbit can "
            f"(about twice the radial clearance: {ORBIT_SPAN[0] * 1e6:g} um to {ORBIT_SPAN[1] * 1e3:g} mm)")
    unit = written.get("x", "")
    if unit in LENGTH_UNITS and span > 0.0:
        best = min(LENGTH_UNITS, key=lambda u: abs(math.log(span / LENGTH_UNITS[unit] * LENGTH_UNITS[u]
                                                             / TYPICAL_SPAN)))
        if best != unit:
            text += (f"; are the columns in {best} rather than {unit}? (the orbit would span "
                     f"{span / LENGTH_UNITS[unit] * LENGTH_UNITS[best] * 1e3:.4g} mm)")
    elif span < ORBIT_SPAN[0]:
        text += ": no drop in it, or a length unit too large"
    raise InputError(text)


#: Fastest sampling a drop record can have [Hz]: eddy-current displacement probes resolve some 10-100 kHz, and
#: their recorders sample at most a few hundred kHz; a record faster than this has a time unit slip.
MAX_SAMPLING_RATE = 1e6
#: A channel without noise that spans less than this share of a noisy one holds no drop: a dead or disconnected
#: probe (a drop moves the journal over the clearance in both directions as it rebounds and whirls).
DEAD_SHARE = 0.02
#: Samples in a row at exactly a channel's extreme that tell a clipped (saturated) probe or recorder: with the
#: noise of any probe, even quantised, the extreme of a moving orbit holds for a sample or two.
CLIPPED_RUN = 20


#: Jitter [m] (median of the second differences over the record's first samples) below which a channel is
#: noise-free: a record written by hand or by a model, where a still or straight stretch is no fault. A probe's
#: noise is some 10 nm or more.
NOISE_FREE = 1e-9


def _jitter(values: np.ndarray) -> float:
    return float(np.median(np.abs(np.diff(values[:64], 2))))


def _live_channels(data: dict[str, np.ndarray], name: str, labels: dict) -> None:
    """Refuse a measured record with a dead channel (flat beside a live one) or a clipped one (flat at an end).

    Both faults are told by a channel holding exactly still where a probe's noise would move it, so a noise-free
    record (written by hand or by a model) is not judged: its still stretches are the journal's.
    """
    live = {axis: _jitter(data[axis]) > NOISE_FREE for axis in ("x", "y")}
    spans = {axis: float(np.ptp(data[axis])) for axis in ("x", "y")}
    for axis, other in (("x", "y"), ("y", "x")):
        column = labels.get(axis, axis)
        if not live[axis] and live[other] and spans[axis] < DEAD_SHARE * spans[other]:
            raise InputError(f"{name}: column {column!r} moves over {spans[axis] * 1e6:.3g} um while "
                             f"{labels.get(other, other)!r} moves over {spans[other] * 1e6:.4g} um: a dead or "
                             "disconnected probe (a drop moves the journal both ways)")
        values = data[axis]
        if not live[axis]:
            continue
        for end in (values.max(), values.min()):
            at = np.flatnonzero(values == end)
            # a run from the first sample is the levitated journal holding still (a noise-free record), not a clip
            runs = [run for run in np.split(at, np.flatnonzero(np.diff(at) > 1) + 1) if run.size and run[0] > 0]
            longest = max((run.size for run in runs), default=0)
            if longest >= CLIPPED_RUN:
                raise InputError(f"{name}: column {column!r} holds {end * 1e6:.6g} um for {longest} samples in a "
                                 "row at its extreme: the probe or its recorder clipped (saturated) there; record "
                                 "with a range that holds the whole orbit")


def _refuse_without_drop(data: dict[str, np.ndarray], name: str, columns: str, span: float) -> None:
    """Refuse a record in which the journal never leaves its levitated spot: it ends before the drop.

    A unit too large shrinks the whole drop, its noise included, so the journal still moves hundreds of times
    further than it jitters while levitated; a record of the levitated journal alone moves no further than
    that jitter. Only the first is told to check its unit.
    """
    from auxbearing.experiment.orbit import OPENING_SAMPLES, OPENING_STRETCH, noise_level

    x, y, t = data["x"], data["y"], data["time"]
    n0 = max(OPENING_SAMPLES, int(np.searchsorted(t, t[0] + OPENING_STRETCH)))
    # the spread of the opening stretch as well as the sample-to-sample noise: a sensor's anti-alias filter
    # smooths its noise, which the second differences of noise_level then underrate
    jitter = max(noise_level(x), noise_level(y), float(np.std(x[:n0])), float(np.std(y[:n0])))
    away = float(np.max(np.hypot(x - np.median(x[:n0]), y - np.median(y[:n0]))))
    if away > DROP_TO_JITTER * jitter:
        return
    raise InputError(f"{name}: columns {columns}: the journal never leaves its levitated position (it moves "
                     f"{away * 1e6:.3g} um at most, within {DROP_TO_JITTER:g} times its jitter of "
                     f"{jitter * 1e6:.2g} um): the record ends before the drop, or holds none ({t.size} samples "
                     f"over {(t[-1] - t[0]) * 1e3:.3g} ms)")


def _checked(data: dict[str, np.ndarray], where: list[str], name: str, labels: dict, meta: dict,
             written: dict | None = None) -> xr.Dataset:
    """Check time, sampling and the orbit's size, then build the Dataset (SI)."""
    t = data["time"]
    label = labels.get("time", "time")
    if t.size < MIN_SAMPLES:
        raise InputError(f"{name}: {t.size} samples; a drop record needs at least {MIN_SAMPLES}")
    step = np.diff(t)
    bad = np.nonzero(step <= 0.0)[0]
    if bad.size:
        k = bad[0] + 1
        raise InputError(f"{name}: column {label!r}, {where[k]}: time {t[k]:.9g} s does not increase "
                         f"(previous {t[k - 1]:.9g} s)")
    dt = float(np.median(step))
    spread = np.abs(step / dt - 1.0)
    worst = int(np.argmax(spread))
    if spread[worst] > UNIFORM_TOLERANCE:
        raise InputError(f"{name}: column {label!r}, {where[worst + 1]}: sampling interval {step[worst]:.6g} s "
                         f"differs from the median {dt:.6g} s by more than {100 * UNIFORM_TOLERANCE:g} % "
                         "(resample to a uniform rate first)")
    rate = 1.0 / dt
    if rate < MIN_SAMPLING_RATE:
        raise InputError(f"{name}: column {label!r}: sampling rate {rate:.4g} Hz is below {MIN_SAMPLING_RATE:g} Hz, "
                         "too slow to resolve impacts lasting about 0.2 ms")
    if rate > MAX_SAMPLING_RATE:
        raise InputError(f"{name}: column {label!r}: sampling rate {rate:.4g} Hz over a record of "
                         f"{(t[-1] - t[0]) * 1e3:.3g} ms, beyond the {MAX_SAMPLING_RATE:g} Hz a displacement probe "
                         "records: is the column in s where its header says ms (or ms where it says us)?")
    _orbit_span(data, name, labels, written or {})
    _live_channels(data, name, labels)
    coords = {"time": ("time", t, {"units": "s", "long_name": "Time of the record"})}
    variables = {
        "x": ("time", data["x"], {"units": "m", "long_name": "Journal centre x as measured (sensor frame)"}),
        "y": ("time", data["y"], {"units": "m", "long_name": "Journal centre y as measured (sensor frame, up)"}),
    }
    if "speed" in data:
        variables["speed"] = ("time", data["speed"], {"units": "rad/s", "long_name": "Rotor speed as measured"})
    ds = xr.Dataset(variables, coords=coords)
    ds.attrs.update({k: v for k, v in meta.items() if k not in ("source_file", "sampling_rate_Hz")})
    ds.attrs["source_file"] = name
    ds.attrs["sampling_rate_Hz"] = rate
    return ds
