"""IkSolver.solve_near: a local solve that gives solve()'s state with one attempt."""

from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.errors import IkFailedError, InputError
from taskrunner.kinematics import IkOptions, IkSolver, frame_pose
from taskrunner.robot import Group, RobotModel, load_robot

LOCAL = IkOptions(attempts=1, timeout=1.0)


def _nearby(model: RobotModel, solver: IkSolver, count: int, seed: int, spread: float,
            position: bool) -> list[tuple[np.ndarray, object]]:
    """(seed state, target) pairs: the target is the frame at a state ``spread`` rad (per
    joint, uniform) from the seed; some are out of reach from the seed (large spread)."""
    rng = np.random.default_rng(seed)
    idx = model.indices(solver.joint_names)
    pairs = []
    for _ in range(count):
        q = model.random_state(rng, solver.group.name)
        goal = q.copy()
        goal[idx] += rng.uniform(-spread, spread, len(idx))
        goal[idx] = np.clip(goal[idx], model.lower[idx], model.upper[idx])
        pose = frame_pose(model, goal, solver.frame)
        pairs.append((q, pose.translation.copy() if position else pose))
    return pairs


def _same_as_solve(solver: IkSolver, pairs, options: IkOptions) -> tuple[int, int]:
    """Compare solve_near with solve(attempts=1) on every pair; (solved, failed) counts."""
    one = dataclasses.replace(options, attempts=1)
    solved = failed = 0
    for q, target in pairs:
        try:
            expected = solver.solve(target, q, one).q
        except IkFailedError as error:
            with pytest.raises(IkFailedError) as near:
                solver.solve_near(target, q, options)
            assert str(near.value).split(" after ")[0] == str(error).split(" after ")[0]
            assert near.value.best_error == error.best_error
            failed += 1
            continue
        got = solver.solve_near(target, q, options)
        np.testing.assert_array_equal(got, expected)
        assert got.flags.writeable
        got[0] += 1.0  # a new array: the solver keeps nothing of it
        solved += 1
    return solved, failed


@pytest.mark.parametrize(("robot", "group"), [("panda_model", "arm"),
                                              ("ur5_model", "manipulator")])
def test_full_pose_states_and_failures_are_those_of_solve(request, robot: str, group: str) -> None:
    model = request.getfixturevalue(robot)
    solver = IkSolver(model, group)
    near = _nearby(model, solver, 30, seed=5, spread=0.05, position=False)
    far = _nearby(model, solver, 30, seed=6, spread=1.5, position=False)
    out_of_reach = [(q, pin.SE3(pose.rotation, pose.translation + np.array([3.0, 0.0, 0.0])))
                    for q, pose in near[:5]]
    solved, failed = _same_as_solve(solver, near + far + out_of_reach, LOCAL)
    assert solved >= 30 and failed >= 5  # both outcomes compared


def test_position_only_states_are_those_of_solve(servo_arm_model: RobotModel,
                                                 panda_model: RobotModel) -> None:
    servo = IkSolver(servo_arm_model, "arm")
    solved, _ = _same_as_solve(servo, _nearby(servo_arm_model, servo, 30, 7, 0.1, True),
                               LOCAL)
    assert solved >= 25
    panda = IkSolver(panda_model, "arm")
    solved, failed = _same_as_solve(
        panda, _nearby(panda_model, panda, 30, 8, 0.05, True)
        + _nearby(panda_model, panda, 20, 9, 2.0, True),
        IkOptions(attempts=1, timeout=1.0, position_only=True))
    assert solved >= 30


def test_the_options_attempts_are_not_used(ur5_model: RobotModel) -> None:
    solver = IkSolver(ur5_model, "manipulator")
    pairs = _nearby(ur5_model, solver, 20, seed=10, spread=1.5, position=False)
    _same_as_solve(solver, pairs, IkOptions(attempts=50, timeout=1.0))


def test_mimic_followers_are_set_and_checked(panda_model: RobotModel) -> None:
    solver = IkSolver(panda_model, "arm_and_hand", frame="panda_rightfinger")
    pairs = _nearby(panda_model, solver, 20, seed=11, spread=0.05, position=True)
    solved, _ = _same_as_solve(solver, pairs, LOCAL)
    assert solved >= 15
    for q, target in pairs[:5]:
        got = solver.solve_near(target, q, LOCAL)
        assert got[8] == got[7]


CONTINUOUS_ARM = """<?xml version="1.0"?>
<robot name="yaw_arm">
  <link name="base"/><link name="upper"/><link name="lower"/><link name="tip"/><link name="tool"/>
  <joint name="yaw" type="continuous">
    <parent link="base"/><child link="upper"/><axis xyz="0 0 1"/>
  </joint>
  <joint name="shoulder" type="revolute">
    <parent link="upper"/><child link="lower"/><origin xyz="0 0 0.3"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="1" velocity="1"/>
  </joint>
  <joint name="elbow" type="revolute">
    <parent link="lower"/><child link="tip"/><origin xyz="0.4 0 0"/><axis xyz="0 1 0"/>
    <limit lower="-2.5" upper="2.5" effort="1" velocity="1"/>
  </joint>
  <joint name="tool" type="fixed">
    <parent link="tip"/><child link="tool"/><origin xyz="0.3 0 0"/>
  </joint>
</robot>
"""


def test_continuous_joints_are_turned_near_the_seed(tmp_path: Path) -> None:
    urdf = tmp_path / "yaw_arm.urdf"
    urdf.write_text(CONTINUOUS_ARM)
    model = load_robot(urdf, allow_missing_meshes=True)  # kinematics only: no <collision>
    names = ("yaw", "shoulder", "elbow")
    group = Group("arm", names, model.indices(names), ("upper", "lower", "tip"), "base", "tool")
    solver = IkSolver(model, group)
    rng = np.random.default_rng(12)
    for _ in range(10):
        seed_q = np.array([3.0 * np.pi + rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)])
        goal = seed_q + rng.uniform(-0.1, 0.1, 3)
        target = frame_pose(model, goal, "tool").translation
        got = solver.solve_near(target, seed_q, LOCAL)
        np.testing.assert_array_equal(got, solver.solve(target, seed_q, LOCAL).q)
        assert abs(got[0] - seed_q[0]) <= np.pi


def test_bad_input_gives_solves_errors(panda_model: RobotModel) -> None:
    solver = IkSolver(panda_model, "arm")
    seed = panda_model.default_state()
    for target, seed_q in [(np.array([np.nan, 0.0, 0.5]), seed), (np.zeros((2, 2)), seed),
                           (pin.SE3.Identity(), np.zeros(3)),
                           (pin.SE3.Identity(), np.full(panda_model.nq, np.inf))]:
        with pytest.raises(InputError) as expected:
            solver.solve(target, seed_q, LOCAL)
        with pytest.raises(InputError) as got:
            solver.solve_near(target, seed_q, LOCAL)
        assert str(got.value) == str(expected.value)
