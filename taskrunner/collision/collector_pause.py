"""Python's cyclic garbage collector paused while numba compiles a kernel.

numba's compiler allocates millions of short-lived objects (IR nodes, types, llvmlite
instructions); each allocation burst triggers a collection, and every third-generation
one walks the whole heap of the process (a scene's robot models, coal's geometry, the
planner). On the servo arm's first verification and screen scan
(``benchmarks/kernel_compile.py``) that was 0.7-0.85 s of the 4.8 s of CPU the kernels'
first compilation took. Paused, the compilation's garbage waits for the first collection
after it (the process's peak memory about 40 MB higher while it compiles).

The pause is a listener of numba's ``numba:compiler_lock`` event (its public event API,
:mod:`numba.core.event`): the time numba holds its compiler lock, which it takes to compile
a kernel, with its one-time set-up of the compiler before the first, and to load one from
the disk cache (a short pause), never to call one. A kernel's callees compile inside its
own hold of the lock (nested events); threads wait for it. The collector is resumed when
the outermost hold ends, and only if it was enabled when it began.
"""

from __future__ import annotations

import gc
import threading

from numba.core import event

__all__ = ["CollectorPause", "pause_collector_while_compiling"]


class CollectorPause(event.Listener):
    """Disables the collector from the start of the outermost hold of numba's compiler lock
    to its end (the event starts before a thread waits for the lock: counted under a lock
    of its own)."""

    def __init__(self) -> None:
        self._lock = threading.Lock()
        self._depth = 0
        self._resume = False

    def on_start(self, event: event.Event) -> None:
        with self._lock:
            if self._depth == 0:
                self._resume = gc.isenabled()
                gc.disable()
            self._depth += 1

    def on_end(self, event: event.Event) -> None:
        with self._lock:
            self._depth -= 1
            if self._depth == 0 and self._resume:
                gc.enable()


_LISTENER: CollectorPause | None = None


def pause_collector_while_compiling() -> None:
    """Register the process's one :class:`CollectorPause` (again: nothing happens)."""
    global _LISTENER
    if _LISTENER is None:
        _LISTENER = CollectorPause()
        event.register("numba:compiler_lock", _LISTENER)
