"""Static stage of the study: Fig. 6-8 of the source paper (Sec. II.C) and its claims.

In a study of the user's own bearings (:class:`~auxbearing.report.model.Framing`) the same load grids
are captioned with those bearings, and the paper's claims are shown only when asked for.
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from auxbearing.analysis.statics import stress_warning, validity_warnings_all
from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.bearings.ratings import ISO76_BALL_STRESS, safety_factor
from auxbearing.paper.static_paper import (
    FIG6_AXIAL_LOADS,
    FIG6_FIXED_AXIAL,
    FIG6_FIXED_RADIAL,
    FIG6_RADIAL_LOADS,
    FIG7_LOADS,
    FIG8_RADIAL_LOADS,
    static_study,
)
from auxbearing.report.claims import DOES_NOT_HOLD, HOLDS, Assumption, Claim
from auxbearing.report.model import PAPER_STUDY, Figure, Framing, Section, retitle

#: Radial load at which the summary compares the two bearings [N]: the load of the paper's Fig. 6 (d).
SUMMARY_RADIAL_LOAD = 1000.0


def _angle_spread(ds: xr.Dataset, pair: int) -> np.ndarray:
    """Max - min loaded contact angle over the loaded balls of one pair, per case [deg]."""
    angle = np.degrees(ds["contact_angle"].isel(pair=pair).values)
    loaded = ds["load"].isel(pair=pair).values > 0
    masked = np.where(loaded, angle, np.nan)
    return np.nanmax(masked, axis=1) - np.nanmin(masked, axis=1)


def _mean_angle(ds: xr.Dataset, pair: int) -> np.ndarray:
    return np.degrees(ds["contact_angle"].isel(pair=pair).mean("ball").values)


def run_static_stage(four_point: BearingGeometry, angular: BearingGeometry, framing: Framing = PAPER_STUDY) -> Section:
    """Compute the load distributions of the paper's Fig. 6-8 for the two bearings and return the report section.

    Parameters
    ----------
    four_point, angular : BearingGeometry
        The four-point bearing and the angular-contact bearing it is compared with.
    framing : Framing
        The paper's study (default: its captions and Sec. II.C claims) or the user's own.
    """
    result = static_study(bearing_4pt=four_point, bearing_ac=angular)
    s = result["summary"]
    radial, axial, fig7, fig8 = result["fig6_radial"], result["fig6_axial"], result["fig7"], result["fig8"]
    spread = _angle_spread(radial, 0)
    pair1, pair2 = _mean_angle(axial, 0), _mean_angle(axial, 1)
    # Fig. 7: displacement per load in its own direction against the cross direction, over the grid
    da_dfa = float(np.nanmean(np.diff(fig7.axial_displacement.values, axis=0))) / float(np.diff(fig7.axial_load)[0])
    dr_dfa = float(np.nanmean(np.diff(fig7.radial_displacement.values, axis=0))) / float(np.diff(fig7.axial_load)[0])
    dr_dfr = float(np.nanmean(np.diff(fig7.radial_displacement.values, axis=1))) / float(np.diff(fig7.radial_load)[0])
    da_dfr = float(np.nanmean(np.diff(fig7.axial_displacement.values, axis=1))) / float(np.diff(fig7.radial_load)[0])
    own_dominates = da_dfa > 3 * abs(dr_dfa) and dr_dfr > 3 * abs(da_dfr)
    cross_increases = dr_dfa > 0 and da_dfr > 0
    four = fig8["max_stress"].isel(bearing=0).values[1:] / 1e6
    loads = fig8.radial_load.values[1:]
    slope = np.diff(four) / np.diff(loads)
    at = s["max_stress_at_1000N_MPa"]
    claims = [] if not framing.paper else [
        Claim("II.C / Fig. 6", "Radial load makes the contact angle vary along the position angle; the larger the "
              "radial load, the larger the variation", "qualitative",
              f"pair-1 spread {spread[0]:.2f} -> {spread[-1]:.2f} deg for Fr = {float(radial.radial_load[0]):g} -> "
              f"{float(radial.radial_load[-1]):g} N (Fa = {float(radial.axial_load[0]):g} N)",
              HOLDS if np.all(np.diff(spread) > 0) else DOES_NOT_HOLD,
              "Radial displacement adds dr cos(phi) to the radial component of the curvature-centre line (Eq. 12-13)."),
        Claim("II.C / Fig. 6", "With increasing axial load the contact angle of that direction increases, the other "
              "decreases", "qualitative",
              f"mean pair-1 angle {pair1[0]:.1f} -> {pair1[-1]:.1f} deg, pair 2 {pair2[0]:.1f} -> {pair2[-1]:.1f} deg "
              f"for Fa = {float(axial.axial_load[0]):g} -> {float(axial.axial_load[-1]):g} N",
              HOLDS if pair1[-1] > pair1[0] and pair2[-1] < pair2[0] else DOES_NOT_HOLD,
              "Axial displacement lengthens the axial component of pair 1 and shortens that of pair 2 (Eq. 10-13)."),
        Claim("II.C / Fig. 7", "Displacement in the loaded direction increases obviously; in the other direction it "
              "increases slightly", "qualitative",
              f"mean compliance: axial/axial {da_dfa * 1e9:.2f}, radial/axial {dr_dfa * 1e9:.3f}, radial/radial "
              f"{dr_dfr * 1e9:.2f}, axial/radial {da_dfr * 1e9:.3f} um/kN",
              HOLDS if own_dominates and cross_increases else DOES_NOT_HOLD,
              "Own-direction compliance dominates by more than 3x" + (
                  "; the cross terms are positive" if cross_increases else
                  ", but a cross term is negative: the other displacement decreases on average, it does not grow")),
        Claim("II.C / Fig. 8", "Max stress rises with radial load, first quickly then slowly", "qualitative",
              f"four-point {four[0]:.0f} -> {four[-1]:.0f} MPa over {loads[0]:g}-{loads[-1]:g} N; slope falls "
              f"{slope[0]:.3f} -> {slope[-1]:.3f} MPa/N", HOLDS if np.all(np.diff(slope) < 0) else DOES_NOT_HOLD,
              "Hertz: stress ~ Q^(1/3), concave in the load."),
        Claim("II.C / Fig. 8", "Angular-contact max stress exceeds the four-point's, and the excess keeps growing",
              "qualitative", f"{at[angular.name]:.0f} vs {at[four_point.name]:.0f} MPa at 1000 N; everywhere above: "
              f"{s['angular_exceeds_four_point_everywhere']}, excess growing: {s['excess_grows_with_load']}",
              HOLDS if s["angular_exceeds_four_point_everywhere"] and s["excess_grows_with_load"] else DOES_NOT_HOLD,
              "One loaded pair per ball instead of two: each contact carries about twice the load."),
    ]
    stribeck = result["stribeck"]
    table = {
        "columns": ["radial load [N]", "Z Q_max cos(α) / Fr (ours)", "Stribeck"],
        "rows": [[f"{float(f):g}", f"{float(k):.3f}", f"{s['stribeck_constant']}"]
                 for f, k in zip(stribeck.radial_load.values, stribeck["k_loaded"].values, strict=True)],
        "caption": "Validation: Stribeck's Q_max = 4.37 Fr / (Z cos α) (zero clearance, pure radial load)",
    }
    section = Section(
        key="static", title="Quasi-static load distribution (Sec. II.C, Fig. 6-8)",
        paper="Newton-Raphson solution of the inner-ring equilibrium (Eq. 9-16) of the Z = 11 bearings under "
              "combined radial, axial and moment load; contact angles, displacements, max stress.",
        figures=_figures(result["figures"], four_point, angular, framing), tables=[table],
        datasets={k: result[k] for k in ("fig6_radial", "fig6_axial", "fig7", "fig8", "stribeck")},
        claims=claims, assumptions=_assumptions(four_point, angular, framing), results=s,
        notes=[f"Largest relative equilibrium residual over Fig. 6: {s['max_relative_residual']:.1e}."],
        key_results=_key_results(fig8), warnings=_warnings(result, four_point),
    )
    if framing.own:
        section.title = f"Quasi-static load distribution: {four_point.name} and {angular.name}"
        section.about = (f"Newton-Raphson equilibrium of the inner ring of {four_point.name} "
                         f"({four_point.ball_count} balls) under combined radial and axial load: loaded contact "
                         f"angles for Fr = {_loads(FIG6_RADIAL_LOADS)} N at Fa = {FIG6_FIXED_AXIAL:g} N and for "
                         f"Fa = {_loads(FIG6_AXIAL_LOADS)} N at Fr = {FIG6_FIXED_RADIAL:g} N; ring displacements over "
                         f"{FIG7_LOADS[0]:g}-{FIG7_LOADS[-1]:g} N of axial and radial load; max contact stress of "
                         f"{four_point.name} and {angular.name} under radial load up to {FIG8_RADIAL_LOADS[-1]:g} N.")
        section.notes = [f"Largest relative equilibrium residual over the contact-angle cases: "
                         f"{s['max_relative_residual']:.1e}."]
        table["caption"] = (f"Check of {four_point.name}: Stribeck's Q_max = 4.37 Fr / (Z cos α) holds for zero "
                            "clearance under pure radial load")
        for key, (stem, title) in _OWN_DATA.items():
            data = section.datasets.pop(key)
            data.attrs["title"] = title.format(four_point.name, angular.name)
            section.datasets[stem] = data
        if not framing.paper:
            section.paper = ""
    return section


def _loads(values) -> str:
    return ", ".join(f"{v:g}" for v in values)


#: Own-study file stem and title of each data set ({0}: four-point bearing, {1}: angular-contact bearing).
_OWN_DATA = {"fig6_radial": ("static_contact_angles_radial", "Loaded contact angles under radial load, {0}"),
             "fig6_axial": ("static_contact_angles_axial", "Loaded contact angles under axial load, {0}"),
             "fig7": ("static_displacements", "Ring displacements over axial x radial load, {0}"),
             "fig8": ("static_max_stress", "Max contact stress under radial load, {0} (four-point) and {1} "
                      "(angular contact)"),
             "stribeck": ("static_stribeck", "Stribeck check, {0}")}

_PAPER_FIGURES = {
    "fig6_contact_angles": ("Fig. 6: loaded contact angles of pair 1 and pair 2 along the position angle",
                            "Radial load makes the angle vary along the position angle; axial load raises one pair's "
                            "angle and lowers the other's."),
    "fig7_displacements": ("Fig. 7: axial and radial displacement against axial and radial load",
                           "The displacement in the loaded direction grows obviously, the other slightly."),
    "fig8_max_stress": ("Fig. 8: max stress against radial load, four-point and angular contact",
                        "Stress rises quickly then slowly; the angular-contact bearing's is higher, the excess "
                        "growing."),
}
#: Own-study file stem and caption of each figure ({0}: four-point bearing, {1}: angular-contact bearing).
_OWN_FIGURES = {
    "fig6_contact_angles": ("static_contact_angles", "{0}: loaded contact angles of pair 1 and pair 2 along the "
                            "position angle"),
    "fig7_displacements": ("static_displacements", "{0}: axial and radial ring displacement against axial and "
                           "radial load"),
    "fig8_max_stress": ("static_max_stress", "Max contact stress against radial load: {0} (four-point) and {1} "
                        "(angular contact)"),
}


def _figures(figs: dict, four_point, angular, framing: Framing) -> list[Figure]:
    out = []
    for stem, fig in figs.items():
        caption, says = _PAPER_FIGURES[stem]
        if framing.own:
            stem, caption = _OWN_FIGURES[stem][0], _OWN_FIGURES[stem][1].format(four_point.name, angular.name)
            fig = retitle(fig, caption)
        out.append(Figure(stem, caption, fig, says if framing.paper else ""))
    return out


def _key_results(fig8: xr.Dataset) -> list[list[str]]:
    """Summary rows: stress and s0 of both bearings at one radial load, and where each reaches ISO 76."""
    at = fig8.sel(radial_load=SUMMARY_RADIAL_LOAD, method="nearest")
    stress = at["max_stress"].values / 1e6
    load = float(at.radial_load)
    s0 = [f"{float(safety_factor(v * 1e6)):.2f}" for v in stress]
    rows = [[f"Max contact stress at Fr = {load:g} N, pure radial load [MPa]", *(f"{v:.0f}" for v in stress)],
            [f"Static safety factor s0 at Fr = {load:g} N [-]", *s0]]
    reach = []
    for k in range(fig8.sizes["bearing"]):
        over = np.flatnonzero(fig8["max_stress"].isel(bearing=k).values > ISO76_BALL_STRESS)
        reach.append(f"{float(fig8.radial_load[over[0]]):g}" if over.size else f"> {float(fig8.radial_load[-1]):g}")
    rows.append(["Radial load where the max stress passes ISO 76's 4200 MPa (s0 = 1) [N]", *reach])
    return rows


def _warnings(result: dict, four_point: BearingGeometry) -> list[str]:
    """Load cases of the stage outside the model's range (ISO 76 stress, small-tilt kinematics)."""
    out = []
    fig8 = result["fig8"]
    for k, name in enumerate(fig8.bearing.values):
        stress = fig8["max_stress"].isel(bearing=k).values
        over = np.flatnonzero(stress > ISO76_BALL_STRESS)
        if over.size:
            worst = int(np.argmax(stress))
            out.append(f"{name}, pure radial load: from Fr = {float(fig8.radial_load[over[0]]):g} N on, at "
                       f"Fr = {float(fig8.radial_load[worst]):g} N the {stress_warning(float(stress[worst]))}.")
    for key in ("fig6_radial", "fig6_axial"):
        ds = result[key]
        for i, sentences in enumerate(validity_warnings_all(ds)):
            for sentence in sentences:
                out.append(f"{four_point.name}, Fa = {float(np.atleast_1d(ds.axial_load.values)[i]):g} N, "
                           f"Fr = {float(np.atleast_1d(ds.radial_load.values)[i]):g} N: {sentence}.")
    fig7 = result["fig7"]["max_stress"].values
    if np.nanmax(fig7) > ISO76_BALL_STRESS:
        out.append(f"{four_point.name}, axial x radial load grid: {int(np.sum(fig7 > ISO76_BALL_STRESS))} of "
                   f"{fig7.size} cases pass ISO 76's 4200 MPa; the largest, "
                   f"{stress_warning(float(np.nanmax(fig7)))}.")
    return out


def _assumptions(four_point, angular, framing: Framing) -> list[Assumption]:
    if not framing.own:
        return [
            Assumption("Moment arm of Eq. 14", "inner groove curvature-centre radius r_ic (Harris)",
                       "The paper writes 0.5 dm; r_ic keeps forces and displacements energy-conjugate (1 % apart)."),
            Assumption("K_b of Eq. 14-16", "Hertz K_i, K_o (Eq. 15) at each ball's loaded contact angle",
                       "The paper gives no value for the static model; Table II's K_b is for the drop and in "
                       "doubtful units."),
            Assumption("Axial condition of the single angular-contact bearing (Fig. 8)",
                       "inner ring axially located and square; the axial reaction is reported",
                       "A single angular-contact bearing cannot carry pure radial load with a free ring."),
            Assumption("Internal clearance", "0", "The paper assumes zero (Sec. II.C)."),
        ]
    clearance = ", ".join(f"{b.name}: {b.diametral_clearance * 1e3:g} mm" for b in (four_point, angular))
    return [
        Assumption("Moment arm of the ring's moment balance", "inner groove curvature-centre radius r_ic (Harris)",
                   "Keeps forces and displacements energy-conjugate."),
        Assumption("Ball contact stiffness", "Hertz K_i, K_o at each ball's loaded contact angle",
                   "Follows the contact geometry as the angles change under load."),
        Assumption(f"Axial condition of {angular.name} under radial load",
                   "inner ring axially located and square; the axial reaction is reported",
                   "A single angular-contact bearing cannot carry pure radial load with a free ring."),
        Assumption("Diametral internal clearance", clearance, "From the bearing tables."),
        Assumption("Load grids", f"contact angles: Fr = {_loads(FIG6_RADIAL_LOADS)} N at Fa = {FIG6_FIXED_AXIAL:g} N "
                   f"and Fa = {_loads(FIG6_AXIAL_LOADS)} N at Fr = {FIG6_FIXED_RADIAL:g} N; displacements: "
                   f"{FIG7_LOADS[0]:g}-{FIG7_LOADS[-1]:g} N; max stress: Fr up to {FIG8_RADIAL_LOADS[-1]:g} N",
                   "Fixed grids of the study (not read from the study file); `auxbearing static-cases` takes loads "
                   "of your own."),
    ]
