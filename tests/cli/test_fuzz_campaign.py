"""Fuzz table (issue 20): campaign files on ``campaign`` and campaign stores on ``campaign-report``.

A campaign file is a machine file with a ``[campaign]`` table (or ``campaign.machine`` naming one): it is
checked whole, as its machine is, before a cluster starts or anything is written. A store that is not
what ``campaign`` wrote (metadata that is not JSON, a chunk cut short, an array missing) is one line
naming the store; a store that another campaign is writing (its lock held by a live process) is refused
in one line naming the store, without a hidden scratch folder's name. Cases run as in
``test_fuzz_commands.py``; the lock's own fault tests (stale locks, two real writers) are in
``tests/unit/test_campaign_store.py`` and ``tests/cli/test_hard_conditions.py``.
"""

from __future__ import annotations

import os
import socket
import tomllib
from pathlib import Path

import pytest

from tests.cli.test_fuzz_harness import case, check_case
from tests.cli.test_fuzz_machine import machine, nested

#: the quick loop leaves this module to `make test` (its share of the loop's time against what it guards)
pytestmark = pytest.mark.slow

CAMPAIGN = """[campaign]
machine = "paper_rig"
samples = 4
seed = 1
batch_size = 2

[[campaign.input]]
key = "rotor.unbalance_phase"
distribution = "uniform"
low = "0 deg"
high = "360 deg"

[drop]
duration = "1 ms"
"""


def _campaign(old: str, new: str) -> str:
    assert old in CAMPAIGN
    return CAMPAIGN.replace(old, new)


#: Stores made once per process, by whether they hold records: each case copies one (making one costs ~0.4 s).
_MADE: dict[bool, Path] = {}


def _make(path: Path, records: bool) -> None:
    import numpy as np

    from auxbearing.campaign.config import campaign_from_mapping
    from auxbearing.campaign.evaluate import output_variables
    from auxbearing.campaign.sampling import design
    from auxbearing.campaign.store import create_store, write_batch

    c = campaign_from_mapping(tomllib.loads(CAMPAIGN), "c")
    create_store(path, c, design(c))
    if records:
        sample, plane = output_variables(c.analysis)
        arrays = {}
        for name, (dtype, *_) in {**sample, **plane}.items():
            shape = (2, len(c.plane_names)) if name in plane else (2,)
            arrays[name] = np.full(shape, "" if dtype.startswith("<U") else 1, dtype=dtype)
        write_batch(path, 0, arrays)


def _store(damage=None, records: bool = True):
    """A writer of a campaign store of :data:`CAMPAIGN` (one batch of records), then ``damage(path)``."""

    def write(path: Path) -> None:
        import atexit
        import shutil
        import tempfile

        if records not in _MADE:
            folder = Path(tempfile.mkdtemp(prefix="fuzz-store-"))
            atexit.register(shutil.rmtree, folder, True)  # the template store outlives each test, not the run
            _make(folder / "s.zarr", records)
            _MADE[records] = folder / "s.zarr"
        shutil.copytree(_MADE[records], path)
        if damage is not None:
            damage(path)

    return write


def _replace(relative: str, content: bytes):
    def damage(path: Path) -> None:
        (path / relative).write_bytes(content)

    return damage


def _truncate(variable: str):
    def damage(path: Path) -> None:
        chunk = next(p for p in sorted((path / variable).iterdir()) if not p.name.startswith("."))
        data = chunk.read_bytes()
        chunk.write_bytes(data[: len(data) // 2])

    return damage


def _remove(variable: str):
    def damage(path: Path) -> None:
        import shutil

        shutil.rmtree(path / variable)

    return damage


def _locked_by(pid_of) -> callable:
    """A lock file of the store held by the process ``pid_of()`` on this host (written as campaign writes it)."""

    def damage(path: Path) -> None:
        lock = path.parent / f".{path.name}.lock"
        lock.write_text(f"{socket.gethostname()} {pid_of()} 2024-01-01T00:00:00+00:00\n")

    return damage


FILES = [
    case("camp-key-typo", "campaign --config c.toml --out s.zarr", "campaign.samplez", "samples",
         files={"c.toml": _campaign("samples = 4", "samplez = 4")}),
    case("camp-table-typo", "campaign --config c.toml --out s.zarr", "[campain]", "campaign",
         files={"c.toml": CAMPAIGN + "[campain]\nx = 1\n"}),
    case("camp-input-key-typo", "campaign --config c.toml --out s.zarr", "rotor.unbalance_phse", "unbalance_phase",
         files={"c.toml": _campaign('"rotor.unbalance_phase"', '"rotor.unbalance_phse"')}),
    case("camp-nested-arrays", "campaign --config c.toml --out s.zarr", "c.toml", "nested",
         files={"c.toml": CAMPAIGN.replace("seed = 1\n", "seed = 1\n" + nested(20000))}),
    case("camp-nested-inline", "campaign --config c.toml --out s.zarr", "c.toml", "nested",
         files={"c.toml": CAMPAIGN.replace("seed = 1\n", "seed = 1\n" + nested(20000, "{"))}),
    case("camp-nested-moderate", "campaign --config c.toml --out s.zarr", "c.toml", "nested",
         files={"c.toml": CAMPAIGN.replace("seed = 1\n", "seed = 1\n" + nested(300, key="whirl_map"))}),
    case("camp-machine-file-nested", "campaign --config c.toml --out s.zarr", "m.toml", "nested",
         files={"c.toml": _campaign('"paper_rig"', '"m.toml"'), "m.toml": machine(rotor=nested(20000))}),
    case("camp-machine-criteria", "campaign --config c.toml --out s.zarr", "criteria.min_s0", "-1",
         files={"c.toml": _campaign('"paper_rig"', '"m.toml"'),
                "m.toml": machine(tables="[criteria]\nmin_s0 = -1\n")},
         note="the campaign's machine is one document: its [criteria] is checked too"),
    case("camp-machine-candidate", "campaign --config c.toml --out s.zarr", "candidate.0", "bore",
         files={"c.toml": _campaign('"paper_rig"', '"m.toml"'),
                "m.toml": machine(tables='[[candidate]]\nbearing = "QJ208"\n')}),
    case("camp-own-criteria", "campaign --config c.toml --out s.zarr", "criteria.min_s00", "min_s0",
         files={"c.toml": CAMPAIGN + "[criteria]\nmin_s00 = 2\n"}),
    case("camp-start-outside", "campaign --config c.toml --out s.zarr", "rotor.start_x", "radial_clearance",
         files={"c.toml": CAMPAIGN + '[rotor]\nstart_x = "1 mm"\n'}),
    case("camp-mount-without-stiffness", "campaign --config c.toml --out s.zarr", "touchdown.0.mount_damping",
         "mount_stiffness", files={"c.toml": CAMPAIGN + '[[touchdown]]\nmount_damping = "100 N*s/m"\n'}),
    case("camp-coast-temperature", "campaign --config c.toml --out s.zarr", "coastdown.max_temperature",
         "coastdown.ambient_temperature", files={"c.toml": CAMPAIGN + '[coastdown]\nmax_temperature = "0 degC"\n'}),
    case("camp-coast-speed-step", "campaign --config c.toml --out s.zarr", "coastdown.speed_step",
         files={"c.toml": CAMPAIGN + "[coastdown]\nspeed_step = 0\n"}),
    case("camp-samples-zero", "campaign --config c.toml --out s.zarr", "campaign.samples", "0",
         files={"c.toml": _campaign("samples = 4", "samples = 0")}),
    case("camp-samples-huge", "campaign --config c.toml --out s.zarr", "campaign.samples",
         files={"c.toml": _campaign("samples = 4", "samples = 100000000000")}),
    case("camp-batch-zero", "campaign --config c.toml --out s.zarr", "campaign.batch_size", "0",
         files={"c.toml": _campaign("batch_size = 2", "batch_size = 0")}),
    case("camp-input-low-above-high", "campaign --config c.toml --out s.zarr", "campaign.input.0",
         files={"c.toml": _campaign('low = "0 deg"', 'low = "400 deg"')}),
    case("camp-input-wrong-unit", "campaign --config c.toml --out s.zarr", "campaign.input.0", "0 mm",
         files={"c.toml": _campaign('low = "0 deg"', 'low = "0 mm"')}),
    case("camp-whirl-map-unknown", "campaign --config c.toml --out s.zarr", "campaign.whirl_map",
         files={"c.toml": _campaign("seed = 1\n", 'seed = 1\nwhirl_map = ["a", "b"]\n')}),
    case("camp-analysis", "campaign --config c.toml --out s.zarr", "campaign.analysis", "static",
         files={"c.toml": _campaign("seed = 1\n", 'seed = 1\nanalysis = "static"\n')}),
    case("camp-machine-missing", "campaign --config c.toml --out s.zarr", "campaign.machine", "nomachine",
         files={"c.toml": _campaign('"paper_rig"', '"nomachine"')}),
    case("camp-binary", "campaign --config c.toml --out s.zarr", "c.toml", files={"c.toml": bytes(range(256)) * 4}),
]

STORES = [
    case("store-attrs-not-json", "campaign-report s.zarr --out r", "s.zarr",
         files={"s.zarr": _store(_replace(".zattrs", b"{not json"))}, note="issue: a JSONDecodeError traceback"),
    case("store-attrs-list", "campaign-report s.zarr --out r", "s.zarr",
         files={"s.zarr": _store(_replace(".zattrs", b"[1, 2]"))}),
    case("store-attrs-binary", "campaign-report s.zarr --out r", "s.zarr",
         files={"s.zarr": _store(_replace(".zattrs", bytes(range(256))))}),
    case("store-chunk-truncated", "campaign-report s.zarr --out r", "s.zarr",
         files={"s.zarr": _store(_truncate("peak_ball_stress"))}, note="issue: a decompression traceback"),
    case("store-verdict-truncated", "campaign-report s.zarr --out r", "s.zarr",
         files={"s.zarr": _store(_truncate("verdict"))}),
    case("store-array-missing", "campaign-report s.zarr --out r", "s.zarr",
         files={"s.zarr": _store(_remove("verdict"))}),
    case("store-array-meta-not-json", "campaign-report s.zarr --out r", "s.zarr",
         files={"s.zarr": _store(_replace("completed/.zarray", b"{"))}),
    case("store-group-missing", "campaign-report s.zarr --out r", "s.zarr",
         files={"s.zarr": _store(lambda p: (p / ".zgroup").unlink())}),
    case("store-resume-attrs-not-json", "campaign --config c.toml --out s.zarr", "s.zarr",
         files={"c.toml": CAMPAIGN, "s.zarr": _store(_replace(".zattrs", b"{not json"))}),
    case("store-resume-completed-truncated", "campaign --config c.toml --out s.zarr", "s.zarr",
         files={"c.toml": CAMPAIGN, "s.zarr": _store(_truncate("completed"))}),
    case("store-locked-by-live-process", "campaign --config c.toml --out s.zarr", "s.zarr", "another campaign",
         files={"c.toml": CAMPAIGN, "s.zarr": _store(_locked_by(os.getpid), records=False)},
         avoid=(".partial", ".s.zarr.")),
    case("store-fresh-locked-by-live-process", "campaign --config c.toml --out s.zarr", "s.zarr",
         "another campaign", files={"c.toml": CAMPAIGN, ".s.zarr.lock": lambda p: p.write_text(
             f"{socket.gethostname()} {os.getpid()} 2024-01-01T00:00:00+00:00\n")},
         avoid=(".partial", ".s.zarr.")),

    case("store-whirl-map-unknown", "campaign-report s.zarr --out r --whirl-map a b", "--whirl-map", "a",
         files={"s.zarr": _store()}),
]

#: Legal extremes of a campaign (a local cluster starts: slow) and a report of a sound store (figures: slow).
LEGAL = [
    case("store-good-report", "campaign-report s.zarr --out r --json", files={"s.zarr": _store()}, expect="ok"),
    case("camp-legal-one-sample", "campaign --config c.toml --out s.zarr --workers 1 --quiet --json",
         files={"c.toml": _campaign("samples = 4", "samples = 1")}, expect="verdict"),
    case("camp-legal-all-invalid", "campaign --config c.toml --out s.zarr --workers 1 --quiet --json",
         files={"c.toml": CAMPAIGN + '[[campaign.input]]\nkey = "touchdown.0.sliding_friction"\n'
                                     'distribution = "uniform"\nlow = 1.5\nhigh = 2\n'}, expect="verdict"),
]

CASES = [*FILES, *STORES, *LEGAL]


def test_ids_are_unique():
    from tests.cli.test_fuzz_machine import test_ids_are_unique as machine_ids

    machine_ids()
    from tests.cli.test_fuzz_machine import CASES as MACHINE

    ids = [c.id for c in [*CASES, *MACHINE]]
    assert len(ids) == len(set(ids))


@pytest.mark.parametrize("c", [pytest.param(c, marks=[pytest.mark.slow] if c in LEGAL else []) for c in CASES],
                         ids=[c.id for c in CASES])
def test_campaign_input(c, tmp_path):
    check_case(c, tmp_path)
