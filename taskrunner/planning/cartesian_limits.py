"""Timing a straight-line (Cartesian) motion within the tool's Cartesian limits.

MoveIt's Pilz planner bounds a straight motion of the tool by ``pilz_cartesian_limits.yaml``
(translational speed, acceleration and deceleration, rotational speed). Here the path is
first timed by the joint limits (toppra, :func:`~taskrunner.planning.timing.parameterize_path`);
when the link then moves faster than the limits allow, the path is timed again with every
joint velocity limit scaled by ``1/k`` and every acceleration limit by ``1/k²``. That
yields the same motion ``k`` times slower (joint velocities ``/k``, accelerations ``/k²``,
so the link's velocity ``J q̇`` scales by ``1/k`` and its acceleration ``J q̈ + J̇ q̇`` by
``1/k²``), with ``k`` the smallest factor that brings the link's speed, acceleration and
rotational speed within the limits. The retimed trajectory is measured again.

The deceleration limit is not told apart from the acceleration limit: the smaller of the
two bounds the link's acceleration along the whole motion (conservative).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np
import pinocchio as pin

from taskrunner.errors import PlanningError
from taskrunner.planning.timing import TimingOptions, parameterize_path
from taskrunner.robot.model import RobotModel
from taskrunner.robot.moveit_yaml import CartesianLimits
from taskrunner.types import JointPath, JointTrajectory

__all__ = ["CartesianMotion", "cartesian_limits_of", "measure_cartesian_motion",
           "time_cartesian_path"]

# Retimed limits aim this much below the Cartesian limits (toppra's own slack).
_MARGIN = 0.99


@dataclass(frozen=True)
class CartesianMotion:
    """The largest speeds of a link along a timed trajectory.

    Attributes:
        speed: translational speed (m/s).
        acceleration: translational acceleration (m/s²).
        rotation_speed: rotational speed (rad/s).
    """

    speed: float
    acceleration: float
    rotation_speed: float


def cartesian_limits_of(model: RobotModel, joint_names: tuple[str, ...]) -> CartesianLimits | None:
    """The Cartesian limits of the robot the joints belong to (the strictest of each
    limit when they span robots that all have limits; None when one has none)."""
    robots = dict.fromkeys(model.joint(name).robot for name in joint_names)
    given = [model.instance(r).cartesian_limits for r in robots]
    found = [f for f in given if f is not None]
    if not found or len(found) < len(given):
        return None
    if len(found) == 1:
        return found[0]
    return CartesianLimits(
        found[0].path, min(f.max_trans_vel for f in found), min(f.max_trans_acc for f in found),
        min(f.max_trans_dec for f in found), min(f.max_rot_vel for f in found))


def measure_cartesian_motion(model: RobotModel, trajectory: JointTrajectory,
                             link: str) -> CartesianMotion:
    """The largest speed, acceleration and rotational speed of ``link`` (in the world
    frame) at the trajectory's samples."""
    frame = model.frame_id(link)
    data = model.model.createData()
    columns = model.velocity_columns(trajectory.names)
    full = model.default_state()
    indices = model.indices(trajectory.names)
    qd = np.zeros(model.model.nv)
    qdd = np.zeros(model.model.nv)
    speed = acceleration = rotation = 0.0
    frame_kind = pin.ReferenceFrame.LOCAL_WORLD_ALIGNED
    for k in range(len(trajectory.times)):
        full[indices] = trajectory.positions[k]
        model.apply_mimic(full)
        qd[:] = 0.0
        qdd[:] = 0.0
        qd[columns] = trajectory.velocities[k]
        qdd[columns] = trajectory.accelerations[k]
        pin.forwardKinematics(model.model, data, model.to_pin(full), qd, qdd)
        velocity = pin.getFrameVelocity(model.model, data, frame, frame_kind)
        accel = pin.getFrameClassicalAcceleration(model.model, data, frame, frame_kind)
        speed = max(speed, float(np.linalg.norm(velocity.linear)))
        rotation = max(rotation, float(np.linalg.norm(velocity.angular)))
        acceleration = max(acceleration, float(np.linalg.norm(accel.linear)))
    return CartesianMotion(speed, acceleration, rotation)


def _excess(motion: CartesianMotion, limits: CartesianLimits) -> float:
    """How many times too fast the motion is (≤ 1: within the limits)."""
    accel_limit = min(limits.max_trans_acc, limits.max_trans_dec)
    return max(motion.speed / limits.max_trans_vel,
               math.sqrt(motion.acceleration / accel_limit),
               motion.rotation_speed / limits.max_rot_vel)


def time_cartesian_path(model: RobotModel, path: JointPath, link: str,
                        timing: TimingOptions | None = None,
                        limits: CartesianLimits | None = None) -> JointTrajectory:
    """Time a straight-line path by the joint limits and, when the robot has them (or
    ``limits`` is given), by the Cartesian limits of ``link`` (see the module docstring).

    Raises:
        PlanningError: the path cannot be timed, or the retimed motion still breaks the
            Cartesian limits (it never should; the message says by how much).
    """
    timing = timing or TimingOptions()
    trajectory = parameterize_path(model, path, timing)
    limits = limits if limits is not None else cartesian_limits_of(model, path.names)
    if limits is None or len(trajectory.times) < 2:
        return trajectory
    factor = _excess(measure_cartesian_motion(model, trajectory, link), limits)
    if factor <= 1.0:
        return trajectory
    robots = [model.instance(r) for r in dict.fromkeys(model.joint(n).robot for n in path.names)]
    v_scale = timing.velocity_scaling or min(r.velocity_scaling for r in robots)
    a_scale = timing.acceleration_scaling or min(r.acceleration_scaling for r in robots)
    k = factor / _MARGIN
    slower = replace(timing, velocity_scaling=v_scale / k, acceleration_scaling=a_scale / k**2)
    trajectory = parameterize_path(model, path, slower)
    after = measure_cartesian_motion(model, trajectory, link)
    if _excess(after, limits) > 1.02:  # sampled curves may peak a little between samples
        raise PlanningError(
            f"straight motion of {link!r} breaks its Cartesian limits ({limits.describe()}) "
            f"even slowed down {k:.2f} times: {after.speed:.3f} m/s, "
            f"{after.acceleration:.3f} m/s², {after.rotation_speed:.3f} rad/s")
    return trajectory
