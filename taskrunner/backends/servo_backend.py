"""A backend driving the servo firmware over any :class:`Transport` (serial or HTTP).

A worker thread owns the streaming: it sends a trajectory's ``TRAJ`` points ahead of the
firmware's clock (keeping ``buffered_ms`` above a lead), polls ``STATUS`` for progress and
positions (commanded angles converted back to joints), and ends the execution when the
firmware is idle after the last point. Cancel is ``STOP`` (the servos stay where they are).

*Arms at once on one board.* The firmware has one queue and one clock, so trajectories of
disjoint joints (two arms of a pair, a ``parallel``'s branches) share one stream: each
is a part of it, started at the stream's time of the last point queued when it arrived
(about ``lead_ms`` of firmware time after now: points already queued cannot change),
and every point carries each running part's servos where that part is then, the other
servos where they were last commanded. A part's progress is the firmware's playback time
less its start (0 until it has begun), so a late start shows as an arm behind its
schedule. Cancelling one part sends ``STOP`` (the queue is cleared, every servo stays
where it is) and streams the other parts on from where they stopped.

While a trajectory streams, every reply has a short deadline (``stream_reply_timeout``,
and never later than when the servos would run out of queued points), with no retries:
a stalled, silent or slow link fails the motion within a fraction of a second instead of
after the 1 s idle timeout. Any link failure, timeout, corrupted (checksum) or garbage
reply fails the running execution with a :class:`BackendError`; the link then sends one
``STOP`` and closes: nothing else is sent. A stop by the firmware's own watchdog (STATUS
``watchdog_stops``) fails the execution too. Units: rad, s; firmware angles in degrees,
times in ms.
"""

from __future__ import annotations

import json
import math
import threading
import time
from dataclasses import dataclass
from typing import Any

import numpy as np

from taskrunner.backends.base import BaseBackend, TrajectoryExecution, check_option
from taskrunner.backends.calibration import ServoCalibration, round_degrees
from taskrunner.backends.execution import sample_positions
from taskrunner.backends.servo_protocol import (
    ServoLink,
    StreamPoint,
    Transport,
    error_code,
    parse_traj_reply,
)
from taskrunner.errors import BackendBusyError, BackendError, UnknownNameError
from taskrunner.types import JointTrajectory

__all__ = ["ServoBackend", "ServoOptions"]

_JOIN_TIMEOUT = 2.0  # s
# Shortest reply deadline while streaming (s), when the servos are about to run out of
# points: below this a busy host would fail motions that are merely late.
_MIN_STREAM_TIMEOUT = 0.05


@dataclass(frozen=True)
class ServoOptions:
    """How :class:`ServoBackend` (and the serial/HTTP backends) talk to the firmware.

    Attributes:
        reply_timeout: seconds to wait for one reply line (outside a stream).
        stream_reply_timeout: seconds to wait for one reply while a trajectory streams
            (wall clock, one attempt); also never later than when the servos would run out
            of queued points (but at least 50 ms). With ``poll_period`` it bounds the
            detection of a silent link: at most poll_period + stream_reply_timeout.
        banner_timeout: seconds to wait for the boot banner after opening a serial port.
        lead_ms: firmware ms of trajectory kept queued ahead of the servos (>= 3 ticks).
        poll_period: seconds between STATUS polls while a trajectory runs.
        idle_poll_period: seconds between STATUS polls when idle (fault detection).
        time_scale: firmware seconds per wall-clock second (the host build's ``--speedup``).
        retries: extra attempts of an idempotent HTTP command (STATUS, PING, VERSION).
        start_tolerance: largest accepted distance (rad) between a trajectory's start and
            the joints' positions (converted from the commanded servo angles).
        home_on_start: send HOME once connected and wait until the servos stop there.
        home_timeout: seconds to wait for the homing to finish.
    """

    reply_timeout: float = 1.0
    stream_reply_timeout: float = 0.12
    banner_timeout: float = 2.0
    lead_ms: int = 400
    poll_period: float = 0.04
    idle_poll_period: float = 0.2
    time_scale: float = 1.0
    retries: int = 2
    start_tolerance: float = 2e-3
    home_on_start: bool = False
    home_timeout: float = 30.0

    def __post_init__(self) -> None:
        positive = (lambda v: 0 < v < math.inf, "a positive number")
        for name in ("reply_timeout", "stream_reply_timeout", "poll_period", "idle_poll_period",
                     "time_scale"):
            check_option(name, getattr(self, name), *positive)
        check_option("banner_timeout", self.banner_timeout, lambda v: 0 <= v < math.inf,
                     "a number >= 0")
        check_option("lead_ms", self.lead_ms, lambda v: 0 < v <= 4000, "in (0, 4000] ms")
        check_option("retries", self.retries, lambda v: v >= 0 and v == int(v),
                     "an integer >= 0")
        check_option("start_tolerance", self.start_tolerance, lambda v: v >= 0, "a number >= 0")


@dataclass
class _Part:
    """One trajectory on the stream's timeline: its first sample at ``start_ms``."""

    execution: TrajectoryExecution
    start_ms: float
    owners: list[tuple[int, int]]  # (column of the trajectory, servo)

    @property
    def end_ms(self) -> float:
        return self.start_ms + 1000.0 * self.execution.duration


@dataclass
class _Stream:
    """The firmware's queue: its timeline (ms from the stream's first point) and the
    parts on it. ``sent_ms`` is the time of the last point queued (``sent_at`` rounded
    as the firmware has it), ``degrees`` the angles it commanded."""

    parts: list[_Part]
    degrees: np.ndarray
    sent_ms: float = 0.0
    sent_at: int = 0
    next: int = 0  # points sent
    buffered_ms: int = 0
    buffered_at: float = 0.0  # wall time of the last buffered_ms
    underruns: int = 0
    watchdog_stops: int = 0  # the firmware's count when the stream began

    def pending(self) -> bool:
        """Whether a part has points left to queue."""
        return any(p.end_ms - self.sent_ms >= 0.5 for p in self.parts)

    def next_point(self, tick_ms: int, calibration: ServoCalibration) -> StreamPoint:
        """The next point: a tick after the last, or a part's end if sooner (the grid of
        :func:`~taskrunner.backends.servo_protocol.plan_points` for one part)."""
        t_ms = self.sent_ms + tick_ms
        for part in self.parts:
            if part.end_ms - self.sent_ms >= 0.5:
                t_ms = min(t_ms, part.end_ms)
        at = max(round(t_ms), self.sent_at + 1)
        degrees = np.array(self.degrees, dtype=float)
        for part in self.parts:
            if part.start_ms > t_ms:
                continue
            trajectory = part.execution.trajectory
            elapsed = min(t_ms - part.start_ms, 1000.0 * part.execution.duration) / 1000.0
            q = sample_positions(trajectory, float(trajectory.times[0]) + elapsed)
            for j, servo in part.owners:
                degrees[servo] = float(calibration.raw_degrees(trajectory.names[j], q[j]))
        return StreamPoint(at, at - self.sent_at, round_degrees(degrees))

    def progress(self, part: _Part, buffered: int) -> float:
        """s of ``part`` the servos have played, ``buffered`` ms still queued."""
        played = self.sent_at - buffered - part.start_ms
        return min(max(played / 1000.0, 0.0), part.execution.duration)


class ServoBackend(BaseBackend):
    """Executes trajectories on the servo firmware over ``transport`` (several at once
    when their joints differ: one stream, module text).

    Args:
        joint_names: joints driven; each must be calibrated.
        calibration: see :mod:`taskrunner.backends.calibration`.
        transport: an open link; the handshake (PING, VERSION) runs here.
        options: see :class:`ServoOptions`.

    Raises:
        UnknownNameError: a joint without calibration.
        BackendError: handshake failure or incompatible firmware (the link is closed).
    """

    def __init__(self, joint_names: tuple[str, ...] | list[str], calibration: ServoCalibration,
                 transport: Transport, options: ServoOptions | None = None) -> None:
        self._options = options or ServoOptions()
        self._calibration = calibration
        for name in joint_names:
            if name not in calibration.joint_names:
                transport.close()
                raise UnknownNameError("joint", name, calibration.joint_names)
        self._link = ServoLink(transport)
        try:
            self._version = self._link.handshake(calibration)
            status = self._link.status()
        except BackendError:
            self._link.close()
            raise
        super().__init__(joint_names, start_tolerance=self._options.start_tolerance)
        self._tick_ms = int(self._version["tick_ms"])
        self._status: dict[str, Any] = {}
        self._status_seq = 0
        self._apply_status(status, self._link.sequence)
        self._stream: _Stream | None = None
        self._wake = threading.Condition(self._lock)
        self._thread = threading.Thread(target=self._run, name=f"ServoBackend-{id(self):x}",
                                        daemon=True)
        self._thread.start()
        if self._options.home_on_start:
            try:
                self.command("HOME", wait=self._options.home_timeout / self._options.time_scale)
            except (BackendError, TimeoutError) as exc:
                self.close()
                raise BackendError(f"homing on start failed: {exc}") from None

    # -- public -------------------------------------------------------------------------

    @property
    def version(self) -> dict[str, Any]:
        """The firmware's VERSION object."""
        return dict(self._version)

    @property
    def calibration(self) -> ServoCalibration:
        """The calibration in use."""
        return self._calibration

    def firmware_status(self) -> dict[str, Any]:
        """The latest STATUS object the worker read (``pos`` in degrees, ``moving``, ...)."""
        with self._lock:
            return dict(self._status)

    def execute(self, trajectory: JointTrajectory) -> TrajectoryExecution:
        """Start ``trajectory``; refused (nothing sent) if any sample needs a servo angle
        outside [0, 180]. See :meth:`BaseBackend.execute`.

        Raises:
            TrajectoryRejectedError: out of range (names joint and time), or see base.
            BackendBusyError: one of its joints moves under another trajectory.
            BackendError: the link is down or the backend closed.
        """
        self._calibration.check_trajectory_in_range(trajectory)
        return super().execute(trajectory)

    def command(self, line: str, wait: float | None = 30.0) -> dict[str, Any]:
        """Send one bench command (``HOME``, ``ZERO``, ``SPEED:n``, ``MOVE:a1,…``) while no
        trajectory runs, then wait up to ``wait`` seconds (None: don't) for the servos to
        stop; returns the last STATUS.

        Raises:
            BackendBusyError: a trajectory is running.
            BackendError: an ``err`` reply (the firmware's reason), or the link is down.
            TimeoutError: still moving after ``wait`` seconds.
        """
        with self._lock:
            if self._executions:
                raise BackendBusyError(f"cannot send {line!r} while a trajectory runs")
        self._link.command(line)
        deadline = None if wait is None else time.monotonic() + wait
        while True:
            self._poll_status()
            status = self.firmware_status()
            if not status.get("moving", False) or deadline is None:
                return status
            if time.monotonic() > deadline:
                raise TimeoutError(f"servos still moving {wait} s after {line!r}")
            time.sleep(min(0.05, self._options.poll_period))

    def stop(self) -> None:
        """Cancel the running trajectory and send STOP in any case (e.g. after a HOME)."""
        with self._lock:
            running = bool(self._executions)
            super().stop()
            if not running and not self._closed:
                self._send_stop()

    def close(self) -> None:
        """Stop, end the worker and close the link (idempotent)."""
        with self._lock:
            super().close()
            self._wake.notify_all()
        if threading.current_thread() is not self._thread:
            self._thread.join(_JOIN_TIMEOUT)
        self._link.close()

    # -- BaseBackend hooks (under self._lock) ---------------------------------------------

    def _begin(self, execution: TrajectoryExecution) -> None:
        trajectory, calibration = execution.trajectory, self._calibration
        owners = [(j, calibration.servo_of(n)) for j, n in enumerate(trajectory.names)
                  if n in calibration.servo_joint_names]
        stream = self._stream
        if stream is None:
            self._stream = _Stream([_Part(execution, 0.0, owners)],
                                   np.array(self._status["pos"], dtype=float),
                                   watchdog_stops=int(self._status.get("watchdog_stops", 0)))
        else:  # beside the parts running: from the last point queued on
            stream.parts.append(_Part(execution, stream.sent_ms, owners))
        self._wake.notify_all()

    def _cancel(self, execution: TrajectoryExecution, message: str) -> None:
        if execution.finished:
            return
        stream = self._stream
        others: list[tuple[_Part, float]] = []
        if stream is not None:
            played = stream.sent_at - stream.buffered_ms - (
                (time.monotonic() - stream.buffered_at) * 1000.0 * self._options.time_scale
                if stream.next else 0.0)
            others = [(p, played - p.start_ms) for p in stream.parts
                      if p.execution is not execution and not p.execution.finished]
            self._stream = None  # the worker sends no more points of it
        try:
            self._send_stop()
        except BackendError as exc:
            self._finish(execution, "failed", f"{message}: STOP failed ({exc})", exc)
            return
        super()._cancel(execution, message)
        if others and stream is not None:
            # STOP cleared the queue: the other parts go on from where they are.
            self._stream = _Stream([_Part(p.execution, -max(done, 0.0), p.owners)
                                    for p, done in others],
                                   np.array(self._status["pos"], dtype=float),
                                   underruns=stream.underruns,
                                   watchdog_stops=int(self._status.get("watchdog_stops", 0)))
            self._wake.notify_all()

    # -- internals ------------------------------------------------------------------------

    def _send_stop(self) -> None:
        self._link.command("STOP")
        status = self._link.status()
        self._apply_status(status, self._link.sequence)

    def _apply_status(self, status: dict[str, Any], sequence: int) -> None:
        if sequence < self._status_seq:
            return  # an older reply than what is already applied
        degrees = np.asarray(status["pos"], dtype=float)
        state = self._calibration.from_servo_degrees(degrees).as_dict()
        for i, name in enumerate(self._names):
            self._positions[i] = state[name]
        self._status, self._status_seq = status, sequence

    def _fail(self, exc: BackendError) -> None:
        with self._lock:
            self._link.kill(str(exc))
            self._closed = True
            self._closed_reason = f"stopped: the servo link failed ({exc})"
            self._stream = None
            for execution in list(self._executions):
                message = f"servo link failed during the motion: {exc}"
                self._finish(execution, "failed", message, BackendError(message))

    def _run(self) -> None:
        try:
            while True:
                with self._lock:
                    if self._closed:
                        return
                    stream = self._stream
                    period = (self._options.poll_period if stream is not None
                              else self._options.idle_poll_period)
                    if stream is None or not self._should_send(stream):
                        self._wake.wait(period)
                        if self._closed:
                            return
                        stream = self._stream
                        if stream is not None and not self._should_send(stream):
                            stream = None
                if stream is not None:
                    self._send_point(stream)
                else:
                    self._poll_status()
        except BackendError as exc:
            self._fail(exc)
        except Exception as exc:  # no handle may wait forever
            self._fail(BackendError(f"servo backend worker died: {exc!r}"))

    def _should_send(self, stream: _Stream) -> bool:
        if not stream.pending():
            return False
        drained = (time.monotonic() - stream.buffered_at) * 1000.0 * self._options.time_scale
        return stream.next == 0 or stream.buffered_ms - drained < self._options.lead_ms

    def _reply_deadline(self, stream: _Stream | None) -> float | None:
        """Seconds to wait for a reply now: None (the transport's own) outside a stream."""
        if stream is None or all(p.execution.finished for p in stream.parts):
            return None
        timeout = self._options.stream_reply_timeout
        if stream.next > 0 and stream.pending():  # more to send: the servos must not starve
            drained = (time.monotonic() - stream.buffered_at) * 1000.0 * self._options.time_scale
            runout = (stream.buffered_ms - drained) / 1000.0 / self._options.time_scale
            timeout = min(timeout, max(runout, _MIN_STREAM_TIMEOUT))
        return timeout

    def _send_point(self, stream: _Stream) -> None:
        with self._lock:
            point = stream.next_point(self._tick_ms, self._calibration)
        result = self._link.exchange(point.line, guard=lambda: self._stream is stream,
                                     timeout=self._reply_deadline(stream))
        if result is None:
            return
        reply, _ = result
        if error_code(reply) == 5:  # queue full: resend after a tick
            with self._lock:
                self._wake.wait(self._tick_ms / 1000.0 / self._options.time_scale)
            return
        queued, buffered = parse_traj_reply(self._link.checked(point.line, reply))
        with self._lock:
            if stream.next > 0 and queued == 1:
                stream.underruns += 1
            stream.next += 1
            stream.sent_ms = min([stream.sent_ms + self._tick_ms]
                                 + [p.end_ms for p in stream.parts
                                    if p.end_ms - stream.sent_ms >= 0.5])
            stream.sent_at, stream.degrees = point.at_ms, point.degrees
            stream.buffered_ms, stream.buffered_at = buffered, time.monotonic()
            if self._stream is stream:
                for part in stream.parts:
                    if not part.execution.finished:
                        part.execution.set_progress(stream.progress(part, buffered))

    def _poll_status(self) -> None:
        with self._lock:
            timeout = self._reply_deadline(self._stream)
        result = self._link.exchange("STATUS", timeout=timeout)
        assert result is not None
        reply, sequence = result
        data = self._link.checked("STATUS", reply)
        status = _decode_status(self._link, data)
        with self._lock:
            self._apply_status(status, sequence)
            stream = self._stream
            if stream is None or all(p.execution.finished for p in stream.parts):
                return
            if int(status.get("watchdog_stops", 0)) > stream.watchdog_stops:
                raise BackendError(
                    "the firmware's watchdog stopped the servos (it heard nothing from the "
                    f"host for {self._version.get('watchdog_ms')} ms of firmware time) at "
                    f"{status.get('pos')} deg")
            buffered = int(status.get("buffered_ms", 0))
            if stream.next > 0:
                stream.buffered_ms, stream.buffered_at = buffered, time.monotonic()
                for part in stream.parts:
                    if not part.execution.finished:
                        part.execution.set_progress(stream.progress(part, buffered))
            idle = not stream.pending() and not status.get("moving", True)
            for part in list(stream.parts):
                # A part ends when its last point has played: the firmware idle after the
                # stream's last point, or, while a part ending later still runs, played
                # past its end.
                queued = part.end_ms - stream.sent_ms < 0.5
                played = (stream.next > 0 and stream.sent_at - buffered >= round(part.end_ms)
                          and any(p.end_ms > part.end_ms and not p.execution.finished
                                  for p in stream.parts))
                if part.execution.finished or not (queued and (idle or played)):
                    continue
                part.execution.set_progress(part.execution.duration)
                message = "trajectory executed"
                if stream.underruns:
                    message += f" ({stream.underruns} underrun(s): the motion was delayed)"
                self._finish(part.execution, "succeeded", message)
            stream.parts = [p for p in stream.parts if not p.execution.finished]
            if not stream.parts:
                self._stream = None


def _decode_status(link: ServoLink, data: str) -> dict[str, Any]:
    try:
        status = json.loads(data)
    except json.JSONDecodeError:
        status = None
    if not isinstance(status, dict) or not isinstance(status.get("pos"), list):
        link.kill(f"garbage STATUS: {data!r}")
        raise BackendError(f"garbage STATUS from the servo firmware: {data!r}")
    return status
