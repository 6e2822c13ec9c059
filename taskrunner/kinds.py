"""Kinds and codes defined once, as enums: what a command line, the REST API and a run
record say with the same values.

An :class:`~enum.IntEnum` is an ``int`` and a :class:`~enum.StrEnum` a ``str``: each
compares equal to, hashes as, and encodes to JSON as its value, so that records and API
answers keep the bytes they had when these were plain constants.
"""

from __future__ import annotations

from enum import IntEnum, StrEnum

from taskrunner.errors import ArgumentError

__all__ = ["BackendKind", "CollisionChoice", "EventKind", "ExitCode", "FailureKind", "NodeStatus",
           "RunStatus", "StopReason", "WaitKind"]


class BackendKind(StrEnum):
    """The backend that executes a run's motions: mock, sim, mujoco (physics), the servo
    arm over serial or http, or bus servos (the SO-101's Feetech bus)."""

    MOCK = "mock"
    """Reaches every target at once (tests, dry runs)."""
    SIM = "sim"
    """Plays trajectories in (scaled) real time, kinematically."""
    MUJOCO = "mujoco"
    """MuJoCo physics: contacts, grasps, objects that fall."""
    SERIAL = "serial"
    """The servo arm's ESP32 over USB serial."""
    HTTP = "http"
    """The servo arm's ESP32 over WiFi/HTTP."""
    FEETECH = "feetech"
    """Feetech bus servos (the SO-101's STS3215) on one USB adapter or several, from the
    cell's hardware file and LeRobot's calibration."""

    @classmethod
    def parse(cls, value: str, what: str = "kind") -> BackendKind:
        """``value`` as a kind.

        Raises:
            ArgumentError: it is none (the message names ``what`` and every kind).
        """
        try:
            return cls(value)
        except ValueError:
            known = ", ".join(k.value for k in cls)
            raise ArgumentError(f"'{what}' must be one of {known} (got {value!r})") from None


class RunStatus(StrEnum):
    """A run's status, in its record and in the REST API."""

    RUNNING = "running"
    SUCCEEDED = "succeeded"
    FAILED = "failed"
    CANCELLED = "cancelled"
    INTERRUPTED = "interrupted"
    """The process that ran it ended before the run did (read back from its journal)."""


class NodeStatus(StrEnum):
    """A tree node's status, in events (``node_finished``), records, the live tree and the
    REST API: py_trees' :class:`~py_trees.common.Status` values, and ``CANCELLED``."""

    SUCCESS = "SUCCESS"
    FAILURE = "FAILURE"
    RUNNING = "RUNNING"
    INVALID = "INVALID"
    """Not started (py_trees' stop also leaves a node INVALID)."""
    CANCELLED = "CANCELLED"
    """Running when the run was stopped (py_trees has no such status)."""


class CollisionChoice(StrEnum):
    """The link geometry collisions are checked with (``--collision``, a robot's or a cell
    robot's ``collision:``, ``load_workcell(collision=)``)."""

    EXACT = "exact"
    """The links' meshes as they are."""
    CONVEX = "convex"
    """Each mesh's convex hull."""
    AUTO = "auto"
    """Hulls where they are tight, exact meshes where a hull would fill a gap."""


class FailureKind(StrEnum):
    """Why a run failed, as ``run-task`` maps it to an exit code."""

    INVALID = "invalid"
    """Invalid input: ``InputError``, ``UnknownNameError``, ``SceneError`` …"""
    PLANNING = "planning"
    """No motion could be produced (``PlanningError``)."""
    EXECUTION = "execution"
    """A backend failed, or an expectation was missed (``BackendError``)."""


class StopReason(StrEnum):
    """Why a Cartesian path stopped short (:class:`taskrunner.planning.CartesianResult`)."""

    IK = "ik"
    """No IK solution near the previous point."""
    COLLISION = "collision"
    """The next point collides."""
    JUMP = "jump"
    """A joint would jump between two points."""


class WaitKind(StrEnum):
    """How a motion that would meet another branch's arm was put off
    (:class:`taskrunner.tree.schedule.Wait`), in the schedule's order of preference."""

    DELAY = "delay"
    """Started a little later, while the other arm's motion still runs: it passes behind."""
    UNTIL_END = "until_end"
    """Started when the other arm's motion has ended (that arm's way is then known)."""
    REPLAN = "replan"
    """Planned again with the other arm where they would have met: the new motion ends
    sooner than the first would have, waiting for the other arm's motion to end."""


class EventKind(StrEnum):
    """The kinds of event a run emits (:class:`taskrunner.runtime.events.RunEvent`)."""

    RUN_STARTED = "run_started"
    """The task was loaded and compiled; data: task, cell, backend, parameters."""
    NODE_STARTED = "node_started"
    """A tree node began (initialise)."""
    NODE_FINISHED = "node_finished"
    """A node ended: status SUCCESS / FAILURE / INVALID (stopped)."""
    PLANNED = "planned"
    """A motion was planned; data: planning_time, duration, waypoints."""
    MOTION = "motion"
    """A trajectory was sent to the backend; data: trajectory, scene, start / sent (s, the
    run's schedule), lane, verify_time (s)."""
    PHYSICS = "physics"
    """What a physics backend did during a node's motion; data: period, joints, t, q,
    objects (poses over time), grasps (welds)."""
    WAIT = "wait"
    """A motion held back for another branch's arm; data: since, until (s, the run's
    schedule), other (its step), bodies, at, distance, resolution (a :class:`WaitKind`)."""
    MESSAGE = "message"
    """Anything else worth showing (a warning, a retry)."""
    CHECKPOINT = "checkpoint"
    """A leaf has finished: what a resumed run continues from (its place in the tree, the
    scene, which arm holds what); see :mod:`taskrunner.runtime.checkpoint`."""
    RUN_FINISHED = "run_finished"
    """The run ended; status succeeded / failed / cancelled."""


class ExitCode(IntEnum):
    """``run-task``'s exit codes, by outcome."""

    OK = 0
    """Success (a run that succeeded, a check that found no problem)."""
    INVALID = 2
    """An invalid task, file or argument."""
    PLANNING = 3
    """No motion could be planned."""
    EXECUTION = 4
    """A backend failed or refused a motion, or an expectation was missed."""
    CANCELLED = 130
    """Cancelled (Ctrl-C: 128 + SIGINT)."""
    TERMINATED = 143
    """Cancelled by SIGTERM (128 + 15)."""
