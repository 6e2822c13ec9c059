"""Task time: the clock a task's ``timeout:`` counts, the same on every backend.

A run's wall-clock time depends on where its motions go: the mock backend ends a motion
at once, the simulator plays it ``speed`` times faster than planned, real servos take
the planned time. A time limit in a task file means the task's own time, so
:class:`TaskClock` counts

- each motion at its trajectory time (the seconds of trajectory executed, whatever the
  backend's speed; a motion the mock ends at once counts its whole duration); while
  several motions run at once, the one furthest along sets the pace;
- everything else (planning, scene edits, ``wait`` steps) at wall-clock time.

Its :meth:`TaskClock.motion_time` is the part of it during which a motion ran: the
cell's own time, the same on any machine however long planning took (what a task's
``motion_time`` expectation bounds).

The same task so gets the same verdict on mock, on the simulator at any speed and on the
robot, as long as its planning time (the only wall-clock part that differs between
machines) is small against the margin. Units: seconds.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable

from taskrunner.backends.base import ExecutionHandle

__all__ = ["TaskClock"]


class TaskClock:
    """Task time in seconds since the clock was made (see the module docstring).

    Args:
        wall: the wall-clock source (s), monotonic.
    """

    def __init__(self, wall: Callable[[], float] = time.monotonic) -> None:
        self._wall = wall
        self._last_wall = wall()
        self._now = 0.0
        self._moving = 0.0  # of _now: while a motion ran
        self._motions: dict[int, tuple[ExecutionHandle, float]] = {}  # id -> (handle, progress)
        self._lock = threading.Lock()

    def track(self, handle: ExecutionHandle, since: float | None = None) -> float:
        """Count ``handle``'s motion from its first sample on (call right after execute);
        returns when it started on this clock (s).

        A backend with a thread of its own may have played the motion on before
        ``execute`` returned (a loaded machine, a fast simulator): that progress is counted
        once, as time since ``since`` (the clock's reading just before ``execute``;
        default: now, as for a backend that ends a motion at once), not again after, so
        every motion's start and end keep their place against the others' on this clock.
        """
        with self._lock:
            self._advance()
            before = self._now if since is None else since
            progress = float(handle.progress)
            now = max(self._now, before + progress)
            self._moving += now - self._now  # progress made before execute returned
            self._now = now
            self._motions[id(handle)] = (handle, progress)
            return self._now - progress

    def now(self) -> float:
        """Task time (s) since the clock was made."""
        with self._lock:
            self._advance()
            return self._now

    def motion_time(self) -> float:
        """Task time (s) during which at least one motion ran, since the clock was made
        (several at once counted once, by the one furthest along)."""
        with self._lock:
            self._advance()
            return self._moving

    def update(self) -> None:
        """Account for the motions up to now (a leaf calls it when it sees its motion end,
        so the wall-clock time after the end is counted from there on)."""
        with self._lock:
            self._advance()

    def _advance(self) -> None:
        wall = self._wall()
        wall_step, self._last_wall = wall - self._last_wall, wall
        if not self._motions:
            self._now += wall_step
            return
        motion_step = 0.0
        for key, (handle, seen) in list(self._motions.items()):
            done = handle.done()  # read before progress: a motion done now has its final one
            progress = max(seen, float(handle.progress))
            motion_step = max(motion_step, progress - seen)
            if done:
                del self._motions[key]
            else:
                self._motions[key] = (handle, progress)
        # When the last motion ended within this step, the rest of the step was wall time:
        # counting the longer of the two is short by at most the motion's own wall time.
        self._now += motion_step if self._motions else max(motion_step, wall_step)
        self._moving += motion_step
