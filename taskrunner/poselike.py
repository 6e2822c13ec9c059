"""Pose-like arguments of the Python API: a :class:`~taskrunner.Pose`, a task file's pose
mapping, or x, y, z; checked with the task file's model and messages, located at the
caller's line. Units: m, rad."""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

from taskrunner.errors import ArgumentError, InputError
from taskrunner.types import Pose

__all__ = ["PoseLike", "Position", "as_pose", "waypoint", "waypoint_list", "xyz"]

Position = Sequence[float]
PoseLike = Pose | Mapping[str, Any]
"""A :class:`~taskrunner.Pose`, or a pose as a task file writes it: ``{"xyz": [...],
"rpy": [...]}`` or ``{"xyz": [...], "quat": [...]}``, with an optional ``"frame"``
(m, radians, quaternion x, y, z, w), checked as a task file's pose is."""


def xyz(name: str, values: Position) -> tuple[float, float, float]:
    try:
        x, y, z = (float(v) for v in values)
    except (TypeError, ValueError):
        raise ArgumentError(f"'{name}' must be 3 numbers x, y, z in metres (got {values!r})") from None
    return (x, y, z)


def as_pose(value: PoseLike, field: str = "pose") -> tuple[Pose, bool]:
    """``value`` as a :class:`Pose`, and whether it gives an orientation (a mapping
    without ``rpy`` or ``quat`` does not: its orientation is the identity).

    A mapping is checked as a task file's pose is (the same model and messages), its
    errors located at the caller's line.

    Raises:
        TaskSpecError: an invalid mapping (an unknown key, not 3 values, both ``rpy``
            and ``quat``, a quaternion that is not a unit one ...).
        InputError: neither a Pose nor a mapping.
    """
    if isinstance(value, Pose):
        return value, True
    if not isinstance(value, Mapping):
        raise InputError(f"'{field}' must be a taskrunner.Pose or a mapping "
                         f"{{xyz, rpy | quat, frame}} (got {value!r})")
    from pydantic import ValidationError

    from taskrunner.builder import _caller as caller_location  # the user's file:line
    from taskrunner.tasks.nodes import PoseSpec
    from taskrunner.tasks.problem import problems_error, problems_from_validation

    data = dict(value)
    try:
        spec = PoseSpec.model_validate(data)
    except ValidationError as exc:
        where = caller_location()
        raise problems_error(problems_from_validation(
            exc, data, where.file if where else None, (field,), PoseSpec,
            where.line if where else None)) from None
    return spec.to_pose(), spec.has_orientation


def waypoint_list(waypoints: PoseLike | Position | Sequence[PoseLike | Position]
                   ) -> list[PoseLike | Position]:
    if isinstance(waypoints, (Pose, Mapping)):
        return [waypoints]
    items: list[Any] = list(waypoints)
    if items and all(isinstance(v, (int, float)) for v in items):
        return [tuple(items)]  # one x, y, z position
    return items


def waypoint(value: PoseLike | Position, here: Pose, index: int) -> Pose:
    """A waypoint pose: a Pose as given; a position, or a mapping without an
    orientation, with the link's start orientation."""
    if isinstance(value, (Pose, Mapping)):
        pose, oriented = as_pose(value, f"waypoints[{index}]")
        if oriented:
            return pose
        if pose.frame != "world":
            raise InputError(f"'waypoints[{index}]' without 'rpy' or 'quat' keeps the "
                             f"link's orientation in the world frame: it must have "
                             f"frame 'world' (got {pose.frame!r})")
        return Pose(pose.xyz, here.quat)
    return Pose(xyz("waypoints", value), here.quat)
