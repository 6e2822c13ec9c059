"""The mujoco backend fails a motion in which two robots' links touch, naming both links
(issue 25): arms of one cell are bodies to each other, an arm's own links are not."""

from __future__ import annotations

import numpy as np
import pytest

from taskrunner.errors import BackendError
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.types import JointTrajectory

mujoco = pytest.importorskip("mujoco", reason="the mujoco backend needs: pip install "
                             "-e '.[mujoco]'")

from taskrunner.backends.physics import MujocoBackend, MujocoOptions, physics_cell  # noqa: E402
from taskrunner.backends.physics.mjcf import MjcfOptions, cell_mjcf  # noqa: E402

PAIR = DATA_ROOT / "robots" / "cells" / "servo_arm_pair.yaml"
# Both arms reaching down to the middle of the table: their grippers meet there.
MIDDLE = [1.5708, -0.7, -0.9, -0.6, -1.5708]


def test_each_robot_of_a_pair_has_a_contact_bit_of_its_own(tmp_path):
    physics = physics_cell(load_cell(PAIR))
    assert physics.link_robots["left_base_link"] == "left"
    assert physics.link_robots["right_gripper_base_1"] == "right"
    xml = cell_mjcf(physics, MjcfOptions(), tmp_path)
    # left: bit 2, touching the world (1) and right (4); right: bit 4, world and left.
    assert 'contype="2" conaffinity="5"' in xml and 'contype="4" conaffinity="3"' in xml
    assert 'contype="1" conaffinity="7"' in xml  # the table touches both
    assert 'contype="2" conaffinity="1"' not in xml


def test_two_arms_driven_into_each_other_fail_the_motion_naming_both_links(tmp_path):
    cell = load_cell(PAIR)
    names = cell.model.joint_names
    start = cell.start_state()
    arms = [*cell.model.group("left_arm").joint_names, *cell.model.group("right_arm").joint_names]
    goal = dict(zip(names, start))
    for prefix in ("left_", "right_"):
        for i, value in enumerate(MIDDLE, 1):
            goal[f"{prefix}Revolute {i}"] = value
    columns = [names.index(n) for n in arms]
    q0 = np.asarray(start)[columns]
    q1 = np.array([goal[n] for n in arms])
    times = np.linspace(0.0, 2.0, 41)
    positions = q0 + (q1 - q0) * (times / times[-1])[:, None]
    zeros = np.zeros_like(positions)
    trajectory = JointTrajectory(tuple(arms), times, positions, zeros, zeros)
    with MujocoBackend(names, physics_cell(cell), dict(zip(names, start)),
                       MujocoOptions(cache_dir=str(tmp_path))) as backend:
        handle = backend.execute(trajectory)
        with pytest.raises(BackendError) as caught:
            handle.wait(60.0)
    message = str(caught.value)
    assert "contact between robots" in message
    left, right = message.index("(left)"), message.index("(right)")
    assert "'left_" in message[:left] and "'right_" in message[left:right]
