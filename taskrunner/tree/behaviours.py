"""The leaves of a compiled task: py_trees behaviours that plan, execute and edit the scene.

Every leaf follows the same rule: it never blocks in ``update()``. Work starts in
``initialise()`` (a plan is submitted to the plan service, a trajectory to the backend),
``update()`` polls it, and ``terminate()`` cancels whatever is still running when the tree
stops the leaf (a sibling failed, a timeout fired, the run was cancelled). A failure is a
``FAILURE`` status whose ``feedback_message`` starts with the task file:line and names
the reason (which pair collided, which target was unreachable); leaves catch only
taskrunner's own errors.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Hashable, Sequence
from dataclasses import replace

import numpy as np
import py_trees
from py_trees.common import Status

from taskrunner.backends.base import ExecutionHandle
from taskrunner.errors import BackendError, ScheduleConflictError, TaskrunnerError
from taskrunner.planning.cartesian import (
    CartesianOptions,
    CartesianResult,
)
from taskrunner.planning.cartesian_limits import time_cartesian_path
from taskrunner.planning.request import Goal, JointGoal, NamedGoal, PlannerOptions, PlanRequest
from taskrunner.planning.service import PlanTicket
from taskrunner.planning.timing import TimingOptions, parameterize_path
from taskrunner.runtime.replay import motion_data
from taskrunner.tree.choice import arm_part, choice_key, chosen, goals_key
from taskrunner.tree.context import ExecutedMotion, TaskContext
from taskrunner.tree.reach import StagedGoals
from taskrunner.tree.replan import Replanning, admit_or_replan, plan_again
from taskrunner.tree.schedule import LAG, Admission, Blocked, LaneKey
from taskrunner.types import JointPath, JointTrajectory, Pose

__all__ = ["MoveJoints", "MoveStraight", "MoveToGoal", "TaskLeaf", "TaskParallel", "lane_of",
           "plays_time"]


class TaskLeaf(py_trees.behaviour.Behaviour):
    """A leaf that knows its task file:line and reports to the run's event log."""

    def __init__(self, name: str, location: str | None, ctx: TaskContext) -> None:
        super().__init__(name)
        self.location = location
        self.ctx = ctx
        self.failure_kind: str | None = None  # "planning" or "execution" after a FAILURE
        self.started_at = 0.0

    def initialise(self) -> None:
        self.feedback_message = ""
        self.failure_kind = None
        self.started_at = time.monotonic()
        self.ctx.events.emit("node_started", node=self.name, location=self.location)
        self.start()

    def terminate(self, new_status: Status) -> None:
        if new_status == Status.INVALID:
            self.abort()
        if new_status != Status.INVALID or self.status == Status.RUNNING:
            self.ctx.events.emit("node_finished", self.feedback_message, node=self.name,
                                 location=self.location, status=new_status.value,
                                 seconds=round(time.monotonic() - self.started_at, 6),
                                 **self.finish_data())

    def fail(self, reason: str, kind: str = "planning") -> Status:
        """FAILURE, with the reason prefixed by the task file:line.

        Args:
            kind: "planning" (nothing moved for this step) or "execution" (the backend
                failed while moving).
        """
        self.feedback_message = f"{self.location}: {reason}" if self.location else reason
        self.failure_kind = kind
        return Status.FAILURE

    # Subclasses override these.
    def finish_data(self) -> dict[str, object]:
        """Extra data of the leaf's ``node_finished`` event."""
        return {}

    def start(self) -> None:
        """Begin the work (called by ``initialise``)."""

    def abort(self) -> None:
        """Stop the work: the leaf was interrupted."""


class TaskParallel(py_trees.composites.Parallel):
    """A ``parallel`` whose branches move their arms at the same time: each start is a new
    instance of it on the run's motion schedule (:mod:`taskrunner.tree.schedule`), so its
    branches' motions are verified against each other in time. It succeeds when every
    branch has."""

    def __init__(self, name: str, children: list[py_trees.behaviour.Behaviour],
                 ctx: TaskContext) -> None:
        super().__init__(name, policy=py_trees.common.ParallelPolicy.SuccessOnAll(
            synchronise=True), children=children)
        self.ctx = ctx
        self.instance = 0

    def initialise(self) -> None:
        children = self.children
        self.instance = self.ctx.schedule.new_instance(
            lambda i: children[i].status not in (Status.SUCCESS, Status.FAILURE),
            len(children))
        super().initialise()


def lane_of(node: py_trees.behaviour.Behaviour) -> LaneKey:
    """The schedule lane of a node: ``(parallel instance, branch index)`` of every
    :class:`TaskParallel` above it, from the root (see :mod:`taskrunner.tree.schedule`)."""
    path: list[tuple[int, int]] = []
    child, parent = node, node.parent
    while parent is not None:
        if isinstance(parent, TaskParallel):
            index = next(i for i, c in enumerate(parent.children) if c is child)
            path.append((parent.instance, index))
        child, parent = parent, parent.parent
    return tuple(reversed(path))


def plays_time(backend: object) -> bool:
    """Whether motions on ``backend`` take their time (a mock without ``speed`` ends each
    at once: its schedule is the planned one, never held against the wall clock)."""
    from taskrunner.backends.mock import MockBackend

    return not (isinstance(backend, MockBackend) and backend.options.speed is None)


class _Executes(TaskLeaf):
    """A leaf that ends by executing one trajectory on the backend.

    Before it is sent, the trajectory is admitted to the run's motion schedule
    (:meth:`~taskrunner.tree.schedule.MotionSchedule.admit`): verified against the motions
    of the branches running beside it, and started later (a ``wait`` event) where it would
    meet one; on a backend that plays motions in time, the leaf holds it until then
    (its planned start plus the schedule's slip, which grows where it is sent late).
    """

    def __init__(self, name: str, location: str | None, ctx: TaskContext,
                 timing: TimingOptions | None) -> None:
        super().__init__(name, location, ctx)
        self.timing = timing or ctx.timing
        self.handle: ExecutionHandle | None = None
        self.trajectory: JointTrajectory | None = None
        self.admission: Admission | None = None
        self.pending: JointTrajectory | None = None  # admitted, held until its start
        # Not admitted yet: another branch's arm rests in its way (trajectory, revision seen).
        self.held: tuple[JointTrajectory, int] | None = None
        self.since: float | None = None  # s, planned: admitted again, verified from here
        self.lagged = False  # its motion was retimed: it ran behind its schedule
        self.holding = False  # held at its start: another arm runs earlier than planned
        self.replanning: Replanning | None = None  # planned again around another arm

    def may_replan(self) -> bool:  # planned again around another arm: tree/replan.py
        return False

    def replan(self, start: np.ndarray, trajectory: JointTrajectory) -> bool:
        return False

    def start(self) -> None:
        self.replanning = None
        self.handle = None
        self.trajectory = None
        self.admission = None
        self.pending = None
        self.held = None
        self.since = None
        self.lagged = False
        self.holding = False

    def execute_path(self, path: JointPath, planning_time: float,
                     trajectory: JointTrajectory | None = None) -> Status:
        """Time ``path`` (unless the planner did: ``trajectory``), admit it to the
        schedule and send it to the backend; RUNNING, or FAILURE with the reason.

        Raises:
            TaskrunnerError: timing failed, or the schedule refused the motion
                (:class:`~taskrunner.errors.ScheduleConflictError`).
        """
        if trajectory is None:
            trajectory = parameterize_path(self.ctx.scene.robot, path, self.timing)
        self.trajectory = trajectory
        self.ctx.events.emit(
            "planned", f"{len(path)} waypoints, {trajectory.duration:.2f} s",
            node=self.name, location=self.location, planning_time=round(planning_time, 6),
            duration=round(trajectory.duration, 6), waypoints=len(path))
        if len(trajectory.times) < 2:
            return Status.SUCCESS  # already there
        return self._admit(trajectory)

    def _admit(self, trajectory: JointTrajectory) -> Status:
        """Put the motion on the run's schedule (module text); send it, hold it until its
        start, or hold it until the branch in its way has moved on."""
        schedule, lane = self.ctx.schedule, lane_of(self)
        if not schedule.turn(lane):
            # Another branch admits its motion of this round first (its plan is not done
            # yet): asked again at the next tick, so the order does not depend on it.
            self.held = (trajectory, -1)
            return Status.RUNNING
        if self.held is not None and self.held[1] == -1:
            self.held = None  # its turn has come
        timed = plays_time(self.ctx.backend)
        # Its start is the schedule's (planned time): where time passes, it is held until
        # then, and the whole schedule slips where it is sent late. Only a motion
        # admitted again (stopped, or verified against a promise since broken) starts
        # from now at the earliest.
        since = self.since if timed else None
        now = schedule.planned(self.ctx.clock.now()) if since is not None else 0.0
        admitted = admit_or_replan(self, lane, trajectory, now, since)
        if admitted is None:  # planned again around another arm: admitted when done
            self.held = None
            return Status.RUNNING
        trajectory, found = admitted
        self.trajectory = trajectory
        if isinstance(found, Blocked):
            refusal = schedule.refusal(lane, found, self.location)
            if refusal is not None:
                schedule.holding.pop(lane, None)
                raise ScheduleConflictError(refusal)
            if self.held is None:
                self.ctx.events.emit("wait", found.describe(self.location), node=self.name,
                                     location=self.location, hold=True, other=found.other,
                                     bodies=list(found.conflict.bodies),
                                     at=round(found.conflict.time, 6),
                                     distance=round(found.conflict.distance, 6))
            schedule.holding[lane] = found.lane
            self.held = (trajectory, schedule.changes)
            return Status.RUNNING
        schedule.holding.pop(lane, None)
        self.held = None
        self.since = None
        admission = found
        self.admission = admission
        for wait in admission.waits:
            self.ctx.events.emit("wait", wait.describe(self.location), node=self.name,
                                 location=self.location, **wait.event_data())
        if timed:
            self.pending = trajectory  # sent at its start (the schedule slips if late)
            return self.poll_execution()
        return self._send(trajectory)

    def _send(self, trajectory: JointTrajectory) -> Status:
        self.pending = None
        timed = plays_time(self.ctx.backend)
        before = self.ctx.clock.now() if timed else 0.0
        slips = len(self.ctx.schedule.slips)
        if timed and self.admission is not None:
            self.ctx.schedule.slip_to(self.admission, before)
        try:
            handle = self.ctx.motion_backend().execute(trajectory)
        except BackendError as exc:  # refused, or stopped on a fault since the last motion
            return self.fail(f"execution failed: {exc}", kind="execution")
        self.handle = handle
        started = self.ctx.clock.track(handle, since=before if timed else None)
        snapshot = self.ctx.scene.snapshot()
        start = self.admission.start if self.admission is not None else 0.0
        sent = started if timed else start
        conflict = None
        if timed and self.admission is not None:
            # Where it really started: verified there if that is not where it was admitted.
            self.admission, conflict = self.ctx.schedule.confirm(
                self.ctx.scene, self.admission, sent, lambda: float(handle.progress))
        shown = trajectory
        if conflict is not None:  # it meets another arm from there: stopped at once
            handle.cancel()
            shown = self._cut_short()
        lane = lane_of(self)
        for _, planned, delay in self.ctx.schedule.slips[slips:]:
            self.ctx.events.emit("wait", f"the schedule slips {delay:.2f} s: "
                                 f"{self.location or 'this motion'} was due at {planned:.2f} s",
                                 node=self.name, location=self.location, slip=round(delay, 6),
                                 since=round(planned, 6))
        self.ctx.executed.append(ExecutedMotion(self.name, self.location, shown, snapshot,
                                                lane, start))
        verified = self.admission.seconds if self.admission is not None else 0.0
        self.ctx.events.emit("motion", f"{shown.duration:.2f} s", node=self.name,
                             location=self.location, start=round(start, 6),
                             sent=round(sent, 6), verify_time=round(verified, 6),
                             lane=[list(k) for k in lane], **motion_data(shown, snapshot))
        if conflict is not None:
            return self._go_on(trajectory, f"started {sent - start:.3f} s late, it would "
                               f"meet another arm: {conflict.describe()}")
        return Status.RUNNING

    def _cut_short(self) -> JointTrajectory:
        """The motion was cancelled: the scene and the schedule take the arm where it
        stopped; returns the trajectory up to there (what really moved)."""
        assert self.handle is not None and self.trajectory is not None
        self.ctx.sync_from_backend()
        progress = min(float(self.handle.progress), self.handle.trajectory.duration)
        self._stopped()
        return _cut(self.handle.trajectory, progress)

    def _go_on(self, trajectory: JointTrajectory, why: str) -> Status:
        """The motion was stopped short (stop-and-go): the rest of it, from where the arm
        stands, is timed from rest and admitted again (held or delayed as the schedule
        says); a "wait" event says why."""
        assert self.handle is not None
        progress = float(self.handle.progress)
        self.ctx.events.emit("wait", f"{self.location or 'this motion'} stops {progress:.2f} s "
                             f"into its trajectory: {why}", node=self.name,
                             location=self.location, hold=True, stopped=round(progress, 6))
        self.handle = None
        self.admission = None
        self.since = self.ctx.schedule.planned(self.ctx.clock.now())
        rest = _rest(trajectory, progress)
        if rest is None:
            return Status.SUCCESS
        try:
            timed = parameterize_path(self.ctx.scene.robot, rest, self.timing)
            return self._admit(timed)
        except TaskrunnerError as exc:
            return self.fail(str(exc))

    @property
    def moving(self) -> bool:
        """A motion is executing, or held (until its start, or until it is admitted)."""
        return self.handle is not None or self.pending is not None or self.held is not None

    def finish_data(self) -> dict[str, object]:
        """How far the motion got: ``executed.until`` (s of trajectory), for a replay;
        with what the backend measured (``executed.tracking`` of a servo bus)."""
        if self.handle is None:
            return {}
        executed: dict[str, object] = {"until": round(float(self.handle.progress), 4),
                                       "status": str(self.handle.status)}
        result = self.handle.result
        executed.update(getattr(result, "data", None) or {})
        return {"executed": executed}

    def poll_execution(self) -> Status:
        schedule = self.ctx.schedule
        if self.held is not None:
            trajectory, seen = self.held
            blocker = schedule.holding.get(lane_of(self))
            if schedule.changes == seen and (blocker is None or schedule.lane_running(blocker)):
                return Status.RUNNING  # nothing has moved on yet
            try:
                return self._admit(trajectory)
            except TaskrunnerError as exc:
                return self.fail(str(exc))
        if self.pending is not None:
            assert self.admission is not None
            now = self.ctx.clock.now()
            if now < schedule.due(self.admission):
                return Status.RUNNING
            try:
                if schedule.stale(self.admission) or (
                        self.holding and not schedule.running_beside(lane_of(self))):
                    # Verified against a promise since broken, or held against arms now
                    # at rest (their next motions wait for it): verified again from now.
                    self.since, self.holding = min(self.admission.start, schedule.planned(now)), False
                    schedule.withdraw(self.admission)
                    trajectory, self.pending = self.pending, None
                    return self._admit(trajectory)
                # In planned order: after another arm's motion due before it, and clear
                # of the motions running earlier than planned since the schedule slipped.
                if schedule.overdue(lane_of(self), self.admission.start) is not None:
                    return Status.RUNNING
                conflict = schedule.clear_to_send(self.ctx.scene, self.admission, now)
                if conflict is not None:
                    if not self.holding:
                        self.holding = True
                        self.ctx.events.emit(
                            "wait", f"{self.location or 'this motion'} holds: another arm "
                            f"runs earlier than planned against it: {conflict.describe()}",
                            node=self.name, location=self.location, hold=True,
                            bodies=list(conflict.bodies), at=round(conflict.time, 6),
                            distance=round(conflict.distance, 6))
                    return Status.RUNNING
                return self._send(self.pending)
            except TaskrunnerError as exc:
                return self.fail(str(exc))
        assert self.handle is not None
        if not self.handle.done():
            self.ctx.sync_from_backend()
            return self._monitor()
        self.ctx.sync_from_backend(finished=(self.name, self.location))
        self.ctx.clock.update()
        try:
            self.handle.wait(0.0)
        except TaskrunnerError as exc:
            self._stopped()
            return self.fail(f"execution failed: {exc}", kind="execution")
        return Status.SUCCESS

    def _monitor(self) -> Status:
        """While the motion runs (stop-and-go): an arm further behind its schedule than
        :data:`~taskrunner.tree.schedule.LAG` is put where it really is; a motion
        verified against a promise since broken (an arm retimed, a motion taken back or
        cut) is verified again from now, and stopped where it would meet another arm."""
        schedule, admission, handle = self.ctx.schedule, self.admission, self.handle
        if admission is None or admission.entry is None or handle is None \
                or not plays_time(self.ctx.backend):
            return Status.RUNNING
        now = self.ctx.clock.now()
        entry = admission.entry
        behind = (min(now - entry.offset, entry.motion.end) - entry.motion.start
                  - float(handle.progress))
        if behind > LAG and handle.progress < entry.motion.trajectory.duration:
            first = admission.entry is not None and admission.entry.motion.start == \
                admission.start and not self.lagged
            self.admission = admission = schedule.retime(admission, now - float(handle.progress))
            self.lagged = True
            if first:  # once a motion: it is retimed each time it falls LAG further behind
                self.ctx.events.emit("message", f"{self.location or 'this motion'} runs "
                                     f"{behind:.2f} s behind its schedule: the other arms' "
                                     f"motions are verified again", node=self.name,
                                     location=self.location, lag=round(behind, 6))
        stop = schedule.stops.get(id(admission.entry))
        if stop is None and schedule.stale(admission):
            try:
                self.admission, conflict = schedule.recheck(self.ctx.scene, admission, now)
            except TaskrunnerError as exc:
                return self.fail(str(exc), kind="execution")
            if conflict is not None and conflict.motions[0] is not None:
                stop = conflict
        if stop is None:
            return Status.RUNNING
        trajectory = handle.trajectory
        handle.cancel()
        self._cut_short()
        return self._go_on(trajectory, f"another arm is not where its schedule had it: "
                           f"{stop.describe()}")

    def abort(self) -> None:
        if self.pending is not None and self.admission is not None:
            self.ctx.schedule.withdraw(self.admission)  # never sent
        self.pending = None
        if self.held is not None:
            self.held = None
            self.ctx.schedule.holding.pop(lane_of(self), None)
        if self.handle is not None and not self.handle.done():
            self.handle.cancel()
            self.ctx.sync_from_backend(finished=(self.name, self.location))
            self._stopped()

    def _stopped(self) -> None:
        """The motion ended before its end: the schedule rests the arm where it stopped."""
        if self.handle is not None and self.admission is not None:
            self.ctx.schedule.stop(self.admission, float(self.handle.progress))


class MoveToGoal(_Executes):
    """Plan a collision-free motion of ``group`` to a goal, then execute it.

    Args:
        goal: builds the goal from the context when the leaf starts (so poses of objects
            are read from the scene as it is then). A
            :class:`~taskrunner.tree.reach.StagedGoals` list is asked for in two steps
            where the options try straight lines (``direct``): its first goal alone, by
            the straight line only (``direct_only``); when that fails, the whole list.
            The plan is the one the whole list gives at once: the planner takes the
            first goal whose line is free, and the list's first goal is the whole list
            where the start state may be a later goal (answered "already there" first).
    """

    def __init__(self, name: str, location: str | None, ctx: TaskContext, group: str,
                 goal: Callable[[TaskContext], Goal | tuple[Goal, ...] | StagedGoals],
                 options: PlannerOptions | None = None,
                 timing: TimingOptions | None = None) -> None:
        super().__init__(name, location, ctx, timing)
        self.group = group
        self._goal = goal
        self.options = options or PlannerOptions()
        self.ticket: PlanTicket | None = None
        # A staged list and the request for all of it, while its first goal is asked for.
        self._rest: tuple[StagedGoals, PlanRequest] | None = None
        # Without a remembered choice: the situation before the seed was drawn, the key.
        self._unchecked: tuple[TaskContext, TaskContext, tuple[Hashable, ...],
                               PlannerOptions] | None = None
        self._replan: PlannerOptions | None = None  # the options, until planned again

    def may_replan(self) -> bool:
        return self._replan is not None

    def replan(self, start: np.ndarray, trajectory: JointTrajectory) -> bool:
        options, self._replan = self._replan, None  # once
        self.ticket = None if options is None else plan_again(self, start, trajectory, options)
        return self.ticket is not None

    def goal(self, ctx: TaskContext) -> Goal | tuple[Goal, ...]:
        """The leaf's goal(s) built in ``ctx`` (a staged list in full)."""
        found = self._goal(ctx)
        return found.all() if isinstance(found, StagedGoals) else found

    def goal_list(self, ctx: TaskContext) -> Goal | tuple[Goal, ...] | StagedGoals:
        """The leaf's goal(s) built in ``ctx``, a staged list as it is."""
        return self._goal(ctx)

    def choice_key(self, ctx: TaskContext, found: Goal | tuple[Goal, ...] | StagedGoals,
                   seed: int) -> tuple[Hashable, ...] | None:
        """The key of the goal state chosen among ``found`` in ``ctx`` with the request's
        ``seed`` (see :mod:`taskrunner.tree.choice`), or None where there is one goal
        state only (a joint or named goal)."""
        if isinstance(found, StagedGoals):
            goals = found.key
        else:
            single = found[0] if isinstance(found, tuple) and len(found) == 1 else found
            if isinstance(single, (JointGoal, NamedGoal)):
                return None
            goals = goals_key(found)
        part = arm_part(ctx.scene.robot, self.group) if self.branch(ctx) else None
        return choice_key(ctx.scene, self.group, self.name, goals, seed, part)

    def branch(self, ctx: TaskContext) -> tuple[int, ...]:
        """The path of branch indices of the ``parallel`` branches around this leaf: in
        the run's tree, after those a check is in (``ctx.branch``)."""
        return ctx.branch + tuple(index for _, index in lane_of(self))

    def request_goals(self, ctx: TaskContext) -> tuple[Goal | tuple[Goal, ...] | StagedGoals,
                                                       PlannerOptions, tuple[Hashable, ...] | None]:
        """What a plan of this leaf asks for in ``ctx`` (the run's and the check's): its goals,
        the options seeded with the context's next seed (in a branch, the leaf's own
        stream), the key of its choice (or None)."""
        with ctx.drawing(self.branch(ctx), self.name):
            found = self._goal(ctx)
            options = replace(self.options, seed=ctx.next_seed())
        return found, options, self.choice_key(ctx, found, options.seed)

    def start(self) -> None:
        super().start()
        self.ticket = None
        self._rest = None
        self._unchecked = None
        try:
            before = replace(self.ctx)  # the situation before the leaf draws its seed
            found, options, key = self.request_goals(self.ctx)
            self._replan = options
            picked = chosen(self.ctx.scene.robot, key) if key is not None else None
            # No check chose here (see tree/lookahead.py): the plan's goal state is
            # played on to the step's end before it moves.
            self._unchecked = (before, replace(self.ctx), key, options) \
                if picked is None and key is not None else None
            if picked is not None:
                # The goal state the check followed to the end of its step: that one only.
                group = self.ctx.scene.robot.group(self.group)
                found = JointGoal(dict(zip(group.joint_names,
                                           picked[group.joint_indices].tolist())))
            goal: Goal | tuple[Goal, ...]
            if isinstance(found, StagedGoals):
                staged = options.direct and not options.direct_only
                goal = found.first() if staged else found.all()
            else:
                goal = found
            request = PlanRequest(self.group, _resolve_named(goal, self.ctx.scene.robot, self.group),
                                  start=self.ctx.scene.state, options=options,
                                  timing=self.timing if self.ctx.planner_times else None)
            if isinstance(found, StagedGoals) and not found.complete:
                self._rest = (found, request)
                request = replace(request, options=replace(options, direct_only=True))
            self.ticket = self.ctx.plan_service().submit(self.ctx.scene, request)
        except TaskrunnerError as exc:
            self.fail(str(exc))

    def update(self) -> Status:
        if self.moving:
            return self.poll_execution()
        if self.ticket is None:
            return Status.FAILURE  # the request itself was invalid: fail() ran in start()
        if not self.ticket.done():
            return Status.RUNNING
        try:
            result = self.ticket.result(0.0)
        except TaskrunnerError as exc:
            self.ticket = None
            if self.replanning is not None:  # no plan around the other arm: the first one
                first, self.replanning = self.replanning.trajectory, None
                return self._admit(first)
            if self._rest is not None:
                return self._ask_all()  # the first goal's line was blocked (or it failed)
            return self.fail(str(exc))
        self.ticket = None
        self._rest = None
        if self._unchecked is not None:
            before, after, key, options = self._unchecked
            self._unchecked = None
            from taskrunner.tree.lookahead import choose_as_the_check, rest_fails

            if rest_fails(self, after, result.end):
                # The rest of the step fails from the planner's goal state: the state the
                # check's rule follows instead, where one lets it succeed.
                picked = choose_as_the_check(self, before, key)
                if picked is not None:
                    return self._plan_to(picked, options)
        try:
            return self.execute_path(result.path, result.planning_time, result.trajectory)
        except TaskrunnerError as exc:
            return self.fail(str(exc))

    def _plan_to(self, q: np.ndarray, options: PlannerOptions) -> Status:
        """Plan again, to the state ``q`` of the group alone (the first request's options:
        its seed too, so that the seeds of the leaves after it stay the check's)."""
        group = self.ctx.scene.robot.group(self.group)
        goal = JointGoal(dict(zip(group.joint_names, q[group.joint_indices].tolist())))
        try:
            request = PlanRequest(self.group, goal, start=self.ctx.scene.state,
                                  options=options,
                                  timing=self.timing if self.ctx.planner_times else None)
            self.ticket = self.ctx.plan_service().submit(self.ctx.scene, request)
        except TaskrunnerError as exc:
            return self.fail(str(exc))
        return self.update()  # an in-process planner has answered already

    def _ask_all(self) -> Status:
        """Plan for the whole staged list: the request the leaf would have made at once."""
        assert self._rest is not None
        found, request = self._rest
        self._rest = None
        try:
            goal = _resolve_named(found.all(), self.ctx.scene.robot, self.group)
            self.ticket = self.ctx.plan_service().submit(self.ctx.scene,
                                                         replace(request, goal=goal))
        except TaskrunnerError as exc:
            return self.fail(str(exc))
        return self.update()  # an in-process planner has answered already

    def abort(self) -> None:
        self._rest = None
        if self.ticket is not None:
            self.ticket.cancel()
            self.ticket = None
        super().abort()


def _resolve_named(goal, model, group: str):  # type: ignore[no-untyped-def]
    """Named poses as joint values from this process's model, so poses added at run time
    (taught through the API) reach a planner whose own copy of the model lacks them."""
    if isinstance(goal, tuple):
        return tuple(_resolve_named(g, model, group) for g in goal)
    if isinstance(goal, NamedGoal):
        return JointGoal(model.named_state(group, goal.name).as_dict())
    return goal


class MoveStraight(_Executes):
    """Move a link of ``group`` in straight lines through waypoints, then execute.

    The Cartesian path is computed in ``initialise`` (a few milliseconds, no OMPL); a path
    that cannot be followed to the end fails the leaf with the reason and the fraction.
    With ``fallback`` options, a path that stops for want of an IK solution (``"ik"``:
    e.g. an arm of five joints asked to hold its tool's orientation) is computed again
    with those (e.g. position only); a "message" event says so.
    """

    def __init__(self, name: str, location: str | None, ctx: TaskContext, group: str,
                 waypoints: Callable[[TaskContext], Sequence[Pose]], link: str | None = None,
                 options: CartesianOptions | None = None,
                 timing: TimingOptions | None = None,
                 fallback: CartesianOptions | None = None) -> None:
        super().__init__(name, location, ctx, timing)
        self.group, self.waypoints, self.link = group, waypoints, link
        self.options = options or CartesianOptions()
        self.fallback = fallback
        self.outcome: Status = Status.RUNNING

    def compute(self, ctx: TaskContext) -> CartesianResult:
        """The Cartesian path from the scene's state (the fallback options applied).

        Raises:
            TaskrunnerError: the path cannot be started (see :class:`CartesianPlanner`).
        """
        planner = ctx.cartesian_planner()
        waypoints = list(self.waypoints(ctx))
        result = planner.compute(self.group, waypoints, link=self.link, options=self.options)
        if result.stop_reason == "ik" and self.fallback is not None:
            how = ("by the position of its tool only" if self.fallback.position_only
                   else "with relaxed IK options")
            ctx.events.emit("message", f"note: the tool's full pose cannot be held along this "
                            f"line ({result.message}); following the line {how}",
                            node=self.name, location=self.location)
            result = planner.compute(self.group, waypoints, link=self.link,
                                     options=self.fallback)
        return result

    def timed(self, ctx: TaskContext, path: JointPath) -> JointTrajectory | None:
        """``path`` timed as the leaf times it before it moves (the run's and the check's): by
        the joint limits, and by pilz_cartesian_limits.yaml's if the robot has it (None: no
        link to time it by). Raises TaskrunnerError where it cannot be timed."""
        model = ctx.scene.robot
        link = self.link if self.link and model.has_link(self.link) else None
        link = link or model.group(self.group).tip_link
        return time_cartesian_path(model, path, link, self.timing) if link is not None else None

    def start(self) -> None:
        super().start()
        started = time.perf_counter()
        try:
            result = self.compute(self.ctx)
        except TaskrunnerError as exc:
            self.outcome = self.fail(str(exc))
            return
        if not result.complete:
            self.outcome = self.fail(f"straight move of {self.link or self.group} stopped at "
                                     f"{100 * result.fraction:.0f} % ({result.message})")
            return
        try:
            trajectory = self.timed(self.ctx, result.path)
            self.outcome = self.execute_path(result.path, time.perf_counter() - started,
                                             trajectory)
        except TaskrunnerError as exc:
            self.outcome = self.fail(str(exc))

    def update(self) -> Status:
        if self.moving:
            return self.poll_execution()
        return self.outcome


JOINT_STEP = 0.01  # rad between the collision checks of a MoveJoints line


class MoveJoints(_Executes):
    """Move joints straight in joint space to target values (a gripper opening or closing).

    The motion is checked for collisions every ``JOINT_STEP`` rad unless ``check`` is False.
    """

    def __init__(self, name: str, location: str | None, ctx: TaskContext,
                 values: Callable[[TaskContext], dict[str, float]], check: bool = True,
                 timing: TimingOptions | None = None) -> None:
        super().__init__(name, location, ctx, timing)
        self.values, self.check = values, check
        self.outcome: Status = Status.RUNNING

    def target(self, ctx: TaskContext) -> tuple[tuple[str, ...], np.ndarray, list[str]]:
        """The joints moved, the state they move to from ``ctx``'s, its joint-limit breaches."""
        target = self.values(ctx)
        goal = ctx.scene.robot.state_with(ctx.scene.state, target)
        return tuple(target), goal, ctx.scene.robot.limit_violations(goal)

    @staticmethod
    def first_collision(ctx: TaskContext, start: np.ndarray, goal: np.ndarray) -> np.ndarray | None:
        """The first state in collision of the straight joint line from ``start`` to
        ``goal``, checked every ``JOINT_STEP`` rad (mimic joints following), or None."""
        model, scene = ctx.scene.robot, ctx.scene
        steps = max(1, int(np.ceil(np.max(np.abs(goal - start)) / JOINT_STEP)))
        for t in np.linspace(0.0, 1.0, steps + 1)[1:]:
            q = model.apply_mimic(start + t * (goal - start))
            if scene.in_collision(q):
                return q
        return None

    def start(self) -> None:
        super().start()
        scene, model = self.ctx.scene, self.ctx.scene.robot
        try:
            start = scene.state
            names, goal, bad = self.target(self.ctx)
            idx = model.indices(names)
            if bad:
                self.outcome = self.fail("target outside the joint limits: " + "; ".join(bad))
                return
            if self.check:
                q = self.first_collision(self.ctx, start, goal)
                if q is not None:
                    pairs = ", ".join(f"{c.a}–{c.b}" for c in scene.collisions(q)[:3])
                    self.outcome = self.fail(f"moving {', '.join(names)} collides: {pairs}")
                    return
            path = JointPath(names, np.vstack([start[idx], goal[idx]]))
            self.outcome = self.execute_path(path, 0.0)
        except TaskrunnerError as exc:
            self.outcome = self.fail(str(exc))

    def update(self) -> Status:
        if self.moving:
            return self.poll_execution()
        return self.outcome


def _cut(trajectory: JointTrajectory, until: float) -> JointTrajectory:
    """``trajectory`` up to ``until`` s of it, ending there (what a stopped motion moved)."""
    times, positions = trajectory.times, trajectory.positions
    keep = times < until
    end = np.array([np.interp(until, times, positions[:, j]) for j in range(positions.shape[1])])
    new_times = np.append(times[keep], max(until, 1e-6))
    rows = np.vstack([positions[keep], end])
    if len(new_times) < 2:
        new_times, rows = np.array([0.0, 1e-6]), np.vstack([end, end])
    zeros = np.zeros_like(rows)
    return JointTrajectory(trajectory.names, new_times, rows, zeros, zeros)


def _rest(trajectory: JointTrajectory, after: float) -> JointPath | None:
    """The waypoints of ``trajectory`` after ``after`` s of it, from where it was then
    (None: nothing is left)."""
    times, positions = trajectory.times, trajectory.positions
    if after >= float(times[-1]):
        return None
    here = np.array([np.interp(after, times, positions[:, j]) for j in range(positions.shape[1])])
    rows = np.vstack([here, positions[times > after]])
    if np.max(np.abs(rows[-1] - rows[0])) < 1e-9 and len(rows) <= 2:
        return None
    return JointPath(trajectory.names, rows)
