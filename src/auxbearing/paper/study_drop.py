"""Drop stage of the study: Fig. 10-11 of the source paper (Sec. II.D) and its claims."""

from __future__ import annotations

from auxbearing.bearing import BearingGeometry
from auxbearing.drop import DropCase, Rotor, from_mapping, run_drop
from auxbearing.paper.claims import DOES_NOT_HOLD, HOLDS, Assumption, Claim
from auxbearing.paper.drop_paper import PAPER_DROP, drop_compare, sweep_dataset
from auxbearing.plots.drop import plot_orbit_force, plot_speeds_stress, plot_sweep
from auxbearing.report.model import Figure, Section

#: Peak values are judged against the paper within this fraction: the paper leaves the clearance,
#: the rotor radius and the unbalance phase unstated, and the sweep shows each moves the peaks
#: by tens of per cent (see the sweep figure).
PEAK_TOLERANCE = 0.25


#: A bounce amplitude counts as "bigger" only beyond this relative margin.
BOUNCE_MARGIN = 0.10


def _verdict(ours: float, paper: float) -> str:
    return HOLDS if abs(ours / paper - 1) <= PEAK_TOLERANCE else DOES_NOT_HOLD


def run_drop_stage(four_point: BearingGeometry, angular: BearingGeometry, sections: dict | None = None) -> Section:
    """Simulate both drops, sweep the unstated parameters, check Sec. II.D claims."""
    sections = sections or {}
    rotor = Rotor(**from_mapping(sections.get("rotor"), "rotor"))
    case = DropCase(**from_mapping(sections.get("drop"), "drop"))
    compare = drop_compare(bearings=(four_point, angular), rotor=rotor, case=case)
    series = {b.name: run_drop(b, rotor, case)[0] for b in (four_point, angular)}
    r4, ra = compare["results"][four_point.name], compare["results"][angular.name]
    p4, pa = PAPER_DROP["QJ202"], PAPER_DROP["7202"]
    f4, fa = r4["peak_contact_force_N"], ra["peak_contact_force_N"]
    s4, sa = r4["peak_ball_stress_MPa"], ra["peak_ball_stress_MPa"]
    stress_change = 100 * (s4 / sa - 1)
    claims = [
        Claim("II.D / Fig. 10", "Max collision force, four-point bearing", f"{p4['peak_contact_force_N']:g} N",
              f"{f4:.0f} N", _verdict(f4, p4["peak_contact_force_N"]),
              f"{100 * (f4 / p4['peak_contact_force_N'] - 1):+.0f} %; judged to ±{100 * PEAK_TOLERANCE:.0f} % since "
              "the clearance, rotor radius and unbalance phase are unstated."),
        Claim("II.D / Fig. 11", "Max collision force, angular-contact bearing", f"{pa['peak_contact_force_N']:g} N",
              f"{fa:.0f} N", _verdict(fa, pa["peak_contact_force_N"]),
              f"{100 * (fa / pa['peak_contact_force_N'] - 1):+.0f} %; same tolerance."),
        Claim("II.D", "Max ball stress, four-point bearing", f"{p4['peak_ball_stress_MPa']:g} MPa", f"{s4:.0f} MPa",
              _verdict(s4, p4["peak_ball_stress_MPa"]), f"{100 * (s4 / p4['peak_ball_stress_MPa'] - 1):+.0f} %."),
        Claim("II.D", "Max ball stress, angular-contact bearing", f"{pa['peak_ball_stress_MPa']:g} MPa",
              f"{sa:.0f} MPa", _verdict(sa, pa["peak_ball_stress_MPa"]),
              f"{100 * (sa / pa['peak_ball_stress_MPa'] - 1):+.0f} %."),
        Claim("II.D", "The four-point bearing's max collision force is larger (1.58 times)", "1.58",
              f"{f4 / fa:.2f}", HOLDS if f4 > fa else DOES_NOT_HOLD,
              "Direction " + ("agrees" if f4 > fa else "disagrees") + "; the stiffer four-point ball set (two pairs "
              "per ball) makes the race a harder stop."),
        Claim("II.D", "The four-point bearing's max ball stress is lower (by 10.2 %)", "-10.2 %",
              f"{stress_change:+.1f} %", HOLDS if s4 < sa else DOES_NOT_HOLD,
              "Two loaded pairs per ball share the race load, as in the static analysis."),
        Claim("II.D", "Rotor drop on the four-point bearing tends to backward whirl", "qualitative",
              f"whirl detected: {r4['whirl']} (four-point), {ra['whirl']} (angular)",
              HOLDS if r4["whirl"] == "backward" else DOES_NOT_HOLD,
              "From the sign of the dominant frequency of the complex orbit x + iy after the first impact."),
        Claim("II.D / IV", "Bounce amplitudes are bigger with the four-point bearing", "qualitative",
              f"largest bounce {r4['largest_bounce_um']:.0f} um vs {ra['largest_bounce_um']:.0f} um",
              HOLDS if r4["largest_bounce_um"] > (1 + BOUNCE_MARGIN) * ra["largest_bounce_um"] else DOES_NOT_HOLD,
              "Largest radial excursion back toward the centre after an impact; 'bigger' needs a margin of "
              f"{100 * BOUNCE_MARGIN:.0f} % to count, less is read as equal."),
        Claim("II.D", "The rotor shows combined rub and bouncing", "qualitative",
              f"{r4['impacts']} impacts, contact fraction {100 * r4['contact_fraction']:.0f} % (four-point)",
              HOLDS if r4["impacts"] > 1 and r4["contact_fraction"] > 0.05 else DOES_NOT_HOLD,
              "Several separate impacts and sustained contact phases."),
    ]
    rows = [[name, f"{PAPER_DROP[key]['peak_contact_force_N']:g}", f"{res['peak_contact_force_N']:.0f}",
             f"{PAPER_DROP[key]['peak_ball_stress_MPa']:g}", f"{res['peak_ball_stress_MPa']:.0f}", res["whirl"],
             f"{res['impacts']}", f"{res['s0']:.2f}" if res.get("s0") else "-"]
            for name, key, res in ((four_point.name, "QJ202", r4), (angular.name, "7202", ra))]
    paper_kb = compare["paper_ball_constant"]
    rows_kb = [[name, "paper's K_b (N/mm^1.5)", "-", f"{paper_kb[name]['peak_contact_force_N']:.0f}", "-",
                f"{paper_kb[name]['peak_ball_stress_MPa']:.0f}", paper_kb[name]["whirl"],
                f"{paper_kb[name]['impacts']}"]
               for name in (four_point.name, angular.name)]
    table = {"columns": ["bearing", "peak force, paper [N]", "ours [N]", "peak stress, paper [MPa]", "ours [MPa]",
                         "whirl", "impacts", "s0"], "rows": rows,
             "caption": "Drop at 6000 rpm, Table II, s = 0.2 mm, Hertz K_b"}
    table_kb = {"columns": ["bearing", "variant", "", "peak force [N]", "", "peak stress [MPa]", "whirl", "impacts"],
                "rows": rows_kb, "caption": "Variant: Table II's K_b = 5.42e5 read as N/mm^1.5 (1.71e10 N/m^1.5)"}
    checks = compare.get("checks", {})
    notes = [f"{name}: 10x tighter tolerance changes peak force/stress by "
             f"{c['tolerance_10x_tighter_change_percent']['peak_contact_force_N']:+.2f} % / "
             f"{c['tolerance_10x_tighter_change_percent']['peak_ball_stress_MPa']:+.2f} %; 10x smaller slip "
             f"regularisation by {c['slip_velocity_10x_smaller_change_percent']['peak_contact_force_N']:+.2f} % / "
             f"{c['slip_velocity_10x_smaller_change_percent']['peak_ball_stress_MPa']:+.2f} %."
             for name, c in checks.items()]
    sweep = sweep_dataset(compare)
    figures = [
        Figure("fig10_orbit_force", f"Fig. 10: orbit (a) and collision force (b), {four_point.name} four-point",
               plot_orbit_force(series[four_point.name], PAPER_DROP["QJ202"]),
               "Combined rub and bouncing; a tendency to backward whirl; max collision force 618 N."),
        Figure("fig11_orbit_force", f"Fig. 11: orbit (a) and collision force (b), {angular.name} angular contact",
               plot_orbit_force(series[angular.name], PAPER_DROP["7202"]), "Max collision force 391 N."),
        Figure("drop_speeds_stress_four_point", f"Beyond the paper: spin speeds and max ball stress, {four_point.name}",
               plot_speeds_stress(series[four_point.name]), "Max stress 1483 MPa (four-point)."),
        Figure("drop_speeds_stress_angular", f"Beyond the paper: spin speeds and max ball stress, {angular.name}",
               plot_speeds_stress(series[angular.name]), "Max stress 1634 MPa (angular contact)."),
        Figure("drop_sweep", "Beyond the paper: peaks against the unstated clearance, friction and unbalance phase",
               plot_sweep(sweep, PAPER_DROP), "The paper gives one case only."),
    ]
    assumptions = [Assumption(u["parameter"], u["ours"], u["note"]) for u in compare["unstated_parameters"]]
    return Section(
        key="drop", title="Rotor drop (Sec. II.D, Fig. 9-11)",
        paper="A 1.48 kg rotor spinning at 6000 rpm drops from the centre onto the auxiliary bearing; rotor and inner "
              "race in x, y and spin (Eq. 17-26, Table II); four-point QJ202 against angular-contact 7202.",
        figures=figures, tables=[table, table_kb],
        datasets={f"drop_{n.lower().replace('-', '_')}": ds for n, ds in series.items()} | {"drop_sweep": sweep},
        claims=claims, assumptions=assumptions, notes=notes,
        results={k: v for k, v in compare.items() if k not in ("files",)},
    )
