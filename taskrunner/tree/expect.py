"""Checking a task's expectations in a run: ``expect`` steps and the task's ``expect:``.

An ``expect`` step compiles to a :class:`CheckExpectation` condition leaf: SUCCESS when
every expectation holds, else FAILURE at its file:line with what was expected and what
was observed. The task's own ``expect:`` is checked by the runner when the tree ends
(:func:`check_task_end`), with the run's status.

What is measured, and how:

- an object's pose: :func:`taskrunner.tree.outcome.measure` (the place and hand-over
  check's machinery: distance, angle, turn about z, over the object's symmetries); the
  expected pose may be in any frame the scene resolves (world, a link, another object);
- what holds an object: the link it is attached to (an arm's grasp frame for
  ``held_by: ARM``); what it rests on: :meth:`taskrunner.scene.Scene.support`;
- a group's joints: the largest joint difference from the named pose or values;
- durations: task time (:class:`~taskrunner.tree.clock.TaskClock`), the run's since the
  context was made, a step's between the start and the end of the step before the
  ``expect`` (a :class:`StepTimer` around it);
- ``collision_free``: each executed trajectory, from the scene it started in, through
  the exact path verifier (:meth:`taskrunner.scene.Scene.path_verifier`); a motion of a
  branch of a ``parallel`` there against everything but the arms of the branches beside
  it (their joints in that scene are where the backend last reported them, not where
  they were at each instant). Arm against arm in time: the run record's ``motion``
  events (trajectories with their ``start`` and ``lane`` on the run's schedule), each
  ``parallel`` on its own, through the independent space-time verifier
  (:func:`taskrunner.collision.spacetime.verify_lanes`, no clearance asked: any contact
  is a miss): robot links and the objects each arm held during each motion (the
  attached objects of the scene the motion started in, as the record has them: each
  moves with its link) against the other arm's, and an object an arm set down (or took)
  in the ``parallel`` where it lay then (:mod:`taskrunner.collision.held`): one put down
  in the other arm's way is a miss. A record that does not say what was held (its
  ``motion`` events' ``scene`` without ``objects``) is verified on the links alone, and
  :func:`arm_conflicts` says so.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import py_trees
from py_trees.behaviour import Behaviour
from py_trees.common import Status

from taskrunner.collision.spacetime import Lane, TimedMotion, verify_lanes
from taskrunner.errors import MissingMeshError, TaskrunnerError
from taskrunner.robot import RobotModel
from taskrunner.runtime.events import RunEvent
from taskrunner.runtime.replay import object_of
from taskrunner.scene import Scene, SceneObject
from taskrunner.shapes import Mesh, Shape
from taskrunner.tasks.expect import (
    DurationBounds,
    Expectation,
    GroupExpectation,
    ObjectExpectation,
    TaskExpectation,
)
from taskrunner.tree.behaviours import TaskLeaf
from taskrunner.tree.context import TaskContext
from taskrunner.tree.outcome import Orientation, Tolerance, describe_pose, measure
from taskrunner.tree.schedule import concurrent
from taskrunner.types import JointTrajectory

__all__ = ["CheckExpectation", "StepTimer", "arm_conflicts", "check_expectation",
           "check_task_end", "motion_collisions", "record_lanes"]


class StepTimer(py_trees.decorators.Decorator):
    """Passes its child's status through and notes its task-time start and end (s)."""

    def __init__(self, child: Behaviour, ctx: TaskContext) -> None:
        super().__init__(name=child.name, child=child)
        self.ctx = ctx
        self.started: float | None = None
        self.ended: float | None = None

    def initialise(self) -> None:
        self.started, self.ended = self.ctx.clock.now(), None

    def update(self) -> Status:
        status = self.decorated.status
        if status != Status.RUNNING:
            self.ended = self.ctx.clock.now()
        return status

    @property
    def seconds(self) -> float | None:
        """The child's duration in task time, once it has ended."""
        if self.started is None or self.ended is None:
            return None
        return self.ended - self.started


def _object(ctx: TaskContext, name: str, want: ObjectExpectation) -> list[str]:
    scene = ctx.scene
    misses: list[str] = []
    if want.pose is not None:
        wanted = scene.to_world(want.pose.to_pose())
        tolerance = Tolerance(want.tolerance.position, math.radians(want.tolerance.angle_deg))
        outcome = measure(scene, name, wanted, Orientation(want.checked_orientation), tolerance,
                          supported=False)
        failure = outcome.failure
        if failure is not None:
            where = f" (expected in frame {want.pose.frame!r})" if want.pose.frame != "world" \
                else ""
            misses.append(failure.replace("requested", "expected").replace(
                "achieved", "observed") + where)
    obj = scene.object(name)
    holder = obj.attached_to
    if want.held_by is not None:
        link = ctx.arm(want.held_by).holder if want.held_by in _arms(ctx) \
            else want.held_by
        if holder != link:
            held = f"attached to {holder!r}" if holder else "attached to nothing"
            misses.append(f"{name!r} expected held by {want.held_by!r} (link {link!r}); "
                          f"observed {held}")
    if want.released and holder is not None:
        misses.append(f"{name!r} expected released; observed attached to {holder!r}")
    if want.on is not None:
        if holder is not None:
            misses.append(f"{name!r} expected on {want.on!r}; observed attached to {holder!r}")
        else:
            support = scene.support(name)
            if support.below != want.on or support.gap > want.tolerance.position:
                seen = ("resting on nothing within 1 m" if support.below is None else
                        f"{1e3 * support.gap:.1f} mm above {support.below!r}")
                misses.append(f"{name!r} expected on {want.on!r} (within "
                              f"{1e3 * want.tolerance.position:g} mm); observed {seen} at "
                              f"{describe_pose(scene.object_pose(name).se3)}")
    return misses


def _arms(ctx: TaskContext) -> set[str]:
    model = ctx.scene.robot
    return {g.name for g in model.groups.values() if g.end_effector and g.tip_link}


def _group(ctx: TaskContext, name: str, want: GroupExpectation) -> list[str]:
    model = ctx.scene.robot
    wanted = model.named_state(name, want.at).as_dict() if want.at is not None \
        else dict(want.joints or {})
    q = ctx.scene.state
    index = {j: i for i, j in enumerate(model.joint_names)}
    errors = {j: abs(float(q[index[j]]) - v) for j, v in wanted.items()}
    worst = max(errors, key=lambda j: errors[j])
    if errors[worst] <= want.tolerance:
        return []
    target = f"at {want.at!r}" if want.at is not None else "at the given joint values"
    off = "; ".join(f"{j!r} expected {v:.4f}, observed {float(q[index[j]]):.4f}"
                    for j, v in wanted.items() if errors[j] > want.tolerance)
    return [f"group {name!r} expected {target} (tolerance {want.tolerance:g}); off by "
            f"{errors[worst]:.4f} at most: {off}"]


def _duration(what: str, seconds: float, bounds: DurationBounds,
              clock: str = "task time") -> list[str]:
    low = bounds.min is not None and seconds < bounds.min
    high = bounds.max is not None and seconds > bounds.max
    if low or high:
        return [f"{what} expected {bounds}; observed {seconds:.3f} s ({clock})"]
    return []


def motion_collisions(ctx: TaskContext, start: int = 0) -> list[str]:
    """Each executed motion from index ``start`` on that collides, re-checked along its
    whole trajectory from the scene it started in: ``'node' (file:line): a, b at t s``.
    The arms of branches running beside a motion are left out (module text)."""
    if len(ctx.executed) <= start:
        return []
    model = ctx.scene.robot
    scene = Scene(model)
    from taskrunner.planning.warmup import exact_path_verifier

    found = []
    for motion in ctx.executed[start:]:
        scene.restore(motion.scene)
        beside = {n for other in ctx.executed if concurrent(other.lane, motion.lane)
                  for n in other.trajectory.names}
        if beside:
            _ignore_arms(scene, beside, set(motion.trajectory.names))
        base = np.asarray(motion.scene.state.positions, dtype=float)
        traj = motion.trajectory
        states = np.array([model.state_with(base, dict(zip(traj.names, row)))
                           for row in traj.positions])
        result = exact_path_verifier(scene).verify(states)
        if not result.valid:
            where = f" ({motion.location})" if motion.location else ""
            at = ""
            if result.fraction is not None:
                k = min(int(result.fraction), len(traj.times) - 1)
                t = float(traj.times[k]) + (result.fraction - k) * (
                    float(traj.times[min(k + 1, len(traj.times) - 1)]) - float(traj.times[k]))
                at = f" at {t:.2f} s of its trajectory"
            # geometry names are 'body/index': the bodies are what a reader knows
            pair = " and ".join(g.rsplit("/", 1)[0] for g in result.pair) if result.pair \
                else "two bodies"
            found.append(f"motion {motion.node!r}{where} collides: {pair}{at}")
    return found


def _carried(model: RobotModel, joints: set[str]) -> set[str]:
    """The links a joint of ``joints``, or a joint carrying one of them, carries."""
    pin_model = model.model
    chain: set[int] = set()
    for name in joints:
        jid = int(pin_model.getJointId(name))
        while jid > 0:
            chain.add(jid)
            jid = int(pin_model.parents[jid])
    links = set()
    names = set(model.link_names)
    for frame in pin_model.frames:
        jid = int(frame.parentJoint)
        while jid > 0 and jid not in chain:
            jid = int(pin_model.parents[jid])
        if jid > 0 and str(frame.name) in names:
            links.add(str(frame.name))
    return links


def _ignore_arms(scene: Scene, beside: set[str], own: set[str]) -> None:
    """Allow every body the joints ``beside`` carry (links, objects held) to touch every
    body ``own`` carries: those pairs are checked in time instead (:func:`arm_conflicts`)."""
    model = scene.robot

    def bodies(links: set[str]) -> set[str]:
        held = {o.name for link in links for o in scene.attached_objects(link)}
        return links | held

    theirs, mine = bodies(_carried(model, beside)), bodies(_carried(model, own))
    for a in theirs:
        for b in mine - theirs:
            scene.allow_collision(a, b, reason="checked in time")


def record_lanes(model: RobotModel, events: list[RunEvent],
                 shapes: Mapping[str, Shape] | None = None) -> list[tuple[Scene, list[Lane]]]:
    """Each ``parallel`` of a run's ``motion`` events as the verifier's lanes, with the
    scene it started in: the robots alone, their joints where the record says they were
    when its first motion was sent; a motion at its real start, up to where a
    stop-and-go stopped it (its ``wait`` event's ``stopped``), holding what the scene it
    started in had attached (:attr:`TimedMotion.held`; None where the record does not
    say: links against links).

    Args:
        shapes: object shapes by name (the cell's, the run's scene's): a mesh the record
            names by its file name only is taken from here.

    Raises:
        MissingMeshError: a held mesh object neither in ``shapes`` nor at its recorded
            file.
    """
    instances: dict[int, dict[tuple[tuple[int, int], ...], list[TimedMotion]]] = {}
    first_state: dict[int, dict[str, float]] = {}
    sent: dict[tuple[str | None, str | None], tuple[list[TimedMotion], int]] = {}
    for event in events:
        stopped = event.data.get("stopped") if event.kind == "wait" else None
        if stopped is not None and (event.node, event.location) in sent:
            # Stopped short (stop-and-go): it moved up to there, and its rest is a motion
            # of its own, sent later.
            motions, index = sent[(event.node, event.location)]
            motion = motions[index]
            motions[index] = TimedMotion(_cut_at(motion.trajectory, float(stopped)),
                                         motion.start, motion.label, motion.held)
            continue
        lane = tuple(tuple(k) for k in event.data.get("lane") or ()) if event.kind == "motion" \
            else ()
        if not lane or "trajectory" not in event.data:
            continue
        data = event.data["trajectory"]
        positions = np.asarray(data["positions"], dtype=float)
        trajectory = JointTrajectory(tuple(data["joints"]), np.asarray(data["times"], float),
                                     positions, np.asarray(data["velocities"], float),
                                     np.zeros_like(positions))
        start = event.data.get("sent", event.data.get("start"))  # when it really started
        motion = TimedMotion(trajectory, float(start or 0.0), event.location or event.node,
                             _held(model, event.data.get("scene") or {},
                                   event.data.get("touch") or {}, shapes or {}))
        key = tuple((int(a), int(b)) for a, b in lane)
        listed = instances.setdefault(key[0][0], {}).setdefault(key, [])
        sent[(event.node, event.location)] = (listed, len(listed))
        listed.append(motion)
        first_state.setdefault(key[0][0], (event.data.get("scene") or {}).get("joints", {}))
    out = []
    for instance, lanes in instances.items():
        scene = Scene(model)  # the robots, and what each motion says its arm held
        scene.set_state(model.state_with(scene.state, first_state[instance]))
        out.append((scene, [Lane(f"branch {'.'.join(str(b) for _, b in key)}",
                                 tuple(motions)) for key, motions in lanes.items()]))
    return out


def _held(model: RobotModel, scene: dict[str, Any], touch: dict[str, list[str]],
          shapes: Mapping[str, Shape]) -> tuple[SceneObject, ...] | None:
    """The attached objects of a recorded scene (None: the record has no ``objects``),
    each with the links ``touch`` says it may touch, a mesh recorded by its file name
    resolved from ``shapes`` (by object name)."""
    if "objects" not in scene:
        return None
    held = []
    for data in scene["objects"]:
        if not data.get("attached_to"):
            continue
        obj = object_of(data)
        links = tuple(n for n in touch.get(obj.name, ()) if model.has_link(n)
                      and n != obj.attached_to)
        obj = SceneObject(obj.name, obj.shape, obj.pose, obj.attached_to, links)
        if isinstance(obj.shape, Mesh) and not obj.shape.path.is_file():
            known = shapes.get(obj.name)
            if not (isinstance(known, Mesh) and known.path.name == obj.shape.path.name):
                raise MissingMeshError(f"held object {obj.name!r}: mesh "
                                       f"{str(obj.shape.path)!r} of the record not found "
                                       f"(and not a mesh of that name in the scene)")
            obj = SceneObject(obj.name, Mesh(Path(known.path), obj.shape.scale), obj.pose,
                              obj.attached_to, obj.touch_links)
        held.append(obj)
    return tuple(held)


def _cut_at(trajectory: JointTrajectory, until: float) -> JointTrajectory:
    """``trajectory`` up to ``until`` s (its last sample there: where the arm stopped)."""
    times, positions = trajectory.times, trajectory.positions
    if until >= times[-1]:
        return trajectory
    until = max(until, 0.0)
    end = np.array([np.interp(until, times, positions[:, j]) for j in range(positions.shape[1])])
    keep = times < until
    new_times, rows = np.append(times[keep], until), np.vstack([positions[keep], end])
    if len(new_times) < 2:  # stopped at its first sample
        new_times, rows = np.array([0.0, 1e-6]), np.vstack([end, end])
    zeros = np.zeros_like(rows)
    return JointTrajectory(trajectory.names, new_times, rows, zeros, zeros)


def arm_conflicts(model: RobotModel, events: list[RunEvent],
                  shapes: Mapping[str, Shape] | None = None,
                  notes: list[str] | None = None) -> list[str]:
    """Arm against arm in time, from a run's ``motion`` events (module text): one message
    per ``parallel`` whose branches' bodies (links, held objects) touch, naming both
    steps and the bodies.

    Args:
        shapes: as :func:`record_lanes`.
        notes: where a parallel's record does not say what its arms held, a line saying
            so is appended here (it is verified on the links alone).
    """
    misses = []
    try:
        recorded = record_lanes(model, events, shapes)
    except TaskrunnerError as exc:
        return [f"arms not verified against each other in time: {exc}"]
    for scene, lanes in recorded:
        unknown = [m.label for lane in lanes for m in lane.motions if m.held is None]
        if unknown and notes is not None:
            notes.append(f"the record does not say what the arms held in the parallel of "
                         f"{unknown[0] or 'a motion'}: its arms verified on their links "
                         f"alone")
        try:
            found = verify_lanes(scene, lanes)
        except TaskrunnerError as exc:
            misses.append(f"arms not verified against each other in time: {exc}")
            continue
        if found.conflict is not None:
            misses.append(f"arms collide in a parallel: {found.conflict.describe()}")
    return misses


def check_expectation(ctx: TaskContext, want: Expectation, step_seconds: float | None = None,
                      collisions_from: int = 0) -> list[str]:
    """What of ``want`` does not hold now, one message each (empty: all hold).

    Args:
        step_seconds: task time of the step before (for ``step_duration``).
        collisions_from: re-check executed motions from this index on.
    """
    misses: list[str] = []
    try:
        for name, obj in want.objects.items():
            misses += _object(ctx, name, obj)
        for name, group in want.groups.items():
            misses += _group(ctx, name, group)
    except TaskrunnerError as exc:  # an object removed, a name the check missed
        misses.append(str(exc))
    if want.duration is not None:
        misses += _duration("the run's duration", ctx.clock.now(), want.duration)
    if want.motion_time is not None:
        misses += _duration("the run's motion time", ctx.clock.motion_time(),
                            want.motion_time, "task time while a motion ran")
    if want.step_duration is not None:
        if step_seconds is None:
            misses.append("the step before has no duration (it did not run to its end)")
        else:
            misses += _duration("the step's duration", step_seconds, want.step_duration)
    if want.collision_free:
        misses += motion_collisions(ctx, collisions_from)
        misses += arm_conflicts(ctx.scene.robot, ctx.events.events(),
                                {o.name: o.shape for o in ctx.scene.objects})
    return misses


class CheckExpectation(TaskLeaf):
    """An ``expect`` step: a condition leaf (see the module docstring)."""

    def __init__(self, name: str, location: str | None, ctx: TaskContext,
                 expectation: Expectation, timer: StepTimer | None = None) -> None:
        super().__init__(name, location, ctx)
        self.expectation = expectation
        self.timer = timer
        self.outcome: Status = Status.RUNNING

    def start(self) -> None:
        misses = check_expectation(self.ctx, self.expectation,
                                   self.timer.seconds if self.timer is not None else None)
        if misses:
            self.outcome = self.fail("expectation not met: " + "; ".join(misses),
                                     kind="execution")
            return
        self.ctx.events.emit("message", "expectations met", node=self.name,
                             location=self.location)
        self.outcome = Status.SUCCESS

    def update(self) -> Status:
        return self.outcome


def check_task_end(expect: TaskExpectation | None, ctx: TaskContext, status: str,
                   error: str | None, location: str | None) -> list[str]:
    """What of the task's ``expect:`` does not hold when the run has ended with ``status``
    (``"succeeded"`` or ``"failed"``) and ``error``; each message starts with
    ``location`` (the ``expect:`` line); all misses in one message, or none. No
    ``expect:``: the run must succeed."""
    want = expect if expect is not None else TaskExpectation()
    prefix = f"{location}: " if location else ""
    misses: list[str] = []
    if status != want.status:
        seen = f"it {status}" + (f" ({error})" if error and status == "failed"
                                 and want.status == "failed" else "")
        misses.append(f"expected the run to have {want.status}; {seen}")
    elif want.error is not None and (error is None or want.error not in error):
        misses.append(f"expected the run's error to contain {want.error!r}; observed {error!r}")
    if expect is not None and not (status == "failed" and want.status == "succeeded"):
        misses += check_expectation(ctx, expect)
    return [prefix + "expectation not met: " + "; ".join(misses)] if misses else []
