"""Static stage of the study: Fig. 6-8 of the source paper (Sec. II.C) and its claims."""

from __future__ import annotations

import numpy as np
import xarray as xr

from auxbearing.bearing import BearingGeometry
from auxbearing.paper.claims import DOES_NOT_HOLD, HOLDS, Assumption, Claim
from auxbearing.paper.static_paper import static_study
from auxbearing.report.model import Figure, Section


def _angle_spread(ds: xr.Dataset, pair: int) -> np.ndarray:
    """Max - min loaded contact angle over the loaded balls of one pair, per case [deg]."""
    angle = np.degrees(ds["contact_angle"].isel(pair=pair).values)
    loaded = ds["load"].isel(pair=pair).values > 0
    masked = np.where(loaded, angle, np.nan)
    return np.nanmax(masked, axis=1) - np.nanmin(masked, axis=1)


def _mean_angle(ds: xr.Dataset, pair: int) -> np.ndarray:
    return np.degrees(ds["contact_angle"].isel(pair=pair).mean("ball").values)


def run_static_stage(four_point: BearingGeometry, angular: BearingGeometry) -> Section:
    """Compute Fig. 6-8, check the paper's Sec. II.C claims, return the report section."""
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
    claims = [
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
    assumptions = [
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
    names = {"fig6_contact_angles": ("Fig. 6: loaded contact angles of pair 1 and pair 2 along the position angle",
                                     "Radial load makes the angle vary along the position angle; axial load raises "
                                     "one pair's angle and lowers the other's."),
             "fig7_displacements": ("Fig. 7: axial and radial displacement against axial and radial load",
                                    "The displacement in the loaded direction grows obviously, the other slightly."),
             "fig8_max_stress": ("Fig. 8: max stress against radial load, four-point and angular contact",
                                 "Stress rises quickly then slowly; the angular-contact bearing's is higher, the "
                                 "excess growing.")}
    figures = [Figure(stem, *names[stem][:1], fig, names[stem][1]) for stem, fig in result["figures"].items()]
    return Section(
        key="static", title="Quasi-static load distribution (Sec. II.C, Fig. 6-8)",
        paper="Newton-Raphson solution of the inner-ring equilibrium (Eq. 9-16) of the Z = 11 bearings under "
              "combined radial, axial and moment load; contact angles, displacements, max stress.",
        figures=figures, tables=[table],
        datasets={k: result[k] for k in ("fig6_radial", "fig6_axial", "fig7", "fig8", "stribeck")},
        claims=claims, assumptions=assumptions, results=s,
        notes=[f"Largest relative equilibrium residual over Fig. 6: {s['max_relative_residual']:.1e}."],
    )
