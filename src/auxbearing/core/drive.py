"""The compiled driver of a machine run: the generic integrator on the machine and its observer.

Functions passed as arguments are named as module attributes (``machine.rhs``): numba 0.68 caches
the caller then, but not when they are plain global names (it keeps a pointer to the Python object).
"""

from __future__ import annotations

from numba import njit

from auxbearing.core import machine, spin, watch
from auxbearing.core.integrate import dopri5
from auxbearing.core.rk4 import rk4


@njit(cache=True)
def advance(m, w, y, t_end, settings, memory, grid):
    """DOPRI5 on the machine (:func:`auxbearing.core.machine.rhs`) with :func:`~auxbearing.core.watch.observe`.

    Arguments as :func:`auxbearing.core.integrate.dopri5`; returns its status.
    """
    return dopri5(machine.rhs, watch.observe, m, w, y, t_end, settings, memory, grid)


@njit(cache=True)
def advance_window(m, w, y, t_end, settings, memory, grid):
    """The classical RK4 (:func:`auxbearing.core.rk4.rk4`) on the machine with its observer, as :func:`advance`.

    For the coast-down's full-dynamics windows, whose steps sit on the stability bound (:mod:`auxbearing.core.rk4`).
    """
    return rk4(machine.rhs, watch.observe, m, w, y, t_end, settings, memory, grid)


@njit(cache=True)
def advance_spin(m, obs, y, t_end, settings, memory, grid):
    """DOPRI5 on the coast-down's reduced model (:func:`auxbearing.core.spin.rhs` and its observer)."""
    return dopri5(spin.rhs, spin.observe, m, obs, y, t_end, settings, memory, grid)
