"""Compiled kernels that count no references: for the hot functions that allocate nothing.

numba keeps every array alive by reference counting: a compiled function that receives arrays, loose or
inside a struct, increments each one's count when it starts and decrements it at each exit, with atomic
instructions. The machine's right-hand side receives fifteen arrays (the state, its derivative and the
thirteen of :class:`~auxbearing.core.machine.Machine`) and runs some 10^5 times a drop; the observer receives
about forty once a step. Measured with ``perf`` on the paper rig's drop: half of the process's samples fell on
the two atomic instructions. Compiled without the counting, the same drop integrates in 0.068 s instead of
0.140 s and the blower's in 0.259 s instead of 0.391 s, to the same bits.

The counting is only needed where a function makes an array or takes one from a callee; a function compiled
here must do neither, anywhere below it:

* an allocation (``np.empty``, ``np.zeros``, ...) in such a function, or in a callee that numba compiles for it,
  does not compile (numba has no allocator without the reference counting);
* a callee compiled earlier with the counting and returning a new array would compile and leak that array
  on every call. None of the kernels decorated here calls one; ``tests/consistency/test_uncounted_kernels.py``
  runs every decorated kernel on the example machines and checks that numba's allocation count stays balanced.

Views (slices, rows of a 2-D array) need no counting: the arrays they view outlive the call.
"""

from __future__ import annotations

from numba import njit
from numba.core.cpu import CPUTargetOptions

#: The numba option that compiles a function without the reference counting: numba's ``_nrt`` target option, a
#: private one (its leading underscore). A numba without it compiles these kernels with the counting: slower,
#: the same numbers.
OPTION = {"_nrt": False} if hasattr(CPUTargetOptions, "_nrt") else {}


def uncounted(function=None, **options):
    """``njit(cache=True, ...)`` without reference counting (module docstring); options as for ``njit``.

    >>> import numpy as np
    >>> @uncounted(cache=False)
    ... def total(values):
    ...     s = 0.0
    ...     for v in values:
    ...         s += v
    ...     return s
    >>> total(np.arange(4.0))
    6.0
    """
    decorate = njit(**{"cache": True, **OPTION, **options})
    return decorate if function is None else decorate(function)
