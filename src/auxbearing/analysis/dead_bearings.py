"""A run carried on without the magnetic bearings that have failed for good: drops and coast-down windows.

The shipped machines' magnetic bearings fail at the drop and never come back. From then on they neither push
nor change (:func:`auxbearing.core.amb.dead`), and the right-hand side skips them, but their states still ride
in the state vector: each step of a coast-down's full-dynamics window carries them through the integrator's
stages, its error norm and its dense output (15 of the blower's 51 mechanical and controller states).
:func:`without_dead_bearings` repacks the machine without them and moves the run's state across, name by name,
so that the windows integrate only what still moves: the blower's coast-down to standstill 12.93 -> 12.12 s, the
compressor's to its run-away 18.62 -> 17.64 s (best of two, alternated), to the bit the same runs. A drop whose
bearings fail at its start (:func:`auxbearing.analysis.drop.integrate_machine`) runs on :func:`lighter_model` too
and is handed back in the machine's own layout (:func:`restored`): a blower drop 0.216 -> 0.212 s, a lean one
(a campaign's) 0.134 -> 0.127 s, the compressor's 0.342 -> 0.333 s, the same grid to the bit.

An elastic rotor keeps the modal basis it ran with: with the ``static_correction`` reduction the basis carries
correction vectors for forces at the stations' nodes, the bearings' among them, and rebuilt without those it
would be another rotor (:func:`_same_rotor` checks the packed modes are the same).

What the move keeps:

* every other state and ledger entry, unchanged;
* the energy audit: the bearings' ledger entries (the work their forces did on the rotor before they failed)
  leave the accounted side, so they leave the start energy too;
* the integrator's memory, the first stage it kept (first same as last) moved across like the state;
* the step control: the integrator's error norm is a root mean square over the states with a finite absolute
  tolerance (Hairer, Norsett & Wanner 1993, Eq. II.4.11). Bearings that fail at the drop are out of it already
  (:func:`auxbearing.machine.pack.pack` gives their states no finite tolerance), so the windows take the steps
  they took with the bearings in the vector; where they were in it (a levitated start), nothing is left out.
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from auxbearing.core import amb as kernel
from auxbearing.core import integrate as ig
from auxbearing.core import machine as cm
from auxbearing.machine.model import Machine
from auxbearing.machine.pack import KernelModel, pack


def dead_for_good(model: KernelModel, t: float) -> bool:
    """Whether the machine has magnetic bearings and every axis of them is dead at ``t`` and cannot come back."""
    params = model.stations[cm.STATION_KINDS.index(cm.amb)]
    if len(params.values) == 0:
        return False
    for row in params.values:
        fails = (kernel.P_FAIL_X,) if row[kernel.P_AXIAL] > 0.0 else (kernel.P_FAIL_X, kernel.P_FAIL_Y)
        if math.isfinite(row[kernel.P_RESTORE]) or not all(kernel.dead.py_func(row, t, row[f]) for f in fails):
            return False
    return True


def _same_rotor(model: KernelModel, repacked: KernelModel) -> bool:
    """Whether the repacked rotor is the one that ran: the same modal model and every state but the bearings'."""
    if not all(np.array_equal(a, b) for a, b in zip(model.modes, repacked.modes, strict=True)):
        return False
    kept = set(repacked.layout.names)
    return all(name in kept for name in model.layout.names if not name.startswith("amb_"))


def lighter_model(machine: Machine, model: KernelModel, t: float) -> KernelModel | None:
    """The machine packed without its magnetic bearings, where that runs the same rotor the same way from ``t``.

    None when there is nothing to leave out: no magnetic bearings, one that may still act (:func:`dead_for_good`),
    a scenario (its events may name the bearings), bearings whose states steer the step (a levitated start), or a
    rotor that would not be the same (:func:`_same_rotor`). The settings are ``model``'s, the tolerances per state
    the lighter layout's.
    """
    if machine.scenario is not None or not dead_for_good(model, t):
        return None
    lighter = replace(machine, stations=tuple(s for s in machine.stations if getattr(s, "KIND", "") != "amb"))
    # the rotor as it ran: an elastic rotor's basis carries static corrections at the bearings' nodes too (the
    # compressor: 18 modes with them, 12 without), kept here so that the lighter machine is the same rotor
    lighter.__dict__["_modal"] = machine.modal()
    repacked = pack(lighter)
    if not _same_rotor(model, repacked):
        return None
    if int(np.isfinite(model.settings.atol).sum()) != int(np.isfinite(repacked.settings.atol).sum()):
        return None  # the bearings' states steered the step: leaving them would change it
    return repacked._replace(settings=model.settings._replace(atol=repacked.settings.atol))


def restored(full: KernelModel, light: KernelModel, values: np.ndarray, frozen: np.ndarray) -> np.ndarray:
    """Arrays of the lighter layout (states along the last axis) back in the full one, the bearings' from ``frozen``.

    The bearings that :func:`lighter_model` left out are frozen at their values when they died (their start, for
    a drop), so their columns are ``frozen``'s (the full layout's values then) at every row.
    """
    where = {name: i for i, name in enumerate(full.layout.names)}
    out = np.empty((*values.shape[:-1], full.layout.size))
    out[...] = frozen
    out[..., [where[name] for name in light.layout.names]] = values
    return out


def without_dead_bearings(machine: Machine, model: KernelModel, y: np.ndarray, memory: ig.Memory, e0: float,
                          t: float) -> tuple[KernelModel, np.ndarray, ig.Memory, float] | None:
    """The packed model, state, integrator memory and start energy without the dead bearings (None: as they are).

    See :func:`lighter_model` for when there is nothing to leave out.
    """
    repacked = lighter_model(machine, model, t)
    if repacked is None:
        return None
    old, new = model.layout, repacked.layout
    where = {name: i for i, name in enumerate(old.names)}
    moved = np.array([y[where[name]] for name in new.names])
    kept = set(new.names)
    # the bearings' ledger (work of their forces) leaves the accounted energy: it leaves the energy in as well
    left = sum(float(y[i]) for i, name in enumerate(old.names) if i >= old.ledger_at and name not in kept)
    carried = ig.new_memory(float(memory.t[0]), float(memory.h[0]), new.size)
    for field in ("err_prev", "rejected_last", "steps", "rejected", "evaluations", "next_output"):
        getattr(carried, field)[...] = getattr(memory, field)
    # the first stage the integrator kept (first same as last) moves across with its states, so the next step
    # starts from the slope it would have started from
    carried.derivative[...] = [memory.derivative[where[name]] for name in new.names]
    return repacked, moved, carried, e0 - left
