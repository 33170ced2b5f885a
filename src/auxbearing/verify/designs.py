"""Other bearings in the same seats, and the best geometry of the chosen bearing family.

Candidates (:func:`candidate_tables`): each candidate bearing replaces the bearing of every touchdown
plane, with everything derived from the bearing (journal radius from its bore, race mass, line-contact
stiffness) derived again, so the comparison is the one the source paper makes (four-point against
angular contact) carried to the machine.

Recommendation (:func:`recommend`): for the family of the machine's bearing, the contact angle (within
the source paper's Sec. IV range of 15-45 deg), the groove radius ratios (0.505-0.53, inner; the outer
keeps its offset from the inner) and the radial touchdown clearance that maximise the worst margin of the
verdict's own criteria a drop at the maximum speed checks: s0 against its required value, the journal's
excursion against the seal clearance, the clearance as made against its share of the magnetic air gap and the
rotor's travel in the point's drop against the whole gap (each margin as the verdict measures it, on this one
drop), with leaving the model's range and sustained backward whirl as failures.
The clearance stays between the levitated rotor's orbit over :data:`ORBIT_ZONE` (ISO 14839-2) and the
air-gap limit less the clearance's fit tolerance, within 60-140 % of the file's. A grid over the box, then a
compass search from its best point (:func:`_polish`), each point a drop of the machine, each round's points run
side by side. The margin against the air gap has a bound known before a point's drop: the clearance rule's,
which the drop's travel can only lower. The grid goes out one clearance level at a time, the
widest bound first, and a point whose bound is already below the best point's smallest margin
(:func:`cannot_beat`) is not run, in the grid or the polish, since no drop can make it better. On the blower,
where the air gap binds at the smallest clearance, that leaves out the grid's two larger clearances (18 of its 27
drops) and the polish's steps towards them. The criterion with the smallest margin at the optimum binds.
Geometries whose smallest margins agree (within :data:`TIE_MARGIN`) are told apart by their next smallest, and so
on (:func:`better`): where one criterion depends mostly on one variable (the air gap on the
clearance), the others are not left to the order in which the grid was run. A variable at a bound of the box is
said. A point that fails a criterion is never recommended; the recommended design is then verified in full
(:func:`auxbearing.verify.run.verify`; its coast-down last, and only when its drops and campaign fail nothing) and
its verdict shown.
"""

from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np

from auxbearing.common.errors import InputError

CONTACT_ANGLE_RANGE = (math.radians(15.0), math.radians(45.0))  #: source paper Sec. IV
GROOVE_RATIO_RANGE = (0.505, 0.53)  #: ours: the paper's 0.51-0.52 widened to what makers grind
CLEARANCE_RANGE = (0.6, 1.4)  #: ours: fraction of the file's radial clearance
#: A levitated rotor's displacement stays below this fraction of the smallest touchdown clearance in normal
#: running (ISO 14839-2:2004, zone A/B boundary), so the clearance must be at least the orbit over it.
ORBIT_ZONE = 0.3
#: Most drops the polish after the grid runs.
POLISH_POINTS = 12
#: Difference in a margin below which two geometries tie on it (:func:`better`), in the grid and the polish.
TIE_MARGIN = 1e-3
#: The polish stops when its step falls below this share of each variable's range (an eighth of the 3-level
#: grid's spacing after three rounds).
POLISH_STEP_MIN = 0.05


def _design_tables(data: dict, machine, x: np.ndarray) -> dict:
    """The machine's tables with contact angle, inner groove ratio and clearance factor x = (alpha, fi, c)."""
    tables = copy.deepcopy(data)
    for k, plane in enumerate(tables["touchdown"]):
        bearing = machine.planes[k].bearing
        table = bearing.to_table()
        if bearing.type != "deep_groove":
            table["contact_angle"] = f"{float(x[0])!r} rad"
        offset = bearing.outer_groove_ratio - bearing.inner_groove_ratio
        table["inner_groove_ratio"] = float(x[1])
        table["outer_groove_ratio"] = float(x[1] + offset)
        plane["bearing"] = table
        plane.pop("ball_constant", None)  # Hertz's K_b (Eq. 15) follows the new contact angle and groove ratios
        pair = machine.planes[k].bearing_set
        if pair is not None:  # the new geometry is each row's: the pair keeps its arrangement and preload
            table["arrangement"] = pair.arrangement
            # a preload class stays a class (a share of the new row's C0, as the maker's class would be); a
            # force stays the force and an offset the offset
            plane["preload"] = pair.preload if not pair.preload.endswith("offset") else f"{pair.preload_offset!r} m"
        clearance = machine.planes[k].radial_clearance * x[2]
        plane["radial_clearance"] = f"{float(clearance)!r} m"
        if "journal_radius" in plane:
            # the bearing's bore stays: a clearance is made by the journal's diameter (its sleeve), so a journal
            # given in the file changes with it (kept, a larger clearance would push the race past the bore)
            race_bore = machine.planes[k].journal_radius + machine.planes[k].radial_clearance
            plane["journal_radius"] = f"{float(race_bore - clearance)!r} m"
    return tables


def recommended_tables(data: dict, name: str, base: Path | None, rec: dict) -> dict:
    """The machine file's tables with the recommended geometry (:func:`recommend`'s result) in every plane."""
    from auxbearing.machine.model import machine_from_mapping

    machine = machine_from_mapping(data, name, base)
    x = np.array([math.radians(rec["contact_angle_deg"]), rec["inner_groove_ratio"], rec["clearance_factor"]])
    return _design_tables(data, machine, x)


def _point_summary(tables: dict, name: str, base: Path | None) -> dict:
    """The summary of one design point's drop (a task of the search), or the reason it cannot be built."""
    from auxbearing.analysis.drop import run_machine
    from auxbearing.machine.model import machine_from_mapping

    try:
        return run_machine(machine_from_mapping(tables, name, base).for_batch(), lean=True).summary
    except InputError as err:  # a geometry the bearing cannot have (e.g. clearance past the bore)
        return {"invalid": str(err)}


def search_refused(machine) -> str | None:
    """Why the geometry search cannot serve this machine, or None: it varies one family's geometry in every plane."""
    families = sorted({p.bearing.type.replace("_", " ") for p in machine.planes})
    if len(families) > 1:  # a deep-groove plane's 0 deg would make the four-point plane a four-point bearing at 0 deg
        return (f"the planes carry bearings of different families ({', '.join(families)}), and the search varies one "
                "family's contact angle and groove ratios in every plane; verify a machine of one family per search")
    return None


def recommend(data: dict, name: str, base: Path | None, criteria: dict, quick: bool = False,
              progress=None, executor=None, as_built=None) -> dict:
    """The geometry of the machine's bearing family that maximises the worst drop margin (module docstring).

    ``executor`` (``submit(fn, *args)``) runs the drops; the grid's points go to it a tier at a time
    (:func:`_tiers`). ``as_built``: the summary of the machine's own drop at the maximum speed, as an object whose
    ``result()`` gives it (the verification's drop of the design), which the bearing as it stands is judged on;
    without it that drop is run here.
    """
    from auxbearing.machine.judging import verify_settings
    from auxbearing.machine.model import machine_from_mapping
    from auxbearing.verify.cases import QUICK_DROP, Immediate, clearance_tolerance
    from auxbearing.verify.criteria import whirls_backward

    executor = executor or Immediate()

    machine = machine_from_mapping(data, name, base)
    first = machine.planes[0].bearing
    angle_free = first.type != "deep_groove"
    c_high = CLEARANCE_RANGE[1]
    gap_limit = None
    # the clearance as made may lie its fit tolerance above the design's (the verdict counts it: judge._air_gap);
    # the tolerance of the file's geometry serves every point (the bore stays, the journal moves by micrometres)
    settings = verify_settings(data)
    tolerances = [clearance_tolerance(p, settings)[0] for p in machine.planes]
    if criteria.get("amb_air_gap"):
        gap_limit = criteria["air_gap_fraction"] * criteria["amb_air_gap"]
        c_high = min(c_high, min((gap_limit - tol) / p.radial_clearance
                                 for p, tol in zip(machine.planes, tolerances, strict=True)))
    # the levitated rotor orbits its mass centre above its rigid-body modes: the orbit is the unbalance, at least
    # the balance grade's (the verification's campaign uses the same)
    orbit = max(machine.rotor.unbalance, settings["balance_grade"] / max(abs(machine.rotor.speed), 1e-9))
    c_low = max(CLEARANCE_RANGE[0], orbit / ORBIT_ZONE / min(p.radial_clearance for p in machine.planes),
                # the campaign keeps a clearance as made above half its own (cases.campaign_spreads): below twice the
                # tolerance, the recommended geometry's campaign would clip its spread
                *(2.0 * tol / p.radial_clearance for p, tol in zip(machine.planes, tolerances, strict=True)))
    bounds = np.array([CONTACT_ANGLE_RANGE if angle_free else (first.contact_angle, first.contact_angle),
                       GROOVE_RATIO_RANGE, (c_low, max(c_high, c_low))])
    duration = {"duration": f"{float(min(machine.simulation.duration, QUICK_DROP))!r} s"} if quick else {}
    evaluated: list[dict] = []

    def gap_margin(x, summary: dict | None = None) -> float | None:
        """The margin against the air gap as the verdict takes it: the smaller of the clearance rule's and the travel's.

        The clearance as made against ``air_gap_fraction`` of the gap is known before the point's drop, and it is
        the larger-margin bound the drop can only lower (the screen of :func:`cannot_beat`): the travel, at least
        the clearance, is judged against the whole gap. With ``summary``, the point's drop's travel counts.
        """
        if gap_limit is None:
            return None
        made = max(p.radial_clearance * x[2] + tol for p, tol in zip(machine.planes, tolerances, strict=True))
        margin = 1.0 - made / gap_limit
        if summary is not None:
            travel = max(max(p.radial_clearance * x[2], q["max_excursion_um"] * 1e-6) + tol
                         for p, q, tol in zip(machine.planes, summary["planes"], tolerances, strict=True))
            margin = min(margin, 1.0 - travel / criteria["amb_air_gap"])
        # rounded: at the box's upper bound the clearance sits on the limit, where the margin is 0 to rounding
        return round(margin, 12)

    def launch(x):
        x = np.clip(x, bounds[:, 0], bounds[:, 1])
        tables = _design_tables(data, machine, x)
        tables.setdefault("drop", {}).update(duration)
        return x, executor.submit(_point_summary, tables, name, base)

    def judged(x, future) -> dict:
        summary = future.result()
        if "invalid" in summary:
            point = {"x": x, "worst": -1.0, "binding": f"invalid geometry: {summary['invalid']}", "margins": {}}
            evaluated.append(point)
            return point
        out = {}
        if summary["verdict"] != "ok":
            out["no run leaves the model's range or a limit"] = -1.0
        s0 = min((p["s0"] for p in summary["planes"] if p["s0"] is not None), default=0.0)
        out["static safety factor s0 of every ball contact"] = s0 / criteria["min_s0"] - 1.0
        if any(whirls_backward(p) for p in summary["planes"]):
            out["no sustained backward whirl or dry whip"] = -1.0
        if criteria.get("seal_clearance"):
            out["journal excursion against the seal clearance"] = (
                1.0 - summary["largest_excursion_m"] / criteria["seal_clearance"])
        if gap_limit is not None:
            out["touchdown clearance against the magnetic air gap"] = gap_margin(x, summary)
        binding = min(out, key=out.get)
        point = {"x": x, "worst": out[binding], "binding": binding, "margins": out}
        evaluated.append(point)
        if progress is not None:
            progress(f"design {len(evaluated)}: worst margin {out[binding]:+.3f} ({binding})")
        return point

    levels = 2 if quick else 3
    grids = [np.linspace(lo, hi, levels) if hi > lo else np.array([lo]) for lo, hi in bounds]
    # the bearing as it stands goes out with the grid, so that no drop of its own waits for the polish to end
    x_as_is = np.array([first.contact_angle, first.inner_groove_ratio, 1.0])
    as_is = (x_as_is, as_built) if as_built is not None else launch(x_as_is)
    left_out: list = []  # points not run: their clearance alone keeps them below the best point run
    grid = [np.array([a, f, c]) for a in grids[0] for f in grids[1] for c in grids[2]]
    tiers = _tiers(grid, gap_margin)
    for i, tier in enumerate(tiers):
        if cannot_beat(gap_margin(tier[0]), best_of(evaluated)):
            left_out += [x for later in tiers[i:] for x in later]  # the tiers' bounds only fall
            break
        for x, future in [launch(x) for x in tier]:  # the tier's drops all out before the first is read
            judged(x, future)
    # the bearing as it stands is the yardstick: a geometry no better than it is no recommendation (it is kept out
    # of the search's own points)
    built = judged(*as_is)
    evaluated[:] = [p for p in evaluated if p is not built]
    best = best_of(evaluated)
    if not quick:
        best = _polish(best, bounds, 0.5 / (levels - 1), evaluated, launch, judged, gap_margin, left_out)
    x = best["x"]
    at_bound = [name for name, value, (lo, hi) in zip(("contact angle", "groove ratio", "clearance"), x, bounds,
                                                        strict=True)
                if hi > lo and (abs(value - lo) < 1e-3 * (hi - lo) or abs(value - hi) < 1e-3 * (hi - lo))]
    offset = first.outer_groove_ratio - first.inner_groove_ratio
    improves = better(best, built)
    passes = bool(best["worst"] >= 0.0 and improves)
    failing = sorted({p["binding"] for p in evaluated})
    # when no point passes, the best one is only the least bad (often a tie at -100 %): say so instead of
    # recommending it
    note = None if passes else (
        f"no {first.type.replace('_', ' ')} geometry within these ranges passes the drop's criteria: all "
        f"{len(evaluated)} points fail ({', '.join(failing)}); the lever is outside the bearing's geometry "
        "(mount stiffness and damping, the clearance beyond this range, the rotor or the speed)"
        if best["worst"] < 0.0 else
        f"the bearing as built is the best geometry of the {len(evaluated)} points run (worst drop margin "
        f"{100 * built['worst']:+.1f} %, {built['binding']}): no change is recommended")
    return {
        "passes": passes, "note": note,
        "family": first.type, "contact_angle_deg": math.degrees(x[0]), "inner_groove_ratio": float(x[1]),
        "outer_groove_ratio": float(x[1] + offset), "radial_clearance_mm": [p.radial_clearance * x[2] * 1e3
                                                                             for p in machine.planes],
        "clearance_factor": float(x[2]), "worst_margin": best["worst"], "binding_criterion": best["binding"],
        "tie_margin": TIE_MARGIN, "grid": [len(g) for g in grids],
        "variables_at_bounds": at_bound, "margins": best["margins"], "evaluations": len(evaluated),
        "left_out": len(left_out),
        "bounds": {"contact_angle_deg": [math.degrees(v) for v in bounds[0]], "inner_groove_ratio": list(bounds[1]),
                   "clearance_factor": list(bounds[2])},
        "points": [{"contact_angle_deg": math.degrees(p["x"][0]), "inner_groove_ratio": float(p["x"][1]),
                    "clearance_factor": float(p["x"][2]), "worst_margin": p["worst"], "binding": p["binding"]}
                   for p in evaluated],
        "as_is": built["worst"],
    }


def _tiers(points: list, bound) -> list[list]:
    """``points`` grouped by ``bound(x)`` (a margin known before the drop), largest first; one group without one."""
    if not points or bound(points[0]) is None:
        return [points] if points else []
    values = sorted({bound(x) for x in points}, reverse=True)
    return [[x for x in points if bound(x) == value] for value in values]


def cannot_beat(bound: float | None, best: dict | None) -> bool:
    """Whether a point whose margin on one criterion is at most ``bound`` can never be :func:`better` than ``best``.

    Its smallest margin is at most that bound; below the best's smallest by more than :data:`TIE_MARGIN`, the first
    pair of margins :func:`better` compares already decides against it, whatever its drop shows.
    """
    return bound is not None and best is not None and bound < best["worst"] - TIE_MARGIN


def better(a: dict, b: dict) -> bool:
    """Whether design point ``a`` beats ``b`` (a maximin order, ties broken by the next smallest margin).

    Their margins are compared from the smallest up; the first pair that differs by more than :data:`TIE_MARGIN`
    decides. All agreeing, it is a tie (False).
    """
    ours = sorted(a["margins"].values()) or [a["worst"]]
    theirs = sorted(b["margins"].values()) or [b["worst"]]
    for mine, other in zip(ours, theirs, strict=False):  # a failure adds a margin
        if abs(mine - other) > TIE_MARGIN:
            return mine > other
    return False


def best_of(points: list) -> dict | None:
    """The point a scan of ``points`` in order keeps: a later one replaces it only if :func:`better` (None for none)."""
    best = None
    for point in points:
        if best is None or better(point, best):
            best = point
    return best


def _polish(best: dict, bounds: np.ndarray, step: float, evaluated: list, launch, judged, bound=None,
            left_out: list | None = None) -> dict:
    """A compass search from the grid's best point; the best point found.

    Kolda, Lewis & Torczon, "Optimization by direct search", SIAM Review 45 (2003) 385-482, Sec. 3 (compass
    search, the coordinate directions +-e_i): each round polls the point one ``step`` (a share of each free
    variable's range) along every direction from the best point, all of them side by side (a poll point that
    ``bound``, a margin known before its drop, shows :func:`cannot_beat` the best point is not run but added to
    ``left_out``); it moves to the best
    poll point if it is :func:`better` and halves the step otherwise, until the step falls below
    :data:`POLISH_STEP_MIN` or :data:`POLISH_POINTS` drops are spent. A poll point outside the box is taken at its
    bound; a point already run is not run again. (A Nelder-Mead polish from scipy started from a
    simplex 0.025 % of the box wide at a corner of the box, where the grid's best point often is, and stopped
    at once: the blower's four polish drops moved the contact angle by 0.0075 deg.)
    """
    lo, span = bounds[:, 0], bounds[:, 1] - bounds[:, 0]
    free = np.flatnonzero(span > 0.0)
    scale = np.where(span > 0.0, span, 1.0)

    def key(x) -> tuple:
        return tuple(np.round((np.asarray(x, float) - lo) / scale, 9))

    seen = {key(p["x"]) for p in evaluated}
    spent = 0
    while step >= POLISH_STEP_MIN and spent < POLISH_POINTS and free.size:
        centre = (best["x"] - lo) / scale
        polls = []
        for i in free:
            for sign in (1.0, -1.0):
                u = centre.copy()
                u[i] = min(1.0, max(0.0, u[i] + sign * step))
                x = lo + u * span
                if key(x) not in seen:
                    seen.add(key(x))
                    if bound is not None and cannot_beat(bound(x), best):
                        if left_out is not None:
                            left_out.append(x)
                        continue
                    polls.append(x)
        polls = polls[:POLISH_POINTS - spent]
        points = [judged(*pending) for pending in [launch(x) for x in polls]]  # all out before the first is read
        spent += len(points)
        top = best_of(points)
        if top is not None and better(top, best):
            best = top
        else:
            step *= 0.5
    return best
