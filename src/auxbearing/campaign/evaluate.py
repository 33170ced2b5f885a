"""One sample of a campaign: the machine with the sampled inputs, its run, and a flat record of outputs.

A record is never an exception: a sampled value the machine refuses is ``invalid_input`` (with the
one-line reason), an exception in the model is ``error``, a run that leaves the model's range or a
budget carries the drop's verdict. :data:`SAMPLE_OUTPUTS` and :data:`PLANE_OUTPUTS` are the variables
of the store; :func:`evaluate_batch` fills them for a slice of the design (what a worker runs).
"""

from __future__ import annotations

import time
from pathlib import Path

import numpy as np

from auxbearing.campaign.config import Campaign, apply_sample
from auxbearing.common.errors import InputError

#: The drop's stops at the edge of the model's range (:data:`auxbearing.core.watch.STOP_NAMES`).
OUT_OF_RANGE = ("journal_contact_overstress", "ball_stress_beyond_elastic", "contact_ellipse_over_shoulder",
                "mount_beyond_travel", "race_runs_off_axially", "energy_gain")
#: Runs that ended without a result: the two budgets, a failed integration, and the campaign's own two
#: (a sampled value the machine refuses, an exception in the model).
FAILED = ("step_budget", "wall_time_budget", "integration_failed", "invalid_input", "error")
#: A coast-down's own ends (:mod:`auxbearing.analysis.coastdown`): the design fails in them, a result.
COASTDOWN_LIMITS = ("thermal_runaway", "radial_clearance_closed", "internal_clearance_preload")
#: Verdict codes in the store: 0 is a sample not run yet; the store keeps this list in its attributes.
VERDICTS = ("pending", "ok", *OUT_OF_RANGE, *FAILED, *COASTDOWN_LIMITS)
#: Whirl codes: 0 when there is no run; then :data:`auxbearing.analysis.whirl.CLASSES` in order.
WHIRL_CODES = ("unknown", "none", "forward", "backward_rolling", "dry_whip", "backward")
BACKWARD_CLASSES = ("backward_rolling", "dry_whip", "backward")
#: Longest reason kept per sample [characters] (reasons are one line).
REASON_LENGTH = 200

#: Per-sample outputs: name -> (dtype, units, long name). Timing variables are marked in TIMING.
SAMPLE_OUTPUTS: dict[str, tuple[str, str, str]] = {
    "verdict": ("i1", "", "Verdict code (index into the store's 'verdicts' attribute)"),
    "reason": (f"<U{REASON_LENGTH}", "", "Why the run ended as it did (empty when ok)"),
    "simulated_time": ("f8", "s", "Simulated time reached"),
    "steps": ("f8", "", "Integration steps"),
    "energy_balance_error": ("f8", "", "Energy ledger error relative to the energy brought in"),
    "max_bearing_excursion": ("f8", "m", "Largest excursion of the rotor from the machine's axis at a radial "
                              "magnetic bearing, bending included (NaN: the machine has none)"),
    "integration_time": ("f8", "s", "Wall time of the integration"),
    "sample_time": ("f8", "s", "Wall time of the whole sample: machine, run and record"),
}
#: Per-plane outputs of a drop: name -> (dtype, units, long name, summary key, scale to the unit).
PLANE_OUTPUTS: dict[str, tuple[str, str, str, str, float]] = {
    "peak_contact_force": ("f8", "N", "Peak journal/race collision force", "peak_contact_force_N", 1.0),
    "peak_ball_stress": ("f8", "Pa", "Peak Hertz ball contact stress", "peak_ball_stress_MPa", 1e6),
    "s0": ("f8", "", "Static safety factor (ISO 76) at the peak ball stress", "s0", 1.0),
    "peak_journal_pressure": ("f8", "Pa", "Peak journal/race contact pressure (conformal contact)",
                              "peak_journal_pressure_MPa", 1e6),
    "backward_whirl_onset": ("f8", "s", "Onset of sustained backward whirl", "backward_whirl_onset_ms", 1e-3),
    "final_contact_force": ("f8", "N", "Collision force at the end of the run", "final_contact_force_N", 1.0),
    "peak_axial_force": ("f8", "N", "Peak axial (face) force", "peak_axial_force_N", 1.0),
    "max_mount_deflection": ("f8", "m", "Largest radial travel of the outer ring in its mount",
                             "max_mount_deflection_um", 1e-6),
    "max_excursion": ("f8", "m", "Largest journal excursion from the machine's axis", "max_excursion_um", 1e-6),
}
#: Per-plane whirl outputs (codes and flags).
WHIRL_OUTPUTS: dict[str, tuple[str, str, str]] = {
    "whirl": ("i1", "", "Whirl class at the end (index into the store's 'whirl_classes' attribute)"),
    "backward_whirl": ("f8", "", "1 when the plane whirls backward at the end or had sustained backward whirl, "
                       "NaN when the drop closed no whirl window"),
}
#: Per-plane outputs of a coast-down (auxbearing.analysis.coastdown): name -> (dtype, units, long name, summary key).
COASTDOWN_PLANE_OUTPUTS: dict[str, tuple[str, str, str, str]] = {
    "max_temperature": ("f8", "degC", "Highest temperature of any part of the plane", "max_temperature_C"),
    "damage_per_drop": ("f8", "", "Fatigue damage of one drop and its coast-down (Miner sum)", "damage_per_drop"),
    "drops_to_failure": ("f8", "", "Drops to fatigue failure", "drops_to_failure"),
    "drops_to_dent_limit": ("f8", "", "Drops to the permanent-set limit", "drops_to_dent_limit"),
    "allowed_drops": ("f8", "", "Drops the governing limit allows", "allowed_drops"),
}
COASTDOWN_SAMPLE_OUTPUTS = {"coastdown_time": ("f8", "s", "Time from the drop to standstill (NaN: not reached)")}
#: Variables whose values depend on the machine that ran them, not on the inputs (left out of comparisons).
TIMING = ("integration_time", "sample_time")


def output_variables(analysis: str) -> tuple[dict, dict]:
    """(per-sample, per-plane) variables of an analysis: name -> (dtype, units, long name)."""
    sample = dict(SAMPLE_OUTPUTS)
    plane = {k: v[:3] for k, v in PLANE_OUTPUTS.items()}
    plane.update(WHIRL_OUTPUTS)
    if analysis == "coastdown":
        sample.update(COASTDOWN_SAMPLE_OUTPUTS)
        plane.update({k: v[:3] for k, v in COASTDOWN_PLANE_OUTPUTS.items()})
    return sample, plane


#: Machine tables with their fixed values already converted, per campaign fingerprint (one per worker).
_PREPARED: dict[str, dict] = {}


def _prepared(campaign: Campaign) -> dict:
    """The campaign's machine tables with every quantity converted once to an SI quantity."""
    key = campaign.fingerprint()
    if key not in _PREPARED:
        from auxbearing.common.params import convert, si_unit
        from auxbearing.common.units import Quantity
        from auxbearing.machine.params import TABLES

        def convert_table(section: str, table: dict) -> dict:
            out = dict(table)
            for name, value in table.items():
                param = TABLES[section].get(name)
                if param is not None and isinstance(value, str) and si_unit(param.dimension):
                    out[name] = Quantity(convert(f"{section}.{name}", value, param.dimension),
                                         si_unit(param.dimension))
            return out

        tables = dict(campaign.tables)
        for section in TABLES:
            if section != "touchdown" and isinstance(tables.get(section), dict):
                tables[section] = convert_table(section, tables[section])
        tables["touchdown"] = [convert_table("touchdown", t) for t in tables.get("touchdown", [])]
        _PREPARED.clear()
        _PREPARED[key] = tables
    return _PREPARED[key]


def _number(value) -> float:
    return np.nan if value is None else float(value)


def _verdict(record: dict, verdict: str | None, reason: str | None) -> None:
    if verdict in VERDICTS:
        record["verdict"] = VERDICTS.index(verdict)
        record["reason"] = (reason or "")[:REASON_LENGTH]
    else:  # a verdict this version does not know is kept in the reason, never dropped
        record["verdict"] = VERDICTS.index("error")
        record["reason"] = f"unknown verdict {verdict!r}: {reason or ''}"[:REASON_LENGTH]


def _record_from_summary(summary: dict, record: dict, n_planes: int) -> None:
    _verdict(record, summary.get("verdict"), summary.get("reason"))
    record["simulated_time"] = _number(summary.get("simulated_s"))
    record["steps"] = _number(summary.get("steps"))
    record["energy_balance_error"] = _number(summary.get("energy_balance_error"))
    record["integration_time"] = _number(summary.get("wall_time_s"))
    at_bearings = [a["max_excursion_um"] for a in summary.get("amb", []) if a.get("max_excursion_um") is not None]
    if at_bearings:
        record["max_bearing_excursion"] = max(at_bearings) * 1e-6
    planes = summary.get("planes", [])[:n_planes]
    for k, plane in enumerate(planes):
        for name, (*_, key, scale) in PLANE_OUTPUTS.items():
            value = plane.get(key)
            record[name][k] = np.nan if value is None else float(value) * scale
        whirl = plane.get("whirl")
        record["whirl"][k] = WHIRL_CODES.index(whirl) if whirl in WHIRL_CODES else 0
        if whirl in WHIRL_CODES[1:]:
            record["backward_whirl"][k] = float(whirl in BACKWARD_CLASSES
                                                or plane.get("backward_whirl_onset_ms") is not None)
        else:  # a drop shorter than one whirl window closed none: whether it whirled is unknown, not "no"
            record["backward_whirl"][k] = np.nan


def _coastdown_record(result, record: dict, n_planes: int) -> None:
    """Fill a record from a coast-down (``auxbearing.analysis.coastdown.run_coastdown``).

    The drop's outputs come from its drop window; the verdict, times and energy audit from the whole run;
    per plane the hottest part, the damage per drop and the drops the limits allow.
    """
    from auxbearing.analysis.coastdown import TIME_BUDGET

    _record_from_summary(result.drop.summary, record, n_planes)
    summary = result.summary
    # a campaign's coast-downs run to standstill or to coastdown.max_time, its horizon for every sample: one that
    # reaches it ended as asked, and its coastdown_time (NaN) says it did not stand still
    verdict = "ok" if summary.get("verdict") == TIME_BUDGET else summary.get("verdict")
    _verdict(record, verdict, None if verdict == "ok" else summary.get("reason"))
    record["simulated_time"] = _number(summary.get("simulated_s"))
    record["energy_balance_error"] = _number(summary.get("energy_balance_error"))
    record["integration_time"] = _number(summary.get("wall_time_s"))
    record["coastdown_time"] = _number(summary.get("coastdown_time_s"))
    for k, plane in enumerate(summary.get("planes", [])[:n_planes]):
        for name, (*_, key) in COASTDOWN_PLANE_OUTPUTS.items():
            value = plane.get(key)
            if isinstance(value, dict):  # temperatures by part: the hottest counts
                value = max((v for v in value.values() if v is not None), default=None)
            record[name][k] = _number(value)


def empty_record(campaign: Campaign) -> dict:
    """A record of a sample with nothing filled in (verdict pending, NaN outputs)."""
    sample, plane = output_variables(campaign.analysis)
    n = len(campaign.plane_names)
    record = {}
    for name, (dtype, *_) in sample.items():
        record[name] = "" if dtype.startswith("<U") else (0 if dtype == "i1" else np.nan)
    for name, (dtype, *_) in plane.items():
        record[name] = np.zeros(n, dtype=np.int8) if dtype == "i1" else np.full(n, np.nan)
    return record


def evaluate_sample(campaign: Campaign, values) -> dict:
    """Run one sample (SI input values in the order of ``campaign.inputs``) into a flat record.

    Examples
    --------
    >>> from auxbearing.campaign.config import campaign_from_mapping
    >>> c = campaign_from_mapping({"campaign": {"machine": "paper_rig", "samples": 1, "input": [
    ...     {"key": "touchdown.0.sliding_friction", "distribution": "uniform", "low": 0.1, "high": 0.3}]},
    ...     "drop": {"duration": "2 ms"}})
    >>> VERDICTS[evaluate_sample(c, [0.2])["verdict"]]
    'ok'
    >>> r = evaluate_sample(c, [1.5])  # outside [0, 1]: a record, not an exception
    >>> VERDICTS[r["verdict"]], r["reason"][:28]
    ('invalid_input', 'touchdown.0.sliding_friction')
    """
    from auxbearing.machine.model import machine_from_mapping

    start = time.perf_counter()
    record = empty_record(campaign)
    n = len(campaign.plane_names)
    base = None if campaign.base is None else Path(campaign.base)
    try:
        tables = apply_sample(_prepared(campaign), campaign.inputs, values, as_quantity=True)
        # a campaign's outcome must not depend on how busy the computer is: steps bound its work, not the clock
        machine = machine_from_mapping(tables, campaign.name, base).for_batch()
        if campaign.analysis == "coastdown":
            from auxbearing.analysis.coastdown import run_coastdown

            _coastdown_record(run_coastdown(machine), record, n)
        else:
            from auxbearing.analysis.drop import run_machine

            _record_from_summary(run_machine(machine, lean=True).summary, record, n)
    except InputError as err:
        record["verdict"] = VERDICTS.index("invalid_input")
        record["reason"] = str(err)[:REASON_LENGTH]
    except Exception as err:  # a model failure is a result of the campaign, never its end
        record["verdict"] = VERDICTS.index("error")
        record["reason"] = f"{type(err).__name__}: {err}".replace("\n", " ")[:REASON_LENGTH]
    record["sample_time"] = time.perf_counter() - start
    return record


def evaluate_batch(campaign: Campaign, values: np.ndarray) -> dict[str, np.ndarray]:
    """Records of consecutive samples stacked into arrays by variable (one task of a campaign)."""
    records = [evaluate_sample(campaign, row) for row in np.atleast_2d(values)]
    sample, plane = output_variables(campaign.analysis)
    out = {}
    for name, (dtype, *_) in {**sample, **plane}.items():
        out[name] = np.array([r[name] for r in records], dtype=dtype)
    return out


def warm_up(campaign: Campaign) -> float:
    """Load (or compile) the kernels in this process with one short run; seconds spent."""
    start = time.perf_counter()
    from auxbearing.analysis.drop import run_machine
    from auxbearing.machine.model import machine_from_mapping

    base = None if campaign.base is None else Path(campaign.base)
    tables = apply_sample(_prepared(campaign), campaign.inputs,
                          [i.distribution.median() for i in campaign.inputs], as_quantity=True)
    machine = machine_from_mapping(tables, campaign.name, base)
    run_machine(machine.with_simulation(duration=1e-4, output_step=1e-5), lean=True)
    return time.perf_counter() - start
