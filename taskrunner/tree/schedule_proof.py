"""What a ``parallel``'s schedule proves: the least clearance between its arms over
time, which steps move at once, and where waits were inserted.

:func:`prove_schedule` reads a :class:`~taskrunner.tree.schedule.MotionSchedule` once its
motions are all committed (``run-task check`` schedules a parallel's branches by the run's
own rule) and measures the committed motions again with
:func:`~taskrunner.collision.spacetime.least_clearance`: the robots' links and the objects
each motion holds (what was attached as it started,
:attr:`~taskrunner.collision.spacetime.TimedMotion.held`), as the record's verifier,
:func:`~taskrunner.tree.expect.arm_conflicts`, measures them, each
lane resting between its motions, the least distance bracketed within
:data:`~taskrunner.collision.spacetime.LEAST_TOLERANCE`. The admission's own
measurements only prove the schedule's clearance (5 mm); this is the distance itself,
with the two bodies (links or held objects), the instant, and each body's step
(file:line) then, so that the check's number can be compared with the verifier's on the
run's record.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from typing import Any

from taskrunner.collision.spacetime import LeastClearance, least_clearance
from taskrunner.kinds import WaitKind
from taskrunner.scene import Scene
from taskrunner.tree.schedule import Committed, LaneKey, MotionSchedule, Wait, concurrent, lanes_of

__all__ = ["Overlap", "PlannedMotion", "ScheduleProof", "ScheduleWait", "prove_schedule"]


@dataclass(frozen=True)
class Overlap:
    """Two steps of different branches whose motions run at the same time.

    Attributes:
        steps: each step's file:line (None: not known), in branch order.
        start: s on the schedule's clock, where they first move together.
        end: s, where they last do.
        seconds: s they move together in all (their motions may overlap in pieces).
    """

    steps: tuple[str | None, str | None]
    start: float
    end: float
    seconds: float


@dataclass(frozen=True)
class ScheduleWait:
    """A wait the schedule inserted before a step's motion.

    Attributes:
        step: the waiting step's file:line.
        since: s, when the motion could have started; ``until`` when it starts.
        reason: why (the conflict it would have met, or the step waited for).
        joints: a ``wait`` step's: the joints of its branch's motions (what it holds
            back; the others are drawn with their step's next motion).
    """

    step: str | None
    since: float
    until: float
    reason: str
    joints: tuple[str, ...] = ()


@dataclass(frozen=True)
class PlannedMotion:
    """A motion where the schedule put it (each arm's timeline, as the web view draws it).

    Attributes:
        step: its step's file:line (None: not known).
        joints: the joints it moves (their robots are the arms it is drawn for).
        start: s on the schedule's clock; ``end`` when it ends.
    """

    step: str | None
    joints: tuple[str, ...]
    start: float
    end: float


@dataclass(frozen=True)
class ScheduleProof:
    """The least clearance between the arms of a parallel over time, its overlapping
    steps and its waits (module text).

    Attributes:
        least: the least distance between two branches' links (m), bracketed; its
            ``motions`` are the two steps' file:lines at that instant (None: resting).
        overlaps: the pairs of steps moving at once, in order of their first overlap.
        waits: the waits inserted, in the order they were.
        motions: how many motions are on the schedule; ``makespan`` when the last ends (s).
        timeline: every motion on the schedule, in order of its start.
    """

    least: LeastClearance
    overlaps: tuple[Overlap, ...]
    waits: tuple[ScheduleWait, ...]
    motions: int
    makespan: float
    timeline: tuple[PlannedMotion, ...] = ()

    def describe(self) -> list[str]:
        """The least clearance and the overlapping steps as lines of text (``run-task
        check`` prints them as notes; it notes each wait where the schedule inserts it)."""
        lines = []
        least = self.least
        if least.bodies is not None and math.isfinite(least.distance):
            steps = " and ".join(m or f"{lane} at rest" for m, lane in
                                 zip(least.motions, least.lanes or ("", "")))
            lines.append(f"least clearance between arms {1e3 * least.distance:.1f} mm "
                         f"({_proven(least.lower)}): "
                         f"{least.bodies[0]} and {least.bodies[1]} at {least.time:.3f} s, "
                         f"during {steps} ({self.motions} motions, {self.makespan:.2f} s)")
        else:
            lines.append(f"no two arms move at once ({self.motions} motions)")
        for overlap in self.overlaps:
            a, b = (s or "a step" for s in overlap.steps)
            lines.append(f"{a} and {b} move at once from {overlap.start:.2f} s to "
                         f"{overlap.end:.2f} s ({overlap.seconds:.2f} s together)")
        return lines

    def to_dict(self) -> dict[str, Any]:
        """The proof as JSON data (m and s; a distance that is not finite as None)."""
        least = self.least

        def number(x: float | None) -> float | None:
            return None if x is None or not math.isfinite(x) else round(float(x), 6)

        return {
            "least_clearance": {
                "distance": number(least.distance),
                "lower": number(least.lower),
                "links": list(least.bodies) if least.bodies else None,
                "time": number(least.time),
                "steps": list(least.motions),
            },
            "overlaps": [{"steps": list(o.steps), "start": number(o.start),
                          "end": number(o.end), "seconds": number(o.seconds)}
                         for o in self.overlaps],
            "waits": [{"step": w.step, "since": number(w.since), "until": number(w.until),
                       "reason": w.reason, **({"joints": list(w.joints)} if w.joints else {})}
                      for w in self.waits],
            "motions": self.motions,
            "makespan": number(self.makespan),
            "timeline": [{"step": m.step, "joints": list(m.joints), "start": number(m.start),
                          "end": number(m.end)} for m in self.timeline],
        }


def prove_schedule(scene: Scene, schedule: MotionSchedule) -> ScheduleProof:
    """What ``schedule`` proves (module text).

    Args:
        scene: the situation the schedule started from: its robot state sets the joints
            no lane moves and each lane's joints before its first motion. Its robots'
            links are measured, and the objects each committed motion holds (its
            world objects, and what it has attached, are not).
    """
    robots = Scene(scene.robot)
    robots.set_state(scene.state)
    committed = list(schedule.committed)
    least = least_clearance(robots, lanes_of(committed))
    inserted = [ScheduleWait(where, since, until, f"until step {step!r} has finished")
                for where, since, until, step in schedule.step_waits]
    inserted += [ScheduleWait(where, w.since, w.until, _reason(w)) for where, w in schedule.waits]
    inserted += [ScheduleWait(where, since, until, f"a wait step of {until - since:g} s",
                              _lane_joints(committed, lane))
                 for where, lane, since, until in schedule.pauses if until > since]
    timeline = tuple(sorted((PlannedMotion(c.location, tuple(c.motion.trajectory.names),
                                           c.motion.start, c.motion.end) for c in committed),
                            key=lambda m: (m.start, m.step or "")))
    return ScheduleProof(least, _overlaps(committed), tuple(inserted),
                         len(committed), max((c.motion.end for c in committed), default=0.0),
                         timeline)


def _reason(wait: Wait) -> str:
    """Why the schedule put a motion off (its ``reason``)."""
    other = wait.other or "the other arm"
    if wait.kind == WaitKind.DELAY:
        return f"to pass behind {other}: {wait.conflict.describe()}"
    if wait.kind == WaitKind.REPLAN:
        return (f"planned again around {other}, ending {wait.sooner:.2f} s sooner than by "
                f"waiting: {wait.conflict.describe()}")
    return f"until {other} has moved: {wait.conflict.describe()}"


def _lane_joints(committed: Sequence[Committed], lane: LaneKey) -> tuple[str, ...]:
    """The joints the motions of ``lane`` (and of the lanes inside it) move, in order."""
    joints: dict[str, None] = {}
    for c in committed:
        if c.lane[:len(lane)] == lane:
            joints.update(dict.fromkeys(c.motion.trajectory.names))
    return tuple(joints)


def _overlaps(committed: Sequence[Committed]) -> tuple[Overlap, ...]:
    """Pairs of steps (file:lines) of concurrent lanes whose motions overlap in time."""
    found: dict[tuple[str | None, str | None], list[float]] = {}
    ordered = sorted(committed, key=lambda c: (c.lane, c.motion.start))
    for i, a in enumerate(ordered):
        for b in ordered[i + 1:]:
            if not concurrent(a.lane, b.lane):
                continue
            start, end = max(a.motion.start, b.motion.start), min(a.motion.end, b.motion.end)
            if end - start <= 1e-9:  # one starts as the other ends (a wait until then),
                continue  # give or take the last bits of a float
            key = (a.location, b.location)
            seen = found.setdefault(key, [start, end, 0.0])
            seen[0], seen[1] = min(seen[0], start), max(seen[1], end)
            seen[2] += end - start
    pairs = [Overlap(k, v[0], v[1], v[2]) for k, v in found.items()]
    return tuple(sorted(pairs, key=lambda o: (o.start, o.steps[0] or "", o.steps[1] or "")))


def _proven(lower: float) -> str:
    return (f"proven >= {1e3 * lower:.1f} mm" if math.isfinite(lower)
            else "touching: nothing proven")
