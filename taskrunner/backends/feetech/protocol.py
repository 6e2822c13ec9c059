"""The Feetech STS/SCS serial bus protocol: packets, checksum, the STS3215 control table.

Every packet, instruction or status, is ``FF FF ID LEN X P1 … Pn CHK`` where ``LEN = n + 2``,
``X`` is the instruction (host to servo) or the servo's error byte (servo to host), and
``CHK = ~(ID + LEN + X + P1 + … + Pn) & 0xFF``. Multi-byte registers are little-endian on
the STS/SMS series (big-endian on the older SCS series); a few registers hold a
sign-magnitude value (the sign in one bit). ``SYNC WRITE`` (0x83, to the broadcast ID 0xFE)
writes one block per servo and gets no reply; ``SYNC READ`` (0x82) makes each listed servo
answer in turn with a status packet of its block.

Sources: the Feetech SMS/STS user manual (memory table, instruction set), as tabulated in
LeRobot's ``motors/feetech/tables.py`` (Apache-2.0). Written here from those tables; no
code taken.
"""

from __future__ import annotations

import enum
from collections.abc import Iterable, Mapping
from dataclasses import dataclass

from taskrunner.errors import ArgumentError

__all__ = [
    "BROADCAST_ID",
    "REGISTERS",
    "STATUS_BLOCK",
    "Instruction",
    "Packet",
    "Register",
    "StatusFlag",
    "checksum",
    "decode_sign_magnitude",
    "encode_packet",
    "encode_sign_magnitude",
    "flags_of",
    "from_bytes",
    "parse_packet",
    "ping_packet",
    "read_packet",
    "sync_read_packet",
    "sync_write_packet",
    "to_bytes",
    "write_packet",
]

HEADER = b"\xff\xff"
BROADCAST_ID = 0xFE
MAX_ID = 0xFD


class Instruction(enum.IntEnum):
    """Instruction codes of the STS/SCS protocol."""

    PING = 0x01
    READ = 0x02
    WRITE = 0x03
    REG_WRITE = 0x04
    ACTION = 0x05
    RESET = 0x06
    SYNC_READ = 0x82
    SYNC_WRITE = 0x83


class StatusFlag(enum.IntFlag):
    """Bits of a status packet's error byte (also the ``Status`` register, 65)."""

    VOLTAGE = 0x01
    ANGLE = 0x02  # the magnetic angle sensor
    OVERHEAT = 0x04
    OVERCURRENT = 0x08
    OVERLOAD = 0x20


def flags_of(error: int) -> list[str]:
    """Names of the flags set in ``error``, lower case (``["overload"]``)."""
    return [str(flag.name).lower() for flag in StatusFlag if error & flag]


@dataclass(frozen=True)
class Register:
    """One entry of a servo's control table.

    Attributes:
        address: first byte.
        size: bytes (1 or 2).
        sign_bit: bit holding the sign of a sign-magnitude value, None for unsigned.
        writable: False for read-only registers.
    """

    address: int
    size: int
    sign_bit: int | None = None
    writable: bool = True


def _table() -> dict[str, Register]:
    rw = {
        "ID": (5, 1), "Baud_Rate": (6, 1), "Return_Delay_Time": (7, 1),
        "Response_Status_Level": (8, 1), "Min_Position_Limit": (9, 2),
        "Max_Position_Limit": (11, 2), "Max_Temperature_Limit": (13, 1),
        "Max_Voltage_Limit": (14, 1), "Min_Voltage_Limit": (15, 1), "Max_Torque_Limit": (16, 2),
        "Phase": (18, 1), "Unloading_Condition": (19, 1), "LED_Alarm_Condition": (20, 1),
        "P_Coefficient": (21, 1), "D_Coefficient": (22, 1), "I_Coefficient": (23, 1),
        "Minimum_Startup_Force": (24, 2), "CW_Dead_Zone": (26, 1), "CCW_Dead_Zone": (27, 1),
        "Protection_Current": (28, 2), "Angular_Resolution": (30, 1), "Homing_Offset": (31, 2),
        "Operating_Mode": (33, 1), "Protective_Torque": (34, 1), "Protection_Time": (35, 1),
        "Overload_Torque": (36, 1), "Torque_Enable": (40, 1), "Acceleration": (41, 1),
        "Goal_Position": (42, 2), "Goal_Time": (44, 2), "Goal_Velocity": (46, 2),
        "Torque_Limit": (48, 2), "Lock": (55, 1),
    }
    ro = {
        "Firmware_Major_Version": (0, 1), "Firmware_Minor_Version": (1, 1),
        "Model_Number": (3, 2), "Present_Position": (56, 2), "Present_Velocity": (58, 2),
        "Present_Load": (60, 2), "Present_Voltage": (62, 1), "Present_Temperature": (63, 1),
        "Status": (65, 1), "Moving": (66, 1), "Present_Current": (69, 2),
    }
    signs = {"Homing_Offset": 11, "Goal_Velocity": 15, "Present_Velocity": 15,
             "Present_Load": 10}
    table = {name: Register(a, s, signs.get(name)) for name, (a, s) in rw.items()}
    table.update({name: Register(a, s, signs.get(name), writable=False)
                  for name, (a, s) in ro.items()})
    return table


REGISTERS: Mapping[str, Register] = _table()
"""The STS3215's control table (EEPROM 0-39, SRAM 40-70), by LeRobot's register names."""

STATUS_BLOCK = (56, 11)
"""Address and length of the block read every cycle: position, velocity, load, voltage,
temperature, (async-write flag), status, moving."""


def checksum(body: Iterable[int]) -> int:
    """``~sum & 0xFF`` of ID, LEN, instruction/error and parameters."""
    return (~sum(body)) & 0xFF


def encode_packet(servo_id: int, code: int, params: bytes = b"") -> bytes:
    """A packet (instruction, or status when ``code`` is an error byte) with its checksum."""
    if not 0 <= servo_id <= BROADCAST_ID:
        raise ArgumentError(f"'servo_id' must be in [0, {BROADCAST_ID}] (got {servo_id})")
    if len(params) > 250:
        raise ArgumentError(f"'params' must be at most 250 bytes (got {len(params)})")
    body = bytes((servo_id, len(params) + 2, code)) + params
    return HEADER + body + bytes((checksum(body),))


@dataclass(frozen=True)
class Packet:
    """A parsed packet. ``code`` is the instruction (host to servo) or the error byte
    (servo to host); ``valid`` is False when the checksum does not match."""

    servo_id: int
    code: int
    params: bytes
    valid: bool = True


def parse_packet(buffer: bytes | bytearray) -> tuple[Packet | None, int]:
    """The first complete packet in ``buffer`` and how many bytes it and any garbage before
    it took; ``(None, n)`` when no full packet is there yet (``n`` bytes of garbage may be
    dropped). A packet whose checksum fails comes back with ``valid=False``."""
    start = bytes(buffer).find(HEADER)
    while start >= 0 and start + 2 < len(buffer) and buffer[start + 2] == 0xFF:
        start += 1  # FF FF FF ...: the header is the last two of a run of FF
    if start < 0:
        keep = 1 if buffer[-1:] == b"\xff" else 0
        return None, len(buffer) - keep
    if len(buffer) < start + 4:
        return None, start
    length = buffer[start + 3]
    end = start + 4 + length
    if length < 2:  # no room for code and checksum: a corrupted header
        return Packet(buffer[start + 2], 0, b"", valid=False), start + 4
    if len(buffer) < end:
        return None, start
    body = bytes(buffer[start + 2:end - 1])
    packet = Packet(body[0], body[2], body[3:], valid=checksum(body) == buffer[end - 1])
    return packet, end


def to_bytes(value: int, size: int) -> bytes:
    """``value`` as ``size`` little-endian bytes (STS/SMS byte order)."""
    if not 0 <= value < (1 << (8 * size)):
        raise ArgumentError(f"'value' must fit {size} unsigned byte(s) (got {value})")
    return value.to_bytes(size, "little")


def from_bytes(data: bytes) -> int:
    """The little-endian unsigned value of ``data``."""
    return int.from_bytes(data, "little")


def encode_sign_magnitude(value: int, sign_bit: int) -> int:
    """``value`` with its sign in bit ``sign_bit`` and its magnitude below it."""
    limit = (1 << sign_bit) - 1
    if abs(value) > limit:
        raise ArgumentError(f"'value' must be within ±{limit} (got {value})")
    return (1 << sign_bit) | -value if value < 0 else value


def decode_sign_magnitude(raw: int, sign_bit: int) -> int:
    """The signed value of a sign-magnitude register."""
    magnitude = raw & ((1 << sign_bit) - 1)
    return -magnitude if raw >> sign_bit & 1 else magnitude


def ping_packet(servo_id: int) -> bytes:
    """``PING``: the servo answers with an empty status packet."""
    return encode_packet(servo_id, Instruction.PING)


def read_packet(servo_id: int, address: int, length: int) -> bytes:
    """``READ`` ``length`` bytes from ``address``."""
    return encode_packet(servo_id, Instruction.READ, bytes((address, length)))


def write_packet(servo_id: int, address: int, data: bytes) -> bytes:
    """``WRITE`` ``data`` at ``address`` (the servo answers unless broadcast)."""
    return encode_packet(servo_id, Instruction.WRITE, bytes((address,)) + data)


def sync_write_packet(address: int, length: int, blocks: Mapping[int, bytes]) -> bytes:
    """``SYNC WRITE``: one ``length``-byte block per servo ID, no reply."""
    params = bytearray((address, length))
    for servo_id, data in blocks.items():
        if len(data) != length:
            raise ArgumentError(f"block of servo {servo_id} must be {length} bytes "
                             f"(got {len(data)})")
        params.append(servo_id)
        params += data
    return encode_packet(BROADCAST_ID, Instruction.SYNC_WRITE, bytes(params))


def sync_read_packet(address: int, length: int, servo_ids: Iterable[int]) -> bytes:
    """``SYNC READ``: each listed servo answers in turn with its ``length`` bytes."""
    return encode_packet(BROADCAST_ID, Instruction.SYNC_READ,
                         bytes((address, length, *servo_ids)))
