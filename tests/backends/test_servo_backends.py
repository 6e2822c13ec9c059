"""Servo calibration and the serial / HTTP backends against the host firmware.

The end-to-end tests build ``firmware/build/taskrunner-servo-host`` (``make -C firmware
host``; skipped without make or g++) and run it faster than real time (``--speedup``); the
backend is told the speedup (``time_scale``) so that it streams ahead of the firmware's
clock. Every wait is bounded. Protocol: firmware/PROTOCOL.md.
"""

from __future__ import annotations

import csv
import json
import math
import os
import signal
import subprocess
import time
import urllib.request
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import pytest
from firmware_host import build_host, running_host

from taskrunner.backends.calibration import ServoCalibration, load_calibration
from taskrunner.backends.http import HttpBackend
from taskrunner.backends.serial import SerialBackend
from taskrunner.backends.servo_backend import ServoBackend, ServoOptions
from taskrunner.backends.servo_protocol import (
    crc8,
    format_angles,
    plan_points,
    strip_checksum,
    with_checksum,
)
from taskrunner.errors import (
    BackendError,
    ExecutionCancelledError,
    TrajectoryRejectedError,
    YamlError,
)
from taskrunner.resources import DATA_ROOT
from taskrunner.robot import load_robot
from taskrunner.types import JointTrajectory

REPO_ROOT = Path(__file__).resolve().parents[2]
FIRMWARE = DATA_ROOT / "firmware"
HARDWARE_YAML = DATA_ROOT / "robots" / "servo_arm" / "config" / "hardware.yaml"
NAMES = tuple(f"Revolute {i}" for i in range(1, 8))
CANDLE = np.array([1.5708, -1.5708, -1.5708, -1.5708, -1.5708, -0.1, -0.1])
OFFSET = np.array([0.3, 0.2, -0.25, 0.15, 0.1, 0.2, 0.2])  # Candle -> a nearby pose (rad)
SPEEDUP = 4.0
TICK_MS = 80
_NO_PROXY = urllib.request.build_opener(urllib.request.ProxyHandler({}))


@pytest.fixture(scope="module")
def calibration() -> ServoCalibration:
    return load_calibration(HARDWARE_YAML, NAMES)


def _trajectory(start: np.ndarray, end: np.ndarray, duration: float) -> JointTrajectory:
    """Quintic time scaling from ``start`` to ``end``, sampled at 100 Hz."""
    t = np.linspace(0.0, duration, round(duration * 100) + 1)
    s = t / duration
    h = 10 * s**3 - 15 * s**4 + 6 * s**5
    positions = start + np.outer(h, end - start)
    return JointTrajectory(NAMES, t, positions, np.zeros_like(positions),
                           np.zeros_like(positions))


# --- calibration ------------------------------------------------------------------------


def test_candle_pose_maps_to_90_degrees_on_every_servo(calibration: ServoCalibration) -> None:
    robot = load_robot(DATA_ROOT / "robots" / "servo_arm")
    candle = robot.named_state("arm", "Candle").as_dict()
    candle.update({"Revolute 6": -0.1, "Revolute 7": -0.1})
    np.testing.assert_allclose(calibration.to_servo_degrees(candle), [90.0] * 6, atol=0.005)
    assert calibration.servo_joint_names == NAMES[:6]
    assert calibration.channels == (0, 3, 6, 9, 12, 15)


def test_revolute_1_at_half_pi_is_90_degrees_and_moves_one_degree_per_degree(
        calibration: ServoCalibration) -> None:
    pose = dict(zip(NAMES, CANDLE))
    pose["Revolute 1"] = math.pi / 2
    assert calibration.to_servo_degrees(pose)[0] == pytest.approx(90.0, abs=0.005)
    pose["Revolute 1"] = math.pi / 2 + math.radians(30)
    assert calibration.to_servo_degrees(pose)[0] == pytest.approx(120.0, abs=0.005)


def test_servo_degrees_round_trip_to_joint_angles_and_mirror_joint_reads_as_leader(
        calibration: ServoCalibration) -> None:
    rng = np.random.default_rng(7)
    for _ in range(20):
        q = CANDLE + rng.uniform(-1.0, 1.0, 7) * np.array([1.4, 1.4, 1.4, 1.4, 1.4, 0.35, 0.35])
        q[6] = q[5]
        degrees = calibration.to_servo_degrees(dict(zip(NAMES, q)))
        back = calibration.from_servo_degrees(degrees)
        assert back.names == NAMES
        np.testing.assert_allclose(back.positions, q, atol=math.radians(0.0051))
    back = calibration.from_servo_degrees([90, 90, 90, 90, 90, 112.9])
    assert back.positions[6] == back.positions[5] == pytest.approx(0.3, abs=1e-3)


def test_direction_and_scale_follow_the_seed_formula(tmp_path: Path) -> None:
    path = tmp_path / "hardware.yaml"
    path.write_text("joints:\n  - {name: a, servo_type: SG90, channel: 1, zero_rad: 0.5,"
                    " direction: -1, scale: 2.0}\n")
    cal = load_calibration(path, ["a"])
    # 90 + (-1) * (0.6 - 0.5) * 180/pi * 2
    assert cal.to_servo_degrees({"a": 0.6})[0] == pytest.approx(
        round(90 - 0.1 * 180 / math.pi * 2, 2), abs=1e-9)
    assert cal.from_servo_degrees([80.0]).positions[0] == pytest.approx(
        0.5 + math.radians(10) / 2)


def test_out_of_range_trajectory_is_refused_naming_joint_and_time(
        calibration: ServoCalibration) -> None:
    end = CANDLE.copy()
    end[1] += math.radians(100)  # Revolute 2: 90 -> 190 degrees
    trajectory = _trajectory(CANDLE, end, 1.0)
    with pytest.raises(TrajectoryRejectedError) as info:
        calibration.check_trajectory_in_range(trajectory)
    message = str(info.value)
    assert "'Revolute 2'" in message
    deg = calibration.raw_degrees("Revolute 2", trajectory.positions[:, 1])
    k = int(np.flatnonzero(np.round(deg, 2) > 180)[0])
    assert f"t = {trajectory.times[k]:.3f} s" in message
    with pytest.raises(TrajectoryRejectedError, match="'Revolute 1'"):
        pose = dict(zip(NAMES, CANDLE))
        pose["Revolute 1"] = -0.1
        calibration.to_servo_degrees(pose)
    calibration.check_trajectory_in_range(_trajectory(CANDLE, CANDLE + OFFSET, 1.0))


@pytest.mark.parametrize(("joint_text", "expected"), [
    ("  - {name: 'Revolute 1', channel: 0, zero_rad: 0, direction: 1, scale: 1, gain: 2}",
     "unknown field 'gain'"),
    ("  - {name: 'Revolute 9', channel: 0, zero_rad: 0, direction: 1, scale: 1}",
     "unknown joint 'Revolute 9'"),
    ("  - {name: 'Revolute 1', channel: 16, zero_rad: 0, direction: 1, scale: 1}",
     "'channel' of joint 'Revolute 1' must be an integer 0..15"),
    ("  - {name: 'Revolute 1', channel: 0, zero_rad: 0, direction: 2, scale: 1}",
     "'direction' of joint 'Revolute 1' must be 1 or -1"),
    ("  - {name: 'Revolute 1', channel: 0, zero_rad: abc, direction: 1, scale: 1}",
     "'zero_rad' of joint 'Revolute 1' must be a finite number"),
    ("  - {name: 'Revolute 7', same_servo_as: 'Revolute 5'}",
     "'same_servo_as' of joint 'Revolute 7' must name a joint with its own servo"),
])
def test_bad_hardware_yaml_is_reported_with_file_and_line(tmp_path: Path, joint_text: str,
                                                          expected: str) -> None:
    path = tmp_path / "hardware.yaml"
    path.write_text("port: /dev/ttyUSB0\njoints:\n"
                    "  - {name: 'Revolute 2', channel: 3, zero_rad: 0, direction: 1, scale: 1}\n"
                    + joint_text + "\n")
    with pytest.raises(YamlError) as info:
        load_calibration(path, NAMES)
    assert expected in str(info.value)
    assert str(info.value).startswith(f"{path}:4: ")


# --- fake transports --------------------------------------------------------------------

_VERSION = ('ok {"firmware":"taskrunner-servo","version":"1.1.0","protocol":2,"servos":6,'
            '"channels":[0,3,6,9,12,15],"home":[90,90,90,90,90,90],"tick_ms":80,'
            '"speed_range":[1,20],"queue":64,"max_line":128,"checksum":"crc8",'
            '"watchdog_ms":300}')
_STATUS = ('ok {"status":"ok","mode":"idle","moving":false,"powered":false,'
           '"pos":[90,90,90,90,90,90],"target":[90,90,90,90,90,90],"speed":5,"queued":0,'
           '"buffered_ms":0,"tick":3}')


class ScriptedTransport:
    """Answers the handshake and STATUS like the firmware, and ``traj_reply`` to TRAJ
    (checksummed, unless ``checksum`` is False); records the lines without checksums."""

    def __init__(self, traj_reply: str = "ok 1 80", ping_reply: str = "ok pong",
                 checksum: bool = True) -> None:
        self.sent: list[str] = []
        self.aborted: list[str] = []
        self.traj_reply = traj_reply
        self.ping_reply = ping_reply
        self.checksum = checksum
        self.closed = False

    def exchange(self, line: str, timeout: float | None = None) -> str:
        assert not self.closed, f"{line!r} sent after close"
        command = strip_checksum(line)
        assert command is not None, f"{line!r} sent without a right checksum"
        self.sent.append(command)
        name = command.split(":")[0]
        reply = {"PING": self.ping_reply, "VERSION": _VERSION, "STATUS": _STATUS,
                 "STOP": "ok"}.get(name, self.traj_reply)
        return with_checksum(reply) if self.checksum else reply

    def abort(self, line: str) -> None:
        self.aborted.append(line)
        self.closed = True

    def close(self) -> None:
        self.closed = True


def test_garbage_reply_fails_the_execution_and_nothing_more_is_sent(
        calibration: ServoCalibration) -> None:
    transport = ScriptedTransport(traj_reply="\x00\x7fgarbage")
    backend = ServoBackend(NAMES, calibration, transport, ServoOptions(poll_period=0.005))
    try:
        handle = backend.execute(_trajectory(CANDLE, CANDLE + OFFSET, 1.0))
        with pytest.raises(BackendError, match="garbage reply to 'TRAJ'") as info:
            handle.wait(1.0)
        assert not isinstance(info.value, ExecutionCancelledError)
        assert handle.status == "failed"
        sent = len(transport.sent)
        time.sleep(0.05)
        assert transport.closed and len(transport.sent) == sent
        assert transport.sent[-1].startswith("TRAJ:")
        with pytest.raises(BackendError, match="servo link failed"):
            backend.execute(_trajectory(CANDLE, CANDLE + OFFSET, 1.0))
    finally:
        backend.close()


def test_garbage_handshake_and_out_of_range_trajectory_send_nothing_further(
        calibration: ServoCalibration) -> None:
    with pytest.raises(BackendError, match="garbage reply to 'PING'"):
        ServoBackend(NAMES, calibration, ScriptedTransport(ping_reply="pong?"))
    transport = ScriptedTransport()
    with ServoBackend(NAMES, calibration, transport, ServoOptions()) as backend:
        end = CANDLE.copy()
        end[0] = 4.5  # Revolute 1 past 180 degrees
        with pytest.raises(TrajectoryRejectedError, match="'Revolute 1' at t = "):
            backend.execute(_trajectory(CANDLE, end, 1.0))
        assert not any(line.startswith("TRAJ") for line in transport.sent)


def test_no_reply_on_the_serial_port_is_a_backend_error_after_the_timeout(
        calibration: ServoCalibration) -> None:
    master, slave = os.openpty()  # nobody answers on the other end
    try:
        start = time.monotonic()
        with pytest.raises(BackendError, match="no reply from the servo firmware"):
            SerialBackend(NAMES, calibration, os.ttyname(slave),
                          ServoOptions(reply_timeout=0.3, banner_timeout=0.05))
        assert 0.3 <= time.monotonic() - start < 1.5
    finally:
        os.close(master)
        os.close(slave)


def test_missing_serial_port_is_named_in_the_error(calibration: ServoCalibration) -> None:
    with pytest.raises(BackendError, match="/dev/does-not-exist-ttyServo"):
        SerialBackend(NAMES, calibration, "/dev/does-not-exist-ttyServo")


def test_stream_points_follow_the_tick_grid_with_integer_dt() -> None:
    cal = load_calibration(HARDWARE_YAML, NAMES)
    points = plan_points(_trajectory(CANDLE, CANDLE + OFFSET, 0.5), cal, np.full(6, 90.0), 80)
    assert [p.at_ms for p in points] == [80, 160, 240, 320, 400, 480, 500]
    assert [p.dt_ms for p in points][-2:] == [80, 20]
    assert format_angles(np.array([90.0, 90.5, 47.254, 0.004, 180.0, 12.3])) == \
        "90,90.5,47.25,0,180,12.3"


# --- end to end against the host firmware -------------------------------------------------


@dataclass
class Host:
    proc: subprocess.Popen[bytes]
    pty: str
    url: str
    log: Path

    def status(self) -> dict:
        body = json.dumps({"cmd": "STATUS"}).encode()
        request = urllib.request.Request(self.url, data=body,
                                         headers={"Content-Type": "application/json"})
        with _NO_PROXY.open(request, timeout=2.0) as response:
            return json.loads(json.loads(response.read())["reply"][3:])

    def log_rows(self) -> np.ndarray:
        with self.log.open(newline="") as stream:
            rows = list(csv.reader(stream))
        return np.array([[float(v) for v in row] for row in rows[1:]])


@pytest.fixture(scope="module")
def host_binary() -> Path:
    return build_host()


@pytest.fixture
def host(host_binary: Path, tmp_path: Path) -> Iterator[Host]:
    with running_host(host_binary, SPEEDUP, tmp_path / "ticks.csv") as running:
        assert running.log is not None
        yield Host(running.proc, running.pty, running.url, running.log)


def _open(kind: str, host: Host, calibration: ServoCalibration, **options: float) -> ServoBackend:
    opts = ServoOptions(time_scale=SPEEDUP, poll_period=0.005, banner_timeout=0.5, **options)
    if kind == "serial":
        return SerialBackend(NAMES, calibration, host.pty, opts)
    return HttpBackend(NAMES, calibration, host.url, opts)


def _expected_degrees(points, start: np.ndarray, t_ms: np.ndarray) -> np.ndarray:
    """The commanded timeline (servo degrees) at ``t_ms`` after its origin."""
    times = np.array([0] + [p.at_ms for p in points], dtype=float)
    values = np.vstack([start] + [p.degrees for p in points])
    return np.column_stack([np.interp(t_ms, times, values[:, i]) for i in range(6)])


@pytest.mark.parametrize("kind", ["serial", "http"])
def test_trajectory_ends_at_the_planned_pose_and_servos_track_every_tick(
        kind: str, host: Host, calibration: ServoCalibration) -> None:
    with _open(kind, host, calibration) as backend:
        np.testing.assert_allclose(backend.joint_state().positions, CANDLE, atol=1e-4)
        trajectory = _trajectory(CANDLE, CANDLE + OFFSET, 1.5)
        result = backend.execute(trajectory).wait(5.0)
        assert result.status == "succeeded"
        np.testing.assert_allclose(result.final.positions, CANDLE + OFFSET, atol=math.radians(1))
    final = host.status()
    assert final["moving"] is False
    planned = calibration.to_servo_degrees(dict(zip(NAMES, CANDLE + OFFSET)))
    np.testing.assert_allclose(final["pos"], planned, atol=1.0)
    # The tick log against the commanded timeline: align its origin (the tick before the
    # first point arrived), then every tick must be within one step of the command.
    rows = host.log_rows()
    points = plan_points(trajectory, calibration, np.full(6, 90.0), TICK_MS)
    step = np.max(np.abs(np.diff(np.vstack([np.full(6, 90.0)] + [p.degrees for p in points]),
                                 axis=0)))
    best = math.inf
    for origin in rows[:, 0]:
        after = rows[rows[:, 0] >= origin]
        error = np.max(np.abs(after[:, 1:] - _expected_degrees(points, np.full(6, 90.0),
                                                                after[:, 0] - origin)))
        best = min(best, error)
    assert best <= step, f"servos off the commanded timeline by {best:.3f} deg (step {step:.3f})"


@pytest.mark.parametrize("kind", ["serial", "http"])
def test_cancel_mid_motion_stops_the_servos_between_start_and_end(
        kind: str, host: Host, calibration: ServoCalibration) -> None:
    with _open(kind, host, calibration) as backend:
        handle = backend.execute(_trajectory(CANDLE, CANDLE + OFFSET, 3.0))
        deadline = time.monotonic() + 3.0
        while handle.progress < 1.0 and time.monotonic() < deadline:
            time.sleep(0.005)
        assert not handle.done(), "finished before it could be cancelled"
        handle.cancel()
        with pytest.raises(ExecutionCancelledError):
            handle.wait(1.0)
        stopped = host.status()
        assert stopped["moving"] is False and stopped["mode"] == "idle"
        start = calibration.to_servo_degrees(dict(zip(NAMES, CANDLE)))
        end = calibration.to_servo_degrees(dict(zip(NAMES, CANDLE + OFFSET)))
        pos = np.array(stopped["pos"])
        assert np.all(pos >= np.minimum(start, end)) and np.all(pos <= np.maximum(start, end))
        assert np.any(np.abs(pos - start) > 1) and np.any(np.abs(pos - end) > 1)
        time.sleep(0.1)  # several ticks at this speedup: nothing moves any more
        assert host.status()["pos"] == stopped["pos"]
        np.testing.assert_allclose(backend.joint_state().positions,
                                   calibration.from_servo_degrees(pos).positions, atol=1e-9)


@pytest.mark.parametrize("kind", ["serial", "http"])
def test_firmware_killed_mid_motion_fails_the_execution_within_200_ms(
        kind: str, host: Host, calibration: ServoCalibration) -> None:
    with _open(kind, host, calibration) as backend:
        handle = backend.execute(_trajectory(CANDLE, CANDLE + OFFSET, 3.0))
        deadline = time.monotonic() + 3.0
        while handle.progress < 0.5 and time.monotonic() < deadline:
            time.sleep(0.005)
        host.proc.kill()
        host.proc.wait(2.0)
        observed = time.monotonic()
        with pytest.raises(BackendError) as info:
            handle.wait(1.0)
        assert time.monotonic() - observed < 0.2
        assert not isinstance(info.value, ExecutionCancelledError)
        assert handle.status == "failed"
        assert "servo link failed" in str(info.value)


def test_firmware_frozen_mid_motion_fails_within_the_stream_reply_deadline(
        host: Host, calibration: ServoCalibration) -> None:
    with _open("serial", host, calibration, reply_timeout=1.0) as backend:
        handle = backend.execute(_trajectory(CANDLE, CANDLE + OFFSET, 3.0))
        deadline = time.monotonic() + 3.0
        while handle.progress < 0.5 and time.monotonic() < deadline:
            time.sleep(0.005)
        os.kill(host.proc.pid, signal.SIGSTOP)
        frozen = time.monotonic()
        with pytest.raises(BackendError, match="no reply from the servo firmware"):
            handle.wait(2.0)
        # Not the 1 s reply timeout: the 120 ms deadline of a stream (+ margin for a
        # loaded machine; test_link_faults measures it at the relay).
        assert time.monotonic() - frozen < 0.12 + 0.18


def test_crc8_matches_the_firmware_and_strip_checksum_refuses_any_changed_digit() -> None:
    assert crc8("123456789") == 0xF4  # the SMBus CRC-8 check value, as in test_link.cpp
    line = with_checksum("ok 3 240")
    assert strip_checksum(line) == "ok 3 240"
    assert strip_checksum(with_checksum("STATUS").upper().replace("S", "s", 1)) is None
    for i, c in enumerate(line[:-3]):
        if c.isdigit():
            assert strip_checksum(line[:i] + str((int(c) + 1) % 10) + line[i + 1:]) is None
    assert strip_checksum("ok 3 240") is None  # no checksum


@pytest.mark.parametrize(("reply", "why"), [
    ("ok 1 80", "no checksum"),
    (with_checksum("ok 1 80").replace("80", "30", 1), "missing or wrong checksum"),
])
def test_reply_without_a_right_checksum_fails_the_motion_naming_the_line_then_stop(
        calibration: ServoCalibration, reply: str, why: str) -> None:
    transport = ScriptedTransport()
    backend = ServoBackend(NAMES, calibration, transport, ServoOptions(poll_period=0.005))
    try:
        transport.traj_reply, transport.checksum = reply, False
        handle = backend.execute(_trajectory(CANDLE, CANDLE + OFFSET, 1.0))
        with pytest.raises(BackendError, match=f"corrupted reply to 'TRAJ:80:.*{why}") as info:
            handle.wait(1.0)
        assert repr(reply) in str(info.value)
        assert backend._link.aborted.wait(1.0)
        assert transport.aborted == [with_checksum("STOP")]
        assert transport.sent[-1].startswith("TRAJ:") and backend._link.corrupted_replies == 1
    finally:
        backend.close()


def _pair_robots() -> list:
    from taskrunner.backends.calibration import RobotOnBoard

    return [RobotOnBoard(side, f"{side}_", HARDWARE_YAML, NAMES) for side in ("left", "right")]


def test_pair_board_file_gives_twelve_servos_with_prefixed_joints_on_its_channels() -> None:
    from taskrunner.backends.calibration import load_board_calibration

    cal = load_board_calibration(DATA_ROOT / "robots" / "cells" / "servo_arm_pair.hardware.yaml",
                                 _pair_robots())
    assert cal.channels == (0, 1, 2, 3, 4, 5, 8, 9, 10, 11, 12, 13)
    assert cal.servo_joint_names[0] == "left_Revolute 1"
    assert cal.servo_joint_names[6] == "right_Revolute 1"
    pose = {f"{side}_{n}": q for side in ("left", "right") for n, q in zip(NAMES, CANDLE)}
    np.testing.assert_allclose(cal.to_servo_degrees(pose), [90.0] * 12, atol=0.005)
    assert cal.from_servo_degrees([90.0] * 11 + [112.9]).as_dict()["right_Revolute 7"] == \
        pytest.approx(0.3, abs=1e-3)


@pytest.mark.parametrize(("robots_text", "expected"), [
    ("  left: {channels: [0, 1, 2, 3, 4, 5]}\n  right: {channels: [5, 9, 10, 11, 12, 13]}\n",
     "channel 5 of joint 'right_Revolute 1' is also 'left_Revolute 6'"),
    ("  left: {channels: [0, 1, 2, 3, 4]}\n  right: {channels: [8, 9, 10, 11, 12, 13]}\n",
     "'channels' of robot 'left' must list 6 channels 0..15"),
    ("  left: {channels: [0, 1, 2, 3, 4, 5]}\n", "robots ['right'] have no channels"),
    ("  left: {channels: [0, 1, 2, 3, 4, 5]}\n  middle: {channels: [8]}\n",
     "unknown robot 'middle'"),
])
def test_bad_board_file_is_reported_with_file_and_line(tmp_path: Path, robots_text: str,
                                                       expected: str) -> None:
    from taskrunner.backends.calibration import load_board_calibration

    path = tmp_path / "pair.hardware.yaml"
    path.write_text("port: /dev/ttyUSB0\nrobots:\n" + robots_text)
    with pytest.raises(YamlError) as info:
        load_board_calibration(path, _pair_robots())
    assert expected in str(info.value) and str(info.value).startswith(f"{path}:")
