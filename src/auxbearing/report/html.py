"""The study report: one self-contained HTML file (figures embedded).

The paper's study is laid beside the paper (its claims, "Paper says" boxes and numbers); a study of
the user's own bearings reports on those bearings, with the paper's numbers only when asked for and
then labelled as the paper's QJ202/7202 numbers. Results outside the model's range are listed in a
warning box at the top in either case.
"""

from __future__ import annotations

import base64
import html
import io
import json
import math
from datetime import UTC, datetime

from auxbearing import __version__
from auxbearing.common.io import to_jsonable, trim_of
from auxbearing.report.claims import CANNOT_CHECK, DOES_NOT_HOLD, HOLDS
from auxbearing.report.model import PAPER_STUDY, Framing, Section

_CSS = """
body{font-family:system-ui,-apple-system,Segoe UI,Roboto,sans-serif;max-width:1100px;margin:2em auto;padding:0 1em;
color:#222;line-height:1.45}
h1{font-size:1.6em}h2{border-bottom:2px solid #ddd;padding-bottom:.2em;margin-top:2em}
table{border-collapse:collapse;margin:1em 0;font-size:.92em}th,td{border:1px solid #ccc;padding:.35em .6em;
vertical-align:top;text-align:left}th{background:#f3f3f3}
figure{margin:1.2em 0}figure img{max-width:100%;border:1px solid #eee}figcaption{font-size:.9em;color:#444}
.paper{background:#f7f7fb;border-left:4px solid #99c;padding:.5em 1em;margin:.6em 0}
.holds{background:#e5f5e5}.does-not-hold{background:#fbe3e3}.cannot-be-checked{background:#f3f0dc}
.small{font-size:.85em;color:#555}code{background:#f3f3f3;padding:0 .2em}
.warning{background:#fdecea;border:2px solid #c62828;padding:.5em 1em;margin:1em 0}.warning h2{border:0;margin:.2em 0;
color:#c62828}.about{background:#f5f8f5;border-left:4px solid #8a8;padding:.5em 1em;margin:.6em 0}
"""


def figure_png_base64(fig) -> str:
    """PNG bytes of a matplotlib Figure as base64 text."""
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=110, **trim_of(fig))
    return base64.b64encode(buffer.getvalue()).decode("ascii")


def tidy_numbers(value):
    """A copy of nested inputs with every float cut to six significant digits, for a page a person reads.

    Unit conversions leave noise in the last digits (25.500000000000004 mm); files keep the full values.
    """
    if isinstance(value, dict):
        return {k: tidy_numbers(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [tidy_numbers(v) for v in value]
    if isinstance(value, float) and math.isfinite(value):
        return float(f"{value:.6g}")
    return value


def _e(text: object) -> str:
    return html.escape(str(text))


def _table(columns: list[str], rows: list[list[object]], caption: str = "", row_classes=None) -> str:
    head = "".join(f"<th>{_e(c)}</th>" for c in columns)
    body = []
    for i, row in enumerate(rows):
        cls = f' class="{row_classes[i]}"' if row_classes else ""
        body.append(f"<tr{cls}>" + "".join(f"<td>{_e(v)}</td>" for v in row) + "</tr>")
    cap = f"<caption>{_e(caption)}</caption>" if caption else ""
    return f"<table>{cap}<thead><tr>{head}</tr></thead><tbody>{''.join(body)}</tbody></table>"


def _verdict_class(verdict: str) -> str:
    return verdict.replace(" ", "-")


def render_report(sections: list[Section], summary_rows: list[list[str]], inputs: dict, title: str,
                  wall_time_s: float, framing: Framing = PAPER_STUDY, intro: str = "",
                  summary_columns: list[str] | None = None, skipped: dict[str, str] | None = None) -> str:
    """HTML text of the report: warnings, summary, one part per section, claims, assumptions, inputs.

    Parameters
    ----------
    sections : list of Section
    summary_rows : list of list of str
        The opening table: claims (quantity, paper, auxbearing, verdict) in the paper's study, key
        results (quantity and one column per bearing, ``summary_columns``) in a study of the user's bearings.
    inputs : dict
        The study's inputs, printed at the end.
    title : str
    wall_time_s : float
    framing : Framing
        The paper's study, or the user's bearings with or without the paper's numbers.
    intro : str
        The opening sentence (default: the paper's reproduction).
    summary_columns : list of str, optional
        Header of ``summary_rows`` when they are key results.
    skipped : dict, optional
        Stages not run, with the reason.
    """
    claims = [c for s in sections for c in s.claims]
    counts = {v: sum(c.verdict == v for c in claims) for v in (HOLDS, DOES_NOT_HOLD, CANNOT_CHECK)}
    intro = intro or ("Reproduction of <em>Performance Analysis of Auxiliary Bearing based on Four-contact-point Ball "
                      "Bearing</em> with auxbearing, and a check of its claims.")
    claims_title = "Claims of the paper" if not framing.own else "The paper's claims, its QJ202/7202 numbers"
    assumptions_title = "Parameters the paper does not give" if not framing.own else "Assumptions and defaults used"
    parts = [
        "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
        f"<title>{_e(title)}</title><style>{_CSS}</style></head><body>",
        f"<h1>{_e(title)}</h1>",
        f"<p>{intro} Generated {datetime.now(UTC):%Y-%m-%d %H:%M} UTC by auxbearing {__version__} in "
        f"{wall_time_s:.1f} s.</p>",
        _warning_box(sections),
        "<h2 id='summary'>Summary</h2>",
    ]
    if summary_columns is None:
        parts.append(_table(["quantity", "paper", "auxbearing", "verdict"], summary_rows,
                            row_classes=[_verdict_class(row[-1]) for row in summary_rows]))
    else:
        parts.append(_table(summary_columns, summary_rows))
    if claims:
        parts.append(f"<p>Claims checked: {len(claims)}: {counts[HOLDS]} hold, {counts[DOES_NOT_HOLD]} do not hold, "
                     f"{counts[CANNOT_CHECK]} cannot be checked (<a href='#claims'>table</a>).</p>")
    for key, why in (skipped or {}).items():
        parts.append(f"<p class='small'>Stage <code>{_e(key)}</code> not run: {_e(why)}</p>")
    parts.append("<ul>" + "".join(f"<li><a href='#{s.key}'>{_e(s.title)}</a></li>" for s in sections)
                 + (f"<li><a href='#claims'>{_e(claims_title)}</a></li>" if claims else "")
                 + f"<li><a href='#assumptions'>{_e(assumptions_title)}</a></li><li><a href='#inputs'>Inputs and "
                 "version</a></li></ul>")
    for section in sections:
        parts.append(_section_html(section, framing))
    if claims:
        parts.append(f"<h2 id='claims'>{_e(claims_title)}</h2>")
        if framing.own:
            parts.append("<p>The paper's numbers are for its QJ202 and 7202 on its own test rig; they are set beside "
                         "the results for the bearings of this study as asked (paper_comparison), not as a check of "
                         "them.</p>")
        parts.append(_table(
            ["section", "claim", _paper_column(framing), "auxbearing", "verdict", "why"],
            [[c.section, c.statement, c.paper, c.ours, c.verdict, c.why] for c in claims],
            row_classes=[_verdict_class(c.verdict) for c in claims],
        ))
    parts.append(f"<h2 id='assumptions'>{_e(assumptions_title)}</h2>")
    if framing.own:
        parts.append("<p>Values not read from the study file or the bearing tables, and the model's choices; the "
                     "study uses the value shown.</p>")
    else:
        parts.append("<p>Every value below is missing from the paper, ambiguous in it, or corrected from it; the "
                     "study uses the value shown.</p>")
    parts.append(_table(["parameter", "value used", "why" if not framing.own else "from"],
                        [[a.parameter, a.value, a.why] for s in sections for a in s.assumptions]))
    parts.append("<h2 id='inputs'>Inputs and version</h2>")
    parts.append(f"<p>auxbearing {__version__}. Every data file (NetCDF, JSON) in this folder carries the same "
                 "inputs and version in its attributes.</p>")
    # the shared encoder's "inf", as the data files beside the page write it (json alone writes bare Infinity)
    shown = json.dumps(to_jsonable(tidy_numbers(inputs)), indent=2, default=str, allow_nan=False)
    parts.append(f"<pre class='small'>{_e(shown)}</pre>")
    parts.append("</body></html>")
    return "\n".join(parts)


def _paper_column(framing: Framing) -> str:
    return "paper" if not framing.own else "paper (its QJ202/7202)"


def _warning_box(sections: list[Section]) -> str:
    """Results outside the model's range, by stage, in a box at the top (empty when there are none)."""
    items = [f"<li><strong>{_e(s.title)}:</strong> {_e(w)}</li>" for s in sections for w in s.warnings]
    if not items:
        return ""
    return ("<div class='warning' id='warnings'><h2>Results outside the model's range</h2><p>Above ISO 76's 4200 MPa "
            "(s0 &lt; 1) the raceways deform permanently and the elastic results are estimates only; a run stopped "
            "outside the model's range has no peaks.</p><ul>" + "".join(items) + "</ul></div>")


def _section_html(section: Section, framing: Framing = PAPER_STUDY) -> str:
    out = [f"<h2 id='{_e(section.key)}'>{_e(section.title)}</h2>"]
    if section.about:
        out.append(f"<div class='about'>{_e(section.about)}</div>")
    if section.paper and framing.paper:
        out.append(f"<div class='paper'><strong>{_e(framing.paper_label)}:</strong> {_e(section.paper)}</div>")
    for note in section.notes:
        out.append(f"<p>{_e(note)}</p>")
    for fig in section.figures:
        data = figure_png_base64(fig.figure)
        says = (f"<br><strong>{_e(framing.paper_label)} says:</strong> {_e(fig.paper_says)}"
                if fig.paper_says and framing.paper else "")
        if fig.paper_says and not framing.paper:  # a note of our own on the figure
            says = f"<br>{_e(fig.paper_says)}"
        out.append(f"<figure><img alt='{_e(fig.caption)}' src='data:image/png;base64,{data}'>"
                   f"<figcaption>{_e(fig.caption)}{says}</figcaption></figure>")
    for table in section.tables:
        out.append(_table(table["columns"], table["rows"], table.get("caption", "")))
    if section.claims:
        out.append("<h3>Claims in this section</h3>")
        out.append(_table(["claim", _paper_column(framing), "auxbearing", "verdict"],
                          [[c.statement, c.paper, c.ours, c.verdict] for c in section.claims],
                          row_classes=[_verdict_class(c.verdict) for c in section.claims]))
    return "\n".join(out)
