"""Tools: where each arm holds what it grasps, and how its gripper opens and closes.

An arm (a group with an SRDF end effector) grasps with a *tool frame*: its origin is the
tool centre point (TCP), between the fingers; its z axis points out of the hand (the
approach direction, into a grasped object) and its y axis is the axis the fingers close
along. Every grasp (``pick``, ``place``, ``handoff``) places this frame.

Where the tool frame is, for each end effector, first match wins:

1. declared: ``end_effectors:`` in the robot's ``robot.yaml`` or on the robot in a cell
   (the cell's entry replaces the manifest's, field by field)::

       end_effectors:
         left_hand:                        # the SRDF end effector's name
           link: left_flange               # default: the end effector's parent_link
           tcp_offset: {xyz: [0, 0, 0.1], rpy: [0, 0, 0]}   # the TCP in that link
           closing_axis: y                 # in the TCP frame: x, y, z, -x … or [x, y, z]
           approach_axis: z                # default z
           open: open                      # the gripper's pose names
           closed: close

2. the robot's ``<prefix>tool0`` link, when it has one (closing along its y axis);
3. the end effector's ``parent_link``, when it already lies between the fingers (as a
   MoveIt ``*_tcp`` link does), closing along its y axis;
4. derived from the fingers' collision geometry, when the parent link is behind them (a
   flange, as MoveIt Setup Assistant configs end): the TCP is halfway between the two
   fingers' geometry (at the gripper's open pose) and a fifth of their length back from
   their tips (the middle of the fingertip pads, where a grasp holds), closing along the
   line between the fingers, approaching along the parent link's axis that points from
   it to the fingers;
5. else the parent link itself, closing along its y axis.

A TCP that is not a link of the URDF is added to the model as a frame named
``<end effector>_tcp``. Declared axes are in the declared TCP frame; the tool frame is
that frame turned so that its y is the closing axis and its z the approach axis.

Gripper poses: ``open`` and ``closed`` when declared, else the gripper group's
``open`` (or ``opened``) and ``closed`` (or ``close``) named poses.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Annotated, Any, Literal

import numpy as np
import pinocchio as pin
from pydantic import BaseModel, ConfigDict, Field, ValidationError, model_validator

from taskrunner.errors import ArgumentError, RobotDescriptionError, YamlError
from taskrunner.robot.model import RobotModel
from taskrunner.validation import Metres, Radians, validate_node
from taskrunner.yamlfile import line_of

__all__ = ["OPEN_SPELLINGS", "CLOSED_SPELLINGS", "EndEffectorSettings", "DeclaredTool", "Tool",
           "install_tools", "read_end_effector_settings", "merge_declared"]

OPEN_SPELLINGS = ("open", "opened")
CLOSED_SPELLINGS = ("closed", "close")
_NAMED_AXES = {"x": 0, "y": 1, "z": 2}
_SNAP = math.radians(5.0)  # a derived axis this near a link axis is that axis
_BEHIND = 1e-3  # m: fingers wholly this far in front of the parent link: it is behind them
PAD_FRACTION = 0.2
"""A derived TCP is this fraction of the fingers' length back from their tips."""

Axis = Annotated[list[float], Field(min_length=3, max_length=3)] | Literal[
    "x", "y", "z", "-x", "-y", "-z", "+x", "+y", "+z"]


class _Strict(BaseModel):
    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)


class TcpOffset(_Strict):
    xyz: Annotated[list[Metres], Field(min_length=3, max_length=3)] = [0.0, 0.0, 0.0]
    rpy: Annotated[list[Radians], Field(min_length=3, max_length=3)] = [0.0, 0.0, 0.0]

    def se3(self) -> pin.SE3:
        return pin.SE3(pin.rpy.rpyToMatrix(*self.rpy), np.array(self.xyz, dtype=float))


def axis_vector(value: Axis) -> np.ndarray:
    """A unit vector from ``x``, ``-y`` … or three numbers."""
    if isinstance(value, str):
        out = np.zeros(3)
        out[_NAMED_AXES[value[-1]]] = -1.0 if value.startswith("-") else 1.0
        return out
    vector = np.array(value, dtype=float)
    norm = float(np.linalg.norm(vector))
    if norm < 1e-9:
        raise ArgumentError(f"must be a non-zero vector (got {value})")
    return vector / norm


class EndEffectorSettings(_Strict):
    """One end effector's declared tool (see the module docstring)."""

    link: str | None = None
    tcp_offset: TcpOffset | None = None
    closing_axis: Axis | None = None
    approach_axis: Axis | None = None
    open: str | None = None
    closed: str | None = None

    @model_validator(mode="after")
    def _axes_apart(self) -> EndEffectorSettings:
        closing = axis_vector(self.closing_axis) if self.closing_axis is not None else None
        approach = axis_vector(self.approach_axis) if self.approach_axis is not None else None
        if closing is not None and abs(float(closing @ (approach if approach is not None
                                                        else np.array([0, 0, 1.0])))) > 0.99:
            raise ValueError("'closing_axis' must be across 'approach_axis' (default z) "
                             f"(got {self.closing_axis} and {self.approach_axis or 'z'})")
        return self


class _Table(_Strict):
    end_effectors: dict[str, EndEffectorSettings]


@dataclass(frozen=True)
class DeclaredTool:
    """Settings of one end effector as files declare them, with where.

    Attributes:
        settings: the fields given (``settings.model_fields_set``).
        sources: the file and line of each given field, and of the entry under ``""``
            (a cell's fields over a manifest's keep their own files).
    """

    settings: EndEffectorSettings
    sources: Mapping[str, tuple[Path | None, int | None]] = field(default_factory=dict)

    def source(self, key: str = "") -> tuple[Path | None, int | None]:
        """File and line of field ``key`` (else of the entry)."""
        return self.sources.get(key, self.sources.get("", (None, None)))

    def error(self, key: str, message: str) -> YamlError:
        """A located error about field ``key`` (``""``: the entry)."""
        path, line = self.source(key)
        return YamlError(message, path, line)

    def where(self, key: str = "") -> str:
        """``path:line`` of field ``key`` (else of the entry)."""
        path, line = self.source(key)
        if path is None:
            return "(no file)"
        return f"{path}:{line}" if line else str(path)


def read_end_effector_settings(node: Any, path: Path | None) -> dict[str, DeclaredTool]:
    """The ``end_effectors:`` mapping of a manifest or a cell's robot entry.

    Raises:
        YamlError: not a mapping of end effector names to settings (with file:line).
    """
    if node is None:
        return {}
    table = validate_node(_Table, {"end_effectors": node}, path)
    out = {}
    for name, settings in table.end_effectors.items():
        entry = node.get(name) if isinstance(node, dict) else None
        sources = {"": (path, line_of(node, name))}
        for key in settings.model_fields_set:
            sources[key] = (path, line_of(entry, key) if entry is not None else sources[""][1])
        out[name] = DeclaredTool(settings, sources)
    return out


def merge_declared(base: Mapping[str, DeclaredTool], over: Mapping[str, DeclaredTool]
                   ) -> dict[str, DeclaredTool]:
    """``base`` with ``over``'s given fields replacing its own (a cell over a manifest).

    Raises:
        YamlError: the merged settings disagree (a closing axis along the approach axis).
    """
    out = dict(base)
    for name, later in over.items():
        earlier = out.get(name)
        if earlier is None:
            out[name] = later
            continue
        given = later.settings.model_fields_set
        values = {k: getattr(earlier.settings, k) for k in earlier.settings.model_fields_set
                  if k not in given}
        values.update({k: getattr(later.settings, k) for k in given})
        sources = {k: v for k, v in earlier.sources.items() if k not in given}
        sources.update(later.sources)
        try:
            merged = EndEffectorSettings(**values)
        except ValidationError as exc:
            reason = exc.errors(include_url=False)[0].get("ctx", {}).get("error", exc)
            raise later.error("", f"end_effectors.{name}: {reason} (with the robot's own "
                                  f"declaration at {earlier.where()})") from None
        out[name] = DeclaredTool(merged, sources)
    return out


@dataclass(frozen=True)
class Tool:
    """The resolved tool of one arm.

    Attributes:
        arm: the arm group.
        end_effector: the SRDF end effector's name.
        gripper: its group (the finger joints), or None when the end effector's group is
            the arm itself.
        frame: the tool frame (a link, or a frame added to the model): its y axis closes,
            its z axis approaches.
        link: the link the tool frame is fixed to.
        offset: the tool frame in ``link``'s frame (m, rad).
        open_pose, closed_pose: the gripper group's pose names, None if it has none.
        origin: how the frame was found (for ``run-task info``).
    """

    arm: str
    end_effector: str
    gripper: str | None
    frame: str
    link: str
    offset: pin.SE3
    open_pose: str | None
    closed_pose: str | None
    origin: str
    pose_names: tuple[str, ...] = ()

    def gripper_pose(self, which: Literal["open", "closed"]) -> str:
        """The gripper's pose name for ``which``.

        Raises:
            RobotDescriptionError: no gripper, or no pose of that meaning.
        """
        if self.gripper is None:
            raise RobotDescriptionError(f"arm {self.arm!r} has no gripper group (end effector "
                                        f"{self.end_effector!r} is the arm itself)")
        name = self.open_pose if which == "open" else self.closed_pose
        if name is None:
            spellings = OPEN_SPELLINGS if which == "open" else CLOSED_SPELLINGS
            raise RobotDescriptionError(
                f"gripper group {self.gripper!r} of arm {self.arm!r} has no {which} pose "
                f"(looked for {' or '.join(repr(s) for s in spellings)}; its poses: "
                f"{', '.join(self.pose_names) or 'none'}): name it as 'end_effectors: "
                f"{{{self.end_effector}: {{{which}: POSE}}}}' in robot.yaml or on the robot "
                "in the cell")
        return name

    def describe(self) -> str:
        """One line for ``run-task info``."""
        xyz = ", ".join(f"{v:+.4f}" for v in self.offset.translation)
        rpy = ", ".join(f"{v:+.3f}" for v in pin.rpy.matrixToRpy(self.offset.rotation))
        place = (f"tool frame {self.frame}" if self.frame == self.link else
                 f"tool frame {self.frame} on {self.link} at xyz [{xyz}] rpy [{rpy}]")
        closes = _axis_name(self.offset.rotation[:, 1])
        approaches = _axis_name(self.offset.rotation[:, 2])
        poses = (f"; gripper {self.gripper}: open {self.open_pose or '-'}, closed "
                 f"{self.closed_pose or '-'}" if self.gripper else "")
        return (f"{self.arm} (end effector {self.end_effector}): {place}; closes along "
                f"{closes}, approaches along {approaches} of {self.link}{poses} ({self.origin})")


def _axis_name(vector: np.ndarray) -> str:
    i = int(np.argmax(np.abs(vector)))
    if abs(abs(float(vector[i])) - 1.0) < 1e-6:
        return ("-" if vector[i] < 0 else "+") + "xyz"[i]
    return "[" + ", ".join(f"{v:+.3f}" for v in vector) + "]"


def install_tools(model: RobotModel, declared: Mapping[str, DeclaredTool] | None = None
                  ) -> dict[str, Tool]:
    """Resolve every arm's tool (see the module docstring), adding the tool frames that
    are not links to ``model`` (existing ones are reused, so calling it again is safe).

    Args:
        declared: settings by end effector name (prefixed as in the model).

    Returns:
        The tool of each arm group, by group name.

    Raises:
        YamlError: a declaration names an end effector, link or pose that is not there.
    """
    declared = dict(declared or {})
    for name, entry in declared.items():
        if name not in model.end_effectors:
            raise entry.error("", f"end_effectors: {name!r} is not an end effector (end "
                                  f"effectors: {', '.join(model.end_effectors) or 'none'})")
    tools: dict[str, Tool] = {}
    for group in model.groups.values():
        if not group.end_effector or not group.tip_link:
            continue
        eef = model.end_effectors[group.end_effector]
        tools[group.name] = _resolve(model, group.name, eef.name, declared.get(eef.name))
    return tools


def _resolve(model: RobotModel, arm: str, eef_name: str, entry: DeclaredTool | None) -> Tool:
    eef = model.end_effectors[eef_name]
    gripper = eef.group if eef.group != arm and eef.group in model.groups else None
    prefix = next((i.prefix for i in model.instances if i.name == model.group(arm).robot), "")
    settings = entry.settings if entry is not None else EndEffectorSettings()
    given = settings.model_fields_set
    link, offset, origin = eef.parent_link, pin.SE3.Identity(), "the end effector's parent link"
    frame: str | None = None
    if given & {"link", "tcp_offset", "closing_axis", "approach_axis"}:
        assert entry is not None
        if settings.link is not None:
            link = prefix + settings.link  # the robot's own name, placed with its prefix
            if not model.has_link(link):
                raise entry.error("link", f"end_effectors.{eef_name}.link: {settings.link!r} "
                                          "is not a link of the robot")
        tcp = settings.tcp_offset.se3() if settings.tcp_offset else pin.SE3.Identity()
        closing = axis_vector(settings.closing_axis) if settings.closing_axis is not None \
            else np.array([0.0, 1.0, 0.0])
        approach = axis_vector(settings.approach_axis) if settings.approach_axis is not None \
            else np.array([0.0, 0.0, 1.0])
        offset = tcp * pin.SE3(_axes(closing, approach), np.zeros(3))
        origin = f"declared at {entry.where()}"
    elif model.has_link(prefix + "tool0"):
        link, origin = prefix + "tool0", f"the robot's {prefix}tool0 link"
    else:
        derived = _derive(model, eef.parent_link, gripper)
        if derived is not None:
            offset, origin = derived, "derived from the fingers' collision geometry"
    if _is_identity(offset):
        frame = link
    else:
        frame = _add_frame(model, f"{eef_name}_tcp", link, offset)
    aliases = model.pose_aliases.get(gripper or "", {})
    # The SRDF's own names (not the aliases the model adds for open/closed).
    names = [n for n in model.named_state_names(gripper) if n not in aliases] if gripper else []
    open_pose = _pose(settings.open, OPEN_SPELLINGS, names, gripper, eef_name, "open", entry)
    closed_pose = _pose(settings.closed, CLOSED_SPELLINGS, names, gripper, eef_name, "closed",
                        entry)
    return Tool(arm, eef_name, gripper, frame, link, offset, open_pose, closed_pose, origin,
                tuple(names))


def _pose(declared: str | None, spellings: tuple[str, ...], names: list[str],
          gripper: str | None, eef: str, key: str, entry: DeclaredTool | None) -> str | None:
    if declared is not None:
        assert entry is not None
        if gripper is None:
            raise entry.error(key, f"end_effectors.{eef}.{key}: end effector {eef!r} has no "
                                   "gripper group (its group is the arm)")
        if declared not in names:
            raise entry.error(key, f"end_effectors.{eef}.{key}: {declared!r} is not a named "
                                   f"pose of gripper group {gripper!r} (poses: "
                                   f"{', '.join(names) or 'none'})")
        return declared
    return next((s for s in spellings if s in names), None)


def _axes(closing: np.ndarray, approach: np.ndarray) -> np.ndarray:
    """The rotation whose y is ``closing`` and z is ``approach`` (closing made square to
    the approach)."""
    z = approach / np.linalg.norm(approach)
    y = closing - (closing @ z) * z
    y = y / np.linalg.norm(y)
    return np.column_stack([np.cross(y, z), y, z])


def _is_identity(offset: pin.SE3) -> bool:
    return bool(np.allclose(offset.rotation, np.eye(3), atol=1e-9)
                and np.allclose(offset.translation, 0.0, atol=1e-9))


def _add_frame(model: RobotModel, name: str, link: str, offset: pin.SE3) -> str:
    """Add frame ``name`` at ``offset`` in ``link`` (or reuse it if it is there already)."""
    pmodel = model.model
    parent_id = model.frame_id(link)
    parent = pmodel.frames[parent_id]
    placement = parent.placement * offset
    if pmodel.existFrame(name):
        there = pmodel.frames[pmodel.getFrameId(name)]
        if there.parentJoint == parent.parentJoint and there.placement.isApprox(placement, 1e-9):
            return name
        raise RobotDescriptionError(f"cannot add tool frame {name!r}: the robot has a link or "
                                    "frame of that name elsewhere")
    pmodel.addFrame(pin.Frame(name, parent.parentJoint, parent_id, placement, pin.OP_FRAME))
    model.data = pmodel.createData()
    return name


def _finger_boxes(model: RobotModel, link: str, gripper: str) -> list[np.ndarray]:
    """Per finger (each gripper joint's moving links, mimic followers included), the
    corners of its collision geometry's bounding boxes in ``link``'s frame, at the
    gripper's open pose (else the default state)."""
    pmodel = model.model
    sources = set(model.group(gripper).joint_names)
    joints = [j for j in model.joints
              if j.name in sources or (j.mimic is not None and j.mimic.source in sources)]
    q = model.default_state()
    names = model.named_state_names(gripper)
    pose = next((s for s in OPEN_SPELLINGS if s in names), None)
    if pose is not None:
        q = model.state_with(q, model.named_state(gripper, pose))
    data = pmodel.createData()
    pin.forwardKinematics(pmodel, data, model.to_pin(q))
    pin.updateFramePlacements(pmodel, data)
    to_link = data.oMf[model.frame_id(link)].inverse()
    out = []
    for joint in joints:
        subtree = set(pmodel.subtrees[pmodel.getJointId(joint.name)])
        corners = []
        for geom in model.collision_model.geometryObjects:
            if geom.parentJoint not in subtree:
                continue
            shape = geom.geometry
            shape.computeLocalAABB()
            lo, hi = np.array(shape.aabb_local.min_), np.array(shape.aabb_local.max_)
            placed = to_link * data.oMi[geom.parentJoint] * geom.placement
            for corner in np.array(np.meshgrid(*zip(lo, hi))).T.reshape(-1, 3):
                corners.append(placed.act(corner))
        if corners:
            out.append(np.array(corners))
    return out


def _derive(model: RobotModel, link: str, gripper: str | None) -> pin.SE3 | None:
    """The TCP from the fingers' geometry, when ``link`` is behind the fingers (see the
    module docstring); None when it is between them or no two fingers have geometry."""
    if gripper is None:
        return None
    fingers = _finger_boxes(model, link, gripper)
    if len(fingers) < 2:
        return None
    centres = [(f.min(axis=0) + f.max(axis=0)) / 2 for f in fingers]
    a, b = max(((i, j) for i in range(len(centres)) for j in range(i + 1, len(centres))),
               key=lambda p: float(np.linalg.norm(centres[p[0]] - centres[p[1]])))
    across = centres[b] - centres[a]
    if np.linalg.norm(across) < 1e-6:
        return None
    closing = _snapped(across / np.linalg.norm(across))
    closing *= math.copysign(1.0, float(closing[int(np.argmax(np.abs(closing)))]))
    corners = np.vstack(fingers)
    centre = (corners.min(axis=0) + corners.max(axis=0)) / 2
    out = centre - (centre @ closing) * closing
    if np.linalg.norm(out) < 1e-6:
        return None
    approach = _snapped(out / np.linalg.norm(out))
    along = corners @ approach
    if float(along.min()) < _BEHIND:
        return None  # the link reaches between the fingers: it is the TCP already
    back = PAD_FRACTION * float(along.max() - along.min())
    tcp = centre + (float(along.max()) - back - float(centre @ approach)) * approach
    return pin.SE3(_axes(closing, approach), tcp)


def _snapped(vector: np.ndarray) -> np.ndarray:
    """``vector``, or the link axis it is within 5° of."""
    i = int(np.argmax(np.abs(vector)))
    if math.acos(min(1.0, abs(float(vector[i])))) < _SNAP:
        out = np.zeros(3)
        out[i] = math.copysign(1.0, float(vector[i]))
        return out
    return vector
