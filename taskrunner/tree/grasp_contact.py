"""Whether a grasp is real: the fingers, closed, meet the object.

A grasp pose says where the arm's tool frame goes; nothing in it says that the fingers
reach the object. Here every grasp candidate is tried against the gripper's geometry: with
the gripper at the width its pick closes to (the arm's ``closed`` pose), each finger's
collision geometry, placed by the grasp pose, must meet the object's surface (coal
distance at most :data:`GRASP_CONTACT_TOLERANCE`; overlap counts as meeting, as a real
finger stops on the surface). A grasp far above the object, one beside it, or an object
narrower than the gap the closed fingers leave, fails, with the distances.

The open hand must clear the object too: at the gripper's ``open`` pose, placed by the
grasp pose, no finger may overlap it by more than :data:`OPEN_OVERLAP_TOLERANCE` (the
fingers and palm are allowed to touch the object from the approach on, so the collision
checks would not catch an object wider than the open gripper: the fingers would come down
on top of it).

Fingers are the subtrees of the gripper group's joints (and of joints mimicking them)
that no other such joint moves: a parallel gripper has two, each with its pads. A gripper
without finger geometry is not checked (nothing to measure). Units: m.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import coal
import numpy as np
import pinocchio as pin

from taskrunner.errors import SceneError
from taskrunner.scene.geometry import MeshCache, shape_geometry
from taskrunner.tree.context import TaskContext

__all__ = ["GRASP_CONTACT_TOLERANCE", "OPEN_OVERLAP_TOLERANCE", "FingerGap", "finger_gaps",
           "touching_grasps"]

GRASP_CONTACT_TOLERANCE = 0.003
"""How far (m) a closed finger may stay from the object and still be said to hold it."""

OPEN_OVERLAP_TOLERANCE = 0.0005
"""How deep (m) an open finger, at the grasp pose, may overlap the object (round-off and
mesh facets; a finger coming down further into it would hit it)."""

_MESHES = MeshCache()  # loaded meshes of objects, shared and never edited


@dataclass(frozen=True)
class _Finger:
    """One finger's collision geometry, placed in the tool frame at the closed width."""

    name: str
    parts: tuple[tuple[coal.CollisionGeometry, pin.SE3], ...]


@dataclass(frozen=True)
class FingerGap:
    """How a grasp's closed fingers meet an object.

    Attributes:
        width: m between the closed fingers (0 when they meet; nan for one finger).
        gaps: per finger (by its first link), m from the object (< 0: overlapping).
    """

    width: float
    gaps: dict[str, float]

    @property
    def worst(self) -> float:
        return max(self.gaps.values())

    def touches(self, tolerance: float = GRASP_CONTACT_TOLERANCE) -> bool:
        return self.worst <= tolerance


def _fingers(ctx: TaskContext, arm_name: str, which: str = "closed") -> list[_Finger]:
    """The arm's fingers at its gripper's ``closed`` (or ``open``) pose (empty: no
    gripper, no geometry)."""
    arm = ctx.arm(arm_name)
    if arm.gripper is None:
        return []
    model = ctx.scene.robot
    pmodel = model.model
    sources = set(model.group(arm.gripper).joint_names)
    joints = [j for j in model.joints
              if j.name in sources or (j.mimic is not None and j.mimic.source in sources)]
    subtrees = {j.name: set(pmodel.subtrees[pmodel.getJointId(j.name)]) for j in joints}
    ids = {j.name: pmodel.getJointId(j.name) for j in joints}
    tops = [j for j in joints
            if not any(ids[j.name] in subtrees[o.name] for o in joints if o.name != j.name)]
    pose = arm.closed_pose if which == "closed" else arm.open_pose
    q = model.state_with(ctx.scene.state, model.named_state(arm.gripper, pose))
    data = pmodel.createData()
    geometry = model.collision_model
    gdata = pin.GeometryData(geometry)
    pin.framesForwardKinematics(pmodel, data, model.to_pin(q))
    pin.updateGeometryPlacements(pmodel, data, geometry, gdata)
    tool_inverse = data.oMf[model.frame_id(arm.grasp_frame)].inverse()
    out = []
    for joint in tops:
        parts = tuple((g.geometry, tool_inverse * gdata.oMg[k])
                      for k, g in enumerate(geometry.geometryObjects)
                      if g.parentJoint in subtrees[joint.name])
        if parts:
            out.append(_Finger(joint.child_link, parts))
    return out


def _transform(placement: pin.SE3) -> coal.Transform3s:
    return coal.Transform3s(placement.rotation, placement.translation)


def _distance(a: coal.CollisionGeometry, at: pin.SE3, b: coal.CollisionGeometry,
              bt: pin.SE3) -> float:
    request, result = coal.DistanceRequest(), coal.DistanceResult()
    request.enable_signed_distance = True
    coal.distance(a, _transform(at), b, _transform(bt), request, result)
    return float(result.min_distance)


def _width(fingers: Sequence[_Finger]) -> float:
    """Gap between the closed fingers (m; nan with fewer than two)."""
    if len(fingers) < 2:
        return float("nan")
    return max(0.0, min(_distance(ga, pa, gb, pb)
                        for i, f in enumerate(fingers) for g in fingers[i + 1:]
                        for ga, pa in f.parts for gb, pb in g.parts))


def finger_gaps(ctx: TaskContext, arm_name: str, obj: str, grasps: Sequence[pin.SE3],
                which: str = "closed") -> list[FingerGap] | None:
    """For each grasp (world pose of the arm's tool frame), how its fingers, ``closed``
    (or ``open``), meet object ``obj`` as the scene has it; None when the gripper has no
    finger geometry."""
    fingers = _fingers(ctx, arm_name, which)
    if not fingers:
        return None
    target = shape_geometry(ctx.scene.object(obj).shape, _MESHES)
    placed = ctx.scene.object_pose(obj).se3
    width = _width(fingers)
    return [FingerGap(width, {f.name: min(_distance(g, grasp * p, target, placed)
                                          for g, p in f.parts) for f in fingers})
            for grasp in grasps]


def touching_grasps(ctx: TaskContext, arm_name: str, obj: str, grasps: Sequence[pin.SE3],
                    tolerance: float = GRASP_CONTACT_TOLERANCE) -> list[pin.SE3]:
    """The grasps of ``grasps`` whose closed fingers all meet ``obj`` and whose open
    fingers all clear it (see the module docstring).

    Raises:
        SceneError: none does; the message gives the width of the fingers and the
            distance (or overlap) of the best grasp's worst finger.
    """
    gaps = finger_gaps(ctx, arm_name, obj, grasps)
    if gaps is None or not grasps:
        return list(grasps)
    where = "" if len(grasps) == 1 else f" (best of {len(grasps)} grasps)"
    kept = [g for g, gap in zip(grasps, gaps, strict=True) if gap.touches(tolerance)]
    if not kept:
        best = min(gaps, key=lambda gap: gap.worst)
        finger = max(best.gaps, key=lambda name: best.gaps[name])
        width = ("" if np.isnan(best.width)
                 else f"the fingers close to {1e3 * best.width:.0f} mm and ")
        raise SceneError(
            f"grasp does not reach {obj!r}: {width}{finger!r} stays {1e3 * best.worst:.1f} "
            f"mm from {obj!r} at closed width{where} (allowed: {1e3 * tolerance:.0f} mm)")
    opened = finger_gaps(ctx, arm_name, obj, kept, "open")
    assert opened is not None  # the same fingers
    clear = [g for g, gap in zip(kept, opened, strict=True)
             if min(gap.gaps.values()) >= -OPEN_OVERLAP_TOLERANCE]
    if clear:
        return clear
    best = max(opened, key=lambda gap: min(gap.gaps.values()))
    finger = min(best.gaps, key=lambda name: best.gaps[name])
    width = "" if np.isnan(best.width) else f"the fingers open to {1e3 * best.width:.0f} mm and "
    where = "" if len(kept) == 1 else f" (best of {len(kept)} grasps)"
    raise SceneError(
        f"grasp does not fit {obj!r}: {width}{finger!r} overlaps {obj!r} by "
        f"{-1e3 * best.gaps[finger]:.1f} mm at open width{where} (the object is wider than "
        f"the open gripper there; allowed: {1e3 * OPEN_OVERLAP_TOLERANCE:.1f} mm)")
