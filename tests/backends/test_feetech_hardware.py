"""A cell's Feetech hardware file, the overrides from the command line, and the feetech
backend kind: what is read, and every mistake named with its file (and line)."""

from __future__ import annotations

import json
import time
from pathlib import Path

import pytest

from taskrunner.backends.feetech import BusEmulator, FeetechBackend, so101_servos
from taskrunner.backends.feetech.hardware import (
    CellRobot,
    load_feetech_hardware,
    parse_overrides,
)
from taskrunner.errors import ArgumentError, InputError, YamlError
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.session import make_backend

CELLS = DATA_ROOT / "robots" / "cells"
FIXTURE = Path(__file__).parent / "fixtures" / "so101_lerobot_calibration.json"
PAIR = [CellRobot("left", "left_"), CellRobot("right", "right_")]


def test_the_shipped_hardware_files_name_buses_ids_and_calibrations() -> None:
    table = load_feetech_hardware(CELLS / "so101_table.hardware.yaml", [CellRobot("arm")])
    assert [(b.name, b.port, b.baud) for b in table.buses] == [("arm", "/dev/ttyACM0", 1_000_000)]
    (arm,) = table.arms
    assert [(m.joint, m.servo_id) for m in arm.motors][:2] == [("shoulder_pan", 1),
                                                               ("shoulder_lift", 2)]
    assert arm.calibration.name == "so101.json" and "~" not in str(arm.calibration)
    two = load_feetech_hardware(CELLS / "so101_pair.hardware.yaml", PAIR)
    assert {a.robot: a.bus for a in two.arms} == {"left": "left", "right": "right"}
    one = load_feetech_hardware(CELLS / "so101_pair.one_bus.hardware.yaml", PAIR)
    right = next(a for a in one.arms if a.robot == "right")
    assert right.bus == "both" and [m.servo_id for m in right.motors] == list(range(7, 13))
    assert right.motors[-1].joint == "right_gripper" and right.motors[-1].mode == "percent"


@pytest.mark.parametrize(("text", "line", "message"), [
    ("buses: {a: {port: /dev/x}}\nrobots: {arm: {bus: a, calibration: c.json}}\n", 1,
     "'protocol' must be 'feetech'"),
    ("protocol: feetech\nbuses: {a: {port: /dev/x}}\nrobots:\n  arm: {bus: b, calibration: c.json}\n",
     4, "robot 'arm': 'bus' must be one of ['a'] (got 'b')"),
    ("protocol: feetech\nbuses: {a: {port: /dev/x}}\nrobots:\n  hand: {bus: a, calibration: c.json}\n",
     4, "unknown robot 'hand'"),
    ("protocol: feetech\nbuses: {a: {port: /dev/x}}\nrobots:\n  arm:\n    bus: a\n"
     "    ids: [1, 2, 3]\n    calibration: c.json\n", 6, "'ids' must list 6 distinct IDs"),
    ("protocol: feetech\nbuses:\n  a: {port: /dev/x, reply_timeout: 5}\n"
     "robots: {arm: {bus: a, calibration: c.json}}\n", 3, "'reply_timeout' must be in (0, 1]"),
    ("protocol: feetech\non_fault: drop\nbuses: {a: {port: /dev/x}}\n"
     "robots: {arm: {bus: a, calibration: c.json}}\n", 2,
     "'on_fault' must be 'hold' or 'torque_off' (got 'drop')"),
    ("protocol: feetech\nbuses: {a: {port: /dev/x, speed: 3}}\n"
     "robots: {arm: {bus: a, calibration: c.json}}\n", 2, "unknown key 'speed'"),
])
def test_a_bad_hardware_file_is_named_with_its_line(tmp_path: Path, text: str, line: int,
                                                     message: str) -> None:
    path = tmp_path / "cell.hardware.yaml"
    path.write_text(text)
    with pytest.raises(YamlError) as caught:
        load_feetech_hardware(path, [CellRobot("arm")])
    assert str(caught.value).startswith(f"{path}:{line}:") and message in str(caught.value)


def test_two_arms_cannot_share_an_id_on_one_bus(tmp_path: Path) -> None:
    path = tmp_path / "pair.hardware.yaml"
    path.write_text("protocol: feetech\nbuses: {both: {port: /dev/x}}\nrobots:\n"
                    "  left: {bus: both, calibration: l.json}\n"
                    "  right: {bus: both, calibration: r.json}\n")
    with pytest.raises(YamlError, match=r"pair.hardware.yaml:5: robot 'right': ID 1 on bus "
                                        r"'both' is also 'left.shoulder_pan''s"):
        load_feetech_hardware(path, PAIR)


def test_port_and_calibration_overrides() -> None:
    assert parse_overrides("/dev/ttyACM3", ["arm"], "port") == {"arm": "/dev/ttyACM3"}
    assert parse_overrides("left=/dev/a, right=/dev/b", ["left", "right"], "port") == {
        "left": "/dev/a", "right": "/dev/b"}
    assert parse_overrides(None, ["arm"], "calibration") == {}
    with pytest.raises(ArgumentError, match=r"'port' must be NAME=PATH pairs, one per bus"):
        parse_overrides("/dev/a", ["left", "right"], "port")
    with pytest.raises(ArgumentError, match=r"NAME one of \['left', 'right'\] \(got 'up=x'\)"):
        parse_overrides("up=x", ["left", "right"], "calibration")


def _table_hardware(tmp_path: Path, port: str, calibration: str) -> Path:
    path = tmp_path / "table.hardware.yaml"
    path.write_text(f"protocol: feetech\nbuses:\n  arm: {{port: {port}}}\nrobots:\n"
                    f"  arm:\n    bus: arm\n    calibration: {calibration}\n")
    return path


def test_a_missing_calibration_file_is_named_with_the_line_that_names_it(tmp_path: Path) -> None:
    cell = load_cell(CELLS / "so101_table.yaml")
    hardware = _table_hardware(tmp_path, "/dev/null", "nowhere/arm.json")
    with pytest.raises(InputError) as caught:
        make_backend("feetech", cell, None, hardware=hardware)
    text = str(caught.value)
    assert text.startswith(f"{tmp_path / 'nowhere' / 'arm.json'}:")
    assert f"named by {hardware}:7" in text and "run-task hw calibrate --robot so101" in text
    # --calibration names another file: that one is read, and named when it is bad
    bad = tmp_path / "bad.json"
    entries = json.loads(FIXTURE.read_text())
    entries["elbow_flex"]["id"] = 9
    bad.write_text(json.dumps(entries))
    with pytest.raises(InputError, match=r"bad.json: robot 'arm': motor 'elbow_flex': 'id' must "
                                         r"be 3 \(got 9\)"):
        make_backend("feetech", cell, None, hardware=hardware, calibration_file=str(bad))


def test_a_cell_without_a_hardware_file_says_which_file_it_looked_for() -> None:
    cell = load_cell(CELLS / "servo_arm_table.yaml")
    with pytest.raises(InputError, match=r"servo_arm_table.hardware.yaml does not exist"):
        make_backend("feetech", cell, None)


def test_servos_whose_homing_offset_is_not_the_calibrations_are_refused(tmp_path: Path) -> None:
    cell = load_cell(CELLS / "so101_table.yaml")
    with BusEmulator(so101_servos()) as emulator:  # never calibrated: offsets 0
        hardware = _table_hardware(tmp_path, emulator.port, str(FIXTURE))
        with pytest.raises(InputError) as caught:
            make_backend("feetech", cell, None, hardware=hardware)
    assert str(caught.value).startswith(f"{FIXTURE}:")
    assert ("joint 'shoulder_pan': servo 1 on bus 'arm' has Homing_Offset 0, its calibration "
            "-1470") in str(caught.value)


def test_on_fault_torque_off_from_the_hardware_file_cuts_the_torque(tmp_path: Path) -> None:
    from taskrunner.backends.feetech import SO101_MOTORS, LeRobotCalibration, calibrated_servos
    from taskrunner.backends.feetech.calibration import load_lerobot_calibration

    cell = load_cell(CELLS / "so101_table.yaml")
    arm = LeRobotCalibration(SO101_MOTORS, load_lerobot_calibration(FIXTURE))
    with BusEmulator(calibrated_servos(arm)) as emulator:
        hardware = _table_hardware(tmp_path, emulator.port, str(FIXTURE))
        hardware.write_text("on_fault: torque_off\n" + hardware.read_text())
        backend = make_backend("feetech", cell, None, hardware=hardware)
        try:
            assert isinstance(backend, FeetechBackend)
            emulator.inject("overheat", 2)
            deadline = time.monotonic() + 2.0
            while backend.fault is None and time.monotonic() < deadline:
                time.sleep(0.01)
            assert backend.fault is not None and backend.fault.stop == "torque off"
        finally:
            backend.close()
        time.sleep(0.05)
        assert all(s.get("Torque_Enable") == 0 for s in emulator.servos.values())


def test_the_backend_drives_every_joint_of_the_cell(tmp_path: Path) -> None:
    from taskrunner.backends.feetech import SO101_MOTORS, LeRobotCalibration, calibrated_servos
    from taskrunner.backends.feetech.calibration import load_lerobot_calibration

    cell = load_cell(CELLS / "so101_table.yaml")
    arm = LeRobotCalibration(SO101_MOTORS, load_lerobot_calibration(FIXTURE))
    with BusEmulator(calibrated_servos(arm, {"elbow_flex": 0.5})) as emulator:
        hardware = _table_hardware(tmp_path, emulator.port, str(FIXTURE))
        backend = make_backend("feetech", cell, None, hardware=hardware)
        try:
            assert isinstance(backend, FeetechBackend)
            assert backend.joint_names == cell.model.joint_names
            state = dict(zip(backend.joint_names, backend.joint_state().positions))
            assert state["elbow_flex"] == pytest.approx(0.5, abs=0.01)
        finally:
            backend.close()
