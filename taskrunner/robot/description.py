"""Finding and reading every file that describes one robot.

A robot is described by a URDF (or xacro), an optional SRDF, and optional MoveIt
``kinematics.yaml``, ``joint_limits.yaml`` and our ``hardware.yaml`` (servo calibration).
:func:`load_description` accepts any of:

- a ``robot.yaml`` manifest (or a folder holding one) naming those files;
- a MoveIt config package folder as the Setup Assistant writes it (``.setup_assistant``,
  ``config/*.srdf``, ``config/*.yaml``), whose URDF lives in a description package found
  through the package map;
- a bare ``.urdf`` / ``.xacro`` file, with an SRDF beside it if one has the same stem.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from taskrunner.errors import RobotDescriptionError, YamlError
from taskrunner.robot.moveit_yaml import (
    JointLimitsConfig,
    KinematicsSettings,
    read_joint_limits_yaml,
    read_kinematics_yaml,
)
from taskrunner.robot.packages import PackageMap
from taskrunner.robot.srdf import Srdf, read_srdf
from taskrunner.robot.urdf import UrdfDescription, read_urdf
from taskrunner.yamlfile import LineDict, line_of, load_yaml

__all__ = ["RobotDescription", "load_description"]

MANIFEST = "robot.yaml"
_MANIFEST_KEYS = {"name", "urdf", "srdf", "kinematics", "joint_limits", "hardware", "xacro_args"}


@dataclass
class RobotDescription:
    """Every file of one robot, read and individually checked (not yet cross-checked)."""

    name: str
    source: Path
    urdf: UrdfDescription
    srdf: Srdf | None = None
    kinematics: dict[str, KinematicsSettings] = field(default_factory=dict)
    kinematics_path: Path | None = None
    joint_limits: JointLimitsConfig | None = None
    hardware_path: Path | None = None

    @property
    def warnings(self) -> list[str]:
        return list(self.urdf.warnings)


def load_description(path: str | Path, packages: PackageMap | None = None) -> RobotDescription:
    """Read a robot from a manifest, a MoveIt config package, or a URDF/xacro file.

    Args:
        path: see the module docstring for what is accepted.
        packages: package map for ``package://`` and ``$(find)``; by default one that
            knows every package found next to ``path`` (its folder and the one above).

    Raises:
        RobotDescriptionError, YamlError: a file is missing or invalid.
    """
    path = Path(path).resolve()
    if not path.exists():
        raise RobotDescriptionError("robot description not found", path)
    if path.is_dir():
        if (path / MANIFEST).is_file():
            return _load_manifest(path / MANIFEST, packages)
        if (path / ".setup_assistant").is_file():
            return _load_moveit_config(path, packages)
        raise RobotDescriptionError(
            f"folder holds neither a {MANIFEST} nor a MoveIt config package (.setup_assistant)",
            path,
        )
    if path.suffix in (".yaml", ".yml"):
        return _load_manifest(path, packages)
    if path.suffix in (".urdf", ".xacro"):
        packages = packages or _default_packages(path.parent)
        srdf_path = path.with_name(path.name.split(".")[0] + ".srdf")
        return RobotDescription(
            name=path.name.split(".")[0],
            source=path,
            urdf=read_urdf(path, packages),
            srdf=read_srdf(srdf_path) if srdf_path.is_file() else None,
        )
    raise RobotDescriptionError(
        "expected a robot.yaml, a .urdf or .xacro file, or a MoveIt config folder", path
    )


def _default_packages(folder: Path) -> PackageMap:
    return PackageMap(search_roots=[folder.parent, folder])


def _load_manifest(path: Path, packages: PackageMap | None) -> RobotDescription:
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
    packages = packages or _default_packages(path.parent)

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
    urdf_path = file_field("urdf")
    assert urdf_path is not None
    srdf_path = file_field("srdf")
    kin_path = file_field("kinematics")
    limits_path = file_field("joint_limits")
    return RobotDescription(
        name=str(data.get("name", path.parent.name)),
        source=path,
        urdf=read_urdf(urdf_path, packages, {str(k): str(v) for k, v in xacro_args.items()}),
        srdf=read_srdf(srdf_path) if srdf_path else None,
        kinematics=read_kinematics_yaml(kin_path) if kin_path else {},
        kinematics_path=kin_path,
        joint_limits=read_joint_limits_yaml(limits_path) if limits_path else None,
        hardware_path=file_field("hardware"),
    )


def _load_moveit_config(folder: Path, packages: PackageMap | None) -> RobotDescription:
    """A package written by the MoveIt Setup Assistant."""
    marker = folder / ".setup_assistant"
    data = load_yaml(marker)
    config = data.get("moveit_setup_assistant_config") if isinstance(data, dict) else None
    if not isinstance(config, dict):
        raise YamlError("missing 'moveit_setup_assistant_config'", marker, line_of(data))
    packages = packages or PackageMap(search_roots=[folder.parent])
    packages.discover(folder)

    def entry_path(key: str) -> Path | None:
        entry = config.get(key)
        if not isinstance(entry, dict) or "relative_path" not in entry:
            return None
        base = folder
        if entry.get("package"):
            try:
                base = packages.find(str(entry["package"]))
            except RobotDescriptionError as exc:
                raise YamlError(
                    f"'{key}': {exc.reason}", marker, line_of(entry, "package")
                ) from None
        return base / str(entry["relative_path"])

    urdf_path = entry_path("URDF")
    if urdf_path is None:
        raise YamlError("no URDF entry with 'relative_path'", marker, line_of(config, "URDF"))
    if not urdf_path.is_file():
        raise YamlError(f"URDF not found: {urdf_path}", marker, line_of(config, "URDF"))
    xacro_args = _parse_xacro_args(str(config["URDF"].get("xacro_args", "") or ""))
    srdf_path = entry_path("SRDF")
    if srdf_path is None:
        found = sorted((folder / "config").glob("*.srdf"))
        srdf_path = found[0] if found else None
    kin_path = folder / "config" / "kinematics.yaml"
    limits_path = folder / "config" / "joint_limits.yaml"
    hardware_path = folder / "config" / "hardware.yaml"
    return RobotDescription(
        name=folder.name.removesuffix("_moveit_config"),
        source=folder,
        urdf=read_urdf(urdf_path, packages, xacro_args),
        srdf=read_srdf(srdf_path) if srdf_path else None,
        kinematics=read_kinematics_yaml(kin_path) if kin_path.is_file() else {},
        kinematics_path=kin_path if kin_path.is_file() else None,
        joint_limits=read_joint_limits_yaml(limits_path) if limits_path.is_file() else None,
        hardware_path=hardware_path if hardware_path.is_file() else None,
    )


def _parse_xacro_args(text: str) -> dict[str, str]:
    """``"a:=1 b:=2"`` → ``{"a": "1", "b": "2"}``."""
    args: dict[str, str] = {}
    for token in text.split():
        name, sep, value = token.partition(":=")
        if sep:
            args[name] = value
    return args
