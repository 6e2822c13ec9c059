"""A line on which one joint moves by a subnormal step (1e-310 rad beside 0.5 rad) is timed by
the joint that moves, without a floating-point overflow on the way."""

from __future__ import annotations

import warnings

import numpy as np

from taskrunner.planning.timing import parameterize_path
from taskrunner.types import JointPath


def test_a_joint_moving_a_subnormal_step_does_not_overflow_the_line_timing(servo_arm_model):
    model = servo_arm_model
    names = model.group("arm").joint_names
    start = np.zeros(len(names))
    end = start.copy()
    end[0], end[1] = 0.5, 1e-310
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # an overflow in numpy is a RuntimeWarning
        trajectory = parameterize_path(model, JointPath(names, np.vstack([start, end])))
        alone = parameterize_path(model, JointPath(names, np.vstack([start, end * [1, 0, 1, 1, 1]])))
    # The same timing as the move without the tiny step: joint 0's limits set it.
    np.testing.assert_array_equal(trajectory.times, alone.times)
    assert np.all(np.isfinite(trajectory.velocities)) and trajectory.duration > 0
    np.testing.assert_array_equal(trajectory.positions[-1], end)
