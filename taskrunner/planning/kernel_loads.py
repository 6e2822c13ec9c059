"""Load cached numba kernels without numba's whole compiler set-up (planning workers).

A planning worker verifies every path it returns with compiled kernels
(:mod:`taskrunner.scene.sweep`, :mod:`taskrunner.scene.screen`, on the forward kinematics
of :mod:`taskrunner.collision.frames`) that numba keeps in its
on-disk cache. Before numba loads the first cached kernel of a process it refreshes its
CPU target: it imports and registers the typing and lowering implementations of
everything numba can compile (about 60 modules: unicode strings, typed containers,
NumPy's random generators and polynomials, datetimes …). A compilation needs those; a
load from the cache reads machine code that is already compiled and only links it. The
refresh took 0.10-0.15 s of CPU of a worker's ~0.45 s from its start to its first
answer, on the path to ``run-task``'s first motion.

:func:`lighter_cache_loads` has the cache loads of this process skip that refresh and
do what linking the cached code needs: numba's runtime (NRT) initialised, and its
symbols registered, as the refresh does first, and the hash secret symbols of
``numba.cpython.hashing`` (registered when that module is imported). Every other symbol
a kernel may call (numba's C helpers, the math functions, Python's exception classes)
is registered when the CPU target is created, before any load. A compilation (a kernel
not in the cache, or a new signature) still refreshes the target first, as numba always
does, so nothing compiled later misses an implementation. The kernels loaded are the
same machine code either way; only what is set up around them differs.

Used by the planning worker process only (:mod:`taskrunner.planning.worker`), never in a
program that merely imports taskrunner. When numba's cache loader is not the one this
was written for (another numba version changed it), nothing is changed.
"""

from __future__ import annotations

import importlib
from typing import Any

__all__ = ["lighter_cache_loads"]

# What numba's Cache.load_overload refers to (0.59-0.68): refresh the target, then load
# within the guard against spurious I/O errors. Any other body: leave numba alone.
_EXPECTED_NAMES = frozenset({"refresh", "_guard_against_spurious_io_errors", "_load_overload"})


def lighter_cache_loads() -> bool:
    """Make numba's cache loads in this process skip the target's refresh (see the
    module docstring).

    Returns:
        Whether the lighter load is installed now (False: numba is not installed, it was
        installed already, or numba's cache loader differs from the one expected).
    """
    try:
        from numba.core import caching
        from numba.core.runtime import nrt
    except ImportError:
        return False
    cache = caching.Cache
    original = cache.__dict__.get("load_overload")
    if original is None or getattr(original, "_lighter", False):
        return False
    code = getattr(original, "__code__", None)
    if code is None or frozenset(code.co_names) != _EXPECTED_NAMES or not all(
            hasattr(cache, name) for name in ("_load_overload", "_guard_against_spurious_io_errors")):
        return False
    if not hasattr(nrt, "rtsys") or not hasattr(nrt.rtsys, "initialize"):
        return False

    def load_overload(self: Any, sig: Any, target_context: Any) -> Any:
        # What linking cached code needs of the refresh: the runtime's symbols and
        # functions, and the hash secret symbols (registered by the module's import).
        nrt.rtsys.initialize(target_context)
        importlib.import_module("numba.cpython.hashing")
        with self._guard_against_spurious_io_errors():
            return self._load_overload(sig, target_context)
        return None  # the guard swallowed an I/O error: not loaded (as numba's own)

    load_overload._lighter = True  # type: ignore[attr-defined]
    load_overload.__wrapped__ = original  # type: ignore[attr-defined]
    load_overload.__doc__ = original.__doc__
    cache.load_overload = load_overload  # type: ignore[method-assign]
    return True
