"""LeRobot's calibration file and its tick conversions.

The expected values of the table below are worked out by hand from LeRobot's
``MotorsBus._normalize`` / ``_unnormalize`` (modes DEGREES and RANGE_0_100), not from our
code: mid = (min + max) / 2, degrees = (ticks - mid) * 360 / 4095,
ticks = int(degrees * 4095 / 360 + mid), percent = (ticks - min) / (max - min) * 100.
The fixture file is made up in the format LeRobot writes (4-space JSON, no final newline).
"""

from __future__ import annotations

import math
from pathlib import Path

import pytest

from taskrunner.backends.feetech.calibration import (
    SO101_MOTORS,
    LeRobotCalibration,
    MotorCalibration,
    degrees_to_ticks,
    load_lerobot_calibration,
    percent_to_ticks,
    ticks_to_degrees,
    ticks_to_percent,
    write_lerobot_calibration,
)
from taskrunner.errors import InputError

FIXTURE = Path(__file__).parent / "fixtures" / "so101_lerobot_calibration.json"
PAN = MotorCalibration(id=1, drive_mode=0, homing_offset=-1470, range_min=758, range_max=3292)
GRIP = MotorCalibration(id=6, drive_mode=0, homing_offset=1372, range_min=2031, range_max=3476)
GRIP_REVERSED = MotorCalibration(id=6, drive_mode=1, homing_offset=0, range_min=2031,
                                 range_max=3476)


def test_the_file_round_trips_unchanged(tmp_path: Path) -> None:
    entries = load_lerobot_calibration(FIXTURE)
    assert list(entries) == ["shoulder_pan", "shoulder_lift", "elbow_flex", "wrist_flex",
                             "wrist_roll", "gripper"]
    assert entries["shoulder_pan"] == PAN
    copy = tmp_path / "follower.json"
    write_lerobot_calibration(copy, entries)
    assert copy.read_bytes() == FIXTURE.read_bytes()


@pytest.mark.parametrize(("ticks", "degrees"), [
    (2025, 0.0),                      # mid = (758 + 3292) / 2
    (3292, 1267 * 360 / 4095),        # 111.3846…
    (758, -1267 * 360 / 4095),
    (2048, 23 * 360 / 4095),          # 2.0220…
    (4000, 1975 * 360 / 4095),        # beyond the range: DEGREES does not clamp
])
def test_ticks_to_degrees_as_lerobot(ticks: int, degrees: float) -> None:
    assert ticks_to_degrees(ticks, PAN) == pytest.approx(degrees, abs=1e-12)


@pytest.mark.parametrize(("degrees", "ticks"), [
    (0.0, 2025), (90.0, 3048),        # int(1023.75 + 2025)
    (-45.0, 1513),                    # int(-511.875 + 2025) = int(1513.125)
    (0.05, 2025),                     # int(2025.57): truncated, as LeRobot does
])
def test_degrees_to_ticks_as_lerobot(degrees: float, ticks: int) -> None:
    assert degrees_to_ticks(degrees, PAN) == ticks


@pytest.mark.parametrize(("cal", "ticks", "percent"), [
    (GRIP, 2031, 0.0), (GRIP, 3476, 100.0), (GRIP, 2753.5, 50.0),
    (GRIP, 1500, 0.0),                # clamped to the range
    (GRIP_REVERSED, 2031, 100.0), (GRIP_REVERSED, 3476, 0.0),
])
def test_gripper_percent_as_lerobot(cal: MotorCalibration, ticks: float, percent: float) -> None:
    assert ticks_to_percent(ticks, cal) == pytest.approx(percent, abs=1e-12)


@pytest.mark.parametrize(("cal", "percent", "ticks"), [
    (GRIP, 50.0, 2753),               # int(722.5 + 2031)
    (GRIP, 120.0, 3476),              # clamped
    (GRIP_REVERSED, 25.0, 3114),      # 100 - 25 = 75: int(1083.75 + 2031)
])
def test_percent_to_ticks_as_lerobot(cal: MotorCalibration, percent: float, ticks: int) -> None:
    assert percent_to_ticks(percent, cal) == ticks


def test_joint_positions_are_lerobot_degrees_in_radians_and_gripper_percent() -> None:
    arm = LeRobotCalibration(SO101_MOTORS, load_lerobot_calibration(FIXTURE))
    assert arm.to_radians("shoulder_pan", 3048) == pytest.approx(
        math.radians(1023 * 360 / 4095))
    assert arm.to_ticks("shoulder_pan", math.radians(90.0)) == 3048
    # gripper: 50 % is halfway between the URDF limits -0.174533 and 1.74533 rad
    assert arm.to_radians("gripper", 2753.5) == pytest.approx(0.7853985, abs=1e-7)
    assert arm.to_ticks("gripper", 0.7853985) == 2753
    low, high = arm.range_radians("shoulder_pan")
    assert (low, high) == pytest.approx((-math.radians(1267 * 360 / 4095),
                                         math.radians(1267 * 360 / 4095)))


def test_bad_files_name_the_motor_and_field(tmp_path: Path) -> None:
    bad = tmp_path / "bad.json"
    bad.write_text('{"shoulder_pan": {"id": 1, "drive_mode": 0, "homing_offset": "x", '
                   '"range_min": 0, "range_max": 4095}}')
    with pytest.raises(InputError, match=r"motor 'shoulder_pan': 'homing_offset' must be an "
                                         r"integer \(got 'x'\)"):
        load_lerobot_calibration(bad)
    bad.write_text('{"gripper": {"id": 6, "drive_mode": 0, "range_min": 0, "range_max": 1,'
                   ' "offset": 3}}')
    with pytest.raises(InputError, match=r"unknown field\(s\) \['offset'\]; missing field\(s\) "
                                         r"\['homing_offset'\]"):
        load_lerobot_calibration(bad)
    bad.write_text('{\n  "gripper": {\n  "id": 6,,\n}')
    with pytest.raises(InputError, match=r"bad\.json:3: not JSON"):
        load_lerobot_calibration(bad)
    entries = load_lerobot_calibration(FIXTURE)
    entries["elbow_flex"] = MotorCalibration(4, 0, 0, 100, 3000)
    with pytest.raises(InputError, match=r"motor 'elbow_flex': 'id' must be 3 \(got 4\)"):
        LeRobotCalibration(SO101_MOTORS, entries)
