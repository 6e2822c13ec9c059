"""Pick, place and hand-over as subtrees of plain leaves.

Each idiom is a function returning the root of a subtree (a py_trees ``Sequence``), in the
manner of MoveIt Task Constructor's stages:

- pick = open the gripper, plan to a pre-grasp ``approach`` back from the grasp, approach
  it in a straight line, close, attach, retreat straight up;
- place = check the target is free (:mod:`taskrunner.tree.occupancy`), plan to a
  pre-place ``approach`` above the release pose, descend in a straight
  line, open, detach, retreat (back along the tool, or straight up);
- hand-over = the giver carries the object to the hand-over pose, the receiver opens,
  plans to a pre-grasp at the free end of the object, approaches and closes; the object
  passes from one gripper to the other in one scene edit (attached to exactly one
  gripper at every moment); the giver opens and backs off, the receiver backs off with it.

The grasp geometry (top, side and hand-over grasps, release poses, which links may touch a
held object) is in :mod:`taskrunner.tree.grasps`. Arms of six joints or more plan full
poses. Arms with fewer (``position_only_ik``, like the 5-DOF servo arm) plan the position
of the grasp frame (or of the held object's centre) exactly and its orientation as near
the wanted one as they can; their straight moves hold the tool's orientation where the
arm can, else follow the line by position only. Goal states of a pre-grasp or pre-place
are chosen so that the straight move from them can be followed
(:mod:`taskrunner.tree.reach`).

Contacts allowed, and only while they are real: the fingers and palm with the object from
the approach until the fingers have backed off it; the object with what it rests on while
it is lifted off (the pairs found touching when it is attached: a pick ends them after its
retreat; an ``attach`` step's end at the first motion that starts with the object clear,
:func:`~taskrunner.tree.grasps.end_lift_offs_left`).
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import numpy as np
import pinocchio as pin
import py_trees

from taskrunner.errors import SceneError, TaskSpecError
from taskrunner.planning.cartesian import CartesianOptions
from taskrunner.planning.request import Goal, NamedGoal, PlannerOptions, PoseGoal
from taskrunner.planning.timing import TimingOptions
from taskrunner.tree.behaviours import MoveJoints, MoveStraight, MoveToGoal
from taskrunner.tree.context import TaskContext
from taskrunner.tree.grasp_contact import touching_grasps
from taskrunner.tree.grasps import (
    allow_lift_off,
    backed_off,
    end_lift_off,
    end_lift_offs_left,
    grasp_candidates,
    half_height,
    hand_links,
    handover_grasps,
    nearest,
    object_extent,
    place_target,
    release_poses,
    releases_with_grasp,
)
from taskrunner.tree.instant_leaves import CheckOutcome, SceneAction
from taskrunner.tree.occupancy import check_target_free
from taskrunner.tree.outcome import Orientation, Outcome, Tolerance, arm_orientation, measure
from taskrunner.tree.reach import Lift, StagedGoals, staged_approach_goals
from taskrunner.types import Pose

__all__ = ["default_orientation", "grasp_candidates", "hand_links", "handoff", "object_extent",
           "pick", "place", "place_target"]

_FULL = CartesianOptions(position_only=False)
_POSITION = CartesianOptions(position_only=True)


# ----------------------------------------------------------------------------- helpers
def _short(ctx: TaskContext, arm_name: str) -> bool:
    """True for an arm that plans positions only (fewer than six joints)."""
    return ctx.scene.robot.group(ctx.arm(arm_name).group).position_only_ik


def default_orientation(ctx: TaskContext, arm_name: str) -> Orientation:
    """What of a placed object's orientation the arm controls (see
    :func:`~taskrunner.tree.outcome.arm_orientation`): the default ``orientation``."""
    arm = ctx.arm(arm_name)
    return arm_orientation(ctx.scene.robot, arm.group, arm.grasp_frame, ctx.scene.state)


def _outcome_check(ctx: TaskContext, name: str, location: str | None, obj: str,
                   wanted: list[pin.SE3], arm_name: str, orientation: Orientation | None,
                   tolerance: Tolerance | None, supported: bool) -> CheckOutcome:
    """A leaf comparing where ``obj`` is with ``wanted[0]`` (filled in by an earlier leaf)."""
    def check(c: TaskContext) -> Outcome:
        how = orientation if orientation is not None else default_orientation(c, arm_name)
        return measure(c.scene, obj, wanted[0], how, tolerance or Tolerance(), supported)
    return CheckOutcome(name, location, ctx, check)


def _gripper_pose(ctx: TaskContext, arm_name: str, which: str) -> dict[str, float]:
    """The joint values of the arm's gripper pose ``which`` ('open' or 'closed', by the
    names its tool gives them)."""
    arm = ctx.arm(arm_name)
    if arm.gripper is None:
        raise TaskSpecError(f"arm {arm_name!r} has no gripper group")
    pose = arm.open_pose if which == "open" else arm.closed_pose
    return ctx.scene.robot.named_state(arm.gripper, pose).as_dict()


def _goals(c: TaskContext, arm_name: str, contact: Sequence[pin.SE3], lift: Lift,
           point: np.ndarray | None = None, grasping: bool = False) -> StagedGoals:
    """Goals a straight move away from the grasp frame poses ``contact`` (``lift(i, pose)``:
    the world offset from ``contact[i]``, reached at ``pose``), from which that move can
    be followed back; a short arm places ``point`` of its grasp frame exactly, its
    orientation as near as it can (see :mod:`taskrunner.tree.reach`). The list is computed
    as far as the planner needs it (:class:`~taskrunner.tree.reach.StagedGoals`)."""
    arm = c.arm(arm_name)
    return staged_approach_goals(c.scene.robot, arm.group, arm.grasp_frame, contact, lift,
                                 c.scene.state, c.next_seed(), point, grasping)


def _move(ctx: TaskContext, name: str, location: str | None, arm_name: str,
          target: Callable[[TaskContext, pin.SE3], np.ndarray], timing: TimingOptions | None
          ) -> MoveStraight:
    """A straight move of the arm's grasp frame to the position ``target(ctx, now)``
    (``now``: the frame's world pose when the move starts), its orientation held; a short
    arm that cannot hold it follows the line by position only."""
    arm = ctx.arm(arm_name)

    def waypoints(c: TaskContext) -> list[Pose]:
        now = c.scene.link_pose(arm.grasp_frame).se3
        return [Pose.from_se3(pin.SE3(now.rotation, np.asarray(target(c, now), dtype=float)))]

    fallback = _POSITION if _short(ctx, arm_name) else None
    return MoveStraight(name, location, ctx, arm.group, waypoints, arm.grasp_frame, _FULL,
                        timing, fallback=fallback)


def _by_world(offset: Sequence[float]) -> Callable[[TaskContext, pin.SE3], np.ndarray]:
    step = np.asarray(offset, dtype=float)
    return lambda c, now: now.translation + step


def _by_tool(distance: float) -> Callable[[TaskContext, pin.SE3], np.ndarray]:
    return lambda c, now: now.translation + now.rotation[:, 2] * distance


def _allow_hand(obj: str, arm_name: str, allow: bool):  # type: ignore[no-untyped-def]
    """Allow (or stop allowing) the arm's fingers and palm to touch ``obj``."""
    def action(ctx: TaskContext) -> None:
        allowed = ctx.scene.allowed_collisions()
        for link in hand_links(ctx, arm_name):
            if allow:
                ctx.scene.allow_collision(obj, link, reason="grasp")
            elif allowed.get(frozenset((obj, link))) == "grasp":
                ctx.scene.disallow_collision(obj, link)
    return action


def _open(ctx: TaskContext, name: str, location: str | None, arm_name: str,
          timing: TimingOptions | None) -> MoveJoints:
    return MoveJoints(name, location, ctx, lambda c: _gripper_pose(c, arm_name, "open"),
                      check=True, timing=timing)


def _close(ctx: TaskContext, name: str, location: str | None, arm_name: str,
           timing: TimingOptions | None) -> MoveJoints:
    return MoveJoints(name, location, ctx, lambda c: _gripper_pose(c, arm_name, "closed"),
                      check=True, timing=timing)


# ----------------------------------------------------------------------------- pick
def pick(ctx: TaskContext, name: str, location: str | None, arm_name: str, obj: str,
         grasp: str | Pose = "top", approach: float = 0.05, retreat: float = 0.05,
         options: PlannerOptions | None = None, timing: TimingOptions | None = None
         ) -> py_trees.composites.Sequence:
    """The pick subtree (see the module docstring)."""
    arm = ctx.arm(arm_name)
    grasps: list[pin.SE3] = []

    def pre_grasps(c: TaskContext) -> StagedGoals:
        end_lift_offs_left(c.scene)  # an object attached before and lifted off since
        grasps[:] = grasp_candidates(c, obj, grasp)
        # Only grasps whose closed fingers meet the object (before the arm moves).
        grasps[:] = touching_grasps(c, arm_name, obj, grasps)
        return _goals(c, arm_name, grasps, lambda i, p: -grasps[i].rotation[:, 2] * approach,
                      grasping=True)

    def grasp_point(c: TaskContext, now: pin.SE3) -> np.ndarray:
        # The grasp whose pre-grasp the arm reached (nearest by position).
        backed = [backed_off(p, approach) for p in grasps]
        return grasps[nearest(backed, now)].translation

    def attach(c: TaskContext) -> None:
        c.scene.attach_object(obj, c.arm(arm_name).holder, touch_links=hand_links(c, arm_name))
        allow_lift_off(c.scene, obj)  # what it rests on may touch it while it is lifted off

    def lifted(c: TaskContext) -> None:
        end_lift_off(c.scene, obj)

    steps = [
        _open(ctx, f"{name}: open", location, arm_name, timing),
        MoveToGoal(f"{name}: to pre-grasp", location, ctx, arm.group, pre_grasps, options, timing),
        SceneAction(f"{name}: allow finger contact", location, ctx,
                    _allow_hand(obj, arm_name, True)),
        _move(ctx, f"{name}: approach", location, arm_name, grasp_point, timing),
        _close(ctx, f"{name}: close", location, arm_name, timing),
        SceneAction(f"{name}: attach", location, ctx, attach),
        _move(ctx, f"{name}: retreat", location, arm_name, _by_world((0.0, 0.0, retreat)),
              timing),
        SceneAction(f"{name}: lifted", location, ctx, lifted),
    ]
    return py_trees.composites.Sequence(name, memory=True, children=steps)


# ----------------------------------------------------------------------------- place
def place(ctx: TaskContext, name: str, location: str | None, arm_name: str, obj: str,
          at: Pose | None = None, on: str | None = None, offset: Sequence[float] = (0.0, 0.0),
          approach: float = 0.05, retreat: float = 0.05, options: PlannerOptions | None = None,
          timing: TimingOptions | None = None, orientation: Orientation | None = None,
          tolerance: Tolerance | None = None, grasp: str | Pose | None = None
          ) -> py_trees.composites.Sequence:
    """The place subtree (see the module docstring), ending with a check that the object
    is at its target (``orientation``: what of its orientation is checked, default the
    arm's :func:`default_orientation`; ``tolerance``: default 5 mm, 5°) and rests on
    something. ``grasp`` ('top', 'side', or the tool's pose in the placed object's frame)
    chooses how the hand is over the object when it lets go (see
    :func:`~taskrunner.tree.grasps.releases_with_grasp`); None: any way it can.

    A short arm may release the object turned a little from the target (its orientation
    is only approximated): the release is then raised so that the object's lowest point
    is where the target's would be, never sunk into the surface.
    """
    arm = ctx.arm(arm_name)
    short = _short(ctx, arm_name)
    release: list[pin.SE3] = []

    def deficit(c: TaskContext, reached: pin.SE3) -> float:
        """How far the object, carried with the grasp frame at ``reached``, reaches below
        the target's lowest point (m; 0 if not: an exact orientation never does)."""
        held = c.scene.object(obj)
        carried = reached * arm.grip(held.pose.se3)
        target = release[0]
        lowest = target.translation[2] - half_height(held.shape, target.rotation)
        bottom = carried.translation[2] - half_height(held.shape, carried.rotation)
        return max(0.0, lowest - bottom) if short else 0.0

    def pre_places(c: TaskContext) -> StagedGoals:
        end_lift_offs_left(c.scene)
        held = c.scene.object(obj)
        if held.attached_to != arm.holder:
            raise SceneError(f"object {obj!r} is not held by arm {arm_name!r}")
        target = place_target(c, obj, at, on, offset)
        release[:] = [target]
        up = np.array([0.0, 0.0, 1.0])
        grip = arm.grip(held.pose.se3)
        poses = release_poses(target, grip, held.shape)
        if grasp is not None:
            poses = releases_with_grasp(poses, target, grasp, obj)
        return _goals(c, arm_name, poses, lambda i, p: up * (approach + deficit(c, p)),
                      grip.translation)

    def descent(c: TaskContext, now: pin.SE3) -> np.ndarray:
        # Down to where the held object's centre is at the target's height (a short arm's
        # pre-place may be lower than `approach`: see taskrunner.tree.reach.LIFT_PARTS),
        # less what would sink the object below the target's bottom.
        centre = now.translation + now.rotation @ arm.grip(c.scene.object(obj).pose.se3).translation
        drop = centre[2] - release[0].translation[2]
        down = pin.SE3(now.rotation, now.translation - np.array([0.0, 0.0, drop]))
        return down.translation + np.array([0.0, 0.0, deficit(c, down)])

    def detach(c: TaskContext) -> None:
        c.scene.detach_object(obj)
        end_lift_off(c.scene, obj)  # as the detach step does: set down, it rests anew
        _allow_hand(obj, arm_name, True)(c)

    def target_free(c: TaskContext) -> None:
        check_target_free(c.scene, obj, place_target(c, obj, at, on, offset))

    steps = [
        SceneAction(f"{name}: target free", location, ctx, target_free),
        MoveToGoal(f"{name}: to pre-place", location, ctx, arm.group, pre_places, options,
                   timing),
        _move(ctx, f"{name}: descend", location, arm_name, descent, timing),
        _open(ctx, f"{name}: open", location, arm_name, timing),
        SceneAction(f"{name}: detach", location, ctx, detach),
        _move(ctx, f"{name}: retreat", location, arm_name,
              _by_world((0.0, 0.0, retreat)) if short else _by_tool(-retreat), timing),
        SceneAction(f"{name}: released", location, ctx, _allow_hand(obj, arm_name, False)),
        _outcome_check(ctx, f"{name}: check outcome", location, obj, release, arm_name,
                       orientation, tolerance, supported=True),
    ]
    return py_trees.composites.Sequence(name, memory=True, children=steps)


# ----------------------------------------------------------------------------- hand-over
def handoff(ctx: TaskContext, name: str, location: str | None, obj: str, giver: str,
            receiver: str, at: str | Pose, approach: float = 0.05, retreat: float = 0.05,
            options: PlannerOptions | None = None, timing: TimingOptions | None = None,
            orientation: Orientation | None = None, tolerance: Tolerance | None = None,
            grasp: str | Pose | None = None) -> py_trees.composites.Sequence:
    """The hand-over subtree (see the module docstring), with a check, when the object
    changes hands, that it is at the hand-over pose: ``at`` as a pose of the object, or
    where the giver's named pose ``at`` puts it (``orientation`` and ``tolerance`` as for
    :func:`place`; the default orientation is the giver's). ``grasp`` is the receiver's
    grasp as for :func:`pick` ('top', 'side', or its tool's pose in the object's frame),
    of the object where the giver presents it; None: the free end (see
    :func:`~taskrunner.tree.grasps.handover_grasps`)."""
    give, take = ctx.arm(giver), ctx.arm(receiver)
    grasps: list[pin.SE3] = []
    meeting: list[pin.SE3] = []  # the object's requested world pose at the hand-over

    def presentation(c: TaskContext) -> Goal:
        end_lift_offs_left(c.scene)
        held = c.scene.object(obj)
        if isinstance(at, str):
            model = c.scene.robot
            there = model.state_with(c.scene.state, model.named_state(give.group, at))
            tool = c.scene.to_world(Pose.from_se3(pin.SE3.Identity(), give.grasp_frame), there)
            meeting[:] = [tool * give.grip(held.pose.se3)]
            return NamedGoal(at)
        meeting[:] = [c.scene.to_world(at)]
        return PoseGoal(Pose.from_se3(meeting[0] * give.grip(held.pose.se3).inverse()),
                        link=give.grasp_frame, position_only=False)

    def pre_grasps(c: TaskContext) -> StagedGoals:
        held = c.scene.object(obj)
        if held.attached_to != give.holder:
            raise SceneError(f"object {obj!r} is not held by arm {giver!r}")
        held_at = give.grip(held.pose.se3).inverse().translation  # giver grasp point, object frame
        base = c.scene.link_pose(c.scene.robot.group(take.group).base_link).se3.translation
        grasps[:] = (handover_grasps(c.scene.object_pose(obj).se3, held.shape, held_at, base)
                     if grasp is None else grasp_candidates(c, obj, grasp))
        # As a pick's: only grasps whose fingers meet the object closed and clear it open.
        grasps[:] = touching_grasps(c, receiver, obj, grasps)
        return _goals(c, receiver, grasps, lambda i, p: -grasps[i].rotation[:, 2] * approach,
                      grasping=True)

    def grasp_point(c: TaskContext, now: pin.SE3) -> np.ndarray:
        backed = [backed_off(p, approach) for p in grasps]
        return grasps[nearest(backed, now)].translation

    def transfer(c: TaskContext) -> None:
        c.scene.detach_object(obj)
        c.scene.attach_object(obj, take.holder, touch_links=hand_links(c, receiver))
        _allow_hand(obj, giver, True)(c)

    steps = [
        MoveToGoal(f"{name}: {giver} presents", location, ctx, give.group, presentation,
                   options, timing),
        _open(ctx, f"{name}: {receiver} opens", location, receiver, timing),
        MoveToGoal(f"{name}: {receiver} to pre-grasp", location, ctx, take.group, pre_grasps,
                   options, timing),
        SceneAction(f"{name}: allow {receiver} contact", location, ctx,
                    _allow_hand(obj, receiver, True)),
        _move(ctx, f"{name}: {receiver} approaches", location, receiver, grasp_point, timing),
        _close(ctx, f"{name}: {receiver} closes", location, receiver, timing),
        SceneAction(f"{name}: transfer to {receiver}", location, ctx, transfer),
        _outcome_check(ctx, f"{name}: check outcome", location, obj, meeting, giver,
                       orientation, tolerance, supported=False),
        _open(ctx, f"{name}: {giver} opens", location, giver, timing),
        _move(ctx, f"{name}: {giver} backs off", location, giver, _by_tool(-retreat), timing),
        SceneAction(f"{name}: {giver} released", location, ctx, _allow_hand(obj, giver, False)),
        _move(ctx, f"{name}: {receiver} backs off", location, receiver, _by_tool(-retreat),
              timing),
    ]
    return py_trees.composites.Sequence(name, memory=True, children=steps)
