"""LeRobot's motor calibration file, and ticks ↔ joint positions as LeRobot converts them.

The file (``~/.cache/huggingface/lerobot/calibration/robots/so101_follower/<id>.json``)
is a JSON object with one entry per motor name::

    {"shoulder_pan": {"id": 1, "drive_mode": 0, "homing_offset": -1470,
                      "range_min": 758, "range_max": 3292}, ...}

``homing_offset`` is written into the servo (Present_Position = actual − offset, so the
middle of the range reads about 2047); ``range_min`` / ``range_max`` are the present
positions at the ends of the joint's travel. LeRobot's conversion (``MotorsBus._normalize``
and ``_unnormalize``, mode ``DEGREES`` for the arm, ``RANGE_0_100`` for the gripper):

- degrees = (ticks − mid) · 360 / 4095, mid = (range_min + range_max) / 2 (drive_mode is not
  applied in this mode); ticks = int(degrees · 4095 / 360 + mid);
- percent = (clamp(ticks) − range_min) / (range_max − range_min) · 100, or 100 − that when
  drive_mode is 1; ticks = int(clamp(percent) / 100 · (range_max − range_min) + range_min).

Here a body joint's position in radians is LeRobot's degrees in radians (the upstream
``so101_new_calib`` URDF has its zeros at the middle of each range), and the gripper's
0-100 % maps linearly onto the URDF joint's [lower, upper] (0 % closed at ``lower``).
"""

from __future__ import annotations

import json
import math
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

from taskrunner.errors import ArgumentError, InputError, UnknownNameError

__all__ = ["SO101_MOTORS", "MAX_TICK", "LeRobotCalibration", "Motor", "MotorCalibration",
           "degrees_to_ticks", "load_lerobot_calibration", "percent_to_ticks",
           "ticks_to_degrees", "ticks_to_percent", "write_lerobot_calibration"]

MAX_TICK = 4095  # LeRobot's max_res for the STS3215 (resolution 4096 − 1)
_FIELDS = ("id", "drive_mode", "homing_offset", "range_min", "range_max")


@dataclass(frozen=True)
class MotorCalibration:
    """One motor's entry of LeRobot's calibration file (ticks)."""

    id: int
    drive_mode: int
    homing_offset: int
    range_min: int
    range_max: int

    def as_dict(self) -> dict[str, int]:
        return {name: getattr(self, name) for name in _FIELDS}


@dataclass(frozen=True)
class Motor:
    """A joint driven by one bus servo.

    Attributes:
        joint: the robot model's joint name.
        servo_id: bus ID.
        mode: ``"degrees"`` (a body joint) or ``"percent"`` (the gripper, 0-100 %).
        lower: for ``"percent"``: the joint position (rad) at 0 %.
        upper: for ``"percent"``: the joint position (rad) at 100 %.
    """

    joint: str
    servo_id: int
    mode: Literal["degrees", "percent"] = "degrees"
    lower: float = 0.0
    upper: float = 0.0

    def __post_init__(self) -> None:
        if self.mode not in ("degrees", "percent"):
            raise ArgumentError(f"'mode' must be 'degrees' or 'percent' (got {self.mode!r})")
        if self.mode == "percent" and not self.upper > self.lower:
            raise ArgumentError(f"'upper' must be above 'lower' for joint {self.joint!r} "
                             f"(got {self.lower}, {self.upper})")


SO101_MOTORS = (
    Motor("shoulder_pan", 1), Motor("shoulder_lift", 2), Motor("elbow_flex", 3),
    Motor("wrist_flex", 4), Motor("wrist_roll", 5),
    # the upstream so101_new_calib URDF's gripper limits
    Motor("gripper", 6, "percent", lower=-0.174533, upper=1.74533),
)
"""The SO-101 as LeRobot wires it: IDs 1-6, the gripper in percent."""


def ticks_to_degrees(ticks: float, cal: MotorCalibration) -> float:
    """LeRobot's ``DEGREES`` normalisation (no clamp, drive_mode not applied)."""
    mid = (cal.range_min + cal.range_max) / 2
    return (ticks - mid) * 360 / MAX_TICK


def degrees_to_ticks(degrees: float, cal: MotorCalibration) -> int:
    """LeRobot's ``DEGREES`` unnormalisation (``int``: truncated toward zero)."""
    mid = (cal.range_min + cal.range_max) / 2
    return int((degrees * MAX_TICK / 360) + mid)


def ticks_to_percent(ticks: float, cal: MotorCalibration) -> float:
    """LeRobot's ``RANGE_0_100`` normalisation (clamped to the range)."""
    bounded = min(cal.range_max, max(cal.range_min, ticks))
    norm = (bounded - cal.range_min) / (cal.range_max - cal.range_min) * 100
    return 100 - norm if cal.drive_mode else norm


def percent_to_ticks(percent: float, cal: MotorCalibration) -> int:
    """LeRobot's ``RANGE_0_100`` unnormalisation."""
    value = 100 - percent if cal.drive_mode else percent
    bounded = min(100.0, max(0.0, value))
    return int((bounded / 100) * (cal.range_max - cal.range_min) + cal.range_min)


class LeRobotCalibration:
    """A LeRobot calibration applied to the motors of an arm: joint positions ↔ ticks.

    Args:
        motors: the joints and their servos.
        calibration: LeRobot's entries by motor name (the joint's name).
        path: the file it came from (for messages), if any.

    Raises:
        InputError: a motor without an entry, an ID that differs from the entry's, or a
            range that is empty.
    """

    def __init__(self, motors: tuple[Motor, ...] | list[Motor],
                 calibration: Mapping[str, MotorCalibration], path: Path | None = None) -> None:
        where = f"{path}: " if path is not None else ""
        for motor in motors:
            cal = calibration.get(motor.joint)
            if cal is None:
                raise InputError(f"{where}no calibration for motor {motor.joint!r} "
                                 f"(entries: {', '.join(calibration) or 'none'})")
            if cal.id != motor.servo_id:
                raise InputError(f"{where}motor {motor.joint!r}: 'id' must be "
                                 f"{motor.servo_id} (got {cal.id})")
            if cal.range_max <= cal.range_min:
                raise InputError(f"{where}motor {motor.joint!r}: 'range_max' must be above "
                                 f"'range_min' (got {cal.range_min}, {cal.range_max}); "
                                 "calibrate again")
        self.motors = tuple(motors)
        self.entries = dict(calibration)
        self.path = path
        self._by_joint = {m.joint: m for m in self.motors}

    @property
    def joint_names(self) -> tuple[str, ...]:
        return tuple(m.joint for m in self.motors)

    def motor(self, joint: str) -> Motor:
        motor = self._by_joint.get(joint)
        if motor is None:
            raise UnknownNameError("joint", joint, self.joint_names)
        return motor

    def to_radians(self, joint: str, ticks: float) -> float:
        """The joint position (rad) of a present position (ticks)."""
        motor, cal = self.motor(joint), self.entries[joint]
        if motor.mode == "percent":
            return motor.lower + ticks_to_percent(ticks, cal) / 100 * (motor.upper - motor.lower)
        return math.radians(ticks_to_degrees(ticks, cal))

    def to_ticks(self, joint: str, q: float) -> int:
        """The goal position (ticks) of a joint position (rad)."""
        motor, cal = self.motor(joint), self.entries[joint]
        if motor.mode == "percent":
            return percent_to_ticks((q - motor.lower) / (motor.upper - motor.lower) * 100, cal)
        return degrees_to_ticks(math.degrees(q), cal)

    def range_radians(self, joint: str) -> tuple[float, float]:
        """The calibrated travel of a joint, rad (low, high)."""
        cal = self.entries[joint]
        ends = sorted((self.to_radians(joint, cal.range_min), self.to_radians(joint, cal.range_max)))
        return ends[0], ends[1]


def load_lerobot_calibration(path: str | Path) -> dict[str, MotorCalibration]:
    """Read LeRobot's calibration file, in the file's order of motors.

    Raises:
        InputError: not readable, not JSON (with line), not an object of motors, or a motor
            entry with a missing, unknown or non-integer field (names motor and field).
    """
    path = Path(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise InputError(f"cannot read the calibration file {path}: {exc.strerror}") from None
    try:
        data = json.loads(text)
    except json.JSONDecodeError as exc:
        raise InputError(f"{path}:{exc.lineno}: not JSON ({exc.msg})") from None
    if not isinstance(data, dict):
        raise InputError(f"{path}: must be a JSON object of motors (got {type(data).__name__})")
    entries = {}
    for name, entry in data.items():
        if not isinstance(entry, dict):
            raise InputError(f"{path}: motor {name!r} must be an object with "
                             f"{', '.join(_FIELDS)} (got {entry!r})")
        unknown = sorted(set(entry) - set(_FIELDS))
        missing = [f for f in _FIELDS if f not in entry]
        if unknown or missing:
            raise InputError(f"{path}: motor {name!r}: "
                             + (f"unknown field(s) {unknown}" if unknown else "")
                             + ("; " if unknown and missing else "")
                             + (f"missing field(s) {missing}" if missing else ""))
        for field_name in _FIELDS:
            value = entry[field_name]
            if not isinstance(value, int) or isinstance(value, bool):
                raise InputError(f"{path}: motor {name!r}: '{field_name}' must be an integer "
                                 f"(got {value!r})")
        entries[str(name)] = MotorCalibration(**{f: entry[f] for f in _FIELDS})
    return entries


def write_lerobot_calibration(path: str | Path, entries: Mapping[str, MotorCalibration]) -> str:
    """Write the file as LeRobot does (JSON, 4-space indent, fields in LeRobot's order, no
    final newline); returns the text."""
    text = json.dumps({name: cal.as_dict() for name, cal in entries.items()}, indent=4)
    Path(path).write_text(text, encoding="utf-8")
    return text
