"""Kinematics of a robot model: forward kinematics, Jacobians and inverse kinematics.

Configurations are state vectors (see :mod:`taskrunner.robot.model`); poses are in the
world frame, in metres and radians.
"""

from __future__ import annotations

from taskrunner.kinematics.fk import frame_jacobian, frame_pose, frame_poses
from taskrunner.kinematics.ik import IkSolver, IkTarget, is_reachable, solve_ik
from taskrunner.kinematics.ik_types import IkOptions, IkSolution

__all__ = [
    "IkOptions",
    "IkSolution",
    "IkSolver",
    "IkTarget",
    "frame_jacobian",
    "frame_pose",
    "frame_poses",
    "is_reachable",
    "solve_ik",
]
