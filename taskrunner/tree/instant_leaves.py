"""The leaves of a task that take no motion: an instant change of the scene, the check of
where an object ended, a wait of so many seconds (the motion leaves are in
:mod:`taskrunner.tree.behaviours`)."""

from __future__ import annotations

import time
from collections.abc import Callable

from py_trees.common import Status

from taskrunner.errors import TaskrunnerError
from taskrunner.tree.behaviours import TaskLeaf, lane_of, plays_time
from taskrunner.tree.context import TaskContext
from taskrunner.tree.outcome import Outcome

__all__ = ["CheckOutcome", "SceneAction", "Wait"]


class SceneAction(TaskLeaf):
    """An instant change of the scene (attach, detach, add or remove an object)."""

    def __init__(self, name: str, location: str | None, ctx: TaskContext,
                 action: Callable[[TaskContext], object]) -> None:
        super().__init__(name, location, ctx)
        self.action = action
        self.outcome: Status = Status.RUNNING

    def start(self) -> None:
        try:
            self.action(self.ctx)
            self.outcome = Status.SUCCESS
        except TaskrunnerError as exc:
            self.outcome = self.fail(str(exc))

    def update(self) -> Status:
        return self.outcome


class CheckOutcome(TaskLeaf):
    """Compare where an object ended with where the task asked (a condition leaf).

    SUCCESS when ``measure(ctx)`` finds the object within its tolerance; else FAILURE
    with the reason, both poses and the error in mm and degrees (see
    :mod:`taskrunner.tree.outcome`). Either way a "message" event records the outcome.
    """

    def __init__(self, name: str, location: str | None, ctx: TaskContext,
                 measure: Callable[[TaskContext], Outcome]) -> None:
        super().__init__(name, location, ctx)
        self.measure = measure
        self.result: Outcome | None = None
        self.outcome: Status = Status.RUNNING

    def start(self) -> None:
        self.result = None
        # A miss is an execution failure (exit code 4): the motions were planned and
        # executed, what they did is not what the task asked.
        try:
            self.result = self.measure(self.ctx)
        except TaskrunnerError as exc:
            self.outcome = self.fail(str(exc), kind="execution")
            return
        failure = self.result.failure
        if failure is not None:
            self.outcome = self.fail(failure, kind="execution")
            return
        self.ctx.events.emit("message", f"{self.result.object!r} at its target: "
                             f"{self.result.poses()}", node=self.name, location=self.location)
        self.outcome = Status.SUCCESS

    def update(self) -> Status:
        return self.outcome


class Wait(TaskLeaf):
    """A ``wait`` step: its branch goes on ``seconds`` later, the others keep their pace.

    On the run's schedule (planned time) the wait starts where its branch stands and the
    branch's next motions start no earlier than its end
    (:meth:`~taskrunner.tree.schedule.MotionSchedule.pause`); in a ``parallel`` the other
    branches go on. On a backend that plays time the leaf holds until that end on the
    run's clock (plus the schedule's slip), so what follows it in the branch happens
    then; on one that plays no time (the mock without ``speed``) it holds ``seconds``
    of wall time. A "wait" event gives the planned ``since`` and ``until``, and the
    ``lane`` (branch) it holds back, as a motion event does.
    """

    def __init__(self, name: str, location: str | None, ctx: TaskContext, seconds: float) -> None:
        super().__init__(name, location, ctx)
        self.seconds = seconds
        self.until = 0.0  # s: planned (a backend that plays time), else wall time
        self.timed = False

    def start(self) -> None:
        schedule, lane = self.ctx.schedule, lane_of(self)
        since, until = schedule.pause(lane, self.seconds, self.location)
        self.ctx.events.emit("wait", f"{self.location or 'this step'} waits "
                             f"{self.seconds:g} s", node=self.name, location=self.location,
                             since=round(since, 6), until=round(until, 6),
                             lane=[list(k) for k in lane])
        self.timed = plays_time(self.ctx.backend)
        self.until = until if self.timed else time.monotonic() + self.seconds

    def update(self) -> Status:
        if self.timed:
            done = self.ctx.clock.now() >= self.until + self.ctx.schedule.slip
        else:
            done = time.monotonic() >= self.until
        if not done:
            return Status.RUNNING
        self.ctx.schedule.pausing.pop(lane_of(self), None)
        return Status.SUCCESS

    def abort(self) -> None:
        self.ctx.schedule.pausing.pop(lane_of(self), None)
