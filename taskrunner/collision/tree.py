"""A robot's kinematic tree as the compiled collision kernels read it.

One record per pinocchio joint (:data:`JOINT`, named fields): its parent, its kind
(:class:`JointKind`, the one code table of the kernels), the index of its value in the
robot's state vector, its placement on the parent (rotation, row-major, then translation,
m: as :func:`taskrunner.collision.frames.compose` reads a placement) and its axis in its own
frame (a unit vector). :class:`KinematicTree` builds the records
of a :class:`~taskrunner.robot.RobotModel` and what bounds on the motion of a body need
(lever arms: :meth:`KinematicTree.levers`, :func:`lever_arms`); the forward kinematics that reads them is
:func:`taskrunner.collision.frames.joint_frames`.
"""

from __future__ import annotations

from enum import IntEnum

import numpy as np
import pinocchio as pin

from taskrunner.robot import RobotModel

__all__ = ["JOINT", "JointKind", "KinematicTree", "lever_arms"]


class JointKind(IntEnum):
    """How a joint moves its child (the ``kind`` field of :data:`JOINT`)."""

    FIXED = 0
    """Does not move (the universe joint, or a joint the kernels do not model: then
    :attr:`KinematicTree.supported` is False)."""
    REVOLUTE = 1
    """Rotates about its axis by the state's value (rad); continuous joints too."""
    PRISMATIC = 2
    """Slides along its axis by the state's value (m)."""


JOINT = np.dtype([
    ("parent", np.int64),          # the parent joint's row (0: the world)
    ("kind", np.int64),            # a JointKind
    ("state", np.int64),           # index of the joint's value in the state vector, -1: none
    # placement on the parent: rotation (row-major, 0-8) then translation (m, 9-11)
    ("placement", np.float64, (12,)),
    ("axis", np.float64, (3,)),    # unit axis in the joint's frame
])
"""One joint of a :class:`KinematicTree` (row ``i`` is pinocchio's joint ``i``)."""


class KinematicTree:
    """The joint records of a robot model, and the per-joint facts lever arms need.

    Attributes:
        joints: ``(model.njoints,)`` records of :data:`JOINT`.
        supported: every joint with a state value is revolute, continuous or prismatic
            (and none is a mimic): the compiled kinematics reproduce pinocchio's.
        state_joint: per state index, its joint's row (-1: none).
        order: the state indices, deepest joint first.
        revolute: per state index, 1 where its joint is revolute.
        prismatic: the rows of the prismatic joints.
        prismatic_travel: per joint row, the farthest a prismatic joint slides (m).
    """

    def __init__(self, robot: RobotModel) -> None:
        model = robot.model
        n = model.njoints
        self.model = model
        self.nq = robot.nq
        self.links = frozenset(robot.link_names)
        joints = np.zeros(n, dtype=JOINT)
        joints["parent"] = [int(p) for p in model.parents]
        joints["state"] = -1
        self.state_joint = np.full(robot.nq, -1, dtype=np.int64)
        depth = np.zeros(n, dtype=np.int64)
        self.prismatic_travel = np.zeros(n)
        prismatic = set()
        for joint in robot.joints:
            jid = int(model.getJointId(joint.name))
            joints["state"][jid] = joint.index
            self.state_joint[joint.index] = jid
            if joint.type == "prismatic":
                prismatic.add(jid)
                self.prismatic_travel[jid] = max(abs(joint.lower), abs(joint.upper))
        self.prismatic = frozenset(prismatic)
        data = model.createData()
        pin.forwardKinematics(model, data, pin.neutral(model))
        supported = True
        for jid in range(1, n):
            placement = model.jointPlacements[jid]
            joints["placement"][jid, :9] = np.asarray(placement.rotation).reshape(9)
            joints["placement"][jid, 9:] = placement.translation
            depth[jid] = depth[joints["parent"][jid]] + 1
            subspace = np.asarray(data.joints[jid].S, dtype=float)
            if subspace.size != 6 or "Mimic" in model.joints[jid].shortname() \
                    or joints["state"][jid] < 0:
                supported = False
                continue
            linear, angular = subspace.reshape(6)[:3], subspace.reshape(6)[3:]
            if np.linalg.norm(angular) > 0.5 and np.linalg.norm(linear) < 1e-12:
                joints["kind"][jid] = JointKind.REVOLUTE
                joints["axis"][jid] = angular / np.linalg.norm(angular)
            elif np.linalg.norm(linear) > 0.5 and np.linalg.norm(angular) < 1e-12:
                joints["kind"][jid] = JointKind.PRISMATIC
                joints["axis"][jid] = linear / np.linalg.norm(linear)
            else:
                supported = False
        self.supported = supported
        self.joints = joints
        self.joint_translation = [float(np.linalg.norm(model.jointPlacements[j].translation))
                                  for j in range(n)]
        self.parent = [int(p) for p in joints["parent"]]
        kind = joints["kind"]
        state_depth = np.array([depth[j] if j >= 0 else 0 for j in self.state_joint])
        self.order = np.argsort(-state_depth, kind="stable").astype(np.int64)
        self.revolute = np.array([j >= 0 and kind[j] == JointKind.REVOLUTE
                                  for j in self.state_joint], dtype=np.int64)

    def levers(self, geometry_object: pin.GeometryObject) -> np.ndarray:
        """Per state index, a bound on how far its joint moves any point of the geometry
        object: for a revolute or continuous joint the distance (m/rad) from its axis,
        through the chain at full reach (joint offsets plus the full travel of prismatic
        joints in between, then the geometry's bounding sphere); 1 (m/m) for a prismatic
        joint; 0 where the joint does not move it (world objects, other branches)."""
        row = np.zeros(self.nq)
        geometry = geometry_object.geometry
        geometry.computeLocalAABB()
        centre = geometry_object.placement.act(np.asarray(geometry.aabb_center, dtype=float))
        reach = float(np.linalg.norm(centre)) + float(geometry.aabb_radius)
        jid = int(geometry_object.parentJoint)
        state_joint = self.state_joint
        while jid > 0:
            index = self.joints["state"][jid]
            if index >= 0 and state_joint[index] == jid:
                row[index] = 1.0 if jid in self.prismatic else reach
            # Reach from the parent joint's origin: this joint's offset and travel added.
            reach += self.joint_translation[jid]
            reach += self.prismatic_travel[jid]
            jid = self.parent[jid]
        return row


def lever_arms(robot: RobotModel, geometry_model: pin.GeometryModel,
               tree: KinematicTree | None = None) -> np.ndarray:
    """Per geometry object and state-vector joint, a bound on how far the joint moves it.

    Args:
        tree: ``robot``'s kinematic tree where the caller keeps one (else built here).

    Returns:
        ``(n_geometries, robot.nq)``: for a revolute or continuous joint, an upper bound
        (m/rad) on the distance from its axis to any point of the geometry (through the
        chain at full reach: joint offsets plus the full travel of prismatic joints in
        between, then the geometry's bounding sphere); for a prismatic joint 1 (m/m);
        0 where the joint does not move the geometry (world objects, other branches).
    """
    if tree is None:
        tree = KinematicTree(robot)
    levers = np.zeros((len(geometry_model.geometryObjects), robot.nq))
    for g, geometry_object in enumerate(geometry_model.geometryObjects):
        levers[g] = tree.levers(geometry_object)
    return levers
