"""The study report: one self-contained HTML file (figures embedded) laid beside the paper."""

from __future__ import annotations

import base64
import html
import io
import json
from datetime import UTC, datetime

from auxbearing import __version__
from auxbearing.paper.claims import CANNOT_CHECK, DOES_NOT_HOLD, HOLDS
from auxbearing.report.model import Section

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
"""


def figure_png_base64(fig) -> str:
    """PNG bytes of a matplotlib Figure as base64 text."""
    buffer = io.BytesIO()
    fig.savefig(buffer, format="png", dpi=110, bbox_inches="tight")
    return base64.b64encode(buffer.getvalue()).decode("ascii")


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
                  wall_time_s: float) -> str:
    """HTML text of the report: summary, one part per section, claims, assumptions, inputs."""
    claims = [c for s in sections for c in s.claims]
    counts = {v: sum(c.verdict == v for c in claims) for v in (HOLDS, DOES_NOT_HOLD, CANNOT_CHECK)}
    parts = [
        "<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
        f"<title>{_e(title)}</title><style>{_CSS}</style></head><body>",
        f"<h1>{_e(title)}</h1>",
        "<p>Reproduction of <em>Performance Analysis of Auxiliary Bearing based on Four-contact-point Ball "
        "Bearing</em> with auxbearing, and a check of its claims. Generated "
        f"{datetime.now(UTC):%Y-%m-%d %H:%M} UTC by auxbearing {__version__} in {wall_time_s:.1f} s.</p>",
        "<h2 id='summary'>Summary</h2>",
        _table(["quantity", "paper", "auxbearing", "verdict"], summary_rows,
               row_classes=[_verdict_class(row[-1]) for row in summary_rows]),
        f"<p>Claims checked: {len(claims)}: {counts[HOLDS]} hold, {counts[DOES_NOT_HOLD]} do not hold, "
        f"{counts[CANNOT_CHECK]} cannot be checked (<a href='#claims'>table</a>).</p>",
        "<ul>" + "".join(f"<li><a href='#{s.key}'>{_e(s.title)}</a></li>" for s in sections)
        + "<li><a href='#claims'>Claims of the paper</a></li><li><a href='#assumptions'>Parameters the paper "
        "does not give</a></li><li><a href='#inputs'>Inputs and version</a></li></ul>",
    ]
    for section in sections:
        parts.append(_section_html(section))
    parts.append("<h2 id='claims'>Claims of the paper</h2>")
    parts.append(_table(
        ["section", "claim", "paper", "auxbearing", "verdict", "why"],
        [[c.section, c.statement, c.paper, c.ours, c.verdict, c.why] for c in claims],
        row_classes=[_verdict_class(c.verdict) for c in claims],
    ))
    parts.append("<h2 id='assumptions'>Parameters the paper does not give</h2>")
    parts.append("<p>Every value below is missing from the paper, ambiguous in it, or corrected from it; the "
                 "study uses the value shown.</p>")
    parts.append(_table(["parameter", "value used", "why"],
                        [[a.parameter, a.value, a.why] for s in sections for a in s.assumptions]))
    parts.append("<h2 id='inputs'>Inputs and version</h2>")
    parts.append(f"<p>auxbearing {__version__}. Every data file (NetCDF, JSON) in this folder carries the same "
                 "inputs and version in its attributes.</p>")
    parts.append(f"<pre class='small'>{_e(json.dumps(inputs, indent=2, default=str))}</pre>")
    parts.append("</body></html>")
    return "\n".join(parts)


def _section_html(section: Section) -> str:
    out = [f"<h2 id='{_e(section.key)}'>{_e(section.title)}</h2>",
           f"<div class='paper'><strong>Paper:</strong> {_e(section.paper)}</div>"]
    for note in section.notes:
        out.append(f"<p>{_e(note)}</p>")
    for fig in section.figures:
        data = figure_png_base64(fig.figure)
        says = f"<br><strong>Paper says:</strong> {_e(fig.paper_says)}" if fig.paper_says else ""
        out.append(f"<figure><img alt='{_e(fig.caption)}' src='data:image/png;base64,{data}'>"
                   f"<figcaption>{_e(fig.caption)}{says}</figcaption></figure>")
    for table in section.tables:
        out.append(_table(table["columns"], table["rows"], table.get("caption", "")))
    if section.claims:
        out.append("<h3>Claims in this section</h3>")
        out.append(_table(["claim", "paper", "auxbearing", "verdict"],
                          [[c.statement, c.paper, c.ours, c.verdict] for c in section.claims],
                          row_classes=[_verdict_class(c.verdict) for c in section.claims]))
    return "\n".join(out)
