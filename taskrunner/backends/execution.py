"""One trajectory in execution: the handle every backend returns, and its outcome.

The backend owns the motion; the handle only reads it. Looking at a handle (``done()``,
``status``, ``progress``, ``result``, ``wait()``) first lets the backend bring itself up
to date (a mock replaying in scaled time, a device answering a status request), so a
backend without a thread of its own still makes progress when polled.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Literal

import numpy as np

from taskrunner.errors import BackendError, ExecutionCancelledError
from taskrunner.types import JointState, JointTrajectory

if TYPE_CHECKING:
    from taskrunner.backends.base import BaseBackend

__all__ = ["ExecutionResult", "ExecutionStatus", "TrajectoryExecution", "sample_positions"]

ExecutionStatus = Literal["running", "succeeded", "cancelled", "failed"]


@dataclass(frozen=True)
class ExecutionResult:
    """How an execution ended.

    Attributes:
        status: ``"succeeded"``, ``"cancelled"`` or ``"failed"``.
        duration: wall-clock seconds from ``execute`` to the end (on the backend's clock).
        final: positions of the trajectory's joints at the end (rad or m), as reported.
        message: what happened, for a log or a tree's feedback message.
        data: what the backend measured, JSON-ready, kept in the run's record (a servo
            bus: ``tracking``, the tracking error per joint); empty when it measures none.
    """

    status: ExecutionStatus
    duration: float
    final: JointState
    message: str
    data: Mapping[str, object] = field(default_factory=dict)


def sample_positions(trajectory: JointTrajectory, t: float) -> np.ndarray:
    """Positions of ``trajectory`` at time ``t`` (s, the trajectory's own clock), linear
    between samples and held before the first and after the last one (a new array)."""
    times, positions = trajectory.times, trajectory.positions
    if t <= times[0]:
        return positions[0].copy()
    if t >= times[-1]:
        return positions[-1].copy()
    k = int(np.searchsorted(times, t, side="right")) - 1
    s = (t - times[k]) / (times[k + 1] - times[k])
    return positions[k] + s * (positions[k + 1] - positions[k])


class TrajectoryExecution:
    """The :class:`~taskrunner.backends.base.ExecutionHandle` of the backends here.

    Made by :meth:`BaseBackend.execute`; ``set_progress`` and ``complete`` are for the
    backend (under its lock), everything else is for the caller.

    Attributes:
        columns: index of each trajectory joint in the backend's joint order.
        start_time: when it started, in seconds on the backend's clock (the clock of
            :meth:`SimBackend.history`).
        duration: seconds from the trajectory's first sample to its last.
    """

    def __init__(self, backend: BaseBackend, trajectory: JointTrajectory,
                 columns: np.ndarray, start_time: float) -> None:
        self._backend = backend
        self._trajectory = trajectory
        self.columns = columns
        self.columns.setflags(write=False)
        self.start_time = start_time
        self.duration = float(trajectory.times[-1] - trajectory.times[0])
        self._progress = 0.0
        self._result: ExecutionResult | None = None
        self._error: BackendError | None = None
        self._finished = threading.Event()

    def __repr__(self) -> str:
        return (f"<TrajectoryExecution {list(self._trajectory.names)} "
                f"{self.status_now} {self._progress:.3f}/{self.duration:.3f} s>")

    # -- caller side ------------------------------------------------------------------

    @property
    def trajectory(self) -> JointTrajectory:
        """The trajectory as given to ``execute``."""
        return self._trajectory

    @property
    def status(self) -> ExecutionStatus:
        """``"running"``, ``"succeeded"``, ``"cancelled"`` or ``"failed"``."""
        self._backend._poll()
        return self.status_now

    @property
    def progress(self) -> float:
        """Seconds of the trajectory executed so far, from its first sample."""
        self._backend._poll()
        return self._progress

    @property
    def result(self) -> ExecutionResult | None:
        """The outcome once finished (whatever the status), None while running."""
        self._backend._poll()
        return self._result

    @property
    def error(self) -> BackendError | None:
        """What :meth:`wait` raises: None unless cancelled or failed."""
        self._backend._poll()
        return self._error

    def done(self) -> bool:
        """True once finished, whatever the status (never blocks for the motion)."""
        self._backend._poll()
        return self._finished.is_set()

    def wait(self, timeout: float | None = None) -> ExecutionResult:
        """Block until finished, ``timeout`` seconds at most (None: no limit).

        Raises:
            TimeoutError: still running after ``timeout`` s (the motion goes on).
            ExecutionCancelledError: cancelled (the handle's or the backend's ``stop``).
            BackendError: the motion failed (the backend's own error class).
        """
        deadline = None if timeout is None else time.monotonic() + max(timeout, 0.0)
        period = self._backend._poll_period
        while True:
            self._backend._poll()
            if self._finished.is_set():
                break
            remaining = None if deadline is None else deadline - time.monotonic()
            if remaining is not None and remaining <= 0:
                raise TimeoutError(
                    f"trajectory still running after {timeout} s ({self._progress:.3f} s "
                    f"of {self.duration:.3f} s done)")
            if period is None:
                self._finished.wait(remaining)
            else:
                self._finished.wait(period if remaining is None else min(period, remaining))
        if self._error is not None:
            raise self._error.with_traceback(None)
        assert self._result is not None
        return self._result

    def cancel(self) -> None:
        """Stop the motion where it is, now; :meth:`wait` then raises
        :class:`~taskrunner.errors.ExecutionCancelledError` (no-op once finished)."""
        backend = self._backend
        with backend._lock:
            backend._refresh()
            backend._cancel(self, "cancelled")

    # -- backend side (under the backend's lock) ---------------------------------------

    @property
    def finished(self) -> bool:
        """True once finished, without polling the backend."""
        return self._finished.is_set()

    @property
    def status_now(self) -> ExecutionStatus:
        """:attr:`status` without polling the backend."""
        return "running" if self._result is None else self._result.status

    @property
    def progress_now(self) -> float:
        """:attr:`progress` without polling the backend."""
        return self._progress

    def set_progress(self, elapsed: float) -> None:
        """Record ``elapsed`` seconds of the trajectory executed."""
        self._progress = float(elapsed)

    def complete(self, result: ExecutionResult, error: BackendError | None = None) -> None:
        """End the execution (once; later calls are ignored). ``error`` is what
        :meth:`wait` raises; by default made from the status and message."""
        if self._finished.is_set():
            return
        if error is None and result.status == "cancelled":
            error = ExecutionCancelledError(result.message)
        elif error is None and result.status == "failed":
            error = BackendError(result.message)
        self._result, self._error = result, error
        self._finished.set()
