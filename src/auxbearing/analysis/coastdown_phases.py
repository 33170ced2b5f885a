"""Which state a coast-down is in, and the reduced model that carries the states it can represent.

After every full-dynamics window (:mod:`auxbearing.analysis.coastdown`) each touchdown plane is put in one state,
from the window's whirl records (:data:`auxbearing.core.watch.WHIRL_FIELDS`) and onsets:

* ``free``: out of contact all the window; the race spins down on its own bearing torque;
* ``rolling``: in contact all the window, no impact, no whirl but a forward one, and the race rolls on the
  journal: the slip of the contact, v = rho_orbit w_whirl + r Omega - R w_race over r |Omega| (window means;
  the journal centre's orbit speed enters, so a journal rolling round the bore is not taken for a sliding
  race), within :data:`ROLL_SLIP`;
* ``whirling``: the same, but in steady backward rolling whirl (every whirl record ``backward_rolling``,
  Jiang 2007: the no-slip condition s w_whirl = R w_race - r Omega fixes the race-to-rotor ratio);
* ``rattling``: rolling within :data:`ROLL_SLIP`, no whirl but a forward one, with impacts (a light
  journal bouncing in the bottom of the bore, or the unbalance lifting it once a turn);
* ``sliding``: a race that does not roll (still being spun up, or braked): full dynamics only;
* ``unsettled``: dry whip, a slipping backward whirl, or a window that changes class.

A stretch is handed to the reduced model (:mod:`auxbearing.core.spin`) only when every plane is free,
rolling, whirling or rattling (rolling and rattling counted alike) in the last :data:`MIN_WINDOWS` to
:data:`MAX_WINDOWS` windows since the last stretch, and the mean of their loss torques is known to
:data:`STATIONARY` (:func:`settled`); that mean is carried, with the cube mean of their loads for the
over-rolling. A sliding race stays in full dynamics until it rolls: the reduced model has no state for the
race's own speed while it is driven. The first stretch, and the first after a window in a state it does not
carry, also waits until the journals' motion has stopped changing (:func:`motion_steady`): a stretch leaves
the motion as it was, so a swing still building up would be frozen in its early form.

A journal that has come to rest in the bottom of its bore is a rolling pendulum, and the unbalance drives it where
the spin passes once, twice and three times its frequency (:func:`pendulum_passages`). There its swing builds up
over seconds, lifts the journal off its race and dies out slowly after: a motion a stretch would stop. While such
a journal swings with :data:`PASSAGE_SWING` of the energy that lifts it off, or bounces on its race in a passage
(:func:`pendulum_swinging`), no stretch carries it; stretches end at the top of each passage, so that the windows
see the journal enter it.
"""

from __future__ import annotations

import math
from itertools import pairwise
from typing import NamedTuple

import numpy as np

from auxbearing.analysis.whirl import BACKWARD, SUSTAINED, classify_window
from auxbearing.core import drive, spin
from auxbearing.core import integrate as ig
from auxbearing.core.bearing_friction import palmgren_viscous_torque
from auxbearing.core.watch import WHIRL_FIELDS
from auxbearing.machine.model import DRAG_SPEED_SCALE, Machine
from auxbearing.machine.pack import plane_blocks

#: A race rolls on its journal when the contact's mean slip is within this fraction of the journal's surface speed.
ROLL_SLIP = 0.02
#: A state is steady when the mean loss torque of the windows since the last stretch is known to this fraction
#: (standard error of the mean): a plane's loss is then measured to about that over the stretch it carries.
STATIONARY = 0.02
#: Fewest full-dynamics windows a stretch's losses are measured over, after every stretch too. Fewer were
#: measured where the window after a stretch finds the torques it held: one window where every plane is calm
#: cut the windows to standstill only on the 7208 DB pair and the QJ208 hybrid (512 -> 439, 500 -> 482, with
#: the stretches kept from growing on it; let grow, the DB pair's went to 412 but the tail, extrapolated over
#: stretches of 40 % of the speed, moved both standstill times to -0.46 % of full dynamics'); two windows on a
#: rattle cut the blower's by 15 % and the compressor's by 20 % but moved the rattling non-drive ends over the
#: first 4 s by up to 8.6 % (five unbalance phases each) and the vertical rotor's damage to standstill by 1.8
#: points. About 1 % of a verification's computing against those shifts: three windows stay.
MIN_WINDOWS = 3
#: Most windows a check looks back over: a sliding set, so that the slow change of the losses with the falling
#: speed over a long full-dynamics stretch is not taken for a drift.
MAX_WINDOWS = 12
#: States the reduced model represents (module docstring).
REDUCIBLE = ("free", "rolling", "whirling", "rattling")
#: The reduced model carries a rolling and a rattling plane alike (a race coupled to its journal at the ratio it
#: has, the window's mean loss torque): a journal that bounces now and then in the bottom of its bore moves
#: between the two from window to window, and those windows count together; their losses' scatter decides.
_FAMILY = {"free": "free", "rolling": "coupled", "rattling": "coupled", "whirling": "whirling"}
_F = {name: i for i, name in enumerate(WHIRL_FIELDS)}


class PlaneWindow(NamedTuple):
    """What one full-dynamics window showed of one plane (SI)."""

    state: str
    onsets: int
    contact: float  #: contact fraction
    force: float  #: mean journal contact force [N]
    axial_force: float  #: mean |axial force| of the collar on the race face [N]
    rotor_speed: float  #: mean Omega [rad/s]
    race_speed: float  #: mean race speed [rad/s]
    whirl_speed: float  #: mean whirl speed of the journal centre [rad/s]
    slip: float  #: mean contact slip over the journal's surface speed [-]
    powers: tuple  #: mean heat powers (contact, bearing, mount) [W]
    #: ISO 281 equivalent load on the bearing [N] (set by the coast-down, which knows the bearing's factors)
    load: float = 0.0
    #: mean square speed of the journal centre in its bore [m^2/s^2]
    orbit_speed_sq: float = 0.0
    #: the class of each of its closed whirl windows, in order (:func:`~auxbearing.analysis.whirl.classify_window`)
    whirl_classes: tuple = ()
    #: mean radial load of the bearing over the window, (time mean of F^3)^(1/3) of the ball set's reaction [N]
    #: (:mod:`~auxbearing.analysis.coastdown_life`)
    bearing_load: float = 0.0

    @property
    def torque(self) -> float:
        """Loss of the plane as a torque on the rotor speed [N m]."""
        return float(sum(self.powers)) / max(abs(self.rotor_speed), 1e-300)


def _means(records: np.ndarray) -> np.ndarray:
    weights = records[:, _F["duration"]]
    total = weights.sum()
    if total <= 0.0:
        return np.zeros(records.shape[1])
    return (records * weights[:, None]).sum(axis=0) / total


def plane_window(machine: Machine, k: int, records: np.ndarray, onsets: int, powers: tuple,
                 geometry: tuple[float, float] | None = None) -> PlaneWindow:
    """Classify plane k over one window (module docstring); ``records`` are its closed whirl windows.

    ``geometry``: the journal radius and radial clearance [m] the window ran with, grown by the heat (default the
    machine's as built). The slip and the rolling whirl's speed are the no-slip kinematics of that geometry: a
    bore opened by 30 um of 200 um moves the rolling reference by 15 %, most of the band it is judged in.
    """
    plane = machine.planes[k]
    r, s = (plane.journal_radius, plane.radial_clearance) if geometry is None else geometry
    mean = _means(records)
    omega, race, whirl = mean[_F["spin_speed"]], mean[_F["race_speed"]], mean[_F["whirl_speed"]]
    contact = float(mean[_F["contact_fraction"]])
    journal = r * abs(omega)
    slip = ((mean[_F["mean_radius"]] * whirl + r * omega - (r + s) * race) / journal) if journal > 0.0 else 0.0
    ordered = tuple(classify_window(rec, s, r, 0.0) for rec in records)
    classes = set(ordered)
    if records.shape[0] == 0:
        state = "unsettled"  # no closed whirl window: nothing to judge the window on
    elif contact <= 0.01 and onsets == 0:
        state = "free"
    elif abs(slip) > ROLL_SLIP:
        state = "sliding"
    elif classes <= {"none", "forward"}:
        state = "rolling" if onsets == 0 and contact >= 0.99 else "rattling"
    elif classes == {"backward_rolling"} and onsets == 0 and contact >= 0.99:
        state = "whirling"
    else:
        state = "unsettled"
    return PlaneWindow(state, onsets, contact, float(mean[_F["mean_normal_force"]]),
                       float(mean[_F["mean_axial_force"]]), float(omega), float(race),
                       float(whirl), float(slip), tuple(float(p) for p in powers),
                       orbit_speed_sq=float(mean[_F["orbit_speed_sq"]]), whirl_classes=ordered,
                       bearing_load=float(max(mean[_F["mean_cube_bearing_load"]], 0.0) ** (1.0 / 3.0)))


class BackwardWhirl:
    """Per plane, when the coast-down's journal first whirls backward for good and for how long (SI).

    As in a drop (:func:`auxbearing.analysis.whirl.timeline`), a backward whirl is sustained once
    :data:`~auxbearing.analysis.whirl.SUSTAINED` whirl windows in a row are backward; the count runs on across
    the check windows. A stretch that carries a plane in steady backward rolling whirl (state ``whirling``)
    carries the whirl with it. ``onset`` [s] is None while a plane never whirled backward for good;
    ``seconds`` is the time it spent so.
    """

    def __init__(self, planes: int) -> None:
        self.run = [0] * planes
        self.onset: list[float | None] = [None] * planes
        self.seconds = [0.0] * planes

    def window(self, windows: list[PlaneWindow], t_end: float, length: float) -> None:
        """A full-dynamics window of ``length`` that ended at ``t_end``, its planes as :func:`plane_window` gave."""
        for k, w in enumerate(windows):
            share = length / max(len(w.whirl_classes), 1)
            for i, c in enumerate(w.whirl_classes):
                self.run[k] = self.run[k] + 1 if c in BACKWARD else 0
                if self.run[k] == SUSTAINED:  # the run counts from its start (earlier windows taken as this long)
                    self.seconds[k] += SUSTAINED * share
                    if self.onset[k] is None:
                        self.onset[k] = t_end - length + (i + 1 - SUSTAINED) * share
                elif self.run[k] > SUSTAINED:
                    self.seconds[k] += share

    def stretch(self, carried: list[PlaneWindow], t_start: float, duration: float) -> None:
        """A reduced stretch from ``t_start`` that carried the planes ``carried`` for ``duration``."""
        for k, w in enumerate(carried):
            if w.state == "whirling":
                self.onset[k] = t_start if self.onset[k] is None else self.onset[k]
                self.seconds[k] += duration


def settled(windows: list[list[PlaneWindow]]) -> list[PlaneWindow] | None:
    """The mean of the windows since the last stretch if a stretch may carry it, or None to go on in full dynamics.

    ``windows`` holds, oldest first, each window's planes; the last ones whose planes are in the same states as
    the last window's count (rolling and rattling as one: the reduced model carries both alike). A stretch
    needs at least :data:`MIN_WINDOWS` of them, in states the reduced model represents, the two
    halves of them agreeing within twice :data:`STATIONARY` (no drift), and each plane's mean loss torque
    known to :data:`STATIONARY`: the standard error of the windows' mean within that fraction of it. A steady
    rolling or whirl agrees at once; a rattle or a journal swinging to and fro in the bottom of the bore
    (a slow pendulum whose losses change along its swing) needs as many windows as its scatter asks for, and
    the stretch carries their mean.
    """
    windows = _same_state_run(windows)
    if windows is None or len(windows) < MIN_WINDOWS or not _losses_known(windows):
        return None
    return [p._replace(powers=tuple(float(np.mean([w[k].powers[j] for w in windows])) for j in range(3)),
                       force=float(np.mean([w[k].force for w in windows])),
                       axial_force=float(np.mean([w[k].axial_force for w in windows])),
                       load=mean_equivalent_load([w[k].load for w in windows]))
            for k, p in enumerate(windows[-1])]


def _same_state_run(windows: list[list[PlaneWindow]]) -> list[list[PlaneWindow]] | None:
    """The windows at the end in the last one's families of states (at most :data:`MAX_WINDOWS`).

    None when the last window is in a state the reduced model does not carry.
    """
    if not windows or any(p.state not in REDUCIBLE for p in windows[-1]):
        return None
    run = 1
    while run < min(len(windows), MAX_WINDOWS) and same_families(windows[-1 - run], windows[-1]):
        run += 1
    return windows[-run:]


def _losses_known(windows: list[list[PlaneWindow]]) -> bool:
    """Whether each plane's mean loss torque over ``windows`` is known to :data:`STATIONARY`, without drift."""
    n = len(windows)
    for k in range(len(windows[-1])):
        torques = np.array([w[k].torque for w in windows])
        scale = max(abs(float(torques.mean())), 1e-12)
        if float(torques.std(ddof=1)) / math.sqrt(n) > STATIONARY * scale:
            return False
        # consecutive windows of a slow swing are alike: its two halves must agree as well (no drift)
        if abs(float(torques[: n // 2].mean() - torques[n - n // 2:].mean())) > 2.0 * STATIONARY * scale:
            return False
    return True


def too_short(windows: list[list[PlaneWindow]]) -> bool:
    """Whether the windows are too short for the motion.

    :data:`MAX_WINDOWS` of them in one reducible state whose losses still scatter beyond :data:`STATIONARY`
    (:func:`settled`), the journals whirling round their bores (:data:`WHIRL_ROUND`). The losses of a motion that
    repeats slower than a window, a whirl beating against the unbalance, change from window to window with where the
    window falls in the beat: measured on the vertical rotor from 8.5 s to its run-away, a forward whirl at
    1100-1500 rad/s against 1550 rad/s of spin, each plane's loss repeating every 40 ms by +-40 % over 10 ms
    windows, so that twelve of them never agree and 400 windows ran in full dynamics. Longer windows average
    the beat within each (:data:`WINDOW_GROWTH`), and their over-rolling load stays the beat's, a cube mean over
    the window (:mod:`auxbearing.analysis.coastdown_life`). Against full dynamics to the vertical rotor's run-away:
    320 windows instead of 628, damage per drop -0.32 / -0.19 % (-0.49 / -0.03 % with the windows left at 10 ms),
    peaks within 0.17 K, the run-away at 13.08 s against 13.11 s.
    """
    run = _same_state_run(windows)
    return (run is not None and len(run) >= MAX_WINDOWS and not _losses_known(run)
            and all(abs(p.whirl_speed) >= WHIRL_ROUND * abs(p.rotor_speed) for p in run[-1]))


#: Longest window over ``coastdown.check_window`` that :func:`too_short` doubles the windows to.
WINDOW_GROWTH = 4
#: Only journals whirling round their bores, at this share of the spin speed or more, get longer windows: their
#: whirl beats against the unbalance over a few windows. A journal swinging in the bottom of its bore (the paper
#: rigs' rolling pendulum, 0.3 s a swing, whirl speed 0.4 % of the spin) repeats far slower than any window of a
#: few tens of ms; windows grown there only sampled the swing differently (the paper rig's standstill time over
#: fifteen unbalance phases moved from -1.2 +- 0.8 % of full dynamics' to -4.0 +- 1.5 %).
WHIRL_ROUND = 0.5


#: Span of full dynamics [s] over which a plane's journal motion is averaged (:func:`motion_steady`): at least
#: a swing of the slowest rolling pendulum among the examples (the paper rig's, about 0.3 s).
STEADY_SPAN = 0.3
#: Consecutive spans that must agree: three, so that a motion dying out and then building up again (the blower's
#: bounce after the drop, then its swing) is not taken as steady where the two meet.
STEADY_SPANS = 3
#: The motion is steady when each plane's mean square orbit speed over every span is within this fraction of
#: the largest. Measured on the blower and its hybrid candidate (10 ms windows): one window scatters by 32 %
#: about the mean, a span's mean by about 6 %; the swing building up after the drop changes it by 2 to 6 times.
STEADY_MOTION = 0.2
#: ... and the first and last span's means within this fraction of the largest, beyond what the rotor's own
#: slowing explains (:func:`motion_steady`): no drift. Measured on the compressor's coupling end after its drop:
#: its orbit speed dies out over seconds (2.1e-4, 1.5e-4, 1.2e-4 m^2/s^2 over the first three seconds), its spans
#: change by 6-7 % each, within STEADY_MOTION; frozen at 1.1 s it left the damage per drop 3.4 % high.
STEADY_TREND = 0.1
#: A motion driven by the rotor (unbalance, the journal rolling round the bore) moves at speeds in proportion to
#: Omega: its mean square speed goes as Omega^2, a drift the trend test allows for.
ORBIT_SPEED_POWER = 2.0
#: A journal moving slower than 0.1 mm/s (RMS) in its bore is taken as at rest there [m^2/s^2].
QUIET_ORBIT = 1e-8
#: A journal's motion is negligible, whatever it does, when the inertial load it can bring, m v^2 / s (a mass
#: m on an orbit of the radial clearance s at the RMS speed v), is within this share of the plane's mean contact
#: force (:func:`quiet_orbits`): a swing dying out at low speed then moves the load by less than this. Measured
#: on the blower from 3000 rpm to standstill against full dynamics: with 0.5 % the damage per drop within 0.25 %,
#: the standstill time within 0.21 %, 61 % of the computing; with 1 % the non-drive end's damage 2.2 % low.
QUIET_LOAD = 0.005


def same_families(a: list[PlaneWindow], b: list[PlaneWindow]) -> bool:
    """Whether two windows' planes are in the same families of states (rolling and rattling as one)."""
    return [_FAMILY.get(p.state) for p in a] == [_FAMILY.get(p.state) for p in b]


def quiet_orbits(machine: Machine, windows: list[PlaneWindow]) -> np.ndarray:
    """Per plane, the mean square orbit speed below which its motion is negligible [m^2/s^2] (:data:`QUIET_LOAD`).

    m v^2 / s <= QUIET_LOAD F, with F the window's mean journal contact force, s the radial clearance and m the
    rotor's mass over its planes (the journal's share of it, to the factor of two this estimate needs). Measured
    on the blower coasting down from 3000 rpm: its swings die out over seconds (mean square orbit speed halving
    every 0.5 s, 1e-4 to 1e-8 m^2/s^2), which kept every window in full dynamics down to 1100 rpm although the
    journals rolled on their races; at 1e-4 m^2/s^2 such a swing adds about 3 N to its drive end's 130 N, at 2e-5 0.5 %.
    A vertical rotor's whirl carries its whole contact force this way, so it is never quiet.
    """
    mass = machine.rotor.mass / max(len(machine.planes), 1)
    return np.array([QUIET_LOAD * abs(w.force) * p.radial_clearance / mass
                     for w, p in zip(windows, machine.planes, strict=True)])


def motion_steady(windows: list[list[PlaneWindow]], count: int, quiet=None) -> bool:
    """Whether the journals move in their bores alike over the last :data:`STEADY_SPANS` spans of ``count`` windows.

    A reduced stretch advances the spin speeds and the temperatures and leaves the motion as the last window
    left it; the windows after it go on from there. A motion still changing on a slow scale would be frozen in
    its early form and every later window would measure the loads of that form. Measured against full dynamics
    over 30 s: after the drop the blower's journals bounce less and less for about a second, then a swing builds
    up to a steady rattle by 1.3 s (mean square orbit speed 7e-4, 1.5e-4, then 4.7e-4 m^2/s^2 at the drive
    end); with its first stretch at 0.46 s the rotor's transverse speed in the windows stayed 40 % below full
    dynamics' for 15 s and the damage per drop was 2.3 % low. The hybrid candidate's swing builds up only by
    1.9 s: a first stretch at 1.2 s froze it and left the damage per drop 5.9 / 7.7 % low. So the first stretch,
    and the first after any window in a state the reduced model does not carry, waits until each plane's mean
    square orbit speed (``orbit_speed_sq``, the motion's kinetic energy per unit mass) agrees within
    :data:`STEADY_MOTION` over :data:`STEADY_SPANS` consecutive spans of :data:`STEADY_SPAN`, and the first
    and the last span agree within :data:`STEADY_TREND` plus the change the rotor's slowing brings
    (:data:`ORBIT_SPEED_POWER`): a transient dying out slowly changes every span a little, and one frozen
    early persists in every later window (the compressor's coupling end: 3.4 % too much damage per drop).
    A plane whose largest span mean is below ``quiet`` (per plane, :func:`quiet_orbits`) or :data:`QUIET_ORBIT`
    counts as steady whatever its motion does.
    """
    if count < 1 or len(windows) < STEADY_SPANS * count:
        return False
    recent = windows[-STEADY_SPANS * count:]
    speeds = np.array([[p.orbit_speed_sq for p in w] for w in recent])
    means = speeds.reshape(STEADY_SPANS, count, -1).mean(axis=1)  # (span, plane)
    rotor = np.abs([w[0].rotor_speed for w in recent]).reshape(STEADY_SPANS, count).mean(axis=1)
    slowing = abs(math.log(rotor[-1] / rotor[0])) if rotor[0] > 0.0 and rotor[-1] > 0.0 else 0.0
    top = means.max(axis=0)
    alike = top - means.min(axis=0) <= STEADY_MOTION * top
    level = np.abs(means[-1] - means[0]) <= (STEADY_TREND + ORBIT_SPEED_POWER * slowing) * top
    floor = np.maximum(QUIET_ORBIT, 0.0 if quiet is None else np.asarray(quiet, float))
    return bool(np.all((top <= floor) | (alike & level)))


def mean_equivalent_load(loads) -> float:
    """Load that does the damage of windows of equal revolutions at loads P_i: P_m = (sum P_i^3 / n)^(1/3) [N].

    Palmgren-Miner over ISO 281:2007 Eq. (1), whose life goes as P^-3 for a ball bearing. A stretch carries the
    windows' loads; their plain mean fell 2-10 % short of full dynamics' damage on a rattle.
    """
    values = np.abs(np.asarray(loads, float))
    return float(np.mean(values ** 3) ** (1.0 / 3.0)) if values.size else 0.0


def stretch_load(before: float, after: float) -> float:
    """Equivalent load of a stretch from the loads of the windows before it and just after it [N].

    Palmgren-Miner's sum over ISO 281:2007 Eq. (1) charges a revolution at P^3. The load is taken linear in the
    revolutions across the stretch and its cube averaged exactly: mean P^3 = (P_b + P_a)(P_b^2 + P_a^2) / 4.
    That is exact for a load that goes as the square of the speed (a journal whirling round its bore, or lifted by
    its unbalance) when the rotor slows at a steady rate, since the revolutions still to run then go as the square
    of the speed too. Taking the cube itself linear (the trapezoidal rule on P^3, as before) overstates such a
    stretch's damage by 2.2 % over a 10 % speed step; charging the whole stretch at the load before it (the
    rectangle rule) biased the damage wherever the load follows the falling speed (the vertical machine's windows
    before each stretch carried 0.6-0.9 % more load than full dynamics' mean over it, 2-3 % in damage). The loads
    of the shipped examples' stretches change little across one: against the trapezoidal rule, their damages per
    drop to standstill moved by 0.23 points at most (the 6208's drive end, -2.13 to -2.36 % of full dynamics').
    """
    a, b = abs(before), abs(after)
    return ((a + b) * (a * a + b * b) / 4.0) ** (1.0 / 3.0)


#: A stretch whose bearing load's cube differs across it by more than this share of the larger end crossed a change
#: of the motion, and is measured inside (:class:`StretchEnd`).
STEP_LOAD = 0.25
#: Measurements inside such a stretch, each halving the segment whose load changes most.
STEP_PROBES = 3


class StretchEnd:
    """A stretch waiting for the load at its end: the windows after it measure it once they settle.

    ``rows`` are the stretch's entries in each plane's over-rolling list of (revolutions, load). The load at the
    stretch's end is the mean of the windows after it once they settle (:func:`settled`), the next stretch's; the
    stretch is then charged at :func:`stretch_load`. The first three windows alone, as taken before, were no
    measure where the load varies: a journal that bounces now and then in the bottom of its bore (the paper rigs
    between 4000 and 3000 rpm) showed an impact in them, and the cube of its load was charged to half a stretch
    of some 500 revolutions (the paper rig's damage per drop +270 +- 54 % of full dynamics' over fifteen phases;
    with the settled load +73 +- 16 %, until its swinging journal was kept out of the stretches:
    :func:`pendulum_swinging`).
    Windows in another family of states than the stretch carried, or the run's end, leave the stretch at its
    starting load: where in the stretch the state changed is not known.

    A load linear across the stretch is an assumption the two ends can refute: where the cube of a plane's load
    after the stretch differs from the one before by more than :data:`STEP_LOAD` of the larger, the motion changed
    its kind inside the stretch (the 7208 DB pair's non-drive end drops from a rattle at 99 N to one at 70 N
    within 250 rpm near 13 600 rpm, which a stretch of 600 rpm crossed and the linear rule charged at 86 N
    throughout). ``inside`` (a share of the stretch's speed fall -> (race revolutions to there, loads) or None)
    then measures the load inside the stretch on a copy of its start, halving the segment that changes most,
    :data:`STEP_PROBES` times; the stretch is charged segment by segment.
    """

    def __init__(self, carried: list[PlaneWindow], rows: list[int], inside=None) -> None:
        self.carried, self.rows, self.inside = carried, rows, inside

    def left(self, windows: list[PlaneWindow]) -> bool:
        """Whether a window after the stretch is in another family of states (the stretch keeps its load)."""
        return not same_families(windows, self.carried)

    def close(self, settled_after: list[PlaneWindow], overrolling: list[list[tuple[float, float]]]) -> None:
        """Charge the stretch at :func:`stretch_load` of its starting load and the settled load after it."""
        ends = [(overrolling[k][row], settled_after[k].load) for k, row in enumerate(self.rows)]
        stepped = [abs(b**3 - a**3) > STEP_LOAD * max(a, b) ** 3 for (_, a), b in ends]
        points = self._points(ends) if any(stepped) and self.inside is not None else None
        for k, row in enumerate(self.rows):
            (revs, before), after = ends[k]
            load = stretch_load(before, after)
            if points is not None and stepped[k] and revs > 0.0:
                # segment by segment, each at the linear rule between its measured ends (Palmgren-Miner)
                nodes = sorted((min(max(r[k], 0.0), revs), p[k]) for _, r, p in points)
                cubes = sum((r1 - r0) * stretch_load(p0, p1) ** 3 for (r0, p0), (r1, p1) in pairwise(nodes))
                load = (cubes / revs) ** (1.0 / 3.0)
            overrolling[k][row] = (revs, load)

    def _points(self, ends) -> list | None:
        """(share of the speed fall, revolutions, loads) at the stretch's ends and where :attr:`inside` measured."""
        n = len(ends)
        points = [(0.0, [0.0] * n, [a for (_, a), _ in ends]), (1.0, [r for (r, _), _ in ends], [b for _, b in ends])]
        for _ in range(STEP_PROBES):
            # the segment whose load's cube changes most, over the planes
            i = max(range(len(points) - 1), key=lambda j: max(abs(x**3 - y**3) for x, y in
                                                             zip(points[j][2], points[j + 1][2], strict=True)))
            share = 0.5 * (points[i][0] + points[i + 1][0])
            found = self.inside(share)
            if found is None:
                return None
            points.insert(i + 1, (share, *found))
        return points


def _viscous(plane, speed: float) -> float:
    if plane.set_viscous_factor <= 0.0 or plane.lubricant_viscosity <= 0.0:
        return 0.0
    return float(palmgren_viscous_torque(plane.lubricant_viscosity, speed, plane.bearing.pitch_diameter,
                                         plane.set_viscous_factor))


def _held(plane, window: PlaneWindow, omega: float) -> tuple[float, float, float]:
    """The torques a stretch holds on a plane from its window [N m].

    Contact and mount on the rotor (none on a free race), and the bearing's loss but its viscous torque on the race.
    """
    race = abs(window.race_speed)
    rest = max(0.0, (window.powers[1] - _viscous(plane, race) * race) / race) if race > 0.0 else 0.0
    if window.state == "free":
        return 0.0, 0.0, rest
    rotor = abs(window.rotor_speed) if window.rotor_speed != 0.0 else abs(omega)
    if rotor <= 0.0:  # a rotor at rest takes no torque from its losses
        return 0.0, 0.0, rest
    return window.powers[0] / rotor, window.powers[2] / rotor, rest


def calm(machine: Machine, windows: list[list[PlaneWindow]]) -> bool:
    """Whether these windows measured steady states, not samples of a motion: a stretch they set may grow.

    Every plane free, in steady backward rolling whirl (a deterministic state) or rolling with a negligible
    motion in its bore (:func:`quiet_orbits`) in every window. A rattle is chaotic, and a journal swinging in the
    bottom of its bore (the paper rig's rolling pendulum; the blower's drive end down to 1200 rpm, whose swing
    brings 15-75 % of its contact force) changes its losses along the swing: the windows sample either, and a
    longer stretch samples it less often. Measured against full dynamics to standstill with the speed and
    clearance steps grown wherever no plane rattled: the paper rig's standstill time moved from +1.3 % to
    -2.5 % and its damage from -4.0 % to -5.2 %, the 7208 candidate's drive-end damage from +0.2 % to -1.5 %.
    """
    for planes in windows:
        quiet = quiet_orbits(machine, planes)
        for p, q in zip(planes, quiet, strict=True):
            if p.state == "rattling" or (p.state == "rolling" and p.orbit_speed_sq > q):
                return False
    return True


def spin_locked(windows: list[PlaneWindow], rested: list[bool]) -> list[bool]:
    """Per plane, whether its journal's motion is locked to the spin, so a stretch hands it back at the new pace.

    Rolling round its bore (pressed there by its unbalance: a synchronous orbit on the clearance circle), whirling
    backward on it (at a speed rolling ties to the spin's and the race's) or free of it (the unbalance response),
    and not yet come to rest in its bore under its weight (``rested``, :func:`resting`): such a motion runs at
    the speed Omega_1 the path it ran at Omega_0, Omega_1 / Omega_0 as fast
    (:meth:`auxbearing.analysis.coastdown._Session.set_speeds`). A journal at rest swings at its own pendulum
    frequency and a rattle's impacts answer to its weight as much as to its unbalance: neither scales with the
    spin. Measured to standstill against full dynamics over four unbalance phases, damage per drop (drive /
    non-drive end): scaling these planes moved the blower from +1.53 +- 0.57 / -0.30 +- 0.08 % to +0.93 +- 0.50 /
    -0.30 +- 0.09 %, the QJ208 hybrid from +2.13 +- 0.39 / +1.04 +- 0.20 % to +0.92 +- 0.48 / +1.42 +- 0.37 %, the
    6208 from -1.37 +- 0.49 / +1.57 +- 0.38 % to -1.32 +- 0.13 / +1.57 +- 0.35 %; scaling the rattling planes as
    well took the 6208's drive end to -2.84 +- 0.64 % and doubled the blower's windows.
    """
    return [not r and w.state in ("rolling", "whirling", "free") for w, r in zip(windows, rested, strict=True)]


#: Most times ``coastdown.speed_step`` a stretch's speed step grows to (:func:`stretch_growth`).
MAX_GROWTH = 4.0
#: Largest share of its speed a stretch whose speed step has grown may lose (unless the speed step itself is larger).
MAX_SPEED_FALL = 0.5


def stretch_growth(growth: float, before: list[PlaneWindow], after: list[PlaneWindow], machine: Machine) -> float:
    """How many times ``coastdown.speed_step`` the next stretch may take (where the windows measured steady states).

    The loop asks only where :func:`calm` holds; the answer comes from what the last stretch held and the windows
    after it. A stretch holds each plane's contact, mount and non-viscous bearing torques at their values before
    it (:func:`spin_model`; the viscous torque and the drag follow their laws of the speed) while the speed falls.
    The windows after it measure those torques again. Where none moved by more than half :data:`STATIONARY`
    of its plane's loss torque, the step doubles, up to :data:`MAX_GROWTH` times; where one moved by more than
    :data:`STATIONARY`, it goes back to its base. A torque that changes linearly over a stretch is held wrong
    by half its change on average, so a stretch whose step grew or stayed grown errs in its heat by 1 % at
    most: a journal rolling steadily at low speed, whose rolling resistance and mount losses hardly move
    with the speed, takes long stretches; one whose losses follow the speed does not. The clearance step
    does not grow: grown as well, it left the 7208 DB pair's peak temperatures 0.64 / 0.36 K below full
    dynamics' to standstill (0.02 K with it kept), as a loss that drifts with the closing clearance (the
    pair's preload) and is held at each stretch's start would.
    """
    if not same_families(before, after):
        return 1.0
    change = 0.0
    for plane, b, a in zip(machine.planes, before, after, strict=True):
        if sum(a.powers) > 0.0:
            moved = sum(abs(x - y) for x, y in zip(_held(plane, a, 0.0), _held(plane, b, 0.0), strict=True))
            change = max(change, moved / abs(a.torque))
    if change > STATIONARY:
        return 1.0
    if change <= 0.5 * STATIONARY:
        return min(2.0 * growth, MAX_GROWTH)
    return growth


def spin_model(machine: Machine, windows: list[PlaneWindow], omega: float, race_speeds: list,
               floor: float) -> spin.SpinModel:
    """The reduced model of a stretch from the windows that carry it (:mod:`auxbearing.core.spin`).

    A coupled race keeps the ratio to the rotor it has at the stretch's start (``race_speeds``, ``omega``): the
    spin energy the stretch starts from is then the full model's, and the energy audit closes across it.
    """
    n = plane_blocks(machine.planes)  # padded as the full model's tuples: one compiled kernel for 1 and 2 planes

    def per_plane(values, fill=0.0):
        out = [fill] * n
        for k, v in enumerate(values):
            out[k] = float(v)
        return tuple(out)

    planes = machine.planes
    coupled = [w.state != "free" for w in windows]
    ratios = [abs(w / omega) if omega != 0.0 else 0.0 for w in race_speeds]
    contact, mount, rest = zip(*(_held(p, w, omega) for p, w in zip(planes, windows, strict=True)), strict=True)
    inertia = machine.rotor.polar_inertia + sum(p.race_inertia * rho**2 for p, rho, c in
                                                zip(planes, ratios, coupled, strict=True) if c)
    coast = machine.coastdown
    return spin.SpinModel(
        inertia=inertia, drag_constant=coast.drag_torque, drag_viscous=coast.viscous_drag,
        drag_windage=coast.windage_drag, speed_scale=DRAG_SPEED_SCALE, process_torque=coast.process_torque,
        floor=floor, active=per_plane([1.0] * len(planes)), coupled=per_plane(coupled), ratio=per_plane(ratios),
        contact_torque=per_plane(contact), mount_torque=per_plane(mount), bearing_torque=per_plane(rest),
        race_inertia=per_plane([p.race_inertia for p in planes], 1.0),
        viscosity=per_plane([p.lubricant_viscosity for p in planes]),
        pitch_diameter=per_plane([p.bearing.pitch_diameter for p in planes], 1.0),
        viscous_factor=per_plane([p.set_viscous_factor for p in planes]))


class Stretch(NamedTuple):
    """A reduced stretch's outcome (SI)."""

    duration: float
    rotor_speed: float
    race_speeds: list  #: per plane [rad/s]
    heat: list  #: per plane: (contact, bearing, mount) [J]
    drag_loss: float
    work: float
    race_revolutions: list
    steps: int


#: Relative tolerance of the reduced model's integration (its right-hand side is smooth).
SPIN_RTOL = 1e-9


def integrate_stretch(model: spin.SpinModel, omega: float, race_speeds: list, span: float) -> Stretch:
    """Integrate the reduced model from the speeds given for at most ``span`` seconds or to its floor."""
    at = spin.layout.py_func(len(model.active))
    n, size = at.planes, at.size
    y = spin.new_state(omega, race_speeds, n)
    atol = np.full(size, np.inf)
    scale = max(abs(omega), 1.0)
    atol[spin.OMEGA] = 1e-12 * scale
    atol[spin.RACE_AT:spin.RACE_AT + n] = 1e-12 * scale
    settings = ig.Settings(SPIN_RTOL, atol, math.inf, 1e-14, 10**6, math.inf)
    memory = ig.new_memory(0.0, min(1e-3, span), size)
    obs = np.zeros(size + 2)
    status = drive.advance_spin(model, obs, y, span, settings, memory, np.empty((0, size)))
    if status == ig.STOPPED:
        y = obs[:size].copy()
        duration = float(obs[size])
    elif status == ig.FINISHED:
        duration = span
    else:  # a smooth two-speed problem that fails to integrate is a defect, not a machine's verdict
        raise RuntimeError(f"the reduced coast-down model did not integrate ({ig.STATUS_TEXT[status]})")
    heat = [tuple(float(y[at.heat_at + 3 * k + j]) for j in range(3)) for k in range(n)]
    return Stretch(duration, float(y[spin.OMEGA]), [float(y[spin.RACE_AT + k]) for k in range(n)], heat,
                   float(y[at.drag_loss]), float(y[at.work_in]),
                   [float(y[at.turn_at + k]) / (2.0 * math.pi) for k in range(n)], int(memory.steps[0]))


#: Orders of the rolling pendulum's resonance the unbalance drives: the spin at once, twice and three times the
#: pendulum's frequency (:func:`pendulum_passages`).
PASSAGE_ORDERS = 3
#: A passage spans these fractions of n times the pendulum's small-swing frequency: near the clearance the swing is
#: large and slower, so the journal answers below n omega_p. Measured in full dynamics to standstill: the paper
#: rig's journal lifts off its race between 0.79 and 0.91 of 3 omega_p, 0.83 and 0.95 of 2 omega_p and 0.71 and
#: 0.83 of omega_p; the blower's non-drive end swings up between 0.83 and 0.95 of 2 omega_p.
PASSAGE_BAND = (0.7, 0.95)
#: A journal that has come to rest in its bore and swings with this share of the kinetic energy that lifts it off
#: the side of its bore (mean square speed over g c) is kept in full dynamics (:func:`pendulum_swinging`). Measured
#: in full dynamics to standstill: the paper rig's journal enters its passages with 0.17-0.6 of it (the swing of
#: the last passage dying out, or already growing) and lifts off in them with 0.5-1; the blower's journals, once
#: at rest, swing with at most 0.1 (at 2000 rpm, near once their pendulum), and its non-drive end enters its
#: passage at twice its pendulum with 0.02, where the swing grows to 0.2-0.6 (:mod:`auxbearing.analysis.coastdown`
#: says what the reduced run makes of it).
PASSAGE_SWING = 0.15


def pendulum_frequencies(machine: Machine) -> list[float]:
    """Per plane, the small-swing angular frequency of its journal resting in the bottom of its bore [rad/s].

    omega_p^2 = k_s / m_k, with k_s the plane's stiffness across its weight (W / c in series with ball set and
    mount, :func:`auxbearing.analysis.modes.swing_stiffness`; the simple pendulum of length c, omega_p^2 = g / c,
    on a rigid support) and m_k the rotor mass whose weight the plane carries. 0 where the plane carries no weight
    (a vertical machine).
    """
    from auxbearing.analysis.modes import swing_stiffness

    out = []
    for k in range(len(machine.planes)):
        mass = machine.rest_share(k) * machine.rotor.mass
        stiffness = swing_stiffness(machine, k) if mass > 0.0 else 0.0
        out.append(math.sqrt(stiffness / mass) if stiffness > 0.0 else 0.0)
    return out


def pendulum_passages(machine: Machine, top_speed: float) -> list[tuple[float, float]]:
    """The spin speeds at which the unbalance drives a resting journal's rolling pendulum, below ``top_speed``.

    Bands (low, high) in rad/s, merged where they overlap, fastest first: :data:`PASSAGE_BAND` of n omega_p for
    n = 1 .. :data:`PASSAGE_ORDERS` and every plane's omega_p (:func:`pendulum_frequencies`). In a passage the
    swing grows over seconds as the spin sweeps through it, and a journal near the clearance lifts off and falls
    back (measured on the paper rig: 56 % of its over-rolling damage to standstill falls within the passage at
    3 omega_p, 26 % within 2 omega_p's and 6 % within omega_p's, its load's cube mean 38-47 N there against
    15-17 N outside). A stretch steps over that growth (the windows after it go on from the motion before it), so
    a swinging journal's passage is left to full dynamics (:func:`pendulum_swinging`).
    """
    bands = sorted((PASSAGE_BAND[0] * n * w, PASSAGE_BAND[1] * n * w) for w in pendulum_frequencies(machine)
                   if w > 0.0 for n in range(1, PASSAGE_ORDERS + 1) if PASSAGE_BAND[0] * n * w < top_speed)
    merged: list[tuple[float, float]] = []
    for low, high in bands:
        if merged and low <= merged[-1][1]:
            merged[-1] = (merged[-1][0], max(high, merged[-1][1]))
        else:
            merged.append((low, high))
    return merged[::-1]


def resting(windows: list[list[PlaneWindow]]) -> list[bool]:
    """Per plane, whether its journal rests in its bore over these windows: in contact 99 % of their time or more."""
    return [float(np.mean([w[k].contact for w in windows])) >= REST_CONTACT for k in range(len(windows[-1]))]


#: A journal rests in its bore when in contact this share of the time or more (:func:`resting`).
REST_CONTACT = 0.99


def pendulum_swinging(machine: Machine, recent: list[list[PlaneWindow]], since_stretch: list[list[PlaneWindow]],
                      rested: list[bool], passage: tuple[float, float] | None) -> bool:
    """Whether a journal that has come to rest in its bore swings so that no stretch may carry it.

    ``rested``: per plane, whether its journal has come to rest in its bore (:func:`resting`) under the weight (a
    plane with a pendulum frequency, :func:`pendulum_frequencies`): a pendulum then. One that the unbalance has kept
    lifting off its race since the drop (the blower's drive end down to 4000 rpm, in contact 50-90 % of the time)
    moves as the rattle makes it, passage or not. Such a journal swings too much to be carried when

    * over ``recent`` (a span of full dynamics, :data:`STEADY_SPAN`) its mean square speed reaches
      :data:`PASSAGE_SWING` of g c: its centre runs on an arc of the radial clearance c and leaves the race once
      the swing climbs past the bore's side, which takes a speed at the bottom of sqrt(2 g c), a mean square speed
      of g c over the swing;
    * or, in a passage (``passage``, :func:`pendulum_passages`), it struck its race in a window since the last
      stretch (``since_stretch``): lifted off by the swing, it bounces. A stretch would carry the bounces the
      windows caught over a tenth of the speed: measured on the paper rig over fifteen unbalance phases, keeping
      only the swing of :data:`PASSAGE_SWING` out of the stretches left its damage per drop +35 +- 11 % of full
      dynamics', this rule as well +3.4 +- 12.4 % (full dynamics' own scatters by 29 % from phase to phase).
    """
    gravity = machine.simulation.gravity
    for k, plane in enumerate(machine.planes):
        if not rested[k]:
            continue
        if recent and float(np.mean([w[k].orbit_speed_sq for w in recent])) >= (
                PASSAGE_SWING * gravity * plane.radial_clearance):
            return True
        if passage is not None and any(w[k].onsets > 0 for w in since_stretch):
            return True
    return False


def passage_at(passages: list[tuple[float, float]], speed: float) -> tuple[float, float] | None:
    """The passage (low, high) the speed lies in, or None."""
    return next(((low, high) for low, high in passages if low <= abs(speed) <= high), None)


def next_passage_top(passages: list[tuple[float, float]], speed: float) -> float:
    """The top of the fastest passage below ``speed`` [rad/s] (0 when none): a stretch ends there."""
    return max((high for low, high in passages if high < abs(speed)), default=0.0)
