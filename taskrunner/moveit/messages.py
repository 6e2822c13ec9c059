"""Messages shared by PlanningScene and MotionPlanRequest files: the file's top level,
``moveit_msgs/CollisionObject``, ``AttachedCollisionObject`` and ``RobotState``.

See :mod:`taskrunner.moveit.scene_file` for what each field becomes.
"""

from __future__ import annotations

import logging
from collections.abc import Callable, Iterable
from dataclasses import dataclass

import numpy as np

from taskrunner.moveit.fields import MessageReader, Msg
from taskrunner.moveit.geometry import read_mesh, read_primitive, ros2_byte
from taskrunner.moveit.names import AmbiguousName, NameMap
from taskrunner.shapes import Shape
from taskrunner.types import Pose
from taskrunner.yamlfile import LineDict

__all__ = ["JOINT_STATE_FIELDS", "OBJECT_FIELDS", "OPERATIONS", "ROBOT_STATE_FIELDS", "ObjectEdit",
           "RobotStateData", "mapped_name", "read_collision_object", "read_robot_state",
           "try_name", "unwrap"]

OPERATIONS = {0: "ADD", 1: "REMOVE", 2: "APPEND", 3: "MOVE"}
OBJECT_FIELDS = ("header", "pose", "id", "type", "primitives", "primitive_poses", "meshes",
                 "mesh_poses", "planes", "plane_poses", "subframe_names", "subframe_poses",
                 "operation")
ROBOT_STATE_FIELDS = ("joint_state", "multi_dof_joint_state", "attached_collision_objects",
                      "is_diff")
JOINT_STATE_FIELDS = ("header", "name", "position", "velocity", "effort")
POSE_FIELDS = ("position", "orientation")
_MIMIC_TOLERANCE = 1e-6  # rad or m: a mimic joint's value that agrees with its source

_log = logging.getLogger("taskrunner.moveit")


@dataclass(frozen=True)
class ObjectEdit:
    """One collision object of the file, ready to apply.

    Attributes:
        id: the object's id.
        operation: ``ADD``, ``REMOVE``, ``APPEND`` or ``MOVE``.
        frame: ``header.frame_id`` as written ("" is the world).
        parts: each shape and its pose in ``frame`` (the object's own pose included: ROS 2, Noetic).
        attach_to: the link carrying it (an attached object), mapped to the model.
        touch_links: links it may touch besides ``attach_to``, mapped.
        where: the field path in the file, for messages; ``line`` its line.
    """

    id: str
    operation: str
    frame: str
    parts: tuple[tuple[Shape, Pose], ...]
    attach_to: str | None = None
    touch_links: tuple[str, ...] = ()
    where: str = ""
    line: int | None = None
    frame_line: int | None = None


@dataclass(frozen=True)
class RobotStateData:
    """A ``moveit_msgs/RobotState``: joint values (model names) and attached objects."""

    values: dict[str, float]
    attached: tuple[ObjectEdit, ...] = ()
    is_diff: bool = False


def unwrap(document: object, wrappers: Iterable[str], reader: MessageReader, known: Iterable[str],
           what: str) -> Msg:
    """The message of a file: its top level, or the one key wrapping it."""
    known = tuple(known)
    if isinstance(document, LineDict) and len(document) == 1:
        key = next(iter(document))
        if key in wrappers:
            return reader.msg(document[key], "", known, document.line_of(key))
    if not isinstance(document, LineDict):
        raise reader.error(f"a {what} file must be a mapping of the message's fields "
                           f"(got {type(document).__name__})", getattr(document, "line", None))
    return reader.msg(document, "", known)


def _operation(msg: Msg) -> str:
    raw = msg.raw("operation", 0)
    if isinstance(raw, str):
        if raw.upper() in OPERATIONS.values():
            return raw.upper()
        raw = ros2_byte(raw)
    if isinstance(raw, int) and not isinstance(raw, bool) and raw in OPERATIONS:
        return OPERATIONS[raw]
    raise msg.error("operation", f"must be 0 (ADD), 1 (REMOVE), 2 (APPEND) or 3 (MOVE) "
                                 f"(got {msg.raw('operation')!r})")


def _compose(outer: Pose | None, inner: Pose) -> Pose:
    if outer is None:
        return inner
    return Pose.from_se3(outer.se3 * inner.se3, inner.frame)


def read_collision_object(msg: Msg, names: NameMap, attach_to: str | None = None,
                          touch_links: tuple[str, ...] = ()) -> ObjectEdit:
    """A ``moveit_msgs/CollisionObject`` (see the module docstring)."""
    object_id = msg.string("id")
    if not object_id:
        raise msg.error("id", "must be a non-empty object name")
    frame = msg.frame_id()
    operation = _operation(msg)
    object_pose = msg.pose("pose", frame)  # ROS 2 only
    parts: list[tuple[Shape, Pose]] = []
    for shapes_key, poses_key, reader in (("primitives", "primitive_poses", read_primitive),
                                          ("meshes", "mesh_poses", read_mesh)):
        known = ("type", "dimensions", "polygon") if shapes_key == "primitives" else (
            "triangles", "vertices", "resource", "dimensions")
        shapes = msg.msgs(shapes_key, known)
        poses = msg.msgs(poses_key, POSE_FIELDS)
        if len(poses) != len(shapes) and not (operation in ("REMOVE", "MOVE") and not shapes):
            raise msg.error(poses_key, f"must have one pose per entry of {shapes_key!r} "
                                       f"({len(shapes)}) (got {len(poses)})")
        if operation == "REMOVE":
            continue
        for shape_msg, pose_msg in zip(shapes, poses):
            parts.append((reader(shape_msg), _compose(object_pose, pose_msg.as_pose(frame))))
        if operation == "MOVE" and poses and not shapes:
            raise msg.error(shapes_key, f"must list the shapes whose {poses_key!r} are given "
                                        "(MOVE with part poses)")
    if operation == "MOVE" and not parts:
        if object_pose is None:
            raise msg.error(None, f"MOVE of object {object_id!r} must give 'pose' (ROS 2) or "
                                  "the shapes with their poses (ROS 1)")
        raise msg.error("pose", f"MOVE of object {object_id!r} by its pose alone is not "
                                "supported: give the shapes with their poses")
    if operation in ("ADD", "APPEND") and not parts:
        raise msg.error(None, f"{operation} of object {object_id!r} must give primitives or meshes")
    for key in ("planes", "subframe_names"):
        if msg.seq(key):
            msg.warn(key, "is not supported; ignored")
    header = msg.raw("header")
    frame_line = header.line_of("frame_id") if isinstance(header, LineDict) else msg.line
    return ObjectEdit(object_id, operation, frame, tuple(parts), attach_to, touch_links,
                      msg.where, msg.line, frame_line)


def read_robot_state(msg: Msg | None, names: NameMap) -> RobotStateData:
    """A ``moveit_msgs/RobotState`` (joint names mapped to the model; the joint state as
    :func:`_joint_values` reads it: fixed joints ignored, unknown names one warning, an
    error in strict mode)."""
    if msg is None:
        return RobotStateData({})
    values: dict[str, float] = {}
    joint_state = msg.msg("joint_state", JOINT_STATE_FIELDS)
    if joint_state is not None:
        values = _joint_values(joint_state, names)
    multi = msg.msg("multi_dof_joint_state", ("header", "joint_names", "transforms", "twist",
                                              "wrench"))
    if multi is not None:
        for index, transform in enumerate(multi.msgs("transforms", ("translation", "rotation"))):
            pose = Pose(transform.vector3("translation"), transform.quaternion("rotation"))
            if not np.allclose(pose.se3.homogeneous, np.eye(4), atol=1e-6):
                joints = multi.strings("joint_names")
                name = joints[index] if index < len(joints) else f"#{index}"
                transform.warn(None, f"moves multi-DOF joint {name!r}: not supported (the robots "
                                     "of a cell have fixed bases); ignored")
    attached = []
    for item in msg.msgs("attached_collision_objects",
                         ("link_name", "object", "touch_links", "detach_posture", "weight")):
        link_name = item.string("link_name")
        link = mapped_name(item, "link_name", names.link, link_name, "link", list(names.model.link_names))
        touch: list[str] = []
        for touch_name in item.strings("touch_links"):
            touch_link: str | None = try_name(item, "touch_links", names.link, touch_name)
            if touch_link is None:
                item.warn("touch_links", f"names {touch_name!r}, not a link of the model; ignored")
            elif touch_link != link:
                touch.append(touch_link)
        obj = item.msg("object", OBJECT_FIELDS, required=True)
        assert obj is not None
        attached.append(read_collision_object(obj, names, link, tuple(touch)))
    return RobotStateData(values, tuple(attached), msg.boolean("is_diff"))


def _joint_values(joint_state: Msg, names: NameMap) -> dict[str, float]:
    """The values of a ``sensor_msgs/JointState`` for the joints the model moves.

    A joint of the description that is fixed in the model has no value: ignored (debug
    log). A name the model does not have at all (a mobile base's wheels in a file written
    for the whole robot): one warning naming them all (strict mode: an error). A mimic
    joint's value is ignored (it follows its source joint), with a warning when it does
    not agree with the source's value in the same message.
    """
    joint_names = joint_state.strings("name")
    positions = joint_state.numbers("position")
    if len(joint_names) != len(positions):
        raise joint_state.error("position", f"must have one value per name ({len(joint_names)}) "
                                            f"(got {len(positions)})")
    values: dict[str, float] = {}
    mimics: dict[str, float] = {}
    fixed: list[str] = []
    unknown: list[str] = []
    for name, value in zip(joint_names, positions):
        mapped = try_name(joint_state, "name", names.joint, name)
        if mapped is not None:
            if names.model.joint(mapped).mimic is not None:
                mimics[mapped] = value
            else:
                values[mapped] = value
        elif try_name(joint_state, "name", names.fixed_joint, name) is not None:
            fixed.append(name)
        else:
            unknown.append(name)
    if fixed:
        _log.debug("%s: %r names joints fixed in the model (no value): %s; ignored",
                   joint_state.reader.path, joint_state.field("name"), ", ".join(fixed))
    if unknown:
        joint_state.warn("name", f"names joint(s) the model does not have: "
                                 f"{', '.join(repr(n) for n in unknown)}; their values are ignored")
    disagree = []
    for joint, value in mimics.items():
        mimic = names.model.joint(joint).mimic
        assert mimic is not None
        if mimic.source not in values:
            disagree.append(f"{joint!r} = {value:.6g} (its source {mimic.source!r} is not given)")
            continue
        follows = mimic.multiplier * values[mimic.source] + mimic.offset
        if abs(value - follows) > _MIMIC_TOLERANCE:
            disagree.append(f"{joint!r} = {value:.6g}, not {follows:.6g} ({mimic.multiplier:g} × "
                            f"{mimic.source!r} + {mimic.offset:g})")
    if disagree:
        joint_state.warn("position", f"gives mimic joint(s) values that do not follow their "
                                     f"source: {'; '.join(disagree)}; the mimic joints follow "
                                     "their source")
    return values


def try_name(msg: Msg, key: str, lookup: Callable[[str], str | None], name: str) -> str | None:
    """``lookup(name)``; an ambiguous name is an error at ``key``."""
    try:
        return lookup(name)
    except AmbiguousName as exc:
        raise msg.error(key, str(exc)) from None


def mapped_name(msg: Msg, key: str, lookup: Callable[[str], str | None], name: str, kind: str,
                known: list[str]) -> str:
    """``lookup(name)``; an unknown name is an error at ``key`` listing ``known``."""
    mapped = try_name(msg, key, lookup, name)
    if mapped is None:
        raise msg.error(key, f"names an unknown {kind} {name!r}; known: "
                             + ", ".join(repr(k) for k in sorted(known)[:20])
                             + (" …" if len(known) > 20 else ""))
    return mapped
