"""The touchdown cases a verification runs on one design (ISO 14839-5:2022's "simulation of the touchdown events").

* a drop at the maximum speed (the machine file's ``rotor.speed``);
* a drop at low speed (:data:`LOW_SPEED_FRACTION` of it, or ``verify.low_speed``): a slow rotor whirls and
  bounces differently;
* when the process pushes axially, the drop with that thrust reversed (a surge or a reversal): a
  single angular-contact bearing catches one direction only;
* the coast-down with heat from the maximum speed to standstill (``--quick``: its first
  :data:`QUICK_COASTDOWN` seconds);
* a small campaign over the drop conditions nobody controls (unbalance phase, friction, clearance
  within its tolerance) on Dask (:mod:`auxbearing.campaign`).
"""

from __future__ import annotations

import copy
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

from auxbearing.coastdown import CoastdownRun, run_coastdown
from auxbearing.drop import MachineRun, run_machine
from auxbearing.errors import InputError
from auxbearing.machine import Machine, machine_from_mapping
from auxbearing.params import Param, by_key, read_table

#: A drop at low speed runs at this fraction of the maximum (ours: the bottom of a typical operating range).
LOW_SPEED_FRACTION = 0.25
#: ``--quick``: the drops last at most this long [s], the coast-down is run for this long [s] and the
#: campaign has this many samples.
QUICK_DROP, QUICK_COASTDOWN, QUICK_SAMPLES = 0.05, 5.0, 8
#: Samples of the verification's campaign unless ``verify.campaign_samples`` says otherwise: a power of two
#: (Sobol' balance) whose whirl-free outcome shows P(backward whirl) within the default 5 % at 95 % confidence
#: (Wilson's bound for no events, 1.96^2 / (n + 1.96^2), is 0.029 at 128 and 0.057 at 64).
CAMPAIGN_SAMPLES = 128

VERIFY: tuple[Param, ...] = (
    Param("verify", "low_speed", "angular_speed", None, "rpm", "optional_positive",
          "Speed of the low-speed drop; default a quarter of rotor.speed", "ours"),
    Param("verify", "campaign_samples", "dimensionless", float(CAMPAIGN_SAMPLES), "", "count",
          "Samples of the verification's campaign",
          "ours: 128 whirl-free drops show P(backward whirl) <= 0.05 at 95 %"),
    Param("verify", "friction_spread", "dimensionless", 0.05, "", "unit_interval",
          "Half-width of the campaign's uniform spread of sliding friction about each plane's value",
          "ours: the literature spans 0.1-0.3"),
    Param("verify", "clearance_tolerance", "length", 1e-5, "um", "nonnegative",
          "Half-width of the campaign's uniform spread of each radial clearance (machining tolerance)", "ours"),
)
VERIFY_TABLE = by_key(VERIFY, "verify")


@dataclass
class Cases:
    """What one design did in every case."""

    machine: Machine
    drops: dict[str, MachineRun] = field(default_factory=dict)  #: case name -> run
    coastdown: CoastdownRun | None = None
    campaign: dict | None = None  #: statistics of :func:`auxbearing.campaign.statistics.campaign_statistics`
    campaign_store: str | None = None
    notes: list[str] = field(default_factory=list)
    tables: tuple[str, ...] = ()  #: the tables the machine file gives (to say where a value came from)
    #: why the coast-down stopped short of standstill without a finding (--quick, a budget); empty: it did not
    partial_coastdown: str = ""


def verify_settings(data: dict) -> dict:
    """The ``[verify]`` table in SI with defaults."""
    given = read_table(data.get("verify"), VERIFY_TABLE, "verify.")
    return {p.key: given.get(p.key, p.default) for p in VERIFY}


def variant(data: dict, name: str, base: Path | None, rotor: dict | None = None, drop: dict | None = None) -> Machine:
    """A machine from the file's tables with some ``[rotor]`` / ``[drop]`` values replaced (values with units)."""
    tables = copy.deepcopy(data)
    if rotor:
        tables.setdefault("rotor", {}).update(rotor)
    if drop:
        tables.setdefault("drop", {}).update(drop)
    return machine_from_mapping(tables, name, base).for_batch()  # a verdict's work is bounded by steps alone


def run_cases(data: dict, name: str, base: Path | None, quick: bool = False, samples: int | None = None,
              store: Path | None = None, workers: int | None = None, scheduler: str | None = None,
              required_s0: float = 1.0, progress: Callable[[str], None] | None = None) -> Cases:
    """Run every case of one design (module docstring); ``samples = 0`` skips the campaign."""
    def say(text: str) -> None:
        if progress is not None:
            progress(text)

    settings = verify_settings(data)
    machine = machine_from_mapping(data, name, base)
    drop = {}
    if quick:
        drop["duration"] = f"{float(min(machine.simulation.duration, QUICK_DROP))!r} s"
    cases = Cases(variant(data, name, base, drop=drop), tables=tuple(data))
    speed = machine.rotor.speed
    low = settings["low_speed"] if settings["low_speed"] is not None else LOW_SPEED_FRACTION * abs(speed)
    say("drop at the maximum speed")
    cases.drops["drop at the maximum speed"] = run_machine(cases.machine)
    say("drop at low speed")
    cases.drops["drop at low speed"] = run_machine(
        variant(data, name, base, rotor={"speed": f"{float(math.copysign(low, speed))!r} rad/s"}, drop=drop))
    if machine.rotor.axial_force != 0.0:
        say("drop with the process thrust reversed")
        cases.drops["drop with the thrust reversed"] = run_machine(
            variant(data, name, base, rotor={"axial_force": f"{float(-machine.rotor.axial_force)!r} N"}, drop=drop))
    first = cases.drops["drop at the maximum speed"].summary
    if first["verdict"] != "ok":
        cases.notes.append("the coast-down was not run: the drop at the maximum speed it starts from already left "
                           f"the model's range ({first['reason']})")
    elif quick:
        say("coast-down with heat")
        cases.coastdown = run_coastdown(cases.machine, until_stop=False,
                                        duration=min(QUICK_COASTDOWN, machine.coastdown.max_time))
        cases.notes.append(f"--quick: the coast-down ran for its first {QUICK_COASTDOWN:g} s only; temperatures, "
                           "clearances and life cover that part")
        if cases.coastdown.summary["coastdown_time_s"] is None:
            cases.partial_coastdown = "only the first part of the coast-down ran (--quick): run without --quick"
    else:
        say("coast-down with heat")
        cases.coastdown = run_coastdown(cases.machine)
        if cases.coastdown.summary["verdict"] in ("step_budget", "wall_time_budget"):
            cases.partial_coastdown = f"the coast-down reached a budget ({cases.coastdown.summary['reason']})"
    if samples is not None:
        n = samples
    elif quick:
        n = QUICK_SAMPLES
    else:
        n = int(settings["campaign_samples"])
    if n > 0:
        say(f"campaign of {n} drops")
        cases.campaign, cases.campaign_store = _campaign(data, name, base, cases.machine, settings, n, store,
                                                         workers, scheduler, required_s0, drop)
    return cases


def campaign_tables(data: dict, machine: Machine, settings: dict, samples: int, drop: dict) -> dict:
    """The verification's campaign over the uncontrolled drop conditions (module docstring)."""
    tables = copy.deepcopy(data)
    for key in ("criteria", "candidate", "verify", "campaign"):
        tables.pop(key, None)
    if drop:
        tables.setdefault("drop", {}).update(drop)
    inputs = [{"key": "rotor.unbalance_phase", "distribution": "uniform", "low": "0 deg", "high": "360 deg"}]
    spread = settings["friction_spread"]
    for k, plane in enumerate(machine.planes):
        mu = plane.sliding_friction
        inputs.append({"key": f"touchdown.{k}.sliding_friction", "distribution": "uniform",
                       "low": max(0.0, mu - spread), "high": min(1.0, mu + spread)})
        tol = settings["clearance_tolerance"]
        if tol > 0.0:
            s = plane.radial_clearance
            inputs.append({"key": f"touchdown.{k}.radial_clearance", "distribution": "uniform",
                           "low": f"{float(max(s - tol, 0.5 * s))!r} m", "high": f"{float(s + tol)!r} m"})
    sampler = "sobol" if samples & (samples - 1) == 0 else "lhs"  # Sobol' points balance at powers of two
    tables["campaign"] = {"sampler": sampler, "samples": samples, "seed": 1, "analysis": "drop", "input": inputs}
    return tables


def _campaign(data, name, base, machine, settings, samples, store, workers, scheduler, required_s0, drop):
    from auxbearing.campaign.config import campaign_from_mapping
    from auxbearing.campaign.run import run_campaign
    from auxbearing.campaign.statistics import campaign_statistics
    from auxbearing.campaign.store import load_results

    if store is None:
        raise InputError("verify: a campaign needs a store folder (--out)")
    campaign = campaign_from_mapping(campaign_tables(data, machine, settings, samples, drop), f"{name} campaign", base)
    run_campaign(campaign, store, scheduler=scheduler, workers=workers)
    stats = campaign_statistics(load_results(store), required_s0=required_s0)
    return stats, str(store)
