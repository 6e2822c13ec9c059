"""What the MuJoCo backend (:mod:`taskrunner.backends.physics.backend`) is asked to
simulate (:class:`MujocoOptions`) and what it records of the world (:class:`PhysicsSample`).
Units: m, kg, rad, s, N.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

from taskrunner.backends.base import check_option
from taskrunner.backends.physics.mjcf import ObjectPhysics
from taskrunner.errors import ArgumentError
from taskrunner.types import JointState, Pose

__all__ = ["MujocoOptions", "PhysicsSample"]


@dataclass(frozen=True)
class MujocoOptions:
    """How :class:`~taskrunner.backends.physics.backend.MujocoBackend` simulates.

    Attributes:
        speed: None: as fast as the machine steps (the default; a benchmark reports the
            real-time factor); a number: paced at ``speed`` times real time.
        timestep: s per physics step (fixed).
        settle: s of physics after each trajectory's end, holding its last sample,
            before the motion ends and the world pauses.
        seed: seeds the only randomness (none in MuJoCo itself; kept for the record).
        tracking_tolerance: rad (m) a joint may lag its trajectory (fingers exempt).
        slip_distance: m a held object may move relative to its gripper.
        slip_angle: rad a held object may turn relative to its gripper.
        contact_force_limit: N, largest contact force on the robot outside grasps.
        effort: per joint, overriding the URDF effort limit (N m or N).
        saturation: per joint, the error (rad or m) at which its servo gives full effort.
        grip_effort: the most a finger joint pushes, by joint kind ("slide": N, "hinge":
            N m), unless ``effort`` names the joint: 20 N, or 0.5 N m (10 N at 5 cm).
        grasp_mode: per arm group, "friction" (default) or "weld"; over the cell's.
        objects: per object, its mass and friction, over what the cell or task gives;
            others get ``default_object``.
        default_object: see :class:`~taskrunner.backends.physics.mjcf.ObjectPhysics`.
        cache_dir: where compiled models are kept (None: the user cache).
        start_tolerance: largest accepted distance (rad or m) between a trajectory's first
            sample and a joint's measured position.
        history_period: s of physics between recorded samples (:meth:`history`,
            :meth:`physics_report`): 0.04 s, 25 Hz.
    """

    speed: float | None = None
    timestep: float = 0.002
    settle: float = 0.3
    seed: int = 0
    tracking_tolerance: float = 0.1
    slip_distance: float = 0.01
    slip_angle: float = math.radians(15.0)
    contact_force_limit: float = 100.0
    effort: Mapping[str, float] = field(default_factory=dict)
    saturation: Mapping[str, float] = field(default_factory=dict)
    grip_effort: Mapping[str, float] = field(
        default_factory=lambda: {"slide": 20.0, "hinge": 0.5})
    grasp_mode: Mapping[str, str] = field(default_factory=dict)
    objects: Mapping[str, ObjectPhysics] = field(default_factory=dict)
    default_object: ObjectPhysics = field(default_factory=ObjectPhysics)
    cache_dir: str | None = None
    start_tolerance: float = 0.05
    history_period: float = 0.04

    def __post_init__(self) -> None:
        check_option("speed", self.speed, lambda v: 0 < v < math.inf, "a positive number",
                     optional=True)
        check_option("timestep", self.timestep, lambda v: 0 < v <= 0.01, "in (0, 0.01] s")
        for name in ("settle", "tracking_tolerance", "slip_distance", "slip_angle",
                     "contact_force_limit", "start_tolerance", "history_period"):
            check_option(name, getattr(self, name), lambda v: 0 <= v < math.inf,
                         "a number >= 0")
        for arm, mode in self.grasp_mode.items():
            if mode not in ("friction", "weld"):
                raise ArgumentError(f"'grasp_mode' of {arm!r} must be 'friction' or 'weld' "
                                 f"(got {mode!r})")


@dataclass(frozen=True)
class PhysicsSample:
    """The world at one moment: physics time (s), every joint, every free object."""

    time: float
    joints: JointState
    objects: dict[str, Pose]
