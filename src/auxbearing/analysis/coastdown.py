"""From the drop to standstill: spin-down, friction heat, thermal growth and the drops a bearing survives.

:func:`run_coastdown` runs a machine's drop with full dynamics (:func:`auxbearing.analysis.drop.integrate_machine`)
and goes on, alternating two paths, until the rotor stands still (``until_stop``) or a time is reached:

* **full dynamics** in windows of ``coastdown.check_window``: the machine right-hand side as in a drop,
  with the clearances of the moment. Each window measures what the motion dissipates, by where the
  heat is made (journal/race and face contacts, inside each bearing, in each mount damper, drag), from
  the energy ledger of the state;
* **a reduced model** (:mod:`auxbearing.core.spin`) on the stretches whose state it can represent, as
  :mod:`auxbearing.analysis.coastdown_phases` decides from the window: every race rolling on its journal (in
  contact or in a steady backward rolling whirl) or free of it, no dry whip, and a whirl or a rattle only
  when the windows agree. A race that still slides stays in full dynamics until it rolls, a journal swinging
  in the bottom of its bore while the swing lasts (pendulum passages, below), and the first stretch waits until
  the journals' motion is steady (a swing building up after the drop). Only the slow
  quantities move there: the rotor's and the free races' spin speeds under the losses the window measured
  (the bearings' viscous torque as Palmgren's law of the speed, the rest as torques), the drag law
  T0 + c1 Omega + c2 Omega^2 and the process torque; the temperatures follow their networks. A stretch ends
  when the speed has fallen by ``coastdown.speed_step`` (where the windows find steady states, no rattle or
  swing, the step doubles, up to four times, while the windows after each stretch find the torques it held
  unchanged within 1 %: :func:`auxbearing.analysis.coastdown_phases.stretch_growth`), a clearance
  has moved by :data:`CLEARANCE_STEP` or the speed reaches a pendulum passage,
  and full dynamics checks again (impacts, whirl onset and a closing clearance are seen there); the first
  ``coastdown.settle_time`` of it after a stretch is run and booked but not judged, and a rattling journal gets
  at least :data:`RATTLE_SETTLE` of it before the next stretch. A stretch hands the
  motion back at its new speed: a journal whose motion is locked to the spin (rolling round its bore, whirling
  backward on it or free of it, not yet at rest in its bore) runs the same path Omega_1 / Omega_0 as fast, so its
  velocity, its race's and its ring's are scaled by that ratio; a journal at rest swings at its own frequency and
  a rattling one as its impacts make it, and both keep their velocity
  (:func:`~auxbearing.analysis.coastdown_phases.spin_locked`, :meth:`_Session.set_speeds`). Otherwise the motion
  only evolves in the windows, so where it changes slowly with the clearances and the speed it lags full
  dynamics' by tens of stretches; settling gives it time to follow (measured on the blower before the contacts
  were carried across the clearance steps: the windows just after a stretch carried 2-6 % less load than full
  dynamics at the same speed, and 150 ms of settling brought every non-chaotic example within 1 %, at 2.5 times
  the cost). Each window's over-rolling load is the mean load of its varying bearing
  load, the cube mean (:mod:`auxbearing.analysis.coastdown_life`); a stretch's revolutions are charged at the
  load measured before it and the load the windows after it settle on (the next stretch's), the load taken
  linear over its revolutions and its cube averaged exactly (:class:`auxbearing.analysis.coastdown_phases.StretchEnd`,
  :func:`~auxbearing.analysis.coastdown_phases.stretch_load`).

Pendulum passages. A journal resting in the bottom of its bore is a rolling pendulum: the weight W on a plane, on an
arc of the radial clearance c, restores a sideways shift with a stiffness W / c, so its small swings go at
sqrt(g / c) / (2 pi) (with the ball set and mount in series,
:func:`~auxbearing.analysis.coastdown_phases.pendulum_frequencies`: 40.3 Hz on the blower, 35.2 Hz on the paper
rig). The unbalance drives it where the spin passes once, twice and three times that frequency; near the clearance
the swing is large and slower, so the journal answers 5-30 % below those speeds. Full dynamics sweeps through each
passage and the swing builds up over seconds; on the paper rig it lifts the journal off its race (loads of 100-170
N against 15 N at rest) and dies out slowly after, and 88 % of the rig's over-rolling damage falls in its passages.
A stretch steps over that growth (the windows after it go on from the motion before it) or carries a bounce its
windows caught over a tenth of the speed: the one-plane rig's damage per drop was +73 +- 16 % of full dynamics'
over fifteen unbalance phases. So no stretch carries a journal that has come to rest in its bore while it swings
with 15 % of the energy that lifts it off, or, in a passage, while it strikes its race; and stretches end at the
top of each passage (:func:`~auxbearing.analysis.coastdown_phases.pendulum_swinging`). The rig is chaotic: moving
the unbalance phase by 1e-9 rad moves full dynamics' damage per drop by 29 % (coefficient of variation over
fifteen phases) and its standstill time by 1.7 %, so one pair of runs says nothing to better than that and the
means over an ensemble do (``python -m tests.consistency.coastdown_ensemble paper_rig --phases 15``): the
reduced runs' standstill time -0.05 +- 1.03 % of full dynamics', damage per drop +3.4 +- 12.4 %, peak
temperatures within 0.22 K; on two planes over ten phases +0.04 +- 0.80 % and -0.44 / -0.50 %, its journals
swinging through nearly all of the coast-down. The reduced run costs the rig 25 s of computing against full
dynamics' 37 s (two planes: 62 s against 70 s). The blower's journals, once at
rest, swing with at most 10 % of a lift-off (its drive end, which the unbalance keeps lifting off down to 4000
rpm, counts as no pendulum before). Its non-drive end's swing grows in the passage at twice its pendulum from 2 %
of a lift-off (4600-4000 rpm, the plane's load 51 -> 75 N in full dynamics), which no window after a stretch
starts: the reduced run steps over it, 2.8 % of that plane's damage per drop. Watching each passage's entry in
full dynamics until the motion was steady caught it (blower +0.43 / -0.13 % of full dynamics' damage per drop)
for 5.3 times the windows (3163 against 601, 42 s of computing against 9 s).

To standstill (or to a run-away) against full dynamics at unbalance phase 0, every example and candidate but the
chaotic paper rigs (above), with the windows on the classical RK4 (:mod:`auxbearing.core.rk4`) and the
spin-locked journals handed back at the new pace: standstill times within 0.15 % and run-aways within 0.2 % of
their time, peak temperatures within 0.10 K, closest internal clearances within 0.08 um, damage per drop blower
-0.21 / -0.32 %, 7208 DB pair -1.87 / -3.86 %, QJ208 hybrid -0.04 / +1.96 %, 6208 -1.08 / +2.17 %, compressor
+0.42 / +1.19 %, vertical rotor +0.82 / +1.16 % (and the 7208, no candidate, -2.60 / +6.01 %; its non-drive end
in steady backward rolling whirl). Over four unbalance phases (0 to 3e-9 rad; full dynamics' own damage moves by
0.1 % between them on the blower, 0.4 / 0.8 % on the 7208): blower +0.93 +- 0.50 / -0.30 +- 0.09 %, 7208 DB pair
-0.90 +- 0.33 / -2.96 +- 0.34 %, hybrid +0.92 +- 0.48 / +1.42 +- 0.37 %, 6208 -1.32 +- 0.13 / +1.57 +- 0.35 %
(its run-away in every run), the 7208 -2.98 +- 0.43 / +4.61 +- 1.12 % (handed back unscaled -2.23 +- 1.41 /
+3.73 +- 0.71 %), standstill times -0.10 to -0.15 %. Before the handover scaled anything, the blower's drive end
was +3.21 % at phase 0 and +1.53 +- 0.57 % over the phases: between 6000 and 3000 rpm, where the unbalance stops
lifting the journal, the windows after each stretch resumed the lifted orbit at the old speed's pace and carried
-1 to +12 % of full dynamics' mean load over the same 500 rpm; the hybrid's drive end was +2.13 +- 0.39 %.
The reduced run cannot leave a motion that is unstable but grows over seconds: the 7208 DB pair's small rattle
turns unstable between 17 000 and 15 000 rpm and full dynamics switches to a larger one (2-4 % more load); the
windows, 30 ms of motion per stretch, stay on the small one, and 50 or 150 ms of settling after each stretch does
not change it. Full dynamics 3.3 and 10 times tighter in its tolerances moves the DB pair's damage by at most
0.04 %.

Today's figures, with a matched pair's two rows of heat, the load-step probes
(:class:`~auxbearing.analysis.coastdown_phases.StretchEnd`) and :data:`RATTLE_SETTLE`, to standstill (or the
run-away) over four unbalance phases 0.05 rad apart (at 1e-9 rad the reduced runs shared one trajectory for
seconds; ``--cache`` of the ensemble script keeps the full-dynamics runs): damage per drop, drive / non-drive end,
blower -0.03 +- 0.60 / -1.13 +- 0.19 %, 7208 DB pair -0.14 +- 0.18 / +1.32 +- 0.31 %, QJ208 hybrid -0.62 +- 0.24 /
-0.95 +- 0.31 %, 6208 -0.59 +- 0.09 / +0.40 +- 0.28 %, compressor +0.10 +- 0.02 / +0.36 +- 0.04 %, vertical rotor
+0.36 +- 0.26 / +0.43 +- 0.43 % (these three run away in every run; the vertical rotor's journals never rattle
in a stretch, so its runs are those of the rule before); standstill times -0.11 to -0.31 %; peak temperatures
within 0.12 K (the vertical rotor's, on its run-away limit), elsewhere 0.10 K; closest internal clearances within
0.13 um (the 6208's non-drive end), elsewhere 0.03 um.

A run to standstill leaves out its last, slowest part once nothing in it can move a result
(:func:`spent_tail`): the spin energy left could warm the smallest part by less than
``coastdown.tail_temperature_rise`` and its revolutions add less than 0.1 % to any damage; the time left to
standstill is extrapolated at the last deceleration. On the blower this is the last 142 rpm of 18 000: 22 % of
the computing of the run (26.7 s against 34.2 s of CPU; half of it before the windows stopped refining peaks
they do not report), for a standstill time 0.38 % early (222.53 s against 223.39 s) and damage 0.04 % low
against simulating down to ``coastdown.stop_speed``, temperatures and clearances unchanged.

Heat goes into one lumped network per plane (:mod:`auxbearing.analysis.thermal`; journal, inner race, balls,
outer race, housing, ambient): contact heat split between journal and race by Charron's partition,
bearing heat at the raceways, mount heat to the housing. Thermal growth changes the journal/race radial
clearance and the bearing's diametral clearance (:meth:`auxbearing.analysis.thermal.ThermalNetwork.clearance_changes`),
and both go back into the dynamics. A run stops with its verdict when a part passes
``coastdown.max_temperature`` (a thermal run-away), when the internal clearance closes into a preload whose
stress at rest passes ISO 76's 4200 MPa, or when the radial clearance closes (the journal seizes).

Energy audit: energy in (mechanical energy at the drop, process work, the work thermal growth does on
the contacts when it changes a clearance under load) = mechanical energy now + energy stored in the ball
sets + heat + drag loss; ``energy_balance_error`` is their difference over the energies in play.
"""

from __future__ import annotations

import copy
import functools
import math
import time
from collections.abc import Callable
from typing import NamedTuple

import numpy as np
import xarray as xr

from auxbearing import __version__
from auxbearing.analysis.coastdown_life import plane_life
from auxbearing.analysis.coastdown_phases import (
    MAX_SPEED_FALL,
    MAX_WINDOWS,
    MIN_WINDOWS,
    REDUCIBLE,
    STEADY_SPAN,
    STEADY_SPANS,
    WINDOW_GROWTH,
    BackwardWhirl,
    StretchEnd,
    calm,
    integrate_stretch,
    motion_steady,
    next_passage_top,
    passage_at,
    pendulum_frequencies,
    pendulum_passages,
    pendulum_swinging,
    plane_window,
    quiet_orbits,
    resting,
    same_families,
    settled,
    spin_locked,
    spin_model,
    stretch_growth,
    too_short,
)
from auxbearing.analysis.dead_bearings import without_dead_bearings
from auxbearing.analysis.drop import (
    MachineRun,
    as_machine,
    integrate_machine,
    machine_dataset,
    machine_summary,
    simulated_time,
    whirl_window,
)
from auxbearing.analysis.life import dynamic_load_rating
from auxbearing.analysis.thermal import HOUSING, JOURNAL, NODE_NAMES, build_network
from auxbearing.bearings.ballset import ballset_state
from auxbearing.bearings.ratings import ISO76_BALL_STRESS
from auxbearing.common import interrupt
from auxbearing.common.errors import InputError
from auxbearing.core import drive
from auxbearing.core import integrate as ig
from auxbearing.core import machine as cm
from auxbearing.core import watch as cw
from auxbearing.machine.model import Machine

#: A reduced stretch ends when a clearance has moved this much since full dynamics last looked [m]. Where the
#: parts heat up, this step and not the speed ends most stretches (the blower's from 3 s to 90 s, 0.7 % of the
#: speed each), and each costs the windows that measure the new state; but the motion those windows resume lags
#: further behind a longer stretch. Measured on every example and candidate whose clearances move (the paper
#: rigs' never reach the step), to standstill or run-away: 1.5 um takes 7-22 % fewer windows and 6-19 % less
#: computing, 2 um 12-35 % and 10-27 %, with peak temperatures within 0.2 K and run-aways within 0.5 % of their
#: time, damage per drop within 1.4 % (1.5 um) and 3.9 % (2 um) of 1 um's at the same unbalance phase (moving the
#: phase by 1e-9 rad alone moves it by up to 2.3 %). But over the vertical rotor's first 4 s, where its speed and
#: temperatures change fastest, damage per drop against full dynamics goes from +0.9 / +0.9 % (1 um) to +1.7 /
#: +2.1 % (1.5 um) and +2.4 / +2.8 % (2 um), past the 2 % the comparison holds; at 4 um the 6208's drive end
#: falls to -3.4 % to standstill. So the step stays at 1 um.
CLEARANCE_STEP = 1e-6
#: Least full dynamics between two stretches after one that carried a rattling journal [s]. A stretch hands the
#: motion back at a speed its impacts have not seen; each handover kicks the rattle, which takes 0.15-0.2 s to forget
#: it (the 7208 DB pair's non-drive end at 15 000-14 000 rpm, 28 stretches over four unbalance phases: its load's
#: cube mean over the windows that follow a stretch's start falls from 101.1 N in the first 0.1 s to 100.1 N after
#: 0.35 s, full dynamics' being 99.6 N). With three windows, 30 ms, between handovers the kicks piled up: the windows
#: that measured each stretch's load read 101.5 N, and the pair's damage per drop came out +3.4 +- 0.3 % over full
#: dynamics' (six phases). The windows of those 0.1 s are judged: where they agree at its end, the next stretch
#: starts there; where a rattle's torques drift over them (the QJ208 hybrid's), the windows after it are judged
#: afresh. Over four phases 0.05 rad apart, to standstill: the pair -0.14 / +1.32 % for 681 windows (at phase 0),
#: the blower -0.03 / -1.13 % for 1072, the hybrid -0.62 / -0.95 % for 768. Before, the 0.1 s was left unjudged
#: and the next three windows judged: -0.11 / +1.20 %, -0.95 / -1.18 % and -0.47 / -0.29 % for 719, 1209 and 877
#: windows; 50 ms unjudged gave the pair +2.0 %, and the 0.1 s judged without the fresh start held the hybrid's
#: stretches back until its drifting torques agreed (55 s of computing against 12 s). Aiming each stretch at the
#: clearance step instead of halving it down to the step (0.65 % -> 0.95 % of the speed a stretch on the blower's
#: rattle) took the blower to 936 windows, but the larger kicks put the pair's non-drive end at +2.72 %.
RATTLE_SETTLE = 0.1
#: Longest reduced stretch between two full-dynamics checks [s].
MAX_STRETCH = 60.0
#: Conductivity of a steel shaft [W/(m K)] for the default journal-to-rotor path (the catalogue 'steel').
SHAFT_CONDUCTIVITY = 60.5
#: Shortest shaft length from a plane to the rotor body held at ambient [m] (a plane at the mass centre).
MIN_SHAFT_LENGTH = 0.05
OK = "ok"


class CoastdownRun(NamedTuple):
    """The result of :func:`run_coastdown`."""

    drop: MachineRun  #: the drop window (full dynamics, with the per-ball stress histories)
    history: xr.Dataset  #: the coast-down at every window and stretch end (units in attrs)
    summary: dict  #: verdict, times, energy audit, per plane temperatures, clearances and life
    #: per plane: the fatigue and dent results (:mod:`auxbearing.analysis.life`); None when the drop did not finish
    life: list


def drop_of(run: MachineRun | CoastdownRun) -> MachineRun:
    """A drop's run, given as itself or as the coast-down that starts with it."""
    return run.drop if isinstance(run, CoastdownRun) else run


# ----------------------------------------------------------------------------- the thermal side
def plane_network(machine: Machine, k: int, contact_load: float):
    """The lumped thermal network of plane k (:func:`auxbearing.analysis.thermal.build_network`)."""
    plane = machine.planes[k]
    coast = machine.coastdown
    journal_to_ambient = plane.journal_to_ambient
    if journal_to_ambient is None:
        # heat leaves the journal along the shaft to the rotor body, taken as a sink at ambient
        length = max(abs(plane.position), MIN_SHAFT_LENGTH)
        journal_to_ambient = SHAFT_CONDUCTIVITY * math.pi * plane.journal_radius**2 / length
    # a matched pair is both its rows, their rings lumped over the set's width (spacer included)
    set_width = None if plane.bearing_set is None else plane.bearing_set.width
    return build_network(plane.bearing, plane.journal_radius, contact_load=max(contact_load, 1.0),
                         housing_mass=plane.housing_mass, housing_to_ambient=plane.housing_to_ambient,
                         journal_to_ambient=journal_to_ambient, vacuum=coast.vacuum, emissivity=plane.emissivity,
                         ambient_temperature=coast.ambient_temperature, rows=plane.rows, set_width=set_width)


def _static_share(machine: Machine, k: int) -> float:
    """The weight a plane carries at rest [N] (:meth:`Machine.rest_share`), for the contact sizes of its network."""
    m = machine.rotor.mass * machine.simulation.gravity
    if machine.orientation == "vertical":
        return m if machine.planes[k].catches_axially else 0.0
    return m * machine.rest_share(k)


def _heat_per_node(network, contact: float, bearing: float, mount: float) -> np.ndarray:
    q = network.heat_inputs(sliding_power=contact, bearing_power=bearing)
    q[HOUSING] += mount
    return q


# ----------------------------------------------------------------------------- the session
class _Session:
    """The full-dynamics state carried between windows and stretches."""

    def __init__(self, machine: Machine, run) -> None:
        self.machine = machine
        self.model = run.model
        self.core = run.model.machine
        self.layout = run.model.layout
        self.y = run.y.copy()
        self.memory = run.memory
        self.t = float(run.memory.t[0])
        self.e0 = run.model.energy0
        self.window = whirl_window(machine)
        self.watch = run.watch
        self.base_clearance = np.array(self.core.planes.clearance)
        self.base_radius = np.array(self.core.planes.journal_radius)
        self.base_internal = self.core.ballset_clearance.copy()

    def forget_dead_bearings(self) -> None:
        """Carry on without the magnetic bearings that failed for good (:mod:`auxbearing.analysis.dead_bearings`)."""
        lighter = without_dead_bearings(self.machine, self.model, self.y, self.memory, self.e0, self.t)
        if lighter is not None:
            self.model, self.y, self.memory, self.e0 = lighter
            self.core, self.layout = self.model.machine, self.model.layout

    def sandbox(self) -> _Session:
        """A copy to run ahead on: its state, integrator memory and clearances are its own."""
        other = copy.copy(self)
        other.y = self.y.copy()
        other.memory = ig.Memory(*(a.copy() for a in self.memory))
        return other

    def energy_error(self) -> float:
        energy_in, accounted, scale = cm.energy_balance(self.y, self.core, self.e0)
        return (accounted - energy_in) / max(scale, 1e-300)

    def set_clearances(self, radial_change: np.ndarray, internal_change: np.ndarray, journal_growth: np.ndarray):
        """New clearances from thermal growth; the energy this adds at the current state is work in.

        The contacts are carried across the change (:meth:`_carry_contacts`): in the machine the clearances
        drift slowly and the rotor follows, while here they change in one step, after a window or a whole
        reduced stretch.
        """
        before = sum(cm.energy(self.y, self.core))
        self._carry_contacts(self.base_clearance + radial_change, self.base_internal + internal_change)
        planes = self.core.planes._replace(clearance=tuple(map(float, self.base_clearance + radial_change)),
                                           journal_radius=tuple(map(float, self.base_radius + journal_growth)))
        self.core = self.core._replace(planes=planes, ballset_clearance=self.base_internal + internal_change)
        self.y[self.layout.work_in] += sum(cm.energy(self.y, self.core)) - before

    def _carry_contacts(self, clearance: np.ndarray, internal: np.ndarray) -> None:
        """Move the races and the rotor so that every contact keeps its compression under the new clearances.

        A race bearing on its balls moves to where they push it as they did (:func:`_race_carry`: half the
        change of the diametral clearance along its load while the set has clearance, hardly at all once
        thermal growth has closed it into a preload); a journal in contact with its race moves with the race
        and by the change of the radial clearance along the contact normal. The journals' moves give the rotor's
        translation and tilts by least squares (exact for two planes). Measured on the blower over 30 s: a
        clearance step that let the journals fall through it rang for tens of milliseconds and took 4 % off the
        damage per drop of the reduced model against full dynamics; carried (half the change), 3.0 % and 2.2 %;
        with the race carried at its force, 2.3 % and 0.9 %.
        """
        y, planes = self.y, self.core.planes
        n = len(self.machine.planes)
        shift = np.zeros((n, 2))
        after = self.core._replace(ballset_clearance=np.asarray(internal, float))
        for k in range(n):
            b = self.layout.plane(k)
            d = np.array([y[b + cm.RX] - y[b + cm.OX], y[b + cm.RY] - y[b + cm.OY]])
            race = _race_carry(self.core, after, k, float(y[b + cm.RZ]), d) - d
            a = planes.position[k]
            e = np.array([y[cm.X] + a * y[cm.TY] - y[b + cm.RX], y[cm.Y] - a * y[cm.TX] - y[b + cm.RY]])
            gap = math.hypot(*e)
            y[b + cm.RX] += race[0]
            y[b + cm.RY] += race[1]
            shift[k] = race
            if gap > planes.clearance[k]:
                shift[k] += (clearance[k] - planes.clearance[k]) * e / gap
        if not shift.any():
            return
        if n == 1 or not self.machine.tilt_free:
            y[cm.X] += shift[:, 0].mean()
            y[cm.Y] += shift[:, 1].mean()
            return
        # journal k sits at (X + a_k TY, Y - a_k TX)
        fit = np.linalg.lstsq(np.column_stack([np.ones(n), np.array(planes.position[:n])]), shift, rcond=None)[0]
        y[cm.X] += fit[0, 0]
        y[cm.TY] += fit[1, 0]
        y[cm.Y] += fit[0, 1]
        y[cm.TX] -= fit[1, 1]

    def full(self, length: float):
        """Full dynamics for ``length`` seconds; returns (status, watch, ledger before).

        Each window has its own onsets and whirl records; the largest ball load carries over (the observer
        evaluates the ball stresses, which its range limits judge, on the steps that come near it). The windows'
        peaks are not reported (the drop's are), so the observer tracks none (:mod:`auxbearing.core.watch`,
        ``track_peaks``): its refinement of a peak, in a steady rolling at low speed, ran a search on one step in
        four and made each step six times as dear.
        """
        ledger = self.y[self.layout.ledger_at:].copy()
        watch = cw.new_watch(self.y.size, self.layout.planes, self.window, math.ceil(length / self.window) + 1,
                             self.e0)
        for name in ("peak_load", "shoulder_use"):
            getattr(watch, name)[...] = getattr(self.watch, name)
        watch.track_peaks[0] = 0.0
        self.watch = watch
        for k in range(len(self.machine.planes)):
            watch.in_contact[k] = 1.0 if _penetration(self.y, self.core, k) > 0.0 else 0.0
        watch.window_end[0] = self.t + self.window
        settings = self.model.settings._replace(step_budget=10**9)
        status = drive.advance_window(self.core, watch, self.y, self.t + length, settings, self.memory,
                               np.empty((0, self.y.size)))
        self.t = float(self.memory.t[0])
        return status, watch, ledger

    def set_speeds(self, omega: float, race_speeds, driven=None) -> None:
        """Set the rotor's and the races' spin speeds (the end of a reduced stretch).

        ``driven``: per plane, whether its journal's motion is locked to the spin
        (:func:`auxbearing.analysis.coastdown_phases.spin_locked`: rolling round its bore, whirling backward on it
        or free of it, and not yet come to rest in its bore). Such a motion runs, at the speed Omega_1, the path
        it ran at Omega_0, Omega_1 / Omega_0 as fast: a journal pressed round its bore by its unbalance whirls at
        the spin speed on the clearance circle, one whirling backward at a speed rolling ties to the spin's and
        the race's. So that journal's lateral velocity, its race's and its ring's are scaled by Omega_1 / Omega_0.
        Carried unscaled, the orbit resumed at the old pace and with the old speed's centrifugal load, and the
        windows after every stretch charged a lift the new speed no longer gives. Scaling the geometric axis'
        velocity scales the mass centre's with it, since the unbalance's turning offset moves at Omega.

        A journal at rest in its bore swings as a pendulum at its own frequency, and a rattling one moves as its
        impacts, its weight and its unbalance together make it; neither is set by the spin alone. Their velocity
        carries on, and only the unbalance terms change. The state holds the geometric axis, whose
        velocity is the mass centre's less the unbalance's turning offset: G' = O' + e u' Omega and
        theta_p' = theta_g' + chi w' Omega (:mod:`auxbearing.core.machine`). Over the stretch the spin slowed
        while the mass centre's momentum and the principal axis' angular momentum carried on, so the axis'
        velocities take the change of the unbalance terms (left as they were, the mass centre took a kick of
        e dOmega at every handover).

        With both kinds of plane on one rotor (two planes or more), the rotor's lateral and tilt velocities are
        those (in least squares beyond two planes) that give each journal its own rule's velocity; the elastic
        modes' rates are scaled only when every plane is driven.
        """
        y = self.y
        planes = len(self.machine.planes)
        driven = [False] * planes if driven is None else list(driven)
        old = float(y[cm.OMEGA])
        ratio = omega / old if old != 0.0 else 1.0
        kin = cm.rotor_kinematics(y, self.core.rotor)
        slowed = old - omega
        # the unbalance terms' change, which the old rule adds to the axis' velocities (VX, VY, WX, WY)
        unbalance_shift = np.array([kin[0] * slowed, kin[1] * slowed, kin[4] * slowed, kin[5] * slowed])
        if all(driven):  # the whole rotor's lateral motion at the new pace, modes included
            for i in (cm.VX, cm.VY, cm.WX, cm.WY):
                y[i] *= ratio
            if self.layout.modes:
                rates = self.layout.modes_at + self.layout.modes
                y[rates:rates + self.layout.modes] *= ratio
        elif any(driven):  # two planes or more, each journal its own rule
            positions = np.asarray(self.core.planes.position[:planes], dtype=float)
            vx, vy, wx, wy = (float(y[i]) for i in (cm.VX, cm.VY, cm.WX, cm.WY))
            # journal k's rigid velocity: (VX + a_k WY, VY - a_k WX); each axis is its own 2-unknown fit
            jx, jy = vx + positions * wy, vy - positions * wx
            tx = np.where(driven, ratio * jx, jx + unbalance_shift[0] + positions * unbalance_shift[3])
            ty = np.where(driven, ratio * jy, jy + unbalance_shift[1] - positions * unbalance_shift[2])
            design = np.column_stack([np.ones(planes), positions])
            (new_vx, new_wy), *_ = np.linalg.lstsq(design, tx, rcond=None)
            (new_vy, minus_wx), *_ = np.linalg.lstsq(design, ty, rcond=None)
            y[cm.VX], y[cm.VY], y[cm.WX], y[cm.WY] = new_vx, new_vy, -minus_wx, new_wy
        else:
            y[cm.VX] += unbalance_shift[0]
            y[cm.VY] += unbalance_shift[1]
            y[cm.WX] += unbalance_shift[2]
            y[cm.WY] += unbalance_shift[3]
        for k in range(planes):
            if driven[k]:
                b = self.layout.plane(k)
                for i in (cm.RVX, cm.RVY, cm.OVX, cm.OVY):
                    y[b + i] *= ratio
        y[cm.OMEGA] = omega
        for k in range(planes):
            y[self.layout.plane(k) + cm.ROMEGA] = race_speeds[k]
        self.memory.evaluations[0] = 0  # the first-stage derivative must be recomputed


def _ballset_radial(core, k: int, dz: float, d: np.ndarray) -> np.ndarray:
    """Radial force (x, y) of plane k's ball set on its race at race displacement ``d`` from the ring [N]."""
    disp, force = np.zeros(5), np.zeros(5)
    if core.planes.rows[k] > 1.0:
        _, fx, fy, _ = cm._pair_reaction(k, dz, float(d[0]), float(d[1]), core, disp, force)
        return np.array([fx, fy])
    disp[0], disp[1], disp[2] = dz, d[0], d[1]
    cm.accumulate(disp, core.ballsets[k], core.ballset_clearance[k], force, core.jac_stub, False, False)
    return force[1:3].copy()


def _race_carry(before, after, k: int, dz: float, d: np.ndarray) -> np.ndarray:
    """The race displacement under the new internal clearance at which the balls push it as they did [m].

    The ball set's force at ``d`` with the old clearance is found again with the new one (Newton's method on
    the ball-set law of Eq. 14/16, finite-difference Jacobian). For a race in clearance that is the old rule, a
    move of half the change of the diametral clearance along its load; for a preloaded set (thermal growth
    closes the clearance into a preload, as on the blower) the balls on both sides are compressed and the
    race hardly moves. An unloaded race keeps its gap to the balls (half the change, along ``d``).
    """
    change = 0.5 * (after.ballset_clearance[k] - before.ballset_clearance[k])
    target = _ballset_radial(before, k, dz, d)
    size = math.hypot(*d)
    guess = d + change * d / size if size > 0.0 else d.copy()
    scale = float(np.hypot(*target))
    if scale <= 0.0:
        return guess
    x, step = d.copy(), 1e-10
    for _ in range(30):
        miss = _ballset_radial(after, k, dz, x) - target
        if np.hypot(*miss) <= 1e-10 * scale:
            return x
        jac = np.column_stack([(_ballset_radial(after, k, dz, x + step * e) - target - miss) / step
                               for e in np.eye(2)])
        try:
            move = np.linalg.solve(jac, -miss)
        except np.linalg.LinAlgError:
            return guess
        x = x + np.clip(move, -abs(change) - 1e-7, abs(change) + 1e-7)
    return guess


def _penetration(y, core, k) -> float:
    from auxbearing.core.probes import plane_diagnostics

    return float(plane_diagnostics(y, core, k)[cm.D_PEN])


def _window_powers(machine: Machine, layout: cm.Layout, y, ledger, length: float) -> dict:
    """Mean heat powers of a window by plane and source [W], and drag power, from the ledger."""
    now = y[layout.ledger_at:]
    diff = (now - ledger) / max(length, 1e-300)
    out = {"drag": diff[cm.L_DRAG_LOSS], "process": diff[cm.L_WORK_IN]}
    for k in range(len(machine.planes)):
        base = cm.L_HEAT + 3 * k
        out[k] = (diff[base], diff[base + 1], diff[base + 2])
    return out


def _window_planes(machine: Machine, watch, powers: dict, core) -> list:
    """Each plane's state over the window just run (:func:`auxbearing.analysis.coastdown_phases.plane_window`).

    Judged on the journal radii and clearances ``core`` (the packed machine) ran it with.
    """
    n = int(watch.window_count[0])
    planes = [plane_window(machine, k, watch.whirl[:n, k], int(watch.onsets[k]), powers[k],
                           (core.planes.journal_radius[k], core.planes.clearance[k]))
              for k in range(len(machine.planes))]
    return [w._replace(load=_window_load(machine, k, w)) for k, w in enumerate(planes)]


def _stretch(machine: Machine, session: _Session, networks, temps, windows, t_end: float, growth: float = 1.0,
             stop_above: float = 0.0):
    """Advance the slow quantities on the reduced model (:mod:`auxbearing.core.spin`).

    The stretch ends when the speed has fallen by ``growth`` times ``coastdown.speed_step`` (at most by
    :data:`~auxbearing.analysis.coastdown_phases.MAX_SPEED_FALL`, unless the speed step itself is larger;
    :func:`auxbearing.analysis.coastdown_phases.stretch_growth`). The temperatures take one exact step with the
    stretch's mean heat input; the stretch is halved until no clearance moves more than :data:`CLEARANCE_STEP`
    and no part passes ``coastdown.max_temperature`` (so a run-away is found within a check window of its
    time). Returns the stretch (:class:`auxbearing.analysis.coastdown_phases.Stretch`) and the new temperatures.
    """
    coast = machine.coastdown
    y = session.y
    omega0 = float(y[cm.OMEGA])
    races = [float(y[cm.N_ROTOR + k * cm.N_PLANE + cm.ROMEGA]) for k in range(len(machine.planes))]
    fall = min(growth * coast.speed_step, max(coast.speed_step, MAX_SPEED_FALL))
    floor = max(abs(omega0) * (1.0 - fall), coast.stop_speed, stop_above)
    model = spin_model(machine, windows, omega0, races, floor)
    span = min(t_end - session.t, MAX_STRETCH)
    while True:
        result = integrate_stretch(model, omega0, races, span)
        duration = result.duration
        new_temps = [net.step(temps[k], _heat_per_node(net, *(np.array(result.heat[k]) / max(duration, 1e-300))),
                              duration) for k, net in enumerate(networks)]
        moved = max(max(abs(a - b) for a, b in zip(net.clearance_changes(nt), net.clearance_changes(t0), strict=True))
                    for net, nt, t0 in zip(networks, new_temps, temps, strict=True))
        # a part passing the temperature limit ends the run: the stretch is shortened until it ends there
        hot = max(float(np.max(nt)) for nt in new_temps) > coast.max_temperature
        if (moved <= CLEARANCE_STEP and not hot) or duration <= coast.check_window:
            return result, new_temps
        span = 0.5 * duration


def _clearance_changes(networks, temps, blocks: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Thermal changes of the radial and internal clearances and the journal's growth [m], per packed plane."""
    radial, internal, growth = np.zeros(blocks), np.zeros(blocks), np.zeros(blocks)
    for k, (net, tk) in enumerate(zip(networks, temps, strict=True)):
        radial[k], internal[k] = net.clearance_changes(tk)
        growth[k] = net.expansion[JOURNAL] * net.journal_radius * (tk[JOURNAL] - net.ambient_temperature)
    return radial, internal, growth


def _load_inside(machine: Machine, start: _Session, networks, temps, carried, t_end: float, growth: float,
                 locked, window: float, top: float, bottom: float, share: float):
    """The bearing loads a stretch from ``top`` to ``bottom`` [rad/s] passes through ``share`` of the way down.

    From ``start`` (the session as the stretch found it), the reduced model runs the stretch again down to
    that speed, then full dynamics for :data:`PROBE_WINDOWS` windows, the first of which lets the motion find the
    new speed; the others' mean equivalent load is the load there. Returns (revolutions of each race to that
    point, loads), or None where the copy leaves the model's range. Nothing of the run itself is touched.
    """
    sandbox = start.sandbox()
    speed = top - share * (top - bottom)
    stretch, new_temps = _stretch(machine, sandbox, networks, temps, carried, t_end, growth, speed)
    sandbox.set_speeds(stretch.rotor_speed, stretch.race_speeds, locked)
    sandbox.t += stretch.duration
    sandbox.memory.t[0] = sandbox.t
    sandbox.set_clearances(*_clearance_changes(networks, new_temps, sandbox.layout.planes))
    loads = []
    for _ in range(PROBE_WINDOWS):
        status, watch, ledger = sandbox.full(window)
        if status in (ig.STOPPED, ig.STEP_UNDERFLOW):
            return None
        loads.append([w.load for w in _window_planes(machine, watch, _window_powers(
            machine, sandbox.layout, sandbox.y, ledger, window), sandbox.core)])
    return list(stretch.race_revolutions), list(np.mean(loads[1:], axis=0))


#: Full-dynamics windows a probe inside a stretch runs (:func:`_load_inside`); the first is not measured.
PROBE_WINDOWS = 4


# ----------------------------------------------------------------------------- the run
class _Limits:
    """Thermal state, clearances and the limits checked after every window and stretch."""

    def __init__(self, machine: Machine, session: _Session, networks) -> None:
        self.machine = machine
        self.session = session
        self.networks = networks
        ambient = machine.coastdown.ambient_temperature
        self.temps = [np.full(len(NODE_NAMES), ambient) for _ in networks]
        self.max_temps = [t.copy() for t in self.temps]
        n = len(networks)
        self.min_radial = [p.radial_clearance for p in machine.planes]
        self.min_internal = [p.bearing.diametral_clearance for p in machine.planes]
        self.radial = np.zeros(n)
        self.internal = np.zeros(n)

    def update(self, temps, t: float) -> tuple[str, str | None]:
        """New temperatures: clearances into the dynamics, limits checked; returns (verdict, reason)."""
        self.temps = [np.asarray(x, float) for x in temps]
        n = len(self.networks)
        for k, tk in enumerate(self.temps):
            self.max_temps[k] = np.maximum(self.max_temps[k], tk)
        radial, internal, growth = _clearance_changes(self.networks, self.temps, self.session.layout.planes)
        self.session.set_clearances(radial, internal, growth)
        self.radial, self.internal = radial[:n], internal[:n]
        for k, plane in enumerate(self.machine.planes):  # every plane's smallest first: the history records them all
            self.min_radial[k] = min(self.min_radial[k], plane.radial_clearance + radial[k])
            self.min_internal[k] = min(self.min_internal[k], plane.bearing.diametral_clearance + internal[k])
        for k, plane in enumerate(self.machine.planes):
            s = plane.radial_clearance + radial[k]
            pd = plane.bearing.diametral_clearance + internal[k]
            hottest = int(np.argmax(self.temps[k]))
            if self.temps[k][hottest] > self.machine.coastdown.max_temperature:
                limit = self.machine.coastdown.max_temperature - 273.15
                return "thermal_runaway", (
                    f"{plane.name}: the {NODE_NAMES[hottest].replace('_', ' ')} passed coastdown.max_temperature = "
                    f"{limit:g} degC at t = {t:.2f} s")
            if s <= 0.0:
                return "radial_clearance_closed", (
                    f"{plane.name}: thermal growth closed the journal/race clearance at t = {t:.2f} s: the journal "
                    "seizes in the race")
            if pd < 0.0 or plane.bearing_set is not None:
                stress = rest_stress(plane, self.session.core.ballsets[k], pd)
                if stress > ISO76_BALL_STRESS:
                    return "internal_clearance_preload", (
                        f"{plane.name}: the internal clearance closed to {pd * 1e6:.1f} um at t = {t:.2f} s, a preload "
                        f"of {stress / 1e6:.0f} MPa at rest, above ISO 76's {ISO76_BALL_STRESS / 1e6:.0f} MPa")
        return OK, None


def rest_stress(plane, ballset, clearance: float) -> float:
    """Largest ball stress at rest [Pa] of a plane's bearing whose internal clearance is ``clearance`` [m].

    A single row is stressed only once thermal growth has closed its clearance into a preload (negative); each row
    of a matched pair is also pushed its share of the set's preload into its balls
    (:attr:`auxbearing.bearings.duplex.DuplexSet.row_preload_displacement`), which the closing adds to (the 7208
    DB pair with 8 um: 675 MPa from the preload alone, 894 MPa with 5.07 um closed; the row alone gave 584).
    Ball-set law of Eq. 14/16 at the race's rest displacement.
    """
    push = plane.bearing_set.row_preload_displacement if plane.bearing_set is not None else 0.0
    if clearance >= 0.0 and push == 0.0:
        return 0.0
    st = ballset_state(np.array([push, 0.0, 0.0, 0.0, 0.0]), ballset, clearance=clearance)
    return float(max(st.stress_inner.max(), st.stress_outer.max()))


def shortest_coastdown(machine: Machine) -> float:
    """Shortest simulated time a coast-down takes [s].

    Two output steps (to rounding): the drop's record it starts from (over-rolling, damage) needs two samples.
    """
    return 2.0 * machine.simulation.output_step * (1.0 - 1e-9)


def _race_speeds(session) -> list[float]:
    """Each plane's race speed in the session's state [rad/s]."""
    return [float(session.y[cm.N_ROTOR + k * cm.N_PLANE + cm.ROMEGA]) for k in range(len(session.machine.planes))]


def _check_output_step(machine: Machine) -> None:
    """Refuse a drop record too coarse for the drop's fatigue count, before anything runs.

    The count follows each ball over its raceway from sample to sample, so a ball may move at most half the
    ball spacing pi / Z per output step (:func:`auxbearing.analysis.life.drop_damage`). The faster of the two
    tracks is the inner raceway's, which passes under the balls at omega_r (1 + gamma) / 2 with the outer ring
    fixed (the inner race's ball-pass frequency, Harris & Kotzalas, Rolling Bearing Analysis, 5th ed., 2007,
    Sec. 8.2; the cage turns at omega_r (1 - gamma) / 2), the race at most at the rotor's speed (rolling on a
    journal smaller than its bore).
    """
    step = machine.simulation.output_step
    spin = abs(machine.rotor.speed)
    for plane in machine.planes:
        b = plane.bearing
        gamma = b.ball_diameter * math.cos(b.contact_angle) / b.pitch_diameter
        passing = spin * (1.0 + gamma) / 2.0
        if passing * step > math.pi / b.ball_count:
            longest = math.pi / b.ball_count / passing
            raise InputError(f"drop.output_step = {step * 1e6:g} us: too coarse for the fatigue count of "
                             f"{plane.name}: at {spin * 30.0 / math.pi:.0f} rpm its balls move more than half their "
                             f"spacing per sample; use {longest * 1e6:.0f} us or less")


def shortest_coastdown_rule(machine: Machine) -> str:
    """The rule :func:`shortest_coastdown` sets, as an error says it."""
    return (f"must be at least {2e6 * machine.simulation.output_step:g} us (two of the drop's output steps, the "
            "shortest record a coast-down starts from)")


def run_coastdown(machine: Machine | str, until_stop: bool = True, duration: float | str | None = None,
                  mode: str = "auto", progress: Callable[[float, str], None] | None = None) -> CoastdownRun:
    """Run a machine from its drop to standstill (or for ``duration`` seconds); see the module docstring.

    Parameters
    ----------
    machine : Machine or str
        A machine, or a machine TOML path or example machine's name.
    until_stop : bool
        Go on until the rotor turns slower than ``coastdown.stop_speed`` (at most ``coastdown.max_time``).
    duration : float or str, optional
        Simulated time (s, or a string with a unit) instead of running to standstill: given, it replaces
        ``until_stop`` (the run still ends at standstill, if it comes first).
    mode : {"auto", "full"}
        "auto" hands settled stretches to the reduced model; "full" keeps full dynamics throughout
        (for checking the reduced model; slow for long coast-downs).
    progress : callable, optional
        Called with (fraction, status line) after every window and stretch.
    """
    if mode not in ("auto", "full"):
        raise InputError.for_field("mode", mode, "must be 'auto' or 'full'")
    machine = as_machine(machine)
    _check_output_step(machine)
    coast = machine.coastdown
    if not isinstance(until_stop, bool):  # 'no' is a true value to Python, not to the person who wrote it
        raise InputError.for_field("until_stop", until_stop, "must be True or False")
    if duration is not None:
        given = duration
        duration = simulated_time(duration)
        if duration < shortest_coastdown(machine):
            raise InputError.for_field("duration", given, shortest_coastdown_rule(machine))
        until_stop = False  # a duration replaces the run to standstill, in the API as on the command line
    elif not until_stop:
        raise InputError.for_field("until_stop", until_stop, "needs a duration (or run to standstill)")
    t_end = coast.max_time if (until_stop and duration is None) else float(duration or coast.max_time)
    if duration is None and t_end < shortest_coastdown(machine):
        from auxbearing.common.params import display_value
        from auxbearing.machine.params import COASTDOWN

        row = next(p for p in COASTDOWN if p.key == "max_time")
        raise InputError.for_field("coastdown.max_time", display_value(row, t_end),
                                   shortest_coastdown_rule(machine))
    wall_start = time.perf_counter()
    drop_length = min(machine.simulation.duration, t_end)
    run = integrate_machine(machine, drop_length, None, None)
    drop_ds = machine_dataset(machine, run.model, run.grid, run.output_step)
    drop = MachineRun(drop_ds, machine_summary(machine, run, drop_ds, drop_length))
    drop_ds.attrs["summary"] = _json(drop.summary)  # as run_machine's: the drop stands as a run of its own
    networks = [plane_network(machine, k, _static_share(machine, k) / max(p.rows * p.bearing.ball_count, 1))
                for k, p in enumerate(machine.planes)]
    session = _Session(machine, run)
    session.forget_dead_bearings()
    limits = _Limits(machine, session, networks)
    history: list[dict] = []
    overrolling: list[list[tuple[float, float]]] = [[] for _ in machine.planes]
    verdict, reason = drop.summary["verdict"], drop.summary["reason"]
    full_time = session.t
    reduced_time = 0.0
    counts = {"windows": 0, "stretches": 0, "states": {}}
    backward = BackwardWhirl(len(machine.planes))  # judged as in a drop: a whirl in the coast-down counts too
    checked: list = []  # each full window's planes since the last stretch
    motion: list = []  # the last full windows in one family of reducible states, for motion_steady
    steady = False  # the motion has been found steady since it last changed state
    ending = None  # the last stretch until the windows after it have measured the load at its end
    held = None  # the windows the last stretch held its torques from, while the states stay reducible
    growth = 1.0  # the stretches' speed step over coastdown.speed_step (coastdown_phases.stretch_growth)
    settling = 0
    kicked_at = None  # when the last stretch handed a rattling journal back, until RATTLE_SETTLE has passed
    stopped_at = None
    window_scale = 1  # the windows' length over the check window: doubled where they are too short (too_short)

    tail = None
    marks: list[tuple[float, float]] = []  # (t, |Omega|) after each window and stretch, for the deceleration

    to_standstill = until_stop and duration is None
    speed0 = max(abs(float(session.y[cm.OMEGA])), coast.stop_speed)
    passages = pendulum_passages(machine, speed0)
    rested = [False] * len(machine.planes)  # per plane: its journal has come to rest in its bore, under the weight
    pendulums = [w > 0.0 for w in pendulum_frequencies(machine)]

    def done() -> float:
        # to standstill: the share of the speed lost (coastdown.max_time is only a bound); else of the time
        if to_standstill:
            left = (abs(float(session.y[cm.OMEGA])) - coast.stop_speed) / max(speed0 - coast.stop_speed, 1e-300)
            return min(1.0, max(0.0, 1.0 - left))
        return min(1.0, session.t / t_end)

    def record(mode_code: int) -> None:
        y = session.y
        history.append({"time": session.t, "mode": mode_code, "rotor_speed": float(y[cm.OMEGA]),
                        "race_speed": [float(y[cm.N_ROTOR + k * cm.N_PLANE + cm.ROMEGA]) for k in range(len(networks))],
                        "temperature": [t.copy() for t in limits.temps],
                        "radial_clearance": [p.radial_clearance + limits.radial[k]
                                             for k, p in enumerate(machine.planes)],
                        "internal_clearance": [p.bearing.diametral_clearance + limits.internal[k]
                                               for k, p in enumerate(machine.planes)],
                        "energy_error": float(session.energy_error())})

    if verdict == OK:
        powers = _window_powers(machine, session.layout, session.y, np.zeros(session.y.size - session.layout.ledger_at),
                                max(session.t, 1e-300))
        temps = [net.step(limits.temps[k], _heat_per_node(net, *powers[k]), session.t)
                 for k, net in enumerate(networks)]
        verdict, reason = limits.update(temps, session.t)
    record(2)  # the drop's end, also when the drop itself left the model's range
    while verdict == OK and session.t < t_end - 1e-12:
        if abs(session.y[cm.OMEGA]) <= coast.stop_speed:  # a run for a duration ends at standstill too
            stopped_at = session.t
            break
        marks.append((session.t, abs(float(session.y[cm.OMEGA]))))
        del marks[:-64]
        deceleration = _deceleration(marks)
        if until_stop and deceleration is not None:
            tail = spent_tail(machine, session, networks, overrolling, deceleration)
            if tail is not None:
                stopped_at = session.t + tail["time_left_s"]
                break
        attempts = int(session.memory.steps[0] + session.memory.rejected[0])
        if attempts >= coast.max_steps:
            verdict = "step_budget"
            reason = (f"the step budget coastdown.max_steps = {coast.max_steps:.3g} was used up at "
                      f"t = {session.t:.2f} s of the coast-down (the motion stayed that long in states only full "
                      "dynamics carries); raise it to go on")
            break
        if time.perf_counter() - wall_start > machine.simulation.max_wall_time:  # interactive use only
            verdict = "wall_time_budget"
            reason = (f"the wall-time guard drop.max_wall_time = {machine.simulation.max_wall_time:g} s was reached "
                      f"at t = {session.t:.2f} s of the coast-down; raise it to go on")
            break
        # a window holds at least one closed whirl window, which its states are judged on
        length = min(max(coast.check_window, session.window) * window_scale, t_end - session.t)
        omega_start = float(session.y[cm.OMEGA])
        races_start = _race_speeds(session)
        status, watch, ledger = session.full(length)
        counts["windows"] += 1
        full_time += length
        if status == ig.STOPPED:
            verdict = cw.STOP_NAMES[int(watch.stop[0])]
            k = int(watch.stop[1])
            reason = (f"{machine.planes[k].name if k >= 0 else 'the machine'}: {verdict.replace('_', ' ')} at "
                      f"t = {float(watch.stop[2]):.3f} s during the coast-down")
            break
        if status == ig.STEP_UNDERFLOW:
            verdict, reason = "integration_failed", f"the integration could not go on at t = {session.t:.4g} s"
            break
        interrupt.check()
        powers = _window_powers(machine, session.layout, session.y, ledger, length)
        temps = [net.step(limits.temps[k], _heat_per_node(net, *powers[k]), length) for k, net in enumerate(networks)]
        omega_mean = 0.5 * (omega_start + float(session.y[cm.OMEGA]))
        windows = _window_planes(machine, watch, powers, session.core)
        backward.window(windows, session.t, length)
        races_end = _race_speeds(session)
        for k, w in enumerate(windows):
            if w.whirl_classes:
                overrolling[k].append((abs(w.race_speed) * length / (2.0 * math.pi), w.load))
            else:  # a last window shorter than a whirl window closed none: its race still turned, under the
                # load of the window before it (or the plane's share of the weight after the drop)
                revs = 0.5 * (abs(races_start[k]) + abs(races_end[k])) * length / (2.0 * math.pi)
                overrolling[k].append((revs, overrolling[k][-1][1] if overrolling[k] else _static_share(machine, k)))
        if ending is not None and ending.left(windows):
            ending = None
        verdict, reason = limits.update(temps, session.t)
        record(0)
        reducible = all(p.state in REDUCIBLE for p in windows)
        if not reducible or (motion and not same_families(motion[-1], windows)):
            motion, steady = [], False
            held, growth = None, 1.0
            window_scale = 1
        if reducible:
            span = math.ceil(STEADY_SPAN / length - 1e-9)
            motion.append(windows)
            del motion[:-STEADY_SPANS * span]
            steady = steady or motion_steady(motion, span, quiet_orbits(machine, windows))
            if len(motion) >= span:
                rested = [a or (b and p) for a, b, p in zip(rested, resting(motion[-span:]), pendulums, strict=True)]
        if progress is not None:
            rpm = abs(session.y[cm.OMEGA]) * 30 / math.pi
            progress(done(), f"t = {session.t:.2f} s, {rpm:.0f} rpm")
        settling -= 1
        if settling >= 0:
            continue
        checked.append(windows)
        del checked[:-MAX_WINDOWS]  # settled looks back over these at most
        carried = settled(checked)
        if kicked_at is not None and session.t - kicked_at >= RATTLE_SETTLE - 1e-12:
            kicked_at = None
            if carried is None and len(checked) >= MIN_WINDOWS:
                checked = []  # still drifting: judged afresh on the windows that follow (RATTLE_SETTLE)
                continue
        if kicked_at is not None:
            continue  # the rattle the last handover kicked has not had the time to forget it
        if carried is None and steady and mode != "full" and window_scale < WINDOW_GROWTH and too_short(checked):
            window_scale *= 2
            checked = []  # the shorter windows' scatter is not the longer ones'
            continue
        if verdict != OK or mode == "full" or carried is None or not steady:
            continue
        if abs(omega_mean) <= coast.stop_speed or abs(session.y[cm.OMEGA]) <= coast.stop_speed:
            continue  # at standstill: the loop's top ends the run
        if pendulum_swinging(machine, motion[-span:], checked, rested, passage_at(passages, session.y[cm.OMEGA])):
            # a swing builds up in a passage and dies out after it on its own time scale, which a stretch would
            # stop: full dynamics while it lasts
            if ending is not None:  # the stretch before ended where these windows started
                ending.close(carried, overrolling)
                ending = None
            continue
        for w in carried:
            counts["states"][w.state] = counts["states"].get(w.state, 0) + 1
        if ending is not None:  # the last stretch ends at the load these windows settled on
            ending.close(carried, overrolling)
        loads = [w.load for w in carried]
        if not calm(machine, checked):
            growth = 1.0
        elif held is not None:
            growth = stretch_growth(growth, held, carried, machine)
        held = carried
        # the stretch's start, kept to measure inside it should its ends disagree (coastdown_phases.StretchEnd)
        start, start_temps, top = session.sandbox(), [t.copy() for t in limits.temps], abs(float(session.y[cm.OMEGA]))
        stretch, temps = _stretch(machine, session, networks, limits.temps, carried, t_end, growth,
                                  next_passage_top(passages, session.y[cm.OMEGA]))
        backward.stretch(carried, session.t, stretch.duration)
        session.set_speeds(stretch.rotor_speed, stretch.race_speeds, spin_locked(carried, rested))
        for k in range(len(networks)):
            for j in range(3):
                session.y[session.layout.heat(k, j)] += stretch.heat[k][j]
            overrolling[k].append((stretch.race_revolutions[k], loads[k]))
        probe_args = (machine, start, networks, start_temps, carried, t_end, growth, spin_locked(carried, rested),
                      min(max(coast.check_window, session.window) * window_scale, t_end - session.t))
        inside = functools.partial(_load_inside, *probe_args, top, abs(stretch.rotor_speed))
        ending = StretchEnd(carried, [len(o) - 1 for o in overrolling], inside)
        session.y[session.layout.drag_loss] += stretch.drag_loss
        session.y[session.layout.work_in] += stretch.work
        session.t += stretch.duration
        session.memory.t[0] = session.t
        reduced_time += stretch.duration
        counts["stretches"] += 1
        checked = []  # the next windows start from a new state: they are judged on their own
        settling = math.ceil(coast.settle_time / max(coast.check_window, session.window) - 1e-9)
        kicked_at = session.t if any(w.state == "rattling" for w in carried) else None
        verdict, reason = limits.update(temps, session.t)
        record(1)
        if progress is not None:
            progress(done(),
                     f"t = {session.t:.2f} s, {abs(stretch.rotor_speed) * 30 / math.pi:.0f} rpm")
    if verdict == OK and stopped_at is None and abs(session.y[cm.OMEGA]) <= coast.stop_speed:
        stopped_at = session.t
    if verdict == OK and to_standstill and stopped_at is None:
        # coastdown.max_time bounds the work of a run to standstill: reaching it is no finding about the machine
        verdict = TIME_BUDGET
        reason = (f"coastdown.max_time = {coast.max_time:g} s was reached at "
                  f"{abs(float(session.y[cm.OMEGA])) * 30.0 / math.pi:.0f} rpm, before standstill "
                  f"(coastdown.stop_speed = {coast.stop_speed * 30.0 / math.pi:g} rpm); raise it to go on")
    history_ds = _history(machine, history)
    # a drop that did not finish leaves a stress history cut at its range exit or budget: damage counted
    # from it would be a number from outside the model, so no life is computed
    finished = drop.summary["verdict"] == "ok"
    lives = [plane_life(machine, k, drop.dataset, drop.summary["planes"][k], overrolling[k]) if finished else None
             for k in range(len(machine.planes))]
    summary = _summary(machine, drop, session, limits, lives, verdict, reason, stopped_at, full_time, reduced_time,
                       counts, time.perf_counter() - wall_start, until_stop, backward)
    summary["tail"] = tail
    history_ds.attrs["summary"] = _json(summary)
    return CoastdownRun(drop, history_ds, summary, lives)


def _partial_life_note(verdict: str, simulated: float) -> str:
    """What a life counted over a coast-down that did not reach standstill covers."""
    why = "run for a duration" if verdict == OK else f"stopped: {verdict.replace('_', ' ')}"
    return (f"counted over the first {simulated:.3g} s only ({why}, before standstill): the damage per drop is a lower "
            "bound and the drops to failure an upper bound")


def required_drops_source(machine: Machine) -> str:
    """Where the number of drops the bearings must survive comes from: the machine file, or our assumption."""
    if "required_drops" in machine.life.given:
        return "the machine file's life.required_drops"
    return "an assumption of auxbearing (life.required_drops), not a standard's clause: set it in your file"


#: Verdict of a run to standstill that reached coastdown.max_time first (a budget: its outcome is not known).
TIME_BUDGET = "time_budget"

#: Span over which the deceleration the tail is extrapolated at is measured [s] (a rattle's windows scatter).
DECELERATION_SPAN = 0.1


def _deceleration(marks: list) -> float | None:
    """Mean deceleration over the last :data:`DECELERATION_SPAN` of (t, |Omega|) marks, or None if shorter."""
    t_now, w_now = marks[-1]
    for t, w in reversed(marks[:-1]):
        if t_now - t >= DECELERATION_SPAN:
            return (w - w_now) / (t_now - t)
    return None


#: Share of the damage so far that the revolutions left may add at most for the tail to be left unsimulated.
TAIL_DAMAGE_SHARE = 1e-3


def spent_tail(machine: Machine, session: _Session, networks, overrolling, deceleration: float) -> dict | None:
    """The rest of a coast-down when nothing it could still do can move a result, else None.

    Every joule the machine still dissipates comes from the spin energy left (the process torque aside, which
    the rule then leaves alone), E = (J_p Omega^2 + sum J_race w_race^2) / 2. Made heat all in the part of
    smallest heat capacity C, it warms that part by at most E / C; a network with no heat coming in only cools
    towards ambient and its parts' temperatures stay between ambient and their present maximum (the maximum
    principle of a conduction network), so no peak temperature or run-away verdict can move by more than that
    bound. The heat already stored still spreads (the journal's into the inner ring), which moves a clearance
    by nanometres over a tail of seconds; simulating to standstill follows that only as far as standstill
    either. At the last deceleration the rotor turns n = Omega^2 / (4 pi a) more revolutions
    (a uniform deceleration a; the losses of a rolling contact hardly depend on speed at the end), which at
    each race's last window load P add n P^3 to the over-rolling sum against the sum so far (ISO 281:2007
    Eq. 1, P^-3 for ball bearings). The run ends when E / C is within ``coastdown.tail_temperature_rise``
    and that share within :data:`TAIL_DAMAGE_SHARE`; the time left is (|Omega| - stop_speed) / a.
    """
    coast = machine.coastdown
    if coast.tail_temperature_rise <= 0.0 or deceleration <= 0.0 or coast.process_torque > 0.0:
        return None
    y = session.y
    omega = abs(float(y[cm.OMEGA]))
    energy = 0.5 * machine.rotor.polar_inertia * omega ** 2
    for k, plane in enumerate(machine.planes):
        energy += 0.5 * plane.race_inertia * float(y[session.layout.plane(k) + cm.ROMEGA]) ** 2
    smallest = min(float(np.min(net.capacities)) for net in networks)
    rise = energy / smallest
    if rise > coast.tail_temperature_rise:
        return None
    revolutions = omega ** 2 / (4.0 * math.pi * deceleration)
    for booked in overrolling:
        done = sum(n * load ** 3 for n, load in booked)
        last = booked[-1][1] if booked else 0.0
        if revolutions * last ** 3 > TAIL_DAMAGE_SHARE * done:
            return None
    return {"from_rotor_speed_rpm": omega * 30.0 / math.pi, "spin_energy_J": energy,
            "temperature_rise_bound_K": rise, "revolutions_left": revolutions,
            "time_left_s": max(0.0, omega - coast.stop_speed) / deceleration}


def tail_note(tail: dict | None) -> str:
    """One sentence on a left-out tail (:func:`spent_tail`) for a report or the console; empty when none."""
    if not tail:
        return ""
    return (f"the last {tail['from_rotor_speed_rpm']:.0f} rpm were not simulated: the spin energy left "
            f"({tail['spin_energy_J']:.2g} J) could warm the smallest part by {tail['temperature_rise_bound_K']:.2g} K "
            f"at most and add {tail['revolutions_left']:.1f} revolutions; the {tail['time_left_s']:.1f} s to "
            "standstill are extrapolated at the last deceleration (coastdown.tail_temperature_rise)")


#: Damage per drop of the reduced runs against full dynamics over the first 30 s of every shipped example and the
#: blower's candidates, each plane, unbalance phase 0: lowest on the 7208 DB pair's non-drive end, whose small
#: rattle turns unstable over seconds (module docstring), highest on the QJ208 hybrid's drive end; every peak
#: temperature within 0.06 K. The paper rigs run these 30 s in full dynamics (their journals swing in a passage).
RATTLE_DAMAGE_RANGE = (-0.0356, 0.0321)
#: The same to standstill (or to a thermal run-away): lowest on the DB pair's non-drive end, highest on the hybrid's
#: drive end, every peak temperature within 0.17 K. The paper rigs' journals are chaotic: a run's damage per drop
#: scatters by 29 % between unbalance phases 1e-9 rad apart, in full dynamics too, and the reduced runs' mean over
#: fifteen phases lies +3.4 +- 12.4 % from full dynamics' (module docstring).
RATTLE_DAMAGE_RANGE_TO_STANDSTILL = (-0.0285, 0.0297)


def rattle_note(summary: dict) -> str:
    """One sentence for a report when the reduced model carried a rattling journal; empty when it did not.

    A rattle's windows restart from the motion a stretch froze, so a rattle that changes over seconds is not
    followed: the damage per drop, and the drops to failure it gives, are only as good as the range measured on
    the shipped examples, to standstill (:data:`RATTLE_DAMAGE_RANGE_TO_STANDSTILL`) for a run that went that far,
    over their first 30 s (:data:`RATTLE_DAMAGE_RANGE`) for a shorter one.
    """
    carried = summary.get("reduced_plane_states") or {}
    rattling = carried.get("rattling", 0)
    if not rattling:
        return ""
    whole = bool(summary.get("until_stop"))
    low, high = RATTLE_DAMAGE_RANGE_TO_STANDSTILL if whole else RATTLE_DAMAGE_RANGE
    span, temperatures = ("run to standstill", "0.2 K") if whole else ("over their first 30 s", "0.1 K")
    return (f"the reduced model carried a rattling journal in {rattling} of {sum(carried.values())} plane-stretches: "
            f"on the shipped examples {span} the reduced model's damage per drop lay {100 * low:+.1f} % "
            f"to {100 * high:+.1f} % off full dynamics' (temperatures within {temperatures}), lowest where the "
            "journal's motion grows over seconds, which the windows between stretches do not follow; a chaotic "
            "rattle's damage scatters by up to 29 % between runs in full dynamics too")


def _window_load(machine: Machine, k: int, window) -> float:
    """ISO 281 equivalent load on plane k's bearing over a window [N].

    Radial: the mean load of the bearing's varying radial load over the window (the cube mean of the ball set's
    reaction, which carries the race's weight too: :mod:`auxbearing.analysis.coastdown_life`); axial: the mean face
    force.
    """
    from auxbearing.analysis.coastdown_life import equivalent_load

    radial = window.bearing_load
    return equivalent_load(machine.planes[k].unit, radial, window.axial_force)


def _history(machine: Machine, rows: list[dict]) -> xr.Dataset:
    names = [p.name for p in machine.planes]
    t = np.array([r["time"] for r in rows])

    def stack(key):
        return np.array([r[key] for r in rows])

    data = {
        "mode": ("time", stack("mode").astype(np.int8), {"long_name": "0 full dynamics, 1 reduced model, 2 the drop",
                                                          "units": "1"}),
        "rotor_speed": ("time", stack("rotor_speed"), {"units": "rad/s", "long_name": "Rotor spin speed"}),
        "race_speed": (("time", "plane"), stack("race_speed"), {"units": "rad/s", "long_name": "Inner race speed"}),
        "temperature": (("time", "plane", "node"), stack("temperature") - 273.15,
                        {"units": "degC", "long_name": "Node temperature of the plane's thermal network"}),
        "radial_clearance": (("time", "plane"), stack("radial_clearance"),
                             {"units": "m", "long_name": "Journal/race radial clearance with thermal growth"}),
        "internal_clearance": (("time", "plane"), stack("internal_clearance"),
                               {"units": "m", "long_name": "Bearing diametral clearance with thermal growth"}),
        "energy_error": ("time", stack("energy_error"), {"units": "1", "long_name": "Energy audit, relative"}),
    }
    coords = {"time": ("time", t, {"units": "s", "long_name": "Time since the drop"}), "plane": ("plane", names),
              "node": ("node", list(NODE_NAMES))}
    ds = xr.Dataset(data, coords=coords)
    ds.attrs.update(title=f"Coast-down of {machine.name}", auxbearing_version=__version__,
                    model="full dynamics in windows and a reduced model on settled stretches "
                          "(auxbearing.analysis.coastdown)")
    return ds


def _json(obj) -> str:
    import json

    from auxbearing.common.io import to_jsonable

    return json.dumps(to_jsonable(obj))


#: Per-plane summary keys that come from the drop's stress history (null when the drop did not finish).
_LIFE_KEYS = ("damage_per_drop", "drop_damage", "coastdown_damage", "drops_to_failure", "drops_to_dent_limit",
              "dent_depth_per_drop_um", "governing", "allowed_drops", "drops_margin")


def _summary(machine, drop, session, limits, lives, verdict, reason, stopped_at, full_time, reduced_time, counts,
             wall, until_stop, backward: BackwardWhirl) -> dict:
    planes = []
    for k, plane in enumerate(machine.planes):
        life = lives[k]
        if life is None:  # the drop did not finish (run_coastdown)
            figures = dict.fromkeys(_LIFE_KEYS)
            figures["life_note"] = f"not computed: the drop ended with verdict {drop.summary['verdict']}"
        else:
            figures = {"life_note": _partial_life_note(verdict, session.t)} if stopped_at is None else {}
            figures |= {
                "damage_per_drop": life["damage_per_drop"], "drop_damage": life["drop_damage"],
                "coastdown_damage": life["coastdown_damage"], "drops_to_failure": life["drops_to_failure"],
                "drops_to_dent_limit": life["drops_to_dent_limit"], "dent_depth_per_drop_um": life["dent_depth_um"],
                "dent_assumption": life["dent_assumption"],
                "governing": life["governing"]["limit"], "allowed_drops": life["governing"]["allowed_drops"],
                "drops_margin": life["governing"].get("margin")}
        ran = life is not None  # a drop that did not finish started no coast-down: no heat, no clearance to show
        planes.append({
            "name": plane.name, "bearing": plane.unit.name,
            "max_temperature_C": {name: float(limits.max_temps[k][i] - 273.15) for i, name in enumerate(NODE_NAMES)}
            if ran else None,
            "min_radial_clearance_um": limits.min_radial[k] * 1e6 if ran else None,
            "min_internal_clearance_um": limits.min_internal[k] * 1e6 if ran else None,
            **figures, "required_drops": machine.life.required_drops,
            "dynamic_load_rating_N": dynamic_load_rating(plane.unit),
            "peak_contact_force_N": drop.summary["planes"][k]["peak_contact_force_N"],
            "peak_ball_stress_MPa": drop.summary["planes"][k]["peak_ball_stress_MPa"],
            "whirl_in_drop": drop.summary["planes"][k]["whirl"],
            # sustained backward whirl after the drop (coastdown_phases.BackwardWhirl): from when, for how long
            "backward_whirl_from_s": backward.onset[k], "backward_whirl_s": backward.seconds[k],
        })
    return {
        "machine": machine.name, "verdict": verdict, "reason": reason,
        "coastdown_time_s": stopped_at, "reached_standstill": stopped_at is not None, "until_stop": until_stop,
        "simulated_s": session.t, "full_dynamics_s": full_time, "reduced_model_s": reduced_time,
        "full_dynamics_steps": int(session.memory.steps[0] + session.memory.rejected[0]),
        "windows": counts["windows"], "reduced_stretches": counts["stretches"],
        "reduced_plane_states": counts["states"],
        "final_rotor_speed_rpm": float(session.y[cm.OMEGA]) * 30.0 / math.pi,
        "energy_balance_error": float(session.energy_error()), "wall_time_s": wall,
        "required_drops": machine.life.required_drops,
        "required_drops_source": required_drops_source(machine),
        "drop_verdict": drop.summary["verdict"], "planes": planes,
    }
