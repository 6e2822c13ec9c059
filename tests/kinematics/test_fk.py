"""Forward kinematics and Jacobians, checked against independent computations."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.errors import InputError, UnknownNameError
from taskrunner.kinematics import frame_jacobian, frame_pose, frame_poses
from taskrunner.robot import RobotModel

# --------------------------------------------------------------------------- by hand


def _rot(axis: str, angle: float) -> np.ndarray:
    c, s = np.cos(angle), np.sin(angle)
    if axis == "x":
        return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])
    if axis == "y":
        return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def _transform(xyz=(0.0, 0.0, 0.0), rpy=(0.0, 0.0, 0.0), rotation=None) -> np.ndarray:
    """URDF origin: rotation Rz(yaw) Ry(pitch) Rx(roll), then translation."""
    out = np.eye(4)
    if rotation is None:
        rotation = _rot("z", rpy[2]) @ _rot("y", rpy[1]) @ _rot("x", rpy[0])
    out[:3, :3] = rotation
    out[:3, 3] = xyz
    return out


# Joint origins of example-robot-data's panda.urdf (every axis is z), then the fixed
# panda_joint8, panda_hand_joint and panda_hand_tcp_joint.
_HALF_PI = np.pi / 2
PANDA_JOINTS = [
    ((0, 0, 0.333), (0, 0, 0)),
    ((0, 0, 0), (-_HALF_PI, 0, 0)),
    ((0, -0.316, 0), (_HALF_PI, 0, 0)),
    ((0.0825, 0, 0), (_HALF_PI, 0, 0)),
    ((-0.0825, 0.384, 0), (-_HALF_PI, 0, 0)),
    ((0, 0, 0), (_HALF_PI, 0, 0)),
    ((0.088, 0, 0), (_HALF_PI, 0, 0)),
]
PANDA_FLANGE_TO_TCP = [((0, 0, 0.107), (0, 0, 0)), ((0, 0, 0), (0, 0, -np.pi / 4)),
                       ((0, 0, 0.1034), (0, 0, 0))]


def panda_tcp_by_hand(q: np.ndarray) -> np.ndarray:
    out = np.eye(4)
    for (xyz, rpy), angle in zip(PANDA_JOINTS, q[:7]):
        out = out @ _transform(xyz, rpy) @ _transform(rotation=_rot("z", angle))
    for xyz, rpy in PANDA_FLANGE_TO_TCP:
        out = out @ _transform(xyz, rpy)
    return out


# UR5 Denavit-Hartenberg parameters (Universal Robots); ROS's base_link is the DH base
# turned by pi about z.
UR5_D = (0.089159, 0.0, 0.0, 0.10915, 0.09465, 0.0823)
UR5_A = (0.0, -0.425, -0.39225, 0.0, 0.0, 0.0)
UR5_ALPHA = (_HALF_PI, 0.0, 0.0, _HALF_PI, -_HALF_PI, 0.0)


def ur5_tool0_by_dh(q: np.ndarray) -> np.ndarray:
    out = _transform(rotation=_rot("z", -np.pi))
    for theta, d, a, alpha in zip(q, UR5_D, UR5_A, UR5_ALPHA):
        out = (out @ _transform(rotation=_rot("z", theta)) @ _transform((a, 0, d))
               @ _transform(rotation=_rot("x", alpha)))
    return out


# --------------------------------------------------------------------------- poses


def test_panda_tcp_at_zero_is_the_published_pose(panda_model: RobotModel) -> None:
    pose = frame_pose(panda_model, np.zeros(panda_model.nq), "panda_hand_tcp")
    np.testing.assert_allclose(pose.translation, [0.088, 0.0, 0.8226], atol=1e-9)
    # Flange pointing down, hand turned -45 degrees about it.
    expected = _rot("x", np.pi) @ _rot("z", -np.pi / 4)
    np.testing.assert_allclose(pose.rotation, expected, atol=1e-9)


def test_panda_tcp_matches_the_urdf_chained_by_hand(panda_model: RobotModel) -> None:
    rng = np.random.default_rng(3)
    for _ in range(5):
        q = panda_model.random_state(rng)
        pose = frame_pose(panda_model, q, "panda_hand_tcp")
        np.testing.assert_allclose(pose.homogeneous, panda_tcp_by_hand(q), atol=1e-6)


def test_panda_default_pose_matches_the_urdf_chained_by_hand(panda_model: RobotModel) -> None:
    q = panda_model.state_with(panda_model.default_state(),
                               panda_model.named_state("arm_and_hand", "default"))
    pose = frame_pose(panda_model, q, "panda_hand_tcp")
    np.testing.assert_allclose(pose.homogeneous, panda_tcp_by_hand(q), atol=1e-6)


def test_ur5_tool0_at_zero_is_at_the_dh_coordinates(ur5_model: RobotModel) -> None:
    pose = frame_pose(ur5_model, np.zeros(6), "tool0")
    # x = -(a2 + a3), y = d4 + d6, z = d1 - d5 (base_link is the DH base turned by pi).
    np.testing.assert_allclose(pose.translation, [0.81725, 0.19145, -0.005491], atol=1e-6)


def test_ur5_tool0_matches_denavit_hartenberg(ur5_model: RobotModel) -> None:
    rng = np.random.default_rng(4)
    for _ in range(5):
        q = ur5_model.random_state(rng)
        pose = frame_pose(ur5_model, q, "tool0")
        np.testing.assert_allclose(pose.homogeneous, ur5_tool0_by_dh(q), atol=1e-6)


def test_frame_poses_agree_with_frame_pose(panda_model: RobotModel) -> None:
    q = panda_model.random_state(np.random.default_rng(5))
    frames = ["panda_link3", "panda_hand_tcp", "panda_joint4", "world"]
    poses = frame_poses(panda_model, q, frames)
    assert list(poses) == frames
    for frame in frames:
        np.testing.assert_allclose(
            poses[frame].homogeneous, frame_pose(panda_model, q, frame).homogeneous, atol=1e-12
        )


def test_frame_pose_returns_a_copy_that_later_calls_do_not_change(panda_model: RobotModel) -> None:
    first = frame_pose(panda_model, np.zeros(panda_model.nq), "panda_hand_tcp")
    kept = first.homogeneous.copy()
    frame_pose(panda_model, panda_model.random_state(np.random.default_rng(0)), "panda_hand_tcp")
    np.testing.assert_array_equal(first.homogeneous, kept)


def test_frame_pose_of_an_unknown_frame_raises_unknown_name(panda_model: RobotModel) -> None:
    with pytest.raises(UnknownNameError, match="panda_hand_tpc"):
        frame_pose(panda_model, np.zeros(panda_model.nq), "panda_hand_tpc")


def test_frame_pose_rejects_a_state_of_the_wrong_length(panda_model: RobotModel) -> None:
    with pytest.raises(InputError, match=r"'q' must be a state vector of shape \(9,\)"):
        frame_pose(panda_model, np.zeros(7), "panda_hand_tcp")


# --------------------------------------------------------------------------- Jacobians


def _finite_difference(model: RobotModel, q: np.ndarray, frame: str, indices, step=1e-6,
                       mimic: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """World-aligned (linear, angular) columns by central differences of the pose."""
    linear, angular = [], []
    for index in indices:
        plus, minus = q.copy(), q.copy()
        plus[index] += step
        minus[index] -= step
        if mimic:
            model.apply_mimic(plus)
            model.apply_mimic(minus)
        a, b = frame_pose(model, plus, frame), frame_pose(model, minus, frame)
        linear.append((a.translation - b.translation) / (2 * step))
        angular.append(pin.log3(a.rotation @ b.rotation.T) / (2 * step))
    return np.array(linear).T, np.array(angular).T


@pytest.mark.parametrize("frame", ["panda_hand_tcp", "panda_link5"])
def test_group_jacobian_matches_finite_differences(panda_model: RobotModel, frame: str) -> None:
    q = panda_model.random_state(np.random.default_rng(6))
    group = panda_model.group("arm")
    linear, angular = _finite_difference(panda_model, q, frame, group.joint_indices)
    world_aligned = frame_jacobian(panda_model, q, frame, "arm")
    assert world_aligned.shape == (6, 7)
    np.testing.assert_allclose(world_aligned[:3], linear, atol=1e-6)
    np.testing.assert_allclose(world_aligned[3:], angular, atol=1e-6)
    rotation = frame_pose(panda_model, q, frame).rotation
    local = frame_jacobian(panda_model, q, frame, group, reference="local")
    np.testing.assert_allclose(local[:3], rotation.T @ linear, atol=1e-6)
    np.testing.assert_allclose(local[3:], rotation.T @ angular, atol=1e-6)


def test_full_state_jacobian_has_one_column_per_state_entry(ur5_model: RobotModel) -> None:
    q = ur5_model.random_state(np.random.default_rng(7))
    jacobian = frame_jacobian(ur5_model, q, "tool0")
    linear, angular = _finite_difference(ur5_model, q, "tool0", range(ur5_model.nq))
    assert jacobian.shape == (6, ur5_model.nq)
    np.testing.assert_allclose(jacobian, np.vstack([linear, angular]), atol=1e-6)


def test_jacobian_columns_follow_the_requested_joint_order(ur5_model: RobotModel) -> None:
    q = ur5_model.random_state(np.random.default_rng(8))
    names = ["wrist_3_joint", "shoulder_pan_joint"]
    full = frame_jacobian(ur5_model, q, "tool0", reference="world")
    picked = frame_jacobian(ur5_model, q, "tool0", names, reference="world")
    np.testing.assert_allclose(picked, full[:, [5, 0]])


def test_jacobian_folds_a_mimic_joint_into_its_source(panda_model: RobotModel) -> None:
    q = panda_model.state_with(panda_model.random_state(np.random.default_rng(9)),
                               {"panda_finger_joint1": 0.02})
    finger1 = panda_model.joint("panda_finger_joint1").index
    finger2 = panda_model.joint("panda_finger_joint2").index
    # Listed alone, finger 1 drives finger 2 (mimic): its column moves the right finger.
    column = frame_jacobian(panda_model, q, "panda_rightfinger", ["panda_finger_joint1"])
    linear, _ = _finite_difference(panda_model, q, "panda_rightfinger", [finger1])
    np.testing.assert_allclose(column[:3], linear, atol=1e-6)
    assert np.linalg.norm(column[:3]) == pytest.approx(1.0)
    # Over the whole state vector each entry is a partial derivative.
    full = frame_jacobian(panda_model, q, "panda_rightfinger")
    assert np.allclose(full[:, finger1], 0.0)
    linear, _ = _finite_difference(panda_model, q, "panda_rightfinger", [finger2], mimic=False)
    np.testing.assert_allclose(full[:3, finger2], linear[:, 0], atol=1e-6)


def test_jacobian_rejects_an_unknown_reference(panda_model: RobotModel) -> None:
    with pytest.raises(InputError, match="'reference' must be one of"):
        frame_jacobian(panda_model, np.zeros(panda_model.nq), "panda_hand_tcp",
                       reference="global")


def test_jacobian_of_an_unknown_joint_raises_unknown_name(panda_model: RobotModel) -> None:
    with pytest.raises(UnknownNameError, match="panda_joint9"):
        frame_jacobian(panda_model, np.zeros(panda_model.nq), "panda_hand_tcp", ["panda_joint9"])
