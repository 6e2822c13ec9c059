"""Checking a task without moving anything: ``run-task check FILE``.

:func:`check_task` reports every problem of a task file at once, each at its
``file:line``, in three passes:

1. the loader's problems (unknown verbs or fields, wrong types, parameters, includes);
   when there are any, nothing else is checked;
2. the names the cell does not have (:func:`~taskrunner.tasks.check_names`);
3. a kinematic dry run of the steps in document order, on the scene the task starts in.

The dry run compiles each leaf step as a run does (:func:`compile_task`: pick, place and
hand-over are the very subtrees of :mod:`taskrunner.tree.idioms`) and plays the leaves
without OMPL and without a backend. A ``MoveToGoal`` goal becomes goal states as the
planner makes them (named and joint targets; IK for poses, seeded like the run) and is
checked for collisions; ``MoveStraight`` runs the :class:`CartesianPlanner` and times the
path (toppra) as a run does before it moves; ``MoveJoints`` checks its joint-space line;
``SceneAction`` edits the scene. A place whose target is inside another object is a
problem too (a run lets a 5-DOF arm's object touch the world while it is set down). The
robot then *is* at the state reached, so later steps are checked in the situation
earlier ones leave: a picked object is attached where it was grasped, a placed one sits
where it was released. What needs a planner is not checked: the joint-space path of a
``go`` or of the motion to a pre-grasp.

Of several goal states (the IK searches are seeded as in the run, so they are the run's)
the dry run follows the first collision-free one; when the rest of the step fails from
it, the others in turn (each followed through first goal states only), and the first from
which the step succeeds is taken. The state followed is remembered as the run's choice
(:mod:`taskrunner.tree.choice`): the run that follows plans to that state alone, so it
reaches the state the check judged whichever its planner would have met first.

A step with a name problem, or naming an object missing because of one, is skipped.
After a failed step the dry run finishes it without checks (collisions ignored), so
later steps start about where the run would have left the robot and the objects, and
the collision of their start state is not reported again. A ``fallback`` reports its
branches' problems only when every branch has some (each branch starts where the one
before stopped, as in a run); the body of ``retry``, ``timeout`` and ``repeat`` is
checked once; a ``parallel`` of ``go`` steps is the one motion a run makes of it, other
parallels are checked child by child, then their motions put on one schedule by the run's
own rule (:mod:`taskrunner.tree.schedule`): waits become notes, a conflict that waiting
cannot resolve a problem naming both lines.
"""

from __future__ import annotations

import math
import re
from collections.abc import Hashable, Iterable, Mapping, Sequence
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

import numpy as np
import pinocchio as pin
import py_trees
from py_trees.behaviour import Behaviour

from taskrunner.errors import (
    IkFailedError,
    InputError,
    InvalidStateError,
    StartInCollisionError,
    TaskrunnerError,
    TaskSpecError,
)
from taskrunner.kinematics import IkSolver
from taskrunner.planning.cartesian import CartesianPlanner
from taskrunner.planning.planner import interpolate_path, pose_goal_states
from taskrunner.planning.request import JointGoal, NamedGoal, PlannerOptions, PoseGoal
from taskrunner.planning.timing import parameterize_path
from taskrunner.robot.cell import Cell, load_cell
from taskrunner.robot.model import Group
from taskrunner.scene import Contact, Scene, scene_from_cell
from taskrunner.scene.geometry import MeshCache
from taskrunner.tasks import (
    AddObjectStep,
    FallbackStep,
    GoStep,
    GripperStep,
    HandoffStep,
    MoveStep,
    Node,
    ParallelStep,
    PickStep,
    PlaceStep,
    Problem,
    StepNode,
    TaskSpec,
    check_names,
    load_task,
    walk_steps,
)
from taskrunner.tasks.waits import WaitPair, wait_pairs
from taskrunner.tree.behaviours import (
    CheckOutcome,
    MoveJoints,
    MoveStraight,
    MoveToGoal,
    SceneAction,
    TaskLeaf,
)
from taskrunner.tree.choice import remember
from taskrunner.tree.compiler import compile_task, object_shape
from taskrunner.tree.context import TaskContext
from taskrunner.tree.idioms import place_target
from taskrunner.tree.occupancy import OVERLAP_TOLERANCE, target_overlap
from taskrunner.tree.outcome import Orientation, Outcome, describe_pose
from taskrunner.tree.reach import StagedGoals
from taskrunner.tree.schedule import Blocked, LaneKey, MotionSchedule
from taskrunner.types import JointPath, JointTrajectory

__all__ = ["MAX_GOAL_STATES", "OVERLAP_TOLERANCE", "CheckReport", "check_task"]

MAX_GOAL_STATES = 8
"""Goal states of one ``MoveToGoal`` tried, in the planner's order, to see whether any
lets the rest of its step succeed."""
_JOINT_STEP = 0.01  # rad between the collision checks of a MoveJoints line, as in a run


@dataclass(frozen=True)
class CheckReport:
    """What :func:`check_task` found.

    Attributes:
        cell: the name of the task's cell ('' when the task or the cell did not load).
        steps: leaf steps dry-run (steps skipped for a name problem not counted).
        problems: every problem once, the task file's first, then by file and line.
        notes: information, not problems: where each place and hand-over will leave its
            object (the orientation the arm achieves, which a position-only arm may not
            make the requested one), in the order the dry run met them.
        task: the task as loaded for the check (None when it did not load): a run of
            the same file with the same parameters may start from it instead of loading
            it again (``run-task`` does). The check never changes it (models are frozen).
        loaded_cell: the cell as loaded for the check (None when it did not load); the
            dry run builds its own scene from it and leaves it as it was loaded.
    """

    cell: str
    steps: int
    problems: list[Problem] = field(default_factory=list)
    notes: list[Problem] = field(default_factory=list)
    task: TaskSpec | None = field(default=None, compare=False, repr=False)
    loaded_cell: Cell | None = field(default=None, compare=False, repr=False)

    @property
    def ok(self) -> bool:
        """True when there is no problem."""
        return not self.problems


def check_task(path: str | Path, parameters: Mapping[str, object] | None = None,
               seed: int = 0) -> CheckReport:
    """Check a task file: structure, names, then a kinematic dry run (nothing moves).

    Args:
        path: the task file.
        parameters: overrides of the task's parameters (as for :func:`load_task`).
        seed: the run's seed: IK searches are seeded as a run with this seed seeds them.

    Returns:
        The report; problems of the task or of its cell are in it, never raised.
    """
    root = Path(path).resolve()
    try:
        spec = load_task(root, parameters)
    except TaskSpecError as exc:
        found = getattr(exc, "problems", None) or [Problem(exc.path, exc.line, exc.reason)]
        return CheckReport("", 0, _ordered(found, root))
    try:
        cell = load_cell(spec.cell)
    except TaskrunnerError as exc:
        if isinstance(exc, InputError) and exc.path is not None:
            return CheckReport("", 0, [Problem(exc.path, exc.line, exc.reason)])
        return CheckReport("", 0, [Problem(root, None, f"cell {spec.cell}: {exc}")])
    named = check_names(spec, cell)
    marked = {(p.path, p.line) for p in named}
    scene, problems, missing = _start_scene(spec, cell, marked)
    run = _DryRun(spec, cell, marked, missing)
    ctx = TaskContext(cell, scene, None, None, seed=seed)  # type: ignore[arg-type]
    run.sequence(spec.steps, ctx)
    return CheckReport(cell.name, run.checked, _ordered(named + problems + run.problems, root),
                       list(dict.fromkeys(run.notes)), task=spec, loaded_cell=cell)


# ----------------------------------------------------------------------------- helpers
def _ordered(problems: Iterable[Problem], root: Path) -> list[Problem]:
    unique = list(dict.fromkeys(problems))
    return sorted(unique, key=lambda p: (p.path != root, str(p.path), p.line or 0))


def _nested(node: Node) -> Iterable[Node]:
    """The models inside ``node``'s fields (poses, objects …), not its sub-steps."""
    for value in node.__dict__.values():
        for item in value if isinstance(value, tuple) else (value,):
            if isinstance(item, Node) and not isinstance(item, StepNode):
                yield item


def _lines(node: Node) -> set[tuple[Path, int | None]]:
    """Every ``(file, line)`` written for ``node`` and the models inside it."""
    found: set[tuple[Path, int | None]] = set()
    if node.loc is not None:
        found.add((node.loc.file, node.loc.line))
        found.update((node.loc.file, line) for _, line in node.loc.field_lines)
    for inner in _nested(node):
        found |= _lines(inner)
    return found


def _names(node: Node) -> set[str]:
    """Every string value of ``node``'s fields and of the models inside it."""
    found = {v for v in node.__dict__.values() if isinstance(v, str)}
    for inner in _nested(node):
        found |= _names(inner)
    return found


def _at(node: Node, message: str) -> Problem:
    loc = node.loc
    return Problem(loc.file if loc else None, loc.line if loc else None, message)


def _start_scene(spec: TaskSpec, cell: Cell, marked: set[Any]
                 ) -> tuple[Scene, list[Problem], set[str]]:
    """The scene the task starts in (built as ``runtime.runner.task_scene`` builds it),
    problems of objects that cannot be added (unless reported by name already), and the
    names of the objects left out."""
    scene = scene_from_cell(cell)
    problems, missing = [], set()
    if spec.scene is not None:
        from taskrunner.errors import InputError
        from taskrunner.moveit import apply_scene_file
        from taskrunner.tree.start import task_start

        try:
            apply_scene_file(scene, spec.scene)
            scene.set_state(task_start(spec, cell).q)  # the run's start too
        except InputError as exc:
            problems.append(Problem(exc.path, exc.line, exc.reason))
    for obj in spec.objects:
        try:
            scene.add_object(obj.name, object_shape(obj), obj.pose.to_pose())
            for link in obj.touch_links:
                scene.allow_collision(obj.name, link, reason="task")
        except TaskrunnerError as exc:
            if obj.name not in scene:
                missing.add(obj.name)
            if not _lines(obj) & marked:
                problems.append(_at(obj, f"object {obj.name!r}: {exc}"))
    return scene, problems, missing


def _pairs(contacts: Iterable[Contact | tuple[str, str]], scene: Scene | None = None) -> str:
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


def _describe(step: StepNode) -> str:
    """How messages name a step: ``go arm to 'Candle'``, ``pick cube`` …"""
    match step:
        case GoStep():
            target = (repr(step.to) if step.to is not None
                      else "joints" if step.joints is not None else "a pose")
            return f"go {step.group} to {target}"
        case MoveStep():
            return f"move {step.group} {'by an offset' if step.by is not None else 'to a pose'}"
        case GripperStep():
            what = step.action or (repr(step.to) if step.to else f"width {step.width:g}")
            return f"gripper {step.arm or step.group} {what}"
        case AddObjectStep():
            return f"add_object {step.object.name}"
        case ParallelStep():
            return "parallel " + ", ".join(_describe(child) for child in step.steps)
    obj = getattr(step, "object", None)
    return f"{step.verb} {obj}" if isinstance(obj, str) else step.label


def _achieved(outcome: Outcome, step: StepNode, ctx: TaskContext) -> str:
    """What a check note says of a place or hand-over's outcome: where the object will
    be, how far from its target, and what of its orientation is checked."""
    e, tol = outcome.error, outcome.tolerance
    where = "end" if isinstance(step, PlaceStep) else "be handed over"
    arm = step.arm if isinstance(step, PlaceStep) else getattr(step, "from_arm", "")
    short = ctx.scene.robot.group(ctx.arm(arm).group).position_only_ik if arm else False
    text = (f"{outcome.object!r} will {where} at {describe_pose(outcome.reached)}, "
            f"{1e3 * e.distance:.1f} mm and {math.degrees(e.angle):.1f}° from its target "
            f"(tilt {math.degrees(e.tilt):.1f}°, turn about z "
            f"{math.degrees(e.turn):.1f}°); orientation: {outcome.orientation.value}")
    if outcome.orientation is not Orientation.FULL and e.angle > tol.angle:
        reason = f"arm {arm!r} plans positions only, " if short else ""
        checked = ("its turn about z is checked" if outcome.orientation is Orientation.YAW
                   else "its position only is checked")
        text += f" ({reason}the requested orientation is not reached: {checked})"
    return text


def _leaves(behaviour: Behaviour) -> list[Behaviour]:
    if isinstance(behaviour, py_trees.composites.Sequence):
        return [leaf for child in behaviour.children for leaf in _leaves(child)]
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
class _Failure:
    """Why a step's leaves stopped: at leaf ``leaf``, in the situation ``ctx``."""

    leaf: int
    text: str
    ctx: TaskContext


class _Unreachable(Exception):
    """No goal of a MoveToGoal has an IK solution (control flow inside this module)."""


# ----------------------------------------------------------------------------- dry run
class _DryRun:
    """Plays the compiled steps kinematically, collecting problems (module docstring)."""

    def __init__(self, spec: TaskSpec, cell: Cell, marked: set[Any], missing: set[str]
                 ) -> None:
        self.spec, self.cell = spec, cell
        self.marked = marked  # (file, line) of every name problem
        # Objects not in the scene, or not where the task expects them, because of an
        # earlier problem: the steps naming them are skipped.
        self.missing = missing
        self.problems: list[Problem] = []
        self.notes: list[Problem] = []
        self.outcome: Outcome | None = None  # of the last CheckOutcome leaf played
        self.checked = 0
        self.tainted = False  # the state comes from a failed step: do not blame its start
        self.stopped: TaskContext | None = None  # the situation at the first failure
        self._ik: dict[tuple[str, str | None], IkSolver] = {}
        self._meshes = MeshCache()
        # The motions the dry run made, in order (leaf, start state, end state, path or
        # None for a straight joint line): what a parallel's branches are scheduled from.
        self.trace: list[tuple[Behaviour, np.ndarray, np.ndarray, JointPath | None]] = []
        # Where each step's motions begin and end in the trace (by id of the step), and
        # the task's wait_for: a parallel's branches are scheduled with them.
        self.spans: dict[int, tuple[int, int]] = {}
        self.waits: list[WaitPair] = wait_pairs(spec.steps)

    # ------------------------------------------------------------------ composites
    def sequence(self, steps: Iterable[StepNode], ctx: TaskContext) -> TaskContext:
        for step in steps:
            ctx = self.step(step, ctx)
        return ctx

    def step(self, step: StepNode, ctx: TaskContext) -> TaskContext:
        mark = len(self.trace)
        ctx = self._step(step, ctx)
        self.spans[id(step)] = (mark, len(self.trace))
        return ctx

    def _step(self, step: StepNode, ctx: TaskContext) -> TaskContext:
        if isinstance(step, FallbackStep):
            return self.fallback(step, ctx)
        if isinstance(step, ParallelStep) and not any(
                _lines(s) & self.marked or _names(s) & self.missing
                for s in walk_steps(step.children)):
            compiled = self.compile(step, ctx)  # reports what only the whole can get wrong
            leaves = _leaves(compiled) if compiled is not None else []
            if leaves and all(isinstance(leaf, TaskLeaf) for leaf in leaves):
                # Its go steps became one motion of the arms together: play it as the run does.
                return self.leaf(step, ctx, leaves)
            if compiled is not None:
                return self.parallel(step, ctx)
        if step.children:
            return self.sequence(step.children, ctx)
        return self.leaf(step, ctx)

    def parallel(self, step: ParallelStep, ctx: TaskContext) -> TaskContext:
        """A ``parallel`` whose branches move at once: each branch checked in turn (each
        starts where the one before left the scene), then their motions put on one
        schedule by the run's own rule (:mod:`taskrunner.tree.schedule`), a motion of
        each branch in turn: where a motion must wait for another branch's arm, a note
        says so; where waiting cannot resolve a conflict, a problem names both steps.
        A ``go`` is scheduled as the straight joint line to its goal state (the path a
        planner tries first), a straight move as its Cartesian path."""
        before = ctx.scene.copy()
        problems = len(self.problems)
        branches: list[list[tuple[Behaviour, np.ndarray, np.ndarray, JointPath | None]]] = []
        marks: list[int] = []
        for child in step.children:
            marks.append(len(self.trace))
            ctx = self.step(child, ctx)
            branches.append(self.trace[marks[-1]:])
        # wait_for between these branches: where in its branch a step waits, and where
        # the step it waits for ends.
        waits: list[tuple[int, int, int, int, str, str | None]] = []
        for pair in self.waits:
            waiter, named = self.spans.get(id(pair.waiter)), self.spans.get(id(pair.named))
            if pair.parallel is step and waiter is not None and named is not None:
                i, j = pair.waiter_branch, pair.named_branch
                where = str(pair.waiter.loc) if pair.waiter.loc is not None else None
                waits.append((i, waiter[0] - marks[i], j, named[1] - marks[j], pair.name,
                              where))
        if len(self.problems) == problems and len(branches) > 1:
            text, notes = schedule_branches(before, branches, waits)
            self.notes += [_at(step, note) for note in notes]
            if text is not None:
                self.problems.append(_at(step, f"{_describe(step)}: {text}"))
                self.tainted = True
        return ctx

    def fallback(self, step: FallbackStep, ctx: TaskContext) -> TaskContext:
        """The first branch without problems ends the fallback; when every branch has
        some, all are reported. A branch starts where the one before stopped (at its
        first problem), as in a run."""
        outer, tainted = self.problems, self.tainted
        tried: list[tuple[list[Problem], TaskContext]] = []
        start = ctx
        for branch in step.steps:
            self.problems, self.tainted, self.stopped = [], tainted, None
            end = self.step(branch, replace(start, scene=start.scene.copy()))
            tried.append((self.problems, end))
            if not self.problems:
                self.problems = outer
                return end
            start = self.stopped or end
        self.problems = outer + [p for found, _ in tried for p in found]
        self.tainted = True
        return tried[0][1]

    # ------------------------------------------------------------------ leaf steps
    def compile(self, step: StepNode, ctx: TaskContext) -> Behaviour | None:
        """``step`` compiled as the run compiles it, or None (its problem reported)."""
        one = self.spec.model_copy(update={"name": step.label, "steps": (step,)})
        try:
            return compile_task(one, ctx)
        except TaskSpecError as exc:
            self.problems.append(Problem(exc.path, exc.line, exc.reason))
            return None

    def leaf(self, step: StepNode, ctx: TaskContext,
             leaves: list[Behaviour] | None = None) -> TaskContext:
        """Check one step (a leaf, or a parallel compiled into ``leaves``)."""
        if _lines(step) & self.marked or _names(step) & self.missing:
            # Its problem is reported already; what it would leave is unknown.
            if isinstance(step, AddObjectStep):
                self.missing.add(step.object.name)
            self.tainted = True
            return ctx
        self.checked += 1
        if leaves is None:
            compiled = self.compile(step, ctx)
            if compiled is None:
                self.tainted = True
                return ctx
            leaves = _leaves(compiled)
        text, finish = self.precheck(step, ctx)
        start = 0
        if text is None:
            self.outcome = None
            end, failure = self.play(leaves, 0, step, ctx)
            if failure is None:
                self.tainted = False
                if self.outcome is not None:
                    self.notes.append(_at(step, f"{_describe(step)}: "
                                                f"{_achieved(self.outcome, step, ctx)}"))
                return end
            text, start, ctx = failure.text, failure.leaf, failure.ctx
        self.problems.append(_at(step, f"{_describe(step)}: {text}"))
        self.tainted = True
        if self.stopped is None:  # where a run stops: a fallback's next branch starts there
            self.stopped = replace(ctx, scene=ctx.scene.copy())
        if finish and not self.force(leaves[start:], ctx):
            held = getattr(step, "object", None)  # pick, place, handoff: left who knows where
            if isinstance(held, str):
                self.missing.add(held)
        if isinstance(step, AddObjectStep) and step.object.name not in ctx.scene:
            self.missing.add(step.object.name)
        return ctx

    def precheck(self, step: StepNode, ctx: TaskContext) -> tuple[str | None, bool]:
        """What fails an idiom before it moves (who holds the object; a place target
        inside another object), and whether the step can be finished all the same."""
        scene = ctx.scene
        try:
            if isinstance(step, PickStep) and scene.object(step.object).attached:
                holder = scene.object(step.object).attached_to
                return f"{step.object!r} is already held (by {holder!r})", False
            if isinstance(step, (PlaceStep, HandoffStep)):
                arm = step.arm if isinstance(step, PlaceStep) else step.from_arm
                if scene.object(step.object).attached_to != ctx.arm(arm).holder:
                    return f"arm {arm!r} is not holding {step.object!r}", False
            if isinstance(step, PlaceStep):
                at = step.at.to_pose() if step.at is not None else None
                target = place_target(ctx, step.object, at, step.on, step.offset or (0.0, 0.0))
                found = self.overlap(scene, step.object, target)
                if found is not None:
                    other = found.a if found.b == step.object else found.b
                    depth = f"{1e3 * found.depth:.0f} mm"
                    return f"target occupied by {other!r} ({depth} overlap)", True
        except TaskrunnerError as exc:
            return str(exc), False
        return None, True

    def overlap(self, scene: Scene, name: str, target: pin.SE3) -> Contact | None:
        """:func:`~taskrunner.tree.occupancy.target_overlap` (the place idiom's own check)."""
        return target_overlap(scene, name, target, self._meshes)

    # ------------------------------------------------------------------ playing leaves
    def play(self, leaves: list[Behaviour], index: int, step: StepNode, ctx: TaskContext,
             explore: bool = True) -> tuple[TaskContext, _Failure | None]:
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
                    return ctx, _Failure(index, text, ctx)
                index += 1
                continue
            found = self.goal_states(leaf, stage, ctx)
            if isinstance(found, str):
                return ctx, _Failure(index, found, ctx)
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
            found = leaf.goal_list(ctx)
            goals = found.all() if isinstance(found, StagedGoals) else found
            group = model.group(leaf.group)
            seed = ctx.next_seed()  # as MoveToGoal draws it, so IK finds what the run finds
            key = leaf.choice_key(ctx, found, seed)
            if not self.tainted and scene.in_collision(start):
                return f"{lead}start state in collision ({_pairs(scene.collisions(start), scene)})"
            valid: list[np.ndarray] = []
            rejected: list[np.ndarray] = []
            for q in self.candidates(goals if isinstance(goals, tuple) else (goals,), group,
                                     start, replace(leaf.options, seed=seed), scene):
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
            return f"{word} in collision ({_pairs(scene.collisions(rejected[0]), scene)})"
        return valid[:MAX_GOAL_STATES], key

    def candidates(self, goals: tuple[Any, ...], group: Group, start: np.ndarray,
                   options: PlannerOptions, scene: Scene) -> list[np.ndarray]:
        """Goal states of every goal with a solution, as ``MotionPlanner`` makes them.

        Raises:
            _Unreachable: no goal has an IK solution (the message: the nearest miss).
            InvalidStateError: joints that are not the group's.
        """
        model = scene.robot
        out: list[np.ndarray] = []
        misses: list[tuple[float, str]] = []
        for goal in goals:
            if isinstance(goal, (JointGoal, NamedGoal)):
                values = (goal.values if isinstance(goal, JointGoal)
                          else model.named_state(group.name, goal.name).as_dict())
                outside = [n for n in values if n not in group.joint_names]
                if outside:
                    raise InvalidStateError(f"joints {outside} are not active joints of "
                                            f"group {group.name!r}")
                out.append(model.state_with(start, values))
                continue
            assert isinstance(goal, PoseGoal)
            solver = self.solver(group, goal.link)
            world = scene.to_world(goal.pose, start)
            try:
                out += pose_goal_states(solver, group, goal, world, start, options)
            except IkFailedError as exc:
                only = group.position_only_ik if goal.position_only is None \
                    else goal.position_only
                xyz = ", ".join(f"{v:.3f}" for v in world.translation)
                residual = exc.best_error if exc.best_error is not None else math.inf
                unit = "m" if only else "(m and rad)"
                text = f"best residual {residual:.3g} {unit} for {solver.frame!r} at ({xyz})"
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
        scene, model = ctx.scene, ctx.scene.robot
        try:
            if isinstance(leaf, MoveStraight):
                return self.straight(leaf, stage, ctx)
            if isinstance(leaf, MoveJoints):
                start = scene.state
                goal = model.state_with(start, leaf.values(ctx))
                what = {"open": "opening the gripper", "close": "closing the gripper"}.get(
                    stage or "", stage or "gripper motion")
                bad = model.limit_violations(goal)
                if bad:
                    return f"{what}: target outside the joint limits: " + "; ".join(bad)
                if leaf.check and not (self.tainted and scene.in_collision(start)):
                    line = interpolate_path(np.vstack([start, goal]), _JOINT_STEP)
                    for k in range(1, len(line)):
                        q = model.apply_mimic(line[k].copy())
                        if scene.in_collision(q):
                            return f"{what} collides ({_pairs(scene.collisions(q))})"
                self.trace.append((leaf, start, goal, None))
                scene.set_state(goal)
            elif isinstance(leaf, SceneAction):
                leaf.action(ctx)
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
            return f"{name}: start state in collision ({_pairs(exc.pairs, ctx.scene)})"
        if not result.complete:
            verb = "blocked" if result.stop_reason == "collision" else "stopped"
            percent = f"{math.floor(100.0 * result.fraction + 1e-9):.0f} %"
            reason = re.sub(r" at \d+ % of the path", "", result.message)
            reason = re.sub(r" \(and (\d+ more pair\(s\))\)", r", and \1", reason)
            return f"{name}{sep}{verb} at {percent} ({reason})"
        try:  # a run times the path before it moves; toppra can fail where IK did not
            parameterize_path(ctx.scene.robot, result.path, leaf.timing)
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
                    scene.set_state(scene.robot.state_with(scene.state, leaf.values(ctx)))
                elif isinstance(leaf, SceneAction):
                    leaf.action(ctx)
            except (_Unreachable, IkFailedError):
                return False
            except TaskrunnerError:
                continue
        return True


@dataclass(frozen=True)
class _Queued:
    """What comes next in a branch the check schedules: a motion (``trajectory``), a step
    waiting for another branch's step ``name`` ("wait"), or the end of a step another
    branch waits for ("done")."""

    kind: str
    where: str | None
    trajectory: JointTrajectory | None = None
    name: str = ""


def schedule_branches(scene: Scene, branches: list[list[tuple[Behaviour, np.ndarray, np.ndarray,
                                                             JointPath | None]]],
                      waits: Sequence[tuple[int, int, int, int, str, str | None]] = ()
                      ) -> tuple[str | None, list[str]]:
    """Put the motions of a parallel's branches on one :class:`MotionSchedule`, a motion
    of each branch in turn, as a run admits them (the scene: as the parallel starts).

    Args:
        waits: each ``wait_for`` between the branches: (branch of the waiting step, the
            index in that branch of its first motion, branch of the step waited for, the
            index after its last motion, that step's name, the waiting step's file:line);
            followed as the run's leaves follow it (:mod:`taskrunner.tree.waiting`).

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
            queue += [_Queued("done", None, name=name) for _, _, b, at, name, _ in waits
                      if (b, at) == (index, position)]
            queue += [_Queued("wait", where, name=name) for b, at, _, _, name, where in waits
                      if (b, at) == (index, position)]
            if position == len(motions):
                break
            leaf, start, end, path = motions[position]
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
            queue.append(_Queued("motion", getattr(leaf, "location", None), trajectory))
    notes: list[str] = []
    least = math.inf
    while any(queues.values()):
        progressed = False
        for lane, queue in queues.items():
            if not queue:
                continue
            item = queue[0]
            if item.kind == "done":
                schedule.finish_step(lane, item.name)
            elif item.kind == "wait":
                at = schedule.finished.get((instance, item.name))
                if at is None:
                    continue  # the other branch has not got there yet
                if at > schedule.lane_end(lane):
                    notes.append(f"{item.where or 'a step'} waits until step {item.name!r} "
                                 f"has finished, at {at:.2f} s")
                schedule.not_before(lane, at)
            if item.kind != "motion":
                queue.pop(0)
                progressed = True
                continue
            location, motion = item.where, item.trajectory
            assert motion is not None
            try:
                found = schedule.admit(scene, lane, motion, location)
            except TaskrunnerError as exc:
                return f"{location}: {exc}", notes
            if isinstance(found, Blocked):
                refusal = schedule.refusal(lane, found, location)
                if refusal is not None:
                    return f"{location}: {refusal}", notes
                schedule.holding[lane] = found.lane
                continue
            schedule.holding.pop(lane, None)
            queue.pop(0)
            progressed = True
            least = min(least, found.least)
            notes += [wait.describe(location) for wait in found.waits]
        if not progressed:
            return "the branches wait for each other's arms (a deadlock)", notes
    if math.isfinite(least):
        notes.append(f"arms at least {1e3 * least:.1f} mm apart at every instant (as "
                     f"scheduled, {len(schedule.committed)} motions)")
    return None, notes
