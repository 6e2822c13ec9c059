"""A Feetech STS bus emulator behind a pseudo-terminal (``run-task bus-sim``).

:class:`BusEmulator` answers PING, READ, WRITE, SYNC WRITE and SYNC READ on a pty for a
:class:`ServoModel` per ID, the way STS3215 servos do: registers at the manual's addresses,
the goal tracked at the Goal_Velocity and Acceleration limits, a 12-bit encoder on the
output shaft after the homing offset (the loop closes there), about 1° of gear backlash
(lost motion on a reversal), a load from gravity and acceleration, the
overload protection (torque cut after the load stays over Overload_Torque for
Protection_Time), status flags in every reply. Faults are injected with
:meth:`BusEmulator.inject`: ``drop`` (no reply), ``corrupt`` (bad checksum), ``wrong_id``,
``stall`` (the output blocked), ``overload`` / ``overheat`` / ``voltage`` (the servo's
flag, torque cut as the servo does), ``unplug`` (the pty closes, as a pulled USB adapter).

Time is the wall clock (``time.monotonic``) times ``time_scale`` (1: real time; 2: the
servos move twice as fast, for tests, with the backend's ``time_scale`` the same): the
model is advanced in 1 ms steps of its own time up to now whenever a packet arrives and
every few milliseconds otherwise, over the whole time since it last ran however long that
was (a real servo goes on moving while the host is busy: an emulator kept from running
catches up, a servo at rest at once). Every SYNC WRITE received is logged
(:attr:`BusEmulator.sync_writes`, and a file with ``log``), with the model's time, so the
rate a backend streams at can be measured on the bus's side. Units: ticks (4096 a turn,
0.088°), ticks/s, s.
"""

from __future__ import annotations

import math
import os
import select
import threading
import time
import tty
from collections import deque
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import TextIO

from taskrunner.backends.feetech.calibration import LeRobotCalibration
from taskrunner.backends.feetech.protocol import (
    BROADCAST_ID,
    REGISTERS,
    Instruction,
    StatusFlag,
    encode_packet,
    encode_sign_magnitude,
    parse_packet,
)
from taskrunner.errors import ArgumentError

__all__ = ["FAULTS", "SO101_FOLDED", "BusEmulator", "ServoModel", "SyncWrite", "calibrated_servos",
           "so101_servos"]

MODEL_STS3215 = 777
MAX_SPEED = 3400.0  # ticks/s: about 300°/s, the STS3215 at 12 V without load
MAX_ACCELERATION = 60000.0  # ticks/s² when Acceleration is 0 (no ramp)
ACCELERATION_UNIT = 100.0  # ticks/s² per unit of the Acceleration register
TICKS_PER_DEGREE = 4096 / 360.0
_DT = 0.001  # s, model step
FAULTS = ("drop", "corrupt", "wrong_id", "stall", "overload", "overheat", "voltage", "unplug")
_FLAG_FAULTS = {"overload": StatusFlag.OVERLOAD, "overheat": StatusFlag.OVERHEAT,
                "voltage": StatusFlag.VOLTAGE}


@dataclass(frozen=True)
class SyncWrite:
    """A SYNC WRITE the emulator received: when (``time.monotonic()``, and ``clock``: the
    model's time, s), to which register block (its first address: 41 for the goals), for
    which servos."""

    time: float
    clock: float
    address: int
    servo_ids: tuple[int, ...]


@dataclass
class ServoModel:
    """One STS3215 on the bus.

    Attributes:
        servo_id: bus ID.
        actual: output shaft position, ticks before the homing offset (the magnet's).
        gravity: load from gravity at its largest, fraction of the maximum torque.
        gravity_zero: actual position (ticks) where gravity's torque is zero.
        backlash: gear backlash, ticks (1° = 11.4 ticks).
    """

    servo_id: int
    actual: float = 2048.0
    gravity: float = 0.0
    gravity_zero: float = 2048.0
    backlash: float = TICKS_PER_DEGREE
    motor: float = field(default=math.nan)  # motor side of the gears (ticks)
    velocity: float = 0.0  # ticks/s
    load: float = 0.0
    flags: int = 0
    stalled: bool = False
    over_since: float | None = None  # s of model time the load has been over the limit
    registers: bytearray = field(default_factory=lambda: bytearray(256))

    def __post_init__(self) -> None:
        if math.isnan(self.motor):
            self.motor = self.actual
        r = self.registers
        self.put("Model_Number", MODEL_STS3215)
        r[0], r[1] = 3, 10
        self.put("ID", self.servo_id)
        self.put("Max_Position_Limit", 4095)
        self.put("Max_Torque_Limit", 1000)
        self.put("Torque_Limit", 1000)
        self.put("Overload_Torque", 80)  # % of the maximum torque
        self.put("Protection_Time", 20)  # ×10 ms
        self.put("Present_Voltage", 120)
        self.put("Present_Temperature", 31)
        self.put("Goal_Position", self.present())

    # -- registers --------------------------------------------------------------------

    def put(self, name: str, value: int) -> None:
        entry = REGISTERS[name]
        if entry.sign_bit is not None:
            value = encode_sign_magnitude(value, entry.sign_bit)
        self.registers[entry.address:entry.address + entry.size] = value.to_bytes(
            entry.size, "little")

    def get(self, name: str) -> int:
        entry = REGISTERS[name]
        raw = int.from_bytes(self.registers[entry.address:entry.address + entry.size], "little")
        if entry.sign_bit is not None:
            magnitude = raw & ((1 << entry.sign_bit) - 1)
            return -magnitude if raw >> entry.sign_bit & 1 else magnitude
        return raw

    def offset(self) -> int:
        return self.get("Homing_Offset")

    def present(self) -> int:
        """Present_Position: the encoder after the homing offset (Present = Actual − Offset)."""
        return int(round(self.actual - self.offset())) % 4096

    def sync_present(self) -> None:
        """Copy the model's state into the read-only registers."""
        self.put("Present_Position", self.present())
        self.put("Present_Velocity", int(round(max(-32767, min(32767, self.velocity)))))
        self.put("Present_Load", int(round(max(-1.0, min(1.0, self.load)) * 1000)))
        self.put("Status", self.flags)
        self.put("Moving", int(abs(self.velocity) > 1.0))

    # -- physics ----------------------------------------------------------------------

    def advance(self, elapsed: float) -> None:
        """Advance ``elapsed`` seconds in steps of at most 1 ms: the motor toward the goal
        at the speed and acceleration limits, the gears, the load, the protection."""
        torque = bool(self.get("Torque_Enable")) and not self.flags
        # the goal in the output's unwrapped ticks: the servo controls in Present_Position's
        # range (0-4095 after the homing offset) and never turns through its ends
        present = (self.actual - self.offset()) % 4096
        goal = self.actual + (self.get("Goal_Position") - present)
        speed = min(abs(self.get("Goal_Velocity")) or MAX_SPEED, MAX_SPEED)
        acc_units = self.get("Acceleration")
        acc = acc_units * ACCELERATION_UNIT if acc_units else MAX_ACCELERATION
        limit = self.get("Overload_Torque") / 100.0
        protection = self.get("Protection_Time") * 0.01
        while elapsed > 1e-9:
            dt = min(_DT, elapsed)
            elapsed -= dt
            before = (self.motor, self.actual, self.velocity, self.load)
            self._step(dt, torque, goal, speed, acc)
            if abs(self.load) <= limit:
                self.over_since = None
                if (self.motor, self.actual, self.velocity, self.load) == before:
                    return  # at rest: the steps left change nothing
            else:
                self.over_since = (self.over_since or 0.0) + dt
                if self.over_since >= protection:
                    self.flags |= StatusFlag.OVERLOAD  # the servo cuts its torque
                    torque = False

    def _step(self, dt: float, torque: bool, goal: float, speed: float, acc: float) -> None:
        change = 0.0
        if self.stalled or not torque:
            self.velocity = 0.0
            if not torque:
                self.motor = self.actual  # limp: the gears rest where the output is
        else:
            # The STS3215's magnetic encoder is on the output shaft and its loop closes
            # there: the output ends at the goal, the backlash is lost motion on a reversal
            # (the motor crosses the gap while the output waits), not an offset at rest.
            distance = goal - self.actual
            wanted = math.copysign(min(speed, math.sqrt(2 * acc * abs(distance))), distance)
            change = max(-acc * dt, min(acc * dt, wanted - self.velocity))
            self.velocity += change
            step = self.velocity * dt
            if abs(step) >= abs(distance):
                self.motor, self.velocity = self.motor + distance, 0.0
            else:
                self.motor += step
        gravity = self.gravity * math.sin(2 * math.pi * (self.actual - self.gravity_zero) / 4096)
        if torque and not self.stalled:  # limp (no torque), the joint stays where it is
            half = self.backlash / 2
            if abs(gravity) > 0.02:  # gravity holds the output on one side of the gap
                self.actual = self.motor - math.copysign(half, gravity)
            elif self.motor - self.actual > half:
                self.actual = self.motor - half
            elif self.actual - self.motor > half:
                self.actual = self.motor + half
        if self.stalled and torque:
            self.load = math.copysign(1.0, goal - self.actual or 1.0)
        elif torque:
            self.load = max(-1.0, min(1.0, gravity + change / dt / MAX_ACCELERATION * 0.3))
        else:
            self.load = 0.0


SO101_FOLDED = {"shoulder_pan": 0.0, "shoulder_lift": -1.7, "elbow_flex": 1.5,
                "wrist_flex": 0.9, "wrist_roll": 0.0, "gripper": -0.17453}
"""Where an unpowered SO-101 rests, folded on its stops (rad): the SRDF's ``rest`` with the
gripper ``closed``."""
_SO101_GRAVITY = {"shoulder_lift": 0.35, "elbow_flex": 0.2, "wrist_flex": 0.08}


def calibrated_servos(calibration: LeRobotCalibration,
                      positions: Mapping[str, float] | None = None) -> list[ServoModel]:
    """Servos as a calibrated arm has them: each one's Homing_Offset the calibration's,
    standing at ``positions`` (rad, by joint; missing joints: 0, the middle of their
    range), gravity on an SO-101's shoulder, elbow and wrist (by the joint's name, a
    prefix such as ``left_`` allowed)."""
    positions = positions or {}
    servos = []
    for motor in calibration.motors:
        offset = calibration.entries[motor.joint].homing_offset
        present = calibration.to_ticks(motor.joint, float(positions.get(motor.joint, 0.0)))
        gravity = next((g for name, g in _SO101_GRAVITY.items()
                        if motor.joint.endswith(name)), 0.0)
        servo = ServoModel(motor.servo_id, actual=float((present + offset) % 4096),
                           gravity=gravity, gravity_zero=float((1024 + offset) % 4096))
        servo.put("Homing_Offset", offset)
        servo.put("Goal_Position", servo.present())
        servo.sync_present()
        servos.append(servo)
    return servos


def so101_servos(seed: int = 0) -> list[ServoModel]:
    """The SO-101's six STS3215 (IDs 1-6) near the middle of their range; gravity on the
    shoulder, elbow and wrist; ``seed`` varies the starting ticks a little."""
    gravity = {1: 0.0, 2: 0.35, 3: 0.2, 4: 0.08, 5: 0.0, 6: 0.0}
    servos = []
    for servo_id in range(1, 7):
        start = 2048.0 + ((seed * 7919 + servo_id * 104729) % 41) - 20
        servos.append(ServoModel(servo_id, actual=start, gravity=gravity[servo_id],
                                 gravity_zero=1024.0))
    return servos


class BusEmulator:
    """STS servos on a pseudo-terminal, served by a thread.

    Args:
        servos: one model per ID (default: :func:`so101_servos`).
        time_scale: model seconds per wall-clock second.
        log: a text stream that gets one line per SYNC WRITE received: model time (s),
            ``time.monotonic()``, start address, IDs (comma-separated).

    Use as a context manager, or :meth:`start` / :meth:`stop`; :attr:`port` is the pty's
    path once started.
    """

    def __init__(self, servos: Sequence[ServoModel] | None = None, time_scale: float = 1.0,
                 log: TextIO | None = None) -> None:
        if not 0 < time_scale <= 100:
            raise ArgumentError(f"'time_scale' must be in (0, 100] (got {time_scale!r})")
        self.servos = {s.servo_id: s for s in (servos or so101_servos())}
        self.time_scale = float(time_scale)
        self.clock = 0.0  # model time, s
        self._log = log
        self.port = ""
        self.injected_at: float | None = None  # time.monotonic() of the last inject()
        self.packets = 0  # instruction packets received
        # the last SYNC WRITEs received, oldest first (about half an hour at 60 Hz)
        self.sync_writes: deque[SyncWrite] = deque(maxlen=100_000)
        self._faults: dict[str, set[int]] = {}
        self._master = -1
        self._slave = -1
        self._rx = bytearray()
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._thread: threading.Thread | None = None
        self._last = time.monotonic()

    def __enter__(self) -> BusEmulator:
        self.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop()

    def start(self) -> str:
        """Open the pty and serve it; returns its path."""
        self._master, self._slave = os.openpty()
        tty.setraw(self._slave)
        self.port = os.ttyname(self._slave)
        self._last = time.monotonic()
        self._thread = threading.Thread(target=self._serve, name="feetech-bus-sim", daemon=True)
        self._thread.start()
        return self.port

    def stop(self) -> None:
        """Stop serving and close the pty (idempotent)."""
        self._stop.set()
        if self._thread is not None and self._thread is not threading.current_thread():
            self._thread.join(2.0)
        self._close_fds()

    def inject(self, kind: str, servo_id: int | None = None) -> None:
        """Inject a fault (:data:`FAULTS`) on one servo (None: every servo) from now on.

        Raises:
            ArgumentError: an unknown fault or servo.
        """
        if kind not in FAULTS:
            raise ArgumentError(f"'kind' must be one of {', '.join(FAULTS)} (got {kind!r})")
        if servo_id is not None and servo_id not in self.servos:
            raise ArgumentError(f"'servo_id' must be one of {sorted(self.servos)} (got {servo_id})")
        ids = set(self.servos) if servo_id is None else {servo_id}
        with self._lock:
            self._advance()
            self.injected_at = time.monotonic()
            if kind == "unplug":
                self._close_fds()
                return
            for i in ids:
                servo = self.servos[i]
                if kind == "stall":
                    servo.stalled = True
                elif kind in _FLAG_FAULTS:
                    servo.flags |= _FLAG_FAULTS[kind]
                    servo.sync_present()
            self._faults.setdefault(kind, set()).update(ids)

    def clear(self) -> None:
        """Remove every injected link fault and stall (servo flags stay, as on a servo)."""
        with self._lock:
            self._faults.clear()
            for servo in self.servos.values():
                servo.stalled = False

    # -- serving --------------------------------------------------------------------------

    def _close_fds(self) -> None:
        for fd in (self._master, self._slave):
            if fd >= 0:
                try:
                    os.close(fd)
                except OSError:
                    pass
        self._master = self._slave = -1

    def _advance(self) -> None:
        now = time.monotonic()
        elapsed = (now - self._last) * self.time_scale  # all of it (see the module's doc)
        self._last = now
        self.clock += elapsed
        for servo in self.servos.values():
            servo.advance(elapsed)
            servo.sync_present()

    def _serve(self) -> None:
        while not self._stop.is_set():
            master = self._master
            if master < 0:
                return
            try:
                ready, _, _ = select.select([master], [], [], 0.005)
                data = os.read(master, 4096) if ready else b""
            except (OSError, ValueError):
                return  # unplugged or stopped
            with self._lock:
                self._advance()
                self._rx += data
                while True:
                    packet, used = parse_packet(self._rx)
                    del self._rx[:used]
                    if packet is None:
                        break
                    if packet.valid:
                        self.packets += 1
                        self._answer(packet.servo_id, packet.code, packet.params)

    def _reply(self, servo_id: int, params: bytes = b"") -> None:
        if servo_id in self._faults.get("drop", ()):
            return
        servo = self.servos[servo_id]
        reply_id = servo_id
        if servo_id in self._faults.get("wrong_id", ()):
            reply_id = (servo_id + 100) % 0xFD  # an ID nobody on the bus has
        packet = bytearray(encode_packet(reply_id, servo.flags, params))
        if servo_id in self._faults.get("corrupt", ()):
            packet[-1] ^= 0x5A
        try:
            os.write(self._master, bytes(packet))
        except OSError:
            pass

    def _answer(self, servo_id: int, code: int, params: bytes) -> None:
        if code == Instruction.SYNC_WRITE and servo_id == BROADCAST_ID and len(params) >= 2:
            address, length = params[0], params[1]
            body = params[2:]
            record = SyncWrite(time.monotonic(), self.clock, address,
                               tuple(body[0:len(body):length + 1]))
            self.sync_writes.append(record)
            if self._log is not None:
                self._log.write(f"{record.clock:.6f} {record.time:.6f} {address} "
                                f"{','.join(map(str, record.servo_ids))}\n")
                self._log.flush()
            for k in range(0, len(body) - length, length + 1):
                target = self.servos.get(body[k])
                if target is not None:
                    self._write(target, address, body[k + 1:k + 1 + length])
            return
        if code == Instruction.SYNC_READ and servo_id == BROADCAST_ID and len(params) >= 2:
            address, length = params[0], params[1]
            for i in params[2:]:
                if i in self.servos:
                    self._reply(i, bytes(self.servos[i].registers[address:address + length]))
            return
        servo = self.servos.get(servo_id)
        if servo is None:
            return  # nobody with that ID: silence, as on a real bus
        if code == Instruction.PING:
            self._reply(servo_id)
        elif code == Instruction.READ and len(params) == 2:
            self._reply(servo_id, bytes(servo.registers[params[0]:params[0] + params[1]]))
        elif code == Instruction.WRITE and params:
            self._write(servo, params[0], params[1:])
            self._reply(servo_id)

    def _write(self, servo: ServoModel, address: int, data: bytes) -> None:
        readonly = {a for r in REGISTERS.values() if not r.writable
                    for a in range(r.address, r.address + r.size)}
        for k, byte in enumerate(data):
            if address + k not in readonly:
                servo.registers[address + k] = byte
        if address <= REGISTERS["Torque_Enable"].address < address + len(data):
            if servo.get("Torque_Enable"):
                servo.flags &= ~StatusFlag.OVERLOAD  # torque on again clears the overload
                servo.over_since = None
