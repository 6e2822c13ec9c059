"""The servo firmware's line protocol (firmware/PROTOCOL.md), shared by serial and HTTP.

A :class:`Transport` sends one command line and returns its reply line; :class:`ServoLink`
formats commands and parses replies on top of it; :func:`plan_points` turns a trajectory
into the timed ``TRAJ`` points streamed every ``tick_ms``. Angles: servo degrees; times:
integer milliseconds of firmware time.
"""

from __future__ import annotations

import contextlib
import json
import re
import threading
from dataclasses import dataclass
from typing import Any, Protocol

import numpy as np

from taskrunner.backends.calibration import ServoCalibration, round_degrees
from taskrunner.backends.execution import sample_positions
from taskrunner.errors import BackendError
from taskrunner.types import JointTrajectory

__all__ = ["PROTOCOL_VERSION", "ServoLink", "StreamPoint", "Transport", "crc8", "format_angles",
           "parse_reply", "plan_points", "strip_checksum", "with_checksum"]

PROTOCOL_VERSION = 2
IDEMPOTENT_COMMANDS = frozenset({"STATUS", "PING", "VERSION"})
_REPLY = re.compile(r"(ok)(?: (.*))?|err (\d+) (.*)")
_TRAJ_REPLY = re.compile(r"(\d+) (\d+)")
_CHECKSUM = re.compile(r"(.*)\*([0-9A-Fa-f]{2})", re.DOTALL)


class Transport(Protocol):
    """A link to the firmware: one command line out, its reply line back."""

    def exchange(self, line: str, timeout: float | None = None) -> str:
        """Send ``line`` (no terminator) and return the reply line (no terminator).

        Args:
            line: the command line, checksum included.
            timeout: seconds to wait for the reply, in a single attempt (no retries);
                None: the transport's own timeout (and retries, for idempotent commands).

        Raises:
            BackendError: no reply within the timeout, or the link failed.
        """
        ...

    def abort(self, line: str) -> None:
        """Send ``line`` (a STOP) without waiting for its reply, ignoring any failure, then
        close: the last thing said on a link that failed."""
        ...

    def close(self) -> None:
        """Release the link (idempotent)."""
        ...


def crc8(text: str) -> int:
    """CRC-8 of ``text``'s bytes (polynomial 0x07, init 0, no reflection: the SMBus CRC-8,
    the firmware's ``crc8``; 0xF4 for "123456789")."""
    crc = 0
    for byte in text.encode("ascii", errors="replace"):
        crc = _CRC8_TABLE[crc ^ byte]
    return crc


def _crc8_table() -> tuple[int, ...]:
    table = []
    for value in range(256):
        crc = value
        for _ in range(8):
            crc = ((crc << 1) ^ 0x07) & 0xFF if crc & 0x80 else (crc << 1) & 0xFF
        table.append(crc)
    return tuple(table)


_CRC8_TABLE = _crc8_table()


def with_checksum(line: str) -> str:
    """``line`` with its ``*XX`` checksum suffix (PROTOCOL.md, "Checksums")."""
    return f"{line}*{crc8(line):02X}"


def strip_checksum(line: str) -> str | None:
    """The line without its ``*XX`` suffix when the suffix is there and right, else None
    (no suffix, a malformed one, or a mismatch: the line was corrupted)."""
    match = _CHECKSUM.fullmatch(line)
    if match is None or int(match.group(2), 16) != crc8(match.group(1)):
        return None
    return match.group(1)


def command_name(line: str) -> str:
    """The upper-case command name of a command line (``TRAJ:80:...`` -> ``TRAJ``)."""
    return line.split(":", 1)[0].strip().upper()


def parse_reply(command: str, reply: str) -> str:
    """The data of an ``ok`` reply ("" for a bare ``ok``).

    Raises:
        BackendError: an ``err`` reply (message with code and reason) or a line that is
            not a reply at all (garbage: a broken link or not our firmware).
    """
    match = _REPLY.fullmatch(reply)
    if match is None:
        raise BackendError(f"garbage reply to {command!r} from the servo firmware: {reply!r}")
    if match.group(1):
        return match.group(2) or ""
    raise BackendError(f"servo firmware refused {command!r}: err {match.group(3)} "
                       f"{match.group(4)}", )


def error_code(reply: str) -> int | None:
    """The code of an ``err`` reply, None for anything else."""
    match = _REPLY.fullmatch(reply)
    return int(match.group(3)) if match and match.group(3) else None


def format_angles(degrees: np.ndarray) -> str:
    """Angles as the firmware reads them: 0.01 resolution, shortest form."""
    parts = []
    for value in round_degrees(degrees):
        text = f"{value:.2f}".rstrip("0").rstrip(".")
        parts.append("0" if text in ("-0", "") else text)
    return ",".join(parts)


class ServoLink:
    """Commands and replies over a :class:`Transport`, one exchange at a time (thread-safe).

    Every command goes out with its checksum and every reply must come back with a right
    one: a reply without it, or with a wrong one, is a corrupted line, which fails the
    link like a timeout or garbage does. A failed link sends one last ``STOP`` (its reply
    not awaited) and closes: nothing else is sent after a fault.

    Args:
        transport: the link; closed by :meth:`close`.
    """

    def __init__(self, transport: Transport) -> None:
        self._transport = transport
        self._io = threading.Lock()
        self._dead: str | None = None
        self.sequence = 0  # exchanges done; orders replies from several threads
        self.corrupted_replies = 0  # replies refused for a missing or wrong checksum
        self.aborted = threading.Event()  # set once the last STOP was handed over

    @property
    def dead(self) -> str | None:
        """Why the link is unusable, or None."""
        return self._dead

    def exchange(self, line: str, guard: Any = None,
                 timeout: float | None = None) -> tuple[str, int] | None:
        """Send ``line``, return ``(reply, sequence)`` with the reply's checksum checked
        and removed; None (nothing sent) if ``guard`` is given and returns False under the
        link's lock. ``timeout``: see :meth:`Transport.exchange`.

        Raises:
            BackendError: the link is dead, fails now, or the reply is corrupted (the
                link then stays dead, after a last STOP).
        """
        with self._io:
            if self._dead is not None:
                raise BackendError(f"servo link is down ({self._dead}); not sending {line!r}")
            if guard is not None and not guard():
                return None
            try:
                raw = self._transport.exchange(with_checksum(line), timeout)
            except BackendError as exc:
                self._fault(str(exc))
                raise
            reply = strip_checksum(raw)
            if reply is None:
                self.corrupted_replies += 1
                plain = _CHECKSUM.fullmatch(raw) is None and _REPLY.fullmatch(raw)
                why = ("no checksum: a firmware before protocol 2?" if plain
                       else "missing or wrong checksum")
                message = f"corrupted reply to {line!r} from the servo firmware ({why}): {raw!r}"
                self._fault(message)
                raise BackendError(message)
            self.sequence += 1
            return reply, self.sequence

    def command(self, line: str) -> str:
        """Send ``line`` and return the data of its ``ok`` reply.

        Raises:
            BackendError: link failure, ``err`` reply or garbage (garbage kills the link).
        """
        result = self.exchange(line)
        assert result is not None
        return self.checked(line, result[0])

    def checked(self, line: str, reply: str) -> str:
        """:func:`parse_reply`, killing the link on garbage (nothing more is sent)."""
        if _REPLY.fullmatch(reply) is None:
            self.kill(f"garbage reply to {command_name(line)!r}: {reply!r}")
        return parse_reply(command_name(line), reply)

    def json_command(self, line: str) -> dict[str, Any]:
        """A command answered ``ok {json}`` (STATUS, VERSION): the decoded object."""
        data = self.command(line)
        try:
            value = json.loads(data)
        except json.JSONDecodeError:
            value = None
        if not isinstance(value, dict):
            self.kill(f"garbage reply to {line!r}: {data!r}")
            raise BackendError(f"garbage reply to {line!r} from the servo firmware: {data!r}")
        return value

    def status(self) -> dict[str, Any]:
        """``STATUS`` (keys: mode, moving, powered, pos, target, queued, buffered_ms, ...)."""
        status = self.json_command("STATUS")
        if not isinstance(status.get("pos"), list):
            self.kill(f"STATUS without 'pos': {status}")
            raise BackendError(f"garbage STATUS from the servo firmware: {status}")
        return status

    def kill(self, reason: str) -> None:
        """Mark the link dead after a fault: one last STOP, then closed."""
        with self._io:
            if self._dead is None:
                self._fault(reason)

    def close(self) -> None:
        """Close the transport (idempotent); no STOP."""
        with self._io:
            if self._dead is None:
                self._dead = "closed"
                with contextlib.suppress(Exception):  # closing a broken link must not raise
                    self._transport.close()

    def _fault(self, reason: str) -> None:
        # Under self._io. The STOP is handed to a thread so that the failure is reported
        # at once, not after the STOP's own timeout on a stalled link.
        self._dead = reason
        line = with_checksum("STOP")

        def abort() -> None:
            with contextlib.suppress(Exception):  # a last word on a broken link
                self._transport.abort(line)
            self.aborted.set()

        threading.Thread(target=abort, name="ServoLink-abort", daemon=True).start()

    def handshake(self, calibration: ServoCalibration, attempts: int = 3) -> dict[str, Any]:
        """``PING`` until ``ok pong``, then ``VERSION`` checked against ``calibration``.

        Returns:
            The VERSION object (``tick_ms``, ``queue``, ...).

        Raises:
            BackendError: no pong, wrong protocol, servo count or channels.
        """
        last: Exception | None = None
        for _ in range(attempts):
            try:
                if self.command("PING") == "pong":
                    break
            except BackendError as exc:
                if self._dead is not None:
                    raise
                last = exc
        else:
            raise BackendError(f"servo firmware did not answer PING with 'ok pong' ({last})")
        version = self.json_command("VERSION")
        problems = []
        if version.get("protocol") != PROTOCOL_VERSION:
            problems.append(f"protocol {version.get('protocol')!r} (need {PROTOCOL_VERSION})")
        if version.get("servos") != len(calibration.servo_joint_names):
            problems.append(f"{version.get('servos')!r} servos (calibration has "
                            f"{len(calibration.servo_joint_names)})")
        if list(version.get("channels") or []) != list(calibration.channels):
            problems.append(f"channels {version.get('channels')!r} (calibration has "
                            f"{list(calibration.channels)})")
        tick = version.get("tick_ms")
        if not isinstance(tick, int) or tick <= 0 or not isinstance(version.get("queue"), int):
            problems.append(f"tick_ms {tick!r} / queue {version.get('queue')!r}")
        if problems:
            self.kill("incompatible firmware")
            raise BackendError("incompatible servo firmware: " + "; ".join(problems))
        return version


@dataclass(frozen=True)
class StreamPoint:
    """One ``TRAJ`` point: ``at_ms`` after the timeline's start, ``dt_ms`` after the
    previous point, at ``degrees`` (servo order)."""

    at_ms: int
    dt_ms: int
    degrees: np.ndarray

    @property
    def line(self) -> str:
        """The command line."""
        return f"TRAJ:{self.dt_ms}:{format_angles(self.degrees)}"


def plan_points(trajectory: JointTrajectory, calibration: ServoCalibration,
                base_degrees: np.ndarray, tick_ms: int) -> list[StreamPoint]:
    """The points streaming ``trajectory`` (host guide, PROTOCOL.md): sampled at
    ``tick_ms`` k (k >= 1) after its first sample, plus its last sample if off the grid.

    Args:
        trajectory: checked against the calibration's range beforehand.
        calibration: the arm's calibration.
        base_degrees: angles (servo order) of the servos the trajectory does not move.
        tick_ms: firmware tick (VERSION ``tick_ms``).
    """
    t0 = float(trajectory.times[0])
    total_ms = (float(trajectory.times[-1]) - t0) * 1000.0
    owners = [(j, calibration.servo_of(n)) for j, n in enumerate(trajectory.names)
              if n in calibration.servo_joint_names]
    grid: list[float] = [float(tick_ms * k) for k in range(1, int(total_ms // tick_ms) + 1)]
    if not grid or total_ms - grid[-1] >= 0.5:
        grid.append(total_ms)
    points: list[StreamPoint] = []
    previous = 0
    for t_ms in grid:
        at = round(t_ms)
        if at <= previous:
            continue
        q = sample_positions(trajectory, t0 + t_ms / 1000.0)
        degrees = np.array(base_degrees, dtype=float)
        for j, servo in owners:
            degrees[servo] = float(calibration.raw_degrees(trajectory.names[j], q[j]))
        points.append(StreamPoint(at, at - previous, round_degrees(degrees)))
        previous = at
    return points


def parse_traj_reply(data: str) -> tuple[int, int]:
    """``<queued> <buffered_ms>`` of a TRAJ reply.

    Raises:
        BackendError: not two integers.
    """
    match = _TRAJ_REPLY.fullmatch(data)
    if match is None:
        raise BackendError(f"garbage reply to TRAJ from the servo firmware: 'ok {data}'")
    return int(match.group(1)), int(match.group(2))
