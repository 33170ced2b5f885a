"""Ctrl-C that cannot be lost: the request is remembered and honoured at the next safe point.

Python turns SIGINT into a KeyboardInterrupt wherever the interpreter happens to be. When that is inside a
finaliser, a weakref callback or a library that catches everything (numba loading a cached kernel, a
Dask callback), CPython prints "Exception ignored" or the library drops it, and the run goes on to the end
as if nothing had been asked. The command line installs :func:`handler`, which remembers the request as
well as raising; long loops (the drop's integration chunks, the coast-down's windows, a campaign's batches)
call :func:`check`, which raises again if a request was swallowed.
"""

from __future__ import annotations

import signal
import threading
from contextlib import contextmanager

_requested = threading.Event()


def handler(signum, frame) -> None:
    """SIGINT/SIGTERM handler: remember the request, then interrupt as Python's own handler does."""
    _requested.set()
    raise KeyboardInterrupt


def requested() -> bool:
    """Whether an interrupt was asked for since :func:`watching` began.

    Its KeyboardInterrupt may have been turned into another exception by the library it hit (a Dask client's).
    """
    return _requested.is_set()


def check() -> None:
    """Raise KeyboardInterrupt if an interrupt was requested (and perhaps swallowed) since :func:`watching`."""
    if _requested.is_set():
        raise KeyboardInterrupt


@contextmanager
def _on_sigint(action):
    """``action`` as the SIGINT handler for the duration; yields False (and installs nothing) off the main thread."""
    if threading.current_thread() is not threading.main_thread():
        yield False
        return
    previous = signal.signal(signal.SIGINT, action)
    try:
        yield True
    finally:
        signal.signal(signal.SIGINT, previous)


@contextmanager
def watching():
    """Install :func:`handler` for SIGINT for the duration (main thread only; elsewhere a no-op)."""
    with _on_sigint(handler) as installed:
        if installed:
            _requested.clear()
        try:
            yield
        finally:
            if installed:
                _requested.clear()


@contextmanager
def deferred():
    """Hold Ctrl-C back for the duration (main thread only), then honour it when the block has finished.

    For a library that must not be interrupted halfway: a KeyboardInterrupt raised inside the NetCDF writer
    while it closes its file leaves the file manager's lock taken, and the close in its own clean-up then waits
    on that lock for ever (seen from the command line: a drop interrupted as it saved its results hung until
    killed). Writing a result file takes well under a second, so the interrupt waits that long.
    """
    held = threading.Event()

    def hold(signum, frame) -> None:
        held.set()
        _requested.set()

    with _on_sigint(hold):
        yield
    if held.is_set():
        raise KeyboardInterrupt
