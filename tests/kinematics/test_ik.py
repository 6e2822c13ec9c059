"""Inverse kinematics: round trips, limits, restarts, failures and reproducibility."""

from __future__ import annotations

import time
from itertools import combinations
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.errors import IkFailedError, InputError, UnknownNameError
from taskrunner.kinematics import (
    IkOptions,
    IkSolution,
    IkSolver,
    frame_pose,
    is_reachable,
    solve_ik,
)
from taskrunner.robot import Group, RobotModel, load_robot
from taskrunner.types import Pose

# Generous enough that a loaded machine does not cut a search short: these tests check
# what is found, benchmarks/ik_bench.py checks how fast.
PATIENT = IkOptions(timeout=0.5, attempts=500)


def _targets(model: RobotModel, group: str, frame: str, count: int, seed: int):
    rng = np.random.default_rng(seed)
    return [frame_pose(model, model.random_state(rng, group), frame) for _ in range(count)]


def _assert_valid(model: RobotModel, solution: IkSolution, target: pin.SE3,
                  position_only: bool = False, tolerance: float = 1e-5) -> None:
    assert model.within_limits(solution.q, tolerance=0.0), model.limit_violations(solution.q)
    pose = frame_pose(model, solution.q, solution.frame)
    assert np.linalg.norm(pose.translation - target.translation) <= tolerance
    if not position_only:
        assert np.linalg.norm(pin.log3(pose.rotation.T @ target.rotation)) <= tolerance


# --------------------------------------------------------------------------- round trips


@pytest.mark.parametrize(("robot", "group"), [("panda_model", "arm"),
                                              ("ur5_model", "manipulator")])
def test_full_pose_round_trips_within_limits_and_tolerance(request, robot: str, group: str) -> None:
    model = request.getfixturevalue(robot)
    solver = IkSolver(model, group, options=PATIENT)
    for target in _targets(model, group, solver.frame, 40, seed=11):
        solution = solver.solve(target)
        _assert_valid(model, solution, target)
        assert solution.position_error <= 1e-5 and solution.rotation_error <= 1e-5
        assert solution.joint_state.names == model.group(group).joint_names
        np.testing.assert_array_equal(
            solution.joint_state.positions, solution.q[model.group(group).joint_indices]
        )


def test_position_only_round_trips_on_the_panda(panda_model: RobotModel) -> None:
    options = IkOptions(timeout=0.5, attempts=500, position_only=True)
    solver = IkSolver(panda_model, "arm", options=options)
    for target in _targets(panda_model, "arm", "panda_hand_tcp", 40, seed=12):
        solution = solver.solve(target)
        _assert_valid(panda_model, solution, target, position_only=True)
        assert solution.rotation_error is None
        assert solution.error == solution.position_error


def test_servo_arm_solves_position_only_from_its_kinematics_settings(
    servo_arm_model: RobotModel,
) -> None:
    assert servo_arm_model.group("arm").position_only_ik
    solver = IkSolver(servo_arm_model, "arm", options=PATIENT)
    for target in _targets(servo_arm_model, "arm", solver.frame, 40, seed=13):
        solution = solver.solve(target)  # a full pose: its orientation is ignored
        _assert_valid(servo_arm_model, solution, target, position_only=True)
        assert solution.rotation_error is None


def test_a_call_can_ask_for_the_full_pose_on_a_position_only_group(
    servo_arm_model: RobotModel,
) -> None:
    q = servo_arm_model.random_state(np.random.default_rng(14), "arm")
    target = frame_pose(servo_arm_model, q, "gripper_base_1")
    solution = solve_ik(servo_arm_model, "arm", target,
                        options=IkOptions(timeout=0.5, attempts=500, position_only=False))
    _assert_valid(servo_arm_model, solution, target)


def test_a_link_other_than_the_tip_can_be_aimed(panda_model: RobotModel) -> None:
    solver = IkSolver(panda_model, "arm", frame="panda_link6", options=PATIENT)
    assert solver.frame == "panda_link6"
    joint7 = panda_model.joint("panda_joint7").index
    seed_q = panda_model.state_with(panda_model.default_state(), {"panda_joint7": 0.3})
    for target in _targets(panda_model, "arm", "panda_link6", 10, seed=15):
        solution = solver.solve(target, seed_q)
        _assert_valid(panda_model, solution, target)
        assert solution.q[joint7] == 0.3  # joint 7 does not move panda_link6


def test_targets_can_be_given_as_pose_matrix_or_position(panda_model: RobotModel) -> None:
    solver = IkSolver(panda_model, "arm", options=PATIENT)
    q = panda_model.random_state(np.random.default_rng(16), "arm")
    target = frame_pose(panda_model, q, "panda_hand_tcp")
    for given in (Pose.from_se3(target), target.homogeneous):
        _assert_valid(panda_model, solver.solve(given), target)
    position = solver.solve(target.translation)  # a bare position: position only
    _assert_valid(panda_model, position, target, position_only=True)
    assert position.rotation_error is None


def test_a_pose_in_a_link_frame_is_taken_at_the_seed_state(panda_model: RobotModel) -> None:
    solver = IkSolver(panda_model, "arm", options=PATIENT)
    seed_q = panda_model.random_state(np.random.default_rng(17), "arm")
    link2 = frame_pose(panda_model, seed_q, "panda_link2")
    goal = frame_pose(panda_model, panda_model.random_state(np.random.default_rng(18), "arm"),
                      "panda_hand_tcp")
    relative = Pose.from_se3(link2.actInv(goal), frame="panda_link2")
    _assert_valid(panda_model, solver.solve(relative, seed_q), goal)
    with pytest.raises(UnknownNameError):
        solver.solve(Pose(frame="no_such_link"), seed_q)


# --------------------------------------------------------------------------- the state


def test_joints_outside_the_group_keep_the_seed_values(panda_model: RobotModel) -> None:
    seed_q = panda_model.state_with(panda_model.default_state(), {"panda_finger_joint1": 0.03})
    target = _targets(panda_model, "arm", "panda_hand_tcp", 1, seed=19)[0]
    solution = solve_ik(panda_model, "arm", target, seed_q=seed_q, options=PATIENT)
    np.testing.assert_array_equal(solution.q[7:], [0.03, 0.03])
    # In a group that has the finger, the finger does not move the TCP: it stays too.
    solution = solve_ik(panda_model, "arm_and_hand", target, frame="panda_hand_tcp",
                        seed_q=seed_q, options=PATIENT)
    _assert_valid(panda_model, solution, target)
    np.testing.assert_array_equal(solution.q[7:], [0.03, 0.03])


def test_mimic_joints_follow_their_source(panda_model: RobotModel) -> None:
    # The right finger is moved by panda_finger_joint2, which mimics panda_finger_joint1.
    solver = IkSolver(panda_model, "arm_and_hand", frame="panda_rightfinger", options=PATIENT)
    assert "panda_finger_joint1" in solver.joint_names
    rng = np.random.default_rng(20)
    for _ in range(10):
        q = panda_model.random_state(rng, "arm_and_hand")
        target = frame_pose(panda_model, q, "panda_rightfinger")
        solution = solver.solve(target.translation)
        _assert_valid(panda_model, solution, target, position_only=True)
        assert solution.q[8] == solution.q[7]


def test_targets_reached_at_the_joint_limits_give_solutions_within_them(
    panda_model: RobotModel,
) -> None:
    solver = IkSolver(panda_model, "arm", options=PATIENT)
    rng = np.random.default_rng(26)
    lower, upper = panda_model.lower[:7], panda_model.upper[:7]
    for _ in range(15):
        q = panda_model.random_state(rng, "arm")
        at_limit = rng.random(7) < 0.4
        q[:7] = np.where(at_limit, np.where(rng.random(7) < 0.5, lower, upper), q[:7])
        target = frame_pose(panda_model, q, "panda_hand_tcp")
        _assert_valid(panda_model, solver.solve(target), target)


def test_the_seed_is_clipped_into_the_limits(panda_model: RobotModel) -> None:
    solver = IkSolver(panda_model, "arm")
    seed_q = np.full(panda_model.nq, 10.0)
    state = solver.seed_state(seed_q)
    np.testing.assert_array_equal(state[:7], panda_model.upper[:7])
    assert state[7] == 10.0  # not one of the solved joints
    with pytest.raises(InputError, match="'seed_q' must be a state vector"):
        solver.seed_state(np.zeros(3))
    with pytest.raises(InputError, match="'seed_q' must be finite"):
        solver.seed_state(np.full(panda_model.nq, np.nan))


# --------------------------------------------------------------------------- failures


def test_an_unreachable_target_raises_quickly_with_the_best_residual(
    panda_model: RobotModel,
) -> None:
    target = pin.SE3(np.eye(3), np.array([2.0, 0.0, 0.5]))
    start = time.perf_counter()
    with pytest.raises(IkFailedError) as caught:
        solve_ik(panda_model, "arm", target)
    assert time.perf_counter() - start < 0.5
    message = str(caught.value)
    assert "group 'arm'" in message and "frame 'panda_hand_tcp'" in message
    assert "xyz=(2.0000, 0.0000, 0.5000)" in message and "best residual" in message
    assert caught.value.best_error > 0.5  # about 2 m - 0.85 m of reach, plus rotation


def test_an_unreachable_position_names_the_position(servo_arm_model: RobotModel) -> None:
    with pytest.raises(IkFailedError, match=r"position \(2.0000, 0.0000, 0.0000\)") as caught:
        solve_ik(servo_arm_model, "arm", np.array([2.0, 0.0, 0.0]))
    assert caught.value.best_error > 1.0
    assert not is_reachable(servo_arm_model, "arm", np.array([2.0, 0.0, 0.0]))


def test_is_reachable_says_yes_to_a_reachable_target(ur5_model: RobotModel) -> None:
    target = _targets(ur5_model, "manipulator", "tool0", 1, seed=21)[0]
    assert is_reachable(ur5_model, "manipulator", target, options=PATIENT)


def test_bad_targets_and_frames_are_input_errors(panda_model: RobotModel,
                                                 servo_arm_model: RobotModel) -> None:
    solver = IkSolver(panda_model, "arm")
    with pytest.raises(InputError, match="'target' must be an SE3"):
        solver.solve(np.zeros(4))
    with pytest.raises(InputError, match="'target' must be a pose when position_only is False"):
        solver.solve(np.zeros(3), options=IkOptions(position_only=False))
    with pytest.raises(InputError, match="'target' must be finite"):
        solver.solve(np.array([np.nan, 0.0, 0.0]))
    with pytest.raises(InputError, match="'frame' must be moved by a joint of group 'hand'"):
        IkSolver(panda_model, "hand", frame="panda_link3")
    with pytest.raises(InputError, match="'frame' must be given"):
        IkSolver(servo_arm_model, "gripper")  # two parallel fingers: no tip
    with pytest.raises(UnknownNameError):
        IkSolver(panda_model, "legs")


# --------------------------------------------------------------------------- restarts


def test_several_solutions_are_distinct_and_valid(ur5_model: RobotModel) -> None:
    target = _targets(ur5_model, "manipulator", "tool0", 1, seed=22)[0]
    options = IkOptions(timeout=1.0, attempts=300, num_solutions=4, min_distance=0.5)
    solutions = IkSolver(ur5_model, "manipulator").solve_all(target, options=options)
    assert len(solutions) == 4
    for solution in solutions:
        _assert_valid(ur5_model, solution, target)
    for a, b in combinations(solutions, 2):
        assert np.linalg.norm(a.q - b.q) >= 0.5
    assert [s.attempts for s in solutions] == sorted(s.attempts for s in solutions)


def test_the_same_seed_gives_the_same_solutions(panda_model: RobotModel) -> None:
    target = _targets(panda_model, "arm", "panda_hand_tcp", 1, seed=23)[0]
    options = IkOptions(timeout=1.0, attempts=300, num_solutions=3, seed=7)
    first = IkSolver(panda_model, "arm").solve_all(target, options=options)
    solver = IkSolver(panda_model, "arm")
    again = solver.solve_all(target, options=options)
    again_same_solver = solver.solve_all(target, options=options)
    assert len(first) == 3
    for a, b, c in zip(first, again, again_same_solver):
        np.testing.assert_array_equal(a.q, b.q)
        np.testing.assert_array_equal(a.q, c.q)
    other = solver.solve_all(target, options=IkOptions(timeout=1.0, attempts=300,
                                                       num_solutions=3, seed=8))
    assert any(not np.array_equal(a.q, b.q) for a, b in zip(first, other))


def test_attempts_limit_the_restarts(panda_model: RobotModel) -> None:
    target = pin.SE3(np.eye(3), np.array([2.0, 0.0, 0.5]))
    with pytest.raises(IkFailedError, match=r"after 3 attempt\(s\)"):
        solve_ik(panda_model, "arm", target, options=IkOptions(timeout=1.0, attempts=3))


def test_timeout_and_attempts_default_to_the_group_settings(panda_model: RobotModel) -> None:
    solver = IkSolver(panda_model, "arm")
    assert solver.settings.timeout == 0.005 and solver.settings.attempts == 50
    target = pin.SE3(np.eye(3), np.array([2.0, 0.0, 0.5]))
    solver.seed_table()  # built once per solver, outside any timing
    start = time.perf_counter()
    with pytest.raises(IkFailedError):
        solver.solve(target)
    assert time.perf_counter() - start < 0.1


# --------------------------------------------------------------------------- other models

CONTINUOUS_ARM = """<?xml version="1.0"?>
<robot name="yaw_arm">
  <link name="world"/>
  <link name="base"/>
  <link name="upper"/>
  <link name="lower"/>
  <link name="tip"/>
  <joint name="fixed_base" type="fixed">
    <parent link="world"/><child link="base"/>
  </joint>
  <joint name="yaw" type="continuous">
    <parent link="base"/><child link="upper"/>
    <origin xyz="0 0 0.1"/><axis xyz="0 0 1"/>
  </joint>
  <joint name="shoulder" type="revolute">
    <parent link="upper"/><child link="lower"/>
    <origin xyz="0 0 0.05"/><axis xyz="0 1 0"/>
    <limit lower="-1.5" upper="1.5" effort="1" velocity="1"/>
  </joint>
  <joint name="elbow" type="revolute">
    <parent link="lower"/><child link="tip"/>
    <origin xyz="0.3 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-2.5" upper="2.5" effort="1" velocity="1"/>
  </joint>
  <joint name="tool" type="fixed">
    <parent link="tip"/><child link="tool"/>
    <origin xyz="0.25 0 0"/>
  </joint>
  <link name="tool"/>
</robot>
"""


def test_continuous_joints_are_unbounded_and_stay_near_the_seed(tmp_path: Path) -> None:
    urdf = tmp_path / "yaw_arm.urdf"
    urdf.write_text(CONTINUOUS_ARM)
    model = load_robot(urdf, allow_missing_meshes=True)  # kinematics only: no <collision>
    names = ("yaw", "shoulder", "elbow")
    group = Group("arm", names, model.indices(names), ("upper", "lower", "tip"), "base", "tool")
    solver = IkSolver(model, group, options=PATIENT)
    rng = np.random.default_rng(24)
    for _ in range(10):
        goal = model.random_state(rng)
        goal[0] += 4 * np.pi  # the same place, two turns further
        target = frame_pose(model, goal, "tool")
        seed_q = np.array([3.0 * np.pi, 0.0, 0.0])
        solution = solver.solve(target.translation, seed_q)
        assert abs(solution.q[0] - seed_q[0]) <= np.pi + 1e-9
        _assert_valid(model, solution, target, position_only=True)


def test_a_cheap_call_is_fast_once_the_solver_exists(ur5_model: RobotModel) -> None:
    """Regression guard for per-call overhead, far above the benchmark's figure."""
    solver = IkSolver(ur5_model, "manipulator")
    q = ur5_model.random_state(np.random.default_rng(25), "manipulator")
    target = frame_pose(ur5_model, q, "tool0")
    solver.solve(target, q)
    start = time.perf_counter()
    for _ in range(50):
        solution = solver.solve(target, q)  # already at the solution: one iteration
    assert solution.iterations == 1 and solution.attempts == 1
    assert (time.perf_counter() - start) / 50 < 0.002
