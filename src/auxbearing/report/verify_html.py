"""The verification report: one self-contained HTML file, verdicts first, then the evidence.

Order: the verdict and why; the machine at a glance; the verdict table (criterion, required, found, margin,
pass/fail); the evidence of every criterion with its figures (drops, coast-down, campaign); the candidate
bearings ranked; the recommended geometry and what binds it; the assumptions and defaults used; inputs and
version. Nothing of the source paper appears unless the machine is the paper's rig (the paper reproduction
is linked: ``auxbearing study``).
"""

from __future__ import annotations

import json
import math
from datetime import UTC, datetime

from auxbearing import __version__
from auxbearing.common.io import to_jsonable
from auxbearing.common.params import display_value
from auxbearing.machine.judging import CRITERIA
from auxbearing.machine.params import COASTDOWN, LIFE, SIMULATION
from auxbearing.report.html import _CSS, _e, _table, figure_png_base64, tidy_numbers

_EXTRA_CSS = """
pre{white-space:pre-wrap;word-break:break-word}
.pass{background:#e5f5e5}.fail{background:#fbe3e3}.unchecked{background:#f3f0dc}
.banner{font-size:1.3em;padding:.6em 1em;border-radius:6px;margin:1em 0}
.banner.pass{border:2px solid #4a4}.banner.fail{border:2px solid #c44}.banner.incomplete{border:2px solid #b90}
"""



def _fmt(value, unit: str = "") -> str:
    if value is None:
        return "-"
    if isinstance(value, bool):
        return "yes" if value else "no"
    if isinstance(value, (int, float)):
        if isinstance(value, float) and not math.isfinite(value):
            return "∞" if value > 0 else "-∞"
        text = f"{value:.4g}"
        return text if unit in ("", "-") else f"{text} {unit}"
    return str(value)


def _margin(value) -> str:
    """A margin as the report prints it; "-" where no checked criterion has one (the worst margin is then NaN).

    >>> _margin(0.051), _margin(float("nan")), _margin(None), _margin(float("inf")), _margin(float("-inf"))
    ('+5.1 %', '-', '-', '∞', '-∞')
    """
    if value is None or math.isnan(value):
        return "-"
    if math.isinf(value):
        return "∞" if value > 0 else "-∞"
    return f"{100.0 * value:+.1f} %"


def _figure(fig, caption: str) -> str:
    """A figure (or its PNG as base64 text, drawn already) with its caption."""
    png = fig if isinstance(fig, str) else figure_png_base64(fig)
    return (f"<figure><img alt='{_e(caption)}' src='data:image/png;base64,{png}'>"
            f"<figcaption>{_e(caption)}</figcaption></figure>")


def verdict_rows(criteria: list) -> tuple[list[list[str]], list[str]]:
    """Rows of the verdict table and their classes."""
    rows, classes = [], []
    for c in criteria:
        status = "not checked" if c.passed is None else ("pass" if c.passed else "FAIL")
        rows.append([c.name, _fmt(c.required, c.unit), _fmt(c.found, c.unit), _margin(c.margin), status])
        classes.append("unchecked" if c.passed is None else ("pass" if c.passed else "fail"))
    return rows, classes


def verdict_reason(criteria: list) -> str:
    """Why the design passes, fails or is incomplete, in one sentence.

    FAIL names every failing criterion with its evidence, then those not checked by name (mending the failures
    does not make a pass while they stay open); INCOMPLETE names every criterion not checked and how to check it
    (its evidence says); PASS says every criterion holds.
    """
    failing = [c for c in criteria if c.passed is False]
    unchecked = [c for c in criteria if c.passed is None]
    if failing:
        reason = "fails on " + "; ".join(f"{c.name} ({_fmt(c.found, c.unit)} against {_fmt(c.required, c.unit)}: "
                                         f"{c.evidence})" for c in failing)
        if unchecked:
            reason += (f"; besides, {len(unchecked)} of {len(criteria)} are not checked: "
                       + ", ".join(c.name for c in unchecked))
        return reason
    if unchecked:
        return (f"no checked criterion fails, but {len(unchecked)} of {len(criteria)} are not checked: "
                + "; ".join(_unchecked_clauses(unchecked)))
    return f"all {len(criteria)} criteria hold"


#: How the evidence of a criterion that a cut run passed ends (auxbearing.verify.judge._unsettled): "; " + the cut.
_NOT_A_PASS = ", so this is not a pass"


def _unchecked_clauses(unchecked: list) -> list[str]:
    """A clause a criterion not checked, with its evidence; those that one cut run passed as one clause.

    A --quick look cuts its drops and its coast-down: nine criteria would each repeat one of the two cuts. They are
    named together, with the cut once (each one's own finding stays in the table).
    """
    shared: dict[str, list] = {}
    for c in unchecked:
        _, sep, cut = c.evidence.rpartition("; ")
        if sep and cut.endswith(_NOT_A_PASS):
            shared.setdefault(cut.removesuffix(_NOT_A_PASS), []).append(c)
    clauses, done = [], set()
    for c in unchecked:
        cut = next((cut for cut, group in shared.items() if c in group and len(group) > 1), None)
        if cut is None:
            clauses.append(f"{c.name} ({c.evidence})")
        elif cut not in done:
            done.add(cut)
            clauses.append(f"{', '.join(g.name for g in shared[cut])} ({cut}, so none of them is a pass)")
    return clauses


def no_campaign(result: dict) -> str:
    """The report's line for a verification without a campaign, naming where its size of 0 came from.

    >>> no_campaign({"campaign_samples_from": "verify.campaign_samples"})
    'No campaign was run (verify.campaign_samples = 0).'
    >>> no_campaign({"campaign_samples_from": "--campaign-samples"})
    'No campaign was run (--campaign-samples 0).'
    """
    source = result.get("campaign_samples_from", "--campaign-samples")
    return f"No campaign was run ({source} 0)." if source.startswith("--") else f"No campaign was run ({source} = 0)."


def render(result: dict, figures: dict[str, list[tuple[object, str]]]) -> str:
    """HTML text of the report from the result of :func:`auxbearing.verify.run.verify` and its figures.

    ``figures`` maps a section key (machine, drops, coastdown, campaign, candidates, recommendation) to a
    list of (matplotlib Figure or its PNG as base64 text, caption).
    """
    main = result["design"]
    verdict = result["verdict"]
    why = verdict_reason(main["criteria"])
    parts = ["<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
             f"<title>Touchdown-bearing verification: {_e(result['machine'])}</title>",
             f"<style>{_CSS}{_EXTRA_CSS}</style></head><body>",
             f"<h1>Touchdown-bearing verification: {_e(result['machine'])}</h1>",
             f"<div class='banner {verdict}'><b>Verdict: {verdict.upper()}</b> "
             f"&mdash; {_e(why)}</div>"]
    if result.get("quick"):
        parts.append("<p class='paper'>A <b>--quick</b> first look: short drops, the first seconds of the "
                     "coast-down and a small campaign. Run without --quick before you rely on it.</p>")
    parts.append("<h2>The machine at a glance</h2>")
    parts += [_figure(f, c) for f, c in figures.get("machine", [])]
    if figures.get("modes"):
        parts.append("<h3>Natural frequencies and critical speeds</h3>")
        parts += [_figure(f, c) for f, c in figures["modes"]]
    rows, classes = verdict_rows(main["criteria"])
    parts.append("<h2>Verdicts</h2>")
    parts.append(_table(["criterion", "required", "found", "margin", "pass/fail"], rows,
                        "Margin: " + "; ".join(f"{kind}: {text}" for kind, text in result["margins"].items()
                                               if kind not in ("yes/no", "not checked")) + ".",
                        classes))
    parts += [_figure(f, c) for f, c in figures.get("criteria", [])]
    conv = result.get("convergence")
    if conv:
        parts.append("<h3>Convergence of the governing result</h3>")
        unit = conv.get("unit", "")
        parts.append(_table(["criterion", "case run again", "quantity", "as run", "tolerances 10x tighter",
                             "change", "converged"],
                            [[conv["criterion"], conv["case"], conv["quantity"], _fmt(conv["as_run"], unit),
                              _fmt(conv["tightened"], unit), "-" if conv["change"] is None else
                              f"{100 * conv['change']:+.2f} %", _fmt(conv["settled"])]], conv["note"]))
    parts.append("<h3>Where each required value comes from, and the evidence</h3>")
    parts.append(_table(["criterion", "required value from", "evidence"],
                        [[c.name, c.origin or "-", c.evidence] for c in main["criteria"]]))
    parts.append("<h2>Evidence: the drops</h2>")
    parts.append(_table(["case", "plane", "verdict", "peak force [N]", "peak stress [MPa]", "s0", "axial peak [N]",
                         "whirl at the end", "backward whirl onset [ms]"], main["drop_rows"]))
    parts += [_figure(f, c) for f, c in figures.get("drops", [])]
    if main.get("scenario_rows"):
        parts.append("<h2>Evidence: the magnetic bearings' scenarios</h2>")
        parts.append(_table(["scenario", "kind", "strikes at [ms]", "outcome", "first contact [ms]",
                             "re-levitated at [ms]", "peak current per axis",
                             "time at the current limit [ms] (the longest of the bearings)"],
                            main["scenario_rows"], "Each scenario starts from the levitated rotor. Outcome: no "
                            "touchdown; re-levitated (no contact in the last fifth of the run after the strike); not "
                            "settled (touching now and then at the end: a longer run tells); held in contact or in "
                            "sustained whirl (the bearings on, the rotor touching through the end); on the touchdown "
                            "bearings (a bearing without power at the end)."))
        parts += [_figure(f, c) for f, c in figures.get("scenarios", [])]
    parts.append("<h2>Evidence: the coast-down with heat</h2>")
    parts.append(_table(["plane", "hottest part [°C]", "smallest journal/race clearance [µm]",
                         "smallest internal clearance [µm]", "damage per drop", "drops to failure",
                         "drops to dent limit", "governs"], main["coastdown_rows"],
                        main.get("coastdown_caption", "")))
    parts += [_figure(f, c) for f, c in figures.get("coastdown", [])]
    parts.append("<h2>Evidence: the campaign over the drop conditions</h2>")
    if main.get("campaign_rows"):
        parts.append(_table(["quantity", "value", "two-sided 95 % interval (Wilson)", "among"],
                            main["campaign_rows"]))
        if main.get("spread_rows"):
            parts.append(_table(["uncontrolled condition", "spread (uniform)", "where the spread comes from"],
                                main["spread_rows"], "The drop conditions the campaign varies; set them in [verify]."))
        drivers = main.get("drivers")
        if drivers:
            parts.append(_table(drivers["columns"], drivers["rows"], drivers["caption"]))
        else:
            parts.append("<p>No outcome of the campaign varied enough to rank what drives it.</p>")
        parts += [_figure(f, c) for f, c in figures.get("campaign", [])]
    else:
        parts.append(f"<p>{_e(no_campaign(result))}</p>")
    if result.get("candidates"):
        parts.append("<h2>Candidate bearings in the same seats</h2>")
        parts.append(_table(["rank", "bearing", "verdict", "worst margin", "failing criteria"],
                            result["candidate_rows"],
                            "Ranked by the criteria failed, then those not checked, then the worst margin of the "
                            "checked ones; designs alike in all three by the margins their unchecked findings show, "
                            "worst first" + (f"; {result['ranking_whirl_term']}" if result.get("ranking_whirl_term")
                                             else "") + "."))
        parts += [_figure(f, c) for f, c in figures.get("candidates", [])]
    if result.get("recommendation_note"):
        parts.append("<h2>Recommendation: geometry of the bearing family</h2>")
        parts.append(f"<p><b>No geometry search:</b> {_e(result['recommendation_note'])}.</p>")
    if result.get("recommendation"):
        rec = result["recommendation"]
        parts.append("<h2>Recommendation: geometry of the bearing family</h2>")
        parts.append(f"<p>For the {_e(rec['family'].replace('_', ' '))} family, over contact angle "
                     f"{rec['bounds']['contact_angle_deg'][0]:.0f}-{rec['bounds']['contact_angle_deg'][1]:.0f} deg, "
                     f"inner groove ratio {rec['bounds']['inner_groove_ratio'][0]:.3f}-"
                     f"{rec['bounds']['inner_groove_ratio'][1]:.3f} and {rec['bounds']['clearance_factor'][0]:.2f}-"
                     f"{rec['bounds']['clearance_factor'][1]:.2f} times the radial clearance "
                     f"({rec['evaluations']} drops at the maximum speed"
                     + (f"; {rec['left_out']} more points were not run, as their clearance alone keeps their margin "
                        "against the air gap below the best point's" if rec.get("left_out") else "") + "):</p>")
        if not rec["passes"]:
            parts.append(f"<p class='fail'><b>No recommendation:</b> {_e(rec['note'])}. The table shows the "
                         f"{_e(_best_found(rec))} point found, not a design to build.</p>")
        point = "recommended" if rec["passes"] else f"{_best_found(rec)} found, not recommended"
        parts.append(_table(["quantity", point, "as the file has it"], result["recommendation_rows"]))
        binds = rec["binding_criterion"] + (
            f"; at the bound of {', '.join(rec['variables_at_bounds'])}" if rec["variables_at_bounds"] else "")
        parts.append(f"<p><b>What binds:</b> {_e(binds)}. Worst margin {_margin(rec['worst_margin'])} against "
                     f"{_margin(rec['as_is'])} as built.</p>")
        parts.append("<p class='small'>Each point of the search is judged by its drop at the maximum speed on the "
                     "verdict's own criteria a drop checks (s0, the model's range, backward whirl, the seal and the "
                     "air gap, each margin as in the verdict table but the air gap's, which takes the travel of this "
                     "one drop, where the verdict takes every case drop's, the campaign's and the coast-down's "
                     "thermal opening); the best point has the largest smallest "
                     f"margin, and of points that tie on it (within {rec.get('tie_margin', 0.0) * 100:g} "
                     "percentage point) the largest next smallest, and so on. The "
                     "coast-down and the campaign would need a whole verification per point, so the best point "
                     "gets one instead, and is recommended only if it passes every criterion, each checked:</p>")
        checked = rec.get("verification")
        if checked:
            whose = "the recommended geometry" if rec["passes"] else "the best geometry found (not recommended)"
            parts.append(f"<div class='banner {checked['verdict']}'><b>Verification of {whose}: "
                         f"{checked['verdict'].upper()}</b> &mdash; {_e(checked['reason'])} (worst margin "
                         f"{_margin(checked['worst_margin'])}; the design as built: "
                         f"{verdict.upper()}, {_margin(main['worst_margin'])})</div>")
        parts += [_figure(f, c) for f, c in figures.get("recommendation", [])]
    parts.append("<h2>Assumptions and defaults used</h2><ul>")
    parts += [f"<li>{_e(a)}</li>" for a in result["assumptions"]]
    parts.append("</ul>")
    parts.append("<h2>Inputs and version</h2>")
    parts.append(f"<p class='small'>auxbearing {__version__}, {datetime.now(UTC):%Y-%m-%d %H:%M} UTC, "
                 f"{result['wall_time_s']:.0f} s. The reproduction of the source paper is a separate command: "
                 "<code>auxbearing study</code>.</p>")
    inputs_text = json.dumps(to_jsonable(readable_inputs(result["inputs"])), indent=1, default=str, allow_nan=False)
    parts.append(f"<pre class='small'>{_e(inputs_text)}</pre>")  # "inf" as verify.json has it, not bare Infinity
    parts.append("</body></html>")
    return "".join(parts)


def _best_found(rec: dict) -> str:
    """What the search's point is when it is not recommended: the least bad (it fails a criterion) or the best.

    >>> _best_found({"worst_margin": -1.0}), _best_found({"worst_margin": 0.3, "verification": {"verdict": "fail"}})
    ('least bad', 'least bad')
    >>> _best_found({"worst_margin": 0.3, "verification": {"verdict": "incomplete"}})
    'best'
    """
    fails = rec["worst_margin"] < 0.0 or (rec.get("verification") or {}).get("verdict") == "fail"
    return "least bad" if fails else "best"


#: Tables of the inputs whose values are read through a parameter row, by where they sit in ``inputs``.
_ROWS = {("machine", "drop"): SIMULATION, ("machine", "coastdown"): COASTDOWN, ("machine", "life"): LIFE,
         ("criteria",): CRITERIA}


def readable_inputs(inputs: dict) -> dict:
    """The verification's inputs as a person reads them.

    Each parameter-table value is in its display unit ("0.5 mm", "120 degC"), every other number is cut
    to six significant digits (no 18.000000000000004); ``verify.json`` keeps the full values.
    """
    out = tidy_numbers(inputs)
    for path, rows in _ROWS.items():
        table = out
        for key in path:
            table = table.get(key) if isinstance(table, dict) else None
        if not isinstance(table, dict):
            continue
        for row in rows:
            if row.key in table and table[row.key] is not None:
                table[row.key] = display_value(row, table[row.key])
    return out
