"""Where an object ended compared with where the task asked: the outcome of a place or hand-over.

After a ``place`` the object must be at its target and rest on something; after a
``handoff`` it must be at the hand-over pose when it changes hands. A leaf that moved
without error has only done what it planned; this module looks at the scene afterwards.

Errors are measured between the requested world pose of the object (``wanted``) and the
one it has in the scene (``reached``):

- *distance*: between their origins (m);
- *angle*: of the rotation from one orientation to the other (rad), the smallest over
  the object's symmetries (:func:`~taskrunner.tree.grasps.symmetries`: a cube turned a
  quarter turn, a bar turned end for end, cannot be told apart);
- *turn* and *tilt*: that rotation, in world axes, split into a turn about the world z
  axis and a tilt of the object's axes away from where the request puts them (the angle
  through which it moves the world vertical; swing–twist decomposition). The tilt is the
  smallest over the symmetries, the turn the smallest over the symmetries of that tilt (within
  a milliradian; a symmetry that turns the object upside down says nothing of its heading).

What is checked is the step's :class:`Orientation`: ``free`` the position only, ``yaw`` the
position and the turn about the world z axis (the tilt is reported, not checked),
``full`` the position and the whole orientation (the angle).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass
from enum import StrEnum

import numpy as np
import pinocchio as pin

from taskrunner.errors import ArgumentError, SceneError
from taskrunner.robot.model import RobotModel
from taskrunner.scene import Scene
from taskrunner.scene.support import Support
from taskrunner.tree.grasps import symmetries
from taskrunner.tree.reach import wrist_roll

__all__ = ["DEFAULT_ANGLE", "DEFAULT_POSITION", "Orientation", "Outcome", "PoseError",
           "Tolerance", "arm_orientation", "describe_pose", "measure", "pose_error"]

DEFAULT_POSITION = 0.005
"""Default position tolerance (m)."""
DEFAULT_ANGLE = math.radians(5.0)
"""Default angle tolerance (rad)."""
_SAME_TILT = 1e-3  # rad: tilts this close are one (a request written 1.5708 is not pi/2)


class Orientation(StrEnum):
    """What of an object's orientation a step checks (see the module docstring)."""

    FREE = "free"
    YAW = "yaw"
    FULL = "full"


@dataclass(frozen=True)
class Tolerance:
    """How far an object may end from its target.

    Attributes:
        position: distance between the origins (m), > 0; also the largest gap allowed
            between a placed object and what it rests on.
        angle: angle of the orientation error, or of its turn about z (rad), > 0.
    """

    position: float = DEFAULT_POSITION
    angle: float = DEFAULT_ANGLE

    def __post_init__(self) -> None:
        for name in ("position", "angle"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
                raise ArgumentError(f"'{name}' must be a finite number > 0 (got {value!r})")

    def __str__(self) -> str:
        return f"{1e3 * self.position:g} mm, {math.degrees(self.angle):g}°"


@dataclass(frozen=True)
class PoseError:
    """How far ``reached`` is from ``wanted`` (module docstring).

    Attributes:
        distance: m.
        angle: rad, the whole orientation.
        turn: rad, about the world z axis.
        tilt: rad, of the object's axes away from the requested ones.
    """

    distance: float
    angle: float
    turn: float
    tilt: float


def _split(error: np.ndarray) -> tuple[float, float]:
    """``(turn about world z, tilt)`` of a rotation in world axes (rad)."""
    q = pin.Quaternion(error)
    turn = 2.0 * math.atan2(abs(q.z), abs(q.w))
    tilt = math.acos(float(np.clip(error[2, 2], -1.0, 1.0)))
    return turn, tilt


def pose_error(wanted: pin.SE3, reached: pin.SE3, turns: Sequence[np.ndarray] = ()) -> PoseError:
    """The error of ``reached`` from ``wanted`` (world poses), the smallest over the
    object-frame rotations ``turns`` that leave the object as it was (its symmetries;
    none: the identity only)."""
    angles, splits = [], []
    for s in turns or (np.eye(3),):
        error = reached.rotation @ (wanted.rotation @ s).T
        angles.append(float(np.linalg.norm(pin.log3(error))))
        splits.append(_split(error))
    tilt = min(t for _, t in splits)
    turn = min(z for z, t in splits if t <= tilt + _SAME_TILT)
    distance = float(np.linalg.norm(reached.translation - wanted.translation))
    return PoseError(distance, min(angles), turn, tilt)


def describe_pose(pose: pin.SE3) -> str:
    """``xyz (x, y, z) rpy (r, p, y)°``: m, and URDF roll-pitch-yaw in degrees."""
    xyz = ", ".join(f"{round(v, 4) + 0.0:.4f}" for v in pose.translation)
    rpy = ", ".join(f"{round(math.degrees(v), 1) + 0.0:.1f}"
                    for v in pin.rpy.matrixToRpy(pose.rotation))
    return f"xyz ({xyz}) rpy ({rpy})°"


def arm_orientation(model: RobotModel, group: str, link: str, q: np.ndarray) -> Orientation:
    """The orientation an arm controls, the default of its steps: ``full`` for an arm that
    plans full poses; for one that plans positions only, ``yaw`` when its last joint rolls
    ``link`` about its own z axis (a wrist roll turns what it holds about the vertical),
    else ``free``."""
    if not model.group(group).position_only_ik:
        return Orientation.FULL
    return Orientation.YAW if wrist_roll(model, group, link, q) is not None else Orientation.FREE


@dataclass(frozen=True)
class Outcome:
    """Where an object ended, measured against its target.

    Attributes:
        object: the object's name.
        wanted: its requested world pose.
        reached: its world pose in the scene.
        error: see :class:`PoseError`.
        orientation: what was checked.
        tolerance: the limits.
        support: what it rests on (after a place), or None (not asked).
    """

    object: str
    wanted: pin.SE3
    reached: pin.SE3
    error: PoseError
    orientation: Orientation
    tolerance: Tolerance
    support: Support | None = None

    @property
    def failure(self) -> str | None:
        """Why the outcome misses its target (error in mm and degrees, both poses), or None."""
        e, tol = self.error, self.tolerance
        misses = []
        if e.distance > tol.position:
            misses.append(f"{1e3 * e.distance:.1f} mm from its target position")
        if self.orientation is Orientation.FULL and e.angle > tol.angle:
            misses.append(f"turned {math.degrees(e.angle):.1f}° from its target orientation")
        if self.orientation is Orientation.YAW and e.turn > tol.angle:
            misses.append(f"turned {math.degrees(e.turn):.1f}° about the world z axis from "
                          "its target orientation")
        if misses:
            return (f"{self.object!r} ended {' and '.join(misses)} (tolerance {tol}, "
                    f"orientation: {self.orientation.value}): {self.poses()}")
        if self.support is not None and self.support.gap > tol.position:
            if self.support.below is None:
                return (f"{self.object!r} rests on nothing: no object below it within "
                        f"1 m (achieved {describe_pose(self.reached)})")
            return (f"{self.object!r} floats {1e3 * self.support.gap:.1f} mm above "
                    f"{self.support.below!r} (tolerance {1e3 * tol.position:g} mm): "
                    f"{self.poses()}")
        return None

    def poses(self) -> str:
        """Both poses and the whole error."""
        e = self.error
        return (f"requested {describe_pose(self.wanted)}, achieved "
                f"{describe_pose(self.reached)}; error {1e3 * e.distance:.1f} mm, "
                f"{math.degrees(e.angle):.1f}° (tilt {math.degrees(e.tilt):.1f}°, turn about "
                f"z {math.degrees(e.turn):.1f}°)")


def measure(scene: Scene, obj: str, wanted: pin.SE3, orientation: Orientation,
            tolerance: Tolerance, supported: bool) -> Outcome:
    """The outcome of object ``obj`` in ``scene`` against ``wanted`` (world).

    Args:
        supported: the object was put down: find what it rests on.

    Raises:
        UnknownNameError: no such object.
        SceneError: ``supported`` and the object is attached.
    """
    shape = scene.object(obj).shape
    try:
        turns = symmetries(shape)
    except SceneError:  # a mesh: no symmetry known
        turns = []
    reached = scene.object_pose(obj).se3
    support = scene.support(obj) if supported else None
    return Outcome(obj, wanted, reached, pose_error(wanted, reached, turns), orientation,
                   tolerance, support)
