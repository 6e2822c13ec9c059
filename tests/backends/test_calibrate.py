"""Bench calibration: answers become zero_rad/direction in hardware.yaml, nothing else moves."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import pytest
from firmware_host import build_host, running_host

from taskrunner.backends.calibrate import calibrate_servos, update_hardware_yaml
from taskrunner.backends.calibration import load_calibration
from taskrunner.backends.serial import SerialBackend
from taskrunner.backends.servo_backend import ServoOptions
from taskrunner.errors import YamlError
from taskrunner.resources import DATA_ROOT

ROOT = Path(__file__).resolve().parents[2]
HARDWARE = DATA_ROOT / "robots" / "servo_arm" / "config" / "hardware.yaml"
NAMES = tuple(f"Revolute {i}" for i in range(1, 8))


def test_update_rewrites_only_the_two_values(tmp_path):
    path = tmp_path / "hardware.yaml"
    shutil.copy(HARDWARE, path)
    before = path.read_text().splitlines()
    update_hardware_yaml(path, {"Revolute 2": {"zero_rad": -1.5, "direction": -1.0}})
    after = path.read_text().splitlines()
    changed = [(a, b) for a, b in zip(before, after) if a != b]
    assert len(before) == len(after) and len(changed) == 2
    assert any("zero_rad: -1.500000" in b and "#" in b for _, b in changed)  # comment kept
    cal = load_calibration(path, NAMES)
    assert cal.raw_degrees("Revolute 2", -1.5) == pytest.approx(90.0)
    assert (tmp_path / "hardware.yaml.bak").read_text().splitlines() == before


def test_update_of_an_unknown_joint_names_it(tmp_path):
    path = tmp_path / "hardware.yaml"
    shutil.copy(HARDWARE, path)
    with pytest.raises(YamlError, match=r"no joint entries for \['Revolute 9'\]"):
        update_hardware_yaml(path, {"Revolute 9": {"zero_rad": 0.0}})


@pytest.fixture
def firmware_pty():
    with running_host(build_host(), 50) as host:
        yield host.pty


def test_calibrate_walks_a_joint_and_writes_the_answers(tmp_path, firmware_pty):
    path = tmp_path / "hardware.yaml"
    shutil.copy(HARDWARE, path)
    calibration = load_calibration(path, NAMES)
    backend = SerialBackend(NAMES, calibration, firmware_pty,
                            ServoOptions(time_scale=50, poll_period=0.005))
    answers = iter(["abc", "85", "n"])
    said: list[str] = []
    try:
        updates = calibrate_servos(backend, path, ["Revolute 1"], ask=lambda q: next(answers),
                                   say=said.append)
        assert backend.firmware_status()["pos"][0] == pytest.approx(90.0)
    finally:
        backend.close()
    assert updates == {"Revolute 1": {"zero_rad": pytest.approx(math.radians(85)),
                                      "direction": -1.0}}
    assert "  (not understood)" in said
    again = load_calibration(path, NAMES)
    assert again.raw_degrees("Revolute 1", math.radians(85)) == pytest.approx(90.0, abs=1e-3)
    assert again.raw_degrees("Revolute 1", math.radians(95)) == pytest.approx(80.0, abs=1e-3)


def test_home_on_start_waits_until_the_servos_are_home(firmware_pty):
    calibration = load_calibration(HARDWARE, NAMES)
    options = ServoOptions(time_scale=50, poll_period=0.005)
    first = SerialBackend(NAMES, calibration, firmware_pty, options)
    try:
        first.command("MOVE:120,60,90,90,90,90")
    finally:
        first.close()
    homed = SerialBackend(NAMES, calibration, firmware_pty,
                          ServoOptions(time_scale=50, poll_period=0.005, home_on_start=True))
    try:
        status = homed.firmware_status()
        assert status["pos"] == pytest.approx([90.0] * 6) and not status["moving"]
    finally:
        homed.close()
