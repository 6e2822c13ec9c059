"""The check mode of a compiled task: ``run-task check`` ticks the task's own tree.

:func:`~taskrunner.tree.compiler.compile_task` with ``check=CheckMode(checker)`` walks the
task as for a run, with the same py_trees composites (``Sequence`` for a sequence, an
include and a body, ``Selector`` for a fallback, ``Parallel`` for a parallel, ``Retry``
and ``Repeat`` with counts of one), and puts here what the check does instead of moving:

- a leaf step becomes a :class:`CheckStep`: the step compiled as the run compiles it, its
  leaves played in check mode (:mod:`taskrunner.tree.leafcheck`: they plan, the robot is
  put at the state reached); a problem is recorded and the step finished without checks,
  so the step always succeeds and later steps start where the run would be;
- every step is wrapped in a :class:`StepSpan`, which records where its motions begin
  and end (what a parallel's ``wait_for`` is scheduled with);
- a fallback's ``Selector`` is wrapped in a :class:`CheckFallback` and each branch in a
  :class:`CheckBranch`: a branch with problems fails (the selector goes on to the next,
  which starts where the one before stopped); the problems are kept only when every
  branch has some, and the fallback then succeeds from where its first branch ended;
- a parallel is a ``Selector`` of a :class:`JointParallel` (the parallel compiled into
  one motion of the arms together, played as one step) and a :class:`ScheduledParallel`
  around the ``Parallel`` of its branches, whose motions are then put on one schedule by
  the run's rule (:mod:`taskrunner.tree.branch_schedule`).

A check's tree finishes in one tick: nothing in it waits.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import replace
from typing import Protocol

import py_trees
from py_trees.behaviour import Behaviour
from py_trees.common import Status

from taskrunner.scene import Scene, SceneObject
from taskrunner.tasks import FallbackStep, GoStep, ParallelStep, Problem, StepNode, walk_steps
from taskrunner.tasks.waits import WaitPair
from taskrunner.tree.behaviours import TaskLeaf
from taskrunner.tree.branch_schedule import schedule_branches
from taskrunner.tree.context import TaskContext
from taskrunner.tree.leafcheck import Motion, leaves_of
from taskrunner.tree.schedule_proof import ScheduleProof
from taskrunner.tree.waiting import moment_end

__all__ = ["CheckBranch", "CheckFallback", "CheckLane", "CheckMode", "CheckStep", "Checker", "JointParallel",
           "ScheduledParallel", "StepSpan", "run_branches"]


class Checker(Protocol):
    """What the check-mode behaviours share (:class:`~taskrunner.tree.check` keeps it)."""

    ctx: TaskContext  # the situation the next step starts in
    problems: list[Problem]
    notes: list[Problem]
    tainted: bool  # the state comes from a failed step: do not blame its start
    stopped: TaskContext | None  # the situation at the first failure (of a branch)
    trace: list[Motion]
    spans: dict[int, tuple[int, int]]
    waits: list[WaitPair]
    proofs: list[ScheduleProof]  # what each scheduled parallel proves
    # What the scene had attached as each motion of the trace began (by id of the entry).
    held: Mapping[int, tuple[SceneObject, ...]]

    def skips(self, step: StepNode) -> bool:
        """Whether ``step`` names something reported already (it is not checked)."""

    def compile(self, step: StepNode, ctx: TaskContext) -> Behaviour | None:
        """``step`` compiled as the run compiles it, or None (its problem reported)."""

    def leaf(self, step: StepNode, ctx: TaskContext,
             leaves: list[Behaviour] | None = None) -> TaskContext:
        """Check one step; the situation it leaves."""

    def problem(self, step: StepNode, message: str) -> None:
        """Report ``message`` at ``step``'s line (the situation is then tainted)."""


class CheckStep(Behaviour):
    """A leaf step in check mode: checked, and finished without checks after a problem."""

    def __init__(self, step: StepNode, checker: Checker) -> None:
        super().__init__(step.label)
        self.step, self.checker = step, checker

    def update(self) -> Status:
        self.checker.ctx = self.checker.leaf(self.step, self.checker.ctx)
        return Status.SUCCESS


class StepSpan(py_trees.decorators.Decorator):
    """Records where the motions of ``step`` begin and end in the checker's trace."""

    def __init__(self, step: StepNode, child: Behaviour, checker: Checker) -> None:
        super().__init__(name=f"{step.label} (span)", child=child)
        self.step, self.checker, self.mark = step, checker, 0

    def initialise(self) -> None:
        self.mark = len(self.checker.trace)

    def update(self) -> Status:
        if self.decorated.status in (Status.SUCCESS, Status.FAILURE):
            self.checker.spans[id(self.step)] = (self.mark, len(self.checker.trace))
        return self.decorated.status


class CheckFallback(py_trees.decorators.Decorator):
    """A fallback's ``Selector`` in check mode (module docstring); always succeeds."""

    def __init__(self, step: FallbackStep, selector: Behaviour, checker: Checker) -> None:
        super().__init__(name=f"{step.label} (check)", child=selector)
        self.checker = checker
        self.outer: list[Problem] = []
        self.was_tainted = False
        self.start: TaskContext | None = None
        self.tried: list[tuple[list[Problem], TaskContext]] = []

    def initialise(self) -> None:
        c = self.checker
        self.outer, self.was_tainted, self.start, self.tried = c.problems, c.tainted, c.ctx, []

    def update(self) -> Status:
        status = self.decorated.status
        if status == Status.FAILURE:  # every branch has problems: all are reported
            c = self.checker
            c.problems = self.outer + [p for found, _ in self.tried for p in found]
            c.tainted = True
            c.ctx = self.tried[0][1]
            return Status.SUCCESS
        return status


class CheckBranch(py_trees.decorators.Decorator):
    """A branch of a :class:`CheckFallback`: starts on a copy of where the branch before
    stopped (at its first problem); fails when it has problems."""

    def __init__(self, child: Behaviour, fallback: CheckFallback, checker: Checker) -> None:
        super().__init__(name=f"{child.name} (branch)", child=child)
        self.fallback, self.checker = fallback, checker

    def initialise(self) -> None:
        c, start = self.checker, self.fallback.start
        assert start is not None
        c.problems, c.tainted, c.stopped = [], self.fallback.was_tainted, None
        c.ctx = replace(start, scene=start.scene.copy())

    def update(self) -> Status:
        if self.decorated.status != Status.SUCCESS:
            return self.decorated.status
        c = self.checker
        self.fallback.tried.append((c.problems, c.ctx))
        if not c.problems:
            c.problems = self.fallback.outer
            return Status.SUCCESS
        self.fallback.start = c.stopped or c.ctx
        return Status.FAILURE


class JointParallel(Behaviour):
    """A parallel compiled as the run compiles it: when that is one motion (``go`` steps
    of several arms), checked as one step (SUCCESS); else FAILURE, and whether its
    branches' motions are to be scheduled (they are not when a name in it was reported,
    nor when it does not compile)."""

    def __init__(self, step: ParallelStep, checker: Checker) -> None:
        super().__init__(f"{step.label} (one motion)")
        self.step, self.checker = step, checker
        self.schedules = False

    def update(self) -> Status:
        c, step = self.checker, self.step
        self.schedules = False
        if any(c.skips(s) for s in walk_steps(step.children)):
            return Status.FAILURE
        compiled = c.compile(step, c.ctx)  # reports what only the whole can get wrong
        leaves = leaves_of(compiled) if compiled is not None else []
        if leaves and all(isinstance(leaf, TaskLeaf) for leaf in leaves):
            c.ctx = c.leaf(step, c.ctx, leaves)
            return Status.SUCCESS
        self.schedules = compiled is not None
        return Status.FAILURE


class ScheduledParallel(py_trees.decorators.Decorator):
    """The ``Parallel`` of a parallel's branches (each checked in turn, each starting where
    the one before left the scene), then their motions on one schedule by the run's own
    rule, a motion of each branch in turn: where a motion must wait for another branch's
    arm, a note says so; where waiting cannot resolve a conflict, a problem names both
    steps. A ``go`` is scheduled as the straight joint line to its goal state (the path a
    planner tries first), a straight move as its Cartesian path."""

    def __init__(self, step: ParallelStep, child: Behaviour, joint: JointParallel,
                 checker: Checker) -> None:
        super().__init__(name=f"{step.label} (schedule)", child=child)
        self.step, self.joint, self.checker = step, joint, checker
        self.before: Scene | None = None  # the scene as the parallel starts
        self.count = 0

    def initialise(self) -> None:
        self.before = self.checker.ctx.scene.copy()
        self.count = len(self.checker.problems)

    def update(self) -> Status:
        if self.decorated.status != Status.SUCCESS:
            return self.decorated.status
        c, step = self.checker, self.step
        if not self.joint.schedules or len(c.problems) != self.count or len(step.children) < 2:
            return Status.SUCCESS
        spans = [c.spans[id(child)] for child in step.children]
        branches = [c.trace[start:end] for start, end in spans]
        # wait_for between these branches: where in its branch a step waits, and where
        # the step it waits for ends.
        waits: list[tuple[int, int, int, int, str, str | None, str]] = []
        for pair in c.waits:
            waiter, named = c.spans.get(id(pair.waiter)), c.spans.get(id(pair.named))
            if pair.parallel is step and waiter is not None and named is not None:
                i, j = pair.waiter_branch, pair.named_branch
                where = str(pair.waiter.loc) if pair.waiter.loc is not None else None
                made = moment_end([m[0] for m in c.trace[named[0]:named[1]]], pair.moment)
                end = named[1] if made is None else named[0] + made
                waits.append((i, waiter[0] - spans[i][0], j, end - spans[j][0],
                              pair.name, where, pair.moment))
        assert self.before is not None
        text, notes = schedule_branches(self.before, branches, waits, c.proofs, c.held)
        c.notes += [_at(step, note) for note in notes]
        if text is not None:
            c.problem(step, text)
        return Status.SUCCESS


class CheckLane(py_trees.decorators.Decorator):
    """A branch of a parallel in check mode: the steps in it are checked with the
    checker's context in that branch (``ctx.branch``: the path of branch indices the run's
    tree gives it), so that they draw the seeds and key the goal choices the run's leaves
    of that branch do (:mod:`taskrunner.tree.choice`), whatever the order of play."""

    def __init__(self, step: ParallelStep, position: int, child: Behaviour,
                 checker: Checker) -> None:
        super().__init__(name=f"{child.name} (branch)", child=child)
        self.step, self.position, self.checker = step, position, checker
        self.outer: tuple[int, ...] = ()

    def initialise(self) -> None:
        c = self.checker
        self.outer = c.ctx.branch
        index = run_branches(self.step, c.waits)[self.position]
        c.ctx = replace(c.ctx, branch=(*self.outer, index))

    def update(self) -> Status:
        status = self.decorated.status
        if status in (Status.SUCCESS, Status.FAILURE):
            c = self.checker
            c.ctx = replace(c.ctx, branch=self.outer)
        return status


def run_branches(step: ParallelStep, waits: list[WaitPair]) -> list[int]:
    """The index in the run's ``parallel`` of each child of ``step`` (document order): the
    run's compiler puts the ``go`` steps that wait for nothing (joined into one motion
    when there are several) after the other branches."""
    joins = {id(s) for pair in waits for s in (pair.waiter, pair.named)}
    gos = [c for c in step.children if isinstance(c, GoStep) and id(c) not in joins]
    others = [id(c) for c in step.children if not any(c is g for g in gos)]
    return [others.index(id(c)) if id(c) in others else len(others) for c in step.children]


def _at(step: StepNode, message: str) -> Problem:
    loc = step.loc
    return Problem(loc.file if loc else None, loc.line if loc else None, message)


class CheckMode:
    """What :func:`~taskrunner.tree.compiler.compile_task` builds in check mode
    (:class:`~taskrunner.tree.compiler.CheckHooks`), for ``checker``."""

    def __init__(self, checker: Checker) -> None:
        self.checker = checker

    def leaf(self, step: StepNode) -> Behaviour:
        return CheckStep(step, self.checker)

    def fallback(self, step: FallbackStep, branches: list[Behaviour]) -> Behaviour:
        selector = py_trees.composites.Selector(step.label, memory=True, children=[])
        check = CheckFallback(step, selector, self.checker)
        selector.add_children([CheckBranch(b, check, self.checker) for b in branches])
        return check

    def parallel(self, step: ParallelStep, branches: list[Behaviour]) -> Behaviour:
        joint = JointParallel(step, self.checker)
        together = py_trees.composites.Parallel(
            step.label, policy=py_trees.common.ParallelPolicy.SuccessOnAll(synchronise=True),
            children=[CheckLane(step, i, b, self.checker) for i, b in enumerate(branches)])
        return py_trees.composites.Selector(
            f"{step.label} (check)", memory=True,
            children=[joint, ScheduledParallel(step, together, joint, self.checker)])

    def span(self, step: StepNode, behaviour: Behaviour) -> Behaviour:
        return StepSpan(step, behaviour, self.checker)
