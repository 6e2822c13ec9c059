"""Where plans are computed: in this process, or in a :class:`PlanningWorker`.

Both offer ``submit(scene, request) -> handle`` with ``done()``, ``result(timeout)`` and
``cancel()``, so a behaviour-tree leaf polls the same way whichever it is given. The
in-process one computes during ``submit`` (it blocks the caller while OMPL runs): use it
for scripts and tests; use a worker wherever other threads must keep running.
"""

from __future__ import annotations

from typing import Protocol

from taskrunner.errors import TaskrunnerError
from taskrunner.planning.planner import MotionPlanner
from taskrunner.planning.request import PlanRequest, PlanResult
from taskrunner.scene import Scene

__all__ = ["InProcessPlanner", "PlanService", "PlanTicket"]


class PlanTicket(Protocol):
    def done(self) -> bool: ...
    def result(self, timeout: float | None = None) -> PlanResult: ...
    def cancel(self) -> None: ...


class PlanService(Protocol):
    def submit(self, scene: Scene, request: PlanRequest) -> PlanTicket: ...


class _Finished:
    """A request answered during submit."""

    def __init__(self, result: PlanResult | None, error: TaskrunnerError | None) -> None:
        self._result, self._error = result, error

    def done(self) -> bool:
        return True

    def result(self, timeout: float | None = None) -> PlanResult:
        if self._error is not None:
            raise self._error
        assert self._result is not None
        return self._result

    def cancel(self) -> None:
        """Nothing to cancel: the plan is already computed."""


class InProcessPlanner:
    """Plans in the calling thread; keeps one :class:`MotionPlanner` per scene."""

    def __init__(self) -> None:
        self._planners: dict[int, tuple[Scene, MotionPlanner]] = {}

    def submit(self, scene: Scene, request: PlanRequest) -> _Finished:
        entry = self._planners.get(id(scene))
        if entry is None or entry[0] is not scene:
            entry = (scene, MotionPlanner(scene))
            self._planners[id(scene)] = entry
        try:
            return _Finished(entry[1].plan(request), None)
        except TaskrunnerError as exc:
            return _Finished(None, exc)

    def close(self) -> None:
        self._planners.clear()
