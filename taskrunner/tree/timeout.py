"""``timeout:`` as a decorator that counts task time (:class:`~taskrunner.tree.clock.TaskClock`).

py_trees' own ``Timeout`` counts wall-clock time, so a task passed on mock and at sim x20
and failed at sim x2. :class:`TaskTimeout` reads the run's task clock instead: motions
count their trajectory time, everything else wall-clock time. It also fails a body that
finished over its limit within one tick (on mock, several motions can end in one tick):
the verdict is the same whether the motion took its time or not.
"""

from __future__ import annotations

import py_trees
from py_trees.common import Status

from taskrunner.tree.clock import TaskClock
from taskrunner.tree.context import TaskContext

__all__ = ["TaskTimeout"]


class TaskTimeout(py_trees.decorators.Decorator):
    """Run the child; FAILURE once it has taken more than ``seconds`` of task time.

    On expiry the child is stopped (its motion stops where it is) and the feedback
    message is ``"<file:line>: timeout after <seconds> s (...)"``.
    """

    def __init__(self, name: str, child: py_trees.behaviour.Behaviour, seconds: float,
                 location: str | None, ctx: TaskContext) -> None:
        super().__init__(name=name, child=child)
        self.seconds = seconds
        self.location = location
        self.ctx = ctx
        self.failure_kind: str | None = None
        self.started_at = 0.0

    @property
    def clock(self) -> TaskClock:
        return self.ctx.clock

    def initialise(self) -> None:
        self.feedback_message = ""
        self.failure_kind = None
        self.started_at = self.clock.now()

    def update(self) -> Status:
        elapsed = self.clock.now() - self.started_at
        if self.decorated.status in (Status.FAILURE, Status.INVALID):
            return self.decorated.status
        if elapsed > self.seconds:
            if self.decorated.status == Status.RUNNING:
                self.decorated.stop(Status.INVALID)
            where = f"{self.location}: " if self.location else ""
            self.feedback_message = (f"{where}timeout after {self.seconds:g} s ({elapsed:.2f} s "
                                     "of task time: motions at their planned time)")
            self.failure_kind = "execution"
            self.ctx.events.emit("node_finished", self.feedback_message, node=self.name,
                                 location=self.location, status=Status.FAILURE.value,
                                 seconds=round(elapsed, 6))
            return Status.FAILURE
        if self.decorated.status == Status.RUNNING:
            self.feedback_message = f"{self.seconds - elapsed:.1f} s of task time left"
        return self.decorated.status
