"""Pick, place and hand-over as subtrees of plain leaves.

Each idiom is a function returning the root of a subtree (a py_trees ``Sequence``), in the
manner of MoveIt Task Constructor's stages:

- pick = open the gripper, plan to a pre-grasp above the object, approach it in a straight
  line, close, attach, retreat straight up;
- place = plan to a pre-place above the target, descend in a straight line, open, detach,
  retreat back along the tool;
- hand-over = the giver carries the object to the hand-over pose, the receiver opens,
  plans to a pre-grasp at the free end of the object, approaches and closes, the object
  passes from one gripper to the other in one scene edit (attached to exactly one gripper
  at every moment), the giver opens and backs off, the receiver backs off with it.

Grasp geometry: both our grippers close along their grasp frame's y axis and point along
its z axis. A top grasp points the tool straight down at the top face, ``depth`` below it;
its yaw is left to the planner among the object's symmetric choices (every 90° for a box,
45° for a cylinder or sphere).

Arms with fewer than six joints (``position_only_ik`` in kinematics.yaml, like the 5-DOF
servo arm) cannot point their tool in an arbitrary direction: for them the grasp frame's
position is planned and the straight moves keep to a line in world axes (down onto the
object, up off it), the orientation following from the arm, as MoveIt does with
position-only IK. While such an arm puts an object down, the object may touch the fixed
objects of the world (it is being set on them); those allowances end with the retreat.
"""

from __future__ import annotations

import math
from collections.abc import Sequence

import numpy as np
import pinocchio as pin
import py_trees

from taskrunner.errors import SceneError, TaskSpecError
from taskrunner.planning.cartesian import CartesianOptions
from taskrunner.planning.request import NamedGoal, PlannerOptions, PoseGoal
from taskrunner.planning.timing import TimingOptions
from taskrunner.shapes import Box, Cylinder, Sphere
from taskrunner.tree.behaviours import MoveJoints, MoveStraight, MoveToGoal, SceneAction
from taskrunner.tree.context import TaskContext
from taskrunner.types import Pose

__all__ = ["grasp_candidates", "handoff", "object_extent", "pick", "place"]

# How far into the object, from its end face, the grasp frame goes (m): at most this, and
# at most GRASP_DEPTH_FRACTION of the object's half size, so fingertips stay clear of what
# the object stands on.
GRASP_DEPTH = 0.02
GRASP_DEPTH_FRACTION = 0.6
# Placed objects stop this far above the surface they are put on (m).
PLACE_CLEARANCE = 0.001


def object_extent(shape) -> np.ndarray:  # type: ignore[no-untyped-def]
    """Full size of the object's bounding box in its own frame (m)."""
    if isinstance(shape, Box):
        return np.array(shape.size)
    if isinstance(shape, Cylinder):
        return np.array([2 * shape.radius, 2 * shape.radius, shape.length])
    if isinstance(shape, Sphere):
        return np.full(3, 2 * shape.radius)
    raise SceneError(f"grasping a {type(shape).__name__.lower()} is not supported")


def _yaw_steps(shape) -> int:  # type: ignore[no-untyped-def]
    return 4 if isinstance(shape, Box) else 8


def grasp_candidates(ctx: TaskContext, obj: str, grasp: str | Pose) -> list[pin.SE3]:
    """World poses of the grasp frame that grasp ``obj`` (several yaw choices for 'top').

    ``grasp`` is 'top', 'side' (horizontal, pointing from the world origin's side… see
    :func:`side_grasps`) or an explicit grasp-frame pose in the object's frame.
    """
    scene = ctx.scene
    placed = scene.object_pose(obj).se3
    shape = scene.object(obj).shape
    if isinstance(grasp, Pose):
        return [placed * grasp.se3]
    extent = object_extent(shape)
    if grasp == "top":
        depth = min(GRASP_DEPTH, GRASP_DEPTH_FRACTION * extent[2] / 2)
        top = placed.translation + placed.rotation @ np.array([0.0, 0.0, extent[2] / 2 - depth])
        out = []
        for k in range(_yaw_steps(shape)):
            yaw = _object_yaw(placed) + k * 2 * math.pi / _yaw_steps(shape)
            # Tool z down, tool y (the closing axis) along the object's rotated x.
            rotation = pin.rpy.rpyToMatrix(0.0, 0.0, yaw) @ pin.rpy.rpyToMatrix(math.pi, 0.0, 0.0)
            out.append(pin.SE3(rotation, top))
        return out
    if grasp == "side":
        return side_grasps(placed, extent)
    raise TaskSpecError(f"'grasp' must be 'top', 'side' or a pose (got {grasp!r})")


def side_grasps(placed: pin.SE3, extent: np.ndarray) -> list[pin.SE3]:
    """Horizontal grasps at mid-height, tool z pointing into each vertical face."""
    out = []
    for k in range(4):
        yaw = _object_yaw(placed) + k * math.pi / 2
        approach = np.array([math.cos(yaw), math.sin(yaw), 0.0])
        half = extent[0] / 2 if k % 2 == 0 else extent[1] / 2
        depth = min(GRASP_DEPTH, GRASP_DEPTH_FRACTION * half)
        centre = placed.translation - approach * (half - depth)
        z = approach
        y = np.array([0.0, 0.0, 1.0])
        x = np.cross(y, z)
        out.append(pin.SE3(np.column_stack([x, y, z]), centre))
    return out


def _object_yaw(placed: pin.SE3) -> float:
    x = placed.rotation[:, 0]
    return math.atan2(x[1], x[0])


def _backed_off(pose: pin.SE3, distance: float) -> pin.SE3:
    """``pose`` moved ``distance`` back along its own z (a pre-grasp)."""
    return pose * pin.SE3(np.eye(3), np.array([0.0, 0.0, -distance]))


def _goals(poses: Sequence[pin.SE3], link: str) -> tuple[PoseGoal, ...]:
    return tuple(PoseGoal(Pose.from_se3(p), link=link, position_only=False) for p in poses)


def _open(ctx: TaskContext, arm_name: str) -> dict[str, float]:
    arm = ctx.arm(arm_name)
    if arm.gripper is None:
        raise TaskSpecError(f"arm {arm_name!r} has no gripper group")
    return ctx.scene.robot.named_state(arm.gripper, "open").as_dict()


def _closed(ctx: TaskContext, arm_name: str) -> dict[str, float]:
    arm = ctx.arm(arm_name)
    if arm.gripper is None:
        raise TaskSpecError(f"arm {arm_name!r} has no gripper group")
    return ctx.scene.robot.named_state(arm.gripper, "closed").as_dict()


def _allow_fingers(obj: str, arm_name: str, allow: bool):  # type: ignore[no-untyped-def]
    def action(ctx: TaskContext) -> None:
        for link in ctx.arm(arm_name).finger_links:
            if allow:
                ctx.scene.allow_collision(obj, link, reason="grasp")
            elif ctx.scene.collision_allowed(obj, link) and \
                    ctx.scene.allowed_collisions().get(frozenset((obj, link))) == "grasp":
                ctx.scene.disallow_collision(obj, link)
    return action


def _straight(ctx: TaskContext, arm_name: str, offset, frame: str):  # type: ignore[no-untyped-def]
    """Waypoints of a straight move of the grasp frame by ``offset`` (tool or world axes);
    ``offset`` may be a function of the context (evaluated when the move starts)."""
    def waypoints(c: TaskContext) -> list[Pose]:
        link = c.arm(arm_name).grasp_frame
        now = c.scene.link_pose(link).se3
        step = np.array(offset(c) if callable(offset) else offset, dtype=float)
        if frame == "tool":
            target = now * pin.SE3(np.eye(3), step)
        else:
            target = pin.SE3(now.rotation, now.translation + step)
        return [Pose.from_se3(target)]
    return waypoints


def _short(ctx: TaskContext, arm_name: str) -> bool:
    """True for an arm that plans positions only (fewer than six joints)."""
    return ctx.scene.robot.group(ctx.arm(arm_name).group).position_only_ik


def _straight_options(ctx: TaskContext, arm_name: str) -> CartesianOptions:
    return CartesianOptions(position_only=True if _short(ctx, arm_name) else False)


def _goals_for(ctx: TaskContext, arm_name: str, poses: Sequence[pin.SE3]) -> tuple[PoseGoal, ...]:
    link = ctx.arm(arm_name).grasp_frame
    if _short(ctx, arm_name):
        # One position goal per distinct position (yaw variants share it).
        seen: list[np.ndarray] = []
        goals = []
        for p in poses:
            if all(np.linalg.norm(p.translation - s) > 1e-6 for s in seen):
                seen.append(p.translation)
                goals.append(PoseGoal(Pose(tuple(p.translation)), link=link, position_only=True))
        return tuple(goals)
    return _goals(poses, link)


def _hold_world_contacts(obj: str, allow: bool):  # type: ignore[no-untyped-def]
    """Let ``obj`` touch the world's fixed objects while it is being set down (or stop)."""
    def action(c: TaskContext) -> None:
        for other in c.scene.objects:
            if other.name == obj or other.attached:
                continue
            pair = frozenset((obj, other.name))
            if allow and not c.scene.collision_allowed(obj, other.name):
                c.scene.allow_collision(obj, other.name, reason="set-down")
            elif not allow and c.scene.allowed_collisions().get(pair) == "set-down":
                c.scene.disallow_collision(obj, other.name)
    return action


def pick(ctx: TaskContext, name: str, location: str | None, arm_name: str, obj: str,
         grasp: str | Pose = "top", approach: float = 0.05, retreat: float = 0.05,
         options: PlannerOptions | None = None, timing: TimingOptions | None = None
         ) -> py_trees.composites.Sequence:
    """The pick subtree (see the module docstring)."""
    arm = ctx.arm(arm_name)
    link = arm.grasp_frame
    straight = _straight_options(ctx, arm_name)
    short = _short(ctx, arm_name)
    resting: list[frozenset[str]] = []
    # Which way the gripper travels onto the object, in world axes (for short arms).
    direction: list[np.ndarray] = [np.array([0.0, 0.0, -1.0])]

    def pre_grasps(c: TaskContext) -> tuple[PoseGoal, ...]:
        grasps = grasp_candidates(c, obj, grasp)
        direction[0] = grasps[0].rotation[:, 2]
        return _goals_for(c, arm_name, [_backed_off(p, approach) for p in grasps])

    def attach(c: TaskContext) -> None:
        c.scene.attach_object(obj, c.arm(arm_name).grasp_frame,
                              touch_links=c.arm(arm_name).finger_links)
        # What the object rests on (world objects were never checked against each other)
        # may touch it while it is lifted off.
        resting.clear()
        for contact in c.scene.collisions():
            if obj in (contact.a, contact.b):
                resting.append(frozenset((contact.a, contact.b)))
        for pair in resting:
            a, b = tuple(pair)
            c.scene.allow_collision(a, b, reason="lift-off")

    def lifted(c: TaskContext) -> None:
        for pair in resting:
            a, b = tuple(pair)
            if c.scene.allowed_collisions().get(pair) == "lift-off":
                c.scene.disallow_collision(a, b)

    steps = [
        MoveJoints(f"{name}: open", location, ctx, lambda c: _open(c, arm_name), timing=timing),
        MoveToGoal(f"{name}: to pre-grasp", location, ctx, arm.group, pre_grasps, options, timing),
        SceneAction(f"{name}: allow finger contact", location, ctx,
                    _allow_fingers(obj, arm_name, True)),
        MoveStraight(f"{name}: approach", location, ctx, arm.group,
                     _straight(ctx, arm_name, lambda c: direction[0] * approach, "world")
                     if short else _straight(ctx, arm_name, (0.0, 0.0, approach), "tool"),
                     link, straight, timing),
        MoveJoints(f"{name}: close", location, ctx, lambda c: _closed(c, arm_name), check=True,
                   timing=timing),
        SceneAction(f"{name}: attach", location, ctx, attach),
        MoveStraight(f"{name}: retreat", location, ctx, arm.group,
                     _straight(ctx, arm_name, (0.0, 0.0, retreat), "world"), link, straight, timing),
        SceneAction(f"{name}: lifted", location, ctx, lifted),
    ]
    return py_trees.composites.Sequence(name, memory=True, children=steps)


def place_target(ctx: TaskContext, obj: str, at: Pose | None, on: str | None,
                 offset: Sequence[float] = (0.0, 0.0)) -> pin.SE3:
    """World pose the object is placed at: ``at``, or on top of object ``on``."""
    if at is not None:
        return ctx.scene.to_world(at)
    assert on is not None
    surface = ctx.scene.object_pose(on).se3
    top = surface.translation[2] + object_extent(ctx.scene.object(on).shape)[2] / 2
    half = object_extent(ctx.scene.object(obj).shape)[2] / 2
    xy = surface.translation[:2] + np.asarray(offset, dtype=float)
    yaw = _object_yaw(surface)
    return pin.SE3(pin.rpy.rpyToMatrix(0.0, 0.0, yaw),
                   np.array([xy[0], xy[1], top + half + PLACE_CLEARANCE]))


def place(ctx: TaskContext, name: str, location: str | None, arm_name: str, obj: str,
          at: Pose | None = None, on: str | None = None, offset: Sequence[float] = (0.0, 0.0),
          approach: float = 0.05, retreat: float = 0.05, options: PlannerOptions | None = None,
          timing: TimingOptions | None = None) -> py_trees.composites.Sequence:
    """The place subtree (see the module docstring)."""
    arm = ctx.arm(arm_name)
    link = arm.grasp_frame
    straight = _straight_options(ctx, arm_name)
    short = _short(ctx, arm_name)

    def pre_places(c: TaskContext) -> tuple[PoseGoal, ...]:
        held = c.scene.object(obj)
        if held.attached_to != link:
            raise SceneError(f"object {obj!r} is not held by arm {arm_name!r}")
        target = place_target(c, obj, at, on, offset)
        grip = held.pose.se3  # object in the grasp frame
        poses = []
        steps = _yaw_steps(held.shape)
        for k in range(steps):
            turned = target * pin.SE3(pin.rpy.rpyToMatrix(0.0, 0.0, k * 2 * math.pi / steps),
                                      np.zeros(3))
            tool = turned * grip.inverse()
            poses.append(pin.SE3(tool.rotation, tool.translation + np.array([0, 0, approach])))
        if short:
            # The arm cannot choose the held object's orientation: aim its position.
            # Offset of the object from the grasp frame, in world axes as it is carried now
            # (the arm's orientation at the target differs little for a short descent).
            carried = c.scene.link_pose(link).se3.rotation @ held.pose.se3.translation
            lift = target.translation + np.array([0.0, 0.0, approach]) - carried
            return (PoseGoal(Pose(tuple(lift)), link=link, position_only=True),)
        return _goals(poses, link)

    def detach(c: TaskContext) -> None:
        c.scene.detach_object(obj)
        _allow_fingers(obj, arm_name, True)(c)

    steps = [
        MoveToGoal(f"{name}: to pre-place", location, ctx, arm.group, pre_places, options, timing),
    ]
    if short:
        steps.append(SceneAction(f"{name}: allow set-down contact", location, ctx,
                                 _hold_world_contacts(obj, True)))
    steps += [
        MoveStraight(f"{name}: descend", location, ctx, arm.group,
                     _straight(ctx, arm_name, (0.0, 0.0, -approach), "world"), link, straight,
                     timing),
        MoveJoints(f"{name}: open", location, ctx, lambda c: _open(c, arm_name), check=False,
                   timing=timing),
        SceneAction(f"{name}: detach", location, ctx, detach),
        MoveStraight(f"{name}: retreat", location, ctx, arm.group,
                     _straight(ctx, arm_name, (0.0, 0.0, retreat), "world") if short
                     else _straight(ctx, arm_name, (0.0, 0.0, -retreat), "tool"), link, straight,
                     timing),
        SceneAction(f"{name}: released", location, ctx, _allow_fingers(obj, arm_name, False)),
    ]
    if short:
        steps.append(SceneAction(f"{name}: set down", location, ctx,
                                 _hold_world_contacts(obj, False)))
    return py_trees.composites.Sequence(name, memory=True, children=steps)


def handoff(ctx: TaskContext, name: str, location: str | None, obj: str, giver: str,
            receiver: str, at: str | Pose, approach: float = 0.05, retreat: float = 0.05,
            options: PlannerOptions | None = None, timing: TimingOptions | None = None
            ) -> py_trees.composites.Sequence:
    """The hand-over subtree (see the module docstring)."""
    give, take = ctx.arm(giver), ctx.arm(receiver)
    straight = CartesianOptions(position_only=False)

    def presentation(c: TaskContext):  # type: ignore[no-untyped-def]
        if isinstance(at, str):
            return NamedGoal(at)
        held = c.scene.object(obj)
        return PoseGoal(Pose.from_se3(c.scene.to_world(at) * held.pose.se3.inverse()),
                        link=give.grasp_frame, position_only=False)

    def receiver_pre_grasps(c: TaskContext) -> tuple[PoseGoal, ...]:
        held = c.scene.object(obj)
        if held.attached_to != give.grasp_frame:
            raise SceneError(f"object {obj!r} is not held by arm {giver!r}")
        placed = c.scene.object_pose(obj).se3
        extent = object_extent(held.shape)
        # The giver holds one end of the object's longest axis: grasp the other end,
        # pointing back toward the giver along that axis.
        axis = int(np.argmax(extent))
        giver_in_object = held.pose.se3.inverse().translation  # grasp frame in object frame
        sign = 1.0 if giver_in_object[axis] >= 0 else -1.0
        direction = placed.rotation[:, axis] * sign  # from the free end toward the giver
        depth = min(GRASP_DEPTH, GRASP_DEPTH_FRACTION * extent[axis] / 2)
        end = placed.translation - direction * (extent[axis] / 2 - depth)
        z = direction / np.linalg.norm(direction)
        poses = []
        for k in range(4):
            ref = np.array([0.0, 0.0, 1.0]) if abs(z[2]) < 0.9 else np.array([1.0, 0.0, 0.0])
            y = np.cross(z, ref)
            y /= np.linalg.norm(y)
            y = pin.AngleAxis(k * math.pi / 2, z).toRotationMatrix() @ y
            x = np.cross(y, z)
            grasp = pin.SE3(np.column_stack([x, y, z]), end)
            poses.append(_backed_off(grasp, approach))
        return _goals(poses, take.grasp_frame)

    def transfer(c: TaskContext) -> None:
        c.scene.detach_object(obj)
        c.scene.attach_object(obj, take.grasp_frame, touch_links=take.finger_links)
        _allow_fingers(obj, giver, True)(c)

    steps = [
        MoveToGoal(f"{name}: {giver} presents", location, ctx, give.group, presentation,
                   options, timing),
        MoveJoints(f"{name}: {receiver} opens", location, ctx, lambda c: _open(c, receiver),
                   timing=timing),
        MoveToGoal(f"{name}: {receiver} to pre-grasp", location, ctx, take.group,
                   receiver_pre_grasps, options, timing),
        SceneAction(f"{name}: allow {receiver} contact", location, ctx,
                    _allow_fingers(obj, receiver, True)),
        MoveStraight(f"{name}: {receiver} approaches", location, ctx, take.group,
                     _straight(ctx, receiver, (0.0, 0.0, approach), "tool"), take.grasp_frame,
                     straight, timing),
        MoveJoints(f"{name}: {receiver} closes", location, ctx, lambda c: _closed(c, receiver),
                   timing=timing),
        SceneAction(f"{name}: transfer to {receiver}", location, ctx, transfer),
        MoveJoints(f"{name}: {giver} opens", location, ctx, lambda c: _open(c, giver),
                   check=False, timing=timing),
        MoveStraight(f"{name}: {giver} backs off", location, ctx, give.group,
                     _straight(ctx, giver, (0.0, 0.0, -retreat), "tool"), give.grasp_frame,
                     straight, timing),
        SceneAction(f"{name}: {giver} released", location, ctx, _allow_fingers(obj, giver, False)),
        MoveStraight(f"{name}: {receiver} backs off", location, ctx, take.group,
                     _straight(ctx, receiver, (0.0, 0.0, -retreat), "tool"), take.grasp_frame,
                     straight, timing),
    ]
    return py_trees.composites.Sequence(name, memory=True, children=steps)
