"""A cell's links as a tf tree: the URDF's joints as parent → child transforms.

Every URDF joint is one edge of the tree (``parent`` link → ``child`` link), as
``robot_state_publisher`` publishes it: fixed joints on ``/tf_static`` (the cell's robot
placements are the fixed ``world`` → base joints of the merged URDF), the others on
``/tf``. Each transform is computed from our own forward kinematics (pinocchio, the model
the planner uses): ``parent_T_child = inverse(world_T_parent) · world_T_child``, so a
viewer composing the chain from ``world`` gets the link poses the planner saw.

The ``/robot_description`` text is the merged URDF with each mesh file given as a
``file://`` URI (Foxglove and RViz resolve those; a bare absolute path they do not).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pinocchio as pin

from taskrunner.errors import RobotDescriptionError
from taskrunner.export.rosmsg import Transform
from taskrunner.robot.model import RobotModel

__all__ = ["FrameTree", "TreeJoint", "robot_description"]


@dataclass(frozen=True)
class TreeJoint:
    """One URDF joint as a tf edge."""

    name: str
    type: str
    parent: str
    child: str

    @property
    def fixed(self) -> bool:
        return self.type == "fixed"


def _quat_xyzw(rotation: np.ndarray) -> tuple[float, float, float, float]:
    q = pin.Quaternion(rotation)
    q.normalize()
    if q.w < 0:  # one of the two equal quaternions, the same every time
        return (-q.x, -q.y, -q.z, -q.w)
    return (q.x, q.y, q.z, q.w)


class FrameTree:
    """The tf tree of a robot model (see the module docstring).

    Args:
        model: the cell's robot model (its merged URDF and pinocchio model).

    Raises:
        RobotDescriptionError: a URDF joint without parent or child, or a link the
            pinocchio model does not know.
    """

    def __init__(self, model: RobotModel) -> None:
        self.model = model
        self._data = model.model.createData()  # its own: a live feed runs in a thread
        urdf = ET.fromstring(model.urdf_xml)
        joints = []
        for element in urdf.findall("joint"):
            parent, child = element.find("parent"), element.find("child")
            name = element.get("name", "")
            if parent is None or child is None or not parent.get("link") or not child.get("link"):
                raise RobotDescriptionError(
                    f"URDF of {model.name!r}: joint {name!r} must have a parent and a child link")
            joints.append(TreeJoint(name, element.get("type", ""), str(parent.get("link")),
                                    str(child.get("link"))))
        self.joints: tuple[TreeJoint, ...] = tuple(joints)
        children = {j.child for j in joints}
        links = [str(link.get("name")) for link in urdf.findall("link")]
        self.root = next((link for link in links if link not in children), links[0])
        for link in {self.root, *children}:
            if not model.model.existFrame(link, pin.BODY):
                raise RobotDescriptionError(
                    f"URDF of {model.name!r}: link {link!r} is not in the kinematic model")
        self.links: tuple[str, ...] = (self.root, *(j.child for j in joints))
        self._ids = {link: model.frame_id(link) for link in self.links}

    def link_poses(self, q: np.ndarray) -> dict[str, pin.SE3]:
        """``world_T_link`` of every link for state vector ``q`` (rad or m)."""
        pin.framesForwardKinematics(self.model.model, self._data, self.model.to_pin(q))
        return {link: pin.SE3(self._data.oMf[i]) for link, i in self._ids.items()}

    def _transforms(self, q: np.ndarray, stamp_ns: int, fixed: bool) -> list[Transform]:
        poses = self.link_poses(q)
        out = []
        for joint in self.joints:
            if joint.fixed != fixed:
                continue
            relative = poses[joint.parent].actInv(poses[joint.child])
            xyz = tuple(float(v) for v in relative.translation)
            out.append(Transform(stamp_ns, joint.parent, joint.child,
                                 (xyz[0], xyz[1], xyz[2]), _quat_xyzw(relative.rotation)))
        return out

    def moving_transforms(self, q: np.ndarray, stamp_ns: int) -> list[Transform]:
        """The ``/tf`` transforms (every non-fixed joint's edge) at state ``q``."""
        return self._transforms(q, stamp_ns, fixed=False)

    def static_transforms(self, stamp_ns: int) -> list[Transform]:
        """The ``/tf_static`` transforms (fixed joints, robot placements included)."""
        return self._transforms(self.model.default_state(), stamp_ns, fixed=True)


def robot_description(model: RobotModel) -> str:
    """The merged URDF, mesh files as ``file://`` URIs (see the module docstring)."""
    urdf = ET.fromstring(model.urdf_xml)
    for mesh in urdf.iter("mesh"):
        filename = mesh.get("filename", "")
        if filename and "://" not in filename:
            mesh.set("filename", Path(filename).resolve().as_uri())
    return ET.tostring(urdf, encoding="unicode")
