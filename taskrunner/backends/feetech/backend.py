"""A backend for arms of bus servos: trajectories streamed as sync writes, states read back.

A worker thread runs a fixed-rate cycle (``rate_hz``, 60 by default: at least 50 with a
late cycle now and then) over one or more
:class:`~taskrunner.backends.feetech.bus.ServoBus` (:class:`BusMotors`: a bus and the
motors on it; two arms on two USB adapters, or on one bus with IDs 1-6 and 7-12): while
trajectories run, it samples every one at the cycle's instant, writes each moving bus's
goals (converted to ticks through the LeRobot calibration) in one sync write, then reads
every servo's position, load and status in one sync read per bus; idle, it only reads.
Each cycle updates the joint positions and the tracking error per joint (the goal written
one cycle earlier minus the position read), reported in the execution's message and
result data (``tracking``: max and RMS per joint, rad) and by
:meth:`FeetechBackend.tracking`.

The trajectories' clock advances with the wall clock, but by at most two periods a cycle:
after a late cycle (a host busy for a while, a reply waited for) the goals go on from
where the last ones were, not from where the wall clock says the plan is by now. A goal
that leapt ahead would have the servos cut across the planned path at their full speed
and read as a tracking error the servos could not help; while no goal comes the servos
hold the last one, and the motion ends later than planned. That lateness is the
execution's ``slip`` (s of the trajectory's time, in its result data and message) and
:attr:`FeetechBackend.slip`, the same for every trajectory running: the arms stay on
one clock.

Faults end everything at once: a link fault (no reply, bad checksum, wrong ID, unplugged
adapter) raised by the bus, a status flag set by a servo (overload, overheat, voltage,
angle sensor, over-current), a stall (the load at ``stall_load`` or more for
``stall_cycles`` cycles while the goal is not reached) or a tracking error over
``max_tracking_error``. The backend then sends a stop (``on_fault``: ``"hold"`` writes
every servo's present position as its goal; ``"torque_off"`` cuts the torque: the arm
falls), fails the running execution with a :class:`~taskrunner.errors.BusFaultError`
naming the joint, servo and fault, and refuses further trajectories; the stop goes to
every bus (one arm of a pair does not go on alone). Detection takes at most one cycle plus
one reply timeout (17 + 40 ms by default). Units: rad, s.
"""

from __future__ import annotations

import math
import threading
import time
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Literal

import numpy as np

from taskrunner.backends.base import BaseBackend, TrajectoryExecution, check_option
from taskrunner.backends.execution import sample_positions
from taskrunner.backends.feetech.bus import FaultKind, ServoBus, ServoState
from taskrunner.backends.feetech.calibration import LeRobotCalibration, Motor
from taskrunner.errors import (
    ArgumentError,
    BusFaultError,
    InputError,
    TrajectoryRejectedError,
    UnknownNameError,
)
from taskrunner.types import JointTrajectory

__all__ = ["BusMotors", "FaultRecord", "FeetechBackend", "FeetechOptions", "JointTracking",
           "tracking_data"]

_JOIN_TIMEOUT = 2.0  # s
_MAX_STEP = 2.0  # periods: the most a cycle advances the trajectories' clock
_KINDS = frozenset(k.value for k in FaultKind)


@dataclass(frozen=True)
class FeetechOptions:
    """How :class:`FeetechBackend` drives the bus.

    Attributes:
        rate_hz: cycles a second (sync writes + sync reads), at least 50.
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
        time_scale: trajectory seconds per wall-clock second: 1 on real servos; an
            emulator run faster than real time (``run-task bus-sim --speedup``) matches
            it. ``rate_hz`` and ``settle_timeout`` count the trajectory's seconds.
    """

    rate_hz: float = 60.0
    on_fault: Literal["hold", "torque_off"] = "hold"
    speed: int = 0
    acceleration: int = 0
    start_tolerance: float = 0.05
    settle_tolerance: float = 0.015
    settle_timeout: float = 1.0
    max_tracking_error: float | None = 0.35
    stall_load: float = 0.95
    stall_cycles: int = 2
    time_scale: float = 1.0

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
        check_option("time_scale", self.time_scale, lambda v: 0 < v <= 100, "in (0, 100]")


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


@dataclass(frozen=True)
class BusMotors:
    """The motors on one bus and their calibration.

    Attributes:
        bus: an open bus (:class:`~.bus.FeetechBus`); the backend closes it.
        calibration: the joints of the servos on this bus (several arms' on one bus:
            their IDs apart, 1-6 and 7-12) and their LeRobot calibration.
        name: the bus's name in messages (the hardware file's; default the bus's port).
    """

    bus: ServoBus
    calibration: LeRobotCalibration
    name: str = ""

    @property
    def label(self) -> str:
        return self.name or str(getattr(self.bus, "port_name", "bus"))


@dataclass
class _Stream:
    execution: TrajectoryExecution
    buses: tuple[int, ...]  # the buses its joints are on
    started: float | None = None  # time.monotonic() of its first cycle
    clock: float = 0.0  # the trajectory's time played, s from its first sample
    slip: float = 0.0  # s of the trajectory's time lost to late cycles
    tracking: dict[str, JointTracking] = field(default_factory=dict)
    cycles: int = 0


class FeetechBackend(BaseBackend):
    """Trajectories on arms of bus servos, on one bus or several, all on one clock.

    Every cycle samples every running trajectory at the same instant, sends one sync write
    to each bus that has a moving joint, then reads every bus. Several trajectories run at
    once when their joints differ (two arms of a pair cell, in parallel branches).

    Args:
        buses: the buses and their motors (joint names unique across them).
        options: see :class:`FeetechOptions`.

    Raises:
        ArgumentError: no bus, a joint on two buses, or an ID twice on one bus.
        InputError: a servo whose Homing_Offset is not its calibration's (names the file,
            joint, servo and both values); every bus is closed.
        BusFaultError: a servo does not answer its ping or its first read (every bus is
            closed); the message names the joint, ID and bus.
    """

    def __init__(self, buses: Sequence[BusMotors], options: FeetechOptions | None = None) -> None:
        self._options = options or FeetechOptions()
        self._links = tuple(buses)
        if not self._links:
            raise ArgumentError("'buses' must name at least one bus (got none)")
        self._where: dict[str, tuple[int, Motor]] = {}  # joint -> (bus index, motor)
        self._ids: list[list[int]] = []
        self._joint_of: list[dict[int, str]] = []
        for b, link in enumerate(self._links):
            ids = [m.servo_id for m in link.calibration.motors]
            if len(set(ids)) != len(ids):
                raise ArgumentError(f"servo IDs on bus {link.label!r} must differ (got {ids})")
            for motor in link.calibration.motors:
                if motor.joint in self._where:
                    raise ArgumentError(f"joint {motor.joint!r} must be on one bus (got "
                                        f"{self._links[self._where[motor.joint][0]].label!r} "
                                        f"and {link.label!r})")
                self._where[motor.joint] = (b, motor)
            self._ids.append(ids)
            self._joint_of.append({m.servo_id: m.joint for m in link.calibration.motors})
        try:
            states = [self._connect(b) for b in range(len(self._links))]
        except (BusFaultError, InputError):
            for link in self._links:
                link.bus.close()
            raise
        initial = {self._joint_of[b][i]: self._radians(b, s)
                   for b, by_id in enumerate(states) for i, s in by_id.items()}
        super().__init__(tuple(self._where), initial,
                         start_tolerance=self._options.start_tolerance)
        self._states = states
        self._goals = [{i: s.position for i, s in by_id.items()} for by_id in states]
        self._sent_q = self._positions.copy()  # last goals written, rad
        self._streams: dict[int, _Stream] = {}  # by id() of the execution
        self._last_tracking: dict[str, JointTracking] = {}
        self._stall_count = [dict.fromkeys(ids, 0) for ids in self._ids]
        self.fault: FaultRecord | None = None
        self.cycles = 0
        self.overruns = 0
        self.slip = 0.0  # s of trajectory time lost to late cycles, every execution's
        self._last_cycle: float | None = None  # time.monotonic() of the last cycle
        self._halt = threading.Event()
        self._thread = threading.Thread(target=self._run, name=f"FeetechBackend-{id(self):x}",
                                        daemon=True)
        self._thread.start()

    def _connect(self, b: int) -> dict[int, ServoState]:
        """Ping bus ``b``'s servos, check their homing offsets, hold them where they are
        and turn their torque on; their first states."""
        link = self._links[b]
        calibration = link.calibration
        for motor in calibration.motors:
            try:
                link.bus.ping(motor.servo_id)
                offset = link.bus.read(motor.servo_id, "Homing_Offset")
            except BusFaultError as exc:
                raise BusFaultError(f"joint {motor.joint!r} (servo {motor.servo_id} on bus "
                                    f"{link.label!r}) does not answer: {exc}", exc.kind,
                                    motor.servo_id) from None
            wanted = calibration.entries[motor.joint].homing_offset
            if offset != wanted:
                where = calibration.path if calibration.path is not None else "its calibration"
                raise InputError(
                    f"joint {motor.joint!r}: servo {motor.servo_id} on bus {link.label!r} has "
                    f"Homing_Offset {offset}, its calibration {wanted}: the file is not this "
                    f"arm's, or the arm was calibrated since (run-task hw calibrate --robot "
                    f"so101 --calibration {where})", calibration.path)
        states = link.bus.read_states(self._ids[b])
        # hold where the arm is before the torque comes on: no jump to a stale goal
        link.bus.write_goals({i: s.position for i, s in states.items()})
        link.bus.set_torque(self._ids[b], True)
        return states

    # -- public ---------------------------------------------------------------------------

    @property
    def buses(self) -> tuple[BusMotors, ...]:
        return self._links

    def calibration_of(self, joint: str) -> LeRobotCalibration:
        """The calibration of the bus that drives ``joint``."""
        if joint not in self._where:
            raise UnknownNameError("joint", joint, list(self._where))
        return self._links[self._where[joint][0]].calibration

    def servo_states(self) -> dict[str, ServoState]:
        """The latest state read of every servo, by joint."""
        with self._lock:
            return {self._joint_of[b][i]: s for b, by_id in enumerate(self._states)
                    for i, s in by_id.items()}

    def tracking(self) -> dict[str, JointTracking]:
        """Tracking errors by joint: of the running executions, else of the last ones."""
        with self._lock:
            found = dict(self._last_tracking)
            for stream in self._streams.values():
                found.update(stream.tracking)
            return found

    def execute(self, trajectory: JointTrajectory) -> TrajectoryExecution:
        """Start ``trajectory``; refused before anything moves when a sample leaves a
        joint's calibrated range. See :meth:`BaseBackend.execute`.

        Raises:
            TrajectoryRejectedError: out of the calibrated range (names joint and time).
            BackendBusyError: one of its joints moves under another trajectory.
            BusFaultError / BackendError: the backend stopped on a fault, or is closed.
        """
        for j, name in enumerate(trajectory.names):
            if name not in self._where:
                continue  # check_trajectory names it
            low, high = self.calibration_of(name).range_radians(name)
            column = trajectory.positions[:, j]
            bad = np.flatnonzero((column < low - 1e-6) | (column > high + 1e-6))
            if bad.size:
                k = int(bad[0])
                raise TrajectoryRejectedError(
                    f"joint {name!r} at t = {float(trajectory.times[k]):.3f} s must be within "
                    f"its calibrated range [{low:.4f}, {high:.4f}] rad (got "
                    f"{float(column[k]):.4f})")
        with self._lock:
            return super().execute(trajectory)

    def close(self) -> None:
        """Stop (the servos hold where they are), end the worker, close the buses."""
        with self._lock:
            super().close()
        self._halt.set()
        if threading.current_thread() is not self._thread:
            self._thread.join(_JOIN_TIMEOUT)
        for link in self._links:
            link.bus.close()

    # -- BaseBackend hooks (under self._lock) ---------------------------------------------

    def _begin(self, execution: TrajectoryExecution) -> None:
        names = execution.trajectory.names
        buses = tuple(sorted({self._where[n][0] for n in names}))
        self._streams[id(execution)] = _Stream(execution, buses,
                                               tracking={n: JointTracking() for n in names})

    def _cancel(self, execution: TrajectoryExecution, message: str) -> None:
        if execution.finished:
            return
        stream = self._streams.get(id(execution))
        if stream is not None:
            self._end_stream(stream)
            try:
                self._hold(stream.execution.trajectory.names)
            except BusFaultError as exc:
                self._finish(execution, "failed", f"{message}: the hold was not sent ({exc})",
                             exc)
                return
        super()._cancel(execution, message)

    # -- the cycle ------------------------------------------------------------------------

    def _run(self) -> None:
        period = 1.0 / (self._options.rate_hz * self._options.time_scale)  # wall s
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
            streams = list(self._streams.values())
            previous_q = self._sent_q.copy()
            now = time.monotonic()  # one instant for every arm
            # the trajectories' clock: the wall clock's step, at most _MAX_STEP periods
            wall = 0.0 if self._last_cycle is None else \
                (now - self._last_cycle) * self._options.time_scale
            self._last_cycle = now
            step = min(wall, _MAX_STEP / self._options.rate_hz)
            if streams:
                self.slip += wall - step
            for stream in streams:
                self._sample(stream, now, step, wall - step)
            for b in sorted({b for stream in streams for b in stream.buses}):
                self._links[b].bus.write_goals(self._goals[b], self._options.speed,
                                               self._options.acceleration)
        states = [self._read(b) for b in range(len(self._links))]
        with self._lock:
            self.cycles += 1
            self._states = states
            for b, by_id in enumerate(states):
                for servo_id, state in by_id.items():
                    joint = self._joint_of[b][servo_id]
                    self._positions[self._index[joint]] = self._radians(b, state)
                self._check_servos(b, by_id)
            for stream in streams:
                if self._streams.get(id(stream.execution)) is stream:
                    self._track(stream, previous_q)

    def _read(self, b: int) -> dict[int, ServoState]:
        """Every servo's state on bus ``b``; a fault names the joint (IDs repeat across
        buses)."""
        try:
            return self._links[b].bus.read_states(self._ids[b])
        except BusFaultError as exc:
            joint = self._joint_of[b].get(exc.servo_id) if exc.servo_id is not None else None
            if joint is None or repr(joint) in str(exc):
                raise
            raise BusFaultError(f"joint {joint!r}: {exc}", exc.kind, exc.servo_id) from None

    def _sample(self, stream: _Stream, now: float, step: float, slip: float) -> None:
        """Goals of ``stream``'s joints: its trajectory ``step`` s (its time) after the
        last cycle's (its first sample in its first cycle); ``slip``: the wall clock's step
        beyond ``step``."""
        if stream.started is None:
            stream.started = now
        else:
            stream.clock += step
            stream.slip += slip
        trajectory, execution = stream.execution.trajectory, stream.execution
        elapsed = min(stream.clock, execution.duration)
        q = sample_positions(trajectory, float(trajectory.times[0]) + elapsed)
        for name, value in zip(trajectory.names, q):
            b, motor = self._where[name]
            self._goals[b][motor.servo_id] = self._links[b].calibration.to_ticks(name, float(value))
            self._sent_q[self._index[name]] = float(value)
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
                b, motor = self._where[name]
                raise BusFaultError(
                    f"joint {name!r} (servo {motor.servo_id} on bus {self._links[b].label!r}) "
                    f"is {error:+.3f} rad from its goal (limit {limit} rad)",
                    FaultKind.TRACKING, motor.servo_id)
        if stream.started is None or execution.progress_now < execution.duration:
            return
        final = execution.trajectory.positions[-1]
        gaps = np.abs(final - self._positions[execution.columns])
        late = stream.clock - execution.duration
        if np.all(gaps <= self._options.settle_tolerance):
            self._end_stream(stream)
            slip = (f"; {1e3 * stream.slip:.0f} ms behind the plan (late cycles: the goals "
                    "went on from the last ones)") if stream.slip > 0.0005 else ""
            self._finish(execution, "succeeded",
                         f"trajectory executed in {stream.cycles} cycles at "
                         f"{self._options.rate_hz:g} Hz{slip}; tracking error max/rms: "
                         + ", ".join(f"{n} {math.degrees(t.largest):.1f}°/"
                                     f"{math.degrees(t.rms):.1f}°"
                                     for n, t in stream.tracking.items()),
                         data={"tracking": tracking_data(stream.tracking),
                               "cycles": stream.cycles, "rate_hz": self._options.rate_hz,
                               "slip": round(stream.slip, 4)})
        elif late > self._options.settle_timeout:
            j = int(np.argmax(gaps))
            name = execution.trajectory.names[j]
            raise BusFaultError(
                f"joint {name!r} did not reach its last goal within "
                f"{self._options.settle_timeout:g} s of the trajectory's end "
                f"({gaps[j]:.3f} rad away)", FaultKind.TRACKING, self._where[name][1].servo_id)

    def _check_servos(self, b: int, states: dict[int, ServoState]) -> None:
        on = f" on bus {self._links[b].label!r}" if len(self._links) > 1 else ""
        for servo_id, state in states.items():
            joint = self._joint_of[b][servo_id]
            if state.status:
                flags = state.flags or [f"status 0x{state.status:02x}"]
                kind = FaultKind(flags[0]) if flags[0] in _KINDS else FaultKind.OVERLOAD
                raise BusFaultError(f"servo {servo_id}{on} (joint {joint!r}) reports "
                                    f"{', '.join(flags)} (status 0x{state.status:02x})",
                                    kind, servo_id)
            goal_gap = abs(self._goals[b][servo_id] - state.position)
            pushing = abs(state.load) >= self._options.stall_load and goal_gap > 2
            count = self._stall_count[b][servo_id] + 1 if pushing else 0
            self._stall_count[b][servo_id] = count
            if count >= self._options.stall_cycles:
                raise BusFaultError(
                    f"servo {servo_id}{on} (joint {joint!r}) is stalled: load "
                    f"{100 * state.load:+.0f} % for {count} cycles, "
                    f"{goal_gap} ticks from its goal", FaultKind.STALL, servo_id)

    # -- stopping -------------------------------------------------------------------------

    def _end_stream(self, stream: _Stream) -> None:
        self._last_tracking.update(stream.tracking)
        self._streams.pop(id(stream.execution), None)

    def _hold(self, joints: Sequence[str] | None = None) -> None:
        """Goals at the present positions (the last read) of ``joints`` (None: all), sent to
        their buses."""
        names = list(self._where) if joints is None else list(joints)
        for name in names:
            b, motor = self._where[name]
            self._goals[b][motor.servo_id] = self._states[b][motor.servo_id].position
            self._sent_q[self._index[name]] = self._positions[self._index[name]]
        for b in sorted({self._where[n][0] for n in names}):
            self._links[b].bus.write_goals(self._goals[b], self._options.speed,
                                           self._options.acceleration)

    def _on_fault(self, exc: BusFaultError) -> None:
        detected = time.monotonic()
        with self._lock:
            action = "torque off" if self._options.on_fault == "torque_off" else "hold"
            failed = []
            for b, link in enumerate(self._links):  # every bus: one arm must not go on alone
                try:
                    if action == "torque off":
                        link.bus.set_torque(self._ids[b], False)
                    else:
                        self._hold([m.joint for m in link.calibration.motors])
                except BusFaultError as sent:
                    failed.append(f"{action} not sent on bus {link.label!r} ({sent})")
            stop = "; ".join(failed) if failed else action
            kind = FaultKind(exc.kind) if exc.kind in _KINDS else FaultKind.NO_REPLY
            joint = self._joint_in(exc)
            message = f"{exc}; stopped: {stop}"
            if joint is not None and repr(joint) not in message:
                message = f"joint {joint!r}: {message}"
            self.fault = FaultRecord(kind, exc.servo_id, joint, detected, stop, message)
            self._closed = True
            self._closed_reason = f"stopped on a bus fault ({message})"
            for stream in list(self._streams.values()):
                self._end_stream(stream)
            for execution in list(self._executions):
                text = (f"servo bus fault at {execution.progress_now:.3f} s of "
                        f"{execution.duration:.3f} s: {message}")
                self._finish(execution, "failed", text,
                             BusFaultError(text, kind.value, exc.servo_id))

    def _joint_in(self, exc: BusFaultError) -> str | None:
        """The joint a fault names: the one whose name its message quotes, else the only
        one with its servo ID."""
        for name in self._where:
            if repr(name) in str(exc):
                return name
        if exc.servo_id is None:
            return None
        owners = [j[exc.servo_id] for j in self._joint_of if exc.servo_id in j]
        return owners[0] if len(owners) == 1 else None

    def _radians(self, b: int, state: ServoState) -> float:
        joint = self._joint_of[b][state.servo_id]
        return self._links[b].calibration.to_radians(joint, state.position)


def tracking_data(tracking: dict[str, JointTracking]) -> dict[str, dict[str, float]]:
    """Tracking errors per joint as a record keeps them: largest and RMS, rad."""
    return {name: {"max": round(t.largest, 5), "rms": round(t.rms, 5), "samples": t.samples}
            for name, t in tracking.items()}
