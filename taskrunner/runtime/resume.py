"""Resuming a run that stopped (a fault, an operator's stop, a killed process) from where it
stopped, with the world as it is now.

A run's record holds a checkpoint after every leaf that finished
(:mod:`taskrunner.runtime.checkpoint`). :func:`plan_resume` reads them and refuses what
cannot be resumed safely; :meth:`ResumePlan.apply` makes a new :class:`Runner`'s tree
and scene those of the moment the run stopped:

1. **The task**: the task file's text must hash as the record's (``task_sha256``) and the
   compiled tree must have the same shape (``tree_sha256``: an include, the cell or a
   parameter changed it otherwise). Otherwise refused: run the task anew.
2. **The position**: the new tree is ticked through the recorded outcomes of the leaves
   that finished, in order: each such leaf returns its recorded status at once, doing and
   saying nothing, so every ``retry``, ``repeat``, ``fallback``, ``parallel`` and
   sequence reaches the state it had, by its own logic. The leaf that did not finish (the
   leaf that failed, when the run failed) is the first to run again, from its start: a
   motion is planned again from where the arm is now. A pick, place or hand-over resumed
   part of the way through first rebuilds what its earlier leaves worked out (its grasps,
   its release pose: each of its ``MoveToGoal`` leaves' goals computed again in the
   scene they started in), so an interrupted approach goes on to the same grasp.
3. **The world**: the scene is the last checkpoint's (objects, what each arm holds, the
   allowances with their reasons) with the robot's joints as the backend reports them
   (joints moved since: a ``message`` says which, and the next motion is planned from
   there). Held objects: on mock and sim (kinematic, nothing is dropped) as recorded; on
   a physics backend that ran the stopped run (``same_world``: the same process, its
   world goes on) where the simulation has them (within :data:`HELD_GAP` of the gripper:
   still held; else lying where they are); elsewhere the operator says, per held object,
   ``held`` (still in the gripper; a physics backend started afresh, its objects first
   put where the checkpoint has them, puts it back between the fingers where the scene
   holds it and closes them on it, refused if it does not hold),
   ``released`` (no longer: detached where the scene has it) or ``objects`` (lying at a
   pose); a held object nobody vouches for is refused, naming the three options.

``from_step`` (a top-level step's name, or its ``file:line``) resumes at that step
instead, the world as it is now (:mod:`taskrunner.runtime.resume_step`): at the first
time the run reached it, or, a step after where it stopped, skipping the leaves between.
The rest of the task from that step is first dry-run by the check a run gets, from the
real state; a problem refuses the resume with its file:line and reason.

A ``timeout:`` that fired is replayed too (its FAILURE, and the leaves it stopped), so a
fallback stays on the branch it went on with. A ``timeout:`` around the resumed step
counts the new run's time only: the step runs again from its start. The new record
carries the story (:mod:`taskrunner.runtime.story`): the task's ``duration`` expectation
counts the task time of every run of it; ``collision_free`` re-checks the new run's
motions only, and the verdict says so.
"""

from __future__ import annotations

import dataclasses
from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any, Protocol, runtime_checkable

import numpy as np
from py_trees.behaviour import Behaviour
from py_trees.common import Status

from taskrunner.backends.base import ObjectTracking
from taskrunner.errors import BackendError, InputError, TaskrunnerError
from taskrunner.runtime.checkpoint import (
    Checkpoint,
    checkpoints_of,
    held_objects,
    preorder,
    restore_scene,
    scene_state,
    text_sha256,
    tree_sha256,
)
from taskrunner.runtime.resume_step import check_rest, skipped_leaves, top_index, top_step
from taskrunner.runtime.story import Story, StoryClock, story_of
from taskrunner.tree.behaviours import MoveToGoal, TaskLeaf
from taskrunner.tree.grasps import end_lift_off
from taskrunner.tree.timeout import TaskTimeout
from taskrunner.types import Pose

if TYPE_CHECKING:
    from taskrunner.robot.cell import Cell
    from taskrunner.runtime.events import EventLog
    from taskrunner.runtime.records import RunRecord
    from taskrunner.runtime.runner import Runner
    from taskrunner.tasks.expect import TaskExpectation
    from taskrunner.tasks.spec import TaskSpec
    from taskrunner.tree.context import TaskContext

__all__ = ["ResumeOptions", "ResumePlan", "plan_resume"]

KINEMATIC = ("mock", "sim")
"""Backends whose world is the scene itself: nothing falls out of a gripper there."""

JOINT_MOVED = 1e-3  # rad or m: a joint further than this from its checkpoint has moved
HELD_GAP = 0.02  # m: a simulated object this near where its gripper holds it is still held


@dataclass(frozen=True)
class ResumeOptions:
    """What the operator says about the world, and where to resume.

    Attributes:
        objects: objects lying at a pose now (world frame), held before or not.
        released: held objects no longer held (detached where the scene has them).
        held: held objects confirmed still in their gripper.
        from_step: resume at this step (its name, or ``file:line``) instead.
    """

    objects: Mapping[str, Pose] = field(default_factory=dict)
    released: tuple[str, ...] = ()
    held: tuple[str, ...] = ()
    from_step: str | None = None


def _refuse(record: RunRecord, reason: str) -> InputError:
    return InputError(f"cannot resume run {record.run_id}: {reason}")


@dataclass
class ResumePlan:
    """What :func:`plan_resume` found in a record: the outcomes to replay, the world to
    start from. Apply it to a new runner with ``Runner(..., resume=plan)``."""

    record: RunRecord
    backend: str
    options: ResumeOptions
    replay: list[Checkpoint]
    world: Checkpoint | None
    stop_joints: dict[str, float]
    same_world: bool = False
    start_step: int | None = None  # --from: the top-level step the rest is checked from
    skip_to: int | None = None  # --from a step the run had not finished leaves before
    played: list[Checkpoint] = field(default_factory=list)  # replay + skipped, once applied
    story: Story | None = None

    @property
    def run_id(self) -> str:
        return self.record.run_id

    def start_state(self, cell: Cell) -> np.ndarray:
        """Every joint of the cell where the run left the arm (for a simulated backend
        started afresh: mock and sim begin there)."""
        names = cell.model.joint_names
        known = {n: v for n, v in self.stop_joints.items() if n in names}
        return cell.model.state_with(cell.start_state(), known)

    # ------------------------------------------------------------------ applying
    def apply(self, runner: Runner) -> list[str]:
        """Bring ``runner`` (new, not started) to where the run stopped; returns what it
        says about it (``message`` events of the new run).

        Raises:
            InputError: the tree is not the one the record ran, a checkpoint names a
                leaf it does not have, or the world is not known well enough.
        """
        record = self.record
        if record.tree_sha256 and tree_sha256(runner.tree) != record.tree_sha256:
            raise _refuse(record, "the task compiles to another tree than the one it ran "
                          "(an included file, the cell or a parameter changed); run it anew")
        nodes = list(preorder(runner.tree))
        leaves: dict[int, Behaviour] = {}
        for point in self.replay:
            node = nodes[point.leaf] if point.leaf is not None and point.leaf < len(nodes) \
                else None
            kind = TaskTimeout if point.cut else TaskLeaf  # a timeout that fired, a leaf
            cut = [nodes[i] if i < len(nodes) else None for i in point.cut]
            if not isinstance(node, kind) or node.name != point.node \
                    or not all(isinstance(leaf, TaskLeaf) for leaf in cut):
                raise _refuse(record, f"its checkpoint {point.seq} ({point.node!r}) names "
                              "no leaf of this task's tree")
            leaves[point.leaf] = node  # type: ignore[index]
            leaves.update((i, nodes[i]) for i in point.cut)
        start_scene = scene_state(runner.scene)
        notes = [f"resuming run {record.run_id} ({record.status}): "
                 f"the outcomes of its {len(self.replay)} finished leaves kept"]
        if self.world is not None:
            restore_scene(runner.scene, self.world.scene)
        if self._fresh_world(runner):  # its objects are not the run's: the scene's are kept
            state = runner.backend.joint_state()
            runner.scene.set_state(dict(zip(state.names, state.positions)))
        else:
            runner.ctx.sync_from_backend()  # the joints (and simulated objects) as they are now
        notes += self._moved_joints(runner)
        notes += self._reconcile(runner)
        self.played = list(self.replay)
        if self.start_step is not None:
            notes += self._from_step(runner, leaves)
        self._rebuild_goals(runner, leaves, start_scene)
        outcomes: dict[int, list[Status]] = {}
        for point in self.played:
            for index in point.cut:  # running when the timeout fired: stopped, no outcome
                outcomes.setdefault(index, []).append(Status.RUNNING)
            outcomes.setdefault(point.leaf, []).append(Status(point.status))  # type: ignore[arg-type]
        for index, statuses in outcomes.items():
            _Replayed(leaves[index], statuses).install()
        runner.checkpointer.count = len(self.played)  # its own checkpoints count on
        if self.replay:
            last = self.replay[-1]
            notes.append(f"continuing after {last.node!r}"
                         + (f" ({last.location})" if last.location else ""))
        return notes

    def emit_replayed(self, events: EventLog) -> None:
        """Put the replayed leaves' checkpoints in the new run's record (``checkpoint``
        events with ``replayed``: the id of the run that finished them), before any of
        its own: the record of a resumed run is resumable alone, without the records
        before it."""
        if self.story is not None:
            story = self.story
            events.emit("message", f"the story so far: {len(story.runs)} runs, "
                        f"{story.task_time:.2f} s of task time, {story.motions} motions",
                        story=dataclasses.asdict(story))
        for done, point in enumerate(self.played, start=1):
            how = "skipped by --from" if point.skipped else f"replayed from run {self.run_id}"
            events.emit("checkpoint", f"after {point.node} ({how})", node=point.node,
                        location=point.location, status=point.status, leaf=point.leaf,
                        done=done, position=point.position, scene=point.scene,
                        held=point.held, replayed=point.run_id or self.run_id,
                        **({"skipped": True} if point.skipped else {}))

    def story_context(self, ctx: TaskContext) -> TaskContext:
        """``ctx`` for the task's ``expect:`` at the end: its clock reads the task time of
        the runs this one resumes plus its own (``duration`` sees the whole story)."""
        story = self.story
        if story is None:
            return dataclasses.replace(ctx, clock=StoryClock(ctx.clock, 0.0))
        return dataclasses.replace(ctx, clock=StoryClock(ctx.clock, story.task_time,
                                                         story.motion_time))

    def covers(self, ctx: TaskContext, expect: TaskExpectation | None) -> str:
        """What the task's ``duration`` and ``collision_free`` covered, said after its
        expectations' verdict (empty when it has neither)."""
        story = self.story
        if expect is None or story is None or (expect.duration is None
                                               and expect.motion_time is None
                                               and not expect.collision_free):
            return ""
        runs = len(story.runs) + 1
        said = []
        if expect.duration is not None:
            said.append(f"duration: {story.task_time + ctx.clock.now():.1f} s of task time "
                        f"over the {runs} runs of the story ({story.task_time:.1f} s before "
                        "this one)")
        if expect.motion_time is not None:
            said.append(f"motion_time: {story.motion_time + ctx.clock.motion_time():.1f} s "
                        f"over the {runs} runs of the story ({story.motion_time:.1f} s before "
                        "this one)")
        if expect.collision_free:
            said.append(f"collision_free: this run's {len(ctx.executed)} motions (the "
                        f"{story.motions} of the runs it resumes were verified as they "
                        "were planned, not again)")
        return " (" + "; ".join(said) + ")"

    def _from_step(self, runner: Runner, leaves: dict[int, Behaviour]) -> list[str]:
        """``--from``: skip to the step if the run had not finished the leaves before it,
        then check the rest of the task from the world as it is (refused on a problem)."""
        assert self.start_step is not None
        step = self.options.from_step
        notes = []
        if self.skip_to is not None:
            skipped, reason = skipped_leaves(runner, self.replay, self.skip_to)
            if reason is not None:
                raise _refuse(self.record, f"--from {step!r}: cannot skip to it: {reason}")
            nodes = list(preorder(runner.tree))
            for point in skipped:
                leaves[point.leaf] = nodes[point.leaf]  # type: ignore[index]
            self.played += skipped
            if skipped:
                notes.append(f"--from {step!r}: {len(skipped)} leaves the run never finished "
                             f"skipped ({', '.join(p.node for p in skipped[:4])}"
                             f"{' …' if len(skipped) > 4 else ''})")
        problems = check_rest(runner, self.start_step)
        if problems:
            more = f" (and {len(problems) - 2} more)" if len(problems) > 2 else ""
            raise _refuse(self.record, f"--from {step!r}: the rest of the task does not check "
                          "from where the robot and the objects are now: "
                          + "; ".join(map(str, problems[:2])) + more)
        notes.append(f"--from {step!r}: the rest of the task checked from where the robot "
                     "and the objects are now: no problem")
        return notes

    def _moved_joints(self, runner: Runner) -> list[str]:
        if self.world is None:
            return []
        recorded = self.world.scene.get("joints", {})
        now = dict(zip(runner.scene.robot.joint_names, runner.scene.state.tolist()))
        moved = [f"{n} {now[n] - v:+.4f}" for n, v in recorded.items()
                 if n in now and abs(now[n] - v) > JOINT_MOVED]
        if not moved:
            return []
        return ["joints not where the last finished step left them (planned from where "
                "they are): " + ", ".join(moved[:8]) + (" …" if len(moved) > 8 else "")]

    def _reconcile(self, runner: Runner) -> list[str]:
        """The held objects of the checkpoint against what the operator says (module
        text, point 3); the scene edited to match."""
        scene, record, options = runner.scene, self.record, self.options
        held = held_objects(runner.ctx)
        said = [*options.objects, *options.released, *options.held]
        for name in said:
            if name not in scene.object_names:
                raise _refuse(record, f"no object {name!r} in its scene (objects: "
                              f"{', '.join(scene.object_names) or 'none'})")
        for name in (*options.released, *options.held):
            if name not in held:
                raise _refuse(record, f"{name!r} was not held when it stopped "
                              f"(held: {', '.join(held) or 'nothing'}); drop --released/"
                              f"--held {name}")
        notes: list[str] = []
        fresh = self._fresh_world(runner)
        if fresh and not isinstance(runner.backend, SceneMatching):
            raise _refuse(record, f"the {self.backend} backend's new simulated world cannot "
                          "be made the one the run left: resume it in the process that ran "
                          f"it (TaskRun.resume, POST /runs/{record.run_id}/resume)")
        regrip: dict[str, str] = {}  # said held, in a simulated world that never held them
        for name, arm in held.items():
            if name in options.released or name in options.objects:
                scene.detach_object(name)
                end_lift_off(scene, name)  # as a detach step does
                notes.append(f"{name!r} no longer held by {arm!r} (the operator says so)")
            elif name in options.held and fresh:
                regrip[name] = arm
            elif name in options.held:
                notes.append(f"{name!r} still held by {arm!r} (the operator says so)")
            elif self.backend in KINEMATIC:
                notes.append(f"{name!r} still held by {arm!r} (the {self.backend} backend "
                             "drops nothing)")
            elif self.same_world and isinstance(runner.backend, ObjectTracking) \
                    and name in (seen := runner.backend.object_poses()):
                gap = float(np.linalg.norm(np.subtract(seen[name].xyz,
                                                       scene.object_pose(name).xyz)))
                if gap <= HELD_GAP:
                    notes.append(f"{name!r} still held by {arm!r} (the simulated world has "
                                 f"it {1e3 * gap:.0f} mm from where it is held)")
                    continue
                scene.detach_object(name)
                end_lift_off(scene, name)
                scene.move_object(name, seen[name])
                notes.append(f"{name!r} no longer held by {arm!r}: the simulated world has it "
                             f"at {tuple(round(v, 4) for v in seen[name].xyz)}, "
                             f"{100 * gap:.0f} cm from the gripper")
            else:
                raise _refuse(record, f"{name!r} was held by {arm!r} when it stopped and "
                              f"the {self.backend} backend cannot tell whether it still is: "
                              f"pass --held {name} if it is, --released {name} if it is not, "
                              f"or --object {name}=X,Y,Z[,QX,QY,QZ,QW] where it lies")
        for name, pose in options.objects.items():
            scene.move_object(name, pose)
            notes.append(f"{name!r} at {tuple(round(v, 4) for v in pose.xyz)} (the operator "
                         "says so)")
        if fresh:
            notes += self._match_world(runner, regrip)
        return notes

    def _match_world(self, runner: Runner, held: dict[str, str]) -> list[str]:
        """A simulated world started afresh made the scene's: its objects where the scene
        has them, those the operator says are ``held`` back in the grip of their arms (the
        fingers driven to their closed pose); refused when the simulation does not hold
        them."""
        backend = runner.backend
        assert isinstance(backend, SceneMatching) and isinstance(backend, ObjectTracking)
        backend.bind_scene(runner.scene, runner.ctx.materials)
        closed: dict[str, float] = {}
        for arm_name in sorted(set(held.values())):
            try:
                arm = runner.ctx.arm(arm_name)
                if arm.gripper is not None:
                    closed.update(runner.scene.robot.named_state(
                        arm.gripper, arm.closed_pose).as_dict())
            except TaskrunnerError:  # held by a link of no arm (suction): welded, no fingers
                continue
        names = ", ".join(map(repr, held))
        which = next(iter(held)) if len(held) == 1 else "NAME"
        try:
            said = backend.match_scene(closed)
        except BackendError as exc:
            raise _refuse(self.record, f"{names} said to be held, but the {self.backend} "
                          f"backend could not grip it again ({exc}); say where it lies with "
                          f"--object {which}=X,Y,Z and resume --from the step that picks "
                          "it") from None
        runner.ctx.sync_from_backend()  # the world now the scene's
        return [note + (" (the operator says it is held)"
                        if any(note.startswith(repr(name)) for name in held) else "")
                for note in said]

    def _fresh_world(self, runner: Runner) -> bool:
        """Whether ``runner``'s backend simulates a world started afresh (a physics
        backend in a new process), whose objects are not where the run left them."""
        return self.backend not in KINEMATIC and not self.same_world \
            and isinstance(runner.backend, ObjectTracking)

    def _rebuild_goals(self, runner: Runner, leaves: dict[int, Behaviour],
                       start_scene: dict[str, Any]) -> None:
        """Compute again the goals of the replayed ``MoveToGoal`` leaves of a subtree the
        run was part of the way through (what a pick, place or hand-over keeps for its
        later leaves), each in the scene it started in."""
        last: dict[int, int] = {}
        for position, point in enumerate(self.played):
            last[point.leaf] = position  # type: ignore[index]
        index = {node.id: i for i, node in enumerate(preorder(runner.tree))}
        for leaf_index, position in last.items():
            leaf = leaves[leaf_index]
            parent = leaf.parent
            if not isinstance(leaf, MoveToGoal) or parent is None \
                    or self.played[position].status != Status.SUCCESS.value:
                continue
            after = parent.children[parent.children.index(leaf) + 1:]
            if not after or all(last.get(index[s.id], -1) > position for s in after):
                continue  # the subtree went past it: nothing later needs its goals
            before = self.played[position - 1].scene if position > 0 else start_scene
            scene = runner.scene.copy()
            restore_scene(scene, before)
            shadow = dataclasses.replace(runner.ctx, scene=scene)
            try:
                leaf.goal_list(shadow)
            except TaskrunnerError as exc:
                raise _refuse(self.record, f"the goals of {leaf.name!r} ({leaf.location}) "
                              f"cannot be computed again: {exc}") from None


@runtime_checkable
class SceneMatching(Protocol):
    """A simulated backend whose world can be made its bound scene's, objects held in a
    grip it never made (:meth:`~taskrunner.backends.physics.MujocoBackend.match_scene`)."""

    def match_scene(self, closed: Mapping[str, float] | None = None) -> list[str]:
        ...


class _Replayed:
    """A finished leaf ticked again on resume: it returns its recorded outcomes one
    after another, at once, doing and saying nothing; then it is itself again. An outcome
    RUNNING is a leaf a ``timeout:`` stopped: it runs until its timeout (replayed too)
    stops it, in the same tick. A fired timeout is replayed the same way (its FAILURE).

    Its ``initialise``, ``update`` and ``terminate`` are shadowed on the instance while
    outcomes are left (py_trees calls them through the instance), not changed in its
    class.
    """

    HOOKS = ("initialise", "update", "terminate")

    def __init__(self, leaf: Behaviour, outcomes: list[Status]) -> None:
        self.leaf = leaf
        self.outcomes = list(outcomes)

    def install(self) -> None:
        for hook in self.HOOKS:
            setattr(self.leaf, hook, getattr(self, hook))

    def initialise(self) -> None:
        pass

    def update(self) -> Status:
        return self.outcomes[0]

    def terminate(self, new_status: Status) -> None:
        if self.outcomes[0] == Status.RUNNING:  # cut short: stopped while it ran
            if new_status != Status.INVALID or self.leaf.status != Status.RUNNING:
                return
        elif new_status not in (Status.SUCCESS, Status.FAILURE):
            return  # reset by its parent: not one of its outcomes
        self.outcomes.pop(0)
        if not self.outcomes:
            for hook in self.HOOKS:
                delattr(self.leaf, hook)


# ----------------------------------------------------------------------------- planning
def plan_resume(record: RunRecord, spec: TaskSpec, options: ResumeOptions | None = None,
                same_world: bool = False) -> ResumePlan:
    """Read what resuming ``record`` takes, with ``spec`` loaded from its task file with
    its parameters; refuse what cannot be resumed safely. ``same_world``: the run resumed
    on the backend that ran it, whose simulated world (a physics backend's) went on.

    Raises:
        InputError: the run succeeded or still runs, it has no checkpoints (recorded
            before they were kept), its task file changed, or ``from_step`` is not a step
            it reached; each message says what to do instead.
    """
    options = options or ResumeOptions()
    if record.status == "succeeded":
        raise _refuse(record, "it succeeded: there is nothing left to do")
    if record.status == "running":
        raise _refuse(record, "it is still running (cancel it first, or wait for its end)")
    if not record.task_sha256:
        raise _refuse(record, "its record has no checkpoints (recorded by an older "
                      "version); run the task anew")
    text = spec.path.read_text(encoding="utf-8") if spec.path is not None else None
    if text is not None and text_sha256(text) != record.task_sha256:
        raise _refuse(record, f"the task file {record.task_file} changed since it ran; "
                      "restore it as it was (the record keeps its text in 'task_text') or "
                      "run the task anew")
    points = checkpoints_of(record)
    for point in points:
        if point.leaf is None:
            raise _refuse(record, f"its checkpoint {point.seq} cannot tell which leaf "
                          f"{point.node!r} was (two leaves of that name at "
                          f"{point.location}); run the task anew")
    world = points[-1] if points else None
    replay = list(points)
    if record.status == "failed" and replay and replay[-1].status == Status.FAILURE.value:
        replay.pop()  # the leaf whose failure ended the run runs again
    start_step = skip_to = None
    if options.from_step is not None:
        start_step = top_step(spec, options.from_step)
        if start_step is None:
            steps = ", ".join(repr(s.label) for s in spec.steps)
            raise _refuse(record, f"--from {options.from_step!r}: no step of that name or "
                          f"file:line at the task's top level (its steps: {steps}); to go "
                          "on inside a step, resume without --from")
        first = next((i for i, p in enumerate(replay) if top_index(p) == start_step), None)
        if first is not None:  # reached: back to it
            replay = replay[:first]
        else:  # not finished before: skip to it
            skip_to = start_step
    return ResumePlan(record, record.backend, options, replay, world, _stop_joints(record),
                      same_world, start_step, skip_to, story=story_of(record))


def _stop_joints(record: RunRecord) -> dict[str, float]:
    """The joints where the run left the arm: its final scene's, else its last
    checkpoint's, else its first scene's."""
    for event in reversed(record.events):
        if event.kind in ("run_finished", "checkpoint", "run_started"):
            joints = (event.data.get("scene") or {}).get("joints")
            if joints:
                return {str(n): float(v) for n, v in joints.items()}
    return {}
