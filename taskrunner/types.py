"""Plain data types shared across the pipeline.

Joint names travel with the arrays: a configuration, a path or a trajectory always says
which joints its columns are, so nothing depends on an implicit joint order.
All angles are radians, lengths metres, times seconds.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import numpy as np
import pinocchio as pin

from taskrunner.errors import ArgumentError, InputError

__all__ = ["JointState", "JointPath", "JointTrajectory", "Pose", "pose_from_xyz_rpy"]


def _as_readonly(values: object, ndim: int, what: str) -> np.ndarray:
    array = np.array(values, dtype=float)
    if array.ndim != ndim:
        raise ArgumentError(f"'{what}' must have {ndim} dimension(s) (got shape {array.shape})")
    array.setflags(write=False)
    return array


@dataclass(frozen=True)
class JointState:
    """Positions of named joints (rad or m)."""

    names: tuple[str, ...]
    positions: np.ndarray

    def __post_init__(self) -> None:
        object.__setattr__(self, "names", tuple(self.names))
        object.__setattr__(self, "positions", _as_readonly(self.positions, 1, "positions"))
        if len(self.names) != len(self.positions):
            raise ArgumentError(
                f"'positions' must have one value per joint ({len(self.names)}) "
                f"(got {len(self.positions)})"
            )

    @classmethod
    def from_mapping(cls, values: Mapping[str, float]) -> JointState:
        """Build from ``{joint_name: value}``."""
        return cls(tuple(values), np.array(list(values.values()), dtype=float))

    def as_dict(self) -> dict[str, float]:
        """``{joint_name: value}``."""
        return {n: float(v) for n, v in zip(self.names, self.positions)}


@dataclass(frozen=True)
class JointPath:
    """A geometric path: waypoints (one row each) over named joints, no timing."""

    names: tuple[str, ...]
    waypoints: np.ndarray

    def __post_init__(self) -> None:
        object.__setattr__(self, "names", tuple(self.names))
        object.__setattr__(self, "waypoints", _as_readonly(self.waypoints, 2, "waypoints"))
        if self.waypoints.shape[1] != len(self.names):
            raise ArgumentError(
                f"'waypoints' must have {len(self.names)} columns (got {self.waypoints.shape[1]})"
            )

    def __len__(self) -> int:
        return int(self.waypoints.shape[0])


@dataclass(frozen=True)
class JointTrajectory:
    """A timed trajectory sampled at ``times`` (s), with positions, velocities, accelerations."""

    names: tuple[str, ...]
    times: np.ndarray
    positions: np.ndarray
    velocities: np.ndarray
    accelerations: np.ndarray

    def __post_init__(self) -> None:
        object.__setattr__(self, "names", tuple(self.names))
        object.__setattr__(self, "times", _as_readonly(self.times, 1, "times"))
        for attr in ("positions", "velocities", "accelerations"):
            array = _as_readonly(getattr(self, attr), 2, attr)
            if array.shape != (len(self.times), len(self.names)):
                raise ArgumentError(
                    f"'{attr}' must have shape {(len(self.times), len(self.names))} "
                    f"(got {array.shape})"
                )
            object.__setattr__(self, attr, array)
        if len(self.times) and np.any(np.diff(self.times) <= 0):
            raise ArgumentError("'times' must be strictly increasing")

    @property
    def duration(self) -> float:
        """Time of the last sample (s)."""
        return float(self.times[-1]) if len(self.times) else 0.0


@dataclass(frozen=True)
class Pose:
    """A rigid transform: translation (m) and unit quaternion (x, y, z, w), in ``frame``."""

    xyz: tuple[float, float, float] = (0.0, 0.0, 0.0)
    quat: tuple[float, float, float, float] = (0.0, 0.0, 0.0, 1.0)
    frame: str = "world"
    _se3: pin.SE3 = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        xyz = tuple(float(v) for v in self.xyz)
        quat = np.array(self.quat, dtype=float)
        if len(xyz) != 3:
            raise ArgumentError(f"'xyz' must have 3 values (got {len(xyz)})")
        if quat.shape != (4,):
            raise ArgumentError(f"'quat' must have 4 values x, y, z, w (got {len(quat)})")
        norm = float(np.linalg.norm(quat))
        if not np.isfinite(norm) or norm < 1e-9:
            raise ArgumentError(f"'quat' must be a non-zero quaternion (got {tuple(quat)})")
        quat = quat / norm
        object.__setattr__(self, "xyz", xyz)
        object.__setattr__(self, "quat", tuple(float(v) for v in quat))
        rotation = pin.Quaternion(quat[3], quat[0], quat[1], quat[2]).toRotationMatrix()
        object.__setattr__(self, "_se3", pin.SE3(rotation, np.array(xyz)))

    @property
    def se3(self) -> pin.SE3:
        """The transform as a pinocchio SE3 (a copy)."""
        return pin.SE3(self._se3)

    @classmethod
    def from_se3(cls, transform: pin.SE3, frame: str = "world") -> Pose:
        """Build from a pinocchio SE3."""
        q = pin.Quaternion(transform.rotation)
        return cls(tuple(transform.translation), (q.x, q.y, q.z, q.w), frame)

    @classmethod
    def from_rpy(cls, xyz: Sequence[float] = (0.0, 0.0, 0.0),
                 rpy: Sequence[float] = (0.0, 0.0, 0.0), frame: str = "world") -> Pose:
        """A pose from a translation (m) and roll, pitch, yaw in **radians** (fixed axes X,
        then Y, then Z, as in URDF and in task files' ``rpy``)::

            Pose.from_rpy([0.45, 0.1, 1.0], [math.pi, 0, 0])   # the tool pointing down

        Raises:
            InputError: ``rpy`` is not 3 finite numbers.
        """
        try:
            angles = np.array(rpy, dtype=float)
        except (TypeError, ValueError):
            angles = np.array([])
        if angles.shape != (3,) or not np.all(np.isfinite(angles)):
            raise InputError(f"'rpy' must be 3 finite numbers roll, pitch, yaw in radians "
                             f"(got {rpy!r})")
        rotation = pin.rpy.rpyToMatrix(*(float(a) for a in angles))
        q = pin.Quaternion(rotation)
        return cls(tuple(xyz), (q.x, q.y, q.z, q.w), frame)  # type: ignore[arg-type]


def pose_from_xyz_rpy(
    xyz: Sequence[float] = (0.0, 0.0, 0.0),
    rpy: Sequence[float] = (0.0, 0.0, 0.0),
    frame: str = "world",
) -> Pose:
    """A pose from a translation (m) and roll-pitch-yaw angles (rad, URDF convention):
    :meth:`Pose.from_rpy`."""
    return Pose.from_rpy(xyz, rpy, frame)
