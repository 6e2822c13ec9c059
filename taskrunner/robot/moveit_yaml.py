"""MoveIt's ``kinematics.yaml``, ``joint_limits.yaml``, ``ompl_planning.yaml`` and
``initial_positions.yaml``, read without ROS.

Both accept the plain form the Setup Assistant writes and the ROS 2 parameter form
(``/**: ros__parameters: robot_description_kinematics: …``). Values are checked for type
and range here; joint and group names are checked against the model when it is built.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from taskrunner.errors import YamlError
from taskrunner.yamlfile import LineDict, line_of, load_yaml

__all__ = [
    "JointLimitOverride",
    "JointLimitsConfig",
    "KinematicsSettings",
    "OmplConfig",
    "OmplGroupSettings",
    "read_initial_positions_yaml",
    "read_joint_limits_yaml",
    "read_kinematics_yaml",
    "read_ompl_planning_yaml",
]


@dataclass(frozen=True)
class KinematicsSettings:
    """IK settings of one group (MoveIt's names in parentheses).

    Attributes:
        position_only_ik: ignore orientation (``position_only_ik``).
        timeout: seconds per IK call (``kinematics_solver_timeout``).
        attempts: random restarts allowed (``kinematics_solver_attempts``).
        search_resolution: kept for reference (``kinematics_solver_search_resolution``).
        solver: the plugin named in the file, for reference only.
        line: where the group's entry starts.
    """

    position_only_ik: bool = False
    timeout: float = 0.005
    attempts: int = 10
    search_resolution: float = 0.005
    solver: str = ""
    line: int | None = None


@dataclass(frozen=True)
class JointLimitOverride:
    """Limits of one joint from joint_limits.yaml; None means "keep the URDF's"."""

    min_position: float | None = None
    max_position: float | None = None
    max_velocity: float | None = None
    max_acceleration: float | None = None
    line: int | None = None


@dataclass(frozen=True)
class JointLimitsConfig:
    """The whole joint_limits.yaml."""

    path: Path | None
    default_velocity_scaling_factor: float = 1.0
    default_acceleration_scaling_factor: float = 1.0
    joints: dict[str, JointLimitOverride] | None = None


def _unwrap_ros_parameters(data: Any, inner_key: str) -> Any:
    """Strip ``/**: ros__parameters: <inner_key>:`` wrappers if present, and a bare
    ``<inner_key>:`` around the whole file (moveit_resources' Panda writes its
    joint_limits.yaml under ``robot_description_planning:``, the parameter namespace it
    is loaded into; read without unwrapping, its limits would be silently ignored)."""
    if isinstance(data, dict) and len(data) == 1:
        (only,) = data.values()
        if isinstance(only, dict) and "ros__parameters" in only:
            data = only["ros__parameters"]
            if isinstance(data, dict) and inner_key in data:
                data = data[inner_key]
    if isinstance(data, dict) and list(data) == [inner_key] and isinstance(data[inner_key], dict):
        data = data[inner_key]
    return data


def _number(
    path: Path, mapping: LineDict, key: str, low: float | None = None, integer: bool = False
) -> float | None:
    if key not in mapping:
        return None
    value = mapping[key]
    ok = isinstance(value, (int, float)) and not isinstance(value, bool)
    if integer:
        ok = ok and float(value).is_integer()
    if not ok:
        kind = "an integer" if integer else "a number"
        raise YamlError(f"'{key}' must be {kind} (got {value!r})", path, line_of(mapping, key))
    if low is not None and value < low:
        raise YamlError(f"'{key}' must be >= {low} (got {value!r})", path, line_of(mapping, key))
    return float(value)


def read_kinematics_yaml(path: str | Path) -> dict[str, KinematicsSettings]:
    """Read a MoveIt ``kinematics.yaml``: group name → settings.

    Raises:
        YamlError: bad YAML, a repeated key, or a value of the wrong type.
    """
    path = Path(path)
    data = _unwrap_ros_parameters(load_yaml(path), "robot_description_kinematics")
    if data is None:
        return {}
    if not isinstance(data, dict):
        raise YamlError("kinematics.yaml must map group names to settings", path, line_of(data))
    result: dict[str, KinematicsSettings] = {}
    for group, entry in data.items():
        if not isinstance(entry, LineDict):
            raise YamlError(
                f"group {group!r}: settings must be a mapping (got {entry!r})",
                path,
                line_of(data, group),
            )
        position_only = entry.get("position_only_ik", False)
        if not isinstance(position_only, bool):
            raise YamlError(
                f"'position_only_ik' must be true or false (got {position_only!r})",
                path,
                line_of(entry, "position_only_ik"),
            )
        timeout = _number(path, entry, "kinematics_solver_timeout", low=0.0)
        attempts = _number(path, entry, "kinematics_solver_attempts", low=1, integer=True)
        resolution = _number(path, entry, "kinematics_solver_search_resolution", low=0.0)
        result[str(group)] = KinematicsSettings(
            position_only_ik=position_only,
            timeout=timeout if timeout is not None else KinematicsSettings.timeout,
            attempts=int(attempts) if attempts is not None else KinematicsSettings.attempts,
            search_resolution=(
                resolution if resolution is not None else KinematicsSettings.search_resolution
            ),
            solver=str(entry.get("kinematics_solver", "")),
            line=line_of(data, group),
        )
    return result


def read_joint_limits_yaml(path: str | Path) -> JointLimitsConfig:
    """Read a MoveIt ``joint_limits.yaml``.

    Raises:
        YamlError: bad YAML, a repeated key, a value of the wrong type, or a
            ``min_position`` above ``max_position``.
    """
    path = Path(path)
    data = _unwrap_ros_parameters(load_yaml(path), "robot_description_planning")
    if data is None:
        return JointLimitsConfig(path, joints={})
    if not isinstance(data, LineDict):
        raise YamlError("joint_limits.yaml must be a mapping", path, line_of(data))
    velocity_scale = _number(path, data, "default_velocity_scaling_factor", low=0.0)
    acceleration_scale = _number(path, data, "default_acceleration_scaling_factor", low=0.0)
    for key, value in (
        ("default_velocity_scaling_factor", velocity_scale),
        ("default_acceleration_scaling_factor", acceleration_scale),
    ):
        if value is not None and not 0.0 < value <= 1.0:
            raise YamlError(f"'{key}' must be in (0, 1] (got {value})", path, line_of(data, key))
    joints_node = data.get("joint_limits")
    if joints_node is None:  # absent or empty: only the scaling factors are set
        joints_node = LineDict()
    if not isinstance(joints_node, LineDict):
        raise YamlError(
            "'joint_limits' must map joint names to limits", path, line_of(data, "joint_limits")
        )
    joints: dict[str, JointLimitOverride] = {}
    for joint, entry in joints_node.items():
        if not isinstance(entry, LineDict):
            raise YamlError(
                f"joint {joint!r}: limits must be a mapping (got {entry!r})",
                path,
                line_of(joints_node, joint),
            )
        has_pos = entry.get("has_position_limits", "min_position" in entry)
        has_vel = entry.get("has_velocity_limits", "max_velocity" in entry)
        has_acc = entry.get("has_acceleration_limits", "max_acceleration" in entry)
        lo = _number(path, entry, "min_position") if has_pos else None
        hi = _number(path, entry, "max_position") if has_pos else None
        vel = _number(path, entry, "max_velocity", low=0.0) if has_vel else None
        acc = _number(path, entry, "max_acceleration", low=0.0) if has_acc else None
        if lo is not None and hi is not None and lo > hi:
            raise YamlError(
                f"joint {joint!r}: 'min_position' ({lo}) is above 'max_position' ({hi})",
                path,
                line_of(entry, "min_position"),
            )
        if vel == 0.0 or acc == 0.0:
            # MoveIt configs often write 0 with has_*_limits: false; with true it is a bug.
            which = "max_velocity" if vel == 0.0 else "max_acceleration"
            raise YamlError(
                f"joint {joint!r}: '{which}' must be > 0 when its limit is enabled",
                path,
                line_of(entry, which),
            )
        joints[str(joint)] = JointLimitOverride(lo, hi, vel, acc, line_of(joints_node, joint))
    return JointLimitsConfig(
        path,
        velocity_scale if velocity_scale is not None else 1.0,
        acceleration_scale if acceleration_scale is not None else 1.0,
        joints,
    )


# --------------------------------------------------------------------------- ompl_planning
# Top-level keys of a ROS 2 ompl_planning.yaml that are not groups.
_OMPL_TOP_KEYS = {"planner_configs", "planning_plugin", "planning_plugins", "request_adapters",
                  "response_adapters", "start_state_max_bounds_error"}


# The geometric planners the ompl 2.0.1 bindings offer that solve our queries. AORRTC is
# left out: it reports "Zero-length path found" on every query here. BiTRRT, TRRT,
# LazyPRM and EST have no Python class in these bindings.
OMPL_PLANNERS = (
    "RRTConnect", "RRT", "RRTstar", "InformedRRTstar", "SORRTstar", "PRM", "PRMstar",
    "BITstar", "KPIECE1", "BKPIECE1", "LBKPIECE1", "FMT", "BFMT",
)


def ompl_planner_name(planner_id: str) -> str:
    """An OMPL planner as MoveIt writes it (``geometric::RRTConnect``, a configuration
    named ``RRTConnectkConfigDefault``) → the planner's name (``RRTConnect``)."""
    return re.sub(r"kConfig\w*$", "", planner_id.split("::")[-1])


@dataclass(frozen=True)
class OmplGroupSettings:
    """One group's entry of ``ompl_planning.yaml``.

    Attributes:
        default_planner_config: the planner configuration used when a request names none
            (``default_planner_config``, else the first of ``planner_configs``).
        planner_type: its OMPL planner (``geometric::RRTConnect``), when the file defines
            the configuration.
        planner_settings: that configuration's parameters (``range``, …).
        settings: the group's other keys (``longest_valid_segment_fraction``, …).
        line: where the group's entry starts.
    """

    default_planner_config: str | None
    planner_type: str | None
    planner_settings: dict[str, Any]
    settings: dict[str, Any]
    line: int | None

    @property
    def range(self) -> float:
        """The default configuration's ``range`` (rad, the longest edge a tree grows at
        once); 0 where it gives none (MoveIt's ``range: 0.0``: the planner's default)."""
        value = self.planner_settings.get("range", 0.0)
        return float(value) if isinstance(value, (int, float)) and not isinstance(value, bool) \
            and math.isfinite(value) and value > 0 else 0.0

    @property
    def planner(self) -> str | None:
        """The default planner's name among :data:`OMPL_PLANNERS` (``geometric::PRM`` →
        ``PRM``), or None when the file gives none or one these bindings lack."""
        given = self.planner_type or self.default_planner_config
        name = ompl_planner_name(given) if given else None
        return name if name in OMPL_PLANNERS else None


@dataclass(frozen=True)
class OmplConfig:
    """``ompl_planning.yaml``: per group, its default planner and settings."""

    path: Path
    groups: dict[str, OmplGroupSettings]
    warnings: tuple[tuple[str, int | None], ...] = ()


def read_ompl_planning_yaml(path: str | Path) -> OmplConfig:
    """Read MoveIt's ``ompl_planning.yaml`` (plain or ROS 2 parameter form).

    A group whose default names a configuration the file does not define is kept, with
    a warning (``warnings``: message, line); unknown group names are checked against
    the SRDF when the model is built.

    Raises:
        YamlError: bad YAML, or a shape that is not MoveIt's.
    """
    path = Path(path)
    data = _unwrap_ros_parameters(load_yaml(path), "planning_pipelines")
    if data is None:
        return OmplConfig(path, {})
    if not isinstance(data, LineDict):
        raise YamlError("ompl_planning.yaml must be a mapping", path, line_of(data))
    if "ompl" in data and isinstance(data["ompl"], LineDict):
        data = data["ompl"]  # the ROS 2 pipeline form: planning_pipelines: … ompl: {…}
    configs = data.get("planner_configs") or LineDict()
    if not isinstance(configs, dict):
        raise YamlError("'planner_configs' must map names to settings", path,
                        line_of(data, "planner_configs"))
    warnings: list[tuple[str, int | None]] = []
    groups: dict[str, OmplGroupSettings] = {}
    for group, entry in data.items():
        if group in _OMPL_TOP_KEYS or not isinstance(entry, dict):
            continue
        names = entry.get("planner_configs") or []
        if not isinstance(names, list) or not all(isinstance(n, str) for n in names):
            raise YamlError(f"group {group!r}: 'planner_configs' must be a list of names",
                            path, line_of(entry, "planner_configs"))
        default = entry.get("default_planner_config") or (names[0] if names else None)
        planner_type, planner_settings = None, {}
        if default is not None:
            config = configs.get(default)
            if isinstance(config, dict):
                planner_type = str(config.get("type", "")) or None
                planner_settings = {str(k): v for k, v in config.items() if k != "type"}
                if isinstance(config, LineDict):  # the planner uses it: checked here
                    _number(path, config, "range", low=0.0)
            else:
                warnings.append((f"group {group!r}: planner configuration {default!r} is "
                                 "not defined under 'planner_configs'",
                                 line_of(entry, "default_planner_config")
                                 if "default_planner_config" in entry else line_of(data, group)))
        given = planner_type or default
        if (isinstance(configs.get(default), dict) and given is not None
                and ompl_planner_name(str(given)) not in OMPL_PLANNERS):
            warnings.append((f"group {group!r}: default planner {given!r} is not available "
                             f"(available: {', '.join(OMPL_PLANNERS)}); RRTConnect is used",
                             line_of(entry, "default_planner_config")
                             if "default_planner_config" in entry else line_of(data, group)))
        settings = {str(k): v for k, v in entry.items()
                    if k not in ("planner_configs", "default_planner_config")}
        groups[str(group)] = OmplGroupSettings(
            str(default) if default is not None else None, planner_type, planner_settings,
            settings, line_of(data, group))
    return OmplConfig(path, groups, tuple(warnings))


# --------------------------------------------------------------------------- pilz_cartesian_limits
_CARTESIAN_KEYS = ("max_trans_vel", "max_trans_acc", "max_trans_dec", "max_rot_vel")


@dataclass(frozen=True)
class CartesianLimits:
    """``pilz_cartesian_limits.yaml``: limits of a straight-line (Cartesian) motion of the
    tool, applied by :func:`taskrunner.planning.cartesian_limits.time_cartesian_path`.

    Attributes:
        max_trans_vel: translational speed (m/s).
        max_trans_acc: translational acceleration (m/s²).
        max_trans_dec: translational deceleration, a magnitude (m/s²; MoveIt writes it
            negative).
        max_rot_vel: rotational speed (rad/s).
    """

    path: Path
    max_trans_vel: float
    max_trans_acc: float
    max_trans_dec: float
    max_rot_vel: float

    def describe(self) -> str:
        return (f"translation {self.max_trans_vel:g} m/s, {self.max_trans_acc:g} m/s² up, "
                f"{self.max_trans_dec:g} m/s² down; rotation {self.max_rot_vel:g} rad/s")


def read_pilz_cartesian_limits_yaml(path: str | Path) -> CartesianLimits:
    """Read MoveIt's ``pilz_cartesian_limits.yaml`` (``cartesian_limits: {max_trans_vel,
    max_trans_acc, max_trans_dec, max_rot_vel}``, plain or in ROS 2 parameter form).

    Raises:
        YamlError: bad YAML, a missing or unknown key, a value that is not a non-zero
            finite number, or a negative speed or acceleration (with the line).
    """
    path = Path(path)
    data = _unwrap_ros_parameters(load_yaml(path), "robot_description_planning")
    node = data.get("cartesian_limits") if isinstance(data, LineDict) else None
    if not isinstance(node, LineDict):
        raise YamlError("expected 'cartesian_limits: {max_trans_vel, max_trans_acc, "
                        "max_trans_dec, max_rot_vel}'", path, line_of(data))
    for key in node:
        if key not in _CARTESIAN_KEYS:
            raise YamlError(f"unknown field {key!r} (expected one of {', '.join(_CARTESIAN_KEYS)})",
                            path, line_of(node, key))
    values: dict[str, float] = {}
    for key in _CARTESIAN_KEYS:
        if key not in node:
            raise YamlError(f"'{key}' is required", path, node.line)
        value = _number(path, node, key)
        assert value is not None
        if not np.isfinite(value) or value == 0:
            raise YamlError(f"'{key}' must be a non-zero finite number (got {value})", path,
                            line_of(node, key))
        if key != "max_trans_dec" and value < 0:
            raise YamlError(f"'{key}' must be > 0 (got {value})", path, line_of(node, key))
        values[key] = abs(value)
    return CartesianLimits(path, **values)


# --------------------------------------------------------------------------- initial_positions
def read_initial_positions_yaml(path: str | Path) -> tuple[dict[str, float], dict[str, int | None]]:
    """Read ``initial_positions.yaml`` (``initial_positions: {joint: value}``, rad or m):
    the joint values and the line of each.

    Raises:
        YamlError: bad YAML, or a value that is not a number.
    """
    path = Path(path)
    data = load_yaml(path)
    node = data.get("initial_positions") if isinstance(data, dict) else None
    if not isinstance(node, LineDict):
        raise YamlError("expected 'initial_positions: {joint: value}'", path, line_of(data))
    values: dict[str, float] = {}
    lines: dict[str, int | None] = {}
    for joint in node:
        value = _number(path, node, joint)
        assert value is not None
        if not np.isfinite(value):
            raise YamlError(f"'{joint}' must be a finite number (got {value})", path,
                            line_of(node, joint))
        values[str(joint)] = value
        lines[str(joint)] = line_of(node, joint)
    return values, lines
