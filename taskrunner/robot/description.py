"""Finding and reading every file that describes one robot.

A robot is described by a URDF (or xacro), an optional SRDF (or ``.srdf.xacro``), and
optional MoveIt ``kinematics.yaml``, ``joint_limits.yaml``, ``ompl_planning.yaml``,
``initial_positions.yaml``, ``pilz_cartesian_limits.yaml`` and our ``hardware.yaml``
(servo calibration).
:func:`load_description` accepts any of:

- a ``robot.yaml`` manifest (or a folder holding one) naming those files;
- a MoveIt config package folder (ROS 1 or ROS 2 layout, with or without
  ``.setup_assistant``; see :mod:`taskrunner.robot.configpackage`), whose URDF may live
  in a description package found through the package map;
- a bare ``.urdf`` / ``.xacro`` file, with an SRDF beside it if one has the same stem.

A defect in a file the robot can do without (``ompl_planning.yaml``,
``initial_positions.yaml``, ``pilz_cartesian_limits.yaml``) is a warning and the file is
not used.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import TypeVar

from taskrunner.errors import InputError, RobotDescriptionError, YamlError
from taskrunner.kinds import CollisionChoice
from taskrunner.robot.configpackage import (
    ConfigFiles,
    find_config_files,
    is_moveit_config,
    optional_error_warning,
)
from taskrunner.robot.moveit_yaml import (
    CartesianLimits,
    JointLimitsConfig,
    KinematicsSettings,
    OmplConfig,
    read_initial_positions_yaml,
    read_joint_limits_yaml,
    read_kinematics_yaml,
    read_ompl_planning_yaml,
    read_pilz_cartesian_limits_yaml,
)
from taskrunner.robot.notes import LoadWarning
from taskrunner.robot.options import LoadOptions
from taskrunner.robot.packages import PackageMap, default_package_map
from taskrunner.robot.srdf import Srdf, read_srdf, srdf_from_document
from taskrunner.robot.tools import DeclaredTool, read_end_effector_settings
from taskrunner.robot.urdf import UrdfDescription, read_urdf
from taskrunner.robot.xacrofile import expand_xacro
from taskrunner.robot.xmldoc import parse_xml
from taskrunner.yamlfile import LineDict, line_of, load_yaml

__all__ = ["RobotDescription", "load_description", "read_srdf_file"]

MANIFEST = "robot.yaml"
_MANIFEST_KEYS = {"name", "urdf", "srdf", "kinematics", "joint_limits", "hardware", "xacro_args",
                  "ompl_planning", "initial_positions", "collision", "end_effectors",
                  "pilz_cartesian_limits"}
COLLISION_CHOICES = tuple(c.value for c in CollisionChoice)
T = TypeVar("T")


@dataclass
class RobotDescription:
    """Every file of one robot, read and individually checked (not yet cross-checked).

    Attributes:
        files: the files used, by role (``urdf``, ``srdf``, ``kinematics``, …), for
            ``run-task info``.
        layout: how the robot was given (manifest, MoveIt config package layout, file).
        notes: how files were chosen where that was not obvious.
        load_warnings: what loading skipped besides the URDF's and SRDF's own warnings.
    """

    name: str
    source: Path
    urdf: UrdfDescription
    srdf: Srdf | None = None
    kinematics: dict[str, KinematicsSettings] = field(default_factory=dict)
    kinematics_path: Path | None = None
    joint_limits: JointLimitsConfig | None = None
    hardware_path: Path | None = None
    ompl: OmplConfig | None = None
    initial_positions: dict[str, float] = field(default_factory=dict)
    initial_positions_lines: dict[str, int | None] = field(default_factory=dict)
    initial_positions_path: Path | None = None
    files: dict[str, Path] = field(default_factory=dict)
    layout: str = ""
    notes: list[str] = field(default_factory=list)
    load_warnings: list[LoadWarning] = field(default_factory=list)
    collision: str | None = None
    """``collision:`` of the manifest (exact, convex, auto), if it says."""
    cartesian_limits: CartesianLimits | None = None
    """``pilz_cartesian_limits.yaml``, if the robot has one."""
    end_effector_settings: dict[str, DeclaredTool] = field(default_factory=dict)
    """The manifest's ``end_effectors:`` (tool frames, gripper poses; see
    :mod:`taskrunner.robot.tools`)."""

    @property
    def warnings(self) -> list[LoadWarning]:
        srdf = self.srdf.warnings if self.srdf is not None else []
        return [*self.load_warnings, *self.urdf.warnings, *srdf]


def read_srdf_file(path: Path, packages: PackageMap,
                   xacro_args: dict[str, str] | None = None) -> Srdf:
    """Read an SRDF, expanding a ``.srdf.xacro`` (bounded, as URDF xacro is) first."""
    if not path.name.endswith(".xacro"):
        return read_srdf(path)
    doc = parse_xml(expand_xacro(path, packages, xacro_args), path)
    doc._lines.clear()  # lines of the expanded text mean nothing to the user
    return srdf_from_document(doc)


def load_description(path: str | Path, packages: PackageMap | None = None, *,
                     options: LoadOptions | None = None) -> RobotDescription:
    """Read a robot from a manifest, a MoveIt config package, or a URDF/xacro file.

    Args:
        path: see the module docstring for what is accepted.
        packages: package map for ``package://`` and ``$(find)``; by default
            :func:`~taskrunner.robot.packages.default_package_map` for ``path``, with
            the ``options``' package path.
        options: how robots are loaded (only its ``package_path`` is used here, and
            only when ``packages`` is None).

    Raises:
        RobotDescriptionError, YamlError: a file is missing or invalid.
    """
    path = Path(path).resolve()
    if not path.exists():
        raise RobotDescriptionError("robot description not found", path)
    if packages is None:
        packages = default_package_map(path, (options or LoadOptions()).package_path)
    seen_warnings = len(packages.warnings)
    if path.is_dir():
        if (path / MANIFEST).is_file():
            description = _load_manifest(path / MANIFEST, packages)
        elif is_moveit_config(path):
            description = _load_moveit_config(path, packages)
        else:
            raise RobotDescriptionError(
                f"folder holds neither a {MANIFEST} nor a MoveIt config package "
                "(.setup_assistant, launch/planning_context.launch, or config/*.srdf with "
                "config/*.urdf.xacro)", path)
    elif path.suffix in (".yaml", ".yml"):
        description = _load_manifest(path, packages)
    elif path.suffix in (".urdf", ".xacro"):
        stem = path.name.split(".")[0]
        srdf_path = next((c for c in (path.with_name(stem + ".srdf"),
                                      path.with_name(stem + ".srdf.xacro")) if c.is_file()), None)
        description = RobotDescription(
            name=stem,
            source=path,
            urdf=read_urdf(path, packages),
            srdf=read_srdf_file(srdf_path, packages) if srdf_path else None,
            files={"urdf": path, **({"srdf": srdf_path} if srdf_path else {})},
            layout="URDF file",
        )
    else:
        raise RobotDescriptionError(
            "expected a robot.yaml, a .urdf or .xacro file, or a MoveIt config folder", path
        )
    description.load_warnings[:0] = packages.warnings[seen_warnings:]
    return description


def _optional(read: Callable[[Path], T], path: Path, what: str,
              warnings: list[LoadWarning]) -> T | None:
    """``read(path)``, or None with a warning when the file is broken."""
    try:
        return read(path)
    except InputError as exc:
        warnings.append(optional_error_warning(exc, what))
        return None


def _add_optional_files(description: RobotDescription, ompl: Path | None,
                        initial: Path | None, cartesian: Path | None = None) -> None:
    warnings = description.load_warnings
    if cartesian is not None:
        description.cartesian_limits = _optional(
            read_pilz_cartesian_limits_yaml, cartesian, "pilz_cartesian_limits.yaml", warnings)
        if description.cartesian_limits is not None:
            description.files["pilz_cartesian_limits"] = cartesian
            description.notes.append(
                f"Cartesian limits: {description.cartesian_limits.describe()} (straight moves "
                "of the tool are slowed to them)")
    if ompl is not None:
        description.ompl = _optional(read_ompl_planning_yaml, ompl, "ompl_planning.yaml",
                                     warnings)
        if description.ompl is not None:
            description.files["ompl_planning"] = ompl
            warnings += [LoadWarning(message, ompl, line)
                         for message, line in description.ompl.warnings]
    if initial is not None:
        found = _optional(read_initial_positions_yaml, initial, "initial_positions.yaml",
                          warnings)
        if found is not None:
            description.initial_positions, description.initial_positions_lines = found
            description.initial_positions_path = initial
            description.files["initial_positions"] = initial


def _load_manifest(path: Path, packages: PackageMap) -> RobotDescription:
    data = load_yaml(path)
    if not isinstance(data, LineDict):
        raise YamlError("robot manifest must be a mapping", path, line_of(data))
    for key in data:
        if key not in _MANIFEST_KEYS:
            raise YamlError(
                f"unknown field {key!r} (expected one of {', '.join(sorted(_MANIFEST_KEYS))})",
                path,
                line_of(data, key),
            )
    if "urdf" not in data:
        raise YamlError("'urdf' is required", path, data.line)

    def file_field(key: str) -> Path | None:
        value = data.get(key)
        if value is None:
            return None
        if not isinstance(value, str):
            raise YamlError(f"'{key}' must be a file path (got {value!r})", path, line_of(data, key))
        try:
            resolved = packages.resolve(value, path.parent)
        except RobotDescriptionError as exc:
            raise YamlError(f"'{key}': {exc.reason}", path, line_of(data, key)) from None
        if not resolved.is_file():
            raise YamlError(f"'{key}': file not found: {resolved}", path, line_of(data, key))
        return resolved

    xacro_args = data.get("xacro_args") or {}
    if not isinstance(xacro_args, dict):
        raise YamlError("'xacro_args' must be a mapping", path, line_of(data, "xacro_args"))
    args = {str(k): str(v) for k, v in xacro_args.items()}
    urdf_path = file_field("urdf")
    assert urdf_path is not None
    srdf_path = file_field("srdf")
    kin_path = file_field("kinematics")
    limits_path = file_field("joint_limits")
    hardware_path = file_field("hardware")
    roles = {"urdf": urdf_path, "srdf": srdf_path, "kinematics": kin_path,
             "joint_limits": limits_path, "hardware": hardware_path}
    description = RobotDescription(
        name=str(data.get("name", path.parent.name)),
        source=path,
        urdf=read_urdf(urdf_path, packages, args),
        srdf=read_srdf_file(srdf_path, packages, args) if srdf_path else None,
        kinematics=read_kinematics_yaml(kin_path) if kin_path else {},
        kinematics_path=kin_path,
        joint_limits=read_joint_limits_yaml(limits_path) if limits_path else None,
        hardware_path=hardware_path,
        files={role: p for role, p in roles.items() if p is not None},
        layout="robot.yaml manifest",
        end_effector_settings=read_end_effector_settings(data.get("end_effectors"), path),
    )
    _add_optional_files(description, file_field("ompl_planning"),
                        file_field("initial_positions"), file_field("pilz_cartesian_limits"))
    collision = data.get("collision")
    if collision is not None and collision not in COLLISION_CHOICES:
        raise YamlError(f"'collision' must be one of {', '.join(COLLISION_CHOICES)} "
                        f"(got {collision!r})", path, line_of(data, "collision"))
    description.collision = collision
    return description


def _load_moveit_config(folder: Path, packages: PackageMap) -> RobotDescription:
    """A MoveIt config package (see :mod:`taskrunner.robot.configpackage`)."""
    packages.discover(folder)
    found: ConfigFiles = find_config_files(folder, packages)
    kin_path = found.yaml.get("kinematics")
    limits_path = found.yaml.get("joint_limits")
    files = {"urdf": found.urdf, **({"srdf": found.srdf} if found.srdf else {})}
    files.update({role: found.yaml[role] for role in ("kinematics", "joint_limits", "hardware")
                  if role in found.yaml})
    description = RobotDescription(
        name=found.name,
        source=folder,
        urdf=read_urdf(found.urdf, packages, found.urdf_args),
        srdf=read_srdf_file(found.srdf, packages, found.srdf_args) if found.srdf else None,
        kinematics=read_kinematics_yaml(kin_path) if kin_path else {},
        kinematics_path=kin_path,
        joint_limits=read_joint_limits_yaml(limits_path) if limits_path else None,
        hardware_path=found.yaml.get("hardware"),
        files=files,
        layout=found.layout,
        notes=list(found.notes),
        load_warnings=list(found.warnings),
    )
    _add_optional_files(description, found.yaml.get("ompl_planning"),
                        found.yaml.get("initial_positions"),
                        found.yaml.get("pilz_cartesian_limits"))
    return description
