"""Finding the files of a MoveIt config package, as MoveIt's launch files would.

A folder is a MoveIt config package when it has one of three layouts:

- **ROS 1** (``launch/planning_context.launch``): the URDF and the SRDF are the files its
  ``robot_description`` and ``robot_description_semantic`` parameters load (``textfile=``,
  or ``command="xacro FILE name:=value …"``), with ``$(find pkg)`` and ``$(arg name)``
  substituted from the launch file's own ``<arg>`` defaults. A ``.urdf`` that a build
  step generates (absent from a clone) is read from the ``.urdf.xacro`` or ``.xacro``
  beside it, as for ROS 2. When no parameter gives a usable URDF, the error says why
  for each (a package not found and the folders searched, a file absent);
- **ROS 2** with a ``.setup_assistant`` file, read as ``MoveItConfigsBuilder`` reads it:
  ``config/<robot>.urdf.xacro`` when the package has one (the Setup Assistant writes it
  to add ``ros2_control``), else the ``URDF`` entry (package, relative path, xacro
  arguments); the ``SRDF`` entry, else ``config/<robot>.srdf``. A ``.urdf`` that a build
  step generates from a ``.urdf.xacro`` beside it is read from the xacro;
- **ROS 2 without ``.setup_assistant``**: ``config/*.srdf`` (or ``*.srdf.xacro``) and
  ``config/*.urdf.xacro`` (or ``*.urdf``), preferring ``<robot>.*`` where there are several.

``<robot>`` is the package's name (its ``package.xml``, else the folder's) without
``_moveit_config``. The MoveIt YAML files are read from ``config/``.
"""

from __future__ import annotations

import re
import shlex
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field
from pathlib import Path

from taskrunner.errors import InputError, RobotDescriptionError, YamlError
from taskrunner.robot.notes import LoadWarning
from taskrunner.robot.packages import PackageMap
from taskrunner.robot.xmldoc import XmlDocument, read_xml
from taskrunner.yamlfile import line_of, load_yaml

__all__ = ["ConfigFiles", "find_config_files", "is_moveit_config", "package_name"]

SETUP_ASSISTANT = ".setup_assistant"
PLANNING_CONTEXT = Path("launch") / "planning_context.launch"
YAML_FILES = ("kinematics", "joint_limits", "ompl_planning", "initial_positions",
              "pilz_cartesian_limits", "hardware")


@dataclass
class ConfigFiles:
    """The files of one MoveIt config package and how they were chosen.

    Attributes:
        name: the robot's name (package name without ``_moveit_config``).
        layout: which layout was recognised, for ``run-task info``.
        urdf, srdf: the description files (xacro or plain).
        urdf_args, srdf_args: xacro arguments for each.
        yaml: ``config/<name>.yaml`` files present, by stem (``kinematics``, …).
        notes: how a file was picked where that was not obvious (for the user).
        warnings: what was skipped.
    """

    name: str
    layout: str
    urdf: Path
    srdf: Path | None
    urdf_args: dict[str, str] = field(default_factory=dict)
    srdf_args: dict[str, str] = field(default_factory=dict)
    yaml: dict[str, Path] = field(default_factory=dict)
    notes: list[str] = field(default_factory=list)
    warnings: list[LoadWarning] = field(default_factory=list)


def package_name(folder: Path) -> str:
    """The ``<name>`` of the folder's package.xml, else the folder's name."""
    manifest = folder / "package.xml"
    if manifest.is_file():
        try:
            element = read_xml(manifest).root.find("name")
        except RobotDescriptionError:
            element = None
        if element is not None and (element.text or "").strip():
            return (element.text or "").strip()
    return folder.name


def _robot_name(folder: Path) -> str:
    return package_name(folder).removesuffix("_moveit_config")


def _globs(folder: Path, patterns: tuple[str, ...]) -> list[Path]:
    found: list[Path] = []
    for pattern in patterns:
        found += sorted(p for p in folder.glob(pattern) if p.is_file())
    return found


def _srdf_candidates(folder: Path) -> list[Path]:
    return _globs(folder, ("config/*.srdf", "config/*.srdf.xacro", "srdf/*.srdf.xacro",
                           "srdf/*.srdf"))


def _urdf_candidates(folder: Path) -> list[Path]:
    return _globs(folder, ("config/*.urdf.xacro", "config/*.urdf"))


def is_moveit_config(folder: Path) -> bool:
    """True if ``folder`` has one of the layouts of the module docstring."""
    if (folder / SETUP_ASSISTANT).is_file() or (folder / PLANNING_CONTEXT).is_file():
        return True
    return bool(_srdf_candidates(folder)) and bool(_urdf_candidates(folder))


def find_config_files(folder: Path, packages: PackageMap) -> ConfigFiles:
    """The files of the MoveIt config package ``folder`` (see the module docstring).

    Raises:
        RobotDescriptionError, YamlError: no URDF can be found, or the file that names
            it is broken (the message names that file and line).
    """
    if (folder / PLANNING_CONTEXT).is_file():
        files = _ros1(folder, packages)
    else:
        files = _ros2(folder, packages)
    for stem in YAML_FILES:
        path = folder / "config" / f"{stem}.yaml"
        if path.is_file():
            files.yaml[stem] = path
    return files


def _pick(candidates: list[Path], name: str, what: str, files_notes: list[str]) -> Path | None:
    """The candidate named after the robot, else the first (noting the others)."""
    if not candidates:
        return None
    preferred = [c for c in candidates if c.name.split(".")[0] == name]
    chosen = (preferred or candidates)[0]
    if len(candidates) > 1:
        others = ", ".join(c.name for c in candidates if c != chosen)
        files_notes.append(f"{what}: {chosen.name} chosen over {others}")
    return chosen


def _generated_from_xacro(path: Path) -> Path | None:
    """The ``.urdf.xacro`` (or ``.xacro``) a missing generated ``.urdf`` is made from."""
    for candidate in (path.with_name(path.name + ".xacro"), path.with_suffix(".xacro")):
        if candidate.is_file():
            return candidate
    return None


def _parse_xacro_args(text: str) -> dict[str, str]:
    """``"a:=1 b:=2"`` → ``{"a": "1", "b": "2"}``."""
    args: dict[str, str] = {}
    for token in text.split():
        name, sep, value = token.partition(":=")
        if sep:
            args[name] = value
    return args


# --------------------------------------------------------------------------- ROS 2
def _ros2(folder: Path, packages: PackageMap) -> ConfigFiles:
    name = _robot_name(folder)
    marker = folder / SETUP_ASSISTANT
    notes: list[str] = []
    urdf: Path | None = None
    urdf_args: dict[str, str] = {}
    srdf: Path | None = None
    layout = "ROS 2 config package without .setup_assistant"
    modified = _modified_urdf(folder, name)
    if modified.is_file():
        urdf = modified
    if marker.is_file():
        layout = "ROS 2 config package (.setup_assistant)"
        data = load_yaml(marker)
        config = data.get("moveit_setup_assistant_config") if isinstance(data, dict) else None
        if not isinstance(config, dict):
            raise YamlError("missing 'moveit_setup_assistant_config'", marker, line_of(data))
        urdf_entry = config.get("URDF", config.get("urdf"))
        srdf_entry = config.get("SRDF", config.get("srdf"))
        if isinstance(urdf_entry, dict):
            urdf_args = _parse_xacro_args(str(urdf_entry.get("xacro_args") or ""))
            if urdf is None:
                urdf = _entry_path(urdf_entry, "URDF", marker, folder, packages)
                if not urdf.is_file():
                    generated = _generated_from_xacro(urdf)
                    if generated is None:
                        raise YamlError(f"URDF not found: {urdf}", marker,
                                        line_of(config, "URDF"))
                    notes.append(f"URDF: {urdf.name} is generated by a build step; "
                                 f"read from {generated.name}")
                    urdf = generated
            else:
                notes.append(f"URDF: config/{modified.name} (as MoveItConfigsBuilder "
                             "prefers it to the .setup_assistant entry)")
        if isinstance(srdf_entry, dict) and srdf_entry.get("relative_path"):
            srdf = _entry_path(srdf_entry, "SRDF", marker, folder, packages)
            if not srdf.is_file():
                raise YamlError(f"SRDF not found: {srdf}", marker, line_of(config, "SRDF"))
    if urdf is None:
        urdf = _pick(_urdf_candidates(folder), name, "URDF", notes)
    if urdf is None:
        raise RobotDescriptionError(
            "MoveIt config package names no URDF (no .setup_assistant URDF entry, no "
            f"config/{name}.urdf.xacro, no config/*.urdf)", folder)
    if srdf is None:
        srdf = _pick(_srdf_candidates(folder), name, "SRDF", notes)
    return ConfigFiles(name, layout, urdf, srdf, urdf_args, dict(urdf_args), notes=notes)


def _modified_urdf(folder: Path, name: str) -> Path:
    """The Setup Assistant's ``config/<robot>.urdf.xacro`` (the URDF with its
    ``ros2_control`` tags), which MoveItConfigsBuilder prefers to the ``.setup_assistant``
    URDF entry. ``<robot>`` is the URDF's robot name: the package's name without
    ``_moveit_config`` where that file exists, else the stem of the one ``config/*.srdf``
    that has a ``config/<stem>.urdf.xacro`` beside it (moveit_resources names its package
    ``moveit_resources_panda_moveit_config`` and its files ``config/panda.*``)."""
    modified = folder / "config" / f"{name}.urdf.xacro"
    if modified.is_file():
        return modified
    paired = [folder / "config" / f"{srdf.name.removesuffix('.srdf')}.urdf.xacro"
              for srdf in _globs(folder, ("config/*.srdf",))]
    paired = [p for p in paired if p.is_file()]
    return paired[0] if len(paired) == 1 else modified


def _entry_path(entry: dict[str, object], key: str, marker: Path, folder: Path,
                packages: PackageMap) -> Path:
    if "relative_path" not in entry:
        raise YamlError(f"'{key}' has no 'relative_path'", marker, line_of(entry))
    base = folder
    if entry.get("package"):
        try:
            base = packages.find(str(entry["package"]), near=folder)
        except RobotDescriptionError as exc:
            raise YamlError(f"'{key}': {exc.reason}", marker, line_of(entry, "package")) from None
    return base / str(entry["relative_path"])


# --------------------------------------------------------------------------- ROS 1
_SUBSTITUTION = re.compile(r"\$\((\w+)(?:\s+([^)]*))?\)")


class _Launch:
    """The parts of a roslaunch file a robot description needs."""

    def __init__(self, doc: XmlDocument, packages: PackageMap) -> None:
        self.doc = doc
        self.packages = packages
        self.notes: list[str] = []
        self.args: dict[str, str] = {}
        for element in doc.root.iter("arg"):
            value = element.get("value", element.get("default"))
            if element.get("name") and value is not None:
                self.args.setdefault(str(element.get("name")), value)

    def substitute(self, text: str, element: ET.Element) -> str:
        def one(match: re.Match[str]) -> str:
            kind, rest = match.group(1), (match.group(2) or "").strip()
            if kind == "find":
                try:
                    near = self.doc.path.parent if self.doc.path is not None else None
                    return str(self.packages.find(rest, near=near))
                except RobotDescriptionError as exc:
                    raise self.doc.error(element, exc.reason) from None
            if kind == "arg" and rest in self.args:
                return self.substitute(self.args[rest], element)
            if kind == "dirname" and self.doc.path is not None:
                return str(self.doc.path.parent)
            if kind == "optenv":
                parts = rest.split(None, 1)
                return parts[1] if len(parts) > 1 else ""
            raise self.doc.error(element, f"cannot evaluate {match.group(0)!r} "
                                          "without ROS")
        return _SUBSTITUTION.sub(one, text)


def _ros1(folder: Path, packages: PackageMap) -> ConfigFiles:
    launch_path = folder / PLANNING_CONTEXT
    launch = _Launch(read_xml(launch_path), packages)
    description = launch.args.get("robot_description", "robot_description")
    found: dict[str, tuple[Path, dict[str, str]]] = {}
    warnings: list[LoadWarning] = []
    urdf_failures: list[RobotDescriptionError] = []
    for param in launch.doc.root.iter("param"):
        raw_name = param.get("name", "")
        try:
            name = launch.substitute(raw_name, param)
        except RobotDescriptionError:
            continue
        role = {description: "urdf", f"{description}_semantic": "srdf"}.get(name)
        if role is None or role in found:
            continue
        try:
            found[role] = _param_file(launch, param)
        except RobotDescriptionError as exc:
            if role == "urdf":
                urdf_failures.append(exc)
            warnings.append(LoadWarning(f"<param name={raw_name!r}>: {exc.reason}; skipped",
                                        exc.path, exc.line))
    notes = [f"files named by {PLANNING_CONTEXT}", *launch.notes]
    robot = _robot_name(folder)
    if "urdf" not in found:
        causes = "; ".join(f"line {exc.line}: {exc.reason}" if exc.line is not None
                           else exc.reason for exc in urdf_failures)
        raise RobotDescriptionError(
            f"no usable <param name=\"{description}\"> loads the URDF"
            + (f": {causes}" if causes else " (the launch file has none)"), launch_path,
            urdf_failures[0].line if urdf_failures else None)
    urdf, urdf_args = found["urdf"]
    srdf, srdf_args = found.get("srdf", (None, {}))
    if srdf is None:
        srdf = _pick(_srdf_candidates(folder), robot, "SRDF", notes)
    return ConfigFiles(robot, "ROS 1 config package (launch/planning_context.launch)", urdf,
                       srdf, urdf_args, srdf_args, notes=notes, warnings=warnings)


def _param_file(launch: _Launch, element: ET.Element) -> tuple[Path, dict[str, str]]:
    """The file a ``<param>`` loads and its xacro arguments."""
    doc = launch.doc
    textfile = element.get("textfile")
    if textfile:
        return _existing(launch, element, Path(launch.substitute(textfile, element))), {}
    command = element.get("command")
    if not command:
        raise doc.error(element, "neither 'textfile' nor 'command'")
    # xacro itself is no package of ours; the rest is substituted before splitting
    # (quotes in the launch file keep substituted paths with spaces whole).
    command = re.sub(r"\$\(find xacro\)/", "", command)
    try:
        tokens = shlex.split(launch.substitute(command, element))
    except ValueError as exc:
        raise doc.error(element, f"'command' does not parse: {exc}") from None
    files: list[Path] = []
    args: dict[str, str] = {}
    for token in tokens:
        if token in ("xacro", "xacro.py", "rosrun") or token.startswith("-"):
            continue
        name, sep, arg = token.partition(":=")
        if sep:
            args[name] = arg
        else:
            files.append(Path(token))
    if len(files) != 1:
        raise doc.error(element, f"'command' must name one file (got {command!r})")
    return _existing(launch, element, files[0]), args


def _existing(launch: _Launch, element: ET.Element, path: Path) -> Path:
    """``path``, or the xacro it is generated from when a build step makes it (absent
    from a clone of the package's repository)."""
    if path.is_file():
        return path
    generated = _generated_from_xacro(path) if path.suffix == ".urdf" else None
    if generated is None:
        beside = (f"; no {path.name}.xacro or {path.stem}.xacro beside it either"
                  if path.suffix == ".urdf" else "")
        raise launch.doc.error(element, f"file not found: {path}{beside}")
    launch.notes.append(f"URDF: {path.name} is generated by a build step; read from "
                        f"{generated.name}")
    return generated


def optional_error_warning(exc: InputError, what: str) -> LoadWarning:
    """A warning for a defect in a file loading can do without."""
    return LoadWarning(f"{exc.reason}; {what} not used", exc.path, exc.line)
