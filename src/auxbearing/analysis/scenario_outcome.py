"""What a scenario led to: touchdown or not, the magnetic bearings' saturation, re-levitation.

Read from a run's time series (:func:`auxbearing.analysis.drop.machine_dataset`) on its output grid, so a contact
shorter than the output step between two samples is not seen there; the first contact is the earliest of the grid's
and the planes' first impacts (from the observer at every step). A contact is the journal on its race or a rotor
collar on a race face (the axial touchdown: a thrust bearing's loss lands the rotor there first;
``first_face_contact_ms``, from the grid). Contacts count over the whole run: a rotor that its bearings let fall
before the strike has touched down (``touched_before_strike``). The classes:

* ``not struck``: the run ends before the scenario's time (``struck`` false): nothing of it was simulated;
* ``no touchdown``: the rotor never touched a touchdown bearing;
* ``re-levitated``: every magnetic bearing works at the end and the rotor left its touchdown bearings for good:
  no contact in the last :data:`SETTLED` of the run after the strike (at least :data:`SETTLED_MIN`), and held there
  within :data:`HELD_EXCURSION` of each plane's clearance (not a free flight between two bounces);
  ``relevitated_at_ms`` is the end of its last contact;
* ``not settled``: every bearing works and the rotor still touches now and then in the last stretch (contact in
  less than :data:`HELD` of it), or is clear but still swinging wide: a longer run tells whether it lifts off;
* ``held in contact``: every bearing works at the end and the rotor touches through the last stretch (the
  controller cannot lift it);
* ``sustained forward whirl``, ``sustained backward whirl``: as held in contact, a touchdown plane whirling at the
  end (:mod:`auxbearing.analysis.whirl`; backward includes rolling whirl and dry whip);
* ``on the touchdown bearings``: a bearing's axis is without power at the end (a power or axis loss not restored).
"""

from __future__ import annotations

import math

import numpy as np

from auxbearing.analysis.whirl import BACKWARD

#: Share of the time after the strike that must end free of contact for the rotor to count as re-levitated
#: (at least :data:`SETTLED_MIN`).
SETTLED = 0.2
SETTLED_MIN = 0.02
#: Largest journal excursion in that stretch, as a share of the plane's radial clearance, of a re-levitated rotor.
HELD_EXCURSION = 0.5
#: Share of the settled stretch in contact above which the rotor counts as held (else it still bounces).
HELD = 0.9
#: A current within this share of its limit counts as saturated.
SATURATED = 0.999


def saturation(times: np.ndarray, currents: np.ndarray, limit: float) -> tuple[float, list[tuple[float, float]]]:
    """Total time [s] a current spent at its limit and the intervals [(start, end)] on the grid."""
    if not math.isfinite(limit) or len(times) < 2:
        return 0.0, []
    return intervals_of(times, saturated(currents, limit))


def saturated(currents: np.ndarray, limit: float) -> np.ndarray:
    """Whether each current is at its limit (within :data:`SATURATED`)."""
    return np.abs(currents) >= SATURATED * limit


def intervals_of(times: np.ndarray, at: np.ndarray) -> tuple[float, list[tuple[float, float]]]:
    """Total time [s] a flag on the grid is set and its intervals [(start, end)], disjoint and in order."""
    intervals, start = [], None
    for t, flag in zip(times, at, strict=True):
        if flag and start is None:
            start = t
        elif not flag and start is not None:
            intervals.append((float(start), float(t)))
            start = None
    if start is not None:
        intervals.append((float(start), float(times[-1])))
    return float(sum(b - a for a, b in intervals)), intervals


def outcome(machine, ds, planes: list[dict]) -> dict:
    """The scenario's outcome (module docstring) from a run's dataset and its planes' summaries."""
    from auxbearing.machine.stations import of_kind

    s = machine.active_scenario()
    out = s.describe()
    t = ds.time.values
    if not s.levitated or len(t) < 2:
        return out
    touching = (ds.normal_force.values > 0.0).any(axis=1)
    # the collar pressed into a race face (its penetration positive) is a touchdown too: the axial one
    face = (ds.axial_penetration.values > 0.0).any(axis=1) if "axial_penetration" in ds else np.zeros(t.size, bool)
    touching = touching | face
    out["first_face_contact_ms"] = float(t[face][0]) * 1e3 if face.any() else None
    end = float(t[-1])
    bearings = of_kind(machine.stations, "amb")
    powered = all(math.isinf(v) or (s.restore_time is not None and end >= s.time + s.restore_time)
                  for b in bearings for v in s.failure_times(b)[:2 - b.axial])
    out["saturation"] = _saturation(s, bearings, ds, t) if "amb_current_x" in ds else []
    # the observer sees every step: a contact between two output samples, or before the first one on the grid
    impacts = [p["first_impact_ms"] * 1e-3 for p in planes if p.get("first_impact_ms") is not None]
    first = min([*impacts, *(float(v) for v in t[touching][:1])], default=None)
    struck = s.time < end
    out["struck"] = struck
    if first is None:
        out.update(outcome="no touchdown" if struck else _not_struck(s, end), first_contact_ms=None,
                   last_contact_ms=None, relevitated_at_ms=None, touched_before_strike=False)
        return out
    # a contact only the observer saw (shorter than the output step) is the last one the grid can date
    last = float(t[touching][-1]) if touching.any() else first
    out.update(first_contact_ms=first * 1e3, last_contact_ms=last * 1e3, relevitated_at_ms=None,
               touched_before_strike=bool(first < s.time))
    if not struck:
        out["outcome"] = _not_struck(s, end) + f"; the levitated rotor touched down at {first * 1e3:.2f} ms"
        return out
    settled = max(SETTLED * (end - s.time), SETTLED_MIN)
    window = t >= end - settled
    share = float(touching[window].mean())
    out["contact_share_at_end"] = share
    excursion = np.hypot(ds.journal_x.values[window] - ds.ring_x.values[window],
                         ds.journal_y.values[window] - ds.ring_y.values[window]).max(axis=0)
    clearance = np.array([p.radial_clearance for p in machine.planes])
    held = bool(np.all(excursion < HELD_EXCURSION * clearance))
    if not powered:
        out["outcome"] = "on the touchdown bearings"
    elif last < end - settled and held:
        out.update(outcome="re-levitated", relevitated_at_ms=last * 1e3)
    elif share == 0.0:
        out["outcome"] = "not settled: clear of the touchdown bearings but not yet held near the centre"
    elif share < HELD:
        out["outcome"] = "not settled: touching now and then at the end"
    elif any(p.get("whirl") in BACKWARD for p in planes):
        out["outcome"] = "sustained backward whirl"
    elif any(p.get("whirl") == "forward" for p in planes):
        out["outcome"] = "sustained forward whirl"
    else:
        out["outcome"] = "held in contact"
    if out["outcome"].startswith(("sustained", "held")) and any(b["saturated_at_end"] for b in out["saturation"]):
        out["outcome"] += ", the controller saturated"
    return out


def _not_struck(s, end: float) -> str:
    return (f"not struck: the run ends at {end * 1e3:.4g} ms, before the scenario's time {s.time * 1e3:.4g} ms "
            "(lengthen the run or move the scenario into it)")


def _saturation(s, bearings, ds, t: np.ndarray) -> list[dict]:
    """Each bearing's time at its current limit: while any of its axes is there, each instant counted once.

    Only while the axis' amplifier has power (:func:`auxbearing.core.amb.powered`): an unpowered axis' states
    freeze, and a current frozen at the limit is no controller asking for more than it gets.
    """
    end = float(t[-1])
    out = []
    for i, b in enumerate(bearings):
        fail_x, fail_y, restore = s.failure_times(b)[:3]
        at = np.zeros(t.size, bool)
        for axis, fail in (("x", fail_x), ("y", fail_y), ("z", fail_x)):
            column = f"amb_current_{axis}"
            if column not in ds or not math.isfinite(b.current_limit()):
                continue
            powered = (t < fail) | (t >= restore)
            at |= saturated(np.nan_to_num(ds[column].values[:, i]), b.current_limit()) & powered
        total, spans = intervals_of(t, at)
        out.append({"name": b.name, "saturated_ms": total * 1e3,
                    "saturated_at_end": bool(spans and spans[-1][1] >= end),
                    "first_intervals_ms": [[a * 1e3, c * 1e3] for a, c in spans[:5]]})
    return out


def late_loads(machine, end: float) -> list[str]:
    """A notice for each ``[[load]]`` that starts at or after the run's end ``end`` [s]: it never acts.

    The same rule as a scenario's ``not struck``: nothing of it is simulated, which a summary would otherwise pass
    over in silence. One sentence each, naming the key as the file writes it (``load.N.start``).
    """
    from auxbearing.common.params import display_value
    from auxbearing.machine.stations import of_kind
    from auxbearing.machine.stations.load import TABLE

    return [f"load.{i}.start = {display_value(TABLE['start'], load.start)!r}: not applied: the run ends at "
            f"{end * 1e3:.4g} ms, before the load '{load.name}' starts (lengthen the run or move the load into it)"
            for i, load in enumerate(of_kind(machine.stations, "load")) if load.start >= end]
