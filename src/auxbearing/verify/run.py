"""``verify``: from a machine file to a report with criteria, margins, candidates and a recommendation.

:func:`verify` runs the cases of :mod:`auxbearing.verify.cases` on the machine's design, judges them
(:mod:`auxbearing.verify.judge`), does the same for every candidate bearing, looks for the best geometry of
the design's bearing family (:mod:`auxbearing.verify.designs`) and writes ``report.html``
(:mod:`auxbearing.report.verify_html`), ``verify.json`` and the data behind it into the output folder.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable
from concurrent.futures import ThreadPoolExecutor
from dataclasses import replace
from functools import partial
from pathlib import Path

from auxbearing.common.errors import InputError
from auxbearing.machine.check import (
    candidate_key,
    check_candidate_seat,
    check_not_the_design,
    check_temperature_criterion,
)
from auxbearing.machine.files import machine_table
from auxbearing.machine.judging import MAX_CAMPAIGN_SAMPLES, candidate_tables, read_criteria, verify_settings
from auxbearing.machine.model import machine_from_mapping
from auxbearing.machine.scenario import SCENARIO_CASE
from auxbearing.verify.cases import (
    MAX_SPEED,
    Cases,
    campaign_size,
    collect_cases,
    drop_summary,
    max_speed_drop,
    plan_cases,
    run_campaign_of,
    submit_cases,
    submit_coastdown,
)
from auxbearing.verify.convergence import convergence_started
from auxbearing.verify.criteria import MARGINS, overall_verdict, ranking_key, worst_margin
from auxbearing.verify.designs import recommend, recommended_tables, search_refused
from auxbearing.verify.judge import WHIRL_BOUND, WHIRL_PROBABILITY, campaign_drops, judge, whirl_by_estimate
from auxbearing.verify.result import Verification
from auxbearing.verify.schedule import verification_cluster

#: Drops in the campaign of a candidate that already fails on a criterion no campaign decides (a power of two
#: for Sobol' balance). 32 drops can show a whirl rate above the default 5 % (two or more whirling drops fail
#: it) but never one below it (73 whirl-free drops are needed), so its criterion fails or is not checked.
FAILING_CANDIDATE_SAMPLES = 32


def _drop_rows(cases: Cases) -> list[list]:
    rows = []
    for case, run in cases.drops.items():
        for p in run.summary["planes"]:
            rows.append([case, p["name"], run.summary["verdict"], _n(p["peak_contact_force_N"], "{:.0f}"),
                         _n(p["peak_ball_stress_MPa"], "{:.0f}"), _n(p["s0"], "{:.2f}"), _n(p["peak_axial_force_N"],
                                                                                            "{:.0f}"),
                         p["whirl"], _n(p["backward_whirl_onset_ms"], "{:.0f}")])
    return rows


def _scenario_rows(cases: Cases) -> list[list]:
    """One row per scenario case: what struck, what came of it, the bearings' currents against their limits."""
    rows = []
    for case, run in cases.drops.items():
        s = run.summary.get("scenario") or {}
        if not case.startswith(SCENARIO_CASE) or "outcome" not in s:
            continue
        worst = max(run.summary.get("amb", []), key=lambda a: a["peak_axis_current_A"] / a["max_current_A"],
                    default=None)
        peak = "-" if worst is None else f"{worst['peak_axis_current_A']:.2f} A ({worst['name']})" + (
            f" of {worst['max_current_A']:g} A" if math.isfinite(worst["max_current_A"]) else "")
        # the longest of the bearings' times: a sum over bearings could exceed the run
        saturated = max((b["saturated_ms"] for b in s.get("saturation", [])), default=0.0)
        rows.append([case.removeprefix(SCENARIO_CASE), s["kind"].replace("_", " "), f"{s['time_ms']:.1f}",
                     s["outcome"], _n(s.get("first_contact_ms"), "{:.1f}"), _n(s.get("relevitated_at_ms"), "{:.1f}"),
                     peak, f"{saturated:.1f}"])
    return rows


def _n(value, fmt: str) -> str:
    return "-" if value is None else fmt.format(value)


def _coastdown_rows(cases: Cases) -> list[list]:
    if cases.coastdown is None:
        return []
    return [[p["name"], "-" if p["max_temperature_C"] is None else f"{max(p['max_temperature_C'].values()):.1f}",
             _n(p["min_radial_clearance_um"], "{:.1f}"),
             _n(p["min_internal_clearance_um"], "{:.2f}"), _n(p["damage_per_drop"], "{:.3g}"),
             _n(p["drops_to_failure"], "{:.3g}"), _n(p["drops_to_dent_limit"], "{:.3g}"), p["governing"] or "-"]
            for p in cases.coastdown.summary["planes"]]


def _campaign_rows(stats: dict | None, spreads: list | None = None) -> tuple[list[list], dict]:
    """The campaign's probabilities and stress quantiles as rows, and its drivers table (columns, rows, caption).

    Inputs are named as the spreads table names them; a column with nothing to rank (an outcome that did not
    vary, such as whirl in a campaign where no drop whirled) is left out and the caption says why.
    """
    if not stats:
        return [], {}
    rows = []
    for key, label in (("p_backward_whirl", "probability of sustained backward whirl"),
                       ("p_out_of_range", "probability of leaving the model's range"),
                       ("p_s0_below_required", "probability of s0 below the required value")):
        p = stats[key]
        counted = p.get("trials")
        value = "-" if counted == 0 or not math.isfinite(p["value"]) else f"{p['value']:.3f}"  # no run to count
        rows.append([label, value, f"{p['low']:.3f}-{p['high']:.3f}",
                     p["among"] if counted is None else f"{p['among']} ({counted})"])
    # the extremes the s0 and seal criteria take from the campaign when they come closer to the limit
    among = f"{stats.get('ok', 0)} runs that ended ok"
    if stats.get("smallest_s0") is not None:
        rows.append(["smallest s0 of a ball contact", f"{stats['smallest_s0']:.4g}", "-", among])
    if stats.get("largest_excursion_mm") is not None:
        rows.append(["largest journal excursion from the machine's axis", f"{stats['largest_excursion_mm']:.4g} mm",
                     "-", among])
    if stats.get("largest_bearing_excursion_mm") is not None:
        rows.append(["largest excursion at a magnetic bearing", f"{stats['largest_bearing_excursion_mm']:.4g} mm", "-",
                     among])
    stress = stats.get("quantiles", {}).get("peak_ball_stress_MPa")
    if stress and stress.get("p95") is not None and math.isfinite(stress["p95"]):
        rows.append(["peak ball contact stress, median / 95th percentile",
                     f"{stress['p50']:.0f} / {stress['p95']:.0f} {stress['unit']}", "-", "-"])
    outputs = stats.get("sensitivity", {}).get("outputs", {})
    labels = {s["key"]: s["label"] for s in spreads or []}
    names = sorted({name for values in outputs.values() for name in values})
    columns, skipped = [], []
    for output, title in (("backward_whirl", "rank correlation with backward whirl"),
                          ("peak_ball_stress_MPa", "rank correlation with the peak ball stress")):
        values = [_driver(outputs, output, name) for name in names]
        if any(v != "-" for v in values):
            columns.append((title, values))
        else:
            skipped.append(title.removeprefix("rank correlation with "))
    if not names or not columns:
        return rows, {}
    caption = "What drives the outcome (Spearman rank correlations)"
    if skipped:
        caption += f"; nothing to rank for {' and '.join(skipped)}: it did not vary over the campaign's drops"
    table_rows = [[labels.get(name, name), *(values[i] for _, values in columns)] for i, name in enumerate(names)]
    return rows, {"columns": ["input", *(title for title, _ in columns)], "rows": table_rows, "caption": caption}


def _driver(outputs: dict, output: str, name: str) -> str:
    entry = outputs.get(output, {}).get(name, {})
    value = entry.get("rho", entry.get("ST"))
    return "-" if value is None or (isinstance(value, float) and not math.isfinite(value)) else f"{value:+.2f}"


def _design(cases: Cases, criteria: dict) -> dict:
    judged = judge(cases, criteria, final=True)
    campaign_rows, drivers = _campaign_rows(cases.campaign, cases.spreads)
    return {"criteria": judged, "worst_margin": worst_margin(judged),
            "verdict": overall_verdict(judged),
            "drop_rows": _drop_rows(cases), "scenario_rows": _scenario_rows(cases),
            "coastdown_rows": _coastdown_rows(cases),
            "coastdown_caption": "; ".join(cases.notes), "campaign_rows": campaign_rows, "drivers": drivers,
            "spread_rows": spread_rows(cases.spreads),
            "cases": cases}


#: ``candidates`` as text that asks for no candidate at all (the command line's ``--candidates none``): the design
#: alone, as an engineer iterating on it runs it, without the file's ``[[candidate]]`` tables.
NO_CANDIDATES = "none"


def candidate_specs(candidates: list | str | None, option: str = "candidates") -> list | None:
    """The candidates asked for: a list (a string split at its commas; :data:`NO_CANDIDATES`: none), or None.

    None leaves the choice to the machine file's ``[[candidate]]`` tables.

    >>> candidate_specs("7208, 6208"), candidate_specs("None"), candidate_specs(None)
    (['7208', '6208'], [], None)
    """
    if not isinstance(candidates, str):
        return candidates
    if candidates.strip().lower() == NO_CANDIDATES:
        return []
    items = [c.strip() for c in candidates.split(",")]
    if not all(items):
        raise InputError.for_field(option, candidates, "a comma-separated list of bearings, no empty item "
                                   f"('{NO_CANDIDATES}' for no candidate)")
    return items


def verify(spec: str | Path, out_dir: Path, candidates: list | None = None, quick: bool = False,
           samples: int | None = None, workers: int | None = None, scheduler: str | None = None,
           with_recommendation: bool = True, progress: Callable[[str], None] | None = None,
           report_figures: bool = True, candidates_option: str = "candidates") -> Verification:
    """Verify a machine's touchdown bearings (module docstring): a :class:`~auxbearing.verify.result.Verification`.

    Parameters
    ----------
    spec : str or Path
        A machine TOML file or an example machine's name.
    out_dir : Path
        Folder the campaign stores go into (the caller writes the report there).
    candidates : list or str, optional
        Catalogue names, bearing TOML paths or ``[[candidate]]`` tables (a string: names separated by commas, as
        the command line's ``--candidates``, or ``"none"``; an empty list: none); default the file's
        ``[[candidate]]``.
    quick : bool
        A first look: short drops, a few seconds of coast-down, a small campaign, a coarse recommendation;
        what the cut runs pass is not checked, so its verdict is INCOMPLETE at best.
    samples : int, optional
        Campaign size (0: no campaign); default ``verify.campaign_samples``.
    report_figures : bool
        Draw the design's report figures on the cluster at the end of the runs, side by side (False:
        :meth:`Verification.to_html` draws them all in this process when the report is written).
    candidates_option : str
        How messages name ``candidates`` (the command line passes ``--candidates``).
    """
    start = time.perf_counter()
    out_dir = Path(out_dir)
    candidates = candidate_specs(candidates, candidates_option)
    # the command line checks its options under their own names first; the API gets the same rules
    for key, value, low, high in (("samples", samples, 0, MAX_CAMPAIGN_SAMPLES), ("workers", workers, 1, 256)):
        if value is not None and (isinstance(value, bool) or not isinstance(value, int) or not low <= value <= high):
            raise InputError.for_field(key, value, f"must be a whole number in [{low}, {high}]")
    data, name, base = machine_table(spec)
    if "campaign" in data:  # the file is one document: its [campaign] table is checked too
        from auxbearing.campaign.config import campaign_from_mapping

        campaign_from_mapping(data, name, base, check_machine=False)
    criteria = read_criteria(data.get("criteria"))
    settings = verify_settings(data)
    from_option = candidates is not None
    if candidates is None:
        candidates = data.get("candidate", [])
        if not isinstance(candidates, list):
            raise InputError.for_field("candidate", candidates, "give [[candidate]] tables")
    candidate_list = candidate_tables(data, candidates)
    labels = [label for label, _ in candidate_list]
    for j, label in enumerate(labels):
        i = labels.index(label)
        if i < j:  # two runs of one bearing under one label: a ranking and a report that cannot tell them apart
            if from_option:
                raise InputError.for_field(candidates_option, label, f"each candidate once (this one is given "
                                           f"twice: items {i + 1} and {j + 1} of the list)")
            key = "name" if isinstance(candidates[j], dict) and "name" in candidates[j] else "bearing"
            raise InputError.for_field(f"candidate.{j}.{key}", label, f"the same as candidate.{i}'s: each candidate "
                                       "once")
    design_machine = machine_from_mapping(data, name, base)
    # the temperature limit's default is verify's alone: the file's check leaves it to the command that judges by it
    check_temperature_criterion(data, design_machine, criteria)
    for i, (label, tables) in enumerate(candidate_list):  # refuse a bad candidate before the first drop, not after
        where = f"{candidates_option} = {label!r}" if from_option else candidate_key(f"candidate.{i}", candidates[i])
        try:
            candidate = machine_from_mapping(tables, name, base)
        except InputError as err:
            raise InputError(f"{where}: {err}") from None
        # a candidate must fit the design's seat: same bore, no larger outside diameter or width
        check_candidate_seat(design_machine, candidate.planes[0].unit, where)
        check_not_the_design(design_machine, candidate, where)

    def say(text: str) -> None:
        if progress is not None:
            progress(text)

    skipped = search_refused(design_machine) if with_recommendation else None
    if skipped is not None:
        say(f"no geometry search: {skipped}")
        with_recommendation = False
    with verification_cluster(scheduler, workers) as (executor, address):
        design, others, rec, converged, figures = _run_all(data, name, base, criteria, settings, candidate_list,
                                                           quick, samples, out_dir, executor, address,
                                                           with_recommendation, say, report_figures)
    machine = design["cases"].machine
    status = recommendation_status(rec)
    if rec is not None:
        rec["status"] = status
    result = {
        "machine": machine.name, "verdict": design["verdict"], "design": design, "quick": quick,
        "criteria": [c.as_json() for c in design["criteria"]], "worst_margin": design["worst_margin"],
        "candidates": [{"bearing": label, "verdict": d["verdict"], "worst_margin": d["worst_margin"],
                        "criteria": [c.as_json() for c in d["criteria"]]} for label, d in others],
        # the campaign's size as it ran: --quick and --campaign-samples replace the file's
        "recommendation": rec, "recommendation_note": skipped, "recommendation_status": status,
        "settings": {**settings, "campaign_samples": campaign_size(settings, quick, samples)}, "wall_time_s": 0.0,
        "convergence": converged, "figures": figures,
        "inputs": {"machine": machine.describe(), "criteria": {k: v for k, v in criteria.items() if k != "given"},
                   "candidates": [label for label, _ in candidate_list], "quick": quick},
    }
    ranked, whirl_term = _ranked([(machine.planes[0].unit.name + " (the design)", design), *others],
                                 criteria["max_backward_whirl_probability"])
    result["margins"] = MARGINS
    result["reason"] = _reason(design["criteria"])
    result["candidate_rows"] = [[i + 1, label, d["verdict"], f"{100 * margin:+.1f} %" if math.isfinite(margin) else "-",
                                 "; ".join(c.name for c in d["criteria"] if c.passed is False) or "-"]
                                for i, (label, d, margin) in enumerate(ranked)]
    result["ranking"] = [label for label, *_ in ranked]
    result["ranking_whirl_term"] = whirl_term if others else None
    for entry, (_, d) in zip(result["candidates"], others, strict=True):
        entry["ranking_worst_margin"] = next(margin for _, e, margin in ranked if e is d)
    result["campaign"] = _campaign_summary(design["cases"].campaign)
    result["campaign_samples_from"] = ("--campaign-samples" if samples is not None else "--quick" if quick
                                       else "verify.campaign_samples")
    if rec is not None:
        first = machine.planes[0].bearing
        result["recommendation_rows"] = [
            ["contact angle", f"{rec['contact_angle_deg']:.1f} deg", f"{math.degrees(first.contact_angle):.1f} deg"],
            ["inner / outer groove ratio", f"{rec['inner_groove_ratio']:.3f} / {rec['outer_groove_ratio']:.3f}",
             f"{first.inner_groove_ratio:.3f} / {first.outer_groove_ratio:.3f}"],
            ["radial clearance", ", ".join(f"{s:.3f}" for s in rec["radial_clearance_mm"]) + " mm",
             ", ".join(f"{p.radial_clearance * 1e3:.3f}" for p in machine.planes) + " mm"],
            # the search judges drops alone: its air-gap margin has one drop's travel and no coast-down, so no
            # thermal opening, and can read above the verdict's for the same clearance
            ["worst drop margin (the drop's criteria; the air gap with this drop's travel, before the coast-down's "
             "thermal growth)",
             f"{100 * rec['worst_margin']:+.1f} %", f"{100 * rec['as_is']:+.1f} %"]]
    result["assumptions"] = _assumptions(design["cases"], criteria, settings, quick,
                                         result["settings"]["campaign_samples"], result["campaign_samples_from"], rec,
                                         skipped)
    result["wall_time_s"] = time.perf_counter() - start
    return Verification(result)


def _ranked(designs: list[tuple[str, dict]], limit: float) -> tuple[list[tuple[str, dict, float]], str]:
    """The designs ranked (:func:`ranking_key`) as (label, design, its ranking margin), and what the whirl term uses.

    A whirl bound rests on its campaign's size: 32 drops (a candidate that fails already) or a campaign stopped
    once decided give a wider bound than 128 whatever the bearing. When the designs' campaigns rest on different
    numbers of drops, the whirl criterion enters the ranking by its estimate instead, which the size does not bias;
    the verdicts keep their bounds.
    """
    sizes = sorted({n for _, d in designs if (n := campaign_drops(d["cases"].campaign)) is not None})
    by_estimate = len(sizes) > 1

    def judged(d: dict) -> list:
        return whirl_by_estimate(d["criteria"], d["cases"].campaign, limit) if by_estimate else d["criteria"]

    ranked = sorted(((label, d, judged(d)) for label, d in designs), key=lambda item: ranking_key(item[2]))
    if by_estimate:
        term = (f"the whirl probability enters the worst margin by its estimate, not its {WHIRL_BOUND}: the "
                f"campaigns rest on different numbers of drops ({', '.join(map(str, sizes))}), and a bound from fewer "
                "drops is wider whatever the bearing")
    else:
        term = f"the whirl probability enters the worst margin by its {WHIRL_BOUND}, as in the verdict" + (
            f" (every campaign rests on {sizes[0]} drops)" if sizes else "")
    return [(label, d, worst_margin(c)) for label, d, c in ranked], term


def _campaign_summary(stats: dict | None) -> dict | None:
    """The design campaign's counts and extremes for ``verify.json`` (its full statistics stay in the store)."""
    if not stats:
        return None
    keys = ("samples", "planned", "completed", "ok", "stopped_decided", "smallest_s0", "largest_excursion_mm",
            "largest_bearing_excursion_mm", "p_backward_whirl", "p_out_of_range", "p_s0_below_required")
    return {key: stats[key] for key in keys if key in stats}


def _run_all(data, name, base, criteria, settings, candidate_list, quick, samples, out_dir, executor, address,
             with_recommendation, say, figures=True):
    """Every case of the verification on one cluster, independent ones side by side (module docstring).

    A candidate that already fails on a criterion no campaign decides (a drop leaving the model's range, a
    temperature, a clearance) gets a campaign of :data:`FAILING_CANDIDATE_SAMPLES` drops, enough to show
    its whirl tendency; its verdict cannot change, and its whirl criterion says how few drops it rests on.

    The drops and coast-downs of the design and of every candidate go to the cluster at once. Then, side by
    side (:func:`_side_by_side`): the design's governing case again tighter as soon as it is known (a criterion
    its drops or coast-down fail, else once its campaign is in), and its campaign; each candidate's campaign
    once its own cases are in; the geometry search, then the recommended geometry's own verification. Their
    batches queue behind the first runs, so no worker idles.
    """
    n = campaign_size(settings, quick, samples)
    designs = [("design", data, name, out_dir / "campaign.zarr")]
    designs += [(label, tables, f"{name} with {label}", out_dir / f"campaign_candidate_{i}.zarr")
                for i, (label, tables) in enumerate(candidate_list)]
    planned = {}
    for label, tables, title, store in designs:
        cases = plan_cases(tables, title, base, quick)
        say(f"{label}: drops and coast-down")
        planned[label] = (cases, submit_cases(cases, executor, lean=label != "design"), tables, title, store)
    collected, short = set(), {}

    def campaign(label: str) -> None:
        cases, futures, tables, title, store = planned[label]
        size = n
        if label != "design" and n > FAILING_CANDIDATE_SAMPLES:
            collect_cases(cases, futures)  # the candidate's own drops and coast-down decide its campaign's size
            collected.add(label)
            failing = [c.name for c in judge(cases, criteria) if c.passed is False]
            if failing:
                size = FAILING_CANDIDATE_SAMPLES
                short[label] = (f"a campaign of {size} drops, not {n}: the candidate already fails on "
                                f"{'; '.join(failing)}, which no campaign can change")
        say(f"{label}: campaign of {size} drops")
        run_campaign_of(cases, tables, title, base, size, store, None, address, criteria["min_s0"],
                        criteria["max_backward_whirl_probability"], client=executor.client)

    def design() -> tuple[dict, Callable]:
        # the design's governing case runs again tighter, beside whatever still runs, as soon as it is known: the
        # campaign's criterion is judged last, so a criterion its own drops or coast-down fail governs whatever
        # the campaign shows (the blower's peak temperature). The campaign goes out with the runs, not after the
        # coast-down: the design verified alone (no candidate, no search) left a worker idle for that long
        cases, futures, *_ = planned["design"]

        def first_look() -> Callable | None:
            collect_cases(cases, futures)
            # judged without the campaign, which may have finished by now: which case runs again must not depend on
            # how fast the cluster went
            before_campaign = judge(replace(cases, campaign=None, campaign_store=None), criteria)
            if any(c.passed is False for c in before_campaign):
                say("convergence of the governing case")
                return convergence_started(cases, before_campaign, executor.ahead())
            return None

        converging, _ = _side_by_side([first_look, partial(campaign, "design")])
        judged = _design(cases, criteria)
        if converging is None:
            say("convergence of the governing case")
            converging = convergence_started(judged["cases"], judged["criteria"], executor.ahead())
        return judged, converging

    def search() -> dict | None:
        # a chain of steps that wait on each other: its tasks go ahead of the campaigns' batches
        ahead = executor.ahead()
        # the bearing as it stands is the design: its drop at the maximum speed is the design's own, read where
        # it ran (the search would otherwise run the same drop again)
        design_drop = max_speed_drop(planned["design"][1])
        as_built = None if design_drop is None else ahead.submit(drop_summary, design_drop)
        rec = recommend(data, name, base, criteria, quick, say, ahead, as_built)
        if rec is not None and rec["passes"]:
            _verify_recommendation(rec, data, name, base, criteria, quick, n, out_dir, ahead, address, say)
        return rec

    candidates = [label for label in planned if label != "design"]
    (design_judged, converging), *_, rec = _side_by_side(
        [design, *(partial(campaign, label) for label in candidates), search if with_recommendation else lambda: None])
    others = []
    for label in candidates:
        cases, futures, *_ = planned[label]
        if label not in collected:
            collect_cases(cases, futures)
        judged = _design(cases, criteria)
        if label in short:
            judged["criteria"] = [c._replace(evidence=f"{c.evidence} ({short[label]})")
                                  if c.name == WHIRL_PROBABILITY else c for c in judged["criteria"]]
        others.append((label, judged))
    drawing = {}
    if figures:
        say("drawing the report's figures")
        cases, futures, *_ = planned["design"]
        drawing = _draw_design_figures(cases, futures, design_judged["criteria"], criteria, executor)
    return design_judged, others, rec, converging(), _drawn(drawing)


def _draw_design_figures(cases: Cases, futures: dict, judged: list, criteria: dict, executor) -> dict:
    """The design's report figures drawn on the cluster once its runs are in: section -> [futures].

    They are queued when every run but the convergence re-run is in. Drawn in this process after the cluster
    closed, the blower's 36 figures took 14 s of one core while the other idled; here the workers draw them
    side by side, one beside the convergence re-run if it still goes. Drawn as soon as the design was judged,
    they only displaced runs (the workers are busy to the end) and the verification took as long. Each task
    reads the runs it draws where they were computed (their futures), so no dataset crosses to this process
    and back. Without a cluster nothing is drawn here: the report draws every figure when it is written.
    """
    from auxbearing.report.verify_figures import design_figure_tasks

    if executor.client is None:
        return {}
    runs = {**futures, MAX_SPEED: max_speed_drop(futures)}  # that drop may be the coast-down's own
    drawing: dict[str, list] = {}
    for key, task, args in design_figure_tasks(cases, judged, {"criteria": criteria}, runs):
        drawing.setdefault(key, []).append(executor.submit(task, *args))
    return drawing


def _drawn(drawing: dict) -> dict:
    """Section -> [(PNG as base64 text, caption)] of the figures drawn on the cluster.

    A section whose drawing failed is left out, for the report to draw (and raise the error) when it is written.
    """
    out = {}
    for key, futures in drawing.items():
        try:
            out[key] = [figure for future in futures for figure in future.result()]
        except Exception:  # the report draws the section again and raises there, with its traceback
            continue
    return out


def _verify_recommendation(rec: dict, data, name, base, criteria, quick, n, out_dir, executor, address, say) -> None:
    """Every case of the design on the recommended geometry into ``rec["verification"]``; a failing one withdrawn.

    Its drops and campaign run first and its coast-down only if they fail nothing: a geometry that already fails
    is not recommended whatever its coast-down would show, and on the blower that coast-down (at 90 um of
    clearance its drive end bounces through a pendulum passage in full dynamics) was the verification's dearest
    single run. The order is fixed, not the cluster's, so which criteria the withdrawn geometry's table leaves
    unchecked does not depend on the computer.
    """
    tables = recommended_tables(data, name, base, rec)
    title = f"{name}, recommended geometry"
    cases = plan_cases(tables, title, base, quick)
    futures = submit_cases(cases, executor, lean=True, coastdown=False)
    say(f"recommended geometry: drops and a campaign of {n} drops")
    run_campaign_of(cases, tables, title, base, n, out_dir / "campaign_recommended.zarr", None, address,
                    criteria["min_s0"], criteria["max_backward_whirl_probability"], executor.priority,
                    executor.client)
    failing = [c.name for c in judge(collect_cases(cases, futures), criteria) if c.passed is False]
    if failing:
        why = (f"the coast-down was not run: the geometry already fails on {'; '.join(failing)}, which no coast-down "
               "can change")
        cases.notes.append(why)
        cases.partial_coastdown = why
    else:
        say("recommended geometry: coast-down")
        submit_coastdown(cases, executor, futures, lean=True)
        collect_cases(cases, futures)
    checked = _design(cases, criteria)
    rec["verification"] = {"verdict": checked["verdict"], "worst_margin": checked["worst_margin"],
                           "reason": _reason(checked["criteria"]),
                           "criteria": [c.as_json() for c in checked["criteria"]]}
    if checked["verdict"] == "fail":
        # a geometry whose own verification fails is not recommended, however well its drops went
        rec["passes"] = False
        reason = rec["verification"]["reason"]
        if failing:  # what is left unchecked is the coast-down left out: said once, not criterion by criterion
            reason = (_reason([c for c in checked["criteria"] if c.passed is False])
                      + "; its coast-down was not run, since nothing it could show changes that")
        rec["note"] = f"the search's best geometry passes the drop criteria but fails its own verification: {reason}"
    elif checked["verdict"] != "pass":
        # a geometry with a criterion nobody checked is no design to sign either: a --quick look's cut runs, a missing
        # input or too small a campaign leave it the best found, not a recommendation
        open_ = [c.name for c in checked["criteria"] if c.passed is None]
        rec["passes"] = False
        rec["note"] = (f"the search's best geometry passes the drop criteria, but its own verification is INCOMPLETE: "
                       f"{len(open_)} of {len(checked['criteria'])} criteria not checked ({'; '.join(open_)}); it is "
                       "the best geometry found, not recommended")


#: What became of the geometry search, as ``verify.json``'s ``recommendation_status`` (and the recommendation's
#: ``status``) says it: only the first is a geometry to build.
RECOMMENDED = "recommended"
STATUSES = (RECOMMENDED, "not recommended: incomplete", "not recommended: fails its own verification",
            "not recommended: fails the drop criteria", "not recommended: no better than the bearing as built",
            "not recommended: not verified", "no search")


def recommendation_status(rec: dict | None) -> str:
    """Whether the search's best geometry is recommended, and if not why (one of :data:`STATUSES`).

    Recommended means its drops passed and then its own verification passed every criterion, each checked.

    >>> recommendation_status(None)
    'no search'
    >>> recommendation_status({"passes": False, "verification": {"verdict": "incomplete"}})
    'not recommended: incomplete'
    """
    if rec is None:
        return STATUSES[-1]
    verdict = (rec.get("verification") or {}).get("verdict")
    if verdict == "pass" and rec["passes"]:
        return RECOMMENDED
    if verdict == "fail":
        return STATUSES[2]
    if verdict is not None:
        return STATUSES[1]
    if rec["passes"]:  # the search's drops passed, its own verification never ran: no basis to sign
        return STATUSES[5]
    return STATUSES[3] if rec["worst_margin"] < 0.0 else STATUSES[4]


def _side_by_side(jobs: list) -> list:
    """Run ``jobs`` each in a thread of this process, all at once; their results in order.

    Each job waits on its own runs on the cluster (a campaign on its batches, the geometry search on its
    drops, a candidate's campaign first on that candidate's coast-down); side by side their tasks keep the
    cluster's queue full while this process reads stores and judges. What each computes does not depend on
    the order the cluster finishes them in (a campaign stops on its drops in design order), so the verdict
    is the same as one after another. The first error is raised at once: the jobs still running end when
    the verification's cluster closes under them, and a Ctrl-C reaches them between their batches
    (:func:`auxbearing.common.interrupt.check`).
    """
    pool = ThreadPoolExecutor(max_workers=len(jobs), thread_name_prefix="verify")
    finished = False
    try:
        futures = [pool.submit(job) for job in jobs]
        results = [future.result() for future in futures]
        finished = True
        return results
    finally:
        pool.shutdown(wait=finished, cancel_futures=not finished)


def _reason(criteria) -> str:
    from auxbearing.report.verify_html import verdict_reason

    return verdict_reason(criteria)


def _spread_value(spread: dict, end: str) -> str:
    value = spread[end] * spread["scale"]
    return f"{value:.4g} {spread['unit']}".strip()


def spread_rows(spreads: list[dict]) -> list[list[str]]:
    """The campaign's spreads as report rows: condition, range, origin."""
    return [[sp["label"], f"{_spread_value(sp, 'low')} to {_spread_value(sp, 'high')}", sp["origin"]]
            for sp in spreads]


def _assumptions(cases: Cases, criteria: dict, settings: dict, quick: bool, samples: int = 0,
                 samples_from: str = "verify.campaign_samples", rec: dict | None = None,
                 skipped: str | None = None) -> list[str]:
    from auxbearing.machine.judging import CRITERIA

    out = []
    for p in CRITERIA:
        if p.key not in criteria["given"] and criteria[p.key] is not None:
            out.append(f"criteria.{p.key}: default ({p.source})")
    for plane in cases.machine.planes:
        if plane.defaults:
            out.append(f"{plane.name}: derived from the bearing's geometry or defaulted: {', '.join(plane.defaults)}")
    out.append("low-speed drop at a quarter of the maximum speed unless verify.low_speed is given")
    for sp in cases.spreads:
        out.append(f"campaign: {sp['label']} from {_spread_value(sp, 'low')} to {_spread_value(sp, 'high')} "
                   f"({sp['origin']})")
    out += cases.notes
    if quick:
        out.append(f"--quick: shorter drops, a partial coast-down, {quick_parts(samples, samples_from, rec, skipped)}")
    return out


def quick_parts(samples: int, samples_from: str, rec: dict | None, skipped: str | None) -> str:
    """What a quick look's campaign and geometry search were, from the values they ran with.

    >>> quick_parts(8, "--quick", {"grid": [1, 2, 2]}, None)
    '8 campaign samples (--quick), a 1x2x2 design grid'
    >>> quick_parts(0, "--campaign-samples", None, None)
    'no campaign (--campaign-samples 0), no geometry search'
    """
    campaign = (f"{samples} campaign samples ({samples_from})" if samples else
                f"no campaign ({samples_from} 0)" if samples_from.startswith("--") else
                f"no campaign ({samples_from} = 0)")
    if rec is not None and rec.get("grid"):
        search = f"a {'x'.join(str(n) for n in rec['grid'])} design grid"
    else:
        search = "no geometry search" + (f" ({skipped})" if skipped else "")
    return f"{campaign}, {search}"
