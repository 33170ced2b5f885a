"""Inputs legal one by one whose results would mean little: physics checks a drop's inputs and results get.

Each returns sentences (warnings) or raises :class:`~auxbearing.common.errors.InputError` where no material
or body could have the input; the command line prints them, the Python API gets the same sentences. Before a
drop: an unbalance beyond the clearance, a clearance large against the journal, a line-contact constant far
from steel's (:func:`plausibility`), rotor inertias no body of that mass has (:func:`inertia_notes`), a ball
constant under which the rotor's weight alone sinks the race into its balls (:func:`sink_check`). After it:
a race that sank further than an elastic contact can (:func:`race_sink_warning`), an impact rate that
says the contact chatters (:func:`impact_rate_warning`).
"""

from __future__ import annotations

import math

from auxbearing.common.errors import InputError


def plausibility(machine, typed: dict) -> list[str]:
    """Warnings for legal inputs whose results would mean little (``typed`` names each input).

    An unbalance beyond the clearance, a clearance large against the journal; a line-contact constant no
    material has is refused (:class:`~auxbearing.common.errors.InputError`).
    """
    from auxbearing.core.hertz import line_contact_constant
    from auxbearing.machine.model import JOURNAL_COMPLIANCE

    notes = []
    rotor = machine.rotor
    for plane in machine.planes:
        s = plane.radial_clearance
        if rotor.unbalance > s:
            notes.append(f"{typed['unbalance']}: the unbalance eccentricity {rotor.unbalance * 1e6:.4g} um is "
                         f"larger than the clearance {s * 1e6:.4g} um at {plane.name}: the mass centre orbits "
                         "outside the clearance circle, far beyond any balance grade (ISO 21940-11 G6.3 is "
                         "e = 6.3 mm/s / speed)")
        if s > CLEARANCE_TO_RADIUS * plane.journal_radius:
            notes.append(f"{typed['clearance']}: the clearance {s * 1e3:.4g} mm is {s / plane.journal_radius:.1%} "
                         f"of the journal radius {plane.journal_radius * 1e3:.4g} mm at {plane.name}: the line-contact "
                         f"law takes the clearance as small against the radius (below {CLEARANCE_TO_RADIUS:.0%})")
        b = plane.bearing
        length = b.width if b.width is not None else 2.0 * b.ball_diameter
        steel = float(line_contact_constant(length, b.ring_material.compliance + JOURNAL_COMPLIANCE))
        ratio = plane.line_stiffness / steel
        if not 1.0 / LINE_STIFFNESS_SPAN <= ratio <= LINE_STIFFNESS_SPAN:
            # refused, not warned: such a contact chatters (10^5 impacts a drop) and no material pair has it
            raise InputError(f"{typed['line_stiffness']}: K_l = {plane.line_stiffness:.4g} N/m**(10/9) is "
                             f"{ratio:.3g} times Palmgren's constant of a steel line contact as long as the race "
                             f"({length * 1e3:g} mm: {steel:.4g}); no journal and race material is that far from "
                             f"steel (allowed: within a factor {LINE_STIFFNESS_SPAN:g})")
    name = typed["polar_inertia"]
    structure = getattr(rotor, "structure", None)
    if structure is not None:  # its inertias come from the matrices: name the key the user wrote, not polar_inertia
        name = name.replace("rotor.polar_inertia", f"{structure.key} = {structure.written!r}")
    notes += inertia_notes(rotor, machine.planes, name)
    return notes


def inertia_notes(rotor, planes, typed: str) -> list[str]:
    """Warnings for rotor inertias unusual for a body of that mass and journal radius; impossible ones refused.

    No body has them, so these raise :class:`~auxbearing.common.errors.InputError`: a mass or polar inertia that
    is not positive (J_p = sum of m r^2 about the spin axis), and J_p above twice J_t. The latter is the
    perpendicular-axis theorem: with the spin axis z, J_p = int(x^2 + y^2) dm while the transverse moments about x
    and y add up to 2 J_t = J_p + 2 int z^2 dm, so J_p <= 2 J_t, equal for a flat disc (principal moments obey
    I_1 <= I_2 + I_3). Merely unusual, so warned of: the polar radius of gyration sqrt(J_p / m) against the journal
    radius r_j (a solid shaft of that radius has r_j / sqrt(2)); below r_j / 4 or above 50 r_j an inertia is more
    likely in the wrong unit than a rotor. ``typed`` names the polar inertia as the user gave it.

    >>> from types import SimpleNamespace as S
    >>> planes = [S(journal_radius=0.02)]
    >>> inertia_notes(S(mass=10.0, polar_inertia=1.5e-6, transverse_inertia=0.2), planes, "J_p")[0][:39]
    'J_p: 1.5e-06 kg*m**2 with 10 kg is a ra'
    >>> inertia_notes(S(mass=10.0, polar_inertia=0.5, transverse_inertia=0.2), planes, "J_p")
    Traceback (most recent call last):
    ...
    auxbearing.common.errors.InputError: J_p: 0.5 kg*m**2 is 2.5 times the transverse inertia 0.2 kg*m**2; ...
    """
    notes = []
    jp, jt, m = rotor.polar_inertia, rotor.transverse_inertia, rotor.mass
    if not (m > 0.0 and jp > 0.0):  # sqrt(J_p / m) below would fail on them; no body has them
        raise InputError(f"{typed}: a mass of {m:.4g} kg and a polar inertia of {jp:.4g} kg*m**2: both must be > 0 "
                         "(J_p = sum of m r^2 about the spin axis)")
    if jt is not None and jp > 2.0 * jt * (1.0 + 1e-9):
        raise InputError(f"{typed}: {jp:.4g} kg*m**2 is {jp / jt:.3g} times the transverse inertia {jt:.4g} kg*m**2; "
                         "no body has a polar moment above twice its transverse moment (the perpendicular-axis "
                         "theorem: J_p = 2 J_t - 2 int z^2 dm, equal for a flat disc)")
    r_j = min(p.journal_radius for p in planes)
    k = math.sqrt(jp / m)
    if not JOURNAL_GYRATION_SPAN[0] * r_j <= k <= JOURNAL_GYRATION_SPAN[1] * r_j:
        notes.append(f"{typed}: {jp:.4g} kg*m**2 with {m:.4g} kg is a radius of gyration of "
                     f"{k * 1e3:.4g} mm against a journal radius of {r_j * 1e3:.4g} mm (a solid shaft of that radius: "
                     f"{r_j / math.sqrt(2.0) * 1e3:.4g} mm); check the unit (kg*m**2)")
    return notes


#: Band of the polar radius of gyration, in journal radii, outside which the inertia is flagged (see
#: :func:`inertia_notes`): a rotor that carries its journals has most of its mass at no less than a
#: quarter of their radius, and 50 journal radii is a flywheel beyond any touchdown-bearing machine.
JOURNAL_GYRATION_SPAN = (0.25, 50.0)


#: Largest radial clearance, as a fraction of the journal radius, for which the journal/race line contact is
#: the conformal contact of a shaft in a bore: the law takes the relative radius r (r + s) / s as r^2 / s
#: (machine model, Johnson 1985 Eq. 4.43), an error of s / r, so 5 %.
CLEARANCE_TO_RADIUS = 0.05


#: Factor by which a line-contact constant may differ from Palmgren's steel value for the race's length before it
#: is flagged: ceramics, bronzes and polymers bring E' within a factor of ~10 of steel's, so 100 is generous.
LINE_STIFFNESS_SPAN = 100.0


def sink_check(bearing, machine, case_ball_constant, typed: str) -> None:
    """Refuse a ball constant under which the rotor's weight alone would sink the race into its balls."""
    import numpy as np

    from auxbearing.analysis.statics import SINK_LIMIT_FRACTION, sink_estimate

    if case_ball_constant is None:
        return
    weight = machine.rotor.mass * machine.simulation.gravity
    sink = float(sink_estimate(bearing, np.array([[0.0, weight, 0.0, 0.0, 0.0]]), case_ball_constant)[0])
    if sink > SINK_LIMIT_FRACTION * bearing.ball_diameter:
        raise InputError(f"{typed}: under the rotor's weight alone ({weight:.3g} N) the race would sink about "
                         f"{sink * 1e3:.3g} mm into its balls (ball diameter {bearing.ball_diameter * 1e3:g} mm), "
                         f"beyond {SINK_LIMIT_FRACTION:.0%} of a ball where no contact law holds; a steel ball "
                         "constant is about 1e10 N/m**1.5")


def race_sink_warning(ds, bearing) -> str | None:
    """A sentence when the race moved into its balls further than an elastic steel contact can (planar view)."""
    import numpy as np

    from auxbearing.analysis.statics import SINK_WARNING_FRACTION

    moved = float(np.max(np.hypot(ds["race_x"].values - ds["ring_x"].values,
                                  ds["race_y"].values - ds["ring_y"].values), initial=0.0))
    moved -= 0.5 * bearing.diametral_clearance
    if moved <= SINK_WARNING_FRACTION * bearing.ball_diameter:
        return None
    return (f"the race moved {moved * 1e6:.4g} um into its balls, {moved / bearing.ball_diameter:.1%} of the ball "
            "diameter: beyond the 1.6 % a steel ball's elastic approach reaches at 6000 MPa, so the ball-set contact "
            "law is outside its range")


#: Shortest time one journal/race impact lasts with steel contacts: about half the ~0.4 ms contact oscillation
#: of the source paper's rig (docs/paper_notes.md, item 7). More contact onsets than one per this interval
#: is a chatter no line contact of steel makes.
IMPACT_DURATION = 0.2e-3


def impact_rate_warning(where: str, impacts: int, first_impact_ms: float | None, simulated_s: float) -> str | None:
    """A sentence when a plane counts more impacts than impacts of :data:`IMPACT_DURATION` can fit in the run.

    >>> impact_rate_warning("QJ202", 20, 7.2, 0.15) is None
    True
    >>> impact_rate_warning("QJ202", 407662, 7.2, 0.15)[:34]
    'QJ202: 407662 impacts in 142.8 ms,'
    """
    if not impacts or first_impact_ms is None:
        return None
    span = simulated_s - first_impact_ms * 1e-3
    if impacts <= max(1.0, span / IMPACT_DURATION):
        return None
    return (f"{where}: {impacts} impacts in {span * 1e3:.1f} ms, more than one per {IMPACT_DURATION * 1e3:g} ms that a "
            "steel impact lasts: the contact chatters and the line-contact law is outside its range (look at the "
            "line stiffness and damping)")


def static_sink_warning(bearing, ds, case: int) -> str | None:
    """A sentence when the solved rings moved further into the balls than an elastic steel contact can."""
    import math

    from auxbearing.analysis.statics import SINK_WARNING_FRACTION

    c = ds.isel(case=case)
    moved = math.hypot(float(c["axial_displacement"]), math.hypot(float(c["displacement_x"]),
                                                                   float(c["displacement_y"])))
    if moved <= SINK_WARNING_FRACTION * bearing.ball_diameter:
        return None
    return (f"the rings moved {moved * 1e6:.4g} um, {moved / bearing.ball_diameter:.1%} of the ball diameter: beyond "
            "the 1.6 % a steel ball's elastic approach reaches at 6000 MPa, so the contact law is outside its range")
