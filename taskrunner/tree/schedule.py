"""The motions a run has committed to, on one clock, and the rule that admits a new one.

Branches of a ``parallel`` move their arms at the same time. Each branch plans its
motions against the other arms *frozen* where they stand when planning starts; what
keeps the arms apart in time is this schedule. Every motion a run sends to the backend is
first *admitted* (:meth:`MotionSchedule.admit`): it gets a start time on the schedule's
clock and is verified, with :func:`~taskrunner.collision.spacetime.verify_lanes`, against
every committed motion of the branches running at the same time (already executing or
admitted to execute later), each other arm resting between its motions, with
:data:`CLEARANCE` to spare. On a conflict with another arm's running (or coming) motion
the new motion starts later (a :class:`Wait`): first a little later, while that motion
still runs, so that it passes behind the other arm (a *delay*: :data:`DELAYS` - 1 starts
evenly spread before that motion's end are tried in order, the first that keeps the
clearance from every other lane then brought earlier by halving, :data:`DELAY_REFINE`
times); else when that motion has ended, verified again from there (and put off again
if it then meets another). Either way the start committed is one that was verified. When
the other arm *rests* in its way after the last motion its branch has committed, the
motion is :class:`Blocked`: its leaf holds it, uncommitted,
until that branch commits its next motion (the arm may move away) and admits it again;
when that branch has ended (its arm stays there) or holds for this one in turn (a
deadlock), waiting cannot help and the step fails (:meth:`MotionSchedule.refusal`, a
:class:`~taskrunner.errors.ScheduleConflictError` naming both steps' file:lines and the bodies). Both
``run-task run`` (each leaf before it executes) and ``run-task check`` (its dry run of a
``parallel``) call this one rule.

*Lanes.* A motion belongs to the lane of its leaf: the branch it runs in, as the path of
``(parallel instance, branch index)`` from the tree's root (``()`` outside any parallel;
each time a ``parallel`` starts it is a new instance). Two lanes run at the same time when
they part at the same instance of a ``parallel`` in different branches; otherwise one
follows the other, so a motion never starts before the motions of the lanes it follows
have ended.

*Turns.* Which of two motions that meet is admitted first decides which one waits, so
the branches take turns, as the check schedules them
(:mod:`taskrunner.tree.branch_schedule`): a branch's k-th motion of a ``parallel`` is
admitted once each branch before it has admitted its k-th and each after it its
(k-1)-th (:meth:`MotionSchedule.turn`; a branch that has ended or holds is passed over).
The schedule is then the same whatever order the branches' plans finish in (a planner
slow for one arm, a loaded machine).

*Waits between branches.* A step with ``wait_for`` (:mod:`taskrunner.tree.waiting`) sets
a *floor* under its lane (:meth:`MotionSchedule.not_before`): the lane's next motions start
no earlier than the named step's last motion ended (:meth:`MotionSchedule.finish_step`).
A ``wait`` step sets one too (:meth:`MotionSchedule.pause`): its lane's next motions start
its seconds after where the lane stands (its planned time), the other lanes go on; while
its leaf holds, its branch is passed over in the turns (as one that holds). How many
motions the other branches admit before the paused branch's next one then depends on
when their plans finish: every one is verified all the same, but which of two meeting
motions waits may differ between runs (``run-task check`` admits the paused branch's
next motion in its turn). A lane that follows another starts no earlier than that one's
floor.

*Planned time.* Seconds. A motion's start is decided by the schedule alone: the end of
the motions it follows, a ``wait_for``'s floor, the other arms' committed motions (its
waits); planning counts as no time, on every backend. A backend that plays motions in
time is told to start it at its planned start plus the schedule's :attr:`~MotionSchedule.
slip` on the run's clock (:class:`~taskrunner.tree.clock.TaskClock`); its leaf holds it
until then. Where it is sent later than :data:`LATE` after that (its plan took longer
than its place on the schedule left it), the whole schedule slips
(:meth:`MotionSchedule.slip_to`: every motion not sent yet goes as much later, the delay
kept in :attr:`MotionSchedule.slips`), never a different plan: the same task gives the
same trajectories and the same planned starts whatever the machine's load. A motion of
another arm already running when the schedule slipped runs earlier against it than
planned: before it is sent, the motion is verified against that one where both really
run (:meth:`MotionSchedule.clear_to_send`) and held while it would meet it. Each motion
sent keeps its *offset* (its real start less its planned start). A motion held while
another arm is overdue (:meth:`MotionSchedule.overdue`) goes when that one has gone. An
arm that *lags* its trajectory (physics, servos) by more than :data:`LAG` is retimed
where it really is (its offset grows), and the motions verified against it are verified
again (:meth:`MotionSchedule.recheck`): held, or stopped and their rest admitted again
(stop-and-go), so a late arm makes the cell slower. A motion verified against a promise
since taken back or cut (:attr:`MotionSchedule.retractions`) is admitted again. What it
does not yet measure: lag in joint space (a backend whose progress runs on while its arm
trails).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Sequence
from dataclasses import dataclass, field, replace
from typing import Any

import numpy as np

from taskrunner.collision.spacetime import (
    Conflict,
    Lane,
    SpacetimeOptions,
    SpacetimeVerification,
    TimedMotion,
    verify_lanes,
)
from taskrunner.errors import InvalidStateError, ScheduleConflictError
from taskrunner.kinds import WaitKind
from taskrunner.scene import Scene
from taskrunner.types import JointTrajectory

__all__ = ["CLEARANCE", "LAG", "LATE", "Admission", "Blocked", "LaneKey", "MotionSchedule", "Wait",
           "concurrent", "lanes_of"]

CLEARANCE = 0.005
"""m: the least distance a motion keeps from the bodies of arms moving at the same time
(another branch of a ``parallel``), at every instant of the schedule. It also absorbs the
difference between a planned trajectory and the one a record keeps (thinned to 25 Hz:
well under a millimetre on these arms)."""

DELAYS = 4
"""A motion that would meet another arm's running motion tries this many starts less one,
evenly spread before that motion's end, before it waits for the end (module text)."""

DELAY_REFINE = 2
"""Halvings of the stretch between the last start tried that met the other arm and the
first that passes behind it: the delay is found to within 1 / (``DELAYS`` × 2 **
``DELAY_REFINE``) of that stretch."""

LATE = 0.005
"""s of task time: a motion sent later than this after its admitted start is admitted
again (a tick late on a fast simulator)."""

LAG = 0.05
"""s of task time: an arm running further behind its schedule than this (its backend's
progress against the run's clock) is put where it really is on the schedule, and every
motion verified against where it should have been is verified again: held, or stopped
where it is running, when it would now meet it (stop-and-go)."""

LaneKey = tuple[tuple[int, int], ...]
"""A lane: ``(parallel instance, branch index)`` pairs from the tree's root."""


def concurrent(a: LaneKey, b: LaneKey) -> bool:
    """Whether motions of lanes ``a`` and ``b`` may run at the same time: the lanes part
    in different branches of one instance of a ``parallel``."""
    for (pa, ba), (pb, bb) in zip(a, b):
        if pa != pb:
            return False
        if ba != bb:
            return True
    return False


@dataclass(frozen=True)
class Committed:
    """A motion on the schedule: its lane, timing, and the step it is of.

    Attributes:
        sent: it was sent to the backend, at ``motion.start`` (its real start).
        seen: the schedule's :attr:`~MotionSchedule.retractions` when it was verified:
            a motion of another lane taken back or stopped since may have been what kept
            it clear, so it is verified again before it is sent.
        progress: s of its trajectory the backend has played (once sent): how far
            behind its schedule the arm runs (:meth:`MotionSchedule.lagging`).
        motion: at its *planned* start (:attr:`MotionSchedule.slip`).
    """

    lane: LaneKey
    motion: TimedMotion
    location: str | None
    sent: bool = False
    seen: int = 0
    progress: Callable[[], float] | None = field(default=None, compare=False)
    offset: float = 0.0
    """s: once sent, its real start on the run's clock less its planned start
    (``motion.start``): the schedule's :attr:`~MotionSchedule.slip` when it was sent."""


@dataclass(frozen=True)
class Wait:
    """A motion held back: it would have met ``conflict`` (another branch's motion, of
    the step at ``other``), so it starts at ``until`` instead (s): a little later, while
    that motion still runs (``kind`` :attr:`~taskrunner.kinds.WaitKind.DELAY`), or when it
    has ended (:attr:`~taskrunner.kinds.WaitKind.UNTIL_END`); or it was planned again
    around the other arm (:attr:`~taskrunner.kinds.WaitKind.REPLAN`)."""

    since: float
    until: float
    conflict: Conflict
    other: str | None
    kind: WaitKind = WaitKind.UNTIL_END
    sooner: float = 0.0
    """s, with :attr:`~taskrunner.kinds.WaitKind.REPLAN`: how much sooner the motion
    planned again ends than the first one would have, waiting (it starts at ``until``)."""

    def event_data(self) -> dict[str, Any]:
        """The data of its ``wait`` event (times in s, distance in m)."""
        data: dict[str, Any] = {
            "since": round(self.since, 6), "until": round(self.until, 6), "other": self.other,
            "bodies": list(self.conflict.bodies), "at": round(self.conflict.time, 6),
            "distance": round(self.conflict.distance, 6), "resolution": self.kind.value}
        if self.kind == WaitKind.REPLAN:
            data["sooner"] = round(self.sooner, 6)
        return data

    def describe(self, here: str | None) -> str:
        if self.kind == WaitKind.REPLAN:
            return (f"{here or 'this motion'} was planned again around "
                    f"{self.other or 'the other arm'}, where they would meet, and ends "
                    f"{self.sooner:.2f} s sooner than by waiting for it: "
                    f"{self.conflict.describe()}")
        if self.kind == WaitKind.DELAY:
            return (f"{here or 'this motion'} waits {self.until - self.since:.2f} s, to pass "
                    f"behind {self.other or 'the other arm'}: {self.conflict.describe()}")
        return (f"{here or 'this motion'} waits {self.until - self.since:.2f} s, until "
                f"{self.other or 'the other arm'} has moved: {self.conflict.describe()}")


@dataclass(frozen=True)
class Blocked:
    """A motion not admitted: another branch's arm rests in its way after that branch's
    last committed motion (the step at ``other``). The branch may still move that arm
    away (its next motion), so the motion is *held*: admitted again once that branch has
    committed more; when it has ended, or holds for this one in turn, waiting cannot
    resolve it (:meth:`MotionSchedule.refusal`)."""

    conflict: Conflict
    lane: LaneKey
    other: str | None

    def describe(self, here: str | None) -> str:
        return (f"{here or 'this motion'} holds until the arm of {self.other or 'another branch'}"
                f" moves on: {self.conflict.describe()}")


@dataclass(frozen=True)
class Admission:
    """Where a motion was put on the schedule.

    Attributes:
        start: s on the schedule's clock.
        waits: the waits inserted before it, in order.
        queries: exact distances the verifications computed; ``seconds`` their wall time.
        least: m, the least distance measured between this motion's bodies and the
            other branches' (inf: none moved beside it).
        entry: the motion as committed (what :meth:`MotionSchedule.withdraw` takes).
    """

    start: float
    waits: tuple[Wait, ...]
    queries: int
    seconds: float
    least: float = math.inf
    entry: Committed | None = None
    stamp: int = -1
    """The schedule's revision it was found at (see :meth:`MotionSchedule.commit`)."""


@dataclass
class MotionSchedule:
    """The motions of one run (or one check), by lane, on one clock (module text).

    Attributes:
        clearance: m, see :data:`CLEARANCE`.
    """

    clearance: float = CLEARANCE
    delays: int = DELAYS
    """Starts tried before a met motion's end (:data:`DELAYS`; 1: wait for its end)."""
    replans: bool = True
    """A planned motion put off long, waiting for another arm's motion to end, is planned
    again around that arm (:mod:`taskrunner.tree.replan`; False: it waits)."""
    committed: list[Committed] = field(default_factory=list)
    holding: dict[LaneKey, LaneKey] = field(default_factory=dict)
    finished: dict[tuple[int, str, str], float] = field(default_factory=dict)
    """When each step another branch waits for (``wait_for``) finished or reached the
    moment waited for, s, by (instance of a ``parallel`` around it, its name, the
    moment: ``finished`` or one within it)."""
    floors: dict[LaneKey, float] = field(default_factory=dict)
    """s: the earliest start of a lane's (and its inner lanes') next motions, set where a
    step of it waited for another branch's step."""
    waits: list[tuple[str | None, Wait]] = field(default_factory=list)
    """Every wait inserted before a motion admitted (the waiting step's file:line, the
    wait), in order; a motion admitted again later (late, withdrawn) adds its own."""
    step_waits: list[tuple[str | None, float, float, str]] = field(default_factory=list)
    """Every ``wait_for`` that held a lane back: (the waiting step's file:line, s when
    its lane could have gone on, s when it may, the name of the step waited for)."""
    pausing: dict[LaneKey, float] = field(default_factory=dict)
    """Lanes in a ``wait`` step (:meth:`pause`), and when it ends (s, planned): passed
    over in the turns while their leaf holds."""
    pauses: list[tuple[str | None, LaneKey, float, float]] = field(default_factory=list)
    """Every ``wait`` step (:meth:`pause`): (its file:line, its lane, s since, s until)."""
    retractions: int = 0
    """How many committed motions were taken back (:meth:`withdraw`) or cut short
    (:meth:`stop`, :meth:`confirm`): promises other motions may have relied on."""
    stops: dict[int, Conflict] = field(default_factory=dict)
    """Motions asked to stop (by ``id`` of their entry), and the conflict why: a late arm
    rests where a running motion was verified to pass after it had gone (stop-and-go)."""
    slip: float = 0.0
    """s: how far the run's clock is behind the plan (module text, *Planned time*): a
    motion planned to start at ``t`` is sent at ``t + slip``."""
    slips: list[tuple[str | None, float, float]] = field(default_factory=list)
    """Every slip of the whole schedule: (the step whose motion was not sent at its
    planned start, that start (s, planned), the delay (s)), in order."""
    _changes: int = 0
    _instances: int = 0
    _branches: dict[int, Callable[[int], bool]] = field(default_factory=dict)
    _counts: dict[int, int] = field(default_factory=dict)

    def new_instance(self, running: Callable[[int], bool] | None = None,
                     branches: int | None = None) -> int:
        """A fresh id for a ``parallel`` that starts; ``running(i)``: whether its branch
        ``i`` has not ended yet (default: always); ``branches``: how many it has, for its
        branches to take turns (:meth:`turn`; None: they do not)."""
        self._instances += 1
        if running is not None:
            self._branches[self._instances] = running
        if branches is not None:
            self._counts[self._instances] = branches
        return self._instances

    def turn(self, lane: LaneKey) -> bool:
        """Whether it is ``lane``'s turn to admit its next motion (module text): at every
        ``parallel`` around it whose branches take turns, each other branch that is
        running and does not hold has admitted as many motions as this one (before it),
        or one fewer (after it)."""
        for depth, (instance, index) in enumerate(lane):
            count = self._counts.get(instance)
            running = self._branches.get(instance)
            if count is None or running is None:
                continue
            mine = self._admitted(lane[:depth + 1])
            for other in range(count):
                if other == index or not running(other):
                    continue
                branch = (*lane[:depth], (instance, other))
                if any(_within(key, branch) for key in (*self.holding, *self.pausing)):
                    continue
                if self._admitted(branch) < mine + (other < index):
                    return False
        return True

    def _admitted(self, branch: LaneKey) -> int:
        return sum(1 for c in self.committed if _within(c.lane, branch))

    def planned(self, now: float) -> float:
        """The schedule's (planned) time at ``now`` s on the run's clock."""
        return now - self.slip

    def due(self, admission: Admission) -> float:
        """When, on the run's clock, an admitted motion is to be sent (s)."""
        return admission.start + self.slip

    def slip_to(self, admission: Admission, now: float) -> float:
        """The admitted motion is sent only at ``now`` (s on the run's clock), more than
        :data:`LATE` after it was due (its plan took longer than its place on the
        schedule left it, the tree reached it late, or it was held): the whole schedule
        slips, every motion not sent yet as much as this one, and keeps its plan.
        Returns the delay (s; 0: on time)."""
        delay = now - self.due(admission)
        if delay <= LATE:
            return 0.0
        self.slip += delay
        entry = admission.entry
        self.slips.append((entry.location if entry is not None else None, admission.start,
                           delay))
        return delay

    def _framed(self, others: Sequence[Committed], frame: float) -> list[Committed]:
        """``others`` as a motion that runs ``frame`` s after its planned start sees
        them: each sent one at its own offset, each not sent yet at the current slip,
        its lane's last offset or ``frame`` itself, whichever is latest (it goes no
        earlier than its arm's last motion, nor than this one: the schedule slips to it)."""
        lanes: dict[LaneKey, float] = {}
        for c in self.committed:
            if c.sent:
                lanes[c.lane] = max(lanes.get(c.lane, self.slip), c.offset)
        out = []
        for c in others:
            shift = (c.offset if c.sent else max(lanes.get(c.lane, self.slip), frame)) - frame
            if shift != 0.0:
                c = replace(c, motion=replace(c.motion, start=c.motion.start + shift))
            out.append(c)
        return out

    def _verify_in_frame(self, scene: Scene, entry: Committed, frame: float,
                         begin: float) -> Conflict | None:
        """Verify ``entry`` run ``frame`` s after its planned start, from ``begin`` (s,
        planned) on, against the concurrent lanes where they really run (sent ones at
        their offsets): the conflict, or None."""
        others = [c for c in self.committed if concurrent(c.lane, entry.lane)]
        if not others:
            return None
        framed = self._framed(others, frame)
        before = tuple(c.motion for c in self._framed(
            [c for c in self.committed if c.lane == entry.lane and c is not entry
             and c.motion.start < entry.motion.start], frame))
        lanes = [Lane("this motion", (*before, entry.motion))] + lanes_of(framed)
        horizon = max([entry.motion.end] + [c.motion.end for c in framed])
        if begin >= horizon:
            return None
        return verify_lanes(scene, lanes, (begin, horizon),
                            SpacetimeOptions(clearance=self.clearance)).conflict

    def clear_to_send(self, scene: Scene, admission: Admission, now: float
                      ) -> Conflict | None:
        """Whether the admitted motion may be sent at ``now`` (s on the run's clock),
        the schedule slipped to it (:meth:`slip_to`): where another arm's motion was
        sent before the slip, it runs earlier against this one than planned, and the
        motion is verified against it there, from now on. None: clear; else the
        conflict (the caller holds the motion, and a motion of another arm running
        through its resting arm is asked to stop, :attr:`stops`)."""
        entry = admission.entry
        assert entry is not None
        conflict = self._verify_sent(scene, entry, max(now - admission.start, self.slip))
        if conflict is not None and conflict.motions[0] is None:
            # Its arm, resting, is in the way of a motion running earlier than planned.
            others = [c for c in self.committed if concurrent(c.lane, entry.lane)]
            framed = self._framed(others, self.slip)
            runner = _blocking(framed, conflict)
            if runner is not None:
                runner = others[framed.index(runner)]
                if runner.sent and id(runner) not in self.stops:
                    self.stops[id(runner)] = conflict
                    self._changes += 1
        return conflict

    def _verify_sent(self, scene: Scene, entry: Committed, frame: float) -> Conflict | None:
        """Verify ``entry`` run ``frame`` s after its planned start, from its start on,
        where a motion of another arm was sent at another offset (else it runs as
        planned against them)."""
        if all(not c.sent or abs(c.offset - frame) <= LATE for c in self.committed
               if concurrent(c.lane, entry.lane)):
            return None
        return self._verify_in_frame(scene, entry, frame, entry.motion.start)

    @property
    def revision(self) -> int:
        """How many motions were committed."""
        return len(self.committed)

    @property
    def changes(self) -> int:
        """How many times the schedule changed (a motion committed, taken back, cut or
        sent late): a held motion is admitted again when it grows."""
        return self._changes

    def overdue(self, lane: LaneKey, now: float) -> Committed | None:
        """A motion of a lane concurrent with ``lane`` due more than :data:`LATE` before
        ``now`` (s, planned: :meth:`planned`) and not sent: its arm rests where the
        schedule has it moving."""
        late = [c for c in self.committed if concurrent(c.lane, lane) and not c.sent
                and c.motion.start + LATE < now]
        return min(late, key=lambda c: c.motion.start) if late else None

    def running_beside(self, lane: LaneKey) -> bool:
        """Whether a motion of a lane concurrent with ``lane`` was sent and has not played
        to its end yet."""
        return any(c.sent and c.progress is not None and concurrent(c.lane, lane)
                   and float(c.progress()) < c.motion.trajectory.duration
                   for c in self.committed)

    def lagging(self, lane: LaneKey, now: float, tolerance: float) -> tuple[Committed, float] | None:
        """A sent motion of a lane concurrent with ``lane`` whose arm runs more than
        ``tolerance`` s behind its schedule at ``now`` (s), and by how much."""
        worst: tuple[Committed, float] | None = None
        for c in self.committed:
            if not (c.sent and c.progress is not None and concurrent(c.lane, lane)):
                continue
            due = min(now - c.offset, c.motion.end) - c.motion.start
            if due <= 0.0:
                continue
            behind = due - float(c.progress())
            if behind > tolerance and (worst is None or behind > worst[1]):
                worst = (c, behind)
        return worst

    def stale(self, admission: Admission) -> bool:
        """Whether a motion admitted but not sent must be verified again: a motion of
        another lane was taken back or cut since (it may have kept this one clear)."""
        entry = admission.entry
        return entry is not None and entry.seen != self.retractions

    def lane_running(self, lane: LaneKey) -> bool:
        """Whether the branch ``lane`` has not ended (it may commit more motions)."""
        return all(self._branches.get(instance, lambda _: True)(index)
                   for instance, index in lane)

    def refusal(self, lane: LaneKey, blocked: Blocked, location: str | None) -> str | None:
        """Why ``blocked`` cannot be resolved by holding the motion of ``lane``: the other
        branch has ended (its arm stays where it is), or it holds for this one (a
        deadlock); None: hold it."""
        if not self.lane_running(blocked.lane):
            return (f"meets the arm of {blocked.other or 'another branch'}, which stays "
                    f"where that branch ended: {blocked.conflict.describe()}; waiting cannot "
                    f"resolve it (order the steps, or move that arm out of the way)")
        seen, key = {lane}, blocked.lane
        while key in self.holding:  # who waits for whom: a cycle back here is a deadlock
            key = self.holding[key]
            if any(_within(key, k) for k in seen):
                return (f"and {blocked.other or 'another branch'} each wait for the other's "
                        f"arm to move (a deadlock): {blocked.conflict.describe()}")
            seen.add(key)
        return None

    def earliest(self, lane: LaneKey) -> float:
        """When a motion of ``lane`` may start at the earliest: every motion of a lane it
        follows has ended (s)."""
        ends = [c.motion.end for c in self.committed if not concurrent(c.lane, lane)]
        ends += [floor for key, floor in self.floors.items() if not concurrent(key, lane)]
        return max(ends, default=0.0)

    def lane_end(self, lane: LaneKey) -> float:
        """When the motions ``lane`` (and the lanes inside it) committed so far end, or
        its floor where later: where it stands on the schedule now (s)."""
        ends = [c.motion.end for c in self.committed if _within(c.lane, lane)]
        ends += [floor for key, floor in self.floors.items()
                 if _within(key, lane) or _within(lane, key)]
        return max(ends, default=self.earliest(lane))

    def pause(self, lane: LaneKey, seconds: float,
              location: str | None = None) -> tuple[float, float]:
        """A ``wait`` of ``seconds`` in ``lane`` (the step at ``location``): from where the
        lane stands (:meth:`lane_end`, at least :meth:`earliest`), its next motions start
        ``seconds`` later; the other lanes keep their schedule. Returns (since, until), s
        planned; the lane is :attr:`pausing` until the caller clears it; kept in
        :attr:`pauses`."""
        since = max(self.lane_end(lane), self.earliest(lane))
        until = since + seconds
        self.floors[lane] = max(self.floors.get(lane, 0.0), until)
        self.pausing[lane] = until
        self.pauses.append((location, lane, since, until))
        return since, until

    def finish_step(self, lane: LaneKey, name: str, moment: str = "finished") -> float:
        """The step ``name`` of ``lane``, which another branch waits for, has finished
        (or reached ``moment`` within it): when its motions so far end (s), recorded for
        every ``parallel`` around it."""
        at = self.lane_end(lane)
        for instance, _ in lane:
            self.finished[(instance, name, moment)] = at
        return at

    def not_before(self, lane: LaneKey, at: float, location: str | None = None,
                   step: str | None = None) -> None:
        """The next motions of ``lane`` start at ``at`` s at the earliest (a ``wait_for``
        of the step at ``location`` for the step named ``step``: kept in
        :attr:`step_waits` where it holds the lane back)."""
        since = self.lane_end(lane)
        if step is not None and at > since:
            self.step_waits.append((location, since, at, step))
        self.floors[lane] = max(self.floors.get(lane, 0.0), at)

    def admit(self, scene: Scene, lane: LaneKey, trajectory: JointTrajectory,
              location: str | None, now: float = 0.0,
              since: float | None = None, commit: bool = True) -> Admission | Blocked:
        """Put a motion of ``lane`` on the schedule, at the earliest time it keeps the
        clearance from every concurrent lane (module text), and commit it (``commit``
        False: only find where it would go; nothing is committed and no running motion
        is asked to stop: :meth:`commit` commits it while the schedule is unchanged).

        Args:
            scene: the bodies as they are now (the motion's arm at its start); what is
                attached is what it holds through it (each committed motion: its own).
            now: the earliest start the backend allows (s; 0 for one that plays no time).
            since: s, verify from here (default: the start): where a motion is admitted
                again after it was late, its arm rests at its start from now until the
                new start, and other arms may have been promised that place by then.

        Returns:
            The admission (committed), or :class:`Blocked` (nothing committed) when the
            motion meets another branch's arm at rest after that branch's last motion.

        Raises:
            ScheduleConflictError: the lanes move the same joints, or the conflicts do
                not end: nothing is committed.
        """
        start = max(self.earliest(lane), now)
        others = [c for c in self.committed if concurrent(c.lane, lane)]
        waits: list[Wait] = []
        queries, seconds = 0, 0.0  # of every verification
        # What is attached now is what the motion holds (TimedMotion.held: the record's).
        options, held = SpacetimeOptions(clearance=self.clearance), scene.attached_objects()
        # The lane's earlier motions too: where they left the joints this one holds.
        before = tuple(c.motion for c in self.committed if c.lane == lane)

        def verify(at: float) -> SpacetimeVerification:
            """The motion started at ``at`` against the others, from then on (from
            ``since`` if earlier)."""
            nonlocal queries, seconds
            mine = TimedMotion(trajectory, at, location, held)
            lanes = [Lane("this motion", (*before, mine))] + lanes_of(others)
            horizon = max([mine.end] + [c.motion.end for c in others])
            begin = at if since is None else min(since, at)
            try:
                found = verify_lanes(scene, lanes, (begin, horizon), options)
            except InvalidStateError as exc:
                raise ScheduleConflictError(f"cannot run beside the other branches: "
                                            f"{exc}") from None
            queries += found.distance_queries
            seconds += found.seconds
            return found

        least = math.inf
        for _ in range(len(others) + 1):
            if not others:
                break
            found = verify(start)
            conflict = found.conflict
            if conflict is None:
                least = found.min_distance
                break
            if conflict.time < start and conflict.motions[0] is None:
                # The arm resting, late, where another's running motion was promised the
                # place: waiting longer cannot help; that motion has to stop (stop-and-go).
                runner = _blocking(others, conflict)
                if runner is not None and runner.sent and commit:
                    self.stops[id(runner)] = conflict
                    self._changes += 1
                last = runner or _last(others, conflict)
                return Blocked(conflict, last.lane, last.location)
            blocking = _blocking(others, conflict)
            if blocking is None:
                last = _last(others, conflict)
                return Blocked(conflict, last.lane, last.location)
            delayed = self._delay(verify, start, blocking.motion.end)
            if delayed is not None:
                at, clear = delayed
                waits.append(Wait(start, at, conflict, blocking.location, WaitKind.DELAY))
                start, least = at, clear.min_distance
                break
            waits.append(Wait(start, blocking.motion.end, conflict, blocking.location))
            start = blocking.motion.end
        else:
            raise ScheduleConflictError(f"still meets another branch's arm after "
                                        f"{len(waits)} waits")
        entry = Committed(lane, TimedMotion(trajectory, start, location, held), location,
                          seen=self.retractions)
        admission = Admission(start, tuple(waits), queries, seconds, least, entry,
                              self._changes)
        if commit:
            self.commit(admission)
        return admission

    def commit(self, admission: Admission) -> bool:
        """Commit an admission found with ``commit=False`` (its waits recorded); False,
        nothing committed, when the schedule has changed since it was found (admit the
        motion again)."""
        entry = admission.entry
        if entry is None or admission.stamp != self._changes:
            return False
        self.committed.append(entry)
        self.waits += [(entry.location, wait) for wait in admission.waits]
        self._changes += 1
        return True

    def _delay(self, verify: Callable[[float], SpacetimeVerification], start: float,
               end: float) -> tuple[float, SpacetimeVerification] | None:
        """The earliest start tried after ``start`` and before ``end`` (when the motion
        met ends) at which the motion keeps its clearance from every concurrent lane, and
        its verification; None when none does (it then waits for ``end``). The starts
        tried are :attr:`delays` - 1 evenly spread ones, then :data:`DELAY_REFINE`
        halvings before the first that passes: a start that passes is verified, whatever
        the ones around it did."""
        step = (end - start) / max(self.delays, 1)
        if step <= LATE:
            return None
        failed = start
        for k in range(1, self.delays):
            at = start + k * step
            found = verify(at)
            if found.conflict is not None:
                failed = at
                continue
            best = (at, found)
            for _ in range(DELAY_REFINE):
                middle = 0.5 * (failed + best[0])
                if best[0] - middle <= LATE:
                    break
                tried = verify(middle)
                if tried.conflict is None:
                    best = (middle, tried)
                else:
                    failed = middle
            return best
        return None

    def confirm(self, scene: Scene, admission: Admission, at: float,
                progress: Callable[[], float] | None = None
                ) -> tuple[Admission, Conflict | None]:
        """The admitted motion was sent, and started at ``at`` (s, on the run's clock).

        Within :data:`LATE` of when it was due (:meth:`due`) it is on time. Later, the
        whole schedule slips (:meth:`slip_to`): it keeps its planned start, the motions
        not sent yet go as much later. Where a motion of another arm was sent at another
        offset, it is verified against that one where both really run.

        Args:
            progress: s of its trajectory the backend has played, when asked.

        Returns:
            The admission as sent (its entry with its offset), and the conflict it meets
            where it runs (None: clear): the caller then stops it at once (:meth:`stop`).
        """
        entry = admission.entry
        assert entry is not None
        self.slip_to(admission, at)
        sent = replace(entry, sent=True, progress=progress, offset=at - admission.start)
        self.committed = [sent if c is entry else c for c in self.committed]
        conflict = self._verify_sent(scene, sent, sent.offset)
        self._changes += 1
        return replace(admission, entry=sent), conflict

    def retime(self, admission: Admission, start: float) -> Admission:
        """The sent motion runs behind its schedule (an arm that lags: physics, servos):
        it is put where it really is, as started at ``start`` (s on the run's clock; its
        plan unchanged, its offset grown). The motions verified against where it should
        have been are verified again (:meth:`recheck`)."""
        entry = admission.entry
        assert entry is not None
        moved = replace(entry, offset=start - entry.motion.start)
        self.committed = [moved if c is entry else c for c in self.committed]
        self.retractions += 1
        self._changes += 1
        return replace(admission, entry=moved)

    def recheck(self, scene: Scene, admission: Admission, now: float
                ) -> tuple[Admission, Conflict | None]:
        """Verify a sent, running motion again from ``now`` (s on the run's clock) on,
        against the other lanes as they are committed and run now (a motion it relied on
        was taken back, cut or retimed since): the conflict ahead, None when it stays
        clear."""
        entry = admission.entry
        assert entry is not None
        fresh = replace(entry, seen=self.retractions)
        self.committed = [fresh if c is entry else c for c in self.committed]
        admission = replace(admission, entry=fresh)
        return admission, self._verify_in_frame(scene, fresh, fresh.offset,
                                                now - fresh.offset)

    def stop(self, admission: Admission, progress: float) -> None:
        """The admitted motion stopped ``progress`` s into its trajectory (cancelled, or
        failed): from then on its arm rests there, as the schedule now says."""
        entry = admission.entry
        if entry is None or progress >= entry.motion.trajectory.duration:
            return
        cut = replace(entry.motion, trajectory=_cut(entry.motion.trajectory, max(progress, 0.0)))
        self.committed = [replace(c, motion=cut, progress=None) if c is entry
                          else c for c in self.committed]
        self.stops.pop(id(entry), None)
        self.retractions += 1
        self._changes += 1

    def withdraw(self, admission: Admission) -> None:
        """Take an admitted motion off the schedule (it was not sent at its start: it is
        admitted again from when it is)."""
        self.committed = [c for c in self.committed if c is not admission.entry]
        self.retractions += 1
        self._changes += 1


def _cut(trajectory: JointTrajectory, until: float) -> JointTrajectory:
    """``trajectory`` up to ``until`` s, its last sample there (the arm then rests)."""
    times, positions = trajectory.times, trajectory.positions
    keep = times < until
    end = np.array([np.interp(until, times, positions[:, j]) for j in range(positions.shape[1])])
    new_times = np.append(times[keep], until)
    rows = np.vstack([positions[keep], end])
    if len(new_times) < 2:  # stopped at its first sample
        new_times, rows = np.array([0.0, 1e-6]), np.vstack([end, end])
    zeros = np.zeros_like(rows)
    return JointTrajectory(trajectory.names, new_times, rows, zeros, zeros)


def lanes_of(others: Sequence[Committed]) -> list[Lane]:
    """The committed motions as the verifier's lanes (``branch 0``, ``branch 1.0`` …),
    each lane's motions in the order committed."""
    by_lane: dict[LaneKey, list[TimedMotion]] = {}
    for c in others:
        by_lane.setdefault(c.lane, []).append(c.motion)
    return [Lane(f"branch {'.'.join(str(b) for _, b in key)}", tuple(motions))
            for key, motions in by_lane.items()]


def _blocking(others: Sequence[Committed], conflict: Conflict) -> Committed | None:
    """The other lane's motion to wait for: the one moving at the conflict, or its next
    one when it rests before it; None when it rests after its last motion."""
    t = conflict.time
    lane_name = conflict.lanes[1]
    mine = [c for c in others if _lane_name(c.lane) == lane_name]
    running = [c for c in mine if c.motion.start <= t <= c.motion.end]
    if running:
        return running[0]
    later = sorted((c for c in mine if c.motion.start > t), key=lambda c: c.motion.start)
    return later[0] if later else None


def _last(others: Sequence[Committed], conflict: Conflict) -> Committed:
    """The other lane's last committed motion (the conflict's arm rests after it)."""
    mine = [c for c in others if _lane_name(c.lane) == conflict.lanes[1]]
    return max(mine, key=lambda c: c.motion.end)


def _within(key: LaneKey, lane: LaneKey) -> bool:
    """Whether lane ``key`` is ``lane`` or a lane inside it."""
    return key[:len(lane)] == lane


def _lane_name(key: LaneKey) -> str:
    return f"branch {'.'.join(str(b) for _, b in key)}"
