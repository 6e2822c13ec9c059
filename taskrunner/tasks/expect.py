"""What a task file says must be true: ``expect:`` (after a step, and at the task's end).

An ``expect`` step checks the scene when the run reaches it; the task's own ``expect:``
is checked when the run ends. Both take the same fields (:class:`Expectation`); the
task's adds the run's ``status`` and ``error`` (:class:`TaskExpectation`)::

    steps:
      - pick: {arm: arm, object: cube}
      - expect:
          objects: {cube: {held_by: arm}}
          step_duration: {max: 10}          # the pick, in task time (s)
      - place: {arm: arm, object: cube, at: {xyz: [0.14, -0.12, 0.7635]}}
    expect:
      objects:
        cube: {pose: {xyz: [0.14, -0.12, 0.7635]}, orientation: yaw, released: true, on: table}
      groups:
        arm: {at: home}
      duration: {max: 40}
      collision_free: true

A task file may also list ``scenarios:`` (:class:`Scenario`): parameter sets, seeds and
backends that ``run-task test`` runs it with.

Units: metres, seconds, joint values in rad (or m); ``angle_deg`` in degrees.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field, model_validator

from taskrunner.tasks.nodes import Node, PoseSpec
from taskrunner.validation import Integer, Number

__all__ = ["DurationBounds", "Expectation", "GroupExpectation", "ObjectExpectation",
           "OutcomeTolerance", "Scenario", "TaskExpectation"]


class OutcomeTolerance(Node):
    """How far an object may end from its target (a place, a hand-over, an expectation)."""

    position: Number = Field(default=0.005, gt=0, le=1)
    """Largest distance between the object's centre and its target's (m, default 0.005);
    for a place, also the largest gap between the object and what it rests on."""
    angle_deg: Number = Field(default=5.0, gt=0, le=180)
    """Largest orientation error, as 'orientation' measures it (degrees, not radians;
    default 5)."""


class ObjectExpectation(Node):
    """Where an object is, what holds it, what it rests on (at least one of them)."""

    pose: PoseSpec | None = None
    """Where the object's centre is: a pose in 'world', a link's frame or another
    object's (taken where that frame is when the expectation is checked)."""
    orientation: Literal["free", "yaw", "full"] | None = None
    """What of 'pose's orientation is checked: 'free', 'yaw' (turn about the world z axis)
    or 'full', up to the object's symmetries (default: 'full' when 'pose' gives rpy or
    quat, else 'free')."""
    tolerance: OutcomeTolerance = OutcomeTolerance()
    """How far from 'pose' it may be (default 5 mm, 5 degrees)."""
    held_by: str | None = None
    """An arm (the object is attached to its grasp frame) or a link it is attached to."""
    released: Literal[True] | None = None
    """true: the object is attached to nothing."""
    on: str | None = None
    """An object it rests on: the nearest body below it, within 'tolerance.position'."""

    @model_validator(mode="after")
    def _something(self) -> ObjectExpectation:
        if self.pose is None and self.held_by is None and self.released is None \
                and self.on is None:
            raise ValueError("needs at least one of 'pose', 'held_by', 'released' or 'on'")
        if self.held_by is not None and self.released is not None:
            raise ValueError("takes only one of 'held_by' or 'released'")
        if self.held_by is not None and self.on is not None:
            raise ValueError("takes only one of 'held_by' or 'on'")
        if self.orientation is not None and self.pose is None:
            raise ValueError("takes 'orientation' only with 'pose'")
        return self

    @property
    def checked_orientation(self) -> str:
        """'orientation' as written, else 'full' for a pose with rpy or quat, else 'free'."""
        if self.orientation is not None:
            return self.orientation
        return "full" if self.pose is not None and self.pose.has_orientation else "free"


class GroupExpectation(Node):
    """A group's joints at a named pose or at joint values."""

    at: str | None = None
    """A named pose of the group."""
    joints: dict[str, Number] | None = Field(default=None, min_length=1)
    """Joint values {joint: rad or m} (the group's other joints are not checked)."""
    tolerance: Number = Field(default=0.01, gt=0, le=3.2)
    """Largest difference of any joint (rad or m, default 0.01)."""

    @model_validator(mode="after")
    def _one_target(self) -> GroupExpectation:
        if (self.at is None) == (self.joints is None):
            raise ValueError("needs exactly one of 'at' or 'joints'")
        return self


class DurationBounds(Node):
    """Bounds of a duration in task time (s): motions at their trajectory time, the rest
    at wall time (see :mod:`taskrunner.tree.clock`)."""

    min: Number | None = Field(default=None, ge=0)
    """At least this long (s)."""
    max: Number | None = Field(default=None, gt=0)
    """At most this long (s)."""

    @model_validator(mode="after")
    def _bounded(self) -> DurationBounds:
        if self.min is None and self.max is None:
            raise ValueError("needs 'min', 'max' or both")
        if self.min is not None and self.max is not None and self.min > self.max:
            raise ValueError(f"'min' must be <= 'max' (got {self.min} > {self.max})")
        return self

    def __str__(self) -> str:
        if self.min is not None and self.max is not None:
            return f"between {self.min:g} s and {self.max:g} s"
        return f"at least {self.min:g} s" if self.min is not None else f"at most {self.max:g} s"


class Expectation(Node):
    """The fields of an ``expect`` step (and of a task's ``expect:``)."""

    objects: dict[str, ObjectExpectation] = {}
    """By object name: its pose, what holds it, what it rests on."""
    groups: dict[str, GroupExpectation] = {}
    """By group name: at a named pose or joint values."""
    duration: DurationBounds | None = None
    """Task time since the run started (s)."""
    motion_time: DurationBounds | None = None
    """The part of the task time since the run started during which a motion ran (s):
    planning, waits and scene edits left out, so the same on any machine."""
    step_duration: DurationBounds | None = None
    """Task time of the step just before this 'expect' in the same list (s)."""
    collision_free: Literal[True] | None = None
    """true: every motion executed so far is re-checked for collisions against the scene
    it started in (exactly, along the whole trajectory), and the arms of each
    ``parallel``'s branches against each other over time (the space-time verifier)."""

    @model_validator(mode="after")
    def _something(self) -> Expectation:
        if not (self.objects or self.groups or self.duration or self.motion_time
                or self.step_duration or self.collision_free or getattr(self, "status", None)):
            raise ValueError("needs at least one of 'objects', 'groups', 'duration', "
                             "'motion_time', 'step_duration' or 'collision_free'")
        return self


class TaskExpectation(Expectation):
    """A task's ``expect:``: checked when the run ends (with the run's status)."""

    status: Literal["succeeded", "failed"] = "succeeded"
    """How the run ends (default: succeeded). With 'failed' the task is expected to fail;
    the other expectations are then checked on the scene it failed in."""
    error: str | None = None
    """Text the run's error must contain (with status: failed)."""

    @model_validator(mode="after")
    def _error_with_failure(self) -> TaskExpectation:
        if self.error is not None and self.status != "failed":
            raise ValueError("takes 'error' only with status: failed")
        if self.step_duration is not None:
            raise ValueError("takes 'step_duration' only in an 'expect' step (the task's "
                             "own duration is 'duration')")
        return self


Backend = Literal["mock", "sim", "mujoco"]


class Scenario(Node):
    """One way to run the task under ``run-task test``: parameters, seed, backend."""

    name: str = Field(min_length=1)
    """Shown in the test report."""
    parameters: dict[str, Annotated[Any, Field()]] = {}
    """Values for the task's parameters."""
    seed: Integer = Field(default=0, ge=0, le=2**32 - 1)
    """Seeds every planner call."""
    backend: Backend = "mock"
    """Where it runs: mock, sim or mujoco (never real servos)."""
    speed: Number | None = Field(default=None, gt=0, le=1000)
    """Speed of sim or mujoco, a multiple of real time."""
