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


def check() -> None:
    """Raise KeyboardInterrupt if an interrupt was requested (and perhaps swallowed) since :func:`watching`."""
    if _requested.is_set():
        raise KeyboardInterrupt


@contextmanager
def watching():
    """Install :func:`handler` for SIGINT for the duration (main thread only; elsewhere a no-op)."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    _requested.clear()
    previous = signal.signal(signal.SIGINT, handler)
    try:
        yield
    finally:
        signal.signal(signal.SIGINT, previous)
        _requested.clear()
