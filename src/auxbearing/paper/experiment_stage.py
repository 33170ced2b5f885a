"""Experiment stage of the study: the pipeline on the SYNTHETIC example drops, and Sec. III's claims.

The paper's measured orbits (Fig. 13) are published only as pictures and its way from orbit to
stress is not described, so its measured-stress numbers (1728 MPa QJ202, 2348 MPa 7202 with a
40 deg contact angle) cannot be checked. What this stage can show is the pipeline at work on
data whose truth is known: SYNTHETIC drops made by our own simulation with sensor offset,
noise and filtering on top (:mod:`auxbearing.experiment.synth`).
"""

from __future__ import annotations

from pathlib import Path

from auxbearing.experiment.run import run_experiment
from auxbearing.experiment.synth import EXAMPLE_DIR
from auxbearing.planar.params import DropCase, Rotor, from_mapping
from auxbearing.report.claims import CANNOT_CHECK, Assumption, Claim
from auxbearing.report.model import Figure, Section

#: Source paper Sec. III: max stress computed from the measured drops.
PAPER_EXPERIMENT = {"QJ202_MPa": 1728.0, "7202_40deg_MPa": 2348.0, "simulated_QJ202_MPa": 1483.0}

#: The shipped SYNTHETIC example drops: (bearing, file).
EXAMPLES = (("QJ202", EXAMPLE_DIR / "qj202_drop_synthetic.csv"),
            ("7202-40", EXAMPLE_DIR / "7202-40_drop_synthetic.csv"))

SYNTHETIC_NOTE = ("The data in this section are SYNTHETIC, not measurements: no measured drop of a QJ202 or a 7202 "
                  "is public. They were made by our drop simulation (true μ₁ = 0.15, s = 0.18 mm, unbalance phase "
                  "40°, damping and rolling friction off the values the fit assumes) with a sensor offset, white "
                  "noise, a causal 10 kHz anti-alias filter and 50 kHz sampling on top. They show that the pipeline "
                  "works and what it recovers; they say nothing about the paper's test rig.")


def experiment_stage(config=None, examples=EXAMPLES) -> Section:
    """Run the experiment pipeline on the example drops and return the report section.

    Parameters
    ----------
    config : StudyConfig, optional
        Its ``[rotor]`` and ``[drop]`` tables, when present, set the simulated case.
    examples : sequence of (bearing, path)
        Drops to analyse; the first is fitted and plotted in full.

    Returns
    -------
    Section
        Figures (orbits, force and stress, fitted stretch), a recovery table, a peak table per
        drop, the Sec. III claims (all "cannot be checked") and the assumptions.
    """
    sections = getattr(config, "sections", {}) or {}
    rotor = Rotor(**from_mapping(sections.get("rotor"), "rotor"))
    case = DropCase(**from_mapping(sections.get("drop"), "drop"))
    from auxbearing.plots.experiment import experiment_figures  # here: matplotlib takes a second to import

    results, figures, tables, data = {}, [], [], {}
    for k, (bearing, path) in enumerate(examples):
        datasets, summary, drawing = run_experiment(Path(path), bearing, rotor, case, fit=True)
        figs = experiment_figures(drawing)
        results[bearing] = summary
        data[f"experiment_{bearing.lower().replace('-', '_')}"] = datasets["measured"]
        table = summary["peak_table"]
        tables.append({"columns": table["columns"], "rows": table["rows"],
                       "caption": f"{bearing}, SYNTHETIC drop: peaks from the orbit ('measured') and from the "
                                  "simulations (exact, and seen through the same sensor filter and orbit pipeline)"})
        if "recovery" in summary:
            tables.append(_recovery_table(bearing, summary))
        for name, fig in figs.items():
            if k > 0 and name != "experiment_orbits":
                continue
            figures.append(Figure(f"{name}_{bearing.lower().replace('-', '_')}",
                                  f"{bearing}, SYNTHETIC drop: {_CAPTIONS[name]}", fig, _PAPER_SAYS[name]))
    qj, ac = results[examples[0][0]], results[examples[-1][0]]
    s_qj, s_ac = qj["measured"]["peak_ball_stress_MPa"], ac["measured"]["peak_ball_stress_MPa"]
    why = ("The paper's orbits are pictures only and its orbit-to-stress method is not described; our number comes "
           "from SYNTHETIC data made by our own simulation, so it is no check of the paper.")
    claims = [
        Claim("III", "Max stress from the measured drop, four-point bearing (QJ202)",
              f"{PAPER_EXPERIMENT['QJ202_MPa']:g} MPa", f"{s_qj:.0f} MPa from the SYNTHETIC QJ202 drop", CANNOT_CHECK,
              why),
        Claim("III", "Max stress from the measured drop, angular-contact bearing (7202, 40 deg)",
              f"{PAPER_EXPERIMENT['7202_40deg_MPa']:g} MPa", f"{s_ac:.0f} MPa from the SYNTHETIC 7202-40 drop",
              CANNOT_CHECK, why),
        Claim("III", "The measured 1728 MPa (QJ202) is close to the simulated 1483 MPa",
              f"{PAPER_EXPERIMENT['QJ202_MPa']:g} vs {PAPER_EXPERIMENT['simulated_QJ202_MPa']:g} MPa",
              f"{s_qj:.0f} MPa from the orbit vs {qj['simulated']['sim fitted']['peak_ball_stress_MPa']:.0f} MPa "
              "simulated with the fitted parameters (SYNTHETIC)", CANNOT_CHECK,
              "Needs the paper's measured orbit. On synthetic data the agreement only shows that the orbit-to-stress "
              "pipeline is consistent with the simulation that made the data."),
        Claim("III", "Experiment and simulation agree: max stress of the four-point bearing below the angular-contact",
              "qualitative", f"SYNTHETIC drops: {s_qj:.0f} MPa (QJ202) vs {s_ac:.0f} MPa (7202-40)", CANNOT_CHECK,
              "The experimental half needs measured data; on synthetic data the order is that of our simulation."),
    ]
    assumptions = [
        Assumption("Example data", "SYNTHETIC drops (catalog/experiments/*.csv)", SYNTHETIC_NOTE),
        Assumption("Race displacement (not measured)", "quasi-static series split of the excursion beyond the "
                   "clearance between line contact (Eq. 19) and ball set (Eq. 22)",
                   "The race rings at ~10 kHz on the ball set, above an impact's ~2.5 kHz."),
        Assumption("Sensor offset", "levitated position before the drop = bearing centre",
                   "The paper: 'suppose the rotor falls from the center'; a circle fit to the orbit is offered too."),
        Assumption("Fitted parameters", "μ₁, s, unbalance phase and the drop moment, on the first 12 ms",
                   "Later the rattle is chaotic: tiny changes move every impact; the least-squares problem turns "
                   "rough."),
    ]
    return Section(
        key="experiment", title="Experiment (Sec. III, Fig. 12-13) — SYNTHETIC data",
        paper="Rotor spinning at 6000 rpm dropped onto a QJ202 and a 7202 (40°); orbits recorded; max stress computed "
              "from them: 1728 MPa (QJ202) vs 2348 MPa (7202).",
        figures=figures, tables=tables, datasets=data, claims=claims, assumptions=assumptions,
        results={"synthetic": True, **{k: _compact(v) for k, v in results.items()}},
        notes=[SYNTHETIC_NOTE,
               "Force from the orbit is very sensitive to the clearance: ±1 µm moves the QJ202 peak stress from "
               f"{qj['measured']['peak_stress_if_clearance_plus_1um_MPa']:.0f} to "
               f"{qj['measured']['peak_stress_if_clearance_minus_1um_MPa']:.0f} MPa. A measured-stress figure is "
               "only as good as the clearance and sensor offset behind it."],
    )


_CAPTIONS = {"experiment_orbits": "orbits of the journal centre inside the clearance circle, measured and simulated",
             "experiment_force_stress": "contact force and max ball stress over time, from the orbit and simulated",
             "experiment_fit_window": "the fitted opening stretch, measured and best-fit simulation"}
_PAPER_SAYS = {"experiment_orbits": "Fig. 13: the orbits bounce in the bottom of the clearance (pictures only).",
               "experiment_force_stress": "Sec. III gives only the peak stresses, 1728 and 2348 MPa.",
               "experiment_fit_window": "The paper fits nothing; it names the unbalance angle at the drop as a cause."}


def _recovery_table(bearing: str, summary: dict) -> dict:
    rows = [[r["parameter"], r["unit"], f"{r['true']:.4g}", f"{r['start']:.4g}",
             f"{r['recovered']:.4g} ± {r['std']:.2g}", f"{r['error']:+.3g}"] for r in summary["recovery"]]
    fit = summary["fit"]
    return {"columns": ["parameter", "unit", "true", "fit start", "recovered ± 1σ", "error"], "rows": rows,
            "caption": f"{bearing}, SYNTHETIC drop: recovered vs true parameters (residual rms "
                       f"{fit['residual_rms_um']:.2f} µm over {fit['window_ms']:g} ms, "
                       f"{fit['simulations']} simulations)"}


def _compact(summary: dict) -> dict:
    keep = ("bearing", "source_file", "synthetic", "measured", "recovery", "peak_table")
    out = {k: summary[k] for k in keep if k in summary}
    if "fit" in summary:
        out["fit"] = {k: summary["fit"][k] for k in ("parameters", "residual_rms_um", "reduced_chi_square",
                                                     "autocorrelation_inflation", "simulations", "success")}
    return out
