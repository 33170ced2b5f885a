"""The touchdown cases a verification runs on one design (ISO 14839-5:2022's "simulation of the touchdown events").

* a drop at the maximum speed (the machine file's ``rotor.speed``);
* a drop at low speed (:data:`LOW_SPEED_FRACTION` of it, or ``verify.low_speed``): a slow rotor whirls and
  bounces differently;
* when the process pushes axially, the drop with that thrust reversed (a surge or a reversal): a
  single angular-contact bearing catches one direction only;
* each ``[[scenario]]`` of the machine's magnetic bearings: levitated until it strikes, then the drop's duration;
* the coast-down with heat from the maximum speed to standstill (``--quick``: its first
  :data:`QUICK_COASTDOWN` seconds);
* a campaign over the drop conditions nobody controls, each over a range with a stated origin
  (:func:`campaign_spreads`): the spin's phase at the drop, where the levitated rotor is when the magnetic
  bearings let go, the journal/race friction, the unbalance up to the balance grade, the radial clearance
  within its fit tolerances and the mount's stiffness and damping within theirs; on Dask
  (:mod:`auxbearing.campaign`).
"""

from __future__ import annotations

import copy
import math
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import xarray as xr

from auxbearing.analysis.coastdown import TIME_BUDGET, CoastdownRun, drop_of, rattle_note, run_coastdown, tail_note
from auxbearing.analysis.drop import MachineRun, run_machine
from auxbearing.common.errors import InputError
from auxbearing.machine.combinations import SEAT_TOLERANCE
from auxbearing.machine.judging import (
    FRICTION_SOURCE,
    VERIFY_TABLE,
    read_criteria,
    verify_settings,
)
from auxbearing.machine.model import Machine, machine_from_mapping
from auxbearing.machine.scenario import SCENARIO_CASE

#: Verdicts of a run that reached a budget of work (steps, the interactive wall-time guard, coastdown.max_time): its
#: outcome is not known, so it is never a pass or a fail.
BUDGETS = ("step_budget", "wall_time_budget", TIME_BUDGET)

#: The first case: its run is the coast-down's own drop (:func:`submit_cases`).
MAX_SPEED = "drop at the maximum speed"
#: A drop at low speed runs at this fraction of the maximum (ours: the bottom of a typical operating range).
LOW_SPEED_FRACTION = 0.25
#: ``--quick``: the drops last at most this long [s], the coast-down is run for this long [s] and the
#: campaign has this many samples.
QUICK_DROP, QUICK_COASTDOWN, QUICK_SAMPLES = 0.05, 5.0, 8
#: ISO 286-1:2010 Table 1: standard tolerance IT6 and IT7 [m] by nominal size (upper bound of each range [m]).
IT_TABLE = ((0.003, 6e-6, 10e-6), (0.006, 8e-6, 12e-6), (0.010, 9e-6, 15e-6), (0.018, 11e-6, 18e-6),
            (0.030, 13e-6, 21e-6), (0.050, 16e-6, 25e-6), (0.080, 19e-6, 30e-6), (0.120, 22e-6, 35e-6),
            (0.180, 25e-6, 40e-6), (0.250, 29e-6, 46e-6), (0.315, 32e-6, 52e-6), (0.400, 36e-6, 57e-6),
            (0.500, 40e-6, 63e-6))


@dataclass
class Cases:
    """What one design did in every case."""

    machine: Machine
    drops: dict[str, MachineRun] = field(default_factory=dict)  #: case name -> run
    machines: dict[str, Machine] = field(default_factory=dict)  #: case name -> the machine it ran
    coastdown: CoastdownRun | None = None
    campaign: dict | None = None  #: statistics of :func:`auxbearing.campaign.statistics.campaign_statistics`
    campaign_store: str | None = None
    notes: list[str] = field(default_factory=list)
    spreads: list[dict] = field(default_factory=list)  #: the campaign's uncontrolled conditions (campaign_spreads)
    tables: tuple[str, ...] = ()  #: the tables the machine file gives (to say where a value came from)
    #: why the coast-down stopped short of standstill (--quick, a budget, a limit that ended it); empty: it did not
    partial_coastdown: str = ""
    #: why every drop ran only its first part (--quick, on a machine whose drop is longer); empty: they ran whole
    partial_drops: str = ""
    quick: bool = False  #: the quick look's shorter cases


def variant(data: dict, name: str, base: Path | None, rotor: dict | None = None, drop: dict | None = None) -> Machine:
    """A machine from the file's tables with some ``[rotor]`` / ``[drop]`` values replaced (values with units)."""
    tables = copy.deepcopy(data)
    if rotor:
        tables.setdefault("rotor", {}).update(rotor)
    if drop:
        tables.setdefault("drop", {}).update(drop)
    return machine_from_mapping(tables, name, base).for_batch()  # a verdict's work is bounded by steps alone


class Immediate:
    """Runs a task at once, in this process: the executor of a verification without a cluster."""

    client = None  #: no Dask client: a campaign run with it starts a cluster of its own
    priority = 0

    class _Done:
        def __init__(self, value) -> None:
            self._value = value

        def result(self):
            return self._value

    def submit(self, fn, *args, **kwargs):
        """Run ``fn`` now; an object whose ``result()`` returns what it returned."""
        return self._Done(fn(*args, **kwargs))

    def ahead(self) -> Immediate:
        """Itself: one task at a time has no order to change."""
        return self


def campaign_size(settings: dict, quick: bool, samples: int | None) -> int:
    """Drops of a design's campaign: ``samples`` if given, the quick look's, or ``verify.campaign_samples``."""
    if samples is not None:
        return samples
    return QUICK_SAMPLES if quick else int(settings["campaign_samples"])


def plan_cases(data: dict, name: str, base: Path | None, quick: bool = False) -> Cases:
    """The cases of one design with their machines, nothing run yet (module docstring)."""
    settings = verify_settings(data)
    machine = machine_from_mapping(data, name, base)
    drop = {}
    if quick:
        drop["duration"] = f"{float(min(machine.simulation.duration, QUICK_DROP))!r} s"
    cases = Cases(variant(data, name, base, drop=drop), tables=tuple(data))
    speed = machine.rotor.speed
    low = settings["low_speed"] if settings["low_speed"] is not None else LOW_SPEED_FRACTION * abs(speed)
    cases.machines[MAX_SPEED] = cases.machine
    cases.machines["drop at low speed"] = variant(
        data, name, base, rotor={"speed": f"{float(math.copysign(low, speed))!r} rad/s"}, drop=drop)
    if machine.rotor.axial_force != 0.0:
        cases.machines["drop with the thrust reversed"] = variant(
            data, name, base, rotor={"axial_force": f"{float(-machine.rotor.axial_force)!r} N"}, drop=drop)
    after = min(machine.simulation.duration, QUICK_DROP) if quick else machine.simulation.duration
    every = read_criteria(data.get("criteria"))["relevitation_time"]
    for scenario in machine.scenarios:  # levitated until the scenario strikes, then the drop's own duration
        # a re-levitation asked for (by the scenario or by [criteria]) is watched as long as the judge needs to tell
        # it, and one output step more: the run's last sample may fall that far short of its duration
        within = scenario.relevitate_within or every
        span = max(after, relevitation_span(within) + machine.simulation.output_step) if within else after
        cases.machines[SCENARIO_CASE + scenario.name] = variant(
            data, name, base, drop={"duration": f"{float(scenario.time + span)!r} s"}).with_scenario(scenario.name)
    cases.spreads = campaign_spreads(cases.machine, settings)
    cases.quick = quick
    if after < machine.simulation.duration:
        cases.partial_drops = (f"only the first {after * 1e3:g} ms of each {machine.simulation.duration * 1e3:g} ms "
                               "drop ran (--quick): run without --quick")
    return cases


def relevitation_span(within: float) -> float:
    """How long after its strike a scenario must run to show whether the rotor re-levitated within ``within`` [s].

    A re-levitation is known once the run's last :data:`~auxbearing.analysis.scenario_outcome.SETTLED` share after
    the strike (at least ``SETTLED_MIN``) is free of contact, so a lift-off at the limit needs the limit plus that
    stretch. The plan (:func:`plan_cases`) and the judge (:func:`auxbearing.verify.judge._scenario_criteria`) both
    use it, so a full run is never too short for its own judge.

    >>> round(relevitation_span(0.030), 6), round(relevitation_span(0.100), 6)
    (0.05, 0.125)
    """
    from auxbearing.analysis.scenario_outcome import SETTLED, SETTLED_MIN

    return max(within / (1.0 - SETTLED), within + SETTLED_MIN)


def _coastdown_horizon(machine: Machine, quick: bool) -> float:
    """Simulated time a case's coast-down may run [s]: ``coastdown.max_time``, or the quick look's first seconds."""
    return min(QUICK_COASTDOWN, machine.coastdown.max_time) if quick else machine.coastdown.max_time


def _coastdown_task(machine: Machine, quick: bool, lean: bool = False) -> CoastdownRun:
    if quick:
        run = run_coastdown(machine, until_stop=False, duration=_coastdown_horizon(machine, quick))
    else:
        run = run_coastdown(machine)
    if lean:  # its drop's time series (38 MB on the blower) stay on the worker: the summary is what is judged
        run = run._replace(drop=MachineRun(xr.Dataset(attrs=run.drop.dataset.attrs), run.drop.summary))
    return run


def submit_cases(cases: Cases, executor, lean: bool = False, coastdown: bool = True) -> dict:
    """Hand the drops and the coast-down of a planned design to ``executor`` (``submit(fn, *args)``): futures.

    The coast-down starts at once, beside the drops. It integrates its own drop at the maximum speed first, the
    same run as :func:`auxbearing.analysis.drop.run_machine` of the same machine, so that case is not run again
    (unless a ``coastdown.max_time`` shorter than the drop would cut it): :func:`collect_cases` takes it from the
    coast-down, and sets the rest of the coast-down aside when that drop leaves the model's range.

    ``lean``: the runs come back with their summaries and the coast-down's history only, no drop time series
    (a candidate's or the recommended geometry's cases, which are judged and tabled but not drawn or saved:
    the blower's seven drops would otherwise bring 250 MB per design into this process).

    ``coastdown=False``: the drops only, the one at the maximum speed as well; :func:`submit_coastdown` adds the
    coast-down later, if it is still wanted.
    """
    futures = {case: executor.submit(run_machine, machine, None, None, lean) for case, machine in cases.machines.items()
               if case != MAX_SPEED or not coastdown
               or _coastdown_horizon(cases.machine, cases.quick) < machine.simulation.duration}
    if coastdown:
        submit_coastdown(cases, executor, futures, lean)
    return futures


def drop_summary(run: MachineRun | CoastdownRun) -> dict:
    """The summary of a drop, given as its run or as the coast-down that starts with it (a task: read where it ran)."""
    return drop_of(run).summary


def max_speed_drop(futures: dict):
    """Of :func:`submit_cases`'s futures, the one holding the drop at the maximum speed (its own, or the coast-down)."""
    return futures.get(MAX_SPEED, futures.get("coast-down"))


def submit_coastdown(cases: Cases, executor, futures: dict, lean: bool = False) -> None:
    """Add the coast-down of a planned design to ``futures`` (:func:`submit_cases`)."""
    futures["coast-down"] = executor.submit(_coastdown_task, cases.machine, cases.quick, lean)


def collect_cases(cases: Cases, futures: dict) -> Cases:
    """The runs of :func:`submit_cases` into ``cases``, with the notes they call for.

    Without a coast-down among them, the drops only: ``cases.coastdown`` stays None until they are collected
    again with one.
    """
    coastdown = futures["coast-down"].result() if "coast-down" in futures else None
    for case in cases.machines:
        cases.drops[case] = futures[case].result() if case in futures else coastdown.drop
    if coastdown is None:
        return cases
    first = cases.drops[MAX_SPEED].summary
    if first["verdict"] != "ok":
        cases.notes.append("the coast-down was not run: the drop at the maximum speed it starts from already left "
                           f"the model's range ({first['reason']})")
        return cases
    cases.coastdown = coastdown
    if cases.quick:
        cases.notes.append(f"--quick: the coast-down ran for its first {QUICK_COASTDOWN:g} s only; temperatures, "
                           "clearances and life cover that part")
        if coastdown.summary["coastdown_time_s"] is None:
            cases.partial_coastdown = "only the first part of the coast-down ran (--quick): run without --quick"
    elif coastdown.summary["verdict"] in BUDGETS:
        cases.partial_coastdown = f"the coast-down reached a budget ({coastdown.summary['reason']})"
    elif coastdown.summary["coastdown_time_s"] is None:
        # stopped on a limit (a thermal run-away, a clearance closed) or at coastdown.max_time: the peaks and the
        # damage of the rest of the coast-down are unknown, so what it shows so far can fail a criterion, not pass it
        verdict = coastdown.summary["verdict"]
        cases.partial_coastdown = (f"the coast-down stopped at its {verdict.replace('_', ' ')} "
                                   f"({coastdown.summary['reason']})" if verdict != "ok" else
                                   "the coast-down reached coastdown.max_time before standstill")
    if coastdown.summary.get("tail"):
        cases.notes.append(tail_note(coastdown.summary["tail"]))
    rattle = rattle_note(coastdown.summary)
    if rattle:
        cases.notes.append(rattle)
    return cases


def run_campaign_of(cases: Cases, data: dict, name: str, base: Path | None, samples: int, store: Path | None,
                    workers: int | None, scheduler: str | None, required_s0: float,
                    whirl_limit: float | None = None, priority: int = 0, client=None) -> None:
    """The design's campaign over its spreads into ``cases`` (:func:`auxbearing.campaign.run.run_campaign`).

    It runs on ``client`` if given, else on the scheduler given, else on a local cluster of its own.

    With ``whirl_limit`` the campaign stops once its first drops (in design order) fail the whirl criterion
    whatever the rest would show (:func:`auxbearing.verify.criteria.whirl_fails_whatever_follows`); its
    statistics are then those of the drops run.
    """
    if samples <= 0:
        return
    drop = {}
    if cases.quick:
        drop["duration"] = f"{float(cases.machine.simulation.duration)!r} s"
    cases.campaign, cases.campaign_store = _campaign(data, name, base, cases.machine, verify_settings(data), samples,
                                                     store, workers, scheduler, required_s0, drop, whirl_limit,
                                                     priority, client)


def run_cases(data: dict, name: str, base: Path | None, quick: bool = False, samples: int | None = None,
              store: Path | None = None, workers: int | None = None, scheduler: str | None = None,
              required_s0: float = 1.0, progress: Callable[[str], None] | None = None) -> Cases:
    """Run every case of one design, one after another (module docstring); ``samples = 0`` skips the campaign."""
    if progress is not None:
        progress("drops and coast-down")
    cases = collect_cases(plan := plan_cases(data, name, base, quick), submit_cases(plan, Immediate()))
    n = campaign_size(verify_settings(data), quick, samples)
    if progress is not None and n > 0:
        progress(f"campaign of {n} drops")
    run_campaign_of(cases, data, name, base, n, store, workers, scheduler, required_s0)
    return cases


def it_tolerance(diameter: float, grade: float) -> float:
    """ISO 286-1 standard tolerance [m] of a nominal diameter [m], grade IT6 or IT7 (Table 1), linear between."""
    for top, it6, it7 in IT_TABLE:
        if diameter <= top:
            return it6 + (it7 - it6) * (min(max(grade, 6.0), 7.0) - 6.0)
    raise InputError.for_field("verify.fit_grade", f"diameter {diameter * 1e3:g} mm",
                               "ISO 286-1's table here covers sizes up to 500 mm")


def campaign_spreads(machine: Machine, settings: dict) -> list[dict]:
    """The uncontrolled drop conditions and their ranges (SI), each with where its range comes from.

    Each entry: ``key`` (a campaign input), ``low``, ``high``, ``unit`` (display), ``label`` and ``origin``.
    """
    r = machine.rotor
    spreads = [{"key": "rotor.unbalance_phase", "low": 0.0, "high": 2.0 * math.pi, "scale": 180.0 / math.pi,
                "unit": "deg", "label": "phase of the spin at the drop",
                "origin": "any: the magnetic bearings do not fail at a chosen angle"}]
    grade = settings["balance_grade"]
    e_grade = grade / abs(r.speed) if r.speed else 0.0
    top = max(e_grade, r.unbalance)
    if top > 0.0:
        spreads.append({"key": "rotor.unbalance", "low": 0.0, "high": top, "scale": 1e6, "unit": "um",
                        "label": "static unbalance (mass-centre offset)",
                        "origin": f"ISO 21940-11: G {grade * 1e3:g} mm/s at {abs(r.speed) * 30 / math.pi:.0f} rpm "
                                  f"is e = {e_grade * 1e6:.3g} um" + (f"; the file's {r.unbalance * 1e6:g} um is larger"
                                                                       if r.unbalance > e_grade else "")})
    offset = settings["start_offset"] * min(p.radial_clearance for p in machine.planes) / math.sqrt(2.0)
    if offset > 0.0:
        for axis in ("x", "y"):
            base = getattr(r, f"start_{axis}")
            spreads.append({"key": f"rotor.start_{axis}", "low": base - offset, "high": base + offset, "scale": 1e6,
                            "unit": "um", "label": f"levitated rotor's position at the drop, {axis}",
                            "origin": VERIFY_TABLE["start_offset"].source})
    for k, plane in enumerate(machine.planes):
        lo, hi = settings["friction_low"], settings["friction_high"]
        spreads.append({"key": f"touchdown.{k}.sliding_friction", "low": lo, "high": hi, "scale": 1.0, "unit": "",
                        "label": f"{plane.name}: journal/race sliding friction", "origin": FRICTION_SOURCE})
        tol, origin = clearance_tolerance(plane, settings)
        if tol > 0.0:
            s = plane.radial_clearance
            spreads.append({"key": f"touchdown.{k}.radial_clearance", "low": max(s - tol, 0.5 * s), "high": s + tol,
                            "scale": 1e6, "unit": "um", "label": f"{plane.name}: radial clearance", "origin": origin})
        if plane.mount is not None:
            for name, value, spread_key in (("mount_stiffness", plane.mount.mount_stiffness, "mount_stiffness_spread"),
                                            ("mount_damping", plane.mount.mount_damping, "mount_damping_spread")):
                f = settings[spread_key]
                if value > 0.0 and f > 0.0:
                    spreads.append({"key": f"touchdown.{k}.{name}", "low": value * (1.0 - f),
                                    "high": value * (1.0 + f), "scale": 1.0,
                                    "unit": "N/m" if name == "mount_stiffness" else "N*s/m",
                                    "label": f"{plane.name}: {name.replace('_', ' ')}",
                                    "origin": VERIFY_TABLE[spread_key].source})
    return spreads


def clearance_tolerance(plane, settings: dict) -> tuple[float, str]:
    """How far a plane's radial clearance as made may lie from the file's [m], and where that comes from.

    ``verify.clearance_tolerance`` if given; else the journal's and the bore's ISO 286-1 tolerance of grade
    ``verify.fit_grade``: each zone is IT wide, the radial clearance is half their diametral difference, so it
    spans (IT_bore + IT_journal) / 2, taken as +- a quarter of the sum about the file's value.
    """
    tol = settings["clearance_tolerance"]
    if tol is not None:
        return float(tol), "your [verify] table"
    bore = 2.0 * (plane.journal_radius + plane.radial_clearance)
    grade = settings["fit_grade"]
    tol = 0.25 * (it_tolerance(bore, grade) + it_tolerance(2.0 * plane.journal_radius, grade))
    return tol, f"ISO 286-1 IT{grade:g} of the {bore * 1e3:.0f} mm bore and journal: +-{tol * 1e6:.1f} um"


def thermal_openings(history, planes) -> list[float]:
    """Per plane, how far thermal growth opened its touchdown clearance beyond the file's over a coast-down [m]."""
    return [max(0.0, float(history.radial_clearance.isel(plane=k).max()) - p.radial_clearance)
            for k, p in enumerate(planes)]


def largest_clearance_tolerances(cases: Cases) -> list[tuple[float, str]]:
    """Per plane, how far above the file's its radial clearance may be made [m], and where that comes from.

    The campaign's spread of the clearance (:func:`campaign_spreads`); (0, "") where it has none.
    """
    out = []
    for k, plane in enumerate(cases.machine.planes):
        spread = next((sp for sp in cases.spreads if sp["key"] == f"touchdown.{k}.radial_clearance"), None)
        out.append((max(0.0, float(spread["high"]) - plane.radial_clearance), spread["origin"]) if spread
                   else (0.0, ""))
    return out


def campaign_tables(data: dict, machine: Machine, settings: dict, samples: int, drop: dict) -> dict:
    """The verification's campaign over the uncontrolled drop conditions (:func:`campaign_spreads`)."""
    tables = copy.deepcopy(data)
    for key in ("criteria", "candidate", "verify", "campaign"):
        tables.pop(key, None)
    if drop:
        tables.setdefault("drop", {}).update(drop)
    for plane, table in zip(machine.planes, tables.get("touchdown", []), strict=False):
        # the clearance tolerance is the journal's and the bore's: a journal radius the file gives with the
        # journal seated in the bore (radius + clearance = bore / 2) is derived per drop from the sampled
        # clearance, as the file would give it; kept fixed, every sample above the file's clearance put the race
        # past the bore (56 of the heavy rotor's 128 drops refused as invalid input)
        bore = plane.bearing.bore
        if "journal_radius" in table and bore is not None and abs(
                plane.journal_radius + plane.radial_clearance - 0.5 * bore) <= SEAT_TOLERANCE:
            del table["journal_radius"]
    si_units = {"rotor.unbalance_phase": "rad", "rotor.unbalance": "m", "rotor.start_x": "m", "rotor.start_y": "m"}
    inputs = []
    for spread in campaign_spreads(machine, settings):
        key = spread["key"]
        unit = si_units.get(key) or ("m" if key.endswith("radial_clearance") else
                                     spread["unit"] if spread["unit"] not in ("", "um", "deg") else "")
        low, high = (f"{float(spread['low'])!r} {unit}", f"{float(spread['high'])!r} {unit}") if unit else (
            float(spread["low"]), float(spread["high"]))
        inputs.append({"key": key, "distribution": "uniform", "low": low, "high": high})
    sampler = "sobol" if samples & (samples - 1) == 0 else "lhs"  # Sobol' points balance at powers of two
    tables["campaign"] = {"sampler": sampler, "samples": samples, "seed": 1, "analysis": "drop", "input": inputs}
    return tables


def _first_drops(store, n: int):
    """The campaign store's first ``n`` samples, read in this process (:func:`auxbearing.campaign.store.open_store`)."""
    from auxbearing.campaign.store import load_results

    return load_results(store).isel(sample=slice(0, n))


def _whirl_settled(store, n: int, total: int, limit: float) -> bool:
    """The campaign's stopping rule: True when its first ``n`` drops fail the whirl criterion whatever follows.

    Asked after every batch, so it reads only the three arrays it needs of this process's own store (0.04 s;
    the whole store, read and checked, took 0.1-0.2 s a batch of this process's time, beside the workers).
    """
    from auxbearing.campaign.statistics import verdict_masks
    from auxbearing.campaign.store import open_store
    from auxbearing.verify.criteria import whirl_fails_whatever_follows

    ds = open_store(store)[["verdict", "completed", "backward_whirl"]].isel(sample=slice(0, n)).load()
    ok = verdict_masks(ds)["ok"]
    whirled = int((ds["backward_whirl"].max("plane", skipna=False).values[ok] > 0.5).sum())
    return whirl_fails_whatever_follows(whirled, int(ok.sum()), total - n, limit)


def _campaign(data, name, base, machine, settings, samples, store, workers, scheduler, required_s0, drop,
              whirl_limit=None, priority=0, client=None):
    from auxbearing.campaign.config import campaign_from_mapping
    from auxbearing.campaign.run import run_campaign
    from auxbearing.campaign.statistics import campaign_statistics

    if store is None:
        raise InputError("verify: a campaign needs a store folder (--out)")
    campaign = campaign_from_mapping(campaign_tables(data, machine, settings, samples, drop), f"{name} campaign", base)
    decided = None if whirl_limit is None else (
        lambda path, n: _whirl_settled(path, n, campaign.runs, whirl_limit))
    # on the verification's cluster the workers have loaded the kernels and run this machine's cases already
    ran = run_campaign(campaign, store, scheduler=scheduler, workers=workers, decided=decided, priority=priority,
                       client=client, warm=client is None)
    stop = ran.get("decided_at")
    stats = campaign_statistics(_first_drops(store, campaign.runs if stop is None else stop), required_s0=required_s0)
    stats["planned"] = campaign.runs
    stats["stopped_decided"] = stop is not None
    return stats, str(store)
