"""run-task hw … --robot so101 and run-task bus-sim, against the bus emulator."""

from __future__ import annotations

import json
import math
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import pytest

from taskrunner.backends.feetech import (
    SO101_MOTORS,
    BusEmulator,
    FeetechBus,
    LeRobotCalibration,
    load_lerobot_calibration,
    so101_servos,
)
from taskrunner.backends.feetech.commands import run_hw
from taskrunner.cli import main
from taskrunner.errors import BusFaultError, InputError

FIXTURE = Path(__file__).parent / "fixtures" / "so101_lerobot_calibration.json"


@pytest.fixture
def emulator() -> Iterator[BusEmulator]:
    with BusEmulator(so101_servos(seed=2)) as emu:
        yield emu


def _place(emulator: BusEmulator, shift: dict[int, float]) -> None:
    """Move the limp joints by hand: each servo's output to its start + shift (ticks)."""
    with emulator._lock:  # the emulator's thread reads the models under it
        for i, ticks in shift.items():
            servo = emulator.servos[i]
            servo.actual = servo.motor = ticks


def test_calibrate_writes_lerobots_file_and_the_servos_eeprom(emulator: BusEmulator,
                                                              tmp_path: Path) -> None:
    middle = {i: s.actual for i, s in emulator.servos.items()}  # where the builder left it
    moves = iter([{i: middle[i] - 900 for i in middle if i != 5},
                  {i: middle[i] + 1000 for i in middle if i != 5}])

    def range_done() -> bool:
        step = next(moves, None)
        if step is not None:
            _place(emulator, step)
        return step is None

    path = tmp_path / "follower.json"
    lines: list[str] = []
    assert run_hw("calibrate", emulator.port, "so101", str(path), ask=lambda prompt: "",
                  range_done=range_done, say=lines.append) == 0
    data = json.loads(path.read_text())
    assert list(data) == [m.joint for m in SO101_MOTORS]
    for motor in SO101_MOTORS:
        entry, i = data[motor.joint], motor.servo_id
        offset = int(middle[i]) - 2047  # the middle then reads 2047 (Present = Actual - Offset)
        expected = (0, 4095) if motor.joint == "wrist_roll" else (2047 - 900, 2047 + 1000)
        assert entry == {"id": i, "drive_mode": 0, "homing_offset": offset,
                         "range_min": expected[0], "range_max": expected[1]}
        servo = emulator.servos[i]
        assert servo.get("Homing_Offset") == offset
        assert (servo.get("Min_Position_Limit"), servo.get("Max_Position_Limit")) == expected
    arm = LeRobotCalibration(SO101_MOTORS, load_lerobot_calibration(path))
    mid = (2047 - 900 + 2047 + 1000) / 2  # LeRobot's zero: the middle of the range
    assert arm.to_radians("elbow_flex", mid) == 0.0
    assert arm.to_radians("elbow_flex", mid + 50) == pytest.approx(math.radians(50 * 360 / 4095))
    assert lines[-1] == f"wrote {path}"


def test_calibrate_refuses_a_joint_that_did_not_move(emulator: BusEmulator,
                                                     tmp_path: Path) -> None:
    with pytest.raises(InputError, match=r"joint 'shoulder_pan' \(servo 1\) did not move"):
        run_hw("calibrate", emulator.port, "so101", str(tmp_path / "c.json"),
               ask=lambda prompt: "", range_done=lambda: True, say=lambda line: None)
    assert not (tmp_path / "c.json").exists()


def test_status_jog_and_torque_off_from_the_command_line(
        emulator: BusEmulator, capsys: pytest.CaptureFixture[str]) -> None:
    port = ["--robot", "so101", "--port", emulator.port, "--calibration", str(FIXTURE)]
    assert main(["hw", "jog", "elbow_flex", "5", *port]) == 0
    arm = LeRobotCalibration(SO101_MOTORS, load_lerobot_calibration(FIXTURE))
    elbow = emulator.servos[3]
    assert elbow.get("Torque_Enable") == 1
    out = capsys.readouterr().out
    assert "jog 'elbow_flex' +5.0°" in out and "elbow_flex     id 3:" in out
    goal_q = float(out.split("→ ")[1].split(" rad")[0])
    assert elbow.get("Goal_Position") == arm.to_ticks("elbow_flex", goal_q)

    assert main(["hw", "torque", "off", *port]) == 0
    assert all(s.get("Torque_Enable") == 0 for s in emulator.servos.values())
    assert "torque off on servos 1, 2, 3, 4, 5, 6" in capsys.readouterr().out
    assert main(["hw", "status", *port]) == 0
    status = capsys.readouterr().out
    assert status.count("torque off") == 6 and "gripper        id 6:" in status

    assert main(["hw", "jog", "elbow_flex", *port]) == 2  # no DEGREES: a usage error
    assert "jog needs JOINT and DEGREES" in capsys.readouterr().err


def test_bus_sim_serves_a_pty_and_takes_fault_commands() -> None:
    process = subprocess.Popen([sys.executable, "-m", "taskrunner.cli", "bus-sim"],
                               stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    try:
        assert process.stdout is not None and process.stdin is not None
        port = process.stdout.readline().strip()
        assert port.startswith("/dev/")
        process.stdout.readline()  # the commands line
        bus = FeetechBus(port, reply_timeout=0.5)
        assert [bus.ping(i) for i in range(1, 7)] == [777] * 6
        process.stdin.write("inject drop 2\n")
        process.stdin.flush()
        assert process.stdout.readline().strip() == "ok inject drop 2"
        with pytest.raises(BusFaultError) as caught:
            bus.ping(2)
        assert caught.value.kind == "no_reply"
        bus.close()
        process.stdin.close()
        assert process.wait(10) == 0
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
