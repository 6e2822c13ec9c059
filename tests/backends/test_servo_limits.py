"""The shipped servo arm's joint limits end where its servos do.

A limit past a servo's end lets the planner use an angle that the servo backends then
refuse (they never clamp): a hand-over once planned ``Revolute 3`` to 0.0001 rad, under
the old 0.0005 rad limit, which is 180.01 degrees. Every position the model allows must
map inside [0, 180] degrees once rounded as the firmware rounds.
"""

from __future__ import annotations

import numpy as np
import pytest

from taskrunner.backends.calibration import load_calibration, round_degrees
from taskrunner.resources import DATA_ROOT
from taskrunner.robot import load_robot


@pytest.mark.parametrize("robot", ["servo_arm"])
def test_every_position_within_the_limits_is_a_servo_angle(robot):
    model = load_robot(DATA_ROOT / "robots" / robot)
    instance = model.instances[0]
    assert instance.hardware_path is not None
    calibration = load_calibration(instance.hardware_path, model.joint_names)
    for name in calibration.servo_joint_names:
        joint = model.joint(name)
        ends = round_degrees(calibration.raw_degrees(name, np.array([joint.lower, joint.upper])))
        assert 0.0 <= ends.min() and ends.max() <= 180.0, (name, joint.lower, joint.upper, ends)
