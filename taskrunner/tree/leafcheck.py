"""The check mode of a compiled task's leaves: each leaf plans but does not move.

``run-task check`` (:mod:`taskrunner.tree.check`) plays the leaves a run would tick, on
the scene the task is in at that step, without OMPL and without a backend: a
:class:`~taskrunner.tree.behaviours.MoveToGoal` becomes its goal states as the planner
makes them (IK seeded as in the run) checked for collisions and joint limits, and the
robot is put at the state followed (the "move" is instant); a
:class:`~taskrunner.tree.behaviours.MoveStraight` runs the leaf's own Cartesian
computation and times the path as a run does before it moves; a
:class:`~taskrunner.tree.behaviours.MoveJoints` checks its joint-space line; a
:class:`~taskrunner.tree.instant_leaves.SceneAction` edits the scene; a
:class:`~taskrunner.tree.instant_leaves.CheckOutcome` measures with the run's own measure.
Of several collision-free goal states the one the run's planner goes to when left to
itself (the first whose straight line is free; else the first) is followed and, where
the rest of the step fails from it, the others; the state followed is remembered as the
run's choice (:mod:`taskrunner.tree.choice`). After a failure, :meth:`LeafPlayer.force`
finishes the leaves without checks so that later steps start about where a run would
leave them.
"""

from __future__ import annotations

import math
import re
from collections.abc import Hashable, Iterable
from dataclasses import dataclass, replace
from typing import Any

import numpy as np
import pinocchio as pin
import py_trees
from py_trees.behaviour import Behaviour

from taskrunner.errors import (
    IkFailedError,
    StartInCollisionError,
    TaskrunnerError,
)
from taskrunner.kinematics import IkSolver
from taskrunner.planning.cartesian import CartesianPlanner
from taskrunner.planning.goal_states import goal_states
from taskrunner.planning.request import PlannerOptions, PoseGoal
from taskrunner.robot.cell import Cell
from taskrunner.robot.model import Group
from taskrunner.scene import Contact, Scene
from taskrunner.scene.geometry import MeshCache
from taskrunner.tasks import StepNode
from taskrunner.tree.behaviours import MoveJoints, MoveStraight, MoveToGoal
from taskrunner.tree.choice import remember
from taskrunner.tree.context import TaskContext
from taskrunner.tree.instant_leaves import CheckOutcome, SceneAction, Wait
from taskrunner.tree.occupancy import target_overlap
from taskrunner.tree.outcome import Outcome
from taskrunner.tree.reach import StagedGoals
from taskrunner.types import JointPath

__all__ = ["MAX_GOAL_STATES", "LeafFailure", "LeafPlayer", "Motion", "describe_pairs", "leaves_of"]

MAX_GOAL_STATES = 8
"""Goal states of one ``MoveToGoal`` tried, in the planner's order, to see whether any
lets the rest of its step succeed."""

Motion = tuple[Behaviour, np.ndarray, np.ndarray, JointPath | None]
"""A motion the check made: the leaf, its start and end states, and its path (None: the
straight joint line from start to end)."""


def describe_pairs(contacts: Iterable[Contact | tuple[str, str]], scene: Scene | None = None) -> str:
    """``a–b, c–d and 2 more``, then the robot links' geometry when ``scene`` is given."""
    pairs = [(c.a, c.b) if isinstance(c, Contact) else c for c in contacts]
    shown = ", ".join(f"{a}–{b}" for a, b in pairs[:3])
    geometry = scene.link_geometry.describe(n for p in pairs[:3] for n in p) if scene else ""
    return (shown + (f" and {len(pairs) - 3} more" if len(pairs) > 3 else "")
            + (f"; {geometry}" if geometry else ""))


def _miss(exc: IkFailedError) -> str:
    """``best residual … for 'frame' at (x, y, z)`` from an IK failure's message."""
    residual = f"best residual {exc.best_error if exc.best_error is not None else math.nan:.3g}"
    found = re.search(r"frame '([^']+)', target (position |pose xyz=)\(([^)]*)\)", str(exc))
    if found is None:
        return residual
    xyz = ", ".join(f"{float(v):.3f}" for v in found[3].split(","))
    unit = " m" if found[2] == "position " else " (m and rad)"
    return f"{residual}{unit} for {found[1]!r} at ({xyz})"



def leaves_of(behaviour: Behaviour) -> list[Behaviour]:
    if isinstance(behaviour, py_trees.composites.Sequence):
        return [leaf for child in behaviour.children for leaf in leaves_of(child)]
    return [behaviour]


def _stage(leaf: Behaviour, step: StepNode) -> str | None:
    """The part of an idiom a leaf plays (``approach``), or None for a step's one leaf."""
    prefix = f"{step.label}: "
    return leaf.name[len(prefix):] if leaf.name.startswith(prefix) else None


def _goal_word(stage: str | None) -> str:
    """What a MoveToGoal stage aims at: ``target``, ``pre-grasp``, ``right_arm pre-grasp``."""
    if stage is None:
        return "target"
    if stage.startswith("to "):
        return stage[3:]
    return stage.replace(" to ", " ", 1) if " to " in stage else f"{stage}: target"


def _moved(ctx: TaskContext, q: np.ndarray) -> TaskContext:
    """A copy of ``ctx`` on a copy of its scene, the robot at state ``q``."""
    branch = replace(ctx, scene=ctx.scene.copy())
    branch.scene.set_state(q)
    return branch


@dataclass(frozen=True)
class LeafFailure:
    """Why a step's leaves stopped: at leaf ``leaf``, in the situation ``ctx``."""

    leaf: int
    text: str
    ctx: TaskContext


class _Unreachable(Exception):
    """No goal of a MoveToGoal has an IK solution (control flow inside this module)."""


def _planners_first(states: list[np.ndarray], start: np.ndarray, options: PlannerOptions,
                    scene: Scene) -> list[np.ndarray]:
    """``states`` (collision-free goal states in the planner's order) with the one a
    planner left to itself goes to put first: with ``options.direct``, the first whose
    straight joint-space line from ``start`` passes the planner's exact verification
    (:meth:`~taskrunner.planning.planner.MotionPlanner.verify_states`, the same
    ``verify_margin``); the others keep their order. Where no line is free the planner
    searches, and whichever goal its search reaches cannot be told here: the order stays.

    Why: a run without the check's remembered choice (another process, a physics
    backend's situation off the check's) goes where its planner goes, and the step
    after it starts there. Following the first collision-free state instead, the check
    judged later steps from a state no run reaches: 12 of 36 receiver grasp offsets of
    ``handoff_so101`` were refused by the check (a hand-over or a set-down blocked) while
    the run, having picked the bar up rolled the other way, succeeded.
    """
    if not options.direct or len(states) < 2:
        return states
    verifier = scene.path_verifier(options.verify_margin)
    for i, q in enumerate(states):
        if verifier.verify(np.vstack([start, q])).valid:
            return [q, *states[:i], *states[i + 1:]] if i else states
    return states




class LeafPlayer:
    """Plays compiled leaves in check mode (module docstring), keeping what a step-level
    check needs: the motions made (:attr:`trace`), the last outcome measured, and whether
    the state comes from a failed step (:attr:`tainted`: its start is not blamed)."""

    def __init__(self, cell: Cell) -> None:
        self.cell = cell
        self.outcome: Outcome | None = None  # of the last CheckOutcome leaf played
        self.tainted = False  # the state comes from a failed step: do not blame its start
        self._ik: dict[tuple[str, str | None], IkSolver] = {}
        self._meshes = MeshCache()
        # The motions played, in order: what a parallel's branches are scheduled from.
        self.trace: list[Motion] = []

    def overlap(self, scene: Scene, name: str, target: pin.SE3) -> Contact | None:
        """:func:`~taskrunner.tree.occupancy.target_overlap` (the place idiom's own check)."""
        return target_overlap(scene, name, target, self._meshes)


    # ------------------------------------------------------------------ playing leaves
    def play(self, leaves: list[Behaviour], index: int, step: StepNode, ctx: TaskContext,
             explore: bool = True) -> tuple[TaskContext, LeafFailure | None]:
        """Play ``leaves[index:]`` on ``ctx`` (its scene edited in place). At a MoveToGoal,
        go on from its first goal state; when the rest fails from there and ``explore``,
        try the other goal states (each followed through first goal states only) and go
        on from the first that lets the rest succeed. The state followed is remembered as
        the run's choice (:mod:`taskrunner.tree.choice`)."""
        while index < len(leaves):
            leaf, stage = leaves[index], _stage(leaves[index], step)
            if not isinstance(leaf, MoveToGoal):
                text = self.apply(leaf, stage, ctx)
                if text is not None:
                    return ctx, LeafFailure(index, text, ctx)
                index += 1
                continue
            found = self.goal_states(leaf, stage, ctx)
            if isinstance(found, str):
                return ctx, LeafFailure(index, found, ctx)
            states, key = found
            model = ctx.scene.robot
            # The state followed is the run's choice (taskrunner.tree.choice): the first,
            # or the first other one from which the rest of the step succeeds.
            if key is not None:
                remember(model, key, states[0])
            mark, start = len(self.trace), ctx.scene.state
            self.trace.append((leaf, start, states[0], None))
            end, first = self.play(leaves, index + 1, step, _moved(ctx, states[0]), explore)
            if first is None or not explore:
                return end, first
            for q in states[1:]:
                if key is not None:
                    remember(model, key, q)
                del self.trace[mark:]
                self.trace.append((leaf, start, q, None))
                other_end, failed = self.play(leaves, index + 1, step, _moved(ctx, q), False)
                if failed is None:
                    return other_end, None
            if key is not None:
                remember(model, key, states[0])
            return end, first
        return ctx, None

    def goal_states(self, leaf: MoveToGoal, stage: str | None, ctx: TaskContext
                    ) -> tuple[list[np.ndarray], tuple[Hashable, ...] | None] | str:
        """The collision-free goal states of ``leaf`` in the planner's order (at most
        :data:`MAX_GOAL_STATES`) and the key of the run's choice among them (None: one
        goal state only), or what is wrong."""
        scene, model = ctx.scene, ctx.scene.robot
        lead, word = (f"{stage}: " if stage else ""), _goal_word(stage)
        start = scene.state
        try:
            # The run's own request (its seed the context's next), so IK finds what the
            # run finds.
            found, options, key = leaf.request_goals(ctx)
            goals = found.all() if isinstance(found, StagedGoals) else found
            group = model.group(leaf.group)
            if not self.tainted and scene.in_collision(start):
                return f"{lead}start state in collision ({describe_pairs(scene.collisions(start), scene)})"
            valid: list[np.ndarray] = []
            rejected: list[np.ndarray] = []
            for q in self.candidates(goals if isinstance(goals, tuple) else (goals,), group,
                                     start, options, scene):
                bad = model.limit_violations(q)
                if bad:
                    return f"{lead}goal outside the joint limits: " + "; ".join(bad)
                (rejected if scene.in_collision(q) else valid).append(q)
        except _Unreachable as exc:
            return f"{word} out of reach (IK): {exc}"
        except IkFailedError as exc:  # from a goal function (joint goals it solved for)
            return f"{word} out of reach (IK): {_miss(exc)}"
        except TaskrunnerError as exc:
            return f"{lead}{exc}"
        if not valid:
            return f"{word} in collision ({describe_pairs(scene.collisions(rejected[0]), scene)})"
        return _planners_first(valid, start, options, scene)[:MAX_GOAL_STATES], key

    def candidates(self, goals: tuple[Any, ...], group: Group, start: np.ndarray,
                   options: PlannerOptions, scene: Scene) -> list[np.ndarray]:
        """Goal states of every goal with a solution, as ``MotionPlanner`` makes them
        (:func:`~taskrunner.planning.goal_states.goal_states`).

        Raises:
            _Unreachable: no goal has an IK solution (the message: the nearest miss).
            InvalidStateError: joints that are not the group's.
        """
        out: list[np.ndarray] = []
        misses: list[tuple[float, str]] = []
        for goal in goals:
            try:
                out += goal_states(goal, group, start, options, scene, self.solver)
            except IkFailedError as exc:
                if not isinstance(goal, PoseGoal):
                    raise
                only = group.position_only_ik if goal.position_only is None \
                    else goal.position_only
                world = scene.to_world(goal.pose, start)
                xyz = ", ".join(f"{v:.3f}" for v in world.translation)
                residual = exc.best_error if exc.best_error is not None else math.inf
                unit = "m" if only else "(m and rad)"
                frame = self.solver(group, goal.link).frame
                text = f"best residual {residual:.3g} {unit} for {frame!r} at ({xyz})"
                misses.append((residual, text))
        if not out:
            raise _Unreachable(min(misses)[1])
        return out

    def solver(self, group: Group, link: str | None) -> IkSolver:
        key = (group.name, link)
        if key not in self._ik:
            self._ik[key] = IkSolver(self.cell.model, group, frame=link)
        return self._ik[key]

    def apply(self, leaf: Behaviour, stage: str | None, ctx: TaskContext) -> str | None:
        """Play a leaf that has no goal states to choose; what failed, or None."""
        scene = ctx.scene
        try:
            if isinstance(leaf, MoveStraight):
                return self.straight(leaf, stage, ctx)
            if isinstance(leaf, MoveJoints):
                start = scene.state
                _, goal, bad = leaf.target(ctx)  # the run's own target and checks
                what = {"open": "opening the gripper", "close": "closing the gripper"}.get(
                    stage or "", stage or "gripper motion")
                if bad:
                    return f"{what}: target outside the joint limits: " + "; ".join(bad)
                if leaf.check and not (self.tainted and scene.in_collision(start)):
                    q = leaf.first_collision(ctx, start, goal)
                    if q is not None:
                        return f"{what} collides ({describe_pairs(scene.collisions(q))})"
                self.trace.append((leaf, start, goal, None))
                scene.set_state(goal)
            elif isinstance(leaf, SceneAction):
                leaf.action(ctx)
            elif isinstance(leaf, Wait):  # no motion: its branch's schedule waits there
                self.trace.append((leaf, scene.state, scene.state, None))
            elif isinstance(leaf, CheckOutcome):
                self.outcome = leaf.measure(ctx)  # the run's own measure
                failure = self.outcome.failure
                if failure is not None:
                    return f"{stage}: {failure}" if stage else failure
        except TaskrunnerError as exc:
            return f"{stage}: {exc}" if stage else str(exc)
        return None

    def straight(self, leaf: MoveStraight, stage: str | None, ctx: TaskContext) -> str | None:
        name = stage or "straight move"
        sep = ": " if stage and " " in stage else " "
        if self.tainted and ctx.scene.in_collision():
            self.force([leaf], ctx)  # a start the run would refuse, reported already
            return None
        try:
            result = leaf.compute(ctx)  # the run's own computation (fallback options too)
        except StartInCollisionError as exc:
            return f"{name}: start state in collision ({describe_pairs(exc.pairs, ctx.scene)})"
        if not result.complete:
            verb = "blocked" if result.stop_reason == "collision" else "stopped"
            percent = f"{math.floor(100.0 * result.fraction + 1e-9):.0f} %"
            reason = re.sub(r" at \d+ % of the path", "", result.message)
            reason = re.sub(r" \(and (\d+ more pair\(s\))\)", r", and \1", reason)
            return f"{name}{sep}{verb} at {percent} ({reason})"
        try:  # a run times the path before it moves; toppra can fail where IK did not
            leaf.timed(ctx, result.path)  # the run's own timing
        except TaskrunnerError as exc:
            return f"{name}{sep}cannot be timed ({exc})"
        self.trace.append((leaf, ctx.scene.state, result.end, result.path))
        ctx.scene.set_state(result.end)
        return None

    # ------------------------------------------------------------------ after a failure
    def force(self, leaves: list[Behaviour], ctx: TaskContext) -> bool:
        """Play ``leaves`` without checks (collisions ignored, nothing reported), so that
        later steps start about where the run would have left the robot and the objects;
        False when a goal cannot be reached at all (the objects are then not where the
        task expects them)."""
        scene = ctx.scene
        for leaf in leaves:
            try:
                if isinstance(leaf, MoveToGoal):
                    goals = leaf.goal(ctx)
                    group = scene.robot.group(leaf.group)
                    states = self.candidates(goals if isinstance(goals, tuple) else (goals,),
                                             group, scene.state, leaf.options, scene)
                    free = [q for q in states if not scene.in_collision(q)]
                    scene.set_state((free or states)[0])
                elif isinstance(leaf, MoveStraight):
                    options = replace(leaf.options, avoid_collisions=False)
                    result = CartesianPlanner(scene).compute(
                        leaf.group, list(leaf.waypoints(ctx)), link=leaf.link, options=options)
                    scene.set_state(result.end)
                elif isinstance(leaf, MoveJoints):
                    scene.set_state(leaf.target(ctx)[1])
                elif isinstance(leaf, SceneAction):
                    leaf.action(ctx)
            except (_Unreachable, IkFailedError):
                return False
            except TaskrunnerError:
                continue
        return True


