"""Compiling a :class:`~taskrunner.tasks.spec.TaskSpec` into a py_trees behaviour tree.

Steps map one to one onto behaviours: leaves onto :mod:`taskrunner.tree.behaviours`,
pick / place / handoff onto the subtrees of :mod:`taskrunner.tree.idioms`, ``sequence`` onto
a ``Sequence``, ``fallback`` onto a ``Selector``, ``retry`` / ``timeout`` / ``repeat`` onto
the decorators of the same names. A ``parallel`` of ``go`` steps of different arms becomes
ONE motion planned in a group spanning those arms, so the arms cannot collide; other
parallel children run side by side on their own joints, each motion verified in time
against the other branches' before it is sent (:mod:`taskrunner.tree.schedule`). A step
with ``wait_for`` is preceded by a leaf holding its branch until the step it names (in
another branch) is followed by one recording that it has finished
(:mod:`taskrunner.tree.waiting`); such steps are never joined into one ``go`` motion.

In check mode (``check=``, :mod:`taskrunner.tree.checkmode`) the same walk builds the tree
``run-task check`` ticks: its composites are the same py_trees composites, each leaf step
(and each ``fallback`` and ``parallel``) is what the check mode makes of it, the body of
``retry``, ``repeat`` and ``timeout`` runs once, and ``wait_for`` holds nothing (the check
puts a parallel's motions on one schedule instead).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from typing import Any, Protocol

import pinocchio as pin
import py_trees
from py_trees.behaviour import Behaviour

from taskrunner.errors import RobotDescriptionError, TaskSpecError
from taskrunner.planning.cartesian import CartesianOptions
from taskrunner.planning.request import Goal, JointGoal, NamedGoal, PlannerOptions, PoseGoal
from taskrunner.planning.timing import TimingOptions
from taskrunner.shapes import Box, Cylinder, Mesh, Sphere
from taskrunner.tasks import (
    AddObjectStep,
    AttachStep,
    DetachStep,
    FallbackStep,
    GoStep,
    GripperStep,
    HandoffStep,
    IncludeStep,
    MotionOptions,
    MoveStep,
    ParallelStep,
    PickStep,
    PlaceStep,
    RemoveObjectStep,
    RepeatStep,
    RetryStep,
    SequenceStep,
    StepNode,
    TaskSpec,
    TimeoutStep,
    WaitStep,
)
from taskrunner.tasks.steps import ExpectStep
from taskrunner.tasks.waits import FINISHED, wait_pairs
from taskrunner.tree import idioms
from taskrunner.tree.behaviours import MoveJoints, MoveStraight, MoveToGoal, TaskParallel
from taskrunner.tree.context import TaskContext
from taskrunner.tree.expect import CheckExpectation, StepTimer
from taskrunner.tree.grasps import allow_lift_off, end_lift_off, end_lift_offs_left, tool_grasp
from taskrunner.tree.instant_leaves import SceneAction, Wait
from taskrunner.tree.outcome import Orientation, Tolerance
from taskrunner.tree.timeout import TaskTimeout
from taskrunner.tree.waiting import StepFinished, WaitForStep, mark_moment
from taskrunner.types import Pose

__all__ = ["CheckHooks", "compile_task", "object_shape", "planner_options", "timing_options"]


class CheckHooks(Protocol):
    """What the check mode makes of the steps it checks (:mod:`taskrunner.tree.checkmode`)."""

    def leaf(self, step: StepNode) -> Behaviour:
        """A step without sub-steps."""

    def fallback(self, step: FallbackStep, branches: list[Behaviour]) -> Behaviour:
        """A ``fallback`` of the compiled ``branches``."""

    def parallel(self, step: ParallelStep, branches: list[Behaviour]) -> Behaviour:
        """A ``parallel`` of the compiled ``branches`` (its children in document order)."""

    def span(self, step: StepNode, behaviour: Behaviour) -> Behaviour:
        """Any step, compiled."""


def compile_task(spec: TaskSpec, ctx: TaskContext, check: CheckHooks | None = None
                 ) -> Behaviour:
    """The behaviour tree of ``spec``; its leaves act on ``ctx``; ``check``: the tree of
    the check mode (module docstring).

    Raises:
        TaskSpecError: a step that names something the cell does not have, with file:line.
    """
    pairs = wait_pairs(spec.steps)
    waited: dict[int, dict[str, str]] = {}
    for p in pairs:
        waited.setdefault(id(p.named), {})[p.moment] = p.name
    waits = _Waits({id(p.waiter): (p.name, p.moment) for p in pairs}, waited, check)
    children = _compile_list(spec.steps, ctx, waits)
    return py_trees.composites.Sequence(spec.name, memory=True, children=children)


@dataclass(frozen=True)
class _Waits:
    """The ``wait_for`` of the steps compiled (by ``id`` of the step): the name and moment
    each waiting step waits for, and the moments of each step waited for (its name by
    moment)."""

    waiting: Mapping[int, tuple[str, str]] = field(default_factory=dict)
    waited: Mapping[int, Mapping[str, str]] = field(default_factory=dict)
    check: CheckHooks | None = None  # the check mode's (compile_task)

    def joins(self, step: StepNode) -> bool:
        """Whether ``step`` takes part in a wait (so stays a branch of its own)."""
        return id(step) in self.waiting or id(step) in self.waited


_NO_WAITS = _Waits()


def _compile_list(steps: tuple[StepNode, ...], ctx: TaskContext,
                  waits: _Waits = _NO_WAITS) -> list[Behaviour]:
    """Steps run one after another; an ``expect`` with ``step_duration`` times the step
    before it (a :class:`StepTimer` around that step's behaviour)."""
    out: list[Behaviour] = []
    for step in steps:
        if isinstance(step, ExpectStep) and waits.check is None:
            timer = None
            if step.step_duration is not None and out:  # (none before: names.py reports it)
                timer = StepTimer(out[-1], ctx)
                out[-1] = timer
            out.append(CheckExpectation(step.label, _where(step), ctx, step, timer))
        else:
            out.append(_compile(step, ctx, waits))
    return out


def _where(step: StepNode) -> str | None:
    return str(step.loc) if step.loc is not None else None


def _error(step: StepNode, message: str) -> TaskSpecError:
    loc = step.loc
    return TaskSpecError(message, loc.file if loc else None, loc.line if loc else None)


def planner_options(step: MotionOptions) -> PlannerOptions:
    """Planner options of a motion step (the task's defaults already applied)."""
    values: dict[str, Any] = {}
    if step.planner is not None:
        values["planner"] = step.planner
    if step.planning_time is not None:
        values["planning_time"] = step.planning_time
    try:
        return PlannerOptions(**values)
    except ValueError as exc:
        raise _error(step, str(exc)) from None  # type: ignore[arg-type]


def timing_options(step: MotionOptions, ctx: TaskContext) -> TimingOptions:
    """Timing of a motion step: its scaling factors, else the run's defaults."""
    from dataclasses import replace

    return replace(ctx.timing,
                   velocity_scaling=step.velocity_scaling or ctx.timing.velocity_scaling,
                   acceleration_scaling=step.acceleration_scaling
                   or ctx.timing.acceleration_scaling)


def _outcome_options(step: PlaceStep | HandoffStep) -> tuple[Orientation | None, Tolerance]:
    """The outcome check a place or hand-over asks for (None: the arm's default)."""
    orientation = Orientation(step.orientation) if step.orientation is not None else None
    return orientation, Tolerance(step.tolerance.position, math.radians(step.tolerance.angle_deg))


def object_shape(spec):  # type: ignore[no-untyped-def]
    """The :mod:`taskrunner.shapes` shape of an object spec."""
    if spec.shape == "box":
        return Box(tuple(spec.size))
    if spec.shape == "cylinder":
        return Cylinder(spec.radius, spec.length)
    if spec.shape == "sphere":
        return Sphere(spec.radius)
    return Mesh(spec.file, tuple(spec.scale or (1.0, 1.0, 1.0)))


def _compile(step: StepNode, ctx: TaskContext, waits: _Waits = _NO_WAITS) -> Behaviour:
    behaviour = _compile_step(step, ctx, waits)
    if waits.check is not None:
        return waits.check.span(step, behaviour)
    if not waits.joins(step):
        return behaviour
    children = [behaviour]
    if id(step) in waits.waiting:
        name, moment = waits.waiting[id(step)]
        children.insert(0, WaitForStep(f"{step.label}: wait for {name!r}", _where(step), ctx,
                                       name, moment))
    for moment, name in waits.waited.get(id(step), {}).items():
        if moment == FINISHED:
            children.append(StepFinished(name, ctx))
        else:  # within the step: after the leaves that make the moment
            mark_moment(behaviour, StepFinished(name, ctx, moment))
    return py_trees.composites.Sequence(f"{step.label} (wait_for)", memory=True,
                                        children=children)


def _compile_step(step: StepNode, ctx: TaskContext, waits: _Waits) -> Behaviour:
    name, where = step.label, _where(step)
    if waits.check is not None:
        match step:
            case FallbackStep():
                return waits.check.fallback(step, _compile_list(step.children, ctx, waits))
            case ParallelStep():
                return waits.check.parallel(step, [_compile(c, ctx, waits)
                                                   for c in step.children])
            case RetryStep():
                return py_trees.decorators.Retry(name, _body(step, ctx, waits), num_failures=1)
            case RepeatStep():
                return py_trees.decorators.Repeat(name, _body(step, ctx, waits), num_success=1)
            case TimeoutStep():
                return _body(step, ctx, waits)  # nothing takes task time in check mode
            case _ if not step.children:
                return waits.check.leaf(step)
    match step:
        case SequenceStep() | IncludeStep():
            return py_trees.composites.Sequence(
                name, memory=True, children=_compile_list(step.children, ctx, waits))
        case FallbackStep():
            return py_trees.composites.Selector(
                name, memory=True, children=_compile_list(step.children, ctx, waits))
        case RetryStep():
            return py_trees.decorators.Retry(name, _body(step, ctx, waits), num_failures=step.times)
        case TimeoutStep():
            return TaskTimeout(name, _body(step, ctx, waits), step.seconds, where, ctx)
        case RepeatStep():
            return py_trees.decorators.Repeat(name, _body(step, ctx, waits), num_success=step.times)
        case ParallelStep():
            return _parallel(step, ctx, waits)
        case GoStep():
            return MoveToGoal(name, where, ctx, _group(step, ctx, step.group), _go_goal(step),
                              planner_options(step), timing_options(step, ctx))
        case MoveStep():
            return _move(step, ctx)
        case GripperStep():
            return _gripper(step, ctx)
        case PickStep():
            arm = _arm(step, ctx, step.arm)
            grasp = _grasp(step.grasp, step, ctx, arm)
            _gripper_poses(step, ctx, arm)
            assert grasp is not None
            return idioms.pick(ctx, name, where, arm, step.object, grasp, step.approach,
                               step.retreat, planner_options(step), timing_options(step, ctx))
        case PlaceStep():
            arm = _arm(step, ctx, step.arm)
            at = step.at.to_pose() if step.at is not None else None
            _gripper_poses(step, ctx, arm)
            return idioms.place(ctx, name, where, arm, step.object, at, step.on,
                                step.offset or (0.0, 0.0), step.approach, step.retreat,
                                planner_options(step), timing_options(step, ctx),
                                *_outcome_options(step), grasp=_grasp(step.grasp, step, ctx, arm))
        case HandoffStep():
            giver, receiver = _arm(step, ctx, step.from_arm), _arm(step, ctx, step.to_arm)
            meet = step.at if isinstance(step.at, str) else step.at.to_pose()
            if isinstance(meet, str) and meet not in ctx.scene.robot.named_state_names(giver):
                raise _error(step, f"'at': {meet!r} is not a named pose of arm {giver!r}")
            _gripper_poses(step, ctx, giver)
            _gripper_poses(step, ctx, receiver)
            return idioms.handoff(ctx, name, where, step.object, giver, receiver, meet,
                                  step.approach, step.retreat, planner_options(step),
                                  timing_options(step, ctx), *_outcome_options(step),
                                  grasp=_grasp(step.grasp, step, ctx, receiver))
        case AttachStep():
            return SceneAction(name, where, ctx, _attach(step, ctx))
        case DetachStep():
            obj = step.object
            def detach(c: TaskContext) -> None:
                c.scene.detach_object(obj)
                end_lift_off(c.scene, obj)

            return SceneAction(name, where, ctx, detach)
        case AddObjectStep():
            spec = step.object
            shape = object_shape(spec)
            pose = spec.pose.to_pose()
            links = tuple(spec.touch_links)

            def add(c: TaskContext) -> None:
                c.scene.add_object(spec.name, shape, pose)
                for link in links:
                    c.scene.allow_collision(spec.name, link, reason="task")

            return SceneAction(name, where, ctx, add)
        case RemoveObjectStep():
            obj = step.object
            return SceneAction(name, where, ctx, lambda c: c.scene.remove_object(obj))
        case WaitStep():
            return Wait(name, where, ctx, step.seconds)
        case ExpectStep():  # alone (the checker's dry run): no step before it to time
            return CheckExpectation(name, where, ctx, step)
    raise _error(step, f"step '{step.verb}' cannot be compiled")


def _body(step, ctx: TaskContext, waits: _Waits) -> Behaviour:  # type: ignore[no-untyped-def]
    children = _compile_list(step.children, ctx, waits)
    if len(children) == 1:
        return children[0]
    return py_trees.composites.Sequence(f"{step.label} body", memory=True, children=children)


def _group(step: StepNode, ctx: TaskContext, name: str) -> str:
    model = ctx.scene.robot
    if name not in model.groups:
        raise _error(step, f"group {name!r} is not a group of cell {ctx.cell.name!r} "
                           f"(groups: {', '.join(model.groups)})")
    return name


def _arm(step: StepNode, ctx: TaskContext, name: str) -> str:
    try:
        ctx.arm(name)
    except Exception as exc:  # UnknownNameError: not an arm
        raise _error(step, str(exc)) from None
    return name


def _grasp(grasp, step: StepNode, ctx: TaskContext,  # type: ignore[no-untyped-def]
           arm: str) -> str | Pose | None:
    """A step's ``grasp`` as the idioms take it (a name, the arm's tool frame's Pose, or
    None)."""
    if grasp is None or isinstance(grasp, str):
        return grasp
    try:
        return tool_grasp(ctx, arm, Pose.from_se3(grasp.se3()), grasp.link)
    except TaskSpecError as exc:
        raise _error(step, exc.reason) from None


def _gripper_poses(step: StepNode, ctx: TaskContext, arm: str) -> tuple[str, str]:
    """The arm's open and closed gripper pose names (an error at the step when it has
    none)."""
    try:
        found = ctx.arm(arm)
        if found.gripper is None:
            raise TaskSpecError(f"arm {arm!r} has no gripper group")
        return found.open_pose, found.closed_pose
    except (RobotDescriptionError, TaskSpecError) as exc:
        raise _error(step, getattr(exc, "reason", str(exc))) from None


def _position_only(target) -> bool | None:  # type: ignore[no-untyped-def]
    """As written, else True for a pose written without an orientation (reach the point),
    else None (the group's IK setting decides)."""
    if target.position_only is not None:
        return bool(target.position_only)
    return None if target.has_orientation else True


def _go_goal(step: GoStep):  # type: ignore[no-untyped-def]
    goal: Goal
    if step.to is not None:
        goal = NamedGoal(step.to)
    elif step.joints is not None:
        goal = JointGoal(dict(step.joints))
    else:
        target = step.pose
        assert target is not None
        goal = PoseGoal(target.to_pose(), link=target.link, position_only=_position_only(target))

    def go(ctx: TaskContext) -> Goal:
        end_lift_offs_left(ctx.scene)  # an attached object clear of its support: no allowance
        return goal

    return go


def _move(step: MoveStep, ctx: TaskContext) -> Behaviour:
    group = _group(step, ctx, step.group)
    link = step.link or ctx.scene.robot.group(group).tip_link
    if link is None:
        raise _error(step, f"group {group!r} has no tip link: give 'link'")
    name, where = step.label, _where(step)

    def target(c: TaskContext) -> Pose:
        end_lift_offs_left(c.scene)  # as a go's goal does
        if step.pose is not None:
            return step.pose.to_pose()
        assert step.by is not None
        now = c.scene.link_pose(link).se3
        offset = step.by.se3()
        if step.by.frame == "tool":
            return Pose.from_se3(now * offset)
        moved = pin.SE3(offset.rotation @ now.rotation, now.translation + offset.translation)
        return Pose.from_se3(moved)

    if step.cartesian:
        position_only = _position_only(step.pose) if step.pose is not None else None
        return MoveStraight(name, where, ctx, group, lambda c: [target(c)], link,
                            CartesianOptions(position_only=position_only),
                            timing_options(step, ctx))
    return MoveToGoal(name, where, ctx, group,
                      lambda c: PoseGoal(target(c), link=link,
                                         position_only=_position_only(step.pose)
                                         if step.pose is not None else None),
                      planner_options(step), timing_options(step, ctx))


def _gripper(step: GripperStep, ctx: TaskContext) -> Behaviour:
    model = ctx.scene.robot
    names = {"open": "open", "close": "closed"}
    if step.arm is not None:
        gripper = ctx.arm(_arm(step, ctx, step.arm)).gripper
        if gripper is None:
            raise _error(step, f"arm {step.arm!r} has no gripper group")
        names = dict(zip(("open", "close"), _gripper_poses(step, ctx, step.arm)))
    else:
        assert step.group is not None
        gripper = _group(step, ctx, step.group)
    if step.width is not None:
        joints = model.group(gripper).joint_names
        kinds = {model.joint(j).type for j in joints}
        if kinds != {"prismatic"}:
            raise _error(step, f"'width' needs prismatic finger joints; gripper {gripper!r} "
                               f"has {', '.join(sorted(kinds))} joints: use 'action' or 'to'")
        # Each finger moves half the width (a mimic finger follows its source).
        values = {j: step.width / 2 for j in joints}
    else:
        pose = step.to or names[step.action or "open"]
        if pose not in model.named_state_names(gripper):
            raise _error(step, f"gripper group {gripper!r} has no named pose {pose!r} "
                               f"(poses: {', '.join(model.named_state_names(gripper))})")
        values = model.named_state(gripper, pose).as_dict()
    bad = model.limit_violations(model.state_with(model.default_state(), values))
    if bad:
        raise _error(step, "gripper target outside the joint limits: " + "; ".join(bad))
    # Closing on a held or touching object is expected: no collision check when closing.
    check = step.action != "close"
    return MoveJoints(step.label, _where(step), ctx, lambda c: dict(values), check=check,
                      timing=timing_options(step, ctx))


def _attach(step: AttachStep, ctx: TaskContext) -> Callable[[TaskContext], object]:
    obj = step.object
    if step.arm is not None:
        arm = ctx.arm(_arm(step, ctx, step.arm))
        link, touch = arm.holder, idioms.hand_links(ctx, step.arm)
    else:
        assert step.link is not None
        if not ctx.scene.robot.has_link(step.link):
            raise _error(step, f"'link': {step.link!r} is not a link of cell {ctx.cell.name!r}")
        link, touch = step.link, (step.link,)
    for other in step.touch_links:
        if not ctx.scene.robot.has_link(other):
            raise _error(step, f"'touch_links': {other!r} is not a link of cell "
                               f"{ctx.cell.name!r}")
    touch = tuple(dict.fromkeys((*touch, *step.touch_links)))

    def attach(c: TaskContext) -> None:
        c.scene.attach_object(obj, link, touch_links=touch)
        allow_lift_off(c.scene, obj)  # as a pick does: it may leave what it rests on

    return attach


def _parallel(step: ParallelStep, ctx: TaskContext, waits: _Waits) -> Behaviour:
    children = step.children
    for child in children:
        if isinstance(child, ExpectStep):
            raise _error(child, "'expect' cannot run in a 'parallel' (it would check while "
                                "the other children move): put it after the 'parallel'")
    gos = [c for c in children if isinstance(c, GoStep) and not waits.joins(c)]
    others = [c for c in children if not (isinstance(c, GoStep) and not waits.joins(c))]
    behaviours = [_compile(c, ctx, waits) for c in others]
    if len(gos) == 1:
        behaviours.append(_compile(gos[0], ctx, waits))
    elif gos:
        behaviours.append(_joint_go(step, gos, ctx))
    if len(behaviours) == 1:
        return behaviours[0]
    return TaskParallel(step.label, behaviours, ctx)


def _joint_go(step: ParallelStep, gos: list[GoStep], ctx: TaskContext) -> Behaviour:
    """Several arms' ``go`` steps as one motion in a group spanning them all."""
    model = ctx.scene.robot
    joints: set[str] = set()
    for go in gos:
        group = model.group(_group(go, ctx, go.group))
        if joints & set(group.joint_names):
            raise _error(go, f"parallel motions share joints of group {go.group!r}")
        joints |= set(group.joint_names)
    spanning = [g.name for g in model.groups.values() if set(g.joint_names) == joints]
    if not spanning:
        groups = ", ".join(go.group for go in gos)
        raise _error(step, f"moving {groups} at once needs a group spanning them; add one "
                           f"to the cell (groups: {{both: [{groups}]}})")
    goals = [(go, _go_goal(go)) for go in gos]

    def joint_goal(c: TaskContext) -> JointGoal:
        values: dict[str, float] = {}
        for go, goal in goals:
            g = goal(c)
            if isinstance(g, NamedGoal):
                values.update(c.scene.robot.named_state(go.group, g.name).as_dict())
            elif isinstance(g, JointGoal):
                values.update(g.values)
            else:
                from taskrunner.kinematics import IkOptions, IkSolver

                target = c.scene.to_world(g.pose)
                solver = IkSolver(c.scene.robot, go.group, frame=g.link)
                found = solver.solve(target, seed_q=c.scene.state,
                                     options=IkOptions(position_only=g.position_only,
                                                       seed=c.next_seed()))
                values.update(found.joint_state.as_dict())
        return JointGoal(values)

    first = gos[0]
    return MoveToGoal(step.label, _where(step), ctx, spanning[0], joint_goal,
                      planner_options(first), timing_options(first, ctx))

