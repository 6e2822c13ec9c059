"""Cells: one or more robots placed in a world frame, plus fixed objects.

A cell file (YAML) looks like::

    name: servo_arm_table
    robots:
      - name: arm                  # instance name
        robot: ../servo_arm        # manifest / folder / URDF, relative to this file
        prefix: ""                 # put before every link, joint and group name
        collision: auto            # link geometry: exact, convex or auto (hulls where tight)
        base: {xyz: [0, 0, 0.75], rpy: [0, 0, 0]}
        poses:                     # more named poses, robot's own names
          arm:
            PickUp: {"Revolute 1": 1.57, "Revolute 2": -0.6}
        end_effectors:             # tool frames, over robot.yaml's (taskrunner.robot.tools)
          gripper_eef: {tcp_offset: {xyz: [0, 0, 0.05]}, closing_axis: y, closed: close}
    groups:                        # groups spanning robots
      both_arms: [left_arm, right_arm]
    start: {arm: home}             # named pose per group at the start
    objects:
      - name: table
        shape: box
        size: [0.8, 0.6, 0.75]
        pose: {xyz: [0.2, 0, 0.375]}
        touch_links: [base_link]   # links allowed to touch it (the robot stands on it)

The result is a :class:`Cell`: one :class:`~taskrunner.robot.model.RobotModel` with a
group per robot group (prefixed), the spanning groups, and the fixed objects.
"""

from __future__ import annotations

import copy
import logging
from dataclasses import dataclass, field
from pathlib import Path
from typing import Literal

import numpy as np
import pinocchio as pin
from pydantic import BaseModel, ConfigDict, Field

from taskrunner.errors import RobotDescriptionError, UnknownNameError, YamlError
from taskrunner.folders import FileKind, FolderPolicy, PathNotAllowedError
from taskrunner.kinds import CollisionChoice
from taskrunner.materials import Material, material_of
from taskrunner.objectspec import ObjectFields
from taskrunner.posespec import PoseFields
from taskrunner.robot.build import WORLD, Placement, build_model
from taskrunner.robot.description import RobotDescription, load_description
from taskrunner.robot.model import RobotModel
from taskrunner.robot.notes import raise_if_strict
from taskrunner.robot.options import LoadOptions
from taskrunner.robot.packages import PackageMap
from taskrunner.robot.selfcollision import self_collision_warnings
from taskrunner.robot.tools import (
    DeclaredTool,
    EndEffectorSettings,
    Tool,
    install_tools,
    merge_declared,
    read_end_effector_settings,
)
from taskrunner.shapes import Box, Cylinder, Mesh, Shape, Sphere
from taskrunner.taught import TaughtPoses, apply_taught
from taskrunner.textfile import file_problem, path_problem, resolve_path
from taskrunner.validation import (
    Number,
    validate_node,
)
from taskrunner.yamlfile import LineDict, line_of, load_yaml

__all__ = ["Cell", "CellObject", "load_cell", "load_cell_or_robot"]

log = logging.getLogger(__name__)



class _Strict(BaseModel):
    # Every number of a cell file is finite (joint values of named poses too).
    model_config = ConfigDict(extra="forbid", frozen=True, allow_inf_nan=False)


class PoseSpec(_Strict, PoseFields):
    """A placement in a cell file: ``xyz`` and ``rpy`` or ``quat``, in ``frame`` (the one
    pose model, :class:`taskrunner.posespec.PoseFields`, as task files write it)."""


GraspMode = Literal["friction", "weld"]


class RobotSpec(_Strict):
    name: str = Field(min_length=1)
    robot: str = Field(min_length=1)
    prefix: str = ""
    base: PoseSpec = PoseSpec()
    poses: dict[str, dict[str, dict[str, Number]]] = {}
    collision: CollisionChoice | None = None
    # How the mujoco backend holds a grasped object: one mode for the robot's arms, or
    # per arm group / end effector (the robot's own names).
    grasp_mode: GraspMode | dict[str, GraspMode] | None = None
    # Tool frames and gripper pose names per end effector (robot's own names), over the
    # robot.yaml's (see taskrunner.robot.tools).
    end_effectors: dict[str, EndEffectorSettings] = {}


class ObjectSpec(_Strict, ObjectFields):
    """A fixed object of a cell file: the task file's object fields and checks
    (:class:`taskrunner.objectspec.ObjectFields`), its mesh path relative to the cell file."""

    pose: PoseSpec = PoseSpec()


class CellSpec(_Strict):
    name: str = Field(min_length=1)
    description: str = ""
    robots: list[RobotSpec] = Field(min_length=1)
    groups: dict[str, list[str]] = {}
    start: dict[str, str] = {}
    objects: list[ObjectSpec] = []


@dataclass(frozen=True)
class CellObject:
    """A fixed object of the cell.

    Attributes:
        pose: placement relative to ``frame`` (a link name or "world").
        line: where it is declared in the cell file.
    """

    name: str
    shape: Shape
    pose: pin.SE3
    frame: str = WORLD
    touch_links: tuple[str, ...] = ()
    line: int | None = None
    material: Material = Material()


@dataclass
class Cell:
    """Robots placed in a world frame and the fixed objects around them."""

    name: str
    path: Path | None
    model: RobotModel
    objects: tuple[CellObject, ...]
    start: dict[str, str]
    description: str = ""
    grasp_modes: dict[str, str] = field(default_factory=dict)
    """Per arm group (prefixed): "friction" or "weld" (the mujoco backend's grasps)."""
    tools: dict[str, Tool] = field(default_factory=dict)
    """Per arm group: its tool frame and gripper poses (:mod:`taskrunner.robot.tools`);
    resolved with no declarations when not given."""

    def __post_init__(self) -> None:
        if not self.tools:
            self.tools = install_tools(self.model)

    def start_state(self) -> np.ndarray:
        """The state the cell starts in: default joint values, the robots'
        ``initial_positions.yaml``, then the ``start`` poses."""
        q = self.model.default_state()
        if self.model.initial_values:
            q = self.model.state_with(q, self.model.initial_values)
        for group, pose in self.start.items():
            q = self.model.state_with(q, self.model.named_state(group, pose))
        return q

    def object(self, name: str) -> CellObject:
        for obj in self.objects:
            if obj.name == name:
                return obj
        raise UnknownNameError("object", name, [o.name for o in self.objects])


def _shape(spec: ObjectSpec, base_dir: Path, packages: PackageMap) -> Shape:
    if spec.shape == "box":
        assert spec.size is not None
        return Box(tuple(spec.size))  # type: ignore[arg-type]
    if spec.shape == "cylinder":
        assert spec.radius is not None and spec.length is not None
        return Cylinder(spec.radius, spec.length)
    if spec.shape == "sphere":
        assert spec.radius is not None
        return Sphere(spec.radius)
    assert spec.file is not None
    scale = spec.scale if spec.scale is not None else (1.0, 1.0, 1.0)
    return Mesh(packages.resolve(spec.file, base_dir), tuple(scale))  # type: ignore[arg-type]


def _resolve_robot(value: str, cell_dir: Path, packages: PackageMap) -> Path:
    """A robot named by a cell: ``package://pkg[/path]``, an absolute path, or a path
    relative to the cell's folder or the folder above it."""
    if value.startswith("package://"):
        try:
            candidate = packages.resolve(value, cell_dir)
        except RobotDescriptionError as exc:
            raise FileNotFoundError(exc.reason) from None
        if candidate.exists():
            return candidate
        raise FileNotFoundError(str(candidate))
    expanded = Path(value).expanduser()
    candidates = [expanded] if expanded.is_absolute() else [cell_dir / value,
                                                           cell_dir.parent / value]
    for candidate in candidates:
        # A name the file system refuses (NUL, too long) is no robot; exists() is False
        # for a symlink loop.
        if path_problem(candidate) is None and candidate.exists():
            return candidate.resolve()
    raise FileNotFoundError(", ".join(str(c) for c in candidates))


def load_cell(path: str | Path, packages: PackageMap | None = None,
              policy: FolderPolicy | None = None, strict: bool | None = None,
              allow_missing_meshes: bool | None = None,
              taught: TaughtPoses | None = None, *,
              options: LoadOptions | None = None) -> Cell:
    """Load a cell file (see the module docstring).

    Args:
        path: the cell file.
        packages: the package map of its robots (default: packages found next to it).
        policy: the folders the cell and its robots may come from (None: anything
            loads). Robots outside the policy's robot folders are refused before any of
            their files is read (xacro runs code).
        strict: every warning of a robot is an error (see
            :func:`taskrunner.robot.load_robot`); None: ``options.strict``.
        allow_missing_meshes: load robots whose mesh files cannot be found (see
            :func:`taskrunner.robot.load_robot`); None: ``options.allow_missing_meshes``.
        taught: taught poses (:mod:`taskrunner.taught`): those of this cell file are
            added to its named poses (None: none).
        options: how its robots are loaded (default ``LoadOptions()``); its
            ``collision`` wins over the cell's and the robots' own choices.

    Raises:
        YamlError: the file does not match the cell schema (with file:line).
        RobotDescriptionError: a robot's files are invalid, or names clash.
        PathNotAllowedError: the cell or one of its robots is outside the policy.
    """
    if policy is not None:
        policy.check(path, FileKind.CELL)
    path = resolve_path(path, YamlError)
    node = load_yaml(path)
    spec = validate_node(CellSpec, node, path)
    robots_node = node["robots"]
    options = _options(options, strict, allow_missing_meshes)
    packages = packages if packages is not None else PackageMap(
        search_roots=[path.parent.parent], package_path=options.package_path)

    placements: list[Placement] = []
    descriptions: dict[Path, RobotDescription] = {}
    declared: dict[str, DeclaredTool] = {}
    seen: set[str] = set()
    for i, robot in enumerate(spec.robots):
        item = robots_node[i]
        if robot.name in seen:
            raise YamlError(f"robots[{i}].name: duplicate robot name {robot.name!r}", path,
                            line_of(item, "name"))
        seen.add(robot.name)
        if robot.base.frame != WORLD:
            raise YamlError(f"robots[{i}].base.frame: a robot base must be given in the "
                            f"'world' frame (got {robot.base.frame!r})", path,
                            line_of(item, "base"))
        try:
            robot_path = _resolve_robot(robot.robot, path.parent, packages)
        except FileNotFoundError as exc:
            raise YamlError(f"robots[{i}].robot: {robot.robot!r} not found (looked at {exc})",
                            path, line_of(item, "robot")) from None
        if policy is not None:
            try:
                policy.check(robot_path, FileKind.ROBOT, robot.robot)
            except PathNotAllowedError as exc:
                raise PathNotAllowedError(f"robots[{i}].robot: {exc.reason}", path,
                                          line_of(item, "robot")) from None
        # The packages around the robot, as when it is loaded on its own (run-task info).
        packages.discover_around(robot_path)
        lines: dict[tuple[str, str], tuple[str, int | None]] = {}
        poses_node = item.get("poses", {}) if isinstance(item, LineDict) else {}
        for group_name, poses in robot.poses.items():
            for pose_name in poses:
                group_node = poses_node.get(group_name, {})
                lines[(group_name, pose_name)] = (str(path), line_of(group_node, pose_name))
        # Two copies of one arm read (and expand the xacro of) their files once.
        if robot_path not in descriptions:
            descriptions[robot_path] = load_description(robot_path, packages)
        description = copy.copy(descriptions[robot_path])
        declared.update({robot.prefix + name: entry for name, entry in merge_declared(
            description.end_effector_settings,
            read_end_effector_settings(item.get("end_effectors"), path)).items()})
        if robot.collision is not None:  # the cell's word wins over the robot.yaml's
            description.collision = robot.collision
        placements.append(
            Placement(description, robot.name, robot.prefix,
                      robot.base.se3(), robot.poses, lines)
        )
    try:
        model = build_model(placements, name=spec.name, extra_groups=spec.groups,
                            strict=options.strict, check_self_collision=False,
                            allow_missing_meshes=options.allow_missing_meshes,
                            collision=options.collision)
    except RobotDescriptionError as exc:
        if exc.path is None:  # a problem with the cell's own declarations
            raise YamlError(exc.reason, path, line_of(node, "groups")) from None
        raise

    objects = []
    object_names: set[str] = set()
    for i, obj in enumerate(spec.objects):
        item = node["objects"][i]
        if obj.name in object_names:
            raise YamlError(f"objects[{i}].name: duplicate object {obj.name!r}", path,
                            line_of(item, "name"))
        object_names.add(obj.name)
        if obj.pose.frame != WORLD and not model.has_link(obj.pose.frame):
            raise YamlError(f"objects[{i}].pose.frame: unknown frame {obj.pose.frame!r}", path,
                            line_of(item, "pose"))
        try:
            shape = _shape(obj, path.parent, packages)
        except (RobotDescriptionError, ValueError) as exc:
            raise YamlError(f"objects[{i}]: {exc}", path, line_of(item)) from None
        problem = file_problem(shape.path) if isinstance(shape, Mesh) else None
        if problem is not None:
            raise YamlError(f"objects[{i}].file: mesh not found: {obj.file}"
                            if problem == "file not found"
                            else f"objects[{i}].file: mesh {obj.file!r}: {problem}", path,
                            line_of(item, "file"))
        for link in obj.touch_links:
            if not model.has_link(link):
                raise YamlError(f"objects[{i}].touch_links: unknown link {link!r}", path,
                                line_of(item, "touch_links"))
        material = material_of(obj)
        if (material.mass or material.density) and obj.pose.frame != WORLD:
            key = "mass" if material.mass is not None else "density"
            raise YamlError(f"objects[{i}].{key}: an object fixed to link {obj.pose.frame!r} "
                            "does not move; a mass or density makes a world object a free "
                            "body in physics", path, line_of(item, key))
        objects.append(CellObject(obj.name, shape, obj.pose.se3(), obj.pose.frame,
                                  tuple(obj.touch_links), line_of(item), material))

    for group, pose in spec.start.items():
        try:
            model.named_state(group, pose)
        except UnknownNameError as exc:
            raise YamlError(f"start.{group}: {exc}", path, line_of(node["start"], group)) from None
    grasp_modes = _grasp_modes(spec, node, model, path)
    cell = Cell(spec.name, path, model, tuple(objects), dict(spec.start), spec.description,
                grasp_modes, tools=install_tools(model, declared))
    # Self-collision from where the cell starts (its start poses), not the zero state.
    start_name = "the cell's start state" if spec.start else None
    found = self_collision_warnings(model, cell.start_state(), start_name)
    raise_if_strict(found, options.strict)
    for warning in found:
        log.warning("%s", warning)
        model.warnings.append(str(warning))
    apply_taught(cell, taught)  # poses taught on this cell (the API's), if any given
    return cell


def _grasp_modes(spec: CellSpec, node: LineDict, model: RobotModel, path: Path
                 ) -> dict[str, str]:
    """Each robot's ``grasp_mode`` per arm group (prefixed names); a key of a mapping
    names one of the robot's arm groups or end effectors."""
    modes: dict[str, str] = {}
    for i, robot in enumerate(spec.robots):
        if robot.grasp_mode is None:
            continue
        prefix = robot.prefix
        arms = {g.name: g for g in model.groups.values() if g.end_effector and g.tip_link
                and g.robot == robot.name}
        given = (robot.grasp_mode if isinstance(robot.grasp_mode, dict)
                 else {name[len(prefix):]: robot.grasp_mode for name in arms})
        for key, mode in given.items():
            found = [g for g in arms.values() if g.name == prefix + key
                     or g.end_effector == prefix + key]
            if not found:
                known = sorted({n[len(prefix):] for n in arms}
                               | {str(g.end_effector)[len(prefix):] for g in arms.values()})
                raise YamlError(f"robots[{i}].grasp_mode: {key!r} is not an arm group or end "
                                f"effector of robot {robot.name!r} (known: "
                                f"{', '.join(known) or 'none'})", path,
                                line_of(node["robots"][i], "grasp_mode"))
            for group in found:
                modes[group.name] = mode
    return modes


def load_cell_or_robot(path: str | Path, packages: PackageMap | None = None,
                       strict: bool | None = None,
                       allow_missing_meshes: bool | None = None, *,
                       options: LoadOptions | None = None) -> Cell:
    """A cell file, or a robot (manifest, folder, URDF, xacro) as a one-robot cell with no
    objects; ``strict`` and ``allow_missing_meshes`` (None: the ``options``') and
    ``options`` as :func:`load_cell`'s."""
    path = Path(path)
    options = _options(options, strict, allow_missing_meshes)
    if path.suffix in (".yaml", ".yml") and path.name != "robot.yaml":
        return load_cell(path, packages, options=options)
    description = load_description(path, packages, options=options)
    model = build_model([Placement(description)], name=description.name,
                        strict=options.strict, allow_missing_meshes=options.allow_missing_meshes,
                        collision=options.collision)
    return Cell(model.name, path, model, (), {},
                tools=install_tools(model, description.end_effector_settings))


def _options(options: LoadOptions | None, strict: bool | None,
             allow_missing_meshes: bool | None) -> LoadOptions:
    """``options`` (default ``LoadOptions()``) with the arguments given explicitly."""
    options = options or LoadOptions()
    if strict is not None:
        options = options.replaced(strict=strict)
    if allow_missing_meshes is not None:
        options = options.replaced(allow_missing_meshes=allow_missing_meshes)
    return options
