"""The time limit of one IK call, when it has one: CPU time of the searching thread, capped
in wall time.

An IK call is bounded by its attempts and iterations; a time limit is an explicit option
(:attr:`~taskrunner.kinematics.IkOptions.timeout`), for callers that prefer an answer
by a time to the same answer on every machine. Without one the search runs with
:meth:`Deadline.never`, which never passes.

A search's time limit is meant to bound the work it does. Measured on the wall clock, it
also counts the time the process waits for a CPU: on a loaded machine (2 cores, 6 busy
processes: each gets a third of a core, in slices of several ms), about 4 % of 0.2 ms
searches were cut at 5 ms having searched for a fraction of that, and whether a target
was solved depended on the load. A
:class:`Deadline` lets the search run while the thread's own CPU time is within the
timeout, and never longer than ``WALL_CAP`` × timeout on the wall clock.

It is cheap where it matters: the search loop compares ``time.perf_counter()`` with
:attr:`Deadline.wall` (0.2 µs); the thread's CPU time (a system call, ~2 µs here) is read
only when that wall time has passed, to move it on by the CPU time left.
"""

from __future__ import annotations

import math
import time

__all__ = ["WALL_CAP", "Deadline"]

WALL_CAP = 4.0
"""A call ends by ``WALL_CAP × timeout`` after it started, whatever its CPU time."""


class Deadline:
    """The budget of one call.

    Args:
        timeout: seconds of the thread's CPU time the call may use.

    Attributes:
        wall: ``time.perf_counter()`` value before which the budget is certainly not
            used up (the search's fast check); :meth:`passed` moves it on.
    """

    __slots__ = ("_cap", "_cpu_start", "_timeout", "wall")

    def __init__(self, timeout: float) -> None:
        now = time.perf_counter()
        self.wall = now + timeout
        self._cap = now + WALL_CAP * timeout
        self._cpu_start = time.thread_time()
        self._timeout = timeout

    @classmethod
    def never(cls) -> Deadline:
        """A deadline that never passes: the call is bounded by its attempts alone."""
        return cls(math.inf)

    def passed(self) -> bool:
        """Whether the budget is used up (CPU time, or the wall-clock cap)."""
        now = time.perf_counter()
        if now <= self.wall:
            return False
        left = self._timeout - (time.thread_time() - self._cpu_start)
        if left <= 0.0 or now >= self._cap:
            return True
        self.wall = min(now + left, self._cap)
        return False

    def exclude(self, wall: float, cpu: float) -> None:
        """Leave out ``wall`` seconds of wall time and ``cpu`` of CPU time spent on
        something not charged to the call (the solver's one-time seed table)."""
        self.wall += wall
        self._cap += wall
        self._cpu_start += cpu
