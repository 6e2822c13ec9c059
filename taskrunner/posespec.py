"""The pose as files and requests write it, defined once: ``xyz`` (m) and an optional
orientation, ``rpy`` (rad, URDF's roll-pitch-yaw: fixed axes X, then Y, then Z) or
``quat`` (a unit quaternion x, y, z, w), in a ``frame``.

:class:`PoseFields` holds the fields and their checks; a file's model adds its own
configuration (a task file's :class:`~taskrunner.tasks.nodes.Node` with its line, a cell
file's frozen model, a REST request's), so a ``quat`` works wherever a pose is written.

Every number is checked before any arithmetic touches it: a coordinate is finite and
within ±:data:`~taskrunner.validation.MAX_METRES`, an angle finite and within
±:data:`~taskrunner.validation.MAX_RADIANS`, a quaternion four finite numbers whose norm
(computed without overflow) is 1 within :data:`QUAT_TOLERANCE`. A number past these
(``1e308``) is refused with the field's name, never overflowing a product on the way.
"""

from __future__ import annotations

import math
from typing import Annotated

import numpy as np
import pinocchio as pin
from pydantic import BaseModel, Field, field_validator, model_validator

from taskrunner.errors import ArgumentError
from taskrunner.types import Pose
from taskrunner.validation import Metres, Number, Radians

__all__ = ["QUAT_TOLERANCE", "WORLD", "Angles", "PoseFields", "Position",
           "Quaternion", "TransformFields", "check_quat"]

WORLD = "world"

Position = Annotated[tuple[Metres, ...], Field(min_length=3, max_length=3)]
Angles = Annotated[tuple[Radians, ...], Field(min_length=3, max_length=3)]
Quaternion = Annotated[tuple[Number, ...], Field(min_length=4, max_length=4)]
"""Four finite numbers x, y, z, w; :func:`check_quat` makes them a unit quaternion."""

QUAT_TOLERANCE = 1e-3
"""How far a quaternion's norm may be from 1 (it is normalized)."""


def check_quat(value: tuple[float, ...] | None) -> tuple[float, ...] | None:
    """``value`` normalized, or an error unless it is a unit quaternion (within
    :data:`QUAT_TOLERANCE`); any finite components are safe here (the norm is computed
    without overflow)."""
    if value is None:
        return None
    norm = math.hypot(*(float(v) for v in value))
    if not math.isfinite(norm) or abs(norm - 1.0) > QUAT_TOLERANCE:
        raise ArgumentError(f"must be a unit quaternion [x, y, z, w] (got norm {norm:.4g})")
    return tuple(float(v) / norm for v in value)


class TransformFields(BaseModel):
    """A rigid transform: translation and an optional orientation (``rpy`` or ``quat``)."""

    xyz: Position = (0.0, 0.0, 0.0)
    """Translation (m)."""
    rpy: Angles | None = None
    """Orientation as roll, pitch, yaw (rad, fixed axes X then Y then Z); not with 'quat'."""
    quat: Quaternion | None = None
    """Orientation as a unit quaternion [x, y, z, w]; not with 'rpy'."""

    @field_validator("quat")
    @classmethod
    def _quat_is_unit(cls, value: tuple[float, ...] | None) -> tuple[float, ...] | None:
        return check_quat(value)

    @model_validator(mode="after")
    def _one_orientation(self) -> TransformFields:
        if self.rpy is not None and self.quat is not None:
            raise ValueError("takes only one of 'rpy' or 'quat'")
        return self

    @property
    def has_orientation(self) -> bool:
        """Whether an orientation was given (else :meth:`rotation` is the identity)."""
        return self.rpy is not None or self.quat is not None

    def rotation(self) -> np.ndarray:
        """The 3x3 rotation matrix (identity when no orientation was given)."""
        if self.quat is not None:
            x, y, z, w = self.quat
            return np.array(pin.Quaternion(w, x, y, z).toRotationMatrix())
        if self.rpy is not None:
            return np.array(pin.rpy.rpyToMatrix(*self.rpy))
        return np.eye(3)

    def se3(self) -> pin.SE3:
        """The transform as a pinocchio SE3."""
        return pin.SE3(self.rotation(), np.array(self.xyz, dtype=float))


class PoseFields(TransformFields):
    """A pose in a frame: 'world', a link of the cell, or an object of the scene."""

    frame: str = WORLD
    """Frame the pose is expressed in: 'world', a link name or an object name."""

    def to_pose(self) -> Pose:
        """As a :class:`taskrunner.types.Pose` (identity orientation if none was given)."""
        return Pose.from_se3(self.se3(), self.frame)
