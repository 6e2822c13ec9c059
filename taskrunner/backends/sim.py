"""A simulated joint controller: plays trajectories in (scaled) real time on a thread.

One thread per backend ticks at ``rate_hz`` while anything moves (it sleeps otherwise):
at each tick every running trajectory puts its joints where it is at that time (linear
between samples), a finished one ends as succeeded, and the reported positions are
recorded in a bounded history. A cancelled trajectory leaves its joints where the last
tick put them. Units: rad (m), s, Hz.
"""

from __future__ import annotations

import math
import threading
from collections import deque
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np

from taskrunner.backends.base import BaseBackend, TrajectoryExecution, check_option
from taskrunner.errors import ArgumentError, BackendError
from taskrunner.types import JointState

__all__ = ["SimBackend", "SimOptions"]

_JOIN_TIMEOUT = 5.0  # s: close() waits this long for the controller thread


@dataclass(frozen=True)
class SimOptions:
    """How :class:`SimBackend` plays trajectories.

    Attributes:
        speed: trajectory seconds per wall-clock second (2: twice as fast as planned).
        rate_hz: controller rate (Hz): how often positions are updated and reported.
        keep_history: record the reported positions at every tick while a trajectory
            runs (see :meth:`SimBackend.history`).
        history_limit: most ticks kept (the oldest are dropped); 60 000 is 10 minutes
            of motion at 100 Hz.
        start_tolerance: largest accepted distance (rad or m) between a trajectory's
            first sample and a joint's current position (``math.inf``: no check).
    """

    speed: float = 1.0
    rate_hz: float = 100.0
    keep_history: bool = True
    history_limit: int = 60_000
    start_tolerance: float = 1e-3

    def __post_init__(self) -> None:
        check_option("speed", self.speed, lambda v: 0 < v < math.inf, "a positive number")
        check_option("rate_hz", self.rate_hz, lambda v: 0 < v <= 10_000, "in (0, 10000]")
        if not isinstance(self.keep_history, bool):
            raise TypeError(f"'keep_history' must be a bool (got {self.keep_history!r})")
        if not (isinstance(self.history_limit, int) and not isinstance(self.history_limit, bool)
                and self.history_limit > 0):
            raise ArgumentError(f"'history_limit' must be a positive integer "
                             f"(got {self.history_limit!r})")
        check_option("start_tolerance", self.start_tolerance, lambda v: v >= 0, "a number >= 0")


class SimBackend(BaseBackend):
    """Plays trajectories in real time scaled by ``speed``, at a controller rate.

    The controller thread starts here and ends in :meth:`close` (use the backend as a
    context manager). It is a daemon thread, so a backend left open does not keep the
    interpreter alive.

    Args:
        joint_names: every joint driven.
        initial_positions: positions at start (rad or m); joints left out start at 0.
        options: see :class:`SimOptions`.

    Raises:
        ValueError: no joint, a repeated joint, a non-finite initial position.
        UnknownNameError: an initial position for a joint not in ``joint_names``.
    """

    def __init__(self, joint_names: tuple[str, ...] | list[str],
                 initial_positions: JointState | Mapping[str, float] | None = None,
                 options: SimOptions | None = None) -> None:
        self._options = options or SimOptions()
        super().__init__(joint_names, initial_positions,
                         start_tolerance=self._options.start_tolerance)
        self._wake = threading.Condition(self._lock)
        self._history: deque[tuple[float, np.ndarray]] = deque(
            maxlen=self._options.history_limit)
        self._thread = threading.Thread(target=self._run, name=f"SimBackend-{id(self):x}",
                                        daemon=True)
        self._thread.start()

    @property
    def options(self) -> SimOptions:
        """The options given at construction."""
        return self._options

    @property
    def running(self) -> bool:
        """True while the controller thread is alive."""
        return self._thread.is_alive()

    def history(self) -> list[tuple[float, JointState]]:
        """The reported positions of every joint at each tick while a trajectory ran:
        ``(time, state)``, time in seconds on the backend's clock (since its creation,
        the clock of :attr:`TrajectoryExecution.start_time`), oldest first."""
        with self._lock:
            return [(t, JointState(self._names, q)) for t, q in self._history]

    def clear_history(self) -> None:
        """Forget the recorded ticks."""
        with self._lock:
            self._history.clear()

    def close(self) -> None:
        """Stop every motion and end the controller thread (idempotent)."""
        with self._lock:
            super().close()
            self._wake.notify_all()
        if threading.current_thread() is not self._thread:
            self._thread.join(_JOIN_TIMEOUT)

    def _begin(self, execution: TrajectoryExecution) -> None:
        self._wake.notify_all()

    def _run(self) -> None:
        period = 1.0 / self._options.rate_hz
        with self._lock:
            try:
                next_tick: float | None = None
                while not self._closed:
                    if not self._executions:
                        next_tick = None
                        self._wake.wait()
                        continue
                    now = self._now()
                    if next_tick is None or now - next_tick > period:
                        next_tick = now  # first tick, or late by a whole period: resync
                    self._tick(now)
                    next_tick += period
                    self._wake.wait_for(lambda: self._closed, max(0.0, next_tick - self._now()))
            except Exception as exc:  # no handle may wait forever
                self._closed = True
                self._closed_reason = f"stopped: its controller thread died ({exc!r})"
                for execution in list(self._executions):
                    message = f"simulated controller died: {exc!r}"
                    self._finish(execution, "failed", message, BackendError(message))

    def _tick(self, now: float) -> None:
        speed = self._options.speed
        for execution in list(self._executions):
            self._play_to(execution, (now - execution.start_time) * speed)
        if self._options.keep_history:
            self._history.append((now, self._positions.copy()))
