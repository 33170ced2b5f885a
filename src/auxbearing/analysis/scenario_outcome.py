"""What a scenario led to: touchdown or not, the magnetic bearings' saturation, re-levitation.

Read from a run's time series (:func:`auxbearing.analysis.drop.machine_dataset`) on its output grid, so a contact
shorter than the output step between two samples is not seen here (the drop's peaks and first impacts, from the
observer at every step, are). The classes:

* ``no touchdown``: the rotor never touched a touchdown bearing after the strike;
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
    at = np.abs(currents) >= SATURATED * limit
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
    after = t >= s.time
    touching = (ds.normal_force.values > 0.0).any(axis=1) & after
    end = float(t[-1])
    bearings = of_kind(machine.stations, "amb")
    powered = all(math.isinf(v) or (s.restore_time is not None and end >= s.time + s.restore_time)
                  for b in bearings for v in s.failure_times(b)[:2 - b.axial])
    saturated = []
    for i, b in enumerate(bearings):
        if "amb_current_x" not in ds:
            break
        total, spans = 0.0, []
        for axis in ("x", "y", "z"):
            if f"amb_current_{axis}" in ds:
                time, own = saturation(t, ds[f"amb_current_{axis}"].values[:, i], b.current_limit())
                total, spans = total + time, spans + own
        spans.sort()
        saturated.append({"name": b.name, "saturated_ms": total * 1e3,
                          "saturated_at_end": bool(spans and spans[-1][1] >= end),
                          "first_intervals_ms": [[a * 1e3, c * 1e3] for a, c in spans[:5]]})
    out["saturation"] = saturated
    if not touching.any():
        out.update(outcome="no touchdown", first_contact_ms=None, last_contact_ms=None, relevitated_at_ms=None)
        return out
    contact_times = t[touching]
    first, last = float(contact_times[0]), float(contact_times[-1])
    settled = max(SETTLED * (end - s.time), SETTLED_MIN)
    out.update(first_contact_ms=first * 1e3, last_contact_ms=last * 1e3, relevitated_at_ms=None)
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
    if out["outcome"].startswith(("sustained", "held")) and any(b["saturated_at_end"] for b in saturated):
        out["outcome"] += ", the controller saturated"
    return out
