"""Grasp geometry: where a gripper's grasp frame goes to hold, take over or put down an object.

Poses here are of an arm's tool frame (:mod:`taskrunner.robot.tools`): its y axis is
the axis the fingers close along, its z axis points out of the hand (into the object).
They are world poses (``pin.SE3``, metres); the functions taking a :class:`TaskContext`
read objects from its scene.

- A *top* grasp points the tool down the object's most vertical axis, ``depth`` below
  its top face, the fingers closing across a pair of side faces.
- A *side* grasp points the tool horizontally into a side face at the object's centre,
  the fingers closing across the two neighbouring side faces (never vertically, so no
  finger goes under the object).
- Fingers close across the object's narrowest way only (a bar lying down is not taken
  along its length).
- A *hand-over* grasp takes the free end of an object another gripper holds: across its
  longest axis (the tool pointing into a side face near that end), so the taker can later
  put the object down in any orientation its wrist allows, on its side included. (Taking
  it end-on would leave the object sticking out along the tool, which cannot be laid on a
  table without the hand hitting it.)
- A *release* pose is where the grasp frame must be for the held object to sit at its
  target, or at a pose the object cannot be told apart from (its symmetries). A place's
  ``grasp`` keeps those whose tool points down (``top``), sideways (``side``), or is the
  given pose of the tool in the placed object's frame.

Depths: the grasp frame goes ``min(GRASP_DEPTH, GRASP_DEPTH_FRACTION * half size)`` into
the object from the face it enters, so fingertips stay clear of what the object stands on.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence

import numpy as np
import pinocchio as pin

from taskrunner.errors import SceneError, TaskSpecError
from taskrunner.scene import Scene
from taskrunner.shapes import Box, Cylinder, Sphere
from taskrunner.tree.context import TaskContext
from taskrunner.types import Pose

__all__ = [
    "GRASP_DEPTH", "GRASP_DEPTH_FRACTION", "LIFT_OFF", "PLACE_CLEARANCE", "allow_lift_off",
    "backed_off", "end_lift_off", "end_lift_offs_left", "grasp_candidates",
    "half_height", "hand_links", "handover_grasps", "nearest", "object_extent", "place_target",
    "tool_grasp",
    "release_poses", "releases_with_grasp", "side_grasps", "symmetries", "top_grasps",
]

GRASP_DEPTH = 0.02
GRASP_DEPTH_FRACTION = 0.6
PLACE_CLEARANCE = 0.001
"""Placed objects stop this far above the surface they are put on (m)."""
LIFT_OFF = "lift-off"
"""The reason of the allowances between a just-taken object and what it rested on."""
ROUND_STEPS = 8
"""Directions tried around a round object's axis (every 45°)."""


def object_extent(shape) -> np.ndarray:  # type: ignore[no-untyped-def]
    """Full size of the object's bounding box in its own frame (m)."""
    if isinstance(shape, Box):
        return np.array(shape.size, dtype=float)
    if isinstance(shape, Cylinder):
        return np.array([2 * shape.radius, 2 * shape.radius, shape.length])
    if isinstance(shape, Sphere):
        return np.full(3, 2 * shape.radius)
    raise SceneError(f"grasping a {type(shape).__name__.lower()} is not supported")


def half_height(shape, rotation: np.ndarray) -> float:  # type: ignore[no-untyped-def]
    """Half the vertical extent of the shape turned by ``rotation`` (m): how far below
    its centre the object reaches."""
    if isinstance(shape, Sphere):
        return float(shape.radius)
    if isinstance(shape, Cylinder):
        c = abs(float(rotation[2, 2]))
        return c * shape.length / 2 + shape.radius * math.sqrt(max(0.0, 1 - c * c))
    return float(np.abs(rotation[2, :]) @ object_extent(shape) / 2)


def symmetries(shape) -> list[np.ndarray]:  # type: ignore[no-untyped-def]
    """Rotations (object frame) that leave the shape as it was, keeping its z axis on the
    z line: turning a placed object by one of them puts it on the same footprint."""
    extent = object_extent(shape)
    if isinstance(shape, Box):
        out = []
        for perm in itertools.permutations(range(3)):
            if perm[2] != 2 or not np.allclose(extent[list(perm)], extent, atol=1e-6):
                continue
            for signs in itertools.product((1.0, -1.0), repeat=3):
                matrix = np.zeros((3, 3))
                for row, (col, sign) in enumerate(zip(perm, signs)):
                    matrix[row, col] = sign
                if np.linalg.det(matrix) > 0:
                    out.append(matrix)
        return out
    turns = [pin.rpy.rpyToMatrix(0.0, 0.0, k * 2 * math.pi / ROUND_STEPS)
             for k in range(ROUND_STEPS)]
    if isinstance(shape, Sphere):
        return turns
    flip = pin.rpy.rpyToMatrix(math.pi, 0.0, 0.0)
    return turns + [t @ flip for t in turns]


def hand_links(ctx: TaskContext, arm_name: str) -> tuple[str, ...]:
    """Links of the arm's hand that may touch an object it holds.

    The fingers (every link their joints move, joints that mimic a finger joint
    included: the Panda's group ``hand`` names only ``panda_finger_joint1``, yet
    ``panda_rightfinger`` closes on the object too), the link the fingers are mounted on
    (the palm) and the arm's tip and grasp frame (when the grasp frame is a link; else the
    link it is fixed to).
    """
    arm = ctx.arm(arm_name)
    model = ctx.scene.robot
    links = list(arm.finger_links)
    if arm.grasp_frame in model.link_names:
        links.append(arm.grasp_frame)
    if arm.gripper is not None:
        sources = set(model.group(arm.gripper).joint_names)
        fingers = [j for j in model.joints
                   if j.name in sources or (j.mimic is not None and j.mimic.source in sources)]
        pmodel = model.model
        moved: set[int] = set()
        for joint in fingers:
            links.append(joint.parent_link)
            moved.update(pmodel.subtrees[pmodel.getJointId(joint.name)])
        links += [f.name for f in pmodel.frames
                  if f.type == pin.FrameType.BODY and f.parentJoint in moved]
    return tuple(dict.fromkeys(links))


def _depth(size: float) -> float:
    """How far into an object of ``size`` (m, along the entry direction) to grasp."""
    return min(GRASP_DEPTH, GRASP_DEPTH_FRACTION * size / 2)


def _frame(y: np.ndarray, z: np.ndarray, origin: np.ndarray) -> pin.SE3:
    """The grasp frame with closing axis ``y`` and pointing axis ``z`` (orthonormalized)."""
    z = z / np.linalg.norm(z)
    y = y - (y @ z) * z
    y = y / np.linalg.norm(y)
    return pin.SE3(np.column_stack([np.cross(y, z), y, z]), np.asarray(origin, dtype=float))


def _narrowest(extent: np.ndarray, axes: Sequence[int]) -> list[int]:
    """Of ``axes``, those the fingers can close across: the object's narrowest way (within
    1 mm; a gripper's opening is not known here, and the narrowest is the safe guess)."""
    least = min(extent[j] for j in axes)
    return [j for j in axes if extent[j] <= least + 1e-3]


def _round_axis(shape) -> int | None:  # type: ignore[no-untyped-def]
    """The axis a shape is round about (2 for a cylinder), None for a box."""
    return 2 if isinstance(shape, Cylinder) else None


def _around(axis: np.ndarray) -> list[np.ndarray]:
    """``ROUND_STEPS`` unit directions perpendicular to ``axis``."""
    ref = np.array([1.0, 0.0, 0.0]) if abs(axis[0]) < 0.9 else np.array([0.0, 1.0, 0.0])
    u = np.cross(axis, ref)
    u /= np.linalg.norm(u)
    v = np.cross(axis, u)
    return [math.cos(a) * u + math.sin(a) * v
            for a in np.arange(ROUND_STEPS) * 2 * math.pi / ROUND_STEPS]


def top_grasps(placed: pin.SE3, shape) -> list[pin.SE3]:  # type: ignore[no-untyped-def]
    """Grasps pointing down the object's most vertical axis, from above."""
    rotation, extent = placed.rotation, object_extent(shape)
    up = int(np.argmax(np.abs(rotation[2, :])))
    vertical = rotation[:, up] * math.copysign(1.0, rotation[2, up])
    top = placed.translation + vertical * (extent[up] / 2 - _depth(extent[up]))
    if isinstance(shape, Sphere) or (isinstance(shape, Cylinder) and up == 2):
        closings = _around(vertical)
    else:
        across = [j for j in range(3) if j != up]
        if isinstance(shape, Cylinder):  # lying: close across its axis only
            across = [j for j in across if j != 2]
        closings = [s * rotation[:, j] for j in _narrowest(extent, across) for s in (1.0, -1.0)]
    return [_frame(y, -vertical, top) for y in closings]


def side_grasps(placed: pin.SE3, shape) -> list[pin.SE3]:  # type: ignore[no-untyped-def]
    """Horizontal-ish grasps at the object's centre, into each side face, closing across
    the neighbouring side faces (two closing directions each)."""
    rotation, extent = placed.rotation, object_extent(shape)
    up = int(np.argmax(np.abs(rotation[2, :])))
    out = []
    if isinstance(shape, Sphere) or (isinstance(shape, Cylinder) and up == 2):
        vertical = rotation[:, up]
        radius = extent[0] / 2
        for normal in _around(vertical):
            centre = placed.translation + normal * (radius - _depth(2 * radius))
            across = np.cross(vertical, normal)
            out += [_frame(s * across, -normal, centre) for s in (1.0, -1.0)]
        return out
    sides = [j for j in range(3) if j != up]
    for j, k in (sides, sides[::-1]):
        if k not in _narrowest(extent, sides):
            continue
        for sign in (1.0, -1.0):
            normal = sign * rotation[:, j]
            centre = placed.translation + normal * (extent[j] / 2 - _depth(extent[j]))
            out += [_frame(s * rotation[:, k], -normal, centre) for s in (1.0, -1.0)]
    return out


def grasp_candidates(ctx: TaskContext, obj: str, grasp: str | Pose) -> list[pin.SE3]:
    """World poses of the grasp frame that grasp ``obj``: 'top', 'side', or an explicit
    grasp-frame pose in the object's frame."""
    placed = ctx.scene.object_pose(obj).se3
    shape = ctx.scene.object(obj).shape
    if isinstance(grasp, Pose):
        return [placed * grasp.se3]
    if grasp == "top":
        return top_grasps(placed, shape)
    if grasp == "side":
        return side_grasps(placed, shape)
    raise TaskSpecError(f"'grasp' must be 'top', 'side' or a pose (got {grasp!r})")


def handover_grasps(placed: pin.SE3, shape, held_at: np.ndarray,  # type: ignore[no-untyped-def]
                    taker: np.ndarray | None = None) -> list[pin.SE3]:
    """Grasps of the free end of an object held at ``held_at`` (the holder's grasp point
    in the object's frame, m): across the longest axis, ``depth`` from that end.

    Both ends are free when the holder grips the middle (within 1 mm). With ``taker``
    (the taking arm's base, world, m), only the grasps that reach for the object from the
    taker's side are kept (pointing away from it, within 45° of the best such direction
    in the horizontal plane), so the taker does not reach around the object or the
    holder's hand.
    """
    rotation, extent = placed.rotation, object_extent(shape)
    axis = int(np.argmax(extent))
    along = rotation[:, axis]
    ends = [1.0, -1.0] if abs(held_at[axis]) < 1e-3 else [-math.copysign(1.0, held_at[axis])]
    round_axis = _round_axis(shape)
    out = []
    for end in ends:
        point = placed.translation + end * along * (extent[axis] / 2 - _depth(extent[axis]))
        if isinstance(shape, Sphere) or round_axis == axis:
            radius = extent[(axis + 1) % 3] / 2
            for normal in _around(along):
                centre = point + normal * (radius - _depth(2 * radius))
                across = np.cross(along, normal)
                out += [_frame(s * across, -normal, centre) for s in (1.0, -1.0)]
            continue
        cross = [j for j in range(3) if j != axis]
        for j, k in (cross, cross[::-1]):
            if k not in _narrowest(extent, cross):
                continue
            for sign in (1.0, -1.0):
                normal = sign * rotation[:, j]
                centre = point + normal * (extent[j] / 2 - _depth(extent[j]))
                out += [_frame(s * rotation[:, k], -normal, centre) for s in (1.0, -1.0)]
    if taker is None:
        return out

    def reach(pose: pin.SE3) -> float:
        away = pose.translation[:2] - np.asarray(taker, dtype=float)[:2]
        norm = float(np.linalg.norm(away))
        return float(pose.rotation[:2, 2] @ away / norm) if norm > 1e-9 else 0.0

    best = max(reach(p) for p in out)
    return [p for p in out if reach(p) >= best - (1 - math.cos(math.pi / 4))]


def place_target(ctx: TaskContext, obj: str, at: Pose | None, on: str | None,
                 offset: Sequence[float] = (0.0, 0.0)) -> pin.SE3:
    """World pose the object is placed at: ``at``, or upright on top of object ``on``
    (turned like it about the vertical, ``offset`` (m) from its centre in its frame)."""
    if at is not None:
        return ctx.scene.to_world(at)
    assert on is not None
    surface = ctx.scene.object_pose(on).se3
    surface_shape = ctx.scene.object(on).shape
    top = surface.translation[2] + half_height(surface_shape, surface.rotation)
    half = object_extent(ctx.scene.object(obj).shape)[2] / 2
    x = surface.rotation[:, 0]
    yaw = math.atan2(x[1], x[0])
    turn = pin.rpy.rpyToMatrix(0.0, 0.0, yaw)
    xy = surface.translation[:2] + (turn[:2, :2] @ np.asarray(offset, dtype=float))
    return pin.SE3(turn, np.array([xy[0], xy[1], top + half + PLACE_CLEARANCE]))


def release_poses(target: pin.SE3, grip: pin.SE3, shape) -> list[pin.SE3]:  # type: ignore[no-untyped-def]
    """Grasp-frame poses that put an object held at ``grip`` (its pose in the grasp frame)
    at ``target`` or at a pose of ``target`` turned by one of its symmetries."""
    inverse = grip.inverse()
    return [target * pin.SE3(s, np.zeros(3)) * inverse for s in symmetries(shape)]


GRASP_KIND_COS = math.cos(math.pi / 4)
"""A release is a 'top' one when its tool points within 45° of straight down, a 'side'
one when it is within 45° of horizontal."""
GRASP_POSE_TOLERANCE = (0.01, math.radians(15.0))
"""How near (m, rad) a release must be to a place's explicit ``grasp`` pose: the object
is held as it was grasped, which an arm of fewer than six joints only approximates."""


def releases_with_grasp(poses: Sequence[pin.SE3], target: pin.SE3, grasp: str | Pose,
                        obj: str) -> list[pin.SE3]:
    """Of the release poses ``poses`` (for an object placed at ``target``), those that
    match a place's ``grasp``: 'top', 'side', or the tool's pose in the placed object's
    frame (the nearest release, within :data:`GRASP_POSE_TOLERANCE`).

    Raises:
        SceneError: none matches (the object is held otherwise).
    """
    if isinstance(grasp, Pose):
        wanted = target * grasp.se3
        best = poses[nearest(poses, wanted)]
        apart = float(np.linalg.norm(best.translation - wanted.translation))
        turn = float(np.linalg.norm(pin.log3(best.rotation.T @ wanted.rotation)))
        if apart <= GRASP_POSE_TOLERANCE[0] and turn <= GRASP_POSE_TOLERANCE[1]:
            return [best]
        raise SceneError(
            f"object {obj!r} is not held so that its tool can be at 'grasp' when it is "
            f"placed: the nearest release is {1e3 * apart:.0f} mm and "
            f"{math.degrees(turn):.0f}° from it (allowed: {1e3 * GRASP_POSE_TOLERANCE[0]:.0f} "
            f"mm, {math.degrees(GRASP_POSE_TOLERANCE[1]):.0f}°)")
    if grasp == "top":
        kept = [p for p in poses if -p.rotation[2, 2] >= GRASP_KIND_COS]
    elif grasp == "side":
        kept = [p for p in poses if abs(p.rotation[2, 2]) < GRASP_KIND_COS]
    else:
        raise TaskSpecError(f"'grasp' must be 'top', 'side' or a pose (got {grasp!r})")
    if not kept:
        raise SceneError(f"object {obj!r} cannot be put down with a {grasp!r} grasp as it "
                         "is held (its tool would point "
                         f"{'sideways or up' if grasp == 'top' else 'up or down'})")
    return kept


def backed_off(pose: pin.SE3, distance: float) -> pin.SE3:
    """``pose`` moved ``distance`` (m) back along its own z (a pre-grasp)."""
    return pose * pin.SE3(np.eye(3), np.array([0.0, 0.0, -distance]))


def nearest(poses: Sequence[pin.SE3], pose: pin.SE3) -> int:
    """Index of the pose of ``poses`` nearest ``pose`` (position, then orientation)."""
    def cost(p: pin.SE3) -> float:
        turn = float(np.linalg.norm(pin.log3(p.rotation.T @ pose.rotation)))
        return float(np.linalg.norm(p.translation - pose.translation)) + 1e-3 * turn
    return min(range(len(poses)), key=lambda i: cost(poses[i]))


def allow_lift_off(scene: Scene, obj: str) -> list[tuple[str, str]]:
    """Let object ``obj``, just attached, touch what it is found touching (what it rests
    on), so that it can be lifted off; the pairs allowed. (MoveIt Task Constructor's pick
    allows the object and its support in its lift stage the same way.)"""
    pairs = [(k.a, k.b) for k in scene.collisions() if obj in (k.a, k.b)]
    for a, b in pairs:
        scene.allow_collision(a, b, reason=LIFT_OFF)
    return pairs


def end_lift_off(scene: Scene, obj: str) -> None:
    """Take back the lift-off allowances of object ``obj`` (see :func:`allow_lift_off`)."""
    for pair, reason in list(scene.allowed_collisions().items()):
        if reason == LIFT_OFF and obj in pair:
            a, b = sorted(pair)
            scene.disallow_collision(a, b)


def end_lift_offs_left(scene: Scene) -> list[tuple[str, str]]:
    """Take back every lift-off allowance (see :func:`allow_lift_off`) whose two bodies no
    longer touch: the object has left what it rested on, and from now on touching it again
    is a collision. The pairs ended.

    Called at the start of every motion (a ``go``'s or ``move``'s goal, the first goal of
    ``pick``, ``place`` and ``handoff``), in ``run-task check`` and in the run alike, so
    that an ``attach`` step's allowance lasts while the object still touches its support
    (the motion that lifts it starts touching) and ends with the first motion that starts
    clear of it, as a ``pick``'s ends after its retreat."""
    pending = [tuple(sorted(pair)) for pair, reason in scene.allowed_collisions().items()
               if reason == LIFT_OFF]
    if not pending:
        return []
    probe = scene.copy()  # the pairs asked without the allowance, the scene left as it is
    for a, b in pending:
        probe.disallow_collision(a, b)
    touching = {frozenset((k.a, k.b)) for k in probe.collisions()}
    ended = [(a, b) for a, b in pending if frozenset((a, b)) not in touching]
    for a, b in ended:
        scene.disallow_collision(a, b)
    return ended


def tool_grasp(ctx: TaskContext, arm_name: str, pose: Pose, link: str | None) -> Pose:
    """An explicit grasp written for ``link`` (its pose in the object's frame) as the pose
    of the arm's tool frame, which the idioms place; ``link`` None: ``pose`` already is.

    Raises:
        TaskSpecError: ``link`` is not a frame of the cell, or a joint lies between it and
            the tool frame (their offset would depend on the joint).
    """
    arm = ctx.arm(arm_name)
    if link is None or link == arm.grasp_frame:
        return pose
    model = ctx.scene.robot
    if not model.model.existFrame(link):
        raise TaskSpecError(f"'grasp.link': {link!r} is not a link or frame of cell "
                            f"{ctx.cell.name!r}")
    frames = model.model.frames
    here, tool = frames[model.frame_id(link)], frames[model.frame_id(arm.grasp_frame)]
    if here.parentJoint != tool.parentJoint:
        raise TaskSpecError(f"'grasp.link': {link!r} does not move with arm {arm_name!r}'s "
                            f"tool frame {arm.grasp_frame!r} (a joint lies between them)")
    link_to_tool = here.placement.actInv(tool.placement)
    return Pose.from_se3(pose.se3 * link_to_tool)
