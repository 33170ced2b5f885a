"""Contact stage of the study: Fig. 2-4 of the source paper, its claims and design window.

In the paper's study the stage is captioned and judged with the paper's QJ202 numbers; in a study of
the user's own bearings (:class:`~auxbearing.report.model.Framing`) it reports on those bearings only,
and shows the paper's claims beside them only when asked to.
"""

from __future__ import annotations

import math

import numpy as np
import xarray as xr

from auxbearing.analysis.contact import PAPER_CONTACT, ball_contact, contact_map, type_comparison
from auxbearing.analysis.statics import stress_warning
from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.bearings.ratings import safety_factor
from auxbearing.plots.contact import plot_contact_angle_sweep, plot_contact_map, plot_groove_ratio_sweep
from auxbearing.report.claims import CANNOT_CHECK, DOES_NOT_HOLD, HOLDS, Assumption, Claim, within
from auxbearing.report.model import PAPER_STUDY, Figure, Framing, Section, retitle

#: Stress penalty that defines the "design window" of contact angle: the largest angle whose
#: inner-race max stress under the same radial ball load exceeds the minimum (at the smallest
#: swept angle) by at most this fraction. A choice of ours, shown in the report.
STRESS_PENALTY = 0.10


def design_window(ds: xr.Dataset, penalty: float = STRESS_PENALTY) -> dict:
    """Largest contact angle and groove ratio keeping the inner max stress within ``penalty``.

    Stress rises monotonically with both (Fig. 2-3), so the window is bounded above only; the
    lower bounds of the paper's recommendation (15 deg, 0.51) come from considerations the
    contact analysis does not model (axial capacity; friction and heat in close conformity).
    """
    inner = ds["max_stress"].sel(race="inner")
    f_ref = float(ds.groove_ratio.sel(groove_ratio=0.52, method="nearest"))
    by_angle = inner.sel(groove_ratio=f_ref)
    angle_ok = by_angle.contact_angle[by_angle <= (1 + penalty) * float(by_angle.min())]
    a_ref = float(ds.contact_angle.sel(contact_angle=35.0, method="nearest"))
    by_ratio = inner.sel(contact_angle=a_ref)
    stress_052 = float(by_ratio.sel(groove_ratio=0.52, method="nearest"))
    stress_051 = float(by_ratio.sel(groove_ratio=0.51, method="nearest"))
    return {
        "stress_penalty": penalty,
        "max_contact_angle_deg": float(angle_ok.max()),
        "stress_at_15_deg_MPa": float(by_angle.sel(contact_angle=15.0, method="nearest")) / 1e6,
        "stress_at_45_deg_MPa": float(by_angle.sel(contact_angle=45.0, method="nearest")) / 1e6,
        "stress_min_MPa": float(by_angle.min()) / 1e6,
        "stress_f051_MPa": stress_051 / 1e6,
        "stress_f052_MPa": stress_052 / 1e6,
        "stress_f060_MPa": float(by_ratio.sel(groove_ratio=0.60, method="nearest")) / 1e6,
    }


def run_contact_stage(bearing: BearingGeometry, ball_load: float, angles_deg, ratios,
                      comparison: BearingGeometry | None = None, framing: Framing = PAPER_STUDY) -> Section:
    """Compute the contact sweeps (the paper's Fig. 2-4) for ``bearing`` and return the report section.

    Parameters
    ----------
    bearing : BearingGeometry
        The four-point bearing swept over contact angle and groove ratio.
    ball_load : float
        Radial load on one ball [N].
    angles_deg, ratios : array_like
        Contact angles [deg] and groove radius coefficients [-] of the sweep.
    comparison : BearingGeometry, optional
        The angular-contact bearing of the study, reported beside ``bearing`` in a study of the
        user's own bearings.
    framing : Framing
        The paper's study (default: its captions and Sec. II.B claims) or the user's own.
    """
    ds = contact_map(bearing, ball_load, angles_deg, ratios)
    comp = type_comparison(bearing, ball_load)
    window = design_window(ds)
    # nearest: the user's grid need not hold the bearing's own angle and groove ratio exactly
    fig2 = ds.sel(groove_ratio=bearing.inner_groove_ratio, method="nearest")
    fig3 = ds.sel(contact_angle=math.degrees(bearing.contact_angle), method="nearest")
    own_rows, key_results, warnings = _own_results(bearing, comparison, ball_load, comp)
    results = {"fig4": comp, "design_window": window}
    if not framing.paper:
        results["fig4"] = {k: v for k, v in comp.items() if not k.startswith("paper")}
    if comparison is not None:
        results["comparison_bearing"] = ball_contact(comparison, ball_load)
    section = Section(
        key="contact", title="Contact analysis (Sec. II.B, Fig. 2-4)",
        paper="Hertz point contact of ball and raceway for the Table I bearing under a 1000 N radial ball load; "
              "sweeps of contact angle (10-75 deg) and groove coefficient (0.505-0.6); four-point versus "
              "angular contact.",
        figures=_figures(ds, bearing, ball_load, framing),
        tables=[_paper_table(comp, ball_load)] if not framing.own else [_own_table(own_rows, bearing, comparison,
                                                                                  ball_load, comp, framing)],
        datasets={"contact_map": ds}, results=results, key_results=key_results, warnings=warnings,
        claims=_claims(ds, fig2, fig3, comp, window) if framing.paper else [],
        assumptions=_paper_assumptions(ball_load) if not framing.own else _own_assumptions(bearing, comparison,
                                                                                            ball_load, ds),
    )
    if framing.own:
        section.title = f"Contact analysis: {bearing.name}" + (f" and {comparison.name}" if comparison else "")
        section.about = (f"Hertz point contact of one ball of {bearing.name} (four-point, α = "
                         f"{math.degrees(bearing.contact_angle):g} deg, inner groove ratio "
                         f"{bearing.inner_groove_ratio:g}) under a {ball_load:g} N radial ball load; sweeps of the "
                         f"contact angle ({float(ds.contact_angle[0]):g}-{float(ds.contact_angle[-1]):g} deg) and of "
                         f"the groove radius coefficient ({float(ds.groove_ratio[0]):g}-"
                         f"{float(ds.groove_ratio[-1]):g}); the same geometry as a four-point and as an "
                         "angular-contact bearing" + (f"; {comparison.name} as it is." if comparison else "."))
        if not framing.paper:
            section.paper = ""
    return section


def _own_results(bearing, comparison, ball_load, comp) -> tuple[list, list, list]:
    """Stresses of the bearings at hand: table rows, summary rows and out-of-range warnings."""
    own = ball_contact(bearing, ball_load)
    other = ball_contact(comparison, ball_load) if comparison is not None else None
    as_angular = comp["angular_contact_max_stress_MPa"]
    rows, warnings = [], []
    for race in ("inner", "outer"):
        rows.append([f"Hertz max stress, {race} race [MPa]", f"{own[race]['max_stress_MPa']:.0f}",
                     f"{as_angular:.0f}" if race == "inner" else "-",
                     f"{other[race]['max_stress_MPa']:.0f}" if other else "-"])
    peak_own = max(own[r]["max_stress_MPa"] for r in ("inner", "outer"))
    peak_other = max(other[r]["max_stress_MPa"] for r in ("inner", "outer")) if other else None
    rows.append(["Static safety factor s0 of this contact (ISO 76) [-]",
                 f"{float(safety_factor(peak_own * 1e6)):.2f}", "-",
                 f"{float(safety_factor(peak_other * 1e6)):.2f}" if other else "-"])
    rows.append(["Elastic approach, inner race [µm]", f"{own['inner']['approach_um']:.2f}", "-",
                 f"{other['inner']['approach_um']:.2f}" if other else "-"])
    for name, peak in ((bearing.name, peak_own), (comparison.name if comparison else "", peak_other)):
        sentence = stress_warning(peak * 1e6) if peak is not None else None
        if sentence:
            warnings.append(f"{name} at {ball_load:g} N radial ball load: {sentence}.")
    key_results = [[f"Hertz max contact stress at {ball_load:g} N ball load [MPa]", f"{peak_own:.0f}",
                    f"{peak_other:.0f}" if peak_other is not None else "-"]]
    return rows, key_results, warnings


def _own_table(rows, bearing, comparison, ball_load, comp, framing: Framing) -> dict:
    columns = ["", f"{bearing.name} (four-point)", f"{bearing.name} geometry as angular contact",
               f"{comparison.name} ({comparison.type.replace('_', ' ')})" if comparison else "comparison bearing"]
    rows = list(rows)
    if framing.paper:
        rows.append([f"{framing.paper_label}, theory, inner race [MPa]",
                     f"{PAPER_CONTACT['theory_four_point_MPa']:g}", "-", "-"])
        rows.append([f"{framing.paper_label}, finite elements [MPa]", f"{PAPER_CONTACT['fe_four_point_MPa']}",
                     f"{PAPER_CONTACT['fe_angular_contact_MPa']}", "-"])
    return {"columns": columns, "rows": rows,
            "caption": f"Contact of one ball under a {ball_load:g} N radial ball load (zero clearance); "
                       f"as a four-point bearing, {bearing.name}'s inner-race stress is "
                       f"{comp['reduction_percent']:.1f} % below that of the same geometry in angular contact"}


def _paper_table(comp: dict, ball_load: float) -> dict:
    s4, sa = comp["four_point_max_stress_MPa"], comp["angular_contact_max_stress_MPa"]
    return {
        "columns": ["", "four-point (QJ202)", "angular contact (7202)"],
        "rows": [
            ["Hertz max stress, ours [MPa]", f"{s4:.1f}", f"{sa:.1f}"],
            ["Paper, theory [MPa]", f"{PAPER_CONTACT['theory_four_point_MPa']:g}", "-"],
            ["Paper, finite elements [MPa]", f"{PAPER_CONTACT['fe_four_point_MPa']}",
             f"{PAPER_CONTACT['fe_angular_contact_MPa']}"],
        ],
        "caption": f"Fig. 4: max stress at {ball_load:g} N radial ball load",
    }


def _figures(ds: xr.Dataset, bearing: BearingGeometry, ball_load: float, framing: Framing) -> list[Figure]:
    alpha, f_i = math.degrees(bearing.contact_angle), bearing.inner_groove_ratio
    sweep_a = plot_contact_angle_sweep(ds, f_i)
    sweep_f = plot_groove_ratio_sweep(ds, alpha)
    cmap = plot_contact_map(ds)
    if not framing.own:
        return [
            Figure("fig2_contact_angle", "Fig. 2: elastic approach (a) and max stress (b) against contact angle",
                   sweep_a, "Approach and stress rise with the angle, faster and faster; inner stress above outer."),
            Figure("fig3_groove_ratio", "Fig. 3: elastic approach (a) and max stress (b) against groove ratio",
                   sweep_f, "Both rise with the groove radius coefficient, the increase slowing down."),
            Figure("contact_map", "Beyond the paper: inner-race max stress over contact angle and groove ratio",
                   cmap, "The dashed box is the paper's recommended window (15-45 deg, 0.51-0.52)."),
        ]
    f_shown = float(ds.groove_ratio.sel(groove_ratio=f_i, method="nearest"))
    a_shown = float(ds.contact_angle.sel(contact_angle=alpha, method="nearest"))
    load = f"{ball_load:g} N radial ball load"
    angle_caption = f"{bearing.name}: elastic approach (a) and max stress (b) against contact angle, f = {f_shown:.3f}"
    ratio_caption = f"{bearing.name}: elastic approach (a) and max stress (b) against groove ratio, α = {a_shown:g} deg"
    map_caption = f"{bearing.name}: inner-race max stress over contact angle and groove ratio, {load}"
    ax = cmap.axes[0]
    if not framing.paper:
        for patch in list(ax.patches):  # the paper's recommended window
            patch.remove()
    ax.plot([f_i], [alpha], marker="o", color="white", markeredgecolor="black", linestyle="none")
    ax.set_title("")
    says = {"angle": "", "ratio": "", "map": "The white dot is the bearing's own contact angle and groove ratio."}
    if framing.paper:
        says = {"angle": "Approach and stress rise with the angle, faster and faster; inner stress above outer.",
                "ratio": "Both rise with the groove radius coefficient, the increase slowing down.",
                "map": "The dashed box is the paper's recommended window (15-45 deg, 0.51-0.52); the white dot is "
                       "this bearing."}
    return [
        Figure("contact_angle_sweep", angle_caption, retitle(sweep_a, f"{angle_caption}, {load}"), says["angle"]),
        Figure("groove_ratio_sweep", ratio_caption, retitle(sweep_f, f"{ratio_caption}, {load}"), says["ratio"]),
        Figure("contact_map", map_caption, retitle(cmap, map_caption), says["map"]),
    ]


def _paper_assumptions(ball_load: float) -> list[Assumption]:
    return [
        Assumption("Load of the contact study", f"{ball_load:g} N radial load on one ball, split Q/(2 cos α) "
                   "per contact (four-point), Q/cos α (angular)",
                   "docs/paper_notes.md reading of Sec. II.B; reproduces 2616 MPa within 0.3 %."),
        Assumption("Ellipticity", "exact elliptic integrals (AGM), solved to machine precision",
                   "The paper's a*, b* come from charts; Hamrock-Brewe fits err by up to 3.8 % in κ."),
        Assumption("Materials", "GCr15 balls, 42CrMo rings, both E = 207 GPa, ν = 0.3", "Paper Sec. II.B."),
    ]


def _own_assumptions(bearing, comparison, ball_load, ds) -> list[Assumption]:
    bearings = [b for b in (bearing, comparison) if b is not None]
    materials = "; ".join(f"{b.name}: balls {b.describe()['ball_material']}, rings {b.describe()['ring_material']}"
                          for b in bearings)
    return [
        Assumption("Contact load", f"{ball_load:g} N radial load on one ball ([study] ball_load), split "
                   "Q/(2 cos α) over the two contacts of a four-point ball, Q/cos α on an angular-contact ball",
                   "Both loaded contacts of a four-point ball share the radial ball load."),
        Assumption("Ellipticity and elliptic integrals", "exact (AGM), solved to machine precision",
                   "Closed-form fits (Hamrock-Brewe) err by up to 3.8 % in the ellipticity."),
        Assumption("Materials", materials, "From the bearing tables."),
        Assumption("Internal clearance in the contact comparison", "0",
                   "A single ball under a given load; the clearance enters the load distribution, not this stage."),
        Assumption("Sweep grid", f"{ds.sizes['contact_angle']} contact angles x {ds.sizes['groove_ratio']} groove "
                   "ratios, both races' groove ratio set to the swept value",
                   "[study] contact_angles and groove_ratios."),
    ]


def _claims(ds, fig2, fig3, comp, window) -> list[Claim]:
    """The paper's Sec. II.B and IV contact claims, judged on the swept map."""
    s4, sa = comp["four_point_max_stress_MPa"], comp["angular_contact_max_stress_MPa"]
    inner_over_outer = bool((ds.max_stress.sel(race="inner") > ds.max_stress.sel(race="outer")).all())
    approach_gap = float(abs(fig2.approach.sel(race="inner") / fig2.approach.sel(race="outer") - 1).max())
    # slopes, not raw differences: the grids need not be uniform
    d_angle = np.diff(fig2.max_stress.sel(race="inner").values) / np.diff(ds.contact_angle.values)
    d_ratio = np.diff(fig3.max_stress.sel(race="inner").values) / np.diff(ds.groove_ratio.values)
    return [
        Claim("II.B", "Max stress of the four-point bearing at 1000 N radial ball load (theory)",
              f"{PAPER_CONTACT['theory_four_point_MPa']:g} MPa", f"{s4:.1f} MPa",
              within(s4, PAPER_CONTACT["theory_four_point_MPa"], 0.01),
              f"{100 * (s4 / PAPER_CONTACT['theory_four_point_MPa'] - 1):+.2f} %: exact Hertz with the load "
              "split Q/(2 cos α) per contact; the rest is table-reading error of the paper's a*, b*."),
        Claim("II.B", "Max stress in the inner race is greater than in the outer race", "qualitative",
              f"inner > outer at every point of the {ds.sizes['contact_angle']} x {ds.sizes['groove_ratio']} grid: "
              f"{inner_over_outer}", HOLDS if inner_over_outer else DOES_NOT_HOLD,
              "The inner race is convex in the rolling direction, the outer concave: larger curvature sum inside."),
        Claim("II.B", "Elastic approach of inner and outer race are very close", "qualitative",
              f"largest difference {100 * approach_gap:.1f} % over 10-75 deg", HOLDS if approach_gap < 0.1 else
              DOES_NOT_HOLD, "The approach depends on the curvature sum only to the 1/3 power."),
        Claim("II.B / Fig. 2", "Approach and max stress increase with contact angle, and the increase accelerates",
              "qualitative", f"inner stress {float(fig2.max_stress.sel(race='inner')[0]) / 1e6:.0f} -> "
              f"{float(fig2.max_stress.sel(race='inner')[-1]) / 1e6:.0f} MPa over "
              f"{float(ds.contact_angle[0]):g}-{float(ds.contact_angle[-1]):g} deg; increments grow",
              HOLDS if np.all(d_angle > 0) and np.all(np.diff(d_angle) > 0) else DOES_NOT_HOLD,
              "Mostly the load split: each contact carries Q/(2 cos α), which grows as 1/cos α."),
        Claim("II.B / Fig. 3", "Approach and max stress increase with groove radius coefficient, ever more slowly",
              "qualitative", f"inner stress {float(fig3.max_stress.sel(race='inner')[0]) / 1e6:.0f} -> "
              f"{float(fig3.max_stress.sel(race='inner')[-1]) / 1e6:.0f} MPa over f = "
              f"{float(ds.groove_ratio[0]):g}-{float(ds.groove_ratio[-1]):g}; increments shrink",
              HOLDS if np.all(d_ratio > 0) and np.all(np.diff(d_ratio) < 0) else DOES_NOT_HOLD,
              "A looser groove lowers the conformity; the effect saturates as the groove curvature vanishes."),
        Claim("II.B / Fig. 4", "FE max stress of the four-point bearing, 2346.2 MPa, slightly below theory",
              f"{PAPER_CONTACT['fe_four_point_MPa']} MPa (FE)", f"{s4:.1f} MPa (Hertz)", CANNOT_CHECK,
              "The paper's single ball-channel FE model (mesh, boundary conditions) is not given; Hertz is "
              f"{100 * (s4 / PAPER_CONTACT['fe_four_point_MPa'] - 1):.1f} % above the FE value."),
        Claim("II.B / Fig. 4", "Four-point max stress 22.9 % lower than angular contact under the same load",
              f"22.9 % (FE: {PAPER_CONTACT['fe_four_point_MPa']} vs {PAPER_CONTACT['fe_angular_contact_MPa']} MPa)",
              f"{comp['reduction_percent']:.1f} % (Hertz: {s4:.0f} vs {sa:.0f} MPa)",
              HOLDS if abs(comp["reduction_percent"] - 22.9) < 5 else DOES_NOT_HOLD,
              "Same direction and size within 2.3 points; Hertz gives the reduction 1 - 2^(-1/3) = 20.6 % "
              "exactly, since halving the contact load lowers stress by 2^(1/3)."),
        Claim("IV", "Recommended contact angle 15-45 deg",
              "15-45 deg", f"stress within {100 * STRESS_PENALTY:.0f} % of its minimum up to "
              f"{window['max_contact_angle_deg']:g} deg; {window['stress_at_15_deg_MPa']:.0f} MPa at 15 deg, "
              f"{window['stress_at_45_deg_MPa']:.0f} MPa at 45 deg",
              HOLDS if 40 <= window["max_contact_angle_deg"] <= 50 else DOES_NOT_HOLD,
              "The upper bound matches a 10 % stress-penalty criterion. The lower bound cannot come from radial "
              "contact stress, which only falls with the angle; it needs the axial capacity (sin α)."),
        Claim("IV", "Recommended groove radius coefficient 0.51-0.52",
              "0.51-0.52", f"{window['stress_f051_MPa']:.0f} MPa at 0.51, {window['stress_f052_MPa']:.0f} MPa "
              f"at 0.52, {window['stress_f060_MPa']:.0f} MPa at 0.60", CANNOT_CHECK,
              "Stress falls monotonically toward f = 0.5, so contact stress alone says 'as small as possible'; "
              "the lower bound reflects friction and heat of close conformity, which the paper does not model."),
    ]
