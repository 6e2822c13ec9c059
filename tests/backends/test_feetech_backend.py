"""FeetechBackend over the bus emulator: streaming, tracking error, every fault stopped.

Fault tests measure detection from the emulator's injection time to the backend's
detection time (both ``time.monotonic``, same process); nothing else is timed.
"""

from __future__ import annotations

import os
import time
import tty
from collections.abc import Iterator, Sequence
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from taskrunner.backends.feetech import (
    SO101_MOTORS,
    BusEmulator,
    BusMotors,
    FaultKind,
    FeetechBackend,
    FeetechBus,
    FeetechOptions,
    LeRobotCalibration,
    ServoState,
    calibrated_servos,
    load_lerobot_calibration,
)
from taskrunner.backends.feetech import bus as bus_module
from taskrunner.errors import BackendError, BusFaultError, ExecutionCancelledError
from taskrunner.types import JointTrajectory

FIXTURE = Path(__file__).parent / "fixtures" / "so101_lerobot_calibration.json"
DETECTION_LIMIT = 0.1  # s, from the injection to the backend's detection
# A loaded test host answers from the emulator late now and then; detection stays within
# one 20 ms cycle plus this, under the limit.
REPLY_TIMEOUT = 0.06


@pytest.fixture
def emulator() -> Iterator[BusEmulator]:
    with BusEmulator(calibrated_servos(_arm(), {"shoulder_lift": -0.2, "elbow_flex": 0.3})) as emu:
        yield emu


def _arm() -> LeRobotCalibration:
    return LeRobotCalibration(SO101_MOTORS, load_lerobot_calibration(FIXTURE))


def _backend(emulator: BusEmulator, reply_timeout: float = REPLY_TIMEOUT,
             **options: object) -> FeetechBackend:
    return FeetechBackend([BusMotors(FeetechBus(emulator.port, reply_timeout=reply_timeout),
                                     _arm())], FeetechOptions(**options))  # type: ignore[arg-type]


def _move(backend: FeetechBackend, delta: list[float], duration: float) -> JointTrajectory:
    """A smooth (cosine) move of every joint by ``delta`` rad from where it is."""
    start = backend.joint_state().positions
    t = np.linspace(0.0, duration, 41)
    s = 0.5 - 0.5 * np.cos(np.pi * t / duration)
    q = start[None, :] + s[:, None] * np.asarray(delta)[None, :]
    return JointTrajectory(backend.joint_names, t, q, np.zeros_like(q), np.zeros_like(q))


def _wait_progress(handle: object, seconds: float) -> None:
    deadline = time.monotonic() + 5.0
    while handle.progress < seconds:  # type: ignore[attr-defined]
        assert time.monotonic() < deadline, "the trajectory did not start"
        time.sleep(0.005)


def test_a_trajectory_streams_as_sync_writes_and_reports_tracking_per_joint(
        emulator: BusEmulator) -> None:
    with _backend(emulator, reply_timeout=0.3) as backend:  # not a fault test: lenient
        trajectory = _move(backend, [0.4, -0.3, 0.3, 0.2, 0.5, 0.6], duration=0.6)
        packets = emulator.packets
        result = backend.execute(trajectory).wait(5.0)
        assert result.status == "succeeded"
        for name in backend.joint_names:
            assert name in result.message
        tracking = backend.tracking()
        assert set(tracking) == set(backend.joint_names)
        assert all(0 < t.largest < 0.1 and t.rms <= t.largest for t in tracking.values())
        final = backend.joint_state().positions
        assert np.all(np.abs(final - trajectory.positions[-1]) < 0.035)
        # one sync write and one sync read a cycle, at 50 Hz over 0.6 s (a loaded host may
        # skip a few cycles; it never sends goals ahead of time)
        cycles = int(result.message.split(" cycles")[0].rsplit(" ", 1)[1])
        assert cycles >= 0.8 * 50 * 0.6
        assert emulator.packets - packets >= 2 * cycles



class _LateBus(FeetechBus):
    """A bus whose next read comes ``late`` s after the goals went out: the host kept from
    running between the two (as a loaded machine does now and then)."""

    late = 0.0

    def read_states(self, servo_ids: Sequence[int]) -> dict[int, ServoState]:
        delay, self.late = self.late, 0.0
        time.sleep(delay)
        return super().read_states(servo_ids)


def test_a_late_cycle_slips_the_plan_instead_of_leaping_the_goals(emulator: BusEmulator) -> None:
    """After a cycle 0.3 s late, the goals go on from the last ones (at most two periods
    further along the plan), not from where the wall clock has the plan by then (0.3 s of
    a motion at nearly 1 rad/s: a leap the servos would cross at full speed, read as a
    tracking error); the time lost is reported as the execution's slip."""
    bus = _LateBus(emulator.port, reply_timeout=0.3)
    with FeetechBackend([BusMotors(bus, _arm())]) as backend:
        handle = backend.execute(_move(backend, [0.5, -0.4, 0.4, 0.3, 0.5, 0.6], duration=1.0))
        _wait_progress(handle, 0.3)
        bus.late = 0.3
        result = handle.wait(5.0)
        assert result.status == "succeeded", result.message
        slip = result.data["slip"]
        assert isinstance(slip, float) and slip >= 0.3 - 2 / 60, result.data
        # (the data rounds to 0.1 ms)
        assert backend.slip >= slip - 1e-4 and "behind the plan" in result.message
        tracking = backend.tracking()
        assert all(t.largest < 0.1 for t in tracking.values()), tracking


def test_a_write_that_went_out_is_not_a_fault_however_late_its_thread_runs_again(
        emulator: BusEmulator, monkeypatch: pytest.MonkeyPatch) -> None:
    """Every byte written, then the thread kept from running past the reply timeout (a busy
    host): no fault (pyserial's timed write called that a 'Write timeout': the adapter
    unplugged); a port that takes no byte for the timeout is one."""
    bus = FeetechBus(emulator.port, reply_timeout=0.05)
    try:
        def write_then_wait(fd: int, data: bytes) -> int:
            written = os.write(fd, data)
            time.sleep(0.1)
            return written

        monkeypatch.setattr(bus_module, "os", SimpleNamespace(write=write_then_wait))
        bus.write_goals({1: emulator.servos[1].present()})
        assert bus.ping(1) == 777
    finally:
        monkeypatch.undo()
        bus.close()
    master, slave = os.openpty()  # nobody reads it: its buffer fills
    tty.setraw(slave)
    bus = FeetechBus(os.ttyname(slave), reply_timeout=0.05)
    try:
        with pytest.raises(BusFaultError, match=r"not taken within 50 ms") as caught:
            for _ in range(100_000):
                bus.write_goals(dict.fromkeys(range(1, 7), 2048))
        assert caught.value.kind == FaultKind.UNPLUGGED
    finally:
        bus.close()
        os.close(master)
        os.close(slave)

def test_cancel_holds_the_servos_where_they_are(emulator: BusEmulator) -> None:
    with _backend(emulator, reply_timeout=0.3) as backend:
        handle = backend.execute(_move(backend, [0.5, 0.0, 0.0, 0.0, 0.0, 0.0], duration=1.0))
        _wait_progress(handle, 0.2)
        handle.cancel()
        with pytest.raises(ExecutionCancelledError):
            handle.wait(1.0)
        _assert_held(emulator)


def _assert_held(emulator: BusEmulator) -> None:
    """Every servo's goal is where it is (within backlash and a cycle of motion), far from
    where the trajectory was going, and no goal is written any more."""
    time.sleep(0.05)  # the emulator's thread takes the last packets in
    goals = {i: s.get("Goal_Position") for i, s in emulator.servos.items()}
    time.sleep(0.1)
    for i, servo in emulator.servos.items():
        assert servo.get("Goal_Position") == goals[i]
        assert abs(goals[i] - servo.present()) < 40, f"servo {i}"


FAULTS = [
    ("drop", 3, FaultKind.NO_REPLY),
    ("corrupt", 2, FaultKind.BAD_CHECKSUM),
    ("wrong_id", 4, FaultKind.WRONG_ID),
    ("unplug", None, FaultKind.UNPLUGGED),
    ("stall", 3, FaultKind.STALL),
    ("overload", 2, FaultKind.OVERLOAD),
    ("overheat", 5, FaultKind.OVERHEAT),
    ("voltage", 1, FaultKind.VOLTAGE),
]


@pytest.mark.parametrize(("fault", "servo_id", "kind"), FAULTS, ids=[f[0] for f in FAULTS])
def test_each_fault_is_detected_quickly_stopped_and_reported(
        emulator: BusEmulator, fault: str, servo_id: int | None, kind: FaultKind) -> None:
    backend = _backend(emulator)
    try:
        handle = backend.execute(_move(backend, [0.4, 0.3, -0.4, 0.3, 0.4, 0.4], duration=1.0))
        _wait_progress(handle, 0.1)
        emulator.inject(fault, servo_id)
        with pytest.raises(BusFaultError) as caught:
            handle.wait(2.0)
        error = caught.value
        assert error.kind == kind.value and error.servo_id == servo_id
        if servo_id is not None:
            joint = SO101_MOTORS[servo_id - 1].joint
            assert f"servo {servo_id}" in str(error) and joint in str(error)
        record = backend.fault
        assert record is not None and record.kind == kind
        assert emulator.injected_at is not None
        assert 0 <= record.detected_at - emulator.injected_at < DETECTION_LIMIT
        if fault == "unplug":
            assert record.stop.startswith("hold not sent")
        else:
            assert record.stop == "hold" and "stopped: hold" in str(error)
            _assert_held(emulator)
        with pytest.raises(BackendError, match="stopped on a bus fault"):
            backend.execute(_move(backend, [0.1] * 6, duration=0.5))
    finally:
        backend.close()


def test_torque_off_on_fault_when_configured(emulator: BusEmulator) -> None:
    with _backend(emulator, on_fault="torque_off") as backend:
        handle = backend.execute(_move(backend, [0.3] * 6, duration=1.0))
        _wait_progress(handle, 0.1)
        emulator.inject("drop", 6)
        with pytest.raises(BusFaultError, match="stopped: torque off"):
            handle.wait(2.0)
        time.sleep(0.05)  # the emulator's thread takes the last packets in
        assert all(s.get("Torque_Enable") == 0 for s in emulator.servos.values())


def test_a_fault_while_idle_stops_the_backend(emulator: BusEmulator) -> None:
    with _backend(emulator) as backend:
        emulator.inject("overheat", 4)
        deadline = time.monotonic() + 2.0
        while backend.fault is None and time.monotonic() < deadline:
            time.sleep(0.005)
        assert backend.fault is not None and backend.fault.kind == FaultKind.OVERHEAT
        assert emulator.injected_at is not None
        assert backend.fault.detected_at - emulator.injected_at < DETECTION_LIMIT
        assert backend.fault.joint == "wrist_flex"


def test_a_trajectory_outside_the_calibrated_range_is_refused(emulator: BusEmulator) -> None:
    from taskrunner.errors import TrajectoryRejectedError

    with _backend(emulator) as backend:
        with pytest.raises(TrajectoryRejectedError, match="joint 'shoulder_pan' at t = "):
            backend.execute(_move(backend, [3.0, 0, 0, 0, 0, 0], duration=1.0))


def test_a_silent_servo_at_connect_is_named(emulator: BusEmulator) -> None:
    emulator.inject("drop", 5)
    with pytest.raises(BusFaultError, match=r"joint 'wrist_roll' \(servo 5 on bus '/dev/.*'\) does "
                       r"not answer"):
        _backend(emulator)
