"""A backend for an arm of bus servos: trajectories streamed as sync writes, states read back.

A worker thread runs a fixed-rate cycle (``rate_hz``, 50 by default) over a
:class:`~taskrunner.backends.feetech.bus.ServoBus`: while a trajectory runs, it writes
every servo's goal (the trajectory sampled at the cycle's time, converted to ticks
through the LeRobot calibration) in one sync write, then reads every servo's position,
load and status in one sync read; idle, it only reads. Each cycle updates the joint
positions and the tracking error per joint (the goal written one cycle earlier minus the
position read), reported in the execution's message and by :meth:`FeetechBackend.tracking`.

Faults end everything at once: a link fault (no reply, bad checksum, wrong ID, unplugged
adapter) raised by the bus, a status flag set by a servo (overload, overheat, voltage,
angle sensor, over-current), a stall (the load at ``stall_load`` or more for
``stall_cycles`` cycles while the goal is not reached) or a tracking error over
``max_tracking_error``. The backend then sends a stop (``on_fault``: ``"hold"`` writes
every servo's present position as its goal; ``"torque_off"`` cuts the torque: the arm
falls), fails the running execution with a :class:`~taskrunner.errors.BusFaultError`
naming the joint, servo and fault, and refuses further trajectories. Detection takes at
most one cycle plus one reply timeout (20 + 40 ms by default). Units: rad, s.
"""

from __future__ import annotations

import math
import threading
import time
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from taskrunner.backends.base import BaseBackend, TrajectoryExecution, check_option
from taskrunner.backends.execution import sample_positions
from taskrunner.backends.feetech.bus import FaultKind, ServoBus, ServoState
from taskrunner.backends.feetech.calibration import LeRobotCalibration
from taskrunner.errors import (
    ArgumentError,
    BackendBusyError,
    BusFaultError,
    TrajectoryRejectedError,
)
from taskrunner.types import JointTrajectory

__all__ = ["FaultRecord", "FeetechBackend", "FeetechOptions", "JointTracking"]

_JOIN_TIMEOUT = 2.0  # s
_KINDS = frozenset(k.value for k in FaultKind)


@dataclass(frozen=True)
class FeetechOptions:
    """How :class:`FeetechBackend` drives the bus.

    Attributes:
        rate_hz: cycles a second (sync write + sync read), at least 50.
        on_fault: the stop sent on a fault: ``"hold"`` (present positions as goals) or
            ``"torque_off"``.
        speed: Goal_Velocity written with every goal, ticks/s (0: the servo's maximum).
        acceleration: Acceleration written with every goal, servo units of 100 ticks/s²
            (0: the servo's maximum).
        start_tolerance: largest distance (rad) between a trajectory's first sample and
            the joints' present positions (backlash and the tick are about 0.02 rad).
        settle_tolerance: distance (rad) to the last sample under which a joint has arrived.
        settle_timeout: seconds after the trajectory's end for every joint to arrive.
        max_tracking_error: a tracking error (rad) that is a fault; None: never.
        stall_load: load (fraction of the maximum torque) that, held for ``stall_cycles``
            cycles while the goal is not reached, is a stall.
        stall_cycles: see ``stall_load``.
    """

    rate_hz: float = 50.0
    on_fault: Literal["hold", "torque_off"] = "hold"
    speed: int = 0
    acceleration: int = 0
    start_tolerance: float = 0.05
    settle_tolerance: float = 0.035
    settle_timeout: float = 1.0
    max_tracking_error: float | None = 0.35
    stall_load: float = 0.95
    stall_cycles: int = 2

    def __post_init__(self) -> None:
        check_option("rate_hz", self.rate_hz, lambda v: 50 <= v <= 1000, "in [50, 1000] Hz")
        if self.on_fault not in ("hold", "torque_off"):
            raise ArgumentError(f"'on_fault' must be 'hold' or 'torque_off' (got {self.on_fault!r})")
        check_option("speed", self.speed, lambda v: 0 <= v <= 32767 and v == int(v),
                     "an integer in [0, 32767] ticks/s")
        check_option("acceleration", self.acceleration,
                     lambda v: 0 <= v <= 254 and v == int(v), "an integer in [0, 254]")
        for name in ("start_tolerance", "settle_tolerance", "settle_timeout"):
            check_option(name, getattr(self, name), lambda v: 0 < v < math.inf,
                         "a positive number")
        check_option("max_tracking_error", self.max_tracking_error,
                     lambda v: 0 < v < math.inf, "a positive number or None", optional=True)
        check_option("stall_load", self.stall_load, lambda v: 0 < v <= 1, "in (0, 1]")
        check_option("stall_cycles", self.stall_cycles, lambda v: v >= 1 and v == int(v),
                     "an integer >= 1")


@dataclass
class JointTracking:
    """Tracking error of one joint over an execution (rad): largest and RMS."""

    largest: float = 0.0
    squares: float = 0.0
    samples: int = 0

    @property
    def rms(self) -> float:
        return math.sqrt(self.squares / self.samples) if self.samples else 0.0

    def add(self, error: float) -> None:
        self.largest = max(self.largest, abs(error))
        self.squares += error * error
        self.samples += 1


@dataclass(frozen=True)
class FaultRecord:
    """The fault that stopped the backend.

    Attributes:
        kind: :class:`FaultKind`.
        servo_id: the servo (None: the bus).
        joint: its joint (None: the bus).
        detected_at: ``time.monotonic()`` when the worker saw it.
        stop: what was sent: ``"hold"``, ``"torque_off"``, or why nothing could be.
        message: the error's message.
    """

    kind: FaultKind
    servo_id: int | None
    joint: str | None
    detected_at: float
    stop: str
    message: str


@dataclass
class _Stream:
    execution: TrajectoryExecution
    started: float | None = None  # time.monotonic() of its first cycle
    tracking: dict[str, JointTracking] = field(default_factory=dict)
    cycles: int = 0


class FeetechBackend(BaseBackend):
    """Trajectories on an arm of bus servos (one trajectory at a time).

    Args:
        calibration: the joints' servos and LeRobot calibration.
        bus: an open bus (:class:`~.bus.FeetechBus`); the backend closes it.
        options: see :class:`FeetechOptions`.

    Raises:
        BusFaultError: a servo does not answer its ping or its first read (the bus is
            closed); the message names the joint and ID.
    """

    def __init__(self, calibration: LeRobotCalibration, bus: ServoBus,
                 options: FeetechOptions | None = None) -> None:
        self._options = options or FeetechOptions()
        self._calibration = calibration
        self._bus = bus
        self._ids = [m.servo_id for m in calibration.motors]
        self._joint_of = {m.servo_id: m.joint for m in calibration.motors}
        try:
            for motor in calibration.motors:
                try:
                    bus.ping(motor.servo_id)
                except BusFaultError as exc:
                    raise BusFaultError(f"joint {motor.joint!r} (servo {motor.servo_id}) "
                                        f"does not answer: {exc}", exc.kind,
                                        motor.servo_id) from None
            states = bus.read_states(self._ids)
            initial = {self._joint_of[i]: self._radians(s) for i, s in states.items()}
            # hold where the arm is before the torque comes on: no jump to a stale goal
            bus.write_goals({i: s.position for i, s in states.items()})
            bus.set_torque(self._ids, True)
        except BusFaultError:
            bus.close()
            raise
        super().__init__(calibration.joint_names, initial,
                         start_tolerance=self._options.start_tolerance)
        self._states = states
        self._goals = {i: s.position for i, s in states.items()}  # last goals written
        self._sent_q = self._positions.copy()  # last goals written, rad
        self._stream: _Stream | None = None
        self._last_tracking: dict[str, JointTracking] = {}
        self._stall_count = dict.fromkeys(self._ids, 0)
        self.fault: FaultRecord | None = None
        self.cycles = 0
        self.overruns = 0
        self._halt = threading.Event()
        self._thread = threading.Thread(target=self._run, name=f"FeetechBackend-{id(self):x}",
                                        daemon=True)
        self._thread.start()

    # -- public ---------------------------------------------------------------------------

    @property
    def calibration(self) -> LeRobotCalibration:
        return self._calibration

    @property
    def bus(self) -> ServoBus:
        return self._bus

    def servo_states(self) -> dict[int, ServoState]:
        """The latest state read of every servo, by ID."""
        with self._lock:
            return dict(self._states)

    def tracking(self) -> dict[str, JointTracking]:
        """Tracking errors of the running execution (else of the last one), by joint."""
        with self._lock:
            stream = self._stream
            return dict(stream.tracking if stream is not None else self._last_tracking)

    def execute(self, trajectory: JointTrajectory) -> TrajectoryExecution:
        """Start ``trajectory``; refused before anything moves when a sample leaves a
        joint's calibrated range. See :meth:`BaseBackend.execute`.

        Raises:
            TrajectoryRejectedError: out of the calibrated range (names joint and time).
            BackendBusyError: another trajectory runs.
            BusFaultError / BackendError: the backend stopped on a fault, or is closed.
        """
        for j, name in enumerate(trajectory.names):
            if name not in self._calibration.joint_names:
                continue  # check_trajectory names it
            low, high = self._calibration.range_radians(name)
            column = trajectory.positions[:, j]
            bad = np.flatnonzero((column < low - 1e-6) | (column > high + 1e-6))
            if bad.size:
                k = int(bad[0])
                raise TrajectoryRejectedError(
                    f"joint {name!r} at t = {float(trajectory.times[k]):.3f} s must be within "
                    f"its calibrated range [{low:.4f}, {high:.4f}] rad (got "
                    f"{float(column[k]):.4f})")
        with self._lock:
            if self._executions:
                raise BackendBusyError("the servo bus streams one trajectory at a time; "
                                       "another one is running")
            return super().execute(trajectory)

    def close(self) -> None:
        """Stop (the servos hold where they are), end the worker, close the bus."""
        with self._lock:
            super().close()
        self._halt.set()
        if threading.current_thread() is not self._thread:
            self._thread.join(_JOIN_TIMEOUT)
        self._bus.close()

    # -- BaseBackend hooks (under self._lock) ---------------------------------------------

    def _begin(self, execution: TrajectoryExecution) -> None:
        self._stream = _Stream(execution, tracking={n: JointTracking()
                                                    for n in execution.trajectory.names})

    def _cancel(self, execution: TrajectoryExecution, message: str) -> None:
        if execution.finished:
            return
        if self._stream is not None and self._stream.execution is execution:
            self._end_stream()
            try:
                self._hold()
            except BusFaultError as exc:
                self._finish(execution, "failed", f"{message}: the hold was not sent ({exc})",
                             exc)
                return
        super()._cancel(execution, message)

    # -- the cycle ------------------------------------------------------------------------

    def _run(self) -> None:
        period = 1.0 / self._options.rate_hz
        next_cycle = time.monotonic()
        while not self._halt.is_set():
            try:
                self._cycle()
            except BusFaultError as exc:
                self._on_fault(exc)
                return
            except Exception as exc:  # no handle may wait forever
                self._on_fault(BusFaultError(f"servo bus worker died: {exc!r}"))
                return
            next_cycle += period
            delay = next_cycle - time.monotonic()
            if delay < 0:
                self.overruns += 1
                next_cycle = time.monotonic()
                delay = 0.0
            self._halt.wait(delay)

    def _cycle(self) -> None:
        with self._lock:
            if self._closed:
                return
            stream = self._stream
            previous_q = self._sent_q.copy()
            if stream is not None:
                self._write_stream_goals(stream)
        states = self._bus.read_states(self._ids)
        with self._lock:
            self.cycles += 1
            self._states = states
            for servo_id, state in states.items():
                self._positions[self._index[self._joint_of[servo_id]]] = self._radians(state)
            self._check_servos(states)
            if self._stream is not None and self._stream is stream:
                self._track(stream, previous_q)

    def _write_stream_goals(self, stream: _Stream) -> None:
        now = time.monotonic()
        if stream.started is None:
            stream.started = now
        trajectory, execution = stream.execution.trajectory, stream.execution
        elapsed = min(now - stream.started, execution.duration)
        q = sample_positions(trajectory, float(trajectory.times[0]) + elapsed)
        for name, value in zip(trajectory.names, q):
            motor = self._calibration.motor(name)
            self._goals[motor.servo_id] = self._calibration.to_ticks(name, float(value))
            self._sent_q[self._index[name]] = float(value)
        self._bus.write_goals(self._goals, self._options.speed, self._options.acceleration)
        execution.set_progress(elapsed)
        stream.cycles += 1

    def _track(self, stream: _Stream, previous_q: np.ndarray) -> None:
        execution = stream.execution
        limit = self._options.max_tracking_error
        for name in execution.trajectory.names:
            i = self._index[name]
            error = float(previous_q[i] - self._positions[i])
            stream.tracking[name].add(error)
            if limit is not None and abs(error) > limit:
                motor = self._calibration.motor(name)
                raise BusFaultError(
                    f"joint {name!r} (servo {motor.servo_id}) is {error:+.3f} rad from its goal "
                    f"(limit {limit} rad)", FaultKind.TRACKING, motor.servo_id)
        if stream.started is None or execution.progress_now < execution.duration:
            return
        final = execution.trajectory.positions[-1]
        gaps = np.abs(final - self._positions[execution.columns])
        late = time.monotonic() - stream.started - execution.duration
        if np.all(gaps <= self._options.settle_tolerance):
            self._end_stream()
            self._finish(execution, "succeeded",
                         f"trajectory executed in {stream.cycles} cycles at "
                         f"{self._options.rate_hz:g} Hz; tracking error max/rms: "
                         + ", ".join(f"{n} {math.degrees(t.largest):.1f}°/"
                                     f"{math.degrees(t.rms):.1f}°"
                                     for n, t in stream.tracking.items()))
        elif late > self._options.settle_timeout:
            j = int(np.argmax(gaps))
            name = execution.trajectory.names[j]
            raise BusFaultError(
                f"joint {name!r} did not reach its last goal within "
                f"{self._options.settle_timeout:g} s of the trajectory's end "
                f"({gaps[j]:.3f} rad away)", FaultKind.TRACKING,
                self._calibration.motor(name).servo_id)

    def _check_servos(self, states: dict[int, ServoState]) -> None:
        for servo_id, state in states.items():
            joint = self._joint_of[servo_id]
            if state.status:
                flags = state.flags or [f"status 0x{state.status:02x}"]
                kind = FaultKind(flags[0]) if flags[0] in _KINDS else FaultKind.OVERLOAD
                raise BusFaultError(f"servo {servo_id} (joint {joint!r}) reports "
                                    f"{', '.join(flags)} (status 0x{state.status:02x})",
                                    kind, servo_id)
            goal_gap = abs(self._goals[servo_id] - state.position)
            pushing = abs(state.load) >= self._options.stall_load and goal_gap > 2
            self._stall_count[servo_id] = self._stall_count[servo_id] + 1 if pushing else 0
            if self._stall_count[servo_id] >= self._options.stall_cycles:
                raise BusFaultError(
                    f"servo {servo_id} (joint {joint!r}) is stalled: load "
                    f"{100 * state.load:+.0f} % for {self._stall_count[servo_id]} cycles, "
                    f"{goal_gap} ticks from its goal", FaultKind.STALL, servo_id)

    # -- stopping -------------------------------------------------------------------------

    def _end_stream(self) -> None:
        if self._stream is not None:
            self._last_tracking = self._stream.tracking
        self._stream = None

    def _hold(self) -> None:
        """Goals at the present positions (the last read)."""
        self._goals = {i: s.position for i, s in self._states.items()}
        self._sent_q = self._positions.copy()
        self._bus.write_goals(self._goals, self._options.speed, self._options.acceleration)

    def _on_fault(self, exc: BusFaultError) -> None:
        detected = time.monotonic()
        with self._lock:
            if self._options.on_fault == "torque_off":
                action = "torque off"
                send = lambda: self._bus.set_torque(self._ids, False)
            else:
                action = "hold"
                send = self._hold
            try:
                send()
                stop = action
            except BusFaultError as sent:
                stop = f"{action} not sent ({sent})"
            kind = FaultKind(exc.kind) if exc.kind in _KINDS else FaultKind.NO_REPLY
            joint = self._joint_of.get(exc.servo_id) if exc.servo_id is not None else None
            message = f"{exc}; stopped: {stop}"
            if joint is not None and repr(joint) not in message:
                message = f"joint {joint!r}: {message}"
            self.fault = FaultRecord(kind, exc.servo_id, joint, detected, stop, message)
            self._closed = True
            self._closed_reason = f"stopped on a bus fault ({message})"
            self._end_stream()
            for execution in list(self._executions):
                text = (f"servo bus fault at {execution.progress_now:.3f} s of "
                        f"{execution.duration:.3f} s: {message}")
                self._finish(execution, "failed", text,
                             BusFaultError(text, kind.value, exc.servo_id))

    def _radians(self, state: ServoState) -> float:
        return self._calibration.to_radians(self._joint_of[state.servo_id], state.position)

