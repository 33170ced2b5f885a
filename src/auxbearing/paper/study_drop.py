"""Drop stage of the study: Fig. 10-11 of the source paper (Sec. II.D) and its claims.

In a study of the user's own bearings (:class:`~auxbearing.report.model.Framing`) the drop is
captioned with the user's rotor, speed and clearance, swept around the user's clearance, and the
paper's numbers and its K_b variant appear only when asked for.
"""

from __future__ import annotations

import math

from auxbearing.analysis.statics import stress_warning
from auxbearing.bearings.geometry import BearingGeometry
from auxbearing.bearings.ratings import ISO76_BALL_STRESS
from auxbearing.paper.drop_paper import PAPER_DROP, SWEEPS, drop_compare, sweep_dataset
from auxbearing.planar.params import PARAMETERS, DropCase, Rotor, display_value, from_mapping
from auxbearing.plots.drop import plot_orbit_force, plot_speeds_stress, plot_sweep
from auxbearing.report.claims import DOES_NOT_HOLD, HOLDS, Assumption, Claim
from auxbearing.report.model import PAPER_STUDY, Figure, Framing, Section, retitle, slug

#: Peak values are judged against the paper within this fraction: the paper leaves the clearance,
#: the rotor radius and the unbalance phase unstated, and the sweep shows each moves the peaks
#: by tens of per cent (see the sweep figure).
PEAK_TOLERANCE = 0.25


#: A bounce amplitude counts as "bigger" only beyond this relative margin.
BOUNCE_MARGIN = 0.10

#: Clearances of the sweep in a study of the user's own bearings, as multiples of the user's clearance:
#: the paper study's 0.1-0.3 mm around its 0.2 mm, carried over to any clearance.
OWN_CLEARANCE_FACTORS = (0.5, 0.75, 1.0, 1.5)

_RPM = 30.0 / math.pi  # rad/s -> rpm
_KIND = {"four_point": "four-point", "angular_contact": "angular contact"}


def _verdict(ours: float, paper: float) -> str:
    return HOLDS if abs(ours / paper - 1) <= PEAK_TOLERANCE else DOES_NOT_HOLD


def run_drop_stage(four_point: BearingGeometry, angular: BearingGeometry, sections: dict | None = None,
                   framing: Framing = PAPER_STUDY) -> Section:
    """Simulate both drops, sweep the parameters the paper leaves out, return the report section.

    Parameters
    ----------
    four_point, angular : BearingGeometry
        The two bearings the rotor drops onto (one drop each).
    sections : dict, optional
        The study file's raw ``[rotor]`` and ``[drop]`` tables (values with units).
    framing : Framing
        The paper's study (default: its captions and Sec. II.D claims) or the user's own.
    """
    sections = sections or {}
    rotor = Rotor(**from_mapping(sections.get("rotor"), "rotor"))
    case = DropCase(**from_mapping(sections.get("drop"), "drop"))
    series: dict = {}
    options = {"clearances": tuple(case.clearance * k for k in OWN_CLEARANCE_FACTORS)} if framing.own else {}
    compare = drop_compare(bearings=(four_point, angular), rotor=rotor, case=case, paper_kb=framing.paper,
                           datasets_out=series, **options)
    r4, ra = compare["results"][four_point.name], compare["results"][angular.name]
    checks = compare.get("checks", {})
    notes = [f"{name}: 10x tighter tolerance changes peak force/stress by "
             f"{c['tolerance_10x_tighter_change_percent']['peak_contact_force_N']:+.2f} % / "
             f"{c['tolerance_10x_tighter_change_percent']['peak_ball_stress_MPa']:+.2f} %; 10x smaller slip "
             f"regularisation by {c['slip_velocity_10x_smaller_change_percent']['peak_contact_force_N']:+.2f} % / "
             f"{c['slip_velocity_10x_smaller_change_percent']['peak_ball_stress_MPa']:+.2f} %."
             for name, c in checks.items()]
    sweep = sweep_dataset(compare)
    results = {k: v for k, v in compare.items() if k not in ("files",)}
    if not framing.paper:
        results.pop("paper", None)
        results["results"] = {n: {k: v for k, v in r.items() if k != "paper"} for n, r in results["results"].items()}
    section = Section(
        key="drop", title="Rotor drop (Sec. II.D, Fig. 9-11)",
        paper="A 1.48 kg rotor spinning at 6000 rpm drops from the centre onto the auxiliary bearing; rotor and inner "
              "race in x, y and spin (Eq. 17-26, Table II); four-point QJ202 against angular-contact 7202.",
        figures=_figures(series, sweep, four_point, angular, rotor, case, framing),
        tables=_tables(compare, four_point, angular, rotor, case, framing),
        datasets={f"drop_{slug(n)}": ds for n, ds in series.items()} | {"drop_sweep": sweep},
        # a drop stopped outside the model's range has no peaks to hold against the paper's
        claims=_claims(r4, ra) if framing.paper and r4["verdict"] == ra["verdict"] == "ok" else [],
        notes=notes, results=results,
        assumptions=([Assumption(u["parameter"], u["ours"], u["note"]) for u in compare["unstated_parameters"]]
                     if not framing.own else _own_assumptions(sections, r4, ra, four_point, angular)),
        key_results=_key_results(r4, ra), warnings=_warnings(compare, four_point, angular, rotor, case),
    )
    if framing.own:
        section.title = f"Rotor drop: {_case_words(rotor, case)} onto {four_point.name} and {angular.name}"
        section.about = (f"A {rotor.mass:g} kg rotor (polar inertia {rotor.polar_inertia:.3g} kg m², unbalance "
                         f"eccentricity {rotor.eccentricity * 1e6:g} µm) spinning at {case.speed * _RPM:g} rpm drops "
                         f"onto the inner race with a radial clearance of {case.clearance * 1e3:g} mm; rotor and "
                         f"inner race move in x, y and spin for {case.duration * 1e3:g} ms. One drop onto "
                         f"{four_point.name} (four-point), one onto {angular.name} (angular contact), and the peaks "
                         f"against clearance ({', '.join(f'{k:g}' for k in OWN_CLEARANCE_FACTORS)} x), sliding "
                         "friction and unbalance phase.")
        section.notes = _rig_notice(sections) + section.notes
        if not framing.paper:
            section.paper = ""
    return section


def _case_words(rotor: Rotor, case: DropCase) -> str:
    return f"{rotor.mass:g} kg rotor at {case.speed * _RPM:g} rpm, clearance {case.clearance * 1e3:g} mm"


def _rig_notice(sections: dict) -> list[str]:
    """A sentence when the rotor or drop case falls back on the default test rig."""
    unset = [(section, key) for section, key in (("rotor", "mass"), ("drop", "speed"), ("drop", "clearance"))
             if key not in (sections.get(section) or {})]
    if not unset:
        return []
    by_key = {(p.section, p.key): p for p in PARAMETERS}
    values = ", ".join(f"{section}.{key} = {display_value(by_key[section, key], by_key[section, key].default)}"
                       for section, key in unset)
    return [f"Not set in the study file, so the defaults are used: {values} (the source paper's test rig, not "
            "your machine). Set them in [rotor] and [drop] for your machine."]


def _figures(series, sweep, four_point, angular, rotor, case, framing: Framing) -> list[Figure]:
    paper = framing.paper
    if not framing.own:
        return [
            Figure("fig10_orbit_force", f"Fig. 10: orbit (a) and collision force (b), {four_point.name} four-point",
                   plot_orbit_force(series[four_point.name], PAPER_DROP["QJ202"]),
                   "Combined rub and bouncing; a tendency to backward whirl; max collision force 618 N."),
            Figure("fig11_orbit_force", f"Fig. 11: orbit (a) and collision force (b), {angular.name} angular contact",
                   plot_orbit_force(series[angular.name], PAPER_DROP["7202"]), "Max collision force 391 N."),
            Figure("drop_speeds_stress_four_point",
                   f"Beyond the paper: spin speeds and max ball stress, {four_point.name}",
                   plot_speeds_stress(series[four_point.name]), "Max stress 1483 MPa (four-point)."),
            Figure("drop_speeds_stress_angular", f"Beyond the paper: spin speeds and max ball stress, {angular.name}",
                   plot_speeds_stress(series[angular.name]), "Max stress 1634 MPa (angular contact)."),
            Figure("drop_sweep", "Beyond the paper: peaks against the unstated clearance, friction and unbalance "
                   "phase", plot_sweep(sweep, PAPER_DROP), "The paper gives one case only."),
        ]
    words = _case_words(rotor, case)
    out = []
    for bearing, key, says in ((four_point, "QJ202", "Combined rub and bouncing; a tendency to backward whirl; "
                                "max collision force 618 N (the paper's QJ202; dotted line)."),
                               (angular, "7202", "Max collision force 391 N (the paper's 7202; dotted line).")):
        kind = _KIND.get(bearing.type, bearing.type)
        caption = f"{bearing.name} ({kind}): orbit (a) and collision force (b), {words}"
        fig = plot_orbit_force(series[bearing.name], PAPER_DROP[key] if paper else None)
        out.append(Figure(f"drop_orbit_force_{slug(bearing.name)}", caption, retitle(fig, caption),
                          says if paper else ""))
    for bearing, stem, says in ((four_point, "four_point", "Max stress 1483 MPa (the paper's QJ202)."),
                                (angular, "angular", "Max stress 1634 MPa (the paper's 7202).")):
        caption = f"{bearing.name}: spin speeds and max ball stress, {words}"
        out.append(Figure(f"drop_speeds_stress_{stem}", caption,
                          retitle(plot_speeds_stress(series[bearing.name]), caption), says if paper else ""))
    caption = (f"Peaks of {four_point.name} and {angular.name} against clearance, sliding friction and unbalance "
               f"phase ({rotor.mass:g} kg rotor at {case.speed * _RPM:g} rpm)")
    out.append(Figure("drop_sweep", caption, retitle(plot_sweep(sweep, None), caption),
                      "The paper gives one case only." if paper else ""))
    return out


def _tables(compare, four_point, angular, rotor, case, framing: Framing) -> list[dict]:
    r4, ra = compare["results"][four_point.name], compare["results"][angular.name]
    pairs = ((four_point.name, "QJ202", r4), (angular.name, "7202", ra))
    if not framing.own:
        rows = [[name, f"{PAPER_DROP[key]['peak_contact_force_N']:g}", f"{res['peak_contact_force_N']:.0f}",
                 f"{PAPER_DROP[key]['peak_ball_stress_MPa']:g}", f"{res['peak_ball_stress_MPa']:.0f}", res["whirl"],
                 f"{res['impacts']}", f"{res['s0']:.2f}" if res.get("s0") else "-"] for name, key, res in pairs]
        table = {"columns": ["bearing", "peak force, paper [N]", "ours [N]", "peak stress, paper [MPa]",
                             "ours [MPa]", "whirl", "impacts", "s0"], "rows": rows,
                 "caption": "Drop at 6000 rpm, Table II, s = 0.2 mm, Hertz K_b"}
    else:
        columns = ["bearing", "peak force [N]", "peak ball stress [MPa]", "s0", "whirl", "impacts",
                   "first impact [ms]", "largest bounce [µm]", "run"]
        rows = [[name, _num(res["peak_contact_force_N"], ".0f"), _num(res["peak_ball_stress_MPa"], ".0f"),
                 _num(res.get("s0"), ".2f"), res["whirl"], f"{res['impacts']}", _num(res["first_impact_ms"], ".2f"),
                 _num(res["largest_bounce_um"], ".0f"), res["verdict"]] for name, _, res in pairs]
        if framing.paper:
            columns += [f"{framing.paper_label}: peak force [N]", f"{framing.paper_label}: peak stress [MPa]"]
            for row, (_, key, _) in zip(rows, pairs, strict=True):
                row += [f"{PAPER_DROP[key]['peak_contact_force_N']:g} ({key})",
                        f"{PAPER_DROP[key]['peak_ball_stress_MPa']:g} ({key})"]
        table = {"columns": columns, "rows": rows,
                 "caption": f"Drop of a {_case_words(rotor, case)}, ball contact constant K_b from Hertz"}
    tables = [table]
    if "paper_ball_constant" in compare:
        paper_kb = compare["paper_ball_constant"]
        rows_kb = [[name, "paper's K_b (N/mm^1.5)", "-", f"{paper_kb[name]['peak_contact_force_N']:.0f}", "-",
                    f"{paper_kb[name]['peak_ball_stress_MPa']:.0f}", paper_kb[name]["whirl"],
                    f"{paper_kb[name]['impacts']}"]
                   for name in (four_point.name, angular.name)]
        tables.append({"columns": ["bearing", "variant", "", "peak force [N]", "", "peak stress [MPa]", "whirl",
                                   "impacts"], "rows": rows_kb,
                       "caption": "Variant: Table II's K_b = 5.42e5 read as N/mm^1.5 (1.71e10 N/m^1.5)"})
    return tables


def _num(value, fmt: str) -> str:
    return "out of range" if value is None else format(value, fmt)


def _key_results(r4: dict, ra: dict) -> list[list[str]]:
    return [["Drop: peak collision force [N]", _num(r4["peak_contact_force_N"], ".0f"),
             _num(ra["peak_contact_force_N"], ".0f")],
            ["Drop: peak ball stress [MPa]", _num(r4["peak_ball_stress_MPa"], ".0f"),
             _num(ra["peak_ball_stress_MPa"], ".0f")],
            ["Drop: static safety factor s0 at the peak [-]", _num(r4.get("s0"), ".2f"), _num(ra.get("s0"), ".2f")],
            ["Drop: whirl, impacts", f"{r4['whirl']}, {r4['impacts']}", f"{ra['whirl']}, {ra['impacts']}"]]


def _warnings(compare: dict, four_point, angular, rotor, case) -> list[str]:
    """Drops that left the model's range or passed ISO 76's stress, base case and sweep."""
    out = []
    words = _case_words(rotor, case)
    for bearing in (four_point, angular):
        res = compare["results"][bearing.name]
        if res["verdict"] != "ok":
            out.append(f"Drop of a {words} onto {bearing.name}: stopped outside the model's range "
                       f"({res['verdict']}): {res['reason']}.")
        elif res["peak_ball_stress_MPa"] * 1e6 > ISO76_BALL_STRESS:
            out.append(f"Drop of a {words} onto {bearing.name}: peak ball "
                       f"{stress_warning(res['peak_ball_stress_MPa'] * 1e6)[4:]}.")
    sweep = compare["sweep"]
    for bearing in (four_point, angular):
        bad = []
        for field, (axis, _, unit) in SWEEPS.items():
            values = sweep.get(f"{field}_{unit or '1'}")
            if values is None:
                continue
            stresses = sweep[bearing.name][axis]["peak_ball_stress_MPa"]
            bad += [f"{field.replace('_', ' ')} {v:g}{' ' + unit if unit else ''}: "
                    + ("out of range" if s is None else f"{s:.0f} MPa")
                    for v, s in zip(values, stresses, strict=True) if s is None or s * 1e6 > ISO76_BALL_STRESS]
        if bad:
            out.append(f"Drop sweep on {bearing.name}: {len(bad)} variant(s) pass ISO 76's "
                       f"{ISO76_BALL_STRESS / 1e6:.0f} MPa or leave the model's range ({'; '.join(bad)}).")
    return out


def _own_assumptions(sections, r4, ra, four_point, angular) -> list[Assumption]:
    """Every rotor and drop parameter, with the value used and where it comes from."""
    rows = []
    for p in PARAMETERS:
        table = sections.get(p.section) or {}
        if p.key in table:
            value, origin = str(table[p.key]), "your study file"
        elif p.default is not None:
            value, origin = display_value(p, p.default), _default_origin(p.source)
        else:
            value, origin = _derived(p.key, r4, ra, four_point, angular), "derived (see the value)"
        rows.append(Assumption(f"{p.section}.{p.key}: {p.help}", value, origin))
    rows += [
        Assumption("Axial condition of the angular-contact bearing", "inner ring axially located",
                   "A single angular-contact bearing needs an axial location to carry radial load."),
        Assumption("Friction law near zero slip", "μ tanh(v_slip / v_eps)", "Coulomb friction regularised; the "
                   "tolerance checks above show the peaks do not depend on v_eps."),
        Assumption("Rolling-resistance arm", "inner raceway radius (dm - D)/2", "Model choice."),
        Assumption("Ball-set damping", "isotropic on the race velocity", "Model choice."),
        Assumption("Integration", "DOPRI5, adaptive, tolerances as above", "Checked by 10x tighter tolerances."),
        Assumption("Clearance sweep", f"{', '.join(f'{k:g}' for k in OWN_CLEARANCE_FACTORS)} x the clearance; the "
                   "journal radius follows (r = bore/2 - s)", "The race bore is the bearing's; the journal is what "
                   "one would change."),
    ]
    return rows


def _default_origin(source: str) -> str:
    """Where a default comes from, said without the paper's own numbers."""
    if source.startswith(("Table II", "Sec. II")):
        return "default (the source paper's test rig)"
    if source.startswith("ours"):
        return "default of auxbearing" + source[4:].replace(":", ";", 1)
    if source == "standard gravity":
        return "default (standard gravity)"
    return "default of auxbearing"


def _derived(key: str, r4: dict, ra: dict, four_point, angular) -> str:
    if key == "radius":
        return f"{r4['rotor_radius_mm']:g} mm (bore/2 - clearance)"
    if key == "line_stiffness":
        return (f"{r4['line_stiffness_N_per_m10_9']:.4g} N/m^(10/9) ({four_point.name}), "
                f"{ra['line_stiffness_N_per_m10_9']:.4g} ({angular.name}): Palmgren line contact over the bearing "
                "width")
    if key == "ball_constant":
        return (f"Hertz at the loaded contact angle: {r4['ball_constant_N_per_m1_5']:.3g} N/m^1.5 "
                f"({four_point.name}), {ra['ball_constant_N_per_m1_5']:.3g} ({angular.name})")
    return "-"


def _claims(r4: dict, ra: dict) -> list[Claim]:
    """The paper's Sec. II.D drop claims, judged on the two base drops."""
    p4, pa = PAPER_DROP["QJ202"], PAPER_DROP["7202"]
    f4, fa = r4["peak_contact_force_N"], ra["peak_contact_force_N"]
    s4, sa = r4["peak_ball_stress_MPa"], ra["peak_ball_stress_MPa"]
    stress_change = 100 * (s4 / sa - 1)
    return [
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
