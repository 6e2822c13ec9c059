"""A ``parallel``'s checked motions on one schedule, as a run admits them.

``run-task check`` plays a parallel's branches one after another
(:mod:`taskrunner.tree.leafcheck`); :func:`schedule_branches` then puts their motions on
one :class:`~taskrunner.tree.schedule.MotionSchedule` by the run's own rule, a motion of
each branch in turn, following the task's ``wait_for`` as the run's leaves follow it.
Each motion is admitted holding what its arm held as the check played it, as a run
admits it with its scene as it starts (the objects attached then: carried through it,
:attr:`~taskrunner.collision.spacetime.TimedMotion.held`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, replace

import numpy as np

from taskrunner.errors import TaskrunnerError
from taskrunner.planning.timing import parameterize_path
from taskrunner.robot import RobotModel
from taskrunner.scene import Scene, SceneObject
from taskrunner.tasks.waits import FINISHED
from taskrunner.tree.behaviours import MoveToGoal
from taskrunner.tree.instant_leaves import Wait
from taskrunner.tree.leafcheck import Motion
from taskrunner.tree.replan import long_wait
from taskrunner.tree.schedule import Blocked, LaneKey, MotionSchedule
from taskrunner.tree.schedule_proof import ScheduleProof, prove_schedule
from taskrunner.tree.waiting import reached
from taskrunner.types import JointPath, JointTrajectory

__all__ = ["schedule_branches"]


@dataclass(frozen=True)
class _Queued:
    """What comes next in a branch the check schedules: a motion (``trajectory``), a step
    waiting for another branch's step ``name`` ("wait"), the end of a step another
    branch waits for ("done"), or a ``wait`` step of ``seconds`` ("pause")."""

    kind: str
    where: str | None
    trajectory: JointTrajectory | None = None
    name: str = ""
    moment: str = FINISHED
    seconds: float = 0.0
    planned: bool = False  # a motion the run plans with the search (a MoveToGoal's)
    held: tuple[SceneObject, ...] | None = None  # attached as it starts (None: not known)


def schedule_branches(scene: Scene, branches: list[list[Motion]],
                      waits: Sequence[tuple[int, int, int, int, str, str | None, str]] = (),
                      proofs: list[ScheduleProof] | None = None,
                      held: Mapping[int, tuple[SceneObject, ...]] | None = None
                      ) -> tuple[str | None, list[str]]:
    """Put the motions of a parallel's branches on one :class:`MotionSchedule`, a motion
    of each branch in turn, as a run admits them (the scene: as the parallel starts).

    Args:
        waits: each ``wait_for`` between the branches: (branch of the waiting step, the
            index in that branch of its first motion, branch of the step waited for, the
            index after its last motion made by the moment waited for, that step's name,
            the waiting step's file:line, the moment: ``finished`` or one within it);
            followed as the run's leaves follow it (:mod:`taskrunner.tree.waiting`).
        proofs: where the schedule holds, what it proves is appended here
            (:func:`~taskrunner.tree.schedule_proof.prove_schedule`; its lines are notes).
        held: by id of a motion of ``branches``, the objects attached as the check
            played it (a motion not in it: those of ``scene``).

    Returns:
        What cannot be resolved (None: the schedule holds), and a note per wait.
    """
    schedule = MotionSchedule()
    queues: dict[LaneKey, list[_Queued]] = {}
    instance = schedule.new_instance(lambda i: bool(queues.get(((instance, i),))))
    model = scene.robot
    for index, motions in enumerate(branches):
        queue = queues.setdefault(((instance, index),), [])
        for position in range(len(motions) + 1):
            queue += [_Queued("done", None, name=name, moment=moment)
                      for _, _, b, at, name, _, moment in waits if (b, at) == (index, position)]
            queue += [_Queued("wait", where, name=name, moment=moment)
                      for b, at, _, _, name, where, moment in waits
                      if (b, at) == (index, position)]
            if position == len(motions):
                break
            leaf, start, end, path = motions[position]
            carried = (held or {}).get(id(motions[position]))
            if isinstance(leaf, Wait):
                queue.append(_Queued("pause", getattr(leaf, "location", None),
                                     seconds=leaf.seconds))
                continue
            if path is None:
                moved = np.flatnonzero(np.abs(np.asarray(end) - np.asarray(start)) > 1e-9)
                if len(moved) == 0:
                    continue
                names = tuple(model.joint_names[int(i)] for i in moved)
                path = JointPath(names, np.vstack([np.asarray(start)[moved],
                                                   np.asarray(end)[moved]]))
            timing = getattr(leaf, "timing", None)  # a moving leaf's own timing
            try:
                trajectory = parameterize_path(model, path, timing)
            except TaskrunnerError:
                continue  # reported by the step itself where a run would time it
            queue.append(_Queued("motion", getattr(leaf, "location", None), trajectory,
                                 planned=isinstance(leaf, MoveToGoal), held=carried))
    notes: list[str] = []
    made: dict[tuple[SceneObject, ...], Scene] = {}  # the scenes holding what motions held
    # Each lane's links (those its joints carry): an object attached to one is its arm's.
    links = {lane: _carried_links(model, {n for q in queue if q.trajectory is not None
                                          for n in q.trajectory.names})
             for lane, queue in queues.items()}
    last: dict[LaneKey, tuple[SceneObject, ...] | None] = {}  # of its last motion admitted
    while any(queues.values()):
        progressed = False
        for lane, queue in queues.items():
            if not queue:
                continue
            item = queue[0]
            if item.kind == "done":
                schedule.finish_step(lane, item.name, item.moment)
            elif item.kind == "wait":
                at = schedule.finished.get((instance, item.name, item.moment))
                if at is None:
                    continue  # the other branch has not got there yet
                if at > schedule.lane_end(lane):
                    notes.append(f"{item.where or 'a step'} waits until "
                                 f"{reached(item.name, item.moment)}, at {at:.2f} s")
                schedule.not_before(lane, at, item.where, item.name)
            elif item.kind == "pause":
                since, until = schedule.pause(lane, item.seconds, item.where)
                schedule.pausing.pop(lane, None)  # nothing here holds in real time
                notes.append(f"{item.where or 'a step'} waits {item.seconds:g} s, from "
                             f"{since:.2f} s to {until:.2f} s (its branch only)")
            if item.kind != "motion":
                queue.pop(0)
                progressed = True
                continue
            location, motion = item.where, item.trajectory
            assert motion is not None
            try:
                # What each arm holds now, as a run's scene has it: this motion's arm what
                # it holds through it, another what its next motion starts with.
                now = {other: next((q.held for q in rest if q.kind == "motion"),
                                   last.get(other)) for other, rest in queues.items()}
                now[lane] = item.held
                found = schedule.admit(_holding(scene, now, links, made), lane, motion,
                                       location)
            except TaskrunnerError as exc:
                return f"{location}: {exc}", notes
            if isinstance(found, Blocked):
                refusal = schedule.refusal(lane, found, location)
                if refusal is not None:
                    return f"{location}: {refusal}", notes
                schedule.holding[lane] = found.lane
                continue
            schedule.holding.pop(lane, None)
            last[lane] = item.held
            queue.pop(0)
            progressed = True
            notes += [wait.describe(location) for wait in found.waits]
            if item.planned and long_wait(found) is not None:
                # A run plans it again around the other arm first (tree/replan.py): the
                # check does not search, so it cannot tell whether that ends sooner.
                notes.append(f"{location or 'a motion'}: a run first plans it again around "
                             f"the other arm, and takes that motion where it ends sooner")
        if not progressed:
            return "the branches wait for each other's arms (a deadlock)", notes
    proof = prove_schedule(scene, schedule)
    notes += proof.describe()
    if proofs is not None:
        proofs.append(proof)
    return None, notes


def _carried_links(model: RobotModel, joints: set[str]) -> set[str]:
    """The links a joint of ``joints`` carries."""
    pin_model = model.model
    ids = {int(pin_model.getJointId(name)) for name in joints}
    out = set()
    for frame in pin_model.frames:
        jid = int(frame.parentJoint)
        while jid > 0 and jid not in ids:
            jid = int(pin_model.parents[jid])
        if jid > 0:
            out.add(str(frame.name))
    return out


def _holding(scene: Scene, now: dict[LaneKey, tuple[SceneObject, ...] | None],
             links: dict[LaneKey, set[str]],
             made: dict[tuple[SceneObject, ...], Scene]) -> Scene:
    """``scene`` with each lane's arm holding what ``now`` says (its objects attached to
    the lane's ``links``; None: as in ``scene``), the scene's allowances naming them kept.
    Kept in ``made``."""
    attached = scene.attached_objects()
    every = set().union(*links.values())
    objects = [o for o in attached if o.attached_to not in every]  # no lane's: as they are
    for lane, held in now.items():
        objects += [o for o in (attached if held is None else held)
                    if o.attached_to in links[lane]]
    holding = tuple(objects)
    if holding == attached:
        return scene
    if holding in made:
        return made[holding]
    snapshot = scene.snapshot()
    names = {o.name for o in holding}
    kept = (o for o in snapshot.objects if o.name not in names and not o.attached)
    every_object = (*kept, *holding)
    bodies = {o.name for o in every_object} | set(scene.robot.link_names)
    allowed = tuple(p for p in snapshot.allowed if p[0] in bodies and p[1] in bodies)
    copy = scene.copy()
    copy.restore(replace(snapshot, objects=every_object, allowed=allowed))
    made[holding] = copy
    return copy
