"""A motion planned again around another arm: the schedule's second preference.

When a motion would meet another branch's arm, the schedule (:mod:`taskrunner.tree.schedule`)
first tries to start it a little later, to pass behind that arm's running motion, and
otherwise waits for that motion's end. Where that wait is long (more than
:data:`REPLAN_AFTER`) and the motion is a planned one (a
:class:`~taskrunner.tree.behaviours.MoveToGoal`), the leaf plans it once more, to the
same goal state, with the other branches' arms where they would have met it (their
committed motions at the conflict's time: the new path goes around that place), and
admits whichever of the two motions ends sooner, by at least :data:`REPLAN_GAIN`. The
motion planned again is admitted as any other (verified over time against every
concurrent motion, delayed or put after them where it still meets one); its record
carries a ``wait`` of resolution ``replan`` with how much sooner it ends.

Only the run re-plans: ``run-task check`` does not plan its motions with the search
(:mod:`taskrunner.tree.leafcheck`), so its schedule shows the wait the first plan would
take, and notes that a run plans that motion again first.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING, Protocol

import numpy as np

from taskrunner.collision.spacetime import lanes_state
from taskrunner.errors import TaskrunnerError
from taskrunner.kinds import WaitKind
from taskrunner.planning.request import JointGoal, PlannerOptions, PlanRequest
from taskrunner.planning.service import PlanTicket
from taskrunner.planning.timing import TimingOptions
from taskrunner.tree.schedule import Admission, Blocked, LaneKey, Wait, concurrent, lanes_of
from taskrunner.types import JointTrajectory

if TYPE_CHECKING:
    from taskrunner.tree.context import TaskContext

__all__ = ["REPLAN_AFTER", "REPLAN_GAIN", "Replanning", "admit_or_replan", "long_wait",
           "plan_again"]

REPLAN_AFTER = 0.3
"""s: a motion put off longer than this, waiting for another arm's motion to end, is
planned again around that arm."""

REPLAN_GAIN = 0.05
"""s: the motion planned again is taken only where it ends at least this much sooner."""


@dataclass(frozen=True)
class Replanning:
    """A motion being planned again: the first plan's trajectory, the wait it would take
    (until another arm's motion ends), and when it would end then (s, planned)."""

    trajectory: JointTrajectory
    wait: Wait
    end: float


class Replans(Protocol):
    """What :func:`admit_or_replan` asks of a leaf."""

    ctx: TaskContext
    location: str | None
    replanning: Replanning | None

    def may_replan(self) -> bool:
        """Whether this motion may be planned again (a planned motion, not yet)."""

    def replan(self, start: np.ndarray, trajectory: JointTrajectory) -> bool:
        """Plan again from the full state ``start`` to where ``trajectory`` ends (the
        answer comes as a new plan does); False where the request cannot be made."""


def admit_or_replan(leaf: Replans, lane: LaneKey, trajectory: JointTrajectory, now: float,
                    since: float | None
                    ) -> tuple[JointTrajectory, Admission | Blocked] | None:
    """Admit ``trajectory`` (the leaf's plan) to the run's schedule, as
    :meth:`~taskrunner.tree.schedule.MotionSchedule.admit` with ``now`` and ``since``, or
    plan it again around another arm (module text): None while that plan is made. When
    it comes (``leaf.replanning`` set, ``trajectory`` the new plan), the sooner of the two
    is admitted. Returns the trajectory admitted and its admission (committed) or
    :class:`~taskrunner.tree.schedule.Blocked`."""
    schedule, scene, location = leaf.ctx.schedule, leaf.ctx.scene, leaf.location
    first = leaf.replanning
    if first is not None:
        leaf.replanning = None
        return _sooner(leaf, lane, first, trajectory, now, since)
    if not (schedule.replans and leaf.may_replan()):
        return trajectory, schedule.admit(scene, lane, trajectory, location, now, since=since)
    found = schedule.admit(scene, lane, trajectory, location, now, since=since, commit=False)
    if isinstance(found, Admission):
        wait = long_wait(found)
        if wait is not None:
            others = [c for c in schedule.committed if concurrent(c.lane, lane)]
            start = lanes_state(scene, lanes_of(others), wait.conflict.time)
            if leaf.replan(start, trajectory):
                leaf.replanning = Replanning(trajectory, wait, found.start + trajectory.duration)
                return None
        if schedule.commit(found):
            return trajectory, found
    # Blocked: admitted again to commit what a refusal asks of the others (a stop).
    return trajectory, schedule.admit(scene, lane, trajectory, location, now, since=since)


def long_wait(admission: Admission) -> Wait | None:
    """The wait for another arm's motion to end that puts the admitted motion off by more
    than :data:`REPLAN_AFTER` (None: none)."""
    if not admission.waits or admission.start - admission.waits[0].since <= REPLAN_AFTER:
        return None
    return next((w for w in admission.waits if w.kind == WaitKind.UNTIL_END), None)


def _sooner(leaf: Replans, lane: LaneKey, first: Replanning, second: JointTrajectory,
            now: float, since: float | None) -> tuple[JointTrajectory, Admission | Blocked]:
    """Admit whichever of the first plan and ``second`` (planned around the other arm)
    ends sooner, the first unless the second gains :data:`REPLAN_GAIN` (both admitted
    anew: other branches may have committed motions while it was planned)."""
    schedule, scene, location = leaf.ctx.schedule, leaf.ctx.scene, leaf.location
    again = schedule.admit(scene, lane, first.trajectory, location, now, since=since,
                           commit=False)
    other = schedule.admit(scene, lane, second, location, now, since=since, commit=False)
    end = (again.start + first.trajectory.duration if isinstance(again, Admission)
           else math.inf)
    if isinstance(other, Admission):
        new_end = other.start + second.duration
        if new_end <= end - REPLAN_GAIN:
            gained = min(end, first.end) - new_end
            record = Wait(first.wait.since, other.start, first.wait.conflict, first.wait.other,
                          WaitKind.REPLAN, max(gained, 0.0))
            chosen = replace(other, waits=(record, *other.waits))
            if schedule.commit(chosen):
                return second, chosen
    if isinstance(again, Admission) and schedule.commit(again):
        return first.trajectory, again
    return first.trajectory, schedule.admit(scene, lane, first.trajectory, location, now,
                                            since=since)


class Plans(Protocol):
    """What :func:`plan_again` asks of a leaf."""

    ctx: TaskContext
    group: str
    timing: TimingOptions


def plan_again(leaf: Plans, start: np.ndarray, trajectory: JointTrajectory,
               options: PlannerOptions) -> PlanTicket | None:
    """Ask the run's planner for the leaf's group from the full state ``start`` (the
    other arms where they would meet it) to where ``trajectory`` ends, with the first
    plan's ``options`` (its seed too); None where the request cannot be made."""
    group = leaf.ctx.scene.robot.group(leaf.group)
    end = dict(zip(trajectory.names, trajectory.positions[-1].tolist()))
    goal = JointGoal({name: end.get(name, float(start[index]))
                      for name, index in zip(group.joint_names, group.joint_indices)})
    try:
        request = PlanRequest(leaf.group, goal, start=start, options=options,
                              timing=leaf.timing if leaf.ctx.planner_times else None)
        return leaf.ctx.plan_service().submit(leaf.ctx.scene, request)
    except TaskrunnerError:
        return None
