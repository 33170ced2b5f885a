"""The study: every stage of the paper, one report, data and figures, in one call.

Stages are entries in :data:`STAGES` (a registry, not an if/elif chain): each takes the
:class:`~auxbearing.paper.study_config.StudyConfig` and returns a report
:class:`~auxbearing.report.model.Section`, or None when it does not apply to the study.

Without a study file, or with one that keeps the paper's bearings, rotor and drop, the study is the
paper's: captioned and judged with the paper's numbers. A study of the user's own bearings reports on
those bearings (captions from the study file, a summary of key results, no claims) and shows the
paper's QJ202/7202 numbers beside them only with ``paper_comparison``.
"""

from __future__ import annotations

import html
import time
from collections.abc import Callable
from pathlib import Path

from auxbearing import __version__
from auxbearing.common.io import atomic_output_dir, save_dataset, save_figure, write_json
from auxbearing.paper.study_config import StudyConfig
from auxbearing.paper.study_contact import run_contact_stage
from auxbearing.paper.study_drop import run_drop_stage
from auxbearing.paper.study_static import run_static_stage
from auxbearing.report.claims import HOLDS
from auxbearing.report.html import render_report
from auxbearing.report.model import Section

#: Why the experiment stage is left out of a study of the user's own bearings.
EXPERIMENT_SKIPPED = ("it analyses the shipped SYNTHETIC drop records made for the source paper's bearings, not "
                      "drops of the bearings of this study; analyse a measured drop of your own with "
                      "`auxbearing experiment --measured FILE`")


def _contact(config: StudyConfig) -> Section:
    return run_contact_stage(config.bearing, config.ball_load, config.angle_grid(), config.ratio_grid(),
                             comparison=config.comparison, framing=config.framing())


def _static(config: StudyConfig) -> Section:
    return run_static_stage(config.bearing, config.comparison, framing=config.framing())


def _drop(config: StudyConfig) -> Section:
    return run_drop_stage(config.bearing, config.comparison, config.sections, framing=config.framing())


def _experiment(config: StudyConfig) -> Section | None:
    if config.own_bearings:
        return None
    from auxbearing.paper.experiment_stage import experiment_stage

    return experiment_stage(config)


#: (key, label shown in the progress bar, stage function)
STAGES: list[tuple[str, str, Callable[[StudyConfig], Section | None]]] = [
    ("contact", "Hertz contact (Fig. 2-4)", _contact),
    ("static", "Load distribution (Fig. 6-8)", _static),
    ("drop", "Rotor drop (Fig. 10-11) and sweeps", _drop),
    ("experiment", "Drop experiment pipeline (Sec. III, synthetic data)", _experiment),
]


def summary_rows(sections: list[Section]) -> list[list[str]]:
    """The paper study's opening table: the paper's headline numbers beside ours."""
    rows = []
    for section in sections:
        for claim in section.claims:
            if claim.paper != "qualitative":
                rows.append([claim.statement, claim.paper, claim.ours, claim.verdict])
    return rows


def key_result_rows(sections: list[Section]) -> list[list[str]]:
    """An own-bearing study's opening table: each stage's key results for the two bearings."""
    return [row for section in sections for row in section.key_results]


def _intro(config: StudyConfig) -> str:
    framing = config.framing()
    if not framing.own:
        return ""
    text = (f"A study of {html.escape(config.bearing.name)} (four-point contact) against "
            f"{html.escape(config.comparison.name)} (angular contact) as auxiliary bearings: contact stress, load "
            "distribution and rotor drop, computed with auxbearing.")
    if framing.paper:
        text += (" As asked (paper_comparison), the paper's numbers for its own QJ202 and 7202 are set beside the "
                 "results, labelled as the paper's.")
    return text


def run_study(config: StudyConfig, out_dir: str | Path, progress: Callable[[str], None] | None = None,
              stages: list[str] | None = None) -> dict:
    """Run the study and write report.html, results.json, NetCDF data and PNG/PDF figures to ``out_dir``.

    Parameters
    ----------
    config : StudyConfig
    out_dir : path
        Output folder; written atomically (nothing is left behind if a stage fails).
    progress : callable, optional
        Called with the label of each stage as it starts.
    stages : list of str, optional
        Keys of :data:`STAGES` to run (default all).

    Returns
    -------
    dict
        The contents of results.json.
    """
    start = time.perf_counter()
    inputs = config.describe()
    framing = config.framing()
    sections: list[Section] = []
    timings: dict[str, float] = {}
    skipped: dict[str, str] = {}
    for key, label, stage in STAGES:
        if stages is not None and key not in stages:
            continue
        if key == "experiment" and config.own_bearings:
            skipped[key] = EXPERIMENT_SKIPPED
            continue
        if progress is not None:
            progress(label if not framing.own else label.split(" (")[0])
        t0 = time.perf_counter()
        section = stage(config)
        timings[key] = time.perf_counter() - t0
        if section is not None:
            sections.append(section)
    with atomic_output_dir(out_dir) as tmp:
        for section in sections:
            for name, ds in section.datasets.items():
                save_dataset(ds, tmp / f"{name}.nc", inputs)
            for fig in section.figures:
                save_figure(fig.figure, tmp / fig.name, formats=("png", "pdf"))
        wall = time.perf_counter() - start
        if framing.own:
            columns = ["quantity", f"{config.bearing.name} (four-point)", f"{config.comparison.name} (angular contact)"]
            report = render_report(sections, key_result_rows(sections), inputs, config.title, wall, framing=framing,
                                   intro=_intro(config), summary_columns=columns, skipped=skipped)
        else:
            report = render_report(sections, summary_rows(sections), inputs, config.title, wall, skipped=skipped)
        (tmp / "report.html").write_text(report)
        claims = [c.as_dict() for s in sections for c in s.claims]
        results = {
            "title": config.title,
            "study_of": "own bearings" if framing.own else "the paper's bearings",
            "paper_comparison": framing.paper,
            "warnings": [f"{s.title}: {w}" for s in sections for w in s.warnings],
            "skipped_stages": skipped,
            "auxbearing_version": __version__,
            "wall_time_s": time.perf_counter() - start,
            "stage_times_s": timings,
            "claims": claims,
            "claims_hold": sum(c["verdict"] == HOLDS for c in claims),
            "claims_total": len(claims),
            "assumptions": [a.as_dict() for s in sections for a in s.assumptions],
            "results": {s.key: s.results for s in sections},
            "files": [*sorted(p.name for p in tmp.iterdir()), "results.json"],
        }
        write_json(results, tmp / "results.json", inputs)
    return results
