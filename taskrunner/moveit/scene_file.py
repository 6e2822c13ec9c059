"""``moveit_msgs/PlanningScene`` files: read, check, and apply to a :class:`Scene`.

Read (ROS 1 and ROS 2 dumps; the message's fields at the top level or under one key
``planning_scene`` / ``scene``):

- ``world.collision_objects``: ``id``, ``header.frame_id``, ``primitives`` +
  ``primitive_poses``, ``meshes`` + ``mesh_poses``, the object ``pose`` (ROS 2, Noetic; the part
  poses are then relative to it), ``operation`` ADD (0) / REMOVE (1) / APPEND (2) /
  MOVE (3). An object of several shapes becomes scene objects ``id``, ``id/1``, ``id/2``
  …; REMOVE, MOVE and ACM entries naming ``id`` apply to all of them.
- ``robot_state``: ``joint_state`` (``name``, ``position``; joints the model has fixed are
  ignored, names it lacks are one warning, mimic joints follow their source: see
  :func:`taskrunner.moveit.messages.read_robot_state`), ``multi_dof_joint_state``
  (identity transforms only: a cell's robots have fixed bases), ``attached_collision_objects``
  (``link_name``, ``object``, ``touch_links``).
- ``allowed_collision_matrix``: ``entry_names`` × ``entry_values[].enabled``, and
  ``default_entry_names`` / ``default_entry_values`` (a body allowed to touch everything).
- ``fixed_frame_transforms``: extra named frames (or a check of frames the model has).
- ``is_diff``: false (a full scene) replaces the scene's objects and allowances, as MoveIt
  does; ``merge=True`` keeps them. ``name``, ``robot_model_name`` (a warning when it is
  not the model's).

Frames: ``header.frame_id`` is ``world`` (or empty: the world of the cell), a link of the
robot (names mapped as :mod:`taskrunner.moveit.names` says), a frame of
``fixed_frame_transforms``, or an object already in the scene; anything else is an error
naming the object and the field. Colors, ``type`` (database key), velocities and efforts
do not affect planning and are read but not used. Unsupported values that do (planes,
subframes, octomaps with data, link padding and scale other than 0 and 1) are warnings.
"""

from __future__ import annotations

import logging
import os
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np
import pinocchio as pin

from taskrunner.errors import InputError, SceneError, UnknownNameError
from taskrunner.moveit.fields import MessageReader, Msg, as_bool
from taskrunner.moveit.messages import (
    OBJECT_FIELDS,
    ROBOT_STATE_FIELDS,
    ObjectEdit,
    read_collision_object,
    read_robot_state,
    unwrap,
)
from taskrunner.moveit.names import AmbiguousName, NameMap
from taskrunner.robot.model import RobotModel
from taskrunner.robot.notes import LoadWarning
from taskrunner.scene import Scene
from taskrunner.types import Pose
from taskrunner.yamlfile import LineList, YamlLimits, line_of, load_yaml

__all__ = ["PlanningSceneFile", "apply_object", "apply_scene_file", "load_planning_scene",
           "object_parts"]

_log = logging.getLogger("taskrunner.moveit")

SCENE_FIELDS = ("name", "robot_state", "robot_model_name", "fixed_frame_transforms",
                "allowed_collision_matrix", "link_padding", "link_scale", "object_colors",
                "world", "is_diff")
_FRAME_MISMATCH = 1e-3  # m / rad: a fixed frame the model has, placed differently


@dataclass(frozen=True)
class _Entry:
    a: str
    b: str
    enabled: bool
    line: int | None


@dataclass(frozen=True)
class _FixedFrame:
    parent: str
    pose: Pose  # in parent
    where: str
    line: int | None


@dataclass
class PlanningSceneFile:
    """A PlanningScene file, read and checked against a model; :meth:`apply` it to a
    scene of that model. See the module docstring for what is read.

    Attributes:
        objects: world objects, then attached ones, in file order.
        state: joint values of ``robot_state`` (model names).
        warnings: what was not used, by file:line.
    """

    path: Path | None
    name: str
    robot_model_name: str
    is_diff: bool
    state: dict[str, float]
    objects: tuple[ObjectEdit, ...]
    allowed: tuple[_Entry, ...]
    default_allowed: tuple[_Entry, ...]
    frames: dict[str, _FixedFrame]
    warnings: list[LoadWarning]
    names: NameMap = field(repr=False)
    reader: MessageReader = field(repr=False)

    @property
    def object_ids(self) -> tuple[str, ...]:
        return tuple(dict.fromkeys(o.id for o in self.objects))

    @property
    def object_names(self) -> tuple[str, ...]:
        """The scene objects the file makes when applied to a scene that has none of its
        ids: ``id`` for an object's first shape, ``id/1``, ``id/2`` … for the others."""
        parts: dict[str, int] = {}
        for edit in self.objects:
            if edit.operation == "REMOVE":
                parts.pop(edit.id, None)
            elif edit.operation in ("ADD", "APPEND"):
                start = parts.get(edit.id, 0) if edit.operation == "APPEND" else 0
                parts[edit.id] = start + len(edit.parts)
        return tuple(name if i == 0 else f"{name}/{i}" for name, n in parts.items()
                     for i in range(n))

    def apply(self, scene: Scene, *, merge: bool | None = None) -> list[str]:
        """Apply the file to ``scene`` (a scene of the model it was read for).

        Args:
            merge: keep the scene's objects and allowances; None: keep them for a diff
                (``is_diff: true``), replace them for a full scene (MoveIt's behaviour).

        Returns:
            the names of the scene objects the file added or changed.

        Raises:
            InputError: an unknown frame, an object id used wrongly (file:line, field).
        """
        keep = self.is_diff if merge is None else merge
        if not keep:
            for name in scene.object_names:
                scene.remove_object(name)
            for pair, reason in scene.allowed_collisions().items():
                if reason == "scene":
                    a, b = sorted(pair)
                    scene.disallow_collision(a, b)
        if self.state:
            scene.set_state(self.state)
        touched: list[str] = []
        for edit in self.objects:
            touched += apply_object(scene, edit, self)
        self._apply_frames_check(scene)
        self._apply_allowed(scene)
        return list(dict.fromkeys(touched))

    # ------------------------------------------------------------------ frames
    def pose_in_scene(self, scene: Scene, pose: Pose, where: str, line: int | None,
                      owner: str) -> Pose:
        """``pose`` (its frame as written in the file) as a pose the scene understands."""
        frame = pose.frame.lstrip("/")
        if frame in ("", "world"):
            return Pose(pose.xyz, pose.quat, "world")
        if frame in self.frames:
            fixed = self.frames[frame]
            parent = self.pose_in_scene(scene, fixed.pose, fixed.where, fixed.line, frame)
            return Pose.from_se3(scene.to_world(parent) * pose.se3)
        try:
            link = self.names.link(frame)
        except AmbiguousName as exc:
            raise InputError(f"'{where}.header.frame_id' of {owner!r}: {exc}", self.path, line) from None
        if link is not None:
            return Pose(pose.xyz, pose.quat, link)
        if frame in scene:
            return Pose(pose.xyz, pose.quat, frame)
        known = ["world", *self.frames, *scene.object_names]
        raise InputError(f"'{where}.header.frame_id' of {owner!r} names an unknown frame "
                         f"{frame!r} (known: {', '.join(repr(k) for k in known)}, or a link "
                         "of the robot)", self.path, line)

    def _apply_frames_check(self, scene: Scene) -> None:
        for child, fixed in self.frames.items():
            try:
                link = self.names.link(child)
            except AmbiguousName:
                continue
            if link is None and child != "world":
                continue
            written = scene.to_world(self.pose_in_scene(scene, fixed.pose, fixed.where, fixed.line,
                                                        child))
            actual = scene.to_world(Pose(frame=link or "world"))
            error = float(np.linalg.norm(pin.log6(written.actInv(actual)).vector))
            if error > _FRAME_MISMATCH:
                self.reader.warn(f"'{fixed.where}' places frame {child!r} {error:.4f} (m, rad) away "
                                 "from where the model has it; the model's placement is used",
                                 fixed.line)

    # ------------------------------------------------------------------ allowed collisions
    def _bodies(self, scene: Scene, name: str, line: int | None, warned: set[str]) -> list[str]:
        try:
            link = self.names.link(name)
        except AmbiguousName as exc:
            raise InputError(f"'allowed_collision_matrix': {exc}", self.path, line) from None
        parts = object_parts(scene, name)
        if link is not None and link in scene.robot.link_names and link != "world":
            # One string namespace, as MoveIt's ACM: a name that is a link and an object
            # (a geometry-free frame, see Scene.add_object) is an entry for both.
            return list(dict.fromkeys([link, *parts]))
        if not parts and name not in warned:
            warned.add(name)
            self.reader.warn(f"'allowed_collision_matrix' names {name!r}, neither a link of "
                             "the robot nor an object of the scene; ignored", line)
        return parts

    def _apply_allowed(self, scene: Scene) -> None:
        kept: list[str] = []
        warned: set[str] = set()
        everything = [n for n in scene.robot.link_names if n != "world"] + list(scene.object_names)
        entries = list(self.allowed)
        for entry in self.default_allowed:
            if entry.enabled:
                entries += [_Entry(entry.a, other, True, entry.line) for other in everything]
        for entry in entries:
            for a in self._bodies(scene, entry.a, entry.line, warned):
                for b in self._bodies(scene, entry.b, entry.line, warned):
                    if a == b:
                        continue
                    if entry.enabled:
                        scene.allow_collision(a, b)
                        continue
                    try:
                        scene.disallow_collision(a, b)
                    except SceneError:
                        kept.append(f"{a}–{b}")
        if kept:
            shown = ", ".join(kept[:6]) + (f" … ({len(kept)} in all)" if len(kept) > 6 else "")
            line = self.allowed[0].line if self.allowed else None
            self.reader.warn(f"'allowed_collision_matrix' checks pairs the robot's SRDF (or an "
                             f"attachment) allows: {shown}; they stay allowed", line)


def apply_scene_file(scene: Scene, path: str | os.PathLike[str], *, robot: str | None = None,
                     strict: bool | None = None) -> PlanningSceneFile:
    """Add a PlanningScene file's objects and allowances to ``scene``, keeping its own
    (what a task's ``scene:`` does); warnings are logged (``taskrunner.moveit``).

    Raises:
        InputError: an invalid file (file:line, field).
    """
    loaded = load_planning_scene(path, scene.robot, robot=robot, strict=strict)
    loaded.apply(scene, merge=True)
    for warning in loaded.warnings:
        _log.warning("%s", warning)
    return loaded


def object_parts(scene: Scene, object_id: str) -> list[str]:
    """The scene objects of a file's object ``id``: ``id`` and ``id/1``, ``id/2`` …"""
    return [n for n in scene.object_names if n == object_id or n.startswith(object_id + "/")]


def apply_object(scene: Scene, edit: ObjectEdit, source: PlanningSceneFile) -> list[str]:
    """Apply one object edit; returns the scene objects it made or moved."""
    existing = object_parts(scene, edit.id)
    where = f"{edit.where}.id" if edit.where else "id"

    def fail(message: str) -> InputError:
        return InputError(f"'{where}' {message}", source.path, edit.line)

    try:
        if edit.operation == "REMOVE":
            if not existing:
                source.reader.warn(f"'{where}': REMOVE of object {edit.id!r}, which the scene "
                                   "does not have; nothing removed", edit.line)
            for name in existing:
                if edit.attach_to is not None and scene.object(name).attached:
                    scene.detach_object(name)
                else:
                    scene.remove_object(name)
            return []
        poses = [source.pose_in_scene(scene, pose, edit.where, edit.frame_line, edit.id)
                 for _, pose in edit.parts]
        if edit.operation == "MOVE":
            if len(existing) != len(edit.parts):
                raise fail(f"MOVE of object {edit.id!r} gives {len(edit.parts)} part poses; the "
                           f"object has {len(existing)} part(s)")
            for name, pose in zip(existing, poses):
                scene.move_object(name, pose)
            return existing
        if edit.operation == "ADD":
            for name in existing:
                scene.remove_object(name)
            existing = []
        made = []
        index = len(existing)
        for (shape, _), pose in zip(edit.parts, poses):
            name = edit.id if index == 0 else f"{edit.id}/{index}"
            index += 1
            scene.add_object(name, shape, pose, attach_to=edit.attach_to,
                             touch_links=edit.touch_links)
            made.append(name)
        return made
    except (SceneError, UnknownNameError) as exc:
        raise fail(f"object {edit.id!r}: {exc}") from None


def _read_frames(msg: Msg) -> dict[str, _FixedFrame]:
    frames = {}
    for item in msg.msgs("fixed_frame_transforms", ("header", "child_frame_id", "transform")):
        child = item.string("child_frame_id").lstrip("/")
        if not child:
            raise item.error("child_frame_id", "must name the frame the transform places")
        transform = item.msg("transform", ("translation", "rotation"), required=True)
        assert transform is not None
        pose = Pose(transform.vector3("translation"), transform.quaternion("rotation"),
                    item.frame_id())
        if child == pose.frame.lstrip("/") or (child == "world" and pose.frame in ("", "world")):
            continue  # a frame placed in itself (MoveIt dumps world → world)
        frames[child] = _FixedFrame(pose.frame, pose, item.where, item.line)
    return frames


def _read_acm(msg: Msg | None) -> tuple[tuple[_Entry, ...], tuple[_Entry, ...]]:
    if msg is None:
        return (), ()
    names = msg.strings("entry_names")
    rows: list[tuple[list[Any], int | None]] = []  # {enabled: [...]} (ROS), or a bare list (robowflex)
    listed = msg.seq("entry_values")
    for index, item in enumerate(listed):
        line = line_of(listed, index) or msg.line_of("entry_values")
        if isinstance(item, LineList):
            rows.append((list(item), line))
        else:
            entry = msg.reader.msg(item, f"{msg.field('entry_values')}[{index}]", ("enabled",), line)
            rows.append((list(entry.seq("enabled")), line))
    if len(rows) != len(names):
        raise msg.error("entry_values", f"must have one row per entry name ({len(names)}) "
                                        f"(got {len(rows)})")
    entries = []
    for i, (row, line) in enumerate(rows):
        if len(row) != len(names):
            raise msg.reader.error(f"'{msg.field('entry_values')}[{i}]' must have one value per "
                                   f"entry name ({len(names)}) (got {len(row)})", line)
        for j in range(i + 1, len(names)):
            value = as_bool(row[j])
            if value is None:
                raise msg.reader.error(f"'{msg.field('entry_values')}[{i}]' must hold true or "
                                       f"false values (got {row[j]!r})", line)
            entries.append(_Entry(names[i], names[j], value, line))
    defaults = msg.strings("default_entry_names")
    values = msg.seq("default_entry_values")
    if len(values) != len(defaults):
        raise msg.error("default_entry_values", f"must have one value per default entry name "
                                                f"({len(defaults)}) (got {len(values)})")
    default_entries = []
    for name, raw in zip(defaults, values):
        value = as_bool(raw)
        if value is None:
            raise msg.error("default_entry_values", f"must hold true or false values (got {raw!r})")
        default_entries.append(_Entry(name, "", value, msg.line_of("default_entry_values")))
    return tuple(entries), tuple(default_entries)


def _check_unused(msg: Msg) -> None:
    for item in msg.msgs("link_padding", ("link_name", "padding")):
        if item.number("padding") != 0.0:
            item.warn("padding", "is not supported (links are not padded); ignored")
    for item in msg.msgs("link_scale", ("link_name", "scale")):
        if item.number("scale", 1.0) != 1.0:
            item.warn("scale", "is not supported (links are not scaled); ignored")
    msg.msgs("object_colors", ("id", "color"))
    world = msg.msg("world", ("collision_objects", "octomap"))
    if world is not None:
        octomap = world.msg("octomap", ("header", "origin", "octomap"))
        inner = octomap.msg("octomap", ("header", "binary", "id", "resolution", "data")) \
            if octomap is not None else None
        if inner is not None and inner.seq("data"):
            inner.warn("data", "(an octomap) is not supported; ignored")


def load_planning_scene(path: str | os.PathLike[str], model: RobotModel, *, robot: str | None = None,
                        strict: bool | None = None,
                        limits: YamlLimits | None = None,
                        package_path: Sequence[Path] = ()) -> PlanningSceneFile:
    """Read a ``moveit_msgs/PlanningScene`` YAML file for ``model``.

    Args:
        path: the file.
        model: the robot or cell model the scene is for.
        robot: the cell's robot instance the file describes (names get its prefix;
            see :mod:`taskrunner.moveit.names`).
        strict: warnings are errors (None: no).
        limits: YAML size and depth bounds.
        package_path: folders searched first for the packages of a mesh ``resource``
            (``LoadOptions.package_path``).

    Raises:
        YamlError: the file does not parse.
        InputError: a field of the wrong type or value, an unknown joint or link
            (file:line and field); in strict mode, the first warning.
    """
    reader = MessageReader(Path(path), strict, package_path)
    names = NameMap(model, robot)
    document = load_yaml(Path(path), limits)
    msg = unwrap(document, ("planning_scene", "scene", "moveit_msgs/PlanningScene",
                            "moveit_msgs/msg/PlanningScene"), reader, SCENE_FIELDS, "PlanningScene")
    model_name = msg.string("robot_model_name")
    if model_name and model_name not in (model.name, *(i.name for i in model.instances)):
        msg.warn("robot_model_name", f"is {model_name!r}; the scene is applied to robot model "
                                     f"{model.name!r}")
    state = read_robot_state(msg.msg("robot_state", ROBOT_STATE_FIELDS), names)
    objects: list[ObjectEdit] = []
    world = msg.msg("world", ("collision_objects", "octomap"))
    if world is not None:
        objects += [read_collision_object(o, names) for o in world.msgs("collision_objects",
                                                                           OBJECT_FIELDS)]
    objects += state.attached
    _check_unused(msg)
    allowed, defaults = _read_acm(msg.msg("allowed_collision_matrix",
                                          ("entry_names", "entry_values", "default_entry_names",
                                           "default_entry_values")))
    return PlanningSceneFile(Path(path), msg.string("name"), model_name, msg.boolean("is_diff"),
                             state.values, tuple(objects), allowed, defaults, _read_frames(msg),
                             reader.warnings, names, reader)

