"""Servo calibration of a hobby-servo arm: joint angles (rad) <-> servo degrees (0..180).

Read from a ``hardware.yaml`` (``robots/servo_arm/config/hardware.yaml``)::

    servo_deg = 90 + direction * (joint_rad - zero_rad) * 180/pi * scale

Degrees are rounded to 0.01 (half away from zero, as the firmware does). A joint with
``same_servo_as`` has no servo of its own: it is never sent and reads as its leader.
Nothing is clamped: an angle outside [0, 180] is refused, naming the joint (and the time).
"""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from taskrunner.errors import ArgumentError, TrajectoryRejectedError, YamlError
from taskrunner.types import JointState, JointTrajectory
from taskrunner.yamlfile import line_of, load_yaml

__all__ = ["JointCalibration", "RobotOnBoard", "ServoCalibration", "load_board_calibration",
           "load_calibration", "round_degrees"]

SERVO_MIN_DEG = 0.0
SERVO_MAX_DEG = 180.0
_SERVO_KEYS = {"name", "servo_type", "channel", "zero_rad", "direction", "scale"}
_MIRROR_KEYS = {"name", "same_servo_as"}
_TOP_KEYS = {"port", "baud", "joints"}


def round_degrees(degrees: np.ndarray | float) -> np.ndarray:
    """Round to 0.01 degree, half away from zero (the firmware's rounding)."""
    values = np.asarray(degrees, dtype=float)
    return np.sign(values) * np.floor(np.abs(values) * 100.0 + 0.5) / 100.0


@dataclass(frozen=True)
class JointCalibration:
    """One joint of ``hardware.yaml``.

    Attributes:
        name: the URDF joint name.
        servo_type: servo model (informative), "" for a joint without its own servo.
        channel: PCA9685 channel (0..15), -1 without a servo.
        zero_rad: joint angle (rad) at the servo's 90-degree centre.
        direction: +1 or -1 (mirrored mounting).
        scale: servo degrees per joint degree.
        same_servo_as: the joint whose servo drives this one, or None.
    """

    name: str
    servo_type: str = ""
    channel: int = -1
    zero_rad: float = 0.0
    direction: int = 1
    scale: float = 1.0
    same_servo_as: str | None = None


@dataclass(frozen=True)
class ServoCalibration:
    """Every calibrated joint; servo order = order of the joints owning a servo.

    Attributes:
        joints: every joint of the file, in file order.
        port: serial port named in the file ("" if none).
        baud: baud rate named in the file.
        path: the file read, if any.
    """

    joints: tuple[JointCalibration, ...]
    port: str = ""
    baud: int = 115200
    path: Path | None = None

    def __post_init__(self) -> None:
        by_name = {j.name: j for j in self.joints}
        object.__setattr__(self, "_by_name", by_name)
        servos = tuple(j for j in self.joints if j.same_servo_as is None)
        object.__setattr__(self, "_servos", servos)
        object.__setattr__(self, "_servo_index", {j.name: i for i, j in enumerate(servos)})

    @property
    def joint_names(self) -> tuple[str, ...]:
        """Every calibrated joint, in file order."""
        return tuple(j.name for j in self.joints)

    @property
    def servo_joint_names(self) -> tuple[str, ...]:
        """The joints owning a servo, in servo order (the order of ``MOVE``/``TRAJ``)."""
        return tuple(j.name for j in self._servos)  # type: ignore[attr-defined]

    @property
    def channels(self) -> tuple[int, ...]:
        """PCA9685 channel of each servo, in servo order."""
        return tuple(j.channel for j in self._servos)  # type: ignore[attr-defined]

    def servo_of(self, name: str) -> int:
        """Servo index (0-based) driving joint ``name`` (its leader's for a mirror)."""
        joint = self._by_name[name]  # type: ignore[attr-defined]
        leader = joint.same_servo_as or joint.name
        return self._servo_index[leader]  # type: ignore[attr-defined]

    def raw_degrees(self, name: str, joint_rad: np.ndarray | float) -> np.ndarray:
        """Unrounded, unclamped servo degrees of joint ``name`` (which owns a servo)."""
        joint = self._by_name[name]  # type: ignore[attr-defined]
        if joint.same_servo_as is not None:
            raise ArgumentError(f"joint {name!r} has no servo of its own "
                             f"(same_servo_as {joint.same_servo_as!r})")
        rad = np.asarray(joint_rad, dtype=float)
        return 90.0 + joint.direction * (rad - joint.zero_rad) * (180.0 / math.pi) * joint.scale

    def to_servo_degrees(self, positions: Mapping[str, float] | JointState) -> np.ndarray:
        """Servo angles (degrees, 0.01 resolution, servo order) of joint ``positions`` (rad).

        Raises:
            ValueError: a servo joint is missing from ``positions``.
            TrajectoryRejectedError: an angle falls outside [0, 180] (never clamped).
        """
        values = positions.as_dict() if isinstance(positions, JointState) else dict(positions)
        missing = [n for n in self.servo_joint_names if n not in values]
        if missing:
            raise ArgumentError(f"'positions' must give every servo joint (missing {missing})")
        out = np.empty(len(self.servo_joint_names))
        for i, name in enumerate(self.servo_joint_names):
            deg = float(round_degrees(self.raw_degrees(name, float(values[name]))))
            if not SERVO_MIN_DEG <= deg <= SERVO_MAX_DEG:
                raise TrajectoryRejectedError(
                    f"joint {name!r} at {float(values[name]):.4f} rad needs servo angle "
                    f"{deg:.2f} deg, outside [0, 180]")
            out[i] = deg
        return out

    def from_servo_degrees(self, degrees: Sequence[float] | np.ndarray) -> JointState:
        """Joint positions (rad) of servo angles (degrees, servo order); a mirror joint
        reads as its leader."""
        degrees = np.asarray(degrees, dtype=float)
        if degrees.shape != (len(self.servo_joint_names),):
            raise ArgumentError(f"'degrees' must hold {len(self.servo_joint_names)} angles "
                             f"(got shape {degrees.shape})")
        positions = []
        for joint in self.joints:
            leader = self._by_name[joint.same_servo_as or joint.name]  # type: ignore[attr-defined]
            deg = degrees[self.servo_of(leader.name)]
            positions.append(leader.zero_rad + (deg - 90.0) * math.pi / 180.0
                             / (leader.direction * leader.scale))
        return JointState(self.joint_names, np.array(positions))

    def check_trajectory_in_range(self, trajectory: JointTrajectory) -> None:
        """Refuse a trajectory that would need a servo angle outside [0, 180] at any sample.

        Raises:
            TrajectoryRejectedError: a joint is not calibrated, or names the joint, the time
                and the angle of the first sample that would need clamping.
        """
        for name in trajectory.names:
            if name not in self._by_name:  # type: ignore[attr-defined]
                raise TrajectoryRejectedError(
                    f"trajectory names joint {name!r} that has no calibration; "
                    f"calibrated: {list(self.joint_names)}")
        first: tuple[float, int, str, float, float] | None = None
        for j, name in enumerate(trajectory.names):
            if self._by_name[name].same_servo_as is not None:  # type: ignore[attr-defined]
                continue
            deg = round_degrees(self.raw_degrees(name, trajectory.positions[:, j]))
            bad = np.flatnonzero((deg < SERVO_MIN_DEG) | (deg > SERVO_MAX_DEG))
            if bad.size and (first is None or bad[0] < first[1]):
                k = int(bad[0])
                first = (float(trajectory.times[k]), k, name,
                         float(trajectory.positions[k, j]), float(deg[k]))
        if first is not None:
            t, k, name, rad, angle = first
            raise TrajectoryRejectedError(
                f"joint {name!r} at t = {t:.3f} s (sample {k}) is at {rad:.4f} rad, which "
                f"needs servo angle {angle:.2f} deg outside [0, 180]; refusing rather than "
                "clamping")


def _fail(message: str, path: Path, node: Any, key: Any = None) -> YamlError:
    return YamlError(message, path, line_of(node, key))


def _number(entry: Any, key: str, path: Path, default: float) -> float:
    value = entry.get(key, default)
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise _fail(f"'{key}' of joint {entry.get('name')!r} must be a finite number "
                    f"(got {value!r})", path, entry, key)
    return float(value)


def _joint(entry: Any, path: Path, known: Sequence[str] | None) -> JointCalibration:
    if not isinstance(entry, dict):
        raise YamlError(f"each joint must be a mapping (got {entry!r})", path)
    name = entry.get("name")
    if not isinstance(name, str) or not name:
        raise _fail(f"joint needs a 'name' string (got {name!r})", path, entry, "name")
    if known is not None and name not in known:
        raise _fail(f"unknown joint {name!r}; the robot's joints: {list(known)}",
                    path, entry, "name")
    if "same_servo_as" in entry:
        extra = sorted(set(entry) - _MIRROR_KEYS)
        if extra:
            raise _fail(f"joint {name!r} has 'same_servo_as' and so no calibration of its "
                        f"own; remove {extra}", path, entry, extra[0])
        leader = entry["same_servo_as"]
        if not isinstance(leader, str):
            raise _fail(f"'same_servo_as' of joint {name!r} must be a joint name (got "
                        f"{leader!r})", path, entry, "same_servo_as")
        return JointCalibration(name=name, same_servo_as=leader)
    unknown = sorted(set(entry) - _SERVO_KEYS)
    if unknown:
        raise _fail(f"unknown field {unknown[0]!r} in joint {name!r}; fields: "
                    f"{sorted(_SERVO_KEYS | {'same_servo_as'})}", path, entry, unknown[0])
    channel = entry.get("channel")
    if isinstance(channel, bool) or not isinstance(channel, int) or not 0 <= channel <= 15:
        raise _fail(f"'channel' of joint {name!r} must be an integer 0..15 (got {channel!r})",
                    path, entry, "channel")
    direction = entry.get("direction", 1)
    if isinstance(direction, bool) or direction not in (1, -1):
        raise _fail(f"'direction' of joint {name!r} must be 1 or -1 (got {direction!r})",
                    path, entry, "direction")
    scale = _number(entry, "scale", path, 1.0)
    if scale <= 0:
        raise _fail(f"'scale' of joint {name!r} must be > 0 (got {scale})", path, entry, "scale")
    servo_type = entry.get("servo_type", "")
    if not isinstance(servo_type, str):
        raise _fail(f"'servo_type' of joint {name!r} must be a string (got {servo_type!r})",
                    path, entry, "servo_type")
    return JointCalibration(name=name, servo_type=servo_type, channel=channel,
                            zero_rad=_number(entry, "zero_rad", path, 0.0),
                            direction=int(direction), scale=scale)


def load_calibration(path: str | Path, joint_names: Sequence[str] | None = None,
                     ) -> ServoCalibration:
    """Read a ``hardware.yaml``.

    Args:
        path: the file.
        joint_names: the robot's joints; a calibrated joint not among them is an error.

    Raises:
        YamlError: unreadable or invalid YAML, or a bad field (``file:line`` in the
            message): unknown key, unknown joint, wrong type, channel out of 0..15,
            direction not +-1, repeated joint or channel, ``same_servo_as`` naming a
            joint without its own servo.
    """
    path = Path(path)
    data, port, baud = _read_link_file(path, "joints", list, _TOP_KEYS)
    joints_node = data["joints"]
    joints: list[JointCalibration] = []
    for i, entry in enumerate(joints_node):
        try:
            joint = _joint(entry, path, joint_names)
        except YamlError as exc:
            if exc.line is None:
                raise YamlError(exc.reason, path, line_of(joints_node, i)) from None
            raise
        if any(j.name == joint.name for j in joints):
            raise _fail(f"joint {joint.name!r} is calibrated twice", path, joints_node, i)
        if joint.channel >= 0 and any(j.channel == joint.channel for j in joints):
            raise _fail(f"channel {joint.channel} of joint {joint.name!r} is used twice",
                        path, entry, "channel")
        joints.append(joint)
    owners = {j.name for j in joints if j.same_servo_as is None}
    for i, joint in enumerate(joints):
        if joint.same_servo_as is not None and joint.same_servo_as not in owners:
            raise _fail(f"'same_servo_as' of joint {joint.name!r} must name a joint with its "
                        f"own servo (got {joint.same_servo_as!r}; servos: {sorted(owners)})",
                        path, joints_node[i], "same_servo_as")
    if not owners:
        raise _fail("no joint with a servo", path, data, "joints")
    return ServoCalibration(tuple(joints), port, int(baud), path)


@dataclass(frozen=True)
class RobotOnBoard:
    """One robot of a cell whose servos share a board (see :func:`load_board_calibration`).

    Attributes:
        name: the cell's robot name (``left``), the key in the board file.
        prefix: put before its joint names in the cell (``left_``).
        hardware_path: its own ``hardware.yaml`` (zero_rad, direction, scale).
        joint_names: its joints, without the prefix.
    """

    name: str
    prefix: str
    hardware_path: Path
    joint_names: tuple[str, ...]


_BOARD_KEYS = {"port", "baud", "robots"}


def load_board_calibration(path: str | Path, robots: Sequence[RobotOnBoard],
                           ) -> ServoCalibration:
    """One calibration for several robots driven by one servo board (a cell's
    ``<cell>.hardware.yaml``), e.g. both arms of ``servo_arm_pair`` on one PCA9685::

        port: /dev/ttyUSB0
        robots:
          left: {channels: [0, 1, 2, 3, 4, 5]}     # the robot's servos, in its own order
          right: {channels: [8, 9, 10, 11, 12, 13]}

    Each robot keeps its own ``hardware.yaml`` (zero_rad, direction, scale); the board file
    gives where its servos are wired on this board. Joint names get the robot's prefix;
    the servo order (``MOVE``/``TRAJ``) is the robots' order in the board file.

    Raises:
        YamlError: unreadable file, unknown key or robot, a robot missing, a wrong number
            of channels, a channel outside 0..15 or used twice (``file:line``).
    """
    path = Path(path)
    data, port, baud = _read_link_file(path, "robots", dict, _BOARD_KEYS)
    by_name = {r.name: r for r in robots}
    node = data["robots"]
    for name in node:
        if name not in by_name:
            raise _fail(f"unknown robot {name!r}; the cell's robots: {list(by_name)}", path,
                        node, name)
    missing = [r.name for r in robots if r.name not in node]
    if missing:
        raise _fail(f"robots {missing} have no channels on this board", path, data, "robots")
    joints: list[JointCalibration] = []
    used: dict[int, str] = {}
    for name, entry in node.items():
        robot = by_name[name]
        own = load_calibration(robot.hardware_path, robot.joint_names)
        channels = entry.get("channels") if isinstance(entry, dict) else None
        if (not isinstance(channels, list) or len(channels) != len(own.servo_joint_names)
                or not all(isinstance(c, int) and not isinstance(c, bool) and 0 <= c <= 15
                           for c in channels)):
            raise _fail(f"'channels' of robot {name!r} must list {len(own.servo_joint_names)} "
                        f"channels 0..15, one per servo {list(own.servo_joint_names)} (got "
                        f"{channels!r})", path, node, name)
        wiring = dict(zip(own.servo_joint_names, channels))
        for joint in own.joints:
            renamed = robot.prefix + joint.name
            if joint.same_servo_as is not None:
                joints.append(JointCalibration(name=renamed,
                                               same_servo_as=robot.prefix + joint.same_servo_as))
                continue
            channel = wiring[joint.name]
            if channel in used:
                raise _fail(f"channel {channel} of joint {renamed!r} is also {used[channel]!r}'s",
                            path, node, name)
            used[channel] = renamed
            joints.append(JointCalibration(renamed, joint.servo_type, channel, joint.zero_rad,
                                           joint.direction, joint.scale))
    return ServoCalibration(tuple(joints), port, int(baud), path)


def _read_link_file(path: Path, body: str, kind: type, keys: frozenset[str] | set[str]
                    ) -> tuple[dict[str, Any], str, int]:
    """A hardware or board file's mapping, its ``port`` and its ``baud``, checked: a
    mapping whose ``body`` key holds a ``kind`` (list or mapping), no unknown key.

    Raises:
        YamlError: unreadable or invalid YAML, or a bad field (``file:line``).
    """
    data = load_yaml(path)
    if not isinstance(data, dict) or not isinstance(data.get(body), kind):
        what = "list" if kind is list else "mapping"
        raise YamlError(f"expected a mapping with a '{body}' {what}", path, line_of(data))
    unknown = sorted(set(data) - set(keys))
    if unknown:
        raise _fail(f"unknown key {unknown[0]!r}; keys: {sorted(keys)}", path, data,
                    unknown[0])
    port, baud = data.get("port", ""), data.get("baud", 115200)
    if not isinstance(port, str):
        raise _fail(f"'port' must be a string (got {port!r})", path, data, "port")
    if isinstance(baud, bool) or not isinstance(baud, int) or baud <= 0:
        raise _fail(f"'baud' must be a positive integer (got {baud!r})", path, data, "baud")
    return data, port, baud
