"""The first drop after an install: compile the drop kernel on two cores instead of one.

From an empty kernel cache, the drop's integrator (:func:`auxbearing.core.drive.advance`) compiles its two
largest callees one after the other: the machine's right-hand side (:func:`auxbearing.core.machine.rhs`, about
21 s on the 2-core reference machine) and the observer (:func:`auxbearing.core.watch.observe`, about 31 s).
Neither is inlined into the integrator, and both are cached on disk. So a helper process compiles the observer
into the shared cache while this one compiles the right-hand side and the small kernels a drop's summary uses;
the integrator then finds both callees in the cache (about 8 s for what is left: numba links both into it and
optimises them once more, since the generic integrator is inlined into it), and the helper goes on to the outputs'
kernels. The default drop from the command line, from an empty cache on the 2-core machine: 51.7-51.8 s
against 104.8-110.4 s without the helper, with less CPU (84-85 s against 95-99 s; README, "Compiled kernels").

It runs once per installation and kernel signature (the shipped examples share one; another plane count makes
another): a marker beside the cached kernels says it has been done, and a lock makes a second process that needs
the same kernel at the same time (a verification's other worker) wait for it and load it from the cache, instead
of compiling it again on the same cores. Anything that goes wrong in the helper only costs time: the integrator
then compiles what is missing itself, as it always did.
"""

from __future__ import annotations

import contextlib
import hashlib
import os
import pickle
import select
import subprocess
import sys
import tempfile
import time

import numba
import numpy as np
from numba import typeof

from auxbearing.common.errors import InputError
from auxbearing.core import cache_folder, probes
from auxbearing.core import machine as cm
from auxbearing.core import watch as cw

#: Longest wait for the helper [s]: about ten times its compile on the 2-core machine. It decides only which process
#: compiles the observer, never a result; a helper past it is stopped and this process compiles on its own.
HELPER_PATIENCE = 300.0
#: How often a process waiting for another's compilation looks whether it has ended [s].
LOCK_POLL = 0.2
#: Environment variable: 0 compiles in this process only, as numba does on its own; 1 (the default) uses the helper.
ENV_SWITCH = "AUXBEARING_COMPILE_HELPER"


def helper_switched_on() -> bool:
    """The environment's :data:`ENV_SWITCH`: unset or 1 on, 0 off; any other value is bad input.

    >>> helper_switched_on() in (True, False)
    True
    """
    value = os.environ.get(ENV_SWITCH, "1")
    if value.strip() not in ("0", "1"):
        raise InputError.for_field(ENV_SWITCH, value, "must be 0 (compile in one process, as numba does on its own) "
                                   "or 1 (the default: a helper process compiles beside the first drop)")
    return value.strip() == "1"


def _marker(model) -> str:
    """The file that says this model's drop kernel was compiled, named after the types it is compiled for."""
    digest = hashlib.sha256(repr(_observe_types(model)).encode()).hexdigest()[:16]
    return os.path.join(cache_folder(), f"drop-kernel-{digest}.compiled")


def first_call_state(model):
    """(state, observer memory) of ``model`` at its start: what its drop kernel is first called and typed with."""
    y = model.y0.copy()
    return y, cw.new_watch(y.size, len(model.machine.planes.active), 1.0, 1, model.energy0)


def _observe_types(model) -> tuple:
    y, watch = first_call_state(model)
    return tuple(typeof(a) for a in (0.0, 1e-7, y, y.copy(), np.empty((5, y.size)), model.machine, watch))


def _rhs_types(model) -> tuple:
    y, _ = first_call_state(model)
    return tuple(typeof(a) for a in (0.0, y, model.machine, np.empty(y.size)))


def _summary_kernels() -> None:
    """The ball set's state and the Hertz ellipticity, which a drop's summary compiles after the run."""
    from auxbearing.bearings.ballset import ballset_params, ballset_state
    from auxbearing.bearings.catalogue import get_bearing
    from auxbearing.core.hertz import ellipticity

    ballset_state([0.0, 1e-6, 0.0, 0.0, 0.0], ballset_params(get_bearing("QJ202")))
    ellipticity(0.9)


def _output_kernels(model) -> None:
    """The kernels a drop's outputs run on the whole trajectory, compiled on a state of this machine."""
    y = model.y0.copy()
    probes.series(np.zeros((1, y.size)), model.machine, True)
    cm.energy_balance(y, model.machine, model.energy0)


@contextlib.contextmanager
def _first_in_line(model):
    """True for the one process that compiles side by side; False where a marker, a lock or the switch says no."""
    try:
        import fcntl
    except ImportError:  # not on POSIX: numba compiles on its own, on one core
        fcntl = None
    if fcntl is None or numba.config.DISABLE_JIT or not helper_switched_on() or os.path.exists(_marker(model)):
        yield False
        return
    try:
        os.makedirs(cache_folder(), exist_ok=True)
        lock = open(_marker(model) + ".lock", "w")
    except OSError:  # a cache folder that cannot be written: numba cannot share kernels through it either
        yield False
        return
    with lock:
        try:
            fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except OSError:
            # Another process (a verification's other worker) is compiling the same kernel: wait for it, then
            # load from the cache rather than compile it a second time on the same two cores (past the patience,
            # compile here: the wait decides only who compiles).
            _wait_for_lock(lock, fcntl)
            yield False
            return
        yield not os.path.exists(_marker(model))


def _wait_for_lock(lock, fcntl) -> bool:
    """Take ``lock`` once its holder lets it go, polling for at most :data:`HELPER_PATIENCE`; whether it was taken."""
    waited = 0.0
    while waited < HELPER_PATIENCE:
        try:
            fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
            return True
        except OSError:
            time.sleep(LOCK_POLL)
            waited += LOCK_POLL
    return False


def compile_side_by_side(model, warm_up) -> None:
    """Run ``warm_up(model)`` (the integrator's first call), with its callees compiled on two cores if still cold."""
    with _first_in_line(model) as first:
        if not first:
            warm_up(model)
            return
        helper, blob = _start_helper(model)
        try:
            cm.rhs.compile(_rhs_types(model))
            _summary_kernels()
            if helper is not None and not _heard_from(helper):
                helper.kill()  # a helper that neither reports nor ends: the integrator compiles the observer itself
            warm_up(model)
            if helper is not None:
                with contextlib.suppress(subprocess.TimeoutExpired):
                    helper.communicate(timeout=HELPER_PATIENCE)  # the outputs' kernels, compiled meanwhile
        finally:
            if helper is not None and helper.poll() is None:
                helper.kill()  # stopped by an error or Ctrl-C: numba's cache files are written whole or not at all
                helper.wait()
            if blob is not None:
                with contextlib.suppress(OSError):
                    os.remove(blob)
        with contextlib.suppress(OSError), open(_marker(model), "w") as done:
            done.write(f"the drop kernel was compiled side by side once for {_observe_types(model)}\n")


def _heard_from(helper) -> bool:
    """Whether the helper reported the observer compiled, or ended, within :data:`HELPER_PATIENCE`."""
    ready, _, _ = select.select([helper.stdout], [], [], HELPER_PATIENCE)
    if ready:
        helper.stdout.readline()  # the observer is in the cache (or the helper ended: compiled by the integrator)
    return bool(ready)


def _start_helper(model):
    """A Python process compiling the observer then the outputs' kernels for ``model``'s types, and its input file.

    (None, None) when it cannot be started; the integrator then compiles the observer itself.
    """
    blob = None
    try:
        handle, blob = tempfile.mkstemp(suffix=".pickle", prefix="auxbearing-model-")
        with os.fdopen(handle, "wb") as out:
            pickle.dump(model, out)
        helper = subprocess.Popen([sys.executable, "-m", __name__, blob], stdout=subprocess.PIPE,
                                  stderr=subprocess.DEVNULL, stdin=subprocess.DEVNULL, text=True)
    except (OSError, pickle.PicklingError):
        if blob is not None:
            with contextlib.suppress(OSError):
                os.remove(blob)
        return None, None
    return helper, blob


def _helper_main(blob: str) -> None:
    with open(blob, "rb") as data:
        model = pickle.load(data)
    cw.observe.compile(_observe_types(model))
    print("observer compiled", flush=True)
    _output_kernels(model)


if __name__ == "__main__":
    _helper_main(sys.argv[1])
