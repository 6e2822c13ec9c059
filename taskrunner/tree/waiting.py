"""``wait_for`` in the tree: a branch of a ``parallel`` held until another branch's step
has finished (:mod:`taskrunner.tasks.waits`).

The step waited for is followed by a :class:`StepFinished` leaf, which records on the
run's schedule when that step's motions end (:meth:`MotionSchedule.finish_step`); the
waiting step is preceded by a :class:`WaitForStep` leaf, which holds its branch until
that record exists and then sets the branch's earliest start there
(:meth:`MotionSchedule.not_before`): on the schedule's clock, the waiting step's first
motion starts when the other step's last motion has ended, whether the backend plays
time or not. While it holds, the branch counts as waiting for the other one (the
schedule's ``holding``), so an arm of the other branch held in turn by this branch's arm
is a deadlock the schedule reports with both lines, not a hang.

.. currentmodule:: taskrunner.tree.schedule
"""

from __future__ import annotations

import py_trees
from py_trees.common import Status

from taskrunner.tree.behaviours import TaskLeaf, TaskParallel, lane_of
from taskrunner.tree.context import TaskContext

__all__ = ["StepFinished", "WaitForStep"]


class StepFinished(py_trees.behaviour.Behaviour):
    """After the step ``step`` (a name another branch waits for): record that it has
    finished, and when on the schedule (the end of its lane's motions so far)."""

    def __init__(self, step: str, ctx: TaskContext) -> None:
        super().__init__(f"{step} finished")
        self.step = step
        self.ctx = ctx

    def update(self) -> Status:
        self.ctx.schedule.finish_step(lane_of(self), self.step)
        return Status.SUCCESS


class WaitForStep(TaskLeaf):
    """Before a step with ``wait_for: {step: NAME}``: RUNNING until the step ``NAME`` of
    another branch of the ``parallel`` around both has finished; FAILURE when that
    branch ended without it (the step was skipped: a ``fallback``'s other branch)."""

    def __init__(self, name: str, location: str | None, ctx: TaskContext, step: str) -> None:
        super().__init__(name, location, ctx)
        self.step = step
        self.target: tuple[TaskParallel, int, StepFinished] | None = None
        self.announced = False

    def start(self) -> None:
        self.target = self._find()
        self.announced = False

    def _find(self) -> tuple[TaskParallel, int, StepFinished] | None:
        """The parallel around this leaf and the step's :class:`StepFinished`, and the
        branch it is in (the nearest parallel with it in another branch)."""
        child: py_trees.behaviour.Behaviour = self
        parent = self.parent
        while parent is not None:
            if isinstance(parent, TaskParallel):
                for index, branch in enumerate(parent.children):
                    if branch is child:
                        continue
                    for node in branch.iterate():
                        if isinstance(node, StepFinished) and node.step == self.step:
                            return parent, index, node
            child, parent = parent, parent.parent
        return None

    def update(self) -> Status:
        if self.target is None:
            return self.fail(f"'wait_for': no step {self.step!r} in another branch of a "
                             f"'parallel' around this step")
        parallel, index, mark = self.target
        schedule, lane = self.ctx.schedule, lane_of(self)
        at = schedule.finished.get((parallel.instance, self.step))
        if at is None:
            if parallel.children[index].status in (Status.SUCCESS, Status.FAILURE):
                schedule.holding.pop(lane, None)
                return self.fail(f"'wait_for': the branch of step {self.step!r} ended "
                                 "without it finishing")
            schedule.holding[lane] = lane_of(mark)
            if not self.announced:
                self.announced = True
                self.ctx.events.emit("wait", f"{self.location or 'this step'} waits for step "
                                     f"{self.step!r}", node=self.name, location=self.location,
                                     step=self.step, hold=True)
            return Status.RUNNING
        schedule.holding.pop(lane, None)
        since = schedule.lane_end(lane)
        schedule.not_before(lane, at, self.location, self.step)
        self.ctx.events.emit("wait", f"{self.location or 'this step'} starts when step "
                             f"{self.step!r} has finished, at {at:.2f} s",
                             node=self.name, location=self.location, step=self.step,
                             since=round(since, 6), until=round(max(at, since), 6))
        return Status.SUCCESS

    def abort(self) -> None:
        self.ctx.schedule.holding.pop(lane_of(self), None)
