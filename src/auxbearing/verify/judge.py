"""Judging one design's cases against the criteria (:mod:`auxbearing.verify.criteria`)."""

from __future__ import annotations

import math

from auxbearing.analysis.scenario_outcome import SATURATED
from auxbearing.analysis.whirl import UNCLASSIFIED
from auxbearing.campaign.evaluate import FAILED, OUT_OF_RANGE
from auxbearing.campaign.statistics import CONFIDENCE
from auxbearing.machine.scenario import SCENARIO_CASE
from auxbearing.machine.stations import of_kind
from auxbearing.verify.cases import (
    BUDGETS,
    MAX_SPEED,
    Cases,
    largest_clearance_tolerances,
    relevitation_span,
    thermal_openings,
)
from auxbearing.verify.criteria import (
    Criterion,
    lower_bound,
    not_checked,
    origin,
    temperature_bound,
    upper_bound,
    whirls_backward,
    yes_no,
)


def _drop_planes(cases: Cases):
    for case, run in cases.drops.items():
        for plane in run.summary["planes"]:
            yield case, run, plane


def judge(cases: Cases, criteria: dict, final: bool = False) -> list[Criterion]:
    """Every criterion of the issue for one design, in the order the report shows them.

    ``final``: the design's last judgement, after its campaign: a design without one (``campaign_samples = 0``) has
    its whirl probability not checked, never left out. Before the campaign (``final`` false) it is not judged yet.
    """
    out = []
    out.append(_static_safety(cases, criteria))
    # no run leaving the model's range
    verdicts = {case: run.summary["verdict"] for case, run in cases.drops.items()}
    if cases.coastdown is not None:
        verdicts["coast-down"] = cases.coastdown.summary["verdict"]
    bad = {c: v for c, v in verdicts.items() if v not in ("ok", *BUDGETS)}
    spent = {c: v for c, v in verdicts.items() if v in BUDGETS}
    reasons = {c: (cases.drops[c].summary if c in cases.drops else cases.coastdown.summary)["reason"]
               for c in (*bad, *spent)}
    exits = _campaign_exits(cases.campaign)
    if exits:  # a drop condition of the campaign is a run as well
        bad["campaign"], reasons["campaign"] = exits
    range_name, range_origin = RANGE, "a run outside the model's range is a failed design"
    if bad or not spent:
        found = "; ".join(f"{c}: {v.replace('_', ' ')}" for c, v in bad.items())  # the verdicts in words
        out.append(yes_no(range_name, "every run ends ok", found or "all ok", not bad,
                          range_origin, "; ".join(f"{c}: {reasons[c]}" for c in bad) or
                          "every drop and the coast-down stayed in range"))
    else:  # a budget reached is no finding about the machine: not checked, never a pass or a fail
        out.append(not_checked(range_name, "budget reached: " + "; ".join(f"{c}: {reasons[c]}" for c in spent),
                               range_origin))
    out.append(_sustained_whirl(cases))
    coast = cases.coastdown.summary if cases.coastdown is not None else None
    if coast is not None and any(p["max_temperature_C"] is None for p in coast["planes"]):
        # its drop did not finish: the figures of a coast-down that never started are no finding
        why = f"the coast-down's own drop ended {coast['drop_verdict'].replace('_', ' ')}: no coast-down ran"
        for name in ("peak bearing temperature", "preload of a closing internal clearance",
                     "drops to failure (fatigue or dent)"):
            out.append(not_checked(name, why, ""))
    elif coast is not None:
        out.append(_peak_temperature(cases, criteria))
        from auxbearing.analysis.coastdown import rest_stress

        stresses = []
        for k, p in enumerate(coast["planes"]):
            pd = p["min_internal_clearance_um"] * 1e-6
            plane = cases.machine.planes[k]
            paired = ", with the matched pair's own preload" if plane.bearing_set is not None else ""
            stresses.append((rest_stress(plane, _ballset(cases, k), pd) / 1e6, p["name"], pd, paired))
        worst_pre = max(stresses)
        out.append(upper_bound("preload of a closing internal clearance", worst_pre[0],
                               criteria["max_preload_stress"] / 1e6, "MPa", origin("max_preload_stress", criteria),
                               f"{worst_pre[1]}: smallest internal clearance {worst_pre[2] * 1e6:.2f} um "
                               f"(stress at rest of the preload it makes{worst_pre[3]})"))
        required = criteria["required_drops"] or cases.machine.life.required_drops
        source = origin("required_drops", criteria) if criteria["required_drops"] else (
            "the machine file's life.required_drops" if "required_drops" in cases.machine.life.given else
            "an assumption of auxbearing (life.required_drops = 10), not a standard's clause")
        lives = [(p["allowed_drops"], p["name"], p["governing"]) for p in coast["planes"]
                 if p["allowed_drops"] is not None]
        if lives:
            allowed = min(lives)
            dent = coast["planes"][0].get("dent_assumption")
            out.append(lower_bound("drops to failure (fatigue or dent)", allowed[0], required, "drops", source,
                                   f"{allowed[1]}: {allowed[2]} governs" + (
                                       f"; dents: {dent} (life.dent_accumulation)" if dent else "")))
        else:
            out.append(not_checked("drops to failure (fatigue or dent)", coast["planes"][0].get("life_note", ""), ""))
    else:
        why = "; ".join(n for n in cases.notes if "coast-down was not run" in n) or "no coast-down was run"
        for name in ("peak bearing temperature", "preload of a closing internal clearance",
                     "drops to failure (fatigue or dent)"):
            out.append(not_checked(name, why, ""))
    # clearance against the magnetic air gap and a seal
    out.append(_air_gap(cases, criteria))
    out.append(_seal(cases, criteria))
    out += _scenario_criteria(cases, criteria)
    if cases.partial_coastdown:
        # a coast-down left out (its design already failing) is no run in range either
        unsettled = PARTIAL_COASTDOWN_CRITERIA + ((range_name,) if cases.coastdown is None else ())
        out = [_unsettled(c, cases.partial_coastdown) if c.name in unsettled else c for c in out]
    out = drops_cut_short(cases, out)
    whirl = _campaign_criterion(cases.campaign, criteria, final)
    return out if whirl is None else [*out, whirl]


def _campaign_criterion(campaign: dict | None, criteria: dict, final: bool) -> Criterion | None:
    """The whirl probability of the campaign; not checked in a final judgement without one; None before it."""
    if campaign is not None:
        return _whirl_probability(campaign, criteria)
    if not final:
        return None
    return not_checked(WHIRL_PROBABILITY, "no campaign was run (a campaign of 0 drops: --campaign-samples or "
                       "verify.campaign_samples)", origin("max_backward_whirl_probability", criteria))


def _peak_temperature(cases: Cases, criteria: dict) -> Criterion:
    """The hottest part of any plane over the coast-down against the allowed temperature.

    A coast-down that ran away thermally stops where a part reaches ``coastdown.max_temperature``: its figure is
    where the run stopped, not the peak the bearing was heading for, and the evidence says so.
    """
    coast = cases.coastdown.summary
    # every part of the plane's network counts (a journal or housing that hot cooks the bearing's grease too); the
    # evidence names the part
    hottest = max((value, p["name"], part) for p in coast["planes"] for part, value in p["max_temperature_C"].items())
    where = f"coast-down, {hottest[1]}, {hottest[2].replace('_', ' ')}"
    if coast["verdict"] == "thermal_runaway":
        where += ("; the run stopped there on its thermal run-away (coastdown.max_temperature): the peak it was "
                  "heading for is higher")
    return temperature_bound("peak bearing temperature", hottest[0], criteria["max_temperature"] - 273.15,
                             cases.machine.coastdown.ambient_temperature - 273.15, origin("max_temperature", criteria),
                             where)


def _micrometres(length: float) -> str:
    """A length [m] in micrometres to 0.01 um: a plane that never touched grows by 1e-17 m, shown as 0."""
    return f"{round(length * 1e6, 2) + 0.0:.3g}"


#: Name of the criterion of the clearance and the rotor's travel against the magnetic air gap (kept from when it
#: judged the clearance alone: verify.json and the reports name it so).
AIR_GAP = "touchdown clearance against the magnetic air gap"
#: How the air gap's evidence begins; what follows names the run its figure came from (the convergence re-run reads it).
AIR_GAP_HEAD = "largest radial travel of the rotor: "
#: How the evidence begins where the clearance rule governs the air-gap criterion.
CLEARANCE_HEAD = "largest radial clearance: "


def _air_gap(cases: Cases, criteria: dict) -> Criterion:
    """The touchdown clearance against its share of the magnetic air gap, and the rotor's travel against the whole gap.

    Two rules, judged as one criterion by the smaller margin (the evidence names the one that governs and gives the
    other's figures):

    * the design rule ``criteria.air_gap_fraction`` (about half the gap) holds the largest clearance the machine
      may have: as given, plus its fit tolerance (:func:`auxbearing.verify.cases.largest_clearance_tolerances`)
      and its thermal opening in the coast-down;
    * the rotor must not reach the magnetic bearings' stators: its largest radial travel in the runs stays inside
      the whole gap. In a drop the journal goes past its clearance by what the mount, the ball set and the contact
      yield (the blower's mounts give 25 um in a drop and 65 um under its 1 kN surge), which the design rule's
      fraction is there to leave room for, so the fraction is not applied to the travel a second time.

    The travel, per plane, is the largest of:

    * each case drop: the journal's largest excursion from the machine's axis, where the stators are centred, plus
      the fit tolerance its clearance may be made above the file's (the drops ran at the file's clearance);
    * the coast-down: the clearance as given, its fit tolerance, its thermal opening, and what the coast-down's own
      drop travelled beyond its clearance (the coast-down keeps no journal positions; its drop at full speed is the
      hardest landing it makes);
    * the campaign's drops that ended ok: their largest excursion (each ran at a clearance within its tolerance;
      which plane is not kept, so it counts for every plane);
    * without a coast-down, the clearance as made.

    The coast-down records the rotor at the touchdown planes only. On a rigid rotor, a radial magnetic bearing
    between the planes sees no more than the planes do (the axis between them is a convex combination of theirs); one
    beyond them is judged where it sits by the planes' figures carried along the axis, the bound of a tilting rotor
    (as :func:`auxbearing.machine.stations.amb._check_air_gaps` bounds the clearance there). A bending rotor's axis
    is no straight line through the planes, so each case drop's record at a radial magnetic bearing
    (``max_excursion_um`` of its ``amb`` summary) is judged too, with the largest of the planes' fit tolerances on
    it, and so is the campaign's (its drops that ended ok, as at the planes; a store made before it was recorded
    has none); the coast-down keeps the planes only, and the evidence says so.
    """
    if criteria["amb_air_gap"] is None:
        return not_checked(AIR_GAP, "give criteria.amb_air_gap to check it", origin("air_gap_fraction", criteria))
    planes = cases.machine.planes
    tolerances = largest_clearance_tolerances(cases)
    # each source: (its figure at every plane [m], the evidence of each plane's figure)
    sources: list[tuple[list[float], list[str]]] = []

    def fit(k: int) -> str:
        tol, source = tolerances[k]
        return f" + {_micrometres(tol)} um of fit tolerance ({source})" if tol > 0.0 else ""

    for case, run in cases.drops.items():
        reach, said = [], []
        for k, (plane, p) in enumerate(zip(planes, run.summary["planes"], strict=True)):
            reach.append(p["max_excursion_um"] * 1e-6 + tolerances[k][0])
            said.append(f"{case}, {plane.name}: the journal {p['max_excursion_um'] * 1e-3:.4g} mm from the machine's "
                        f"axis ({plane.radial_clearance * 1e3:.4g} mm of clearance as given, the mount travelling "
                        f"{p['max_mount_deflection_um']:.3g} um){fit(k)}")
        sources.append((reach, said))
    history = cases.coastdown.history if cases.coastdown is not None else None
    if history is not None:
        own = cases.drops[MAX_SPEED].summary["planes"]  # the coast-down starts with this drop (cases.submit_cases)
        reach, said = [], []
        for k, (plane, growth, p) in enumerate(zip(planes, thermal_openings(history, planes), own, strict=True)):
            beyond = max(0.0, p["max_excursion_um"] * 1e-6 - plane.radial_clearance)
            reach.append(plane.radial_clearance + tolerances[k][0] + growth + beyond)
            said.append(f"coast-down, {plane.name}: {plane.radial_clearance * 1e3:.4g} mm as given{fit(k)} + "
                        f"{_micrometres(growth)} um of thermal growth in the coast-down + {_micrometres(beyond)} um "
                        "the journal went past its clearance in the coast-down's own drop (the mount travelling "
                        f"{p['max_mount_deflection_um']:.3g} um; the coast-down keeps no journal positions, so its "
                        "hardest landing stands in for the rest of it)")
        sources.append((reach, said))
    else:
        sources.append(([p.radial_clearance + tol for p, (tol, _) in zip(planes, tolerances, strict=True)],
                        [f"{p.name}: {p.radial_clearance * 1e3:.4g} mm as given{fit(k)} (no coast-down ran to open "
                         "it further)" for k, p in enumerate(planes)]))
    reached = (cases.campaign or {}).get("largest_excursion_mm")
    if reached is not None:
        sources.append(([reached * 1e-3] * len(planes),
                        [f"the campaign's {cases.campaign['ok']} drops that ended ok: the journal {reached:.4g} mm "
                         "from the machine's axis at its largest (each at a clearance within its fit tolerance)"]
                        * len(planes)))
    found, where = -math.inf, ""
    for reach, said in sources:  # the first of equal figures governs: a case drop before the coast-down
        for value, text in zip(reach, said, strict=True):
            if value > found:
                found, where = value, text
    bearings = [b for b in of_kind(cases.machine.stations, "amb") if not b.axial]
    covered = ""
    if bearings and bends(cases.machine):
        # a bending rotor's axis is no straight line through the planes: each case drop records it at the bearings
        widest = max(range(len(planes)), key=lambda k: tolerances[k][0])
        for case, run in cases.drops.items():
            for record in run.summary.get("amb", []):
                if record.get("max_excursion_um") is None:  # an axial bearing
                    continue
                value = record["max_excursion_um"] * 1e-6 + tolerances[widest][0]
                if value > found:
                    found = value
                    where = (f"{case}, {record['name']}: the rotor {record['max_excursion_um'] * 1e-3:.4g} mm from "
                             f"the machine's axis at the magnetic bearing, bending included{fit(widest)}")
        at_bearings = (cases.campaign or {}).get("largest_bearing_excursion_mm")  # None: a store made before it
        if at_bearings is not None and at_bearings * 1e-3 > found:
            found = at_bearings * 1e-3
            where = (f"the campaign's {cases.campaign['ok']} drops that ended ok: the rotor {at_bearings:.4g} mm from "
                     "the machine's axis at a magnetic bearing at its largest, bending included (each at a clearance "
                     "within its fit tolerance)")
        recorded = "the case drops and the campaign" if at_bearings is not None else "the case drops"
        unrecorded = ("the coast-down is judged at the touchdown planes, which it records" if at_bearings is not None
                      else "the coast-down and the campaign are judged at the touchdown planes, which they record")
        covered = (f"; the magnetic bearings are judged in {recorded}, which record the bending rotor there; "
                   f"{unrecorded}")
    elif bearings and len(planes) > 1:
        ends = (min(p.position for p in planes), max(p.position for p in planes))
        outside = [b for b in bearings if not ends[0] <= b.position <= ends[1]]
        for b in outside:
            for reach, said in sources:
                value = _carried(b.position, [p.position for p in planes], reach)
                if value > found:
                    found = value
                    where = (f"{b.name} at {b.position * 1e3:g} mm, beyond the touchdown planes: "
                             f"{value * 1e3:.4g} mm, the rigid rotor's axis through the planes' figures ("
                             + "; ".join(dict.fromkeys(said)) + ")")  # the campaign's one figure, said once
        covered = ("; the magnetic bearings sit between the touchdown planes, where a rigid rotor's excursion is no "
                   "larger than at the planes" if not outside else "")
    gap = criteria["amb_air_gap"]
    allowed = criteria["air_gap_fraction"] * gap
    openings = thermal_openings(history, planes) if history is not None else [0.0] * len(planes)
    made_at = [p.radial_clearance + tolerances[k][0] + openings[k] for k, p in enumerate(planes)]
    k = max(range(len(planes)), key=made_at.__getitem__)  # the first of equal clearances, as for the travel
    made = made_at[k]
    # named "coast-down, <plane>" where the coast-down opened it: the convergence re-run reads the evidence so
    rule = (f"{'coast-down, ' if history is not None else ''}{planes[k].name}: {planes[k].radial_clearance * 1e3:.4g} "
            f"mm as given{fit(k)}" + (f" + {_micrometres(openings[k])} um of thermal growth in the coast-down"
                                      if history is not None else ""))
    if 1.0 - found / gap < 1.0 - made / allowed:
        return upper_bound(AIR_GAP, found * 1e3, gap * 1e3, "mm",
                           "the whole air gap from your [criteria]: the rotor must not reach the magnetic bearings",
                           AIR_GAP_HEAD + where + covered + f"; the largest clearance, {made * 1e3:.4g} mm, keeps "
                           f"within the design rule's {allowed * 1e3:.4g} mm")
    # the travel's figure without its run's name: the convergence re-run must not take it for the governing one
    return upper_bound(AIR_GAP, made * 1e3, allowed * 1e3, "mm",
                       f"{origin('air_gap_fraction', criteria)}; air gap from your [criteria]",
                       CLEARANCE_HEAD + rule + f"; the rotor's largest travel, {found * 1e3:.4g} mm, keeps within "
                       f"the whole {gap * 1e3:.4g} mm air gap" + covered)


def bends(machine) -> bool:
    """Whether the rotor has elastic modes kept (its axis is then no straight line between the planes)."""
    modal = machine.modal()
    return modal is not None and modal.n_modes > 0


def _carried(at: float, positions: list[float], reach: list[float]) -> float:
    """The most a rigid rotor's axis can be from the machine's axis at ``at`` with plane k within ``reach[k]`` [m].

    The least over pairs of planes of r_j |a_k - a| / L + r_k |a - a_j| / L, L = |a_k - a_j| (each plane at its
    limit, in opposite directions beyond the span).

    >>> round(_carried(0.3, [-0.15, 0.15], [1.0, 1.0]), 9), round(_carried(0.0, [-0.15, 0.15], [1.0, 2.0]), 9)
    (2.0, 1.5)
    """
    out = math.inf
    for j, (aj, rj) in enumerate(zip(positions, reach, strict=True)):
        for ak, rk in zip(positions[j + 1:], reach[j + 1:], strict=True):
            span = abs(ak - aj)
            if span > 0.0:
                out = min(out, (rj * abs(ak - at) + rk * abs(at - aj)) / span)
    return out if math.isfinite(out) else max(reach)


def _seal(cases: Cases, criteria: dict) -> Criterion:
    """The journal's largest excursion from the machine's axis in the drops against the seal clearance.

    The campaign's drops are drops the machine may see: the largest of the case drops and of the campaign's drops
    that ended ok is judged, and the evidence says which it is (a campaign's drop has no case of its own, so the
    convergence re-run leaves it alone).
    """
    name = "journal excursion against the seal clearance"
    limit = criteria["seal_clearance"]
    if limit is None:
        return not_checked(name, "give criteria.seal_clearance to check it", "user input")
    excursion, case = max((run.summary["largest_excursion_m"], case) for case, run in cases.drops.items())
    where = f"largest journal excursion from the machine's axis in the drops: {case}"
    reached = (cases.campaign or {}).get("largest_excursion_mm")
    if reached is not None and reached * 1e-3 > excursion:
        where = (f"largest journal excursion from the machine's axis in the campaign's {cases.campaign['ok']} drops "
                 f"that ended ok (the case drops' largest: {excursion * 1e3:.4g} mm)")
        excursion = reached * 1e-3
    return upper_bound(name, excursion * 1e3, limit * 1e3, "mm", origin("seal_clearance", criteria), where)


def _sustained_whirl(cases: Cases) -> Criterion:
    """No sustained backward whirl or dry whip in any drop or in the coast-down after the drop at full speed."""
    whirls = [(case, p["name"], p["backward_whirl_onset_ms"], p["whirl"]) for case, _, p in _drop_planes(cases)
              if whirls_backward(p)]
    found = [f"{c}, {n}: backward whirl sustained from {o:.0f} ms, {w} at the end" if o is not None
             else f"{c}, {n}: {w} at the end" for c, n, o, w in whirls]
    if cases.coastdown is not None:  # its windows judge the journals' whirl as a drop does (coastdown_phases)
        found += [f"coast-down, {p['name']}: backward whirl sustained from {p['backward_whirl_from_s']:.2f} s, "
                  f"{p['backward_whirl_s']:.2f} s of it" for p in cases.coastdown.summary["planes"]
                  if p.get("backward_whirl_from_s") is not None]
    c = yes_no("no sustained backward whirl or dry whip", "none in any drop or in the coast-down",
               "; ".join(found) or "none", not found,
               "Jiang & Ulbrich 2005 and Jiang 2007: backward whirl and dry whip destroy touchdown bearings",
               "whirl judged window by window (auxbearing.analysis.whirl)")
    unknown = [f"{case}, {p['name']}" for case, _, p in _drop_planes(cases) if p["whirl"] == UNCLASSIFIED]
    if unknown and c.passed:  # a drop shorter than one whirl window shows no whirl either way
        return _unsettled(c, "no whirl window closed in " + "; ".join(unknown) + " (shorter than drop.whirl_window)")
    return c


def _campaign_exits(campaign: dict | None) -> tuple[str, str] | None:
    """(finding, reason) when drops of the campaign left the model's range, else None."""
    if not campaign:
        return None
    counts = {v: n for v, n in campaign.get("verdicts", {}).items() if v in OUT_OF_RANGE and n}
    if not counts:
        return None
    left, ran = sum(counts.values()), campaign["completed"]
    return (f"{left} of {ran} drops out of range",
            f"{left} of the campaign's {ran} drops left the model's range ("
            + ", ".join(f"{v.replace('_', ' ')}: {n}" for v, n in counts.items()) + ")")


def drops_cut_short(cases: Cases, criteria: list[Criterion]) -> list[Criterion]:
    """``criteria`` with those of :data:`PARTIAL_DROP_CRITERIA` that pass not checked when a drop was cut short.

    A drop stops early when it leaves the model's range or reaches a budget; under ``--quick`` every drop runs only
    its first part (``cases.partial_drops``), and then staying in the model's range so far is no pass either: the
    heavy rotor's drop is in range at the quick look's 50 ms and runs a ball over its groove shoulder at 66.9 ms.
    """
    cut = {case: run.summary["verdict"] for case, run in cases.drops.items() if run.summary["verdict"] != "ok"}
    whys = [f"{c} stopped early ({v.replace('_', ' ')})" for c, v in cut.items()]
    names = PARTIAL_DROP_CRITERIA
    if cases.partial_drops:
        whys.append(cases.partial_drops)
        names += (RANGE,)
    if not whys:
        return criteria
    why = "; ".join(whys)
    return [_unsettled(c, why) if c.name in names else c for c in criteria]


def _static_safety(cases: Cases, criteria: dict) -> Criterion:
    """s0 of every ball contact in every drop (ISO 76), a drop cut short included up to where it stopped.

    A drop that left the model's range or reached a budget stops there: its stresses so far are inside the
    model and count; the criterion is then not checked unless a value already fails (:data:`PARTIAL_DROP_CRITERIA`;
    the heavy rotor's drop at the maximum speed reaches s0 1.16 before a contact ellipse runs over its groove
    shoulder, where its drop at low speed, which ends, gives 16). The campaign's drops are drops the machine may
    see: the smallest of the case drops and of the campaign's drops that ended ok is judged, and the evidence says
    which it is.
    """
    s0s = [(p["s0"], case, p["name"], run.summary["verdict"]) for case, run, p in _drop_planes(cases)
           if p["s0"] is not None]
    if not s0s:
        found, where = None, "no drop reached a ball contact inside the model's range"
    else:
        worst = min(s0s)
        found = worst[0]
        where = f"smallest in the drops: {worst[1]}, {worst[2]}" + (
            "" if worst[3] == "ok" else " (up to where that drop stopped)")
    campaign = cases.campaign or {}
    smallest = campaign.get("smallest_s0")
    below = campaign.get("p_s0_below_required", {}).get("successes", 0)
    # without a case drop's value the campaign's stands in only when it fails: a case drop that found no ball
    # contact in range is itself no pass
    if smallest is not None and (smallest < found if found is not None else below):
        ours = ("no case drop reached a ball contact inside the model's range" if found is None else
                f"the case drops' smallest: {found:.4g}")
        # no case is named: the convergence re-run finds the drop it repeats by its case name in the evidence
        where = (f"{below} of the campaign's {campaign['ok']} drops that ended ok fall below {criteria['min_s0']:g}, "
                 f"the smallest at {smallest:.4g}" if below else
                 f"smallest in the campaign's {campaign['ok']} drops that ended ok: {smallest:.4g}") + f" ({ours})"
        found = smallest
    return lower_bound("static safety factor s0 of every ball contact", found, criteria["min_s0"], "-",
                       origin("min_s0", criteria), where)


#: Name of the criterion that no run leaves the model's range.
RANGE = "no run leaves the model's range or a limit"

#: Criteria judged over the drops that a drop cut short (out of the model's range or at a budget) can fail but not
#: pass: what it would have shown after its stop is unknown.
PARTIAL_DROP_CRITERIA = ("static safety factor s0 of every ball contact", "no sustained backward whirl or dry whip",
                         "journal excursion against the seal clearance",
                         "peak magnetic-bearing current against its amplifier's limit", AIR_GAP)

#: Criteria a coast-down cut short (``--quick``, a budget, or a limit such as a thermal run-away that ends it before
#: standstill) can fail but not pass: temperatures and the closing clearance go on changing, the over-rolling of
#: the rest of the run adds damage, and a journal may still start to whirl backward.
PARTIAL_COASTDOWN_CRITERIA = ("peak bearing temperature", "preload of a closing internal clearance",
                              "drops to failure (fatigue or dent)", AIR_GAP,
                              "no sustained backward whirl or dry whip")


#: The bound the campaign's whirl criterion is judged by, in words: the upper end of the two-sided 95 % Wilson
#: interval (campaign.statistics.CONFIDENCE) leaves 2.5 % above it, so it is a one-sided 97.5 % bound.
WHIRL_BOUND = f"one-sided {50.0 * (1.0 + CONFIDENCE):g} % upper bound"
#: Name of the campaign's criterion: judged by :data:`WHIRL_BOUND`, not by the estimate.
WHIRL_PROBABILITY = f"probability of backward whirl over the drop conditions, {WHIRL_BOUND}"


def _scenario_criteria(cases: Cases, criteria: dict | None = None) -> list[Criterion]:
    """The magnetic bearings' criteria over the scenario cases: current against its limit, re-levitation asked."""
    criteria = criteria or {"max_amb_current_share": 1.0, "relevitation_time": None, "given": []}
    runs = {c: r.summary for c, r in cases.drops.items() if c.startswith(SCENARIO_CASE) and r.summary.get("amb")}
    if not runs:
        return []
    out = []
    shares = [(a["peak_axis_current_A"] / a["max_current_A"], a["peak_axis_current_A"], a["max_current_A"], c,
               a["name"]) for c, s in runs.items() for a in s["amb"] if math.isfinite(a["max_current_A"])]
    name = "peak magnetic-bearing current against its amplifier's limit"
    if shares:
        share, peak, limit, case, bearing = max(shares)
        allowed = criteria["max_amb_current_share"]
        # the amplifier's lag brings a current towards its clipped command without ever reaching it: within
        # SATURATED of the limit it is there, so that threshold is the required value and the margin is measured
        # against it (a current at its limit fails with a negative margin, never with +0.0 %)
        threshold = SATURATED * allowed * limit
        c = upper_bound(name, peak, threshold, "A",
                        ("your [criteria] max_amb_current_share of " if "max_amb_current_share" in criteria["given"]
                         else "") + f"amb.max_current of the machine file, less {100 * (1 - SATURATED):g} % (a "
                        "controller at its limit has lost authority: reaching it fails, and the amplifier's lag "
                        "only approaches it)",
                        f"{case}, {bearing}: {share * 100:.1f} % of its limit")
        out.append(c if c.passed else c._replace(evidence=c.evidence + " (saturated)"))
    else:
        out.append(not_checked(name, "give amb.max_current to check it", "amb.max_current"))
    levitations = {c: s["scenario"]["levitation"] for c, s in runs.items() if "levitation" in s["scenario"]}
    if levitations:
        unstable = {c: v for c, v in levitations.items() if not v["stable"]}
        out.append(yes_no("the levitated machine is stable at its speed", "stable in every scenario",
                          "stable" if not unstable else "; ".join(
                              f"{c.removeprefix(SCENARIO_CASE)}: a mode near {v['least_damped_mode_Hz']:.1f} Hz "
                              + ("is undamped (its rate is zero to the computation's precision)" if v.get("undamped")
                                 else f"grows at {v['least_damped_rate_per_s']:+.3g} 1/s")
                              for c, v in unstable.items()),
                          not unstable, "a magnetic bearing that cannot hold the spinning rotor fails before any "
                          "touchdown", "the levitated machine linearised at its speed (its least damped mode)"))
    every = criteria.get("relevitation_time")
    for case, s in runs.items():
        asked, found = s["scenario"].get("relevitate_within_ms"), s["scenario"]
        source = "the scenario's relevitate_within"
        if asked is None and every is not None and found.get("outcome") != "on the touchdown bearings":
            asked, source = every * 1e3, "your [criteria] relevitation_time"
        if asked is None:
            continue
        took = found["relevitated_at_ms"] - found["time_ms"] if found.get("relevitated_at_ms") is not None else None
        name = f"re-levitation after {case.removeprefix(SCENARIO_CASE)}"
        ran = s["simulated_s"] * 1e3 - found["time_ms"]  # [ms] after the strike
        # a run shorter than this past the strike cannot show a re-levitation within the limit, so without one it is
        # no finding (plan_cases runs the scenario this long)
        needed = relevitation_span(asked * 1e-3) * 1e3
        if took is None and ran < needed:
            out.append(not_checked(name, f"{case}: {found.get('outcome', 'not levitated')}; the run ended {ran:.1f} ms "
                                   f"after the strike, too soon to tell a re-levitation within {asked:g} ms (it needs "
                                   f"{needed:.1f} ms)" + (" (--quick)" if cases.quick else ""), source))
            continue
        out.append(upper_bound(name, took, asked, "ms",
                               source, f"{case}: {found.get('outcome', 'not levitated')}"))
    return out


def _whirl_probability(campaign: dict, criteria: dict) -> Criterion:
    """P(backward whirl) against its limit, by the Wilson upper bound of the campaign's estimate.

    A campaign passes only when the upper end of its two-sided 95 % Wilson interval (a one-sided 97.5 % upper bound,
    :data:`WHIRL_BOUND`) is within the limit; an estimate above the limit fails; between the two the campaign is
    too small to tell, and the criterion is not checked (with the number of whirl-free drops that would show it:
    Wilson's upper bound for no events is z^2 / (n + z^2), z = 1.96).
    """
    limit = criteria["max_backward_whirl_probability"]
    source = origin("max_backward_whirl_probability", criteria)
    if not campaign["ok"]:
        return not_checked(WHIRL_PROBABILITY, f"none of the campaign's {campaign.get('samples', 0)} drops ended "
                           "inside the model's range", source)
    p = campaign["p_backward_whirl"]
    unclassified = campaign.get("whirl_unclassified", 0)
    if not p.get("trials", campaign["ok"]):
        return not_checked(WHIRL_PROBABILITY, f"none of the campaign's {campaign['ok']} drops that ended ok closed a "
                           "whirl window (drop.whirl_window), so none shows whether it whirled", source)
    evidence = (f"campaign of {campaign['ok']} drops that ended ok: estimate {p['value']:.3f}, two-sided "
                f"{100 * CONFIDENCE:g} % Wilson interval {p['low']:.3f}-{p['high']:.3f}, whose upper end is judged")
    if campaign.get("stopped_decided"):
        evidence += (f" (stopped after its first {campaign['samples']} of {campaign['planned']} drops: even with "
                     "every drop left ending without whirl the estimate stays above the limit)")
    lost = {v: n for v, n in campaign.get("verdicts", {}).items() if v in FAILED and n}
    if unclassified:  # drops too short to close a whirl window: whether they whirled is unknown too
        lost["whirl not classified"] = unclassified
    if lost:  # a budget reached, a sample refused, an error: no result, so no whirl either way
        evidence += (f"; {sum(lost.values())} drops gave no result ("
                     + ", ".join(f"{v.replace('_', ' ')}: {n}" for v, n in lost.items()) + ")")
    c = upper_bound(WHIRL_PROBABILITY, p["high"], limit, "-", source, evidence)
    if c.passed is True and lost:
        return c._replace(passed=None, kind="not checked",
                          evidence=f"{evidence}: whether they whirled is unknown, so this is not a pass")
    if c.passed is False and p["value"] <= limit:
        need = _drops_to_show(p["value"], limit)
        more = "" if need is None else (
            f"; {need} or more drops without whirl would show it" if p["value"] == 0.0 else
            f"; at the estimated rate about {need} drops would show it") + " (verify.campaign_samples)"
        c = c._replace(passed=None, kind="not checked",
                       evidence=f"{evidence}: too few drops to show the probability is within {limit:g}{more}")
    return c


def campaign_drops(campaign: dict | None) -> int | None:
    """How many drops a campaign's whirl probability rests on (those that ended ok with their whirl classified)."""
    if not campaign:
        return None
    return (campaign.get("p_backward_whirl") or {}).get("trials", campaign.get("ok"))


def whirl_by_estimate(criteria: list[Criterion], campaign: dict | None, limit: float) -> list[Criterion]:
    """``criteria`` with the whirl probability's margin taken from the campaign's estimate instead of its upper bound.

    For ranking designs whose campaigns differ in size (:func:`auxbearing.verify.run._ranked`); pass or fail stays
    the verdict's.
    """
    value = ((campaign or {}).get("p_backward_whirl") or {}).get("value")
    if value is None or not math.isfinite(value):
        return criteria
    return [c._replace(margin=1.0 - value / limit) if c.name == WHIRL_PROBABILITY and c.margin is not None else c
            for c in criteria]


def _drops_to_show(rate: float, limit: float) -> int | None:
    """Smallest campaign whose Wilson upper bound at this observed rate is within the limit (None: none is).

    The bound (p + z^2/2n + z sqrt(p (1 - p)/n + z^2/4n^2)) / (1 + z^2/n) falls with n towards p, so a rate
    below the limit reaches it; bisection on n. For p = 0 it is z^2 (1/limit - 1).
    """
    from scipy.stats import norm

    if not 0.0 <= rate < limit:
        return None
    z = float(norm.ppf(0.5 * (1.0 + CONFIDENCE)))

    def bound(n: float) -> float:
        return (rate + z * z / (2 * n) + z * math.sqrt(rate * (1 - rate) / n + z * z / (4 * n * n))) / (1 + z * z / n)

    low, high = 1, 2
    while bound(high) > limit:
        low, high = high, 2 * high
        if high > 10**9:
            return None
    while high - low > 1:
        mid = (low + high) // 2
        low, high = (mid, high) if bound(mid) > limit else (low, mid)
    return high


def _unsettled(c: Criterion, why: str) -> Criterion:
    """A criterion a partial coast-down passed: kept with its finding, but not checked (``why``: what cut it)."""
    if c.passed is not True:
        return c
    return c._replace(passed=None, kind="not checked", evidence=f"{c.evidence}; {why}, so this is not a pass")


def _ballset(cases: Cases, k: int):
    from auxbearing.bearings.ballset import ballset_params

    plane = cases.machine.planes[k]
    return ballset_params(plane.bearing, plane.ball_constant)

