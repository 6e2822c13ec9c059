"""URDFs of example-robot-data load directly with ``load_robot(path_to_urdf)``."""

from __future__ import annotations

import numpy as np
import pytest

from taskrunner.robot import load_description, load_robot

SO_ARM_JOINTS = ("shoulder_pan", "shoulder_lift", "elbow_flex", "wrist_flex", "wrist_roll", "gripper")


@pytest.fixture(scope="module")
def erd_robots(example_robot_data):
    return example_robot_data / "robots"


def test_panda_urdf_loads_with_its_mimic_finger(erd_robots):
    m = load_robot(erd_robots / "panda_description" / "urdf" / "panda.urdf")
    assert m.joint_names == (
        *(f"panda_joint{i}" for i in range(1, 8)),
        "panda_finger_joint1",
        "panda_finger_joint2",
    )
    assert m.joint("panda_finger_joint2").mimic.source == "panda_finger_joint1"
    assert m.groups == {}  # its SRDF is in srdf/, not beside the URDF
    assert m.has_link("panda_hand_tcp")
    assert m.collision_model.ngeoms > 0
    # No SRDF, so no collision matrix: its default state touches itself, as in MoveIt.
    assert len(m.warnings) == 1
    assert "the default state (every joint at 0, clipped to its limits) is in self-collision (" in m.warnings[0]
    assert "run `run-task collision-matrix ROBOT --write SRDF`" in m.warnings[0]


def test_ur5_robot_urdf_loads(erd_robots):
    m = load_robot(erd_robots / "ur_description" / "urdf" / "ur5_robot.urdf")
    assert m.nq == 6
    assert m.joint_names[0] == "shoulder_pan_joint" and m.joint_names[-1] == "wrist_3_joint"
    assert m.has_link("tool0")
    assert np.all(np.isfinite(m.lower))


def test_so101_urdf_loads_and_drops_its_transmissions(erd_robots):
    path = erd_robots / "so_arm_description" / "urdf" / "so101.urdf"
    assert "<transmission" in path.read_text()
    description = load_description(path)
    assert description.urdf.root.find("transmission") is None
    m = load_robot(path)
    assert set(m.joint_names) == set(SO_ARM_JOINTS)
    assert all(j.type == "revolute" for j in m.joints)
    assert m.collision_model.ngeoms > 0


def test_so100_urdf_with_a_link_and_a_joint_of_the_same_name_loads(erd_robots):
    m = load_robot(erd_robots / "so_arm_description" / "urdf" / "so100.urdf")
    assert set(m.joint_names) == set(SO_ARM_JOINTS)
    assert m.has_link("gripper")


def test_so100_description_reads_and_drops_its_transmissions(erd_robots):
    """so100 names a link and a joint 'gripper': both survive reading."""
    description = load_description(erd_robots / "so_arm_description" / "urdf" / "so100.urdf")
    assert description.urdf.root.find("transmission") is None
    assert "gripper" in description.urdf.links and "gripper" in description.urdf.joints
    assert description.srdf is None
