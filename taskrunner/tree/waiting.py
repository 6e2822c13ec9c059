"""``wait_for`` in the tree: a branch of a ``parallel`` held until another branch's step
has finished, or reached a moment within it (:mod:`taskrunner.tasks.waits`).

The step waited for is followed by a :class:`StepFinished` leaf, which records on the
run's schedule when that step's motions end (:meth:`MotionSchedule.finish_step`); for a
moment within it (``until:``, :data:`~taskrunner.tasks.steps.MOMENTS`) the leaf is put
inside the step's subtree, right after the leaves that make the moment
(:func:`mark_moment`: a ``place``'s ``released`` after its gripper opened and the object
was detached, before the retreat), and records when the motions so far end; the
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

from collections.abc import Sequence

import py_trees
from py_trees.common import Status

from taskrunner.errors import TaskSpecError
from taskrunner.tasks.waits import FINISHED
from taskrunner.tree.behaviours import TaskLeaf, TaskParallel, lane_of
from taskrunner.tree.context import TaskContext

__all__ = ["MOMENT_LEAVES", "StepFinished", "WaitForStep", "mark_moment", "moment_end", "reached"]

MOMENT_LEAVES: dict[str, tuple[str, ...]] = {
    "set_down": ("descend",),
    "released": ("open", "detach"),
    "grasped": ("close", "attach"),
}
"""The leaves (by role: the end of the leaf's name, ``"<step>: <role>"``, as
:mod:`taskrunner.tree.idioms` names them) after which each moment of
:data:`~taskrunner.tasks.steps.MOMENTS` is reached."""


class StepFinished(py_trees.behaviour.Behaviour):
    """After the step ``step`` (a name another branch waits for), or at its ``moment``:
    record that it has got there, and when on the schedule (the end of its lane's
    motions so far)."""

    def __init__(self, step: str, ctx: TaskContext, moment: str = FINISHED) -> None:
        super().__init__(f"{step} {moment}")
        self.step = step
        self.moment = moment
        self.ctx = ctx

    def update(self) -> Status:
        self.ctx.schedule.finish_step(lane_of(self), self.step, self.moment)
        return Status.SUCCESS


def reached(step: str, moment: str) -> str:
    """How a note says that ``step`` got to ``moment``."""
    if moment == FINISHED:
        return f"step {step!r} has finished"
    return f"step {step!r} has {moment.replace('_', ' ')} its object"


def _ends(name: str, moment: str) -> bool:
    return any(name.endswith(f": {role}") for role in MOMENT_LEAVES[moment])


def mark_moment(step: py_trees.behaviour.Behaviour, mark: StepFinished) -> None:
    """Put ``mark`` inside the compiled ``step`` right after the last leaf that makes its
    moment (:data:`MOMENT_LEAVES`).

    Raises:
        TaskSpecError: the subtree has no such leaf (the loader lets only a step with
            that moment be named with it).
    """
    found: tuple[py_trees.composites.Composite, int] | None = None
    for node in step.iterate():
        if isinstance(node, py_trees.composites.Sequence):
            for index, child in enumerate(node.children):
                if _ends(child.name, mark.moment):
                    found = (node, index)
    if found is None:
        raise TaskSpecError(f"'wait_for': step {mark.step!r} has no moment {mark.moment!r}")
    parent, index = found
    parent.insert_child(mark, index + 1)


def moment_end(leaves: Sequence[py_trees.behaviour.Behaviour], moment: str) -> int | None:
    """In the motions of one step (their leaves, in order), how many are made by the
    time of ``moment`` (the check's schedule); None: all of them (``finished``, or no
    motion of its leaves was needed)."""
    if moment == FINISHED:
        return None
    made = [i + 1 for i, leaf in enumerate(leaves) if _ends(leaf.name, moment)]
    return made[-1] if made else None


class WaitForStep(TaskLeaf):
    """Before a step with ``wait_for: {step: NAME}``: RUNNING until the step ``NAME`` of
    another branch of the ``parallel`` around both has finished; FAILURE when that
    branch ended without it (the step was skipped: a ``fallback``'s other branch)."""

    def __init__(self, name: str, location: str | None, ctx: TaskContext, step: str,
                 moment: str = FINISHED) -> None:
        super().__init__(name, location, ctx)
        self.step = step
        self.moment = moment
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
                        if isinstance(node, StepFinished) and node.step == self.step \
                                and node.moment == self.moment:
                            return parent, index, node
            child, parent = parent, parent.parent
        return None

    def update(self) -> Status:
        if self.target is None:
            return self.fail(f"'wait_for': no step {self.step!r} in another branch of a "
                             f"'parallel' around this step")
        parallel, index, mark = self.target
        schedule, lane = self.ctx.schedule, lane_of(self)
        at = schedule.finished.get((parallel.instance, self.step, self.moment))
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
        moment = {} if self.moment == FINISHED else {"moment": self.moment}
        self.ctx.events.emit("wait", f"{self.location or 'this step'} starts when "
                             f"{reached(self.step, self.moment)}, at {at:.2f} s",
                             node=self.name, location=self.location, step=self.step,
                             since=round(since, 6), until=round(max(at, since), 6), **moment)
        return Status.SUCCESS

    def abort(self) -> None:
        self.ctx.schedule.holding.pop(lane_of(self), None)
