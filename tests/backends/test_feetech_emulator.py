"""The STS3215 model behind ``run-task bus-sim``: goal tracking, backlash, load, protection."""

from __future__ import annotations

import time

import pytest

from taskrunner.backends.feetech.emulator import (
    ACCELERATION_UNIT,
    TICKS_PER_DEGREE,
    BusEmulator,
    ServoModel,
    so101_servos,
)
from taskrunner.backends.feetech.protocol import StatusFlag


def _servo(**kwargs: float) -> ServoModel:
    servo = ServoModel(1, **kwargs)  # type: ignore[arg-type]
    servo.put("Torque_Enable", 1)
    return servo


def test_goal_is_tracked_at_the_speed_and_acceleration_limits() -> None:
    servo = _servo(actual=1000.0, backlash=0.0)
    servo.put("Goal_Velocity", 1000)  # ticks/s
    servo.put("Acceleration", 50)  # 5000 ticks/s²: 0.2 s to full speed
    servo.put("Goal_Position", 2000)
    servo.advance(0.2)
    assert servo.velocity == pytest.approx(1000.0, abs=1.0)
    assert servo.actual == pytest.approx(1000 + 0.5 * 50 * ACCELERATION_UNIT * 0.2 ** 2, abs=6)
    servo.advance(0.5)
    assert servo.velocity == pytest.approx(1000.0, abs=1.0)  # cruising, not yet braking
    servo.advance(0.6)
    assert servo.present() == 2000 and servo.velocity == 0.0


def test_backlash_is_lost_motion_on_a_reversal_and_the_output_ends_at_the_goal() -> None:
    servo = _servo(actual=2048.0)  # no gravity: the output rests where the gears left it
    servo.put("Goal_Velocity", 100)  # ticks/s: the gap (11.4 ticks) takes about 0.11 s
    servo.put("Goal_Position", 2300)
    servo.advance(3.0)
    # the loop closes on the output's encoder: the output at the goal, the motor ahead
    assert servo.actual == pytest.approx(2300) and servo.present() == 2300
    assert servo.motor == pytest.approx(2300 + TICKS_PER_DEGREE / 2)
    servo.put("Goal_Position", 2100)
    servo.advance(0.08)  # the motor turns back through the gap, the output waits
    assert servo.motor < 2300 and servo.actual == pytest.approx(2300)
    servo.advance(3.0)
    assert servo.actual == pytest.approx(2100) and servo.present() == 2100
    assert servo.motor == pytest.approx(2100 - TICKS_PER_DEGREE / 2)


def test_gravity_loads_the_servo_and_holds_the_output_on_one_side() -> None:
    servo = _servo(actual=2048.0, gravity=0.3, gravity_zero=1024.0)  # horizontal at 2048
    servo.put("Goal_Position", 2048)
    servo.advance(0.2)
    assert servo.load == pytest.approx(0.3, abs=0.01)
    # the output held at the goal, the gears pushing up against gravity across the gap
    assert servo.actual == pytest.approx(2048)
    assert servo.motor == pytest.approx(2048 + TICKS_PER_DEGREE / 2)


def test_a_stall_trips_the_overload_protection_after_its_time() -> None:
    servo = _servo(actual=2048.0)
    servo.put("Goal_Position", 2500)
    servo.stalled = True
    servo.advance(0.15)  # Protection_Time 20 × 10 ms
    assert servo.load == 1.0 and not servo.flags
    servo.advance(0.06)
    assert servo.flags == StatusFlag.OVERLOAD
    servo.stalled = False
    position = servo.actual
    servo.advance(0.2)
    assert servo.actual == position  # the torque is cut: no motion


def test_inject_refuses_unknown_faults_and_servos() -> None:
    emulator = BusEmulator(so101_servos())
    with pytest.raises(ValueError, match="'kind' must be one of drop, corrupt"):
        emulator.inject("fire")
    with pytest.raises(ValueError, match=r"'servo_id' must be one of \[1, 2, 3, 4, 5, 6\]"):
        emulator.inject("drop", 9)


def test_an_emulator_kept_from_running_catches_up_as_a_servo_moves_meanwhile() -> None:
    """The servos move over all the wall-clock time since the emulator last ran (a real
    servo does not wait for the host), however long: here 1 s or more without running,
    for a move that takes about 0.8 s, where a step capped at 0.5 s left the servo half
    way. A servo at rest then stays, over an hour of its time, and a stalled one still
    trips its protection after any pause."""
    servos = so101_servos()
    emulator = BusEmulator(servos)  # not serving: the model advances only when told
    moving, stalled = servos[0], servos[4]
    for servo, goal in ((moving, moving.present() + 1600), (stalled, stalled.present() + 400)):
        servo.put("Torque_Enable", 1)
        servo.put("Goal_Velocity", 2000)  # ticks/s: 0.8 s for 1600 ticks
        servo.put("Goal_Position", goal)
    stalled.stalled = True
    start = emulator.clock
    time.sleep(1.0)
    emulator.inject("drop", 6)  # brings the model up to now, as any packet does
    assert emulator.clock - start >= 1.0
    assert moving.present() == moving.get("Goal_Position") and moving.velocity == 0.0
    assert stalled.flags == StatusFlag.OVERLOAD
    at_rest = moving.actual
    moving.advance(3600.0)
    assert moving.actual == at_rest and moving.velocity == 0.0
