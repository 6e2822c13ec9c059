"""Checking a task without moving anything: ``run-task check FILE``.

:func:`check_task` reports every problem of a task file at once, each at its
``file:line``, in three passes:

1. the loader's problems (unknown verbs or fields, wrong types, parameters, includes);
   when there are any, nothing else is checked;
2. the names the cell does not have (:func:`~taskrunner.tasks.check_names`);
3. a kinematic dry run on the scene the task starts in: the task's tree compiled as for
   a run and ticked in check mode (:mod:`taskrunner.tree.checkmode`): its composites are
   the run's py_trees composites, its steps plan but do not move.

Each leaf step is compiled as a run compiles it (:func:`compile_task`: pick, place and
hand-over are the very subtrees of :mod:`taskrunner.tree.idioms`) and its leaves played
without OMPL and without a backend (:mod:`taskrunner.tree.leafcheck`). A ``MoveToGoal``
goal becomes goal states as the planner makes them (named and joint targets; IK for
poses, seeded like the run) and is checked for collisions; ``MoveStraight`` runs the
:class:`CartesianPlanner` and times the path (toppra) as a run does before it moves;
``MoveJoints`` checks its joint-space line; ``SceneAction`` edits the scene. A place
whose target is inside another object is a problem too (a run lets a 5-DOF arm's object
touch the world while it is set down). The robot then *is* at the state reached, so
later steps are checked in the situation earlier ones leave: a picked object is attached
where it was grasped, a placed one sits where it was released. What needs a planner is
not checked: the joint-space path of a ``go`` or of the motion to a pre-grasp.

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
own rule (:mod:`taskrunner.tree.branch_schedule`): waits become notes, a conflict that waiting
cannot resolve a problem naming both lines.
"""

from __future__ import annotations

import math
from collections.abc import Iterable, Mapping
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from py_trees.behaviour import Behaviour
from py_trees.common import Status

from taskrunner.errors import InputError, TaskrunnerError, TaskSpecError
from taskrunner.folders import FolderPolicy
from taskrunner.robot.cell import Cell, load_cell
from taskrunner.robot.options import LoadOptions
from taskrunner.scene import Scene, SceneObject, scene_from_cell
from taskrunner.tasks import (
    AddObjectStep,
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
)
from taskrunner.tasks.waits import WaitPair, wait_pairs
from taskrunner.taught import TaughtPoses
from taskrunner.tree.checkmode import CheckMode
from taskrunner.tree.compiler import compile_task, object_shape
from taskrunner.tree.context import TaskContext
from taskrunner.tree.idioms import place_target
from taskrunner.tree.leafcheck import MAX_GOAL_STATES, LeafFailure, LeafPlayer, Motion, leaves_of
from taskrunner.tree.occupancy import OVERLAP_TOLERANCE
from taskrunner.tree.outcome import Orientation, Outcome, describe_pose
from taskrunner.tree.schedule_proof import ScheduleProof

__all__ = ["MAX_GOAL_STATES", "OVERLAP_TOLERANCE", "CheckReport", "check_from", "check_task"]


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
    schedules: list[ScheduleProof] = field(default_factory=list)
    """What each scheduled ``parallel`` proves (:mod:`taskrunner.tree.schedule_proof`)."""

    @property
    def ok(self) -> bool:
        """True when there is no problem."""
        return not self.problems


def check_task(path: str | Path, parameters: Mapping[str, object] | None = None,
               seed: int = 0, *, policy: FolderPolicy | None = None,
               taught: TaughtPoses | None = None,
               options: LoadOptions | None = None) -> CheckReport:
    """Check a task file: structure, names, then a kinematic dry run (nothing moves).

    Args:
        path: the task file.
        parameters: overrides of the task's parameters (as for :func:`load_task`).
        seed: the run's seed: IK searches are seeded as a run with this seed seeds them.
        policy: the folders the task, its cell and their files may come from (None:
            anything loads; see :mod:`taskrunner.folders`).
        taught: taught poses added to the cell's named poses, as a run has them (None:
            none; see :mod:`taskrunner.taught`).
        options: how the cell's robots are loaded (default ``LoadOptions()``; see
            :mod:`taskrunner.robot.options`), as the run loads them.

    Returns:
        The report; problems of the task or of its cell are in it, never raised.
    """
    root = Path(path).resolve()
    try:
        spec = load_task(root, parameters, policy=policy)
    except TaskSpecError as exc:
        found = getattr(exc, "problems", None) or [Problem(exc.path, exc.line, exc.reason)]
        return CheckReport("", 0, _ordered(found, root))
    try:
        cell = load_cell(spec.cell, policy=policy, taught=taught, options=options)
    except TaskrunnerError as exc:
        if isinstance(exc, InputError) and exc.path is not None:
            return CheckReport("", 0, [Problem(exc.path, exc.line, exc.reason)])
        return CheckReport("", 0, [Problem(root, None, f"cell {spec.cell}: {exc}")])
    named = check_names(spec, cell)
    marked = {(p.path, p.line) for p in named}
    scene, problems, missing = _start_scene(spec, cell, marked)
    run = _TaskCheck(spec, cell, marked, missing)
    run.check(TaskContext(cell, scene, seed=seed))  # no planner, no backend: nothing moves
    return CheckReport(cell.name, run.checked, _ordered(named + problems + run.problems, root),
                       list(dict.fromkeys(run.notes)), task=spec, loaded_cell=cell,
                       schedules=run.proofs)


def check_from(spec: TaskSpec, cell: Cell, scene: Scene, seed: int = 0) -> list[Problem]:
    """The problems of the dry run of ``spec``'s steps (pass 3 of the module text) from
    ``scene`` instead of the task's start: a resumed run's rest, from the robot and the
    objects as they are (``run-task resume --from``). ``scene`` is not changed."""
    run = _TaskCheck(spec, cell, set(), set())
    run.check(TaskContext(cell, scene.copy(), seed=seed))
    return _ordered(run.problems, Path(spec.path) if spec.path else Path())


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


# ----------------------------------------------------------------------------- the check
class _HeldTrace(list[Motion]):
    """The motions played, noting for each what the scene it starts in has attached
    (:attr:`held`, by id of the entry): what its arm holds while it runs, as a run's
    record has it (a parallel's schedule is verified with it)."""

    def __init__(self) -> None:
        super().__init__()
        self.scenes: list[Scene] = []  # the scenes being played, innermost last
        self.held: dict[int, tuple[SceneObject, ...]] = {}

    def append(self, entry: Motion) -> None:
        super().append(entry)
        if self.scenes:
            self.held[id(entry)] = self.scenes[-1].attached_objects()


class _TaskCheck(LeafPlayer):
    """The check of one task (module docstring): its problems and notes, the situation the
    next step starts in, and the step-level checks its check-mode tree calls
    (:class:`~taskrunner.tree.checkmode.Checker`)."""

    def __init__(self, spec: TaskSpec, cell: Cell, marked: set[Any], missing: set[str]
                 ) -> None:
        super().__init__(cell)
        self.spec = spec
        self.marked = marked  # (file, line) of every name problem
        # Objects not in the scene, or not where the task expects them, because of an
        # earlier problem: the steps naming them are skipped.
        self.missing = missing
        self.problems: list[Problem] = []
        self.notes: list[Problem] = []
        self.proofs: list[ScheduleProof] = []
        self.checked = 0
        self.stopped: TaskContext | None = None  # the situation at the first failure
        self.ctx: TaskContext  # the situation the next step starts in (set by check)
        # Where each step's motions begin and end in the trace (by id of the step), and
        # the task's wait_for: a parallel's branches are scheduled with them.
        self.spans: dict[int, tuple[int, int]] = {}
        self.waits: list[WaitPair] = wait_pairs(spec.steps)
        self.held_trace = _HeldTrace()
        self.trace = self.held_trace
        # What the scene had attached as each motion of the trace began (by id).
        self.held: Mapping[int, tuple[SceneObject, ...]] = self.held_trace.held

    def play(self, leaves: list[Behaviour], index: int, step: StepNode, ctx: TaskContext,
             explore: bool = True) -> tuple[TaskContext, LeafFailure | None]:
        """:meth:`LeafPlayer.play`, the trace noting what each motion's scene holds."""
        self.held_trace.scenes.append(ctx.scene)
        try:
            return super().play(leaves, index, step, ctx, explore)
        finally:
            self.held_trace.scenes.pop()

    # ------------------------------------------------------------------ check mode
    def check(self, ctx: TaskContext) -> None:
        """Tick the task's tree compiled in check mode (:mod:`taskrunner.tree.checkmode`)
        from the situation ``ctx``; it finishes in one tick."""
        self.ctx = ctx
        tree = compile_task(self.spec, ctx, check=CheckMode(self))
        tree.tick_once()
        assert tree.status == Status.SUCCESS, tree.status  # check-mode steps never wait

    def skips(self, step: StepNode) -> bool:
        """Whether ``step`` names something reported already (it is not checked)."""
        return bool(_lines(step) & self.marked or _names(step) & self.missing)

    def problem(self, step: StepNode, message: str) -> None:
        """Report ``message`` at ``step``'s line; the situation is then tainted."""
        self.problems.append(_at(step, f"{_describe(step)}: {message}"))
        self.tainted = True

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
        if self.skips(step):
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
            leaves = leaves_of(compiled)
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
        self.problem(step, text)
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

