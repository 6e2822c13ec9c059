"""A backend without hardware or physics: trajectories end at once, or replay in scaled time.

Nothing runs in the background: a replaying trajectory is brought up to date whenever
the backend or one of its handles is looked at, from the time on the backend's clock
(inject a fake clock and the replay is fully deterministic). ``fail_after`` turns every
motion into a failure after that much trajectory time, to exercise failure paths.
"""

from __future__ import annotations

import math
import time
from collections.abc import Callable, Mapping
from dataclasses import dataclass

from taskrunner.backends.base import BaseBackend, TrajectoryExecution, check_option
from taskrunner.errors import BackendError
from taskrunner.types import JointState

__all__ = ["MockBackend", "MockOptions"]

_POLL_PERIOD = 0.002  # s: how often wait() looks at a replaying trajectory


@dataclass(frozen=True)
class MockOptions:
    """How :class:`MockBackend` plays trajectories.

    Attributes:
        speed: None: every trajectory jumps to its last sample in ``execute`` (its handle
            is done at once). A number > 0: trajectories replay at ``speed`` times real
            time (10: ten times faster), so they are "running" for a while.
        fail_after: if set, every trajectory longer than this many seconds of trajectory
            time (from its first sample) fails there: the joints stay where the
            trajectory is at that time, ``wait()`` raises
            :class:`~taskrunner.errors.BackendError`. Shorter ones succeed.
        start_tolerance: largest accepted distance (rad or m) between a trajectory's
            first sample and a joint's current position (``math.inf``: no check).
    """

    speed: float | None = None
    fail_after: float | None = None
    start_tolerance: float = 1e-3

    def __post_init__(self) -> None:
        check_option("speed", self.speed, lambda v: 0 < v < math.inf, "a positive number",
                     optional=True)
        check_option("fail_after", self.fail_after, lambda v: 0 <= v < math.inf,
                     "a number >= 0", optional=True)
        check_option("start_tolerance", self.start_tolerance, lambda v: v >= 0, "a number >= 0")


class MockBackend(BaseBackend):
    """Accepts any valid trajectory and reports the positions it commands.

    Args:
        joint_names: every joint driven.
        initial_positions: positions at start (rad or m); joints left out start at 0.
        options: see :class:`MockOptions`.
        clock: monotonic time source (s) of the scaled replay; a fake clock makes a
            replay independent of the machine's speed (``wait()`` still sleeps in real
            time, and times out if the fake clock does not move).

    Raises:
        ValueError: no joint, a repeated joint, a non-finite initial position.
        UnknownNameError: an initial position for a joint not in ``joint_names``.
    """

    def __init__(self, joint_names: tuple[str, ...] | list[str],
                 initial_positions: JointState | Mapping[str, float] | None = None,
                 options: MockOptions | None = None, *,
                 clock: Callable[[], float] = time.monotonic) -> None:
        self._options = options or MockOptions()
        super().__init__(joint_names, initial_positions,
                         start_tolerance=self._options.start_tolerance,
                         poll_period=None if self._options.speed is None else _POLL_PERIOD,
                         clock=clock)

    @property
    def options(self) -> MockOptions:
        """The options given at construction."""
        return self._options

    def _begin(self, execution: TrajectoryExecution) -> None:
        self._step(execution, math.inf if self._options.speed is None else 0.0)

    def _refresh(self) -> None:
        speed = self._options.speed
        if speed is None or not self._executions:
            return
        now = self._now()
        for execution in list(self._executions):
            self._step(execution, (now - execution.start_time) * speed)

    def _step(self, execution: TrajectoryExecution, elapsed: float) -> None:
        fail_after = self._options.fail_after
        if fail_after is not None and fail_after < execution.duration and elapsed >= fail_after:
            self._play_to(execution, fail_after)
            message = (f"simulated failure after {fail_after:.3f} s of "
                       f"{execution.duration:.3f} s (MockOptions.fail_after)")
            self._finish(execution, "failed", message, BackendError(message))
        else:
            self._play_to(execution, elapsed)
