"""The collision core's kinematic tree and forward kinematics agree with pinocchio."""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.collision import JOINT, JointKind, KinematicTree
from taskrunner.collision.frames import AXIS, ORIGIN, ROTATION, forward_kinematics
from taskrunner.robot import RobotModel


@pytest.mark.parametrize("name", ["panda_model", "ur5_model", "servo_arm_model"])
def test_forward_kinematics_equals_pinocchio_at_random_states(
        name: str, request: pytest.FixtureRequest) -> None:
    robot: RobotModel = request.getfixturevalue(name)
    tree = KinematicTree(robot)
    assert tree.supported
    assert tree.joints.dtype == JOINT
    data = robot.model.createData()
    rng = np.random.default_rng(24)
    for _ in range(20):
        q = robot.apply_mimic(robot.random_state(rng))
        frames = forward_kinematics(tree, q)
        pin.forwardKinematics(robot.model, data, robot.to_pin(q))
        for jid in range(1, robot.model.njoints):
            placed = data.oMi[jid]
            rotation = frames[jid, ROTATION:ROTATION + 9].reshape(3, 3)
            np.testing.assert_allclose(rotation, placed.rotation, atol=1e-12)
            np.testing.assert_allclose(frames[jid, ORIGIN:ORIGIN + 3], placed.translation,
                                       atol=1e-12)
            axis = placed.rotation @ tree.joints["axis"][jid]
            np.testing.assert_allclose(frames[jid, AXIS:AXIS + 3], axis, atol=1e-12)


def test_joint_kinds_are_read_from_the_model(servo_arm_model: RobotModel,
                                             panda_model: RobotModel) -> None:
    panda = KinematicTree(panda_model)
    kinds = {j.name: JointKind(panda.joints["kind"][panda_model.model.getJointId(j.name)])
             for j in panda_model.joints}
    assert kinds["panda_joint1"] is JointKind.REVOLUTE
    assert kinds["panda_finger_joint1"] is JointKind.PRISMATIC
    assert panda.joints["kind"][0] == JointKind.FIXED  # the universe
    servo = KinematicTree(servo_arm_model)
    moving = servo.joints["state"] >= 0
    assert set(servo.joints["kind"][moving]) <= {JointKind.REVOLUTE, JointKind.PRISMATIC}
    assert np.allclose(np.linalg.norm(servo.joints["axis"][moving], axis=1), 1.0)


def test_a_prismatic_joint_moves_its_lever_by_one_metre_per_metre(panda_model: RobotModel) -> None:
    tree = KinematicTree(panda_model)
    finger = panda_model.model.getJointId("panda_finger_joint1")
    index = int(tree.joints["state"][finger])
    assert tree.state_joint[index] == finger
    assert finger in tree.prismatic and tree.revolute[index] == 0


def test_numba_environment_is_set_before_numba_reads_it() -> None:
    """Importing the state screen first (it once imported numba before frames) still has
    frames set numba's environment before numba's import reads it: no error message
    highlighting (colorama was set up again at each typing attempt of a compilation) and
    no LLVM loop vectorization."""
    env = {k: v for k, v in os.environ.items()
           if k not in ("NUMBA_DISABLE_ERROR_MESSAGE_HIGHLIGHTING", "NUMBA_LOOP_VECTORIZE")}
    code = ("import taskrunner.scene.screen\n"
            "import numba.core.config as config, numba.core.errors as errors\n"
            "print(type(errors.termcolor()).__name__, config.LOOP_VECTORIZE)")
    done = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True,
                          check=True, timeout=120)
    assert done.stdout.split() == ["NOPColorScheme", "0"]
