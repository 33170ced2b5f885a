"""Convergence evidence: the case that governs a verdict, run again with tolerances ten times tighter.

The governing criterion is the failing one, or else the one with the smallest margin. Its case (a drop, or
the coast-down) runs again with the integration's relative and absolute tolerances divided by
:data:`TIGHTER` and, for a coast-down, a reduced-model speed step halved (finer stretches between the
full-dynamics checks), and when the governing quantity is an extreme over time (the hottest part, the
closest internal clearance, the widest touchdown clearance) only a little past the time the first run reached it
(:data:`EXTREME_MARGIN`), unless the tighter run's extreme is still coming there. The rotor's travel against the
air gap is re-run where its governing figure came from: a case drop (its journal's excursion), the coast-down (its
thermal opening and its own drop's travel past the clearance, compared without the clearance and tolerance, which
are input), or, from the campaign, nothing; the governing quantity's change is reported, and a change beyond
:data:`SETTLED` says the verdict rests on a number the numerics still move. When a run leaving the model's
range governs, that run is repeated and the time of its stop compared (a tighter run that stops otherwise,
or not at all, says so). A campaign's probability has its confidence interval as its own evidence and is
not re-run.
"""

from __future__ import annotations

import copy
from dataclasses import replace

from auxbearing.verify.cases import Cases, thermal_openings
from auxbearing.verify.judge import AIR_GAP, bends

#: Factor by which the tolerances are tightened.
TIGHTER = 10.0
#: Largest relative change of the governing quantity for which it counts as converged.
SETTLED = 0.01

_COASTDOWN = ("peak bearing temperature", "preload of a closing internal clearance",
              "drops to failure (fatigue or dent)", AIR_GAP)
#: Coast-down quantities that are an extreme over time (the rest, the damage, sums over the whole run).
_EXTREMES = _COASTDOWN[:2] + _COASTDOWN[3:]
#: A tighter coast-down for an extreme runs past the time the first run reached it by this share of that time
#: (at least :data:`EXTREME_MARGIN_MIN`), not to standstill: the blower's hottest part peaks at 153 s of 215 s,
#: and the tighter run to 170 s found the same peak for 43 s of computing instead of 62 s.
EXTREME_MARGIN = 0.1
EXTREME_MARGIN_MIN = 1.0  # [s]


def _tightened(machine, coastdown: bool):
    """A copy of a (batch) machine with tolerances divided by :data:`TIGHTER`, and a finer coast-down."""
    sim = copy.copy(machine.simulation)
    object.__setattr__(sim, "rtol", machine.simulation.rtol / TIGHTER)  # both stay valid: smaller, positive
    object.__setattr__(sim, "atol", machine.simulation.atol / TIGHTER)
    out = replace(machine, simulation=sim)
    if coastdown:
        out = replace(out, coastdown=replace(machine.coastdown, speed_step=0.5 * machine.coastdown.speed_step))
    return out


def _coastdown_quantity(name: str, run, touchdowns) -> float | None:
    """The governing coast-down quantity of criterion ``name`` in a run (``touchdowns``: the machine's planes)."""
    summary, history = run.summary, run.history
    planes = summary["planes"]
    if any(p["max_temperature_C"] is None for p in planes):  # its drop did not finish: no coast-down ran
        return None
    if name == "peak bearing temperature":
        return max(max(p["max_temperature_C"].values()) for p in planes)
    if name == "preload of a closing internal clearance":
        return min(p["min_internal_clearance_um"] for p in planes)
    if name == "drops to failure (fatigue or dent)":
        values = [p["allowed_drops"] for p in planes if p["allowed_drops"] is not None]
        return min(values) if values else None
    # the air gap: the clearance as given and its fit tolerance are inputs, the numerics move the opening and how far
    # the coast-down's own drop took the journal past the clearance (judge._air_gap)
    own = run.drop.summary["planes"]
    return max(opening + max(0.0, p["max_excursion_um"] * 1e-6 - plane.radial_clearance)
               for opening, p, plane in zip(thermal_openings(history, touchdowns), own, touchdowns, strict=True)) * 1e3


def _extreme_time(name: str, history) -> float:
    """When the first run reached the extreme a coast-down criterion judges [s] (:data:`_EXTREMES`)."""
    if name == "peak bearing temperature":
        series = history.temperature.max(dim=[d for d in history.temperature.dims if d != "time"])
        at = series.argmax(dim="time")
    elif name == "preload of a closing internal clearance":
        at = history.internal_clearance.min(dim="plane").argmin(dim="time")
    else:
        at = history.radial_clearance.max(dim="plane").argmax(dim="time")
    return float(history.time[int(at)])


def _drop_quantity(name: str, summary: dict, at_bearings: bool = False) -> float | None:
    """The drop's figure of a criterion; ``at_bearings``: the excursion at the magnetic bearings counts too [mm]."""
    if name.startswith("static safety factor"):
        values = [p["s0"] for p in summary["planes"] if p["s0"] is not None]
        return min(values) if values else None
    largest = summary["largest_excursion_m"] * 1e3
    if at_bearings:  # a bending rotor (judge._air_gap): its records at the radial bearings
        largest = max([largest] + [a["max_excursion_um"] * 1e-3 for a in summary.get("amb", [])
                                   if a.get("max_excursion_um") is not None])
    return largest


def governing(criteria: list):
    """The criterion that governs a verdict: the first failing one, else the checked one with the smallest margin."""
    failing = [c for c in criteria if c.passed is False]
    if failing:
        return failing[0]
    with_margin = [c for c in criteria if c.passed is not None and c.margin is not None]
    return min(with_margin, key=lambda c: c.margin) if with_margin else None


def convergence(cases: Cases, criteria: list, executor=None) -> dict | None:
    """Re-run the governing case tighter (module docstring); None when nothing re-runnable governs.

    ``executor`` (``submit(fn, *args)``) runs the case; default this process.
    """
    return convergence_started(cases, criteria, executor)()


def convergence_started(cases: Cases, criteria: list, executor=None):
    """:func:`convergence` with its run handed to ``executor`` now: call the result for the comparison."""
    from auxbearing.analysis.coastdown import run_coastdown
    from auxbearing.analysis.drop import run_machine
    from auxbearing.verify.cases import Immediate

    executor = executor or Immediate()

    def completed(run):  # a run that answers as it is
        return run

    c = governing(criteria)
    if c is None or c.found is None:
        return lambda: None
    what = {"criterion": c.name, "unit": c.unit, "tolerance_factor": TIGHTER}
    # the air gap's figure comes from a case drop, the coast-down or the campaign: its evidence says which
    from_drop = c.name == AIR_GAP and any(k in (c.evidence or "") for k in cases.drops)
    if c.name == AIR_GAP and not from_drop and "coast-down, " not in (c.evidence or ""):
        return lambda: None  # the campaign's drop, or the clearance as made (no run to tighten)
    if c.name in _COASTDOWN and not from_drop:
        if cases.coastdown is None:
            return lambda: None
        first = cases.coastdown
        tighter = _tightened(cases.machine, True)
        whole = (run_coastdown, tighter, first.summary["until_stop"],
                 None if first.summary["until_stop"] else first.summary["simulated_s"])
        what["case"] = "the coast-down (speed step halved too)"
        reached, span = None, None
        if c.name in _EXTREMES:
            reached = _extreme_time(c.name, first.history)
            span = reached + max(EXTREME_MARGIN * reached, EXTREME_MARGIN_MIN)
        if span is not None and span < float(first.summary["simulated_s"]):
            # an extreme passed well before the end: the tighter run need not go further than a little past it
            future = executor.submit(run_coastdown, tighter, False, span)
            what["case"] += f" to {span:.1f} s, past the first run's extreme at {reached:.1f} s"
        else:
            span = None
            future = executor.submit(*whole)
        before = _coastdown_quantity(c.name, first, cases.machine.planes)

        def completed(run):
            if span is not None and _extreme_time(c.name, run.history) > span - 0.5 * (span - reached):
                # the tighter run's extreme is still coming at its end: only the whole run can tell it
                what["case"] = "the coast-down (speed step halved too)"
                return executor.submit(*whole).result()
            return run

        def after_of(run):
            return _coastdown_quantity(c.name, run, cases.machine.planes)

        if c.name == AIR_GAP:
            what["quantity"] = ("largest thermal opening of a touchdown clearance with the travel past it in the "
                                "coast-down's own drop")
        if c.name == "peak bearing temperature":  # on an offset scale: compare the rises above ambient
            ambient = cases.machine.coastdown.ambient_temperature - 273.15
            before = None if before is None else before - ambient
            what["quantity"] = "hottest part's rise above ambient"
            what["unit"] = "K"  # a difference of two temperatures: kelvin, not a reading in degC

            def after_of(run, plain=after_of):
                value = plain(run)
                return None if value is None else value - ambient
    elif c.name.startswith("static safety factor") or c.name.startswith("journal excursion") or from_drop:
        # the drop the evidence names; none (a campaign's drop governs) has no case of its own to run again
        case = next((k for k in cases.drops if k in (c.evidence or "")), None)
        if case is None:
            return lambda: None
        future = executor.submit(run_machine, _tightened(cases.machines[case], False))
        at_bearings = from_drop and bends(cases.machine)
        before = _drop_quantity(c.name, cases.drops[case].summary, at_bearings)
        what["case"] = case
        if from_drop:
            what["quantity"] = ("largest excursion of the rotor from the machine's axis in that drop, at its journals "
                                "and magnetic bearings" if at_bearings else
                                "largest journal excursion from the machine's axis in that drop")

        def after_of(run):
            return _drop_quantity(c.name, run.summary, at_bearings)
    elif c.name.startswith("no run leaves the model's range"):
        # a run that stopped governs: re-run it tighter and compare when it stops (and that it stops alike)
        stopped = [k for k, run in cases.drops.items() if run.summary["verdict"] != "ok"]
        if stopped:
            case, first = stopped[0], cases.drops[stopped[0]]
            future = executor.submit(run_machine, _tightened(cases.machines[case], False))
        elif cases.coastdown is not None and cases.coastdown.summary["verdict"] != "ok":
            case, first = "the coast-down (speed step halved too)", cases.coastdown
            future = executor.submit(run_coastdown, _tightened(cases.machine, True), first.summary["until_stop"],
                                     None if first.summary["until_stop"] else first.summary["simulated_s"])
        else:
            return lambda: None
        stop = first.summary["verdict"]
        before = float(first.summary["simulated_s"])
        what.update(case=case, unit="s", quantity=f"time of the stop ({stop.replace('_', ' ')})")

        def after_of(run):
            return float(run.summary["simulated_s"]) if run.summary["verdict"] == stop else None
    else:
        return lambda: None
    what.setdefault("quantity", c.name)

    def finish() -> dict:
        run = completed(future.result())
        after = after_of(run)
        what.update(as_run=before, tightened=after, verdict=run.summary["verdict"])
        if after is None and what["quantity"].startswith("time of the stop"):
            what.update(change=None, settled=False,
                        note=f"the tighter run ends '{run.summary['verdict']}' instead: the verdict rests on a stop "
                             "the numerics move")
            return what
        if before is None or after is None or before == 0.0:
            what.update(change=None, settled=None, note="the tighter run gave no value to compare")
            return what
        change = (after - before) / abs(before)
        what.update(change=change, settled=abs(change) <= SETTLED,
                    note=(f"{what['quantity']} moves {100 * change:+.2f} % with tolerances {TIGHTER:g}x tighter"
                          + ("" if abs(change) <= SETTLED else
                             f": more than {100 * SETTLED:g} %, so the verdict rests on a number the numerics "
                             "still move")))
        return what

    return finish
