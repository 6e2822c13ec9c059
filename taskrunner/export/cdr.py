"""A CDR writer: the byte layout ROS 2 sends its messages in (``cdr`` in MCAP).

ROS 2's middleware serialises a message as plain CDR (XCDR1, OMG DDS-XTypes 1.3
section 7.4.1) in little-endian order, after the four-byte RTPS encapsulation header
``00 01 00 00`` (``CDR_LE``, DDSI-RTPS 2.3 section 10.2). Each primitive is aligned to
its own size (8 at most), counted from the end of that header; a string is its length
with the closing NUL (uint32), its UTF-8 bytes and the NUL; a sequence is its element
count (uint32) and the elements. Field order is the order of the ``.msg`` file.

One writer serves both the MCAP files and the live Foxglove feed (the same bytes), so
that what a reader decodes from a file is what a live client gets.
"""

from __future__ import annotations

import struct
from collections.abc import Sequence

import numpy as np

from taskrunner.errors import ArgumentError

__all__ = ["CdrWriter"]

_HEADER = b"\x00\x01\x00\x00"  # CDR_LE, options 0


class CdrWriter:
    """Appends CDR-encoded fields; :meth:`getvalue` gives the message's bytes."""

    def __init__(self) -> None:
        self._buf = bytearray(_HEADER)

    def _align(self, size: int) -> None:
        pad = -(len(self._buf) - len(_HEADER)) % size
        if pad:
            self._buf += b"\x00" * pad

    def bool(self, value: bool) -> None:
        self._buf.append(1 if value else 0)

    def uint8(self, value: int) -> None:
        self._buf += struct.pack("<B", value)

    def int32(self, value: int) -> None:
        self._align(4)
        self._buf += struct.pack("<i", value)

    def uint32(self, value: int) -> None:
        self._align(4)
        self._buf += struct.pack("<I", value)

    def float32(self, value: float) -> None:
        self._align(4)
        self._buf += struct.pack("<f", value)

    def float64(self, value: float) -> None:
        self._align(8)
        self._buf += struct.pack("<d", value)

    def string(self, value: str) -> None:
        data = value.encode("utf-8")
        if b"\x00" in data:
            raise ArgumentError(f"a CDR string cannot hold a NUL character (got {value!r})")
        self.uint32(len(data) + 1)
        self._buf += data + b"\x00"

    def strings(self, values: Sequence[str]) -> None:
        """A ``string[]`` field."""
        self.uint32(len(values))
        for value in values:
            self.string(value)

    def float64s(self, values: Sequence[float] | np.ndarray) -> None:
        """A ``float64[]`` field."""
        array = np.asarray(values, dtype="<f8").ravel()
        self.uint32(len(array))
        if len(array):
            self._align(8)
            self._buf += array.tobytes()

    def uint8s(self, values: bytes) -> None:
        """A ``uint8[]`` field."""
        self.uint32(len(values))
        self._buf += values

    def getvalue(self) -> bytes:
        return bytes(self._buf)
