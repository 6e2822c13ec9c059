"""The STS packet format, its checksum and sign-magnitude registers."""

from __future__ import annotations

import pytest

from taskrunner.backends.feetech.protocol import (
    REGISTERS,
    Instruction,
    decode_sign_magnitude,
    encode_packet,
    encode_sign_magnitude,
    flags_of,
    parse_packet,
    ping_packet,
    read_packet,
    sync_read_packet,
    sync_write_packet,
    write_packet,
)


def test_packets_match_the_manuals_examples() -> None:
    # PING of ID 1 and READ of Present_Position (56, 2 bytes) as the Feetech manual shows
    assert ping_packet(1) == bytes.fromhex("ffff010201fb")
    assert read_packet(1, 56, 2) == bytes.fromhex("ffff0104023802be")
    # WRITE Goal_Position 2048 (0x0800, little-endian) to ID 1
    assert write_packet(1, 42, bytes((0x00, 0x08))) == bytes.fromhex("ffff010503" "2a0008" "c4")


def test_sync_packets_carry_one_block_per_servo() -> None:
    packet = sync_write_packet(42, 2, {1: b"\x00\x08", 2: b"\xff\x0f"})
    assert packet[:5] == bytes((0xFF, 0xFF, 0xFE, 2 + 2 + 2 * 3, Instruction.SYNC_WRITE))
    assert packet[5:-1] == bytes((42, 2, 1, 0x00, 0x08, 2, 0xFF, 0x0F))
    read = sync_read_packet(56, 11, [1, 2, 3])
    assert read[4] == Instruction.SYNC_READ and read[5:-1] == bytes((56, 11, 1, 2, 3))
    with pytest.raises(ValueError, match="block of servo 2 must be 2 bytes"):
        sync_write_packet(42, 2, {2: b"\x00"})


def test_parse_skips_garbage_waits_for_the_rest_and_flags_a_bad_checksum() -> None:
    status = encode_packet(3, 0x20, b"\x10\x02")  # overload flag, two data bytes
    packet, used = parse_packet(b"\x00\x13" + status)
    assert packet is not None and used == 2 + len(status)
    assert (packet.servo_id, packet.code, packet.params, packet.valid) == (3, 0x20, b"\x10\x02",
                                                                           True)
    assert flags_of(packet.code) == ["overload"]
    assert parse_packet(status[:-1]) == (None, 0)  # incomplete: nothing consumed
    corrupted = status[:-1] + bytes((status[-1] ^ 0x01,))
    bad, _ = parse_packet(corrupted)
    assert bad is not None and not bad.valid


def test_sign_magnitude_registers_round_trip() -> None:
    bit = REGISTERS["Homing_Offset"].sign_bit
    assert bit == 11
    assert encode_sign_magnitude(-100, bit) == 0x800 | 100
    for value in (-2047, -1, 0, 1, 2047):
        assert decode_sign_magnitude(encode_sign_magnitude(value, bit), bit) == value
    with pytest.raises(ValueError, match="within ±2047"):
        encode_sign_magnitude(4000, bit)
    assert decode_sign_magnitude(0x400 | 250, REGISTERS["Present_Load"].sign_bit or 0) == -250
