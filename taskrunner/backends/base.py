"""The execution-backend protocol and the parts every backend shares.

A backend drives named joints. ``execute(trajectory)`` checks the trajectory, claims its
joints and returns an :class:`ExecutionHandle` at once; the motion goes on in the
background (a controller thread, a device) or is brought up to date whenever someone
looks (the handle's ``done()``, ``status``, ``wait()``, the backend's ``joint_state()``),
so a behaviour-tree leaf can start a motion in ``initialise()``, poll it in ``update()``
and cancel it in ``terminate()``. Failures reach the caller through the handle.

:class:`BaseBackend` holds the joints' positions (one array, one lock), checks
trajectories before anything moves, tracks which joints move under which execution
(several trajectories over disjoint joints run at once) and finishes handles
(:class:`TrajectoryExecution`). A concrete backend adds how time passes and what moves:
:class:`~taskrunner.backends.mock.MockBackend`, :class:`~taskrunner.backends.sim.SimBackend`.
Units: rad (m for prismatic joints), s.
"""

from __future__ import annotations

import math
import threading
import time
from abc import ABC, abstractmethod
from collections.abc import Callable, Mapping
from typing import Any, Protocol, Self, runtime_checkable

import numpy as np

from taskrunner.backends.execution import (
    ExecutionResult,
    ExecutionStatus,
    TrajectoryExecution,
    sample_positions,
)
from taskrunner.errors import (
    ArgumentError,
    BackendBusyError,
    BackendError,
    TrajectoryRejectedError,
    UnknownNameError,
)
from taskrunner.types import JointState, JointTrajectory, Pose

__all__ = [
    "Backend",
    "BaseBackend",
    "ExecutionHandle",
    "ExecutionResult",
    "ExecutionStatus",
    "ObjectTracking",
    "TrajectoryExecution",
    "check_option",
    "check_trajectory",
    "sample_positions",
]

_END_SLACK = 1e-9  # s: a trajectory this close to its end has ended (clock rounding)


@runtime_checkable
class ExecutionHandle(Protocol):
    """A trajectory being executed. Only :meth:`wait` blocks."""

    @property
    def trajectory(self) -> JointTrajectory:
        """The trajectory as given to ``execute``."""
        ...

    @property
    def status(self) -> ExecutionStatus:
        """``"running"``, ``"succeeded"``, ``"cancelled"`` or ``"failed"``."""
        ...

    @property
    def progress(self) -> float:
        """Seconds of the trajectory executed so far, from its first sample."""
        ...

    @property
    def result(self) -> ExecutionResult | None:
        """The outcome once finished (whatever the status), None while running."""
        ...

    def done(self) -> bool:
        """True once finished, whatever the status (never blocks)."""
        ...

    def wait(self, timeout: float | None = None) -> ExecutionResult:
        """Block until finished (``timeout`` s at most, None: no limit).

        Raises:
            TimeoutError: still running after ``timeout`` s (the motion goes on).
            ExecutionCancelledError: the motion was cancelled or the backend stopped.
            BackendError: the motion failed.
        """
        ...

    def cancel(self) -> None:
        """Stop the motion where it is, now (no-op once finished)."""
        ...


@runtime_checkable
class Backend(Protocol):
    """Something that moves named joints along timed trajectories."""

    @property
    def joint_names(self) -> tuple[str, ...]:
        """Every joint the backend drives."""
        ...

    def execute(self, trajectory: JointTrajectory) -> ExecutionHandle:
        """Start ``trajectory`` and return at once.

        Raises:
            TrajectoryRejectedError: refused before anything moved (unknown joint,
                non-finite value, no sample, a start away from the current positions).
            BackendBusyError: a joint of the trajectory is moving under another one.
            BackendError: the backend is closed or its device is gone.
        """
        ...

    def joint_state(self) -> JointState:
        """The current positions of every joint, as the controller reports them."""
        ...

    def stop(self) -> None:
        """Stop every motion where it is; their handles end as cancelled."""
        ...

    def close(self) -> None:
        """Stop every motion and release the backend's resources (idempotent)."""
        ...

    def __enter__(self) -> Self: ...

    def __exit__(self, *exc: object) -> None: ...


@runtime_checkable
class ObjectTracking(Protocol):
    """A backend that knows where objects are (a physics simulation): it is shown the
    task's scene (its objects and what it believes is held) and reports the objects' world
    poses, which the scene then takes over."""

    def bind_scene(self, scene: Any, materials: Mapping[str, Any] | None = None) -> None:
        """Follow ``scene`` (a :class:`taskrunner.scene.Scene`; idempotent, cheap);
        ``materials``: the mass and friction the task gives its objects
        (:class:`taskrunner.materials.Material` by name; None: as before)."""
        ...

    def object_poses(self) -> dict[str, Pose]:
        """World pose of every free object the backend simulates."""
        ...

    def physics_report(self) -> dict[str, Any] | None:
        """Joint states and object poses over time since the last report, JSON-ready
        (None: nothing new); the run's ``physics`` events carry it."""
        ...


def check_option(name: str, value: Any, ok: Callable[[float], bool], expectation: str,
                 optional: bool = False) -> None:
    """Raise ``ValueError`` unless ``value`` is a real number for which ``ok`` holds."""
    if optional and value is None:
        return
    number = isinstance(value, (int, float)) and not isinstance(value, bool)
    if not (number and not math.isnan(value) and ok(value)):
        raise ArgumentError(f"'{name}' must be {expectation} (got {value!r})")


def check_trajectory(trajectory: JointTrajectory, known: tuple[str, ...]) -> None:
    """Refuse a trajectory that cannot be executed whatever the state of the joints.

    Raises:
        TrajectoryRejectedError: no joint or no sample, a repeated or unknown joint, a
            non-finite time, position, velocity or acceleration (names joint and time).
    """
    names = trajectory.names
    if not names or len(trajectory.times) == 0:
        raise TrajectoryRejectedError(
            f"'trajectory' must have joints and samples (got {len(names)} joint(s), "
            f"{len(trajectory.times)} sample(s))")
    repeated = sorted({n for n in names if names.count(n) > 1})
    if repeated:
        raise TrajectoryRejectedError(f"trajectory names joint {repeated[0]!r} more than once")
    known_set = set(known)
    for name in names:
        if name not in known_set:
            shown = ", ".join(repr(k) for k in known)
            raise TrajectoryRejectedError(
                f"trajectory names joint {name!r} that this backend does not drive; "
                f"known: {shown}")
    bad_times = np.flatnonzero(~np.isfinite(trajectory.times))
    if bad_times.size:
        k = int(bad_times[0])
        raise TrajectoryRejectedError(
            f"'times' must be finite (got {trajectory.times[k]} at sample {k})")
    for attr in ("positions", "velocities", "accelerations"):
        bad = np.argwhere(~np.isfinite(getattr(trajectory, attr)))
        if bad.size:
            k, j = (int(i) for i in bad[0])
            raise TrajectoryRejectedError(
                f"{attr[:-1]} of joint {names[j]!r} at t = {trajectory.times[k]:.3f} s "
                f"(sample {k}) must be finite (got {getattr(trajectory, attr)[k, j]})")


def _initial_positions(names: tuple[str, ...],
                       initial: JointState | Mapping[str, float] | None) -> np.ndarray:
    positions = np.zeros(len(names))
    if initial is None:
        return positions
    values = initial.as_dict() if isinstance(initial, JointState) else dict(initial)
    index = {name: i for i, name in enumerate(names)}
    for name, value in values.items():
        if name not in index:
            raise UnknownNameError("joint", name, names)
        if not math.isfinite(float(value)):
            raise ArgumentError(f"'initial_positions' must be finite (got {value} for {name!r})")
        positions[index[name]] = float(value)
    return positions


class BaseBackend(ABC):
    """Joint positions, trajectory checks and joint bookkeeping shared by the backends.

    A subclass implements :meth:`_begin` (an execution was accepted) and, if its state
    changes only when looked at, :meth:`_refresh`; it moves joints with :meth:`_play_to`
    and ends executions with :meth:`_finish`, always under ``self._lock``.

    Args:
        joint_names: every joint driven (unique, at least one).
        initial_positions: positions at start (rad or m); joints left out start at 0.
        start_tolerance: largest accepted distance (rad or m) between a trajectory's
            first sample and a joint's current position; ``math.inf`` disables the check.
        poll_period: seconds between polls of :meth:`_refresh` while a handle waits;
            None when another thread finishes executions (``wait`` just sleeps).
        clock: monotonic time source (s).

    Raises:
        ValueError: no joint, a repeated joint, a non-finite initial position.
        UnknownNameError: an initial position for a joint not in ``joint_names``.
    """

    def __init__(self, joint_names: tuple[str, ...] | list[str],
                 initial_positions: JointState | Mapping[str, float] | None = None, *,
                 start_tolerance: float = 1e-3, poll_period: float | None = None,
                 clock: Callable[[], float] = time.monotonic) -> None:
        names = tuple(str(n) for n in joint_names)
        if not names or len(set(names)) != len(names):
            raise ArgumentError(f"'joint_names' must be at least one unique name (got {list(names)})")
        self._names = names
        self._index = {name: i for i, name in enumerate(names)}
        self._positions = _initial_positions(names, initial_positions)
        self._start_tolerance = float(start_tolerance)
        self._poll_period = poll_period
        self._clock = clock
        self._t0 = clock()
        self._lock = threading.RLock()
        self._moving: dict[str, TrajectoryExecution] = {}  # joint name -> its execution
        self._executions: list[TrajectoryExecution] = []  # running, in start order
        self._closed = False
        self._closed_reason = "closed"  # a subclass may say why (e.g. a dead controller)

    # -- public API -------------------------------------------------------------------

    @property
    def joint_names(self) -> tuple[str, ...]:
        """Every joint the backend drives, in the order of :meth:`joint_state`."""
        return self._names

    @property
    def closed(self) -> bool:
        """True after :meth:`close`."""
        return self._closed

    def execute(self, trajectory: JointTrajectory) -> TrajectoryExecution:
        """Check ``trajectory``, claim its joints and start it; returns at once.

        Raises:
            TrajectoryRejectedError: see :func:`check_trajectory`, or the first sample
                is more than ``start_tolerance`` away from a joint's current position
                (a plan made from a stale state).
            BackendBusyError: a joint is moving under another execution.
            BackendError: the backend is closed.
        """
        check_trajectory(trajectory, self._names)
        with self._lock:
            if self._closed:
                raise BackendError(f"{type(self).__name__} is {self._closed_reason}")
            self._refresh()
            for name in trajectory.names:
                if name in self._moving:
                    raise BackendBusyError(
                        f"joint {name!r} is already moving under another trajectory "
                        f"({self._moving[name].progress_now:.3f} s of "
                        f"{self._moving[name].duration:.3f} s done)")
            columns = np.array([self._index[n] for n in trajectory.names], dtype=int)
            self._check_start(trajectory, columns)
            execution = TrajectoryExecution(self, trajectory, columns, self._now())
            for name in trajectory.names:
                self._moving[name] = execution
            self._executions.append(execution)
            self._begin(execution)
            return execution

    def joint_state(self) -> JointState:
        """A consistent snapshot of every joint's current position."""
        with self._lock:
            self._refresh()
            return JointState(self._names, self._positions.copy())

    def stop(self) -> None:
        """Cancel every running execution where it is."""
        with self._lock:
            self._refresh()
            for execution in list(self._executions):
                self._cancel(execution, "stopped by the backend's stop()")

    def close(self) -> None:
        """Stop every motion; the backend then refuses new trajectories (idempotent)."""
        with self._lock:
            if self._closed:
                return
            self.stop()
            self._closed = True

    def __enter__(self) -> Self:
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    # -- for subclasses and handles ---------------------------------------------------

    def _now(self) -> float:
        """Seconds since the backend was created, on its clock."""
        return self._clock() - self._t0

    @abstractmethod
    def _begin(self, execution: TrajectoryExecution) -> None:
        """An execution was accepted (called under the lock): start moving it."""

    def _refresh(self) -> None:
        """Bring positions and executions up to date (called under the lock). Override
        when the state changes only when looked at (no thread of its own)."""

    def _poll(self) -> None:
        """:meth:`_refresh` under the lock (what a handle calls when looked at)."""
        with self._lock:
            self._refresh()

    def _cancel(self, execution: TrajectoryExecution, message: str) -> None:
        """Stop ``execution`` where its joints are now (called under the lock)."""
        if not execution.finished:
            self._finish(execution, "cancelled",
                         f"{message} at {execution.progress_now:.3f} s of {execution.duration:.3f} s")

    def _play_to(self, execution: TrajectoryExecution, elapsed: float) -> bool:
        """Put the execution's joints where its trajectory is ``elapsed`` s after its first
        sample; finish it as succeeded at the end. Returns True if it finished."""
        if elapsed >= execution.duration - _END_SLACK:
            elapsed = execution.duration
        elapsed = max(elapsed, 0.0)
        trajectory = execution.trajectory
        self._positions[execution.columns] = sample_positions(
            trajectory, float(trajectory.times[0]) + elapsed)
        execution.set_progress(elapsed)
        if elapsed >= execution.duration:
            self._finish(execution, "succeeded", "trajectory executed")
            return True
        return False

    def _finish(self, execution: TrajectoryExecution, status: ExecutionStatus, message: str,
                error: BackendError | None = None,
                data: Mapping[str, object] | None = None) -> None:
        """End ``execution`` with its joints where they are now and free them. ``data``:
        what the backend measured (:attr:`ExecutionResult.data`)."""
        for name in execution.trajectory.names:
            if self._moving.get(name) is execution:
                del self._moving[name]
        if execution in self._executions:
            self._executions.remove(execution)
        final = JointState(execution.trajectory.names, self._positions[execution.columns])
        execution.complete(ExecutionResult(status, self._now() - execution.start_time,
                                           final, message, dict(data or {})), error)

    def _check_start(self, trajectory: JointTrajectory, columns: np.ndarray) -> None:
        start = trajectory.positions[0]
        current = self._positions[columns]
        offsets = np.abs(start - current)
        j = int(np.argmax(offsets))
        if offsets[j] > self._start_tolerance:
            raise TrajectoryRejectedError(
                f"first sample of joint {trajectory.names[j]!r} (t = "
                f"{float(trajectory.times[0]):.3f} s) must be within {self._start_tolerance:g} "
                f"of the joint's current position {current[j]:.4f} (got {start[j]:.4f}); "
                "was the trajectory planned from a stale state?")
