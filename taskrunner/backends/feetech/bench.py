"""Bench helpers for an arm of Feetech servos: status, jog, torque, LeRobot's calibration.

:func:`calibrate_arm` follows LeRobot's SO-101 procedure, so the file it writes works
with both tools: torque off; the builder puts every joint in the middle of its range;
each servo's Homing_Offset is set so that this position reads 2047 (half a turn); the
builder then moves every joint through its whole range while the positions are read, and
the extremes become ``range_min`` / ``range_max`` (``wrist_roll`` turns all the way:
0-4095); the offsets and limits are written into the servos and the JSON file.
"""

from __future__ import annotations

import math
import shutil
from collections.abc import Callable, Sequence
from pathlib import Path

from taskrunner.backends.feetech.bus import ServoBus
from taskrunner.backends.feetech.calibration import (
    MAX_TICK,
    LeRobotCalibration,
    Motor,
    MotorCalibration,
    write_lerobot_calibration,
)
from taskrunner.errors import InputError, TrajectoryRejectedError

__all__ = ["FULL_TURN_JOINTS", "calibrate_arm", "jog_joint", "set_torque", "status_lines"]

FULL_TURN_JOINTS = ("wrist_roll",)  # LeRobot gives these the whole turn as their range
HALF_TURN = MAX_TICK // 2  # 2047: where the middle of a range reads after homing


def status_lines(bus: ServoBus, motors: Sequence[Motor],
                 calibration: LeRobotCalibration | None = None) -> list[str]:
    """One line per servo: ID, model, present position (and the joint's angle when
    calibrated), load, voltage, temperature, torque, status flags."""
    states = bus.read_states([m.servo_id for m in motors])
    lines = []
    for motor in motors:
        state = states[motor.servo_id]
        torque = bus.read(motor.servo_id, "Torque_Enable")
        where = f"{state.position:4d} ticks"
        if calibration is not None:
            q = calibration.to_radians(motor.joint, state.position)
            where += f" = {q:+.4f} rad ({math.degrees(q):+.1f}°)"
        flags = ", ".join(state.flags) or "ok"
        lines.append(f"{motor.joint:<14} id {motor.servo_id}: {where}, load "
                     f"{100 * state.load:+.0f} %, {state.voltage:.1f} V, "
                     f"{state.temperature} °C, torque {'on' if torque else 'off'}, {flags}")
    return lines


def set_torque(bus: ServoBus, motors: Sequence[Motor], enabled: bool) -> None:
    """Torque on or off on every motor, each acknowledged (so a silent servo is an error)."""
    for motor in motors:
        bus.write(motor.servo_id, "Torque_Enable", 1 if enabled else 0)


def jog_joint(bus: ServoBus, calibration: LeRobotCalibration, joint: str,
              degrees: float) -> tuple[float, int]:
    """Move one joint ``degrees`` from where it is (torque on); returns the goal (rad,
    ticks).

    Raises:
        UnknownNameError: not a joint of the arm.
        TrajectoryRejectedError: the goal leaves the joint's calibrated range.
    """
    motor = calibration.motor(joint)
    present = bus.read(motor.servo_id, "Present_Position")
    goal_q = calibration.to_radians(joint, present) + math.radians(degrees)
    low, high = calibration.range_radians(joint)
    if not low <= goal_q <= high:
        raise TrajectoryRejectedError(
            f"jog of {joint!r} by {degrees:+.1f}° must stay within its calibrated range "
            f"[{low:.4f}, {high:.4f}] rad (got {goal_q:.4f})")
    goal = calibration.to_ticks(joint, goal_q)
    bus.write(motor.servo_id, "Goal_Position", goal)
    bus.write(motor.servo_id, "Torque_Enable", 1)
    return goal_q, goal


def calibrate_arm(bus: ServoBus, motors: Sequence[Motor], path: str | Path,
                  wait_enter: Callable[[str], object], range_done: Callable[[], bool],
                  say: Callable[[str], None] = print) -> dict[str, MotorCalibration]:
    """LeRobot's calibration of an arm (see the module); writes ``path`` (an existing file
    is kept as ``<path>.bak``) and the servos' EEPROM.

    Args:
        bus: the arm's bus.
        motors: its joints and servos.
        path: the calibration file to write.
        wait_enter: shows a prompt and returns when the builder is ready.
        range_done: True once the builder has moved every joint through its range; called
            between two reads of the positions.
        say: where the progress lines go.

    Raises:
        BusFaultError: a servo does not answer.
        InputError: a joint (not a full-turn one) that did not move during the range step.
    """
    ids = [m.servo_id for m in motors]
    for motor in motors:
        bus.write(motor.servo_id, "Torque_Enable", 0)
        bus.write(motor.servo_id, "Lock", 0)  # EEPROM writable
    wait_enter("Move the arm to the middle of its range of motion, then press Enter... ")
    for motor in motors:  # LeRobot's reset_calibration: raw positions over the whole turn
        bus.write(motor.servo_id, "Homing_Offset", 0)
        bus.write(motor.servo_id, "Min_Position_Limit", 0)
        bus.write(motor.servo_id, "Max_Position_Limit", MAX_TICK)
    raw = {i: s.position for i, s in bus.read_states(ids).items()}
    offsets = {i: raw[i] - HALF_TURN for i in ids}  # Present = Actual − Homing_Offset
    for motor in motors:
        bus.write(motor.servo_id, "Homing_Offset", offsets[motor.servo_id])
    say("Move every joint (but wrist_roll) through its whole range of motion; "
        "press Enter when done.")
    states = bus.read_states(ids)
    lows = {i: s.position for i, s in states.items()}
    highs = dict(lows)
    while True:
        finished = range_done()
        for i, state in bus.read_states(ids).items():
            lows[i], highs[i] = min(lows[i], state.position), max(highs[i], state.position)
        if finished:
            break
    entries = {}
    for motor in motors:
        i = motor.servo_id
        if motor.joint in FULL_TURN_JOINTS:
            lows[i], highs[i] = 0, MAX_TICK
        if highs[i] <= lows[i]:
            raise InputError(f"joint {motor.joint!r} (servo {i}) did not move during the range "
                             f"step (stayed at {lows[i]} ticks): nothing was written")
        entries[motor.joint] = MotorCalibration(id=i, drive_mode=0, homing_offset=offsets[i],
                                                range_min=lows[i], range_max=highs[i])
    for motor in motors:
        cal = entries[motor.joint]
        bus.write(motor.servo_id, "Min_Position_Limit", cal.range_min)
        bus.write(motor.servo_id, "Max_Position_Limit", cal.range_max)
    path = Path(path)
    if path.is_file():
        shutil.copyfile(path, path.with_suffix(path.suffix + ".bak"))
    path.parent.mkdir(parents=True, exist_ok=True)
    write_lerobot_calibration(path, entries)
    for name, cal in entries.items():
        say(f"  {name:<14} id {cal.id}: homing_offset {cal.homing_offset:+5d}, "
            f"range {cal.range_min}-{cal.range_max}")
    say(f"wrote {path}")
    return entries
