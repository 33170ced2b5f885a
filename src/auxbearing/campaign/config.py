"""A campaign file: a machine plus a ``[campaign]`` table of uncertain inputs, checked before any work.

The file holds the tables of a machine TOML file (``[machine]``, ``[rotor]``, ``[[touchdown]]``,
``[drop]``), or ``machine = "<catalogue name or file>"`` in ``[campaign]`` with any of those tables
laid over it (``[drop] duration = "20 ms"`` shortens every run), and::

    [campaign]
    sampler = "sobol"        # sobol, lhs, random (scipy.stats.qmc) or saltelli (SALib, for Sobol indices)
    samples = 256            # rows of the design; for saltelli the base count N (N (D + 2) runs)
    seed = 1
    analysis = "drop"        # or "coastdown"
    [[campaign.input]]
    key = "rotor.unbalance_phase"           # rotor.<key>, drop.<key>, touchdown.<plane>.<key>, touchdown.*.<key>
                                            # (and the keys of any other parameter table, e.g. coastdown.<key>)
    distribution = "uniform"                # uniform, normal, lognormal, truncated_normal or list
    low = "0 deg"
    high = "360 deg"

Every mistake is one :class:`~auxbearing.common.errors.InputError` line naming the key: an unknown table or
key, a dotted key that names nothing, a distribution with impossible parameters, a distribution whose
bounded support breaks the input's rule, or a central sample that is no valid machine.
"""

from __future__ import annotations

import copy
import hashlib
import json
import math
from dataclasses import dataclass, field
from pathlib import Path

from auxbearing.campaign.distributions import Distribution, distribution_from_table, share_outside_rule
from auxbearing.common.errors import InputError
from auxbearing.common.io import to_jsonable
from auxbearing.common.params import Param, did_you_mean, si_unit, unknown
from auxbearing.machine.check import MACHINE_FILE_TABLES
from auxbearing.machine.combinations import FACE_KEYS, MOUNT_KEYS
from auxbearing.machine.params import TABLES, TOUCHDOWN_TEXT

SAMPLERS = ("sobol", "lhs", "random", "saltelli")
ANALYSES = ("drop", "coastdown")
#: Tables of a machine file: [machine] and one per parameter table (rotor, touchdown, drop, ...).
MACHINE_TABLES = ("machine", *TABLES)
#: The keys of ``[campaign]``: default and meaning (``docs/machine_file.md`` is made from this table).
CAMPAIGN_KEY_HELP: dict[str, tuple[str, str]] = {
    "machine": ("this file's machine tables", "A catalogue machine or a machine file (relative to this file); the "
                "machine tables of this file are laid over it"),
    "sampler": ("`sobol`", "Design of the samples: `sobol`, `lhs`, `random` (scipy.stats.qmc) or `saltelli` "
                "(SALib, for Sobol' indices)"),
    "samples": ("required", "Rows of the design (a whole number); for `saltelli` the base count N, which gives "
                "N (D + 2) runs for D inputs"),
    "seed": ("`0`", "Seed of the design (a whole number): the same seed gives the same samples"),
    "analysis": ("`drop`", "What each sample runs: `drop`, or `coastdown` (the drop to standstill with heat and "
                 "life)"),
    "input": ("required", "One `[[campaign.input]]` table per uncertain input (below)"),
    "batch_size": ("derived", "Samples per task and per store write (a whole number); default about 64 tasks, "
                   "8-32 samples each"),
    "required_s0": ("`1`", "Static safety factor the statistics count P(s0 < required) against (ISO 76: 1 loads a "
                    "contact to 4200 MPa)"),
    "second_order": ("`false`", "With `saltelli`: second-order Sobol' indices too (N (2 D + 2) runs)"),
    "whirl_map": ("the first two inputs", "Two input keys for the whirl map of `campaign-report`"),
}
CAMPAIGN_KEYS = tuple(CAMPAIGN_KEY_HELP)
#: Required static safety factor when the file gives none: s0 = 1 is where the peak ball stress reaches
#: ISO 76's 4200 MPa reference for ball bearings, where the permanent set is 1e-4 of the ball diameter (ISO 76:2006).
DEFAULT_REQUIRED_S0 = 1.0
#: Most runs one campaign may hold (a guard against a typo such as samples = 1e9).
MAX_RUNS = 10_000_000
#: A batch is sized so that a campaign has about this many tasks (load balance and progress) ...
TARGET_BATCHES = 64
#: ... holds at least this many samples once the campaign has 16 batches of them (a store write costs
#: ~50-80 ms of the client's time, which should stay small against a batch's drops) ...
MIN_BATCH = 8
#: ... and at most this many (a lost worker loses little). The size depends on the campaign only, not on
#: the cluster, so a store can be resumed anywhere.
MAX_BATCH = 32
#: An unbounded distribution that puts more than this share of its samples outside the input's rule
#: is reported in the campaign's notes (those samples become ``invalid_input`` records).
OUTSIDE_NOTE = 1e-6


@dataclass(frozen=True)
class CampaignInput:
    """One uncertain input: the dotted key, where it lives in the machine tables, its row and distribution."""

    key: str
    section: str  #: a machine file's table: "rotor", "drop", "touchdown", "coastdown", ...
    name: str  #: key in the table
    planes: tuple[int, ...]  #: planes it sets (touchdown only; ``touchdown.*`` sets them all)
    param: Param
    distribution: Distribution

    @property
    def unit(self) -> str:
        """SI unit of the values."""
        return si_unit(self.param.dimension)


@dataclass(frozen=True)
class Campaign:
    """A checked campaign: machine tables, design settings and inputs (SI)."""

    name: str
    tables: dict  #: the machine's TOML tables (values with units), overlays applied
    base: str | None  #: folder for relative bearing files of the machine tables
    sampler: str
    samples: int
    seed: int
    analysis: str
    inputs: tuple[CampaignInput, ...]
    batch_size: int
    plane_names: tuple[str, ...]
    second_order: bool = False
    required_s0: float = DEFAULT_REQUIRED_S0
    whirl_map: tuple[str, str] | None = None
    notes: tuple[str, ...] = field(default=(), compare=False)
    #: (as written, content hash) of each file the tables name, taken when the campaign file was read: the
    #: campaign is what the files held then, whatever happens to them while it runs
    files: tuple[tuple[str, str], ...] = ()

    @property
    def runs(self) -> int:
        """Rows of the design: ``samples``, or N (D + 2) (N (2D + 2) with second order) for saltelli."""
        if self.sampler != "saltelli":
            return self.samples
        d = len(self.inputs)
        return self.samples * ((2 * d + 2) if self.second_order else (d + 2))

    @property
    def keys(self) -> tuple[str, ...]:
        """Dotted keys of the inputs."""
        return tuple(i.key for i in self.inputs)

    def describe(self) -> dict:
        """Everything that fixes the samples and their results (JSON-able, SI)."""
        return {"name": self.name, "tables": self.tables, "files": self.named_files(), "base": self.base,
                "sampler": self.sampler,
                "samples": self.samples, "runs": self.runs, "seed": self.seed, "analysis": self.analysis,
                "second_order": self.second_order, "batch_size": self.batch_size,
                "inputs": [{"key": i.key, "unit": i.unit, **i.distribution.describe()} for i in self.inputs]}

    def named_files(self) -> dict[str, str]:
        """The files the machine tables name (bearing files, a rotor's matrices): as written -> content hash."""
        return dict(self.files)

    def fingerprint(self) -> str:
        """A hash of :meth:`describe` but the name and folder: a store holds results of one fingerprint.

        The file's name and folder are left out, so a campaign file that is renamed or moved (with any
        bearing files it names) still finds its store; the files the tables name count by their contents, so
        an edited bearing file is another campaign, wherever it lies.
        """
        files = self.named_files()
        fixed = {k: v for k, v in self.describe().items() if k not in ("name", "base")}
        fixed["tables"] = _swap_strings(fixed["tables"], files)
        # through the shared encoder, as the store holds the description: no bare Infinity, numpy numbers as numbers
        text = json.dumps(to_jsonable(fixed), sort_keys=True, default=str, allow_nan=False)
        return hashlib.sha256(text.encode()).hexdigest()[:16]


def _map_strings(value, change):
    """``value`` with ``change`` applied to every string in it (tables of tables and lists walked)."""
    if isinstance(value, dict):
        return {k: _map_strings(v, change) for k, v in value.items()}
    if isinstance(value, list):
        return [_map_strings(v, change) for v in value]
    return change(value) if isinstance(value, str) else value


def _named_file(text: str, base) -> Path | None:
    """The existing file ``text`` names (absolute, or relative to ``base``), or None."""
    if not text.strip() or "\n" in text:
        return None
    path = Path(text.strip()).expanduser()
    if not path.is_absolute():
        if base is None:
            return None
        path = Path(base) / path
    try:
        return path if path.is_file() else None
    except OSError:  # a name too long for a path, say
        return None


def _files_in(tables, base: str | None) -> dict[str, Path]:
    """Every string in ``tables`` that names an existing file (absolute, or relative to ``base``)."""
    found: dict[str, Path] = {}

    def note(text: str) -> str:
        path = _named_file(text, base)
        if path is not None:
            found[text] = path
        return text

    _map_strings(tables, note)
    return found


def named_file_hashes(tables: dict, base) -> dict[str, str]:
    """Each file the tables name (:func:`_files_in`): as written -> a hash of its contents."""
    return {text: _file_hash(path) for text, path in _files_in(tables, None if base is None else str(base)).items()}


def _file_hash(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()[:16]


def _swap_strings(value, swaps: dict[str, str]):
    """``value`` with every string in ``swaps`` replaced by its content hash."""
    return _map_strings(value, lambda text: f"file {swaps[text]}" if text in swaps else text)


def read_campaign(path: str | Path) -> Campaign:
    """A campaign from a TOML file (module docstring)."""
    from auxbearing.common.io import read_toml

    path = Path(path)
    return campaign_from_mapping(read_toml(path), path.stem, path.parent)


def _integer(table: dict, key: str, default: int | None, low: int, high: int) -> int:
    value = table.get(key, default)
    if value is None:
        raise InputError(f"campaign.{key}: missing; give a whole number")
    if isinstance(value, float) and value.is_integer():
        value = int(value)
    if isinstance(value, bool):  # quoted as the file spells it
        raise InputError(f"campaign.{key} = {str(value).lower()}: must be a whole number from {low} to {high}")
    if not isinstance(value, int) or not low <= value <= high:
        raise InputError.for_field(f"campaign.{key}", value, f"must be a whole number from {low} to {high}")
    return value


def _machine_tables(data: dict, head: dict, base: Path | None) -> tuple[dict, Path | None]:
    """The machine's raw tables: ``campaign.machine`` (catalogue or file) with the file's tables laid over."""
    from auxbearing.common.io import read_toml
    from auxbearing.machine.files import machine_document, machine_names

    tables: dict = {}
    machine_base = base
    spec = head.get("machine")
    if spec is not None:
        if not isinstance(spec, str) or not spec.strip():
            raise InputError.for_field("campaign.machine", spec, "must be a catalogue name or a machine file")
        spec = spec.strip()
        if spec in machine_names():
            # its folder too: the files a catalogue machine names (an elastic rotor's matrices) sit beside it
            tables, _, machine_base = machine_document(spec)
        else:
            path = Path(spec) if base is None or Path(spec).is_absolute() else base / spec
            if not path.is_file():
                raise InputError.for_field("campaign.machine", spec, "neither a file nor a catalogue machine ("
                                           + ", ".join(machine_names()) + ")")
            tables = read_toml(path, "campaign.machine")
            machine_base = path.parent
        tables.setdefault("machine", {}).setdefault("name", spec)
    here = base  # the campaign file's folder: the files its own tables name lie relative to it
    for key in MACHINE_TABLES:
        if key not in data:
            continue
        over = _anchored(data[key], here) if here is not None and machine_base != here else data[key]
        if key == "touchdown":
            if not isinstance(over, list):
                raise InputError.for_field("touchdown", over, "give [[touchdown]] tables")
            planes = list(tables.get("touchdown", []))
            for k, table in enumerate(over):
                planes[k:k + 1] = [{**(planes[k] if k < len(planes) else {}), **table}]
            tables["touchdown"] = planes
        elif isinstance(over, dict):
            tables[key] = {**tables.get(key, {}), **over}
        else:
            raise InputError.for_field(key, over, "must be a table")
    if not tables:
        raise InputError("campaign.machine: missing; give machine = NAME (or a file) or the machine tables "
                         "[rotor], [[touchdown]] in the campaign file")
    return tables, machine_base


def _anchored(value, folder: Path):
    """``value`` with each relative name of a file beside the campaign file made absolute (tables walked).

    The machine's own files are read relative to the machine's folder; a bearing file the campaign file names is
    the user's, beside the campaign file.
    """
    def anchor(text: str) -> str:
        if Path(text.strip()).expanduser().is_absolute():
            return text
        path = _named_file(text, folder)
        return text if path is None else str(path.resolve())

    return _map_strings(value, anchor)


def resolve_key(key: object, n_planes: int, where: str) -> tuple[str, str, tuple[int, ...], Param]:
    """Section, name, planes and parameter row of a dotted key; a one-line error when it names nothing.

    >>> resolve_key("touchdown.0.sliding_friction", 1, "campaign.input.0")[:3]
    ('touchdown', 'sliding_friction', (0,))
    >>> resolve_key("touchdown.1.sliding_friction", 1, "campaign.input.0")
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: campaign.input.0.key = 'touchdown.1.sliding_friction': names nothing: \
the machine has 1 touchdown plane (touchdown.0)
    """
    if not isinstance(key, str) or not key.strip():
        raise InputError.for_field(where + ".key", key, "give a dotted key such as 'rotor.unbalance_phase'")
    parts = key.strip().split(".")
    field_ = where + ".key"
    section = parts[0]
    if section not in TABLES:
        raise InputError.for_field(field_, key, "names nothing a campaign can vary; keys start with "
                                   + ", ".join(f"{s}.<plane>." if s == "touchdown" else f"{s}." for s in TABLES)
                                   + did_you_mean(section, TABLES))
    depth = 3 if section == "touchdown" else 2
    if len(parts) != depth or not all(parts):
        shape = "touchdown.<plane>.<key>" if section == "touchdown" else f"{section}.<key>"
        raise InputError.for_field(field_, key, f"names nothing: write {shape}")
    name = parts[-1]
    if section == "touchdown" and name in TOUCHDOWN_TEXT:
        raise InputError.for_field(field_, key, "names a text, not a quantity; a campaign varies numbers")
    if name not in TABLES[section]:
        raise InputError.for_field(field_, key, f"unknown key; allowed keys of [{section}]: "
                                   + ", ".join(TABLES[section]) + did_you_mean(name, TABLES[section]))
    planes: tuple[int, ...] = ()
    if section == "touchdown":
        index = parts[1]
        listed = ", ".join(f"touchdown.{k}" for k in range(n_planes))
        count = f"{n_planes} touchdown plane{'s' if n_planes != 1 else ''}"
        if index == "*":
            planes = tuple(range(n_planes))
        elif index.isdigit() and int(index) < n_planes:
            planes = (int(index),)
        else:
            raise InputError.for_field(field_, key, f"names nothing: the machine has {count} ({listed})")
    return section, name, planes, TABLES[section][name]


def _inputs(head: dict, n_planes: int) -> tuple[tuple[CampaignInput, ...], list[str]]:
    tables = head.get("input")
    if not isinstance(tables, list) or not tables or not all(isinstance(t, dict) for t in tables):
        raise InputError.for_field("campaign.input", tables, "give one [[campaign.input]] table per uncertain input")
    inputs, notes, seen = [], [], {}
    for i, table in enumerate(tables):
        where = f"campaign.input.{i}"
        section, name, planes, param = resolve_key(table.get("key"), n_planes, where)
        dist = distribution_from_table(table, param, where)
        key = table["key"].strip()
        if param.rule == "count":
            # a continuous draw of a whole number (a step budget, a count of drops) breaks its rule in every
            # sample: each would be an invalid_input record and the campaign would say nothing of the machine
            # (a list's values are each checked against the rule as they are read)
            if dist.kind != "list":
                raise InputError.for_field(where + ".distribution", table.get("distribution"), f"{key} is a whole "
                                           "number: give distribution = \"list\" with its values")
        for k in planes or (None,):
            slot = (section, k, name)
            if slot in seen:
                raise InputError.for_field(where + ".key", key, f"sets the same value as {seen[slot]}")
            seen[slot] = key
        share = share_outside_rule(dist, param)
        if share > OUTSIDE_NOTE:
            notes.append(f"{key}: {100.0 * share:.3g} % of the samples fall outside its rule ({param.rule}); they are "
                         "recorded as invalid_input (a truncated_normal keeps them inside)")
        inputs.append(CampaignInput(key, section, name, planes, param, dist))
    return tuple(inputs), notes



def _check_inputs_act(inputs: tuple[CampaignInput, ...], machine, analysis: str = "drop") -> None:
    """Refuse an input that would change nothing.

    A mount value on a rigid plane, a face value without a catch, a coast-down value in a campaign of drops.
    """
    for i, inp in enumerate(inputs):
        if inp.section == "coastdown" and analysis != "coastdown":
            raise InputError.for_field(f"campaign.input.{i}.key", inp.key, f"names nothing here: a campaign of "
                                       f"{analysis}s runs no coast-down (give campaign.analysis = \"coastdown\")")
    varied = {(k, i.name) for i in inputs for k in i.planes}
    for inp in inputs:
        for k in inp.planes:
            plane = machine.planes[k]
            if inp.name in MOUNT_KEYS and plane.mount is None and (k, "mount_stiffness") not in varied:
                raise InputError.for_field(f"campaign.input.{inputs.index(inp)}.key", inp.key,
                                           f"names nothing: plane {k} ({plane.name}) has no mount (give "
                                           f"touchdown.{k}.mount_stiffness), so the value would change nothing")
            if inp.name in FACE_KEYS and not plane.catches_axially and (k, "axial_clearance") not in varied:
                raise InputError.for_field(f"campaign.input.{inputs.index(inp)}.key", inp.key,
                                           f"names nothing: plane {k} ({plane.name}) does not catch axially (give "
                                           f"touchdown.{k}.axial_clearance), so the value would change nothing")


def apply_sample(tables: dict, inputs: tuple[CampaignInput, ...], values, as_quantity: bool = False) -> dict:
    """The machine tables with each input set to its sampled SI value (as ``"<value> <SI unit>"`` text).

    With ``as_quantity`` the values go in as unit-library quantities (the same conversion and checks,
    without parsing text: what the workers use).

    >>> from auxbearing.machine.params import TABLES
    >>> from auxbearing.campaign.distributions import Distribution
    >>> phase = CampaignInput("rotor.unbalance_phase", "rotor", "unbalance_phase", (),
    ...                       TABLES["rotor"]["unbalance_phase"], Distribution("uniform", (0.0, 6.0)))
    >>> apply_sample({"rotor": {"mass": "1 kg"}}, (phase,), [1.5])["rotor"]
    {'mass': '1 kg', 'unbalance_phase': '1.5 rad'}
    """
    # copies of the tables the inputs write into; the caller's tables stay as they were
    out = {key: dict(value) if isinstance(value, dict) else value for key, value in tables.items()}
    for inp in inputs:
        if inp.section != "touchdown":
            out.setdefault(inp.section, {})
    out["touchdown"] = [dict(t) for t in tables.get("touchdown", [])]
    if as_quantity:
        from auxbearing.common.units import Quantity
    for inp, value in zip(inputs, values, strict=True):
        value = float(value)
        unit = inp.unit
        if not unit or inp.param.dimension == "dimensionless":
            text = value
        else:
            text = Quantity(value, unit) if as_quantity else f"{value!r} {unit}"
        for target in ([out["touchdown"][k] for k in inp.planes] if inp.section == "touchdown"
                       else [out[inp.section]]):
            target[inp.name] = text
    return out


def campaign_from_mapping(data: dict, name: str = "campaign", base: Path | None = None, *,
                          check_machine: bool = True) -> Campaign:
    """A checked :class:`Campaign` from the tables of a campaign file (module docstring).

    The campaign's machine (the file's machine tables laid over ``campaign.machine``) is checked whole, as
    every command checks a machine file (:func:`auxbearing.machine.check.check_machine_document`), with the
    file's own ``[criteria]``, ``[verify]`` and ``[[candidate]]`` tables. ``check_machine=False`` is for a
    machine file already checked that way (:func:`auxbearing.cli.common.read_machine_file`), whose
    ``[campaign]`` table is then checked here alone.
    """
    from auxbearing.machine.check import check_machine_document, check_tables
    from auxbearing.machine.model import machine_from_mapping

    check_tables(data, MACHINE_FILE_TABLES)
    head = data.get("campaign")
    if not isinstance(head, dict):
        raise InputError("campaign: missing; a campaign file needs a [campaign] table")
    for key in head:
        if key not in CAMPAIGN_KEYS:
            raise unknown(f"campaign.{key}", head[key], key, CAMPAIGN_KEYS)
    sampler = str(head.get("sampler", "sobol")).strip().lower()
    if sampler not in SAMPLERS:
        raise InputError.for_field("campaign.sampler", head.get("sampler"), "use one of " + ", ".join(SAMPLERS))
    samples = _integer(head, "samples", None, 1, MAX_RUNS)
    seed = _integer(head, "seed", 0, 0, 2**63 - 1)
    analysis = str(head.get("analysis", "drop")).strip().lower()
    if analysis not in ANALYSES:
        raise InputError.for_field("campaign.analysis", head.get("analysis"), "use one of " + ", ".join(ANALYSES))
    second_order = head.get("second_order", False)
    if not isinstance(second_order, bool):
        raise InputError.for_field("campaign.second_order", second_order, "must be true or false")
    if second_order and sampler != "saltelli":
        raise InputError.for_field("campaign.second_order", second_order, "second-order Sobol' indices need "
                                   f"sampler = \"saltelli\" (this campaign's is {sampler!r})")
    required = head.get("required_s0", DEFAULT_REQUIRED_S0)
    if isinstance(required, bool) or not isinstance(required, (int, float)) or not 0.0 < required < math.inf:
        raise InputError.for_field("campaign.required_s0", required, "must be a number > 0")
    tables, base = _machine_tables(data, head, base)
    if check_machine:
        document = {key: value for key, value in tables.items() if key != "campaign"}
        document.update({key: data[key] for key in ("criteria", "verify", "candidate") if key in data})
        machine = check_machine_document(document, name, base)
    else:
        machine = machine_from_mapping(tables, name, base)
    inputs, notes = _inputs(head, len(machine.planes))
    _check_inputs_act(inputs, machine, analysis)
    whirl_map = head.get("whirl_map")
    if whirl_map is not None:
        keys = [i.key for i in inputs]
        if not (isinstance(whirl_map, list) and len(whirl_map) == 2 and all(k in keys for k in whirl_map)
                and whirl_map[0] != whirl_map[1]):  # a map of one input against itself is a line
            raise InputError.for_field("campaign.whirl_map", whirl_map, "give two different input keys: "
                                       + ", ".join(keys))
        whirl_map = (whirl_map[0], whirl_map[1])
    central = apply_sample(tables, inputs, [i.distribution.median() for i in inputs])
    try:
        machine_from_mapping(copy.deepcopy(central), name, base)
    except InputError as err:
        raise InputError(f"campaign: the central sample (every input at its median) is no valid machine: {err}") \
            from None
    runs = samples * ((2 * len(inputs) + 2) if second_order else (len(inputs) + 2)) if sampler == "saltelli" \
        else samples
    if runs > MAX_RUNS:
        raise InputError.for_field("campaign.samples", samples, f"gives {runs} runs, more than {MAX_RUNS}")
    default_batch = min(MAX_BATCH, max(math.ceil(runs / TARGET_BATCHES), min(MIN_BATCH, math.ceil(runs / 16))))
    batch = _integer(head, "batch_size", default_batch, 1, MAX_RUNS)
    return Campaign(name=machine.name if name == "campaign" else name, tables=tables,
                    base=None if base is None else str(Path(base).resolve()), sampler=sampler, samples=samples,
                    seed=seed, analysis=analysis, inputs=inputs, batch_size=batch,
                    plane_names=tuple(p.name for p in machine.planes), second_order=second_order,
                    required_s0=float(required), whirl_map=whirl_map, notes=tuple(notes),
                    files=tuple(sorted(named_file_hashes(tables, base).items())))
