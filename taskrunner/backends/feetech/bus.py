"""A servo bus: the layer the bus-servo backend talks to, and its Feetech STS implementation.

:class:`ServoBus` is what :class:`~taskrunner.backends.feetech.backend.FeetechBackend`
needs from a bus of position servos, in ticks: ping, read and write a named register,
write every goal at once (sync write), read every servo's state at once (sync read), torque
on or off. :class:`FeetechBus` speaks the STS protocol (:mod:`.protocol`) over pyserial.
A Dynamixel 2.0 bus would be a second class with the same methods (docs/so101-hardware.md).

Every exchange has one short deadline and no retry: a missing, corrupted or foreign reply
raises :class:`~taskrunner.errors.BusFaultError` at once, and the input is flushed so the
next exchange starts clean. A port that fails (the USB adapter pulled out) raises it with
kind ``unplugged``. Units: ticks (0-4095 a turn), ticks/s, load as a fraction of the
servo's maximum torque, V, °C.
"""

from __future__ import annotations

import enum
import os
import select
import termios
import threading
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any, Protocol

import serial as pyserial

from taskrunner.backends.feetech.protocol import (
    REGISTERS,
    STATUS_BLOCK,
    Packet,
    decode_sign_magnitude,
    encode_sign_magnitude,
    flags_of,
    from_bytes,
    parse_packet,
    ping_packet,
    read_packet,
    sync_read_packet,
    sync_write_packet,
    to_bytes,
    write_packet,
)
from taskrunner.errors import BusFaultError, UnknownNameError

__all__ = ["FaultKind", "FeetechBus", "ServoBus", "ServoState"]


class FaultKind(enum.StrEnum):
    """What went wrong on a bus (:attr:`BusFaultError.kind`)."""

    NO_REPLY = "no_reply"
    BAD_CHECKSUM = "bad_checksum"
    WRONG_ID = "wrong_id"
    UNPLUGGED = "unplugged"
    VOLTAGE = "voltage"
    ANGLE = "angle"
    OVERHEAT = "overheat"
    OVERCURRENT = "overcurrent"
    OVERLOAD = "overload"
    STALL = "stall"
    TRACKING = "tracking"


@dataclass(frozen=True)
class ServoState:
    """One servo as read in one cycle.

    Attributes:
        servo_id: bus ID.
        position: present position, ticks (after the servo's homing offset).
        velocity: ticks/s.
        load: signed fraction of the maximum torque (-1 … 1).
        voltage: V.
        temperature: °C.
        status: the status packet's error byte or'ed with the Status register
            (:class:`~.protocol.StatusFlag` bits).
        moving: the servo says it is moving.
    """

    servo_id: int
    position: int
    velocity: int
    load: float
    voltage: float
    temperature: int
    status: int
    moving: bool

    @property
    def flags(self) -> list[str]:
        """Names of the status flags set (``["overload"]``)."""
        return flags_of(self.status)


class ServoBus(Protocol):
    """A bus of position servos addressed by ID (ticks, ticks/s)."""

    resolution: int  # ticks per turn

    def ping(self, servo_id: int) -> int:
        """The servo's model number. Raises BusFaultError (no reply, …)."""
        ...

    def read(self, servo_id: int, register: str) -> int:
        """A register's value (signed where the register is)."""
        ...

    def write(self, servo_id: int, register: str, value: int) -> None:
        """Write a register and wait for the servo's acknowledgement."""
        ...

    def write_goals(self, goals: Mapping[int, int], speed: int = 0,
                    acceleration: int = 0) -> None:
        """Every servo's goal position at once, with a speed (ticks/s, 0: the servo's
        maximum) and an acceleration (servo units, 0: its maximum); no reply."""
        ...

    def read_states(self, servo_ids: Sequence[int]) -> dict[int, ServoState]:
        """Every listed servo's state, in one exchange."""
        ...

    def set_torque(self, servo_ids: Sequence[int], enabled: bool) -> None:
        """Torque on or off on the listed servos at once (no reply)."""
        ...

    def close(self) -> None:
        """Release the port (idempotent)."""
        ...


_LOAD_FULL = 1000  # Present_Load counts 0.1 % of the maximum torque


class FeetechBus:
    """The STS protocol over a serial port (1 Mbaud by default, the SO-101's).

    Args:
        port: device path (``/dev/ttyACM0``, the emulator's pty), or an open pyserial-like
            object (``read``, ``write``, ``reset_input_buffer``, ``close``, ``timeout``).
        baud: baud rate.
        reply_timeout: seconds to wait for one reply (a sync read: for every reply).

    Raises:
        BusFaultError: the port cannot be opened (kind ``unplugged``; names the port).
    """

    resolution = 4096

    def __init__(self, port: str | Any, baud: int = 1_000_000,
                 reply_timeout: float = 0.04) -> None:
        self._timeout = float(reply_timeout)
        if isinstance(port, str):
            self.port_name = port
            try:
                self._serial = pyserial.Serial(port, baud, timeout=reply_timeout,
                                               write_timeout=reply_timeout)
            except (pyserial.SerialException, OSError, ValueError) as exc:
                raise BusFaultError(f"cannot open the servo bus on {port!r}: {exc}",
                                    FaultKind.UNPLUGGED) from None
            # written to directly (see _write_all); pyserial keeps it non-blocking
            self._fd: int | None = self._serial.fileno()
        else:
            self.port_name = str(getattr(port, "port", port))
            self._serial = port
            self._fd = None
        self._rx = bytearray()
        self._lock = threading.Lock()
        self._closed = False

    # -- ServoBus -------------------------------------------------------------------------

    def ping(self, servo_id: int) -> int:
        with self._lock:
            self._send(ping_packet(servo_id))
            self._receive(servo_id, time.monotonic() + self._timeout, "PING")
            self._send(read_packet(servo_id, REGISTERS["Model_Number"].address, 2))
            reply = self._receive(servo_id, time.monotonic() + self._timeout, "READ")
        return from_bytes(reply.params)

    def read(self, servo_id: int, register: str) -> int:
        entry = _register(register)
        with self._lock:
            self._send(read_packet(servo_id, entry.address, entry.size))
            reply = self._receive(servo_id, time.monotonic() + self._timeout, f"READ {register}")
        if len(reply.params) != entry.size:
            raise self._fault(FaultKind.BAD_CHECKSUM, servo_id,
                              f"{len(reply.params)} byte(s) for READ {register}, "
                              f"{entry.size} expected")
        raw = from_bytes(reply.params)
        return raw if entry.sign_bit is None else decode_sign_magnitude(raw, entry.sign_bit)

    def write(self, servo_id: int, register: str, value: int) -> None:
        entry = _register(register)
        if not entry.writable:
            raise UnknownNameError("writable register", register,
                                   [n for n, r in REGISTERS.items() if r.writable])
        raw = value if entry.sign_bit is None else encode_sign_magnitude(value, entry.sign_bit)
        with self._lock:
            self._send(write_packet(servo_id, entry.address, to_bytes(raw, entry.size)))
            self._receive(servo_id, time.monotonic() + self._timeout, f"WRITE {register}")

    def write_goals(self, goals: Mapping[int, int], speed: int = 0,
                    acceleration: int = 0) -> None:
        # Acceleration (41), Goal_Position (42), Goal_Time (44), Goal_Velocity (46)
        tail = to_bytes(0, 2) + to_bytes(encode_sign_magnitude(int(speed), 15), 2)
        blocks = {i: bytes((int(acceleration),)) + to_bytes(int(g), 2) + tail
                  for i, g in goals.items()}
        with self._lock:
            self._send(sync_write_packet(REGISTERS["Acceleration"].address, 7, blocks))

    def read_states(self, servo_ids: Sequence[int]) -> dict[int, ServoState]:
        address, length = STATUS_BLOCK
        states = {}
        with self._lock:
            self._send(sync_read_packet(address, length, servo_ids))
            deadline = time.monotonic() + self._timeout
            for k, servo_id in enumerate(servo_ids):
                reply = self._receive(servo_id, deadline, "SYNC READ", servo_ids[k + 1:])
                if len(reply.params) != length:
                    raise self._fault(FaultKind.BAD_CHECKSUM, servo_id,
                                      f"{len(reply.params)} byte(s) in its SYNC READ reply, "
                                      f"{length} expected")
                states[servo_id] = _decode_state(servo_id, reply)
        return states

    def set_torque(self, servo_ids: Sequence[int], enabled: bool) -> None:
        blocks = {i: bytes((1 if enabled else 0,)) for i in servo_ids}
        with self._lock:
            self._send(sync_write_packet(REGISTERS["Torque_Enable"].address, 1, blocks))

    def close(self) -> None:
        self._closed = True
        try:
            self._serial.close()
        except (pyserial.SerialException, OSError):
            pass

    # -- internals ------------------------------------------------------------------------

    def _fault(self, kind: FaultKind, servo_id: int | None, detail: str) -> BusFaultError:
        self._rx.clear()
        try:
            self._serial.reset_input_buffer()
        except (pyserial.SerialException, OSError, TypeError, termios.error):
            pass  # a port that is gone has nothing to flush
        who = f"servo {servo_id}" if servo_id is not None else "the bus"
        return BusFaultError(f"{kind.value.replace('_', ' ')} from {who} on "
                             f"{self.port_name!r}: {detail}", kind, servo_id)

    def _send(self, packet: bytes) -> None:
        if self._closed:
            raise BusFaultError(f"the servo bus on {self.port_name!r} is closed",
                                FaultKind.UNPLUGGED)
        try:
            if self._fd is None:
                self._serial.write(packet)
            else:
                self._write_all(self._fd, packet)
        except (pyserial.SerialException, OSError, TypeError) as exc:
            raise self._fault(FaultKind.UNPLUGGED, None, f"write failed ({exc})") from None

    def _write_all(self, fd: int, packet: bytes) -> None:
        """Every byte of ``packet`` to the port, or a fault once the port has taken none
        for the reply timeout. (pyserial's write with a timeout raises 'Write timeout' when
        its thread was kept from running past the timeout, every byte already written: a
        busy host read as an unplugged adapter.)"""
        rest = memoryview(packet)
        deadline = time.monotonic() + self._timeout
        while True:
            try:
                rest = rest[os.write(fd, rest):]
            except BlockingIOError:
                pass  # the port's buffer is full: wait for room below
            if not rest:
                return
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                raise self._fault(FaultKind.UNPLUGGED, None,
                                  f"write failed ({len(rest)} of {len(packet)} byte(s) not "
                                  f"taken within {1000 * self._timeout:.0f} ms)")
            select.select([], [fd], [], remaining)

    def _receive(self, servo_id: int, deadline: float, what: str,
                 later: Sequence[int] = ()) -> Packet:
        """The reply of ``servo_id``; ``later``: the servos expected to answer after it (a
        reply from one of them means ``servo_id`` said nothing)."""
        drained = False
        while True:
            packet, used = parse_packet(self._rx)
            del self._rx[:used]
            if packet is not None:
                if not packet.valid:
                    raise self._fault(FaultKind.BAD_CHECKSUM, servo_id,
                                      f"the reply to {what} failed its checksum")
                if packet.servo_id in later:
                    raise self._fault(FaultKind.NO_REPLY, servo_id,
                                      f"no reply to {what}: servo {packet.servo_id} answered "
                                      "in its place")
                if packet.servo_id != servo_id:
                    raise self._fault(FaultKind.WRONG_ID, servo_id,
                                      f"the reply to {what} came from ID {packet.servo_id}")
                return packet
            remaining = deadline - time.monotonic()
            if remaining <= 0 and not drained:
                # A thread kept from running past the deadline (a busy host) may find the
                # reply already waiting: take what the port holds once before saying none.
                drained = True
                try:
                    waiting = int(getattr(self._serial, "in_waiting", 0) or 0)
                    self._rx += self._serial.read(waiting) if waiting else b""
                except (pyserial.SerialException, OSError, TypeError) as exc:
                    raise self._fault(FaultKind.UNPLUGGED, None, f"read failed ({exc})") from None
                if waiting:
                    continue
            if remaining <= 0:
                raise self._fault(FaultKind.NO_REPLY, servo_id,
                                  f"no reply to {what} within {1000 * self._timeout:.0f} ms")
            try:
                self._serial.timeout = remaining
                chunk = self._serial.read(max(1, getattr(self._serial, "in_waiting", 0) or 0))
            except (pyserial.SerialException, OSError, TypeError) as exc:
                raise self._fault(FaultKind.UNPLUGGED, None, f"read failed ({exc})") from None
            self._rx += chunk


def _register(name: str) -> Any:
    entry = REGISTERS.get(name)
    if entry is None:
        raise UnknownNameError("register", name, list(REGISTERS))
    return entry


def _decode_state(servo_id: int, reply: Packet) -> ServoState:
    p = reply.params  # the STATUS_BLOCK, from address 56
    load = decode_sign_magnitude(from_bytes(p[4:6]), 10) / _LOAD_FULL
    return ServoState(servo_id=servo_id, position=from_bytes(p[0:2]),
                      velocity=decode_sign_magnitude(from_bytes(p[2:4]), 15),
                      load=load, voltage=p[6] / 10.0, temperature=p[7],
                      status=reply.code | p[9], moving=bool(p[10]))
