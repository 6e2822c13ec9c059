"""Forward kinematics and Jacobians of any frame, for a state vector.

A *state vector* has one value per 1-DOF joint of the model (rad or m), in
:attr:`RobotModel.joint_names` order, mimic joints included (see
:mod:`taskrunner.robot.model`). Poses are expressed in the world frame (the model's root).

Jacobian columns are velocities of the listed joints: ``v = J @ qd``, with ``v`` the
spatial velocity ``(linear m/s, angular rad/s)`` of the frame in the chosen reference:

* ``"local_world_aligned"``: at the frame's origin, axes of the world (linear part = the
  time derivative of the frame's world position);
* ``"local"``: at the frame's origin, axes of the frame;
* ``"world"``: pinocchio's spatial velocity at the world origin, world axes.
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pinocchio as pin

from taskrunner.errors import InputError
from taskrunner.robot.model import Group, RobotModel

__all__ = [
    "JointsArg",
    "frame_jacobian",
    "frame_pose",
    "frame_poses",
    "jacobian_columns",
    "parse_reference",
]

JointsArg = Group | str | Sequence[str] | None
"""Which joints a Jacobian has columns for: a group (object or name), joint names, or
None for the whole state vector."""

_REFERENCES = {
    "local_world_aligned": pin.LOCAL_WORLD_ALIGNED,
    "local": pin.LOCAL,
    "world": pin.WORLD,
}


def parse_reference(reference: str | pin.ReferenceFrame) -> pin.ReferenceFrame:
    """Pinocchio reference frame of ``"local_world_aligned"``, ``"local"`` or ``"world"``."""
    if isinstance(reference, pin.ReferenceFrame):
        return reference
    try:
        return _REFERENCES[reference]
    except (KeyError, TypeError):
        raise InputError(
            f"'reference' must be one of {sorted(_REFERENCES)} (got {reference!r})"
        ) from None


def _state_vector(model: RobotModel, q: np.ndarray) -> np.ndarray:
    q = np.asarray(q, dtype=float)
    if q.shape != (model.nq,):
        raise InputError(f"'q' must be a state vector of shape ({model.nq},) (got {q.shape})")
    return q


def frame_pose(
    model: RobotModel, q: np.ndarray, frame: str, data: pin.Data | None = None
) -> pin.SE3:
    """Pose of a link or frame in the world frame.

    Args:
        model: the robot model.
        q: state vector (rad or m).
        frame: link or frame name.
        data: pinocchio data to compute in (default ``model.data``; pass your own when
            several threads compute at once).

    Returns:
        ``world_T_frame`` (a new SE3; translation in m).

    Raises:
        UnknownNameError: ``frame`` is not in the model.
        InputError: ``q`` has the wrong length.
    """
    frame_id = model.frame_id(frame)
    data = model.data if data is None else data
    pin.forwardKinematics(model.model, data, model.to_pin(_state_vector(model, q)))
    return pin.SE3(pin.updateFramePlacement(model.model, data, frame_id))


def frame_poses(
    model: RobotModel, q: np.ndarray, frames: Sequence[str], data: pin.Data | None = None
) -> dict[str, pin.SE3]:
    """Poses of several links or frames in the world frame, from one FK pass.

    Returns:
        ``{frame: world_T_frame}`` in the order of ``frames``.
    """
    ids = [model.frame_id(f) for f in frames]
    data = model.data if data is None else data
    pin.forwardKinematics(model.model, data, model.to_pin(_state_vector(model, q)))
    return {f: pin.SE3(pin.updateFramePlacement(model.model, data, i)) for f, i in zip(frames, ids)}


def jacobian_columns(
    model: RobotModel, joints: JointsArg
) -> tuple[tuple[str, ...], np.ndarray, list[tuple[int, int, float]]]:
    """Map state-vector joints to columns of pinocchio's Jacobian.

    Args:
        model: the robot model.
        joints: a group (object or name), joint names, or None for every joint of the
            state vector.

    Returns:
        ``(names, columns, mimic_terms)``: the joint names (the output columns, in order),
        their pinocchio tangent columns, and for every mimic joint that is not listed but
        follows a listed joint, ``(output column, pinocchio column, multiplier)`` to add.

    Raises:
        UnknownNameError: an unknown group or joint.
    """
    if joints is None:
        names = model.joint_names
    elif isinstance(joints, Group):
        names = joints.joint_names
    elif isinstance(joints, str):
        names = model.group(joints).joint_names
    else:
        names = tuple(joints)
        for name in names:
            model.joint(name)
    columns = model.velocity_columns(names)
    position = {name: k for k, name in enumerate(names)}
    mimic_terms = []
    for info in model.joints:
        if info.mimic is None or info.name in position:
            continue
        if info.mimic.source in position:
            pin_column = int(model.velocity_columns([info.name])[0])
            mimic_terms.append((position[info.mimic.source], pin_column, info.mimic.multiplier))
    return tuple(names), columns, mimic_terms


def frame_jacobian(
    model: RobotModel,
    q: np.ndarray,
    frame: str,
    joints: JointsArg = None,
    reference: str | pin.ReferenceFrame = "local_world_aligned",
    data: pin.Data | None = None,
) -> np.ndarray:
    """Jacobian of a link or frame with respect to joint velocities.

    Args:
        model: the robot model.
        q: state vector (rad or m).
        frame: link or frame name.
        joints: the columns: a group (object or name; columns in the group's joint order),
            a sequence of joint names, or None for every entry of the state vector (in
            state order). Mimic joints that are not listed follow their source joint, so
            their motion is added to the source's column; listed ones get their own
            column (the partial derivative).
        reference: ``"local_world_aligned"`` (default), ``"local"`` or ``"world"`` (see
            the module docstring).
        data: pinocchio data to compute in (default ``model.data``).

    Returns:
        A ``(6, len(joints))`` array; rows are linear (m/s) then angular (rad/s) velocity
        per unit joint velocity (rad/s or m/s).

    Raises:
        UnknownNameError: an unknown frame, group or joint.
        InputError: a bad ``reference`` or ``q`` of the wrong length.
    """
    frame_id = model.frame_id(frame)
    ref = parse_reference(reference)
    _, columns, mimic_terms = jacobian_columns(model, joints)
    data = model.data if data is None else data
    full = pin.computeFrameJacobian(
        model.model, data, model.to_pin(_state_vector(model, q)), frame_id, ref
    )
    out = full[:, columns]
    for out_column, pin_column, multiplier in mimic_terms:
        out[:, out_column] += multiplier * full[:, pin_column]
    return out
