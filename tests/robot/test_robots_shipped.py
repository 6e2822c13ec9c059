"""The robots in robots/ (servo_arm, panda, ur5) load with their groups, poses and limits."""

from __future__ import annotations

import shutil

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.errors import RobotDescriptionError, UnknownNameError
from taskrunner.robot import PackageMap, load_description, load_robot

SERVO_JOINTS = tuple(f"Revolute {i}" for i in range(1, 8))


def tool_position(model, q, frame):
    data = model.model.createData()
    pin.framesForwardKinematics(model.model, data, model.to_pin(q))
    return data.oMf[model.frame_id(frame)].translation.copy()


# ---------------------------------------------------------------- servo_arm
def test_servo_arm_joints_keep_their_names_with_spaces(servo_arm_model):
    m = servo_arm_model
    assert m.joint_names == SERVO_JOINTS
    assert m.nq == 7 and m.model.nq == 7
    assert all(j.type == "revolute" and j.mimic is None for j in m.joints)
    assert m.joint("Revolute 3").parent_link == "arm_link_1"
    assert m.joint("Revolute 3").child_link == "arm_link_2"


def test_servo_arm_groups_tips_and_ik_settings(servo_arm_model):
    arm = servo_arm_model.group("arm")
    assert arm.joint_names == SERVO_JOINTS[:5]
    assert list(arm.joint_indices) == [0, 1, 2, 3, 4]
    assert arm.base_link == "base_link"
    assert arm.tip_link == "gripper_base_1"
    assert arm.position_only_ik is True
    assert arm.kinematics.timeout == pytest.approx(0.2)
    assert arm.kinematics.attempts == 10
    assert arm.end_effector == "gripper_eef"
    gripper = servo_arm_model.group("gripper")
    assert gripper.joint_names == ("Revolute 6", "Revolute 7")
    assert gripper.position_only_ik is False
    assert set(servo_arm_model.groups) == {"arm", "gripper"}


def test_servo_arm_named_poses_have_the_seed_values(servo_arm_model):
    m = servo_arm_model
    home = m.named_state("arm", "home")
    assert home.names == SERVO_JOINTS[:5]
    assert home.positions == pytest.approx([0.8, -0.8, -1.2, -0.8, -2.6])
    assert m.named_state("gripper", "open").as_dict() == {"Revolute 6": 0.1, "Revolute 7": 0.1}
    assert m.named_state("gripper", "closed").as_dict() == {
        "Revolute 6": -0.35,
        "Revolute 7": -0.35,
    }
    assert m.named_state("arm", "Candle").positions == pytest.approx(
        [1.5708, -1.5708, -1.5708, -1.5708, -1.5708]
    )
    assert m.named_state_names("arm") == ["Candle", "home", "ready"]
    with pytest.raises(UnknownNameError, match=r"unknown named pose of group 'arm' 'hoem'"):
        m.named_state("arm", "hoem")


def test_servo_arm_limits_come_from_joint_limits_yaml(servo_arm_model):
    m = servo_arm_model
    r1 = m.joint("Revolute 1")
    assert r1.max_velocity == pytest.approx(3.0)  # MG996R: half its no-load speed
    assert r1.max_acceleration == pytest.approx(6.0)  # the URDF has no acceleration limits
    assert (r1.lower, r1.upper) == pytest.approx((0.0, 3.14))  # the servo's 0 and 180 deg
    assert m.joint("Revolute 6").max_velocity == pytest.approx(4.0)
    assert m.joint("Revolute 6").max_acceleration == pytest.approx(8.0)
    instance = m.instances[0]
    assert instance.velocity_scaling == pytest.approx(0.2)
    assert instance.acceleration_scaling == pytest.approx(0.2)
    assert instance.hardware_path is not None and instance.hardware_path.name == "hardware.yaml"


def test_servo_arm_joint_limits_yaml_overrides_the_urdf(tmp_path, robots_dir):
    """Change a copy of the shipped yaml to see that its values, not the URDF's, count."""
    copy = tmp_path / "robots" / "servo_arm"
    shutil.copytree(robots_dir / "servo_arm", copy)
    limits = copy / "config" / "joint_limits.yaml"
    text = limits.read_text()
    text = text.replace("max_velocity: 3.0\n", "max_velocity: 0.15\n", 1)
    text = text.replace("min_position: 0.0\n    max_position: 3.14", "min_position: 0.5\n    max_position: 2.5")
    limits.write_text(text)
    r1 = load_robot(copy).joint("Revolute 1")
    assert r1.max_velocity == pytest.approx(0.15)
    assert (r1.lower, r1.upper) == pytest.approx((0.5, 2.5))


def test_servo_arm_poses_are_within_limits_and_home_is_above_the_table(servo_arm_model):
    m = servo_arm_model
    q = m.state_with(m.default_state(), m.named_state("arm", "home"))
    q = m.state_with(q, m.named_state("gripper", "open"))
    assert m.within_limits(q)
    assert tool_position(m, q, "tool0")[2] > 0.05


def test_servo_arm_ros2_control_and_gazebo_tags_are_ignored(robots_dir, servo_arm_model):
    description = load_description(robots_dir / "servo_arm")
    root = description.urdf.root
    for tag in ("ros2_control", "gazebo", "transmission"):
        assert root.find(tag) is None
        assert f"<{tag}" not in servo_arm_model.urdf_xml
    assert description.warnings == []
    # It starts at 'home' (initial_positions.yaml): its zero state would fold the gripper
    # into the base. Loaded on its own, it has nothing to warn about.
    assert servo_arm_model.warnings == []
    assert servo_arm_model.initial_values["Revolute 5"] == -2.6


def test_servo_arm_xacro_finds_its_package_through_package_xml_name(robots_dir):
    """The folder is servo_arm, the package servo_arm_description: $(find) must use the name."""
    xacro_file = robots_dir / "servo_arm" / "urdf" / "servo_arm.urdf.xacro"
    packages = PackageMap({"servo_arm_description": robots_dir / "servo_arm"})
    model = load_robot(xacro_file, packages)
    assert model.joint_names == SERVO_JOINTS
    assert model.groups == {}  # a bare xacro file brings no SRDF


def test_servo_arm_xacro_with_a_package_map_lacking_its_package_names_it(robots_dir):
    xacro_file = robots_dir / "servo_arm" / "urdf" / "servo_arm.urdf.xacro"
    with pytest.raises(RobotDescriptionError) as info:
        load_robot(xacro_file, PackageMap({"other": robots_dir}))
    message = str(info.value)
    assert message.startswith(f"{xacro_file}: ")
    assert "package 'servo_arm_description' not found" in message


def test_servo_arm_collision_model_has_primitives_on_every_moving_link(servo_arm_model):
    m = servo_arm_model
    links = {m.model.frames[g.parentFrame].name for g in m.collision_model.geometryObjects}
    assert {"base_link", "arm_link_1", "gripper_base_1", "finger_left_1", "finger_right_1"} <= links
    assert "tool0" not in links
    assert m.disabled_collisions[frozenset({"base_link", "arm_link_1"})] == "Never"
    assert frozenset({"finger_left_1", "finger_right_1"}) not in m.disabled_collisions


# ---------------------------------------------------------------- panda
def test_panda_groups_tips_and_default_pose(panda_model):
    m = panda_model
    arm = m.group("arm")
    assert arm.joint_names == tuple(f"panda_joint{i}" for i in range(1, 8))
    assert arm.tip_link == "panda_hand_tcp"
    assert arm.base_link == "panda_link0"
    assert arm.kinematics is not None and arm.kinematics.attempts == 50
    assert m.group("hand").joint_names == ("panda_finger_joint1",)
    both = m.group("arm_and_hand")
    assert both.joint_names == (*arm.joint_names, "panda_finger_joint1")
    default = m.named_state("arm_and_hand", "default").as_dict()
    assert default["panda_joint4"] == pytest.approx(-2.35619)
    assert default["panda_finger_joint1"] == pytest.approx(0.001)
    assert m.instances[0].velocity_scaling == pytest.approx(0.5)
    assert m.joint("panda_joint1").max_acceleration == pytest.approx(15.0)
    assert m.joint("panda_joint1").max_velocity == pytest.approx(2.175)


def test_panda_mimic_finger_follows_its_source(panda_model):
    m = panda_model
    finger2 = m.joint("panda_finger_joint2")
    assert finger2.mimic is not None and finger2.mimic.source == "panda_finger_joint1"
    assert "panda_finger_joint2" not in m.group("hand").joint_names  # not an active joint
    q = m.state_with(m.default_state(), {"panda_finger_joint1": 0.03})
    assert q[finger2.index] == pytest.approx(0.03)
    q[m.joint("panda_finger_joint1").index] = 0.01
    assert m.apply_mimic(q) is q
    assert q[finger2.index] == pytest.approx(0.01)
    # Both fingers really open: they sit symmetric about the hand's axis.
    left, right = tool_position(m, q, "panda_leftfinger"), tool_position(m, q, "panda_rightfinger")
    hand = tool_position(m, q, "panda_hand")
    assert np.linalg.norm(left - hand) == pytest.approx(np.linalg.norm(right - hand))
    # Which joint sets move a mimic joint; rows of states at once.
    assert m.mimic_follows(m.group("hand").joint_indices)
    assert not m.mimic_follows(m.group("arm").joint_indices)
    rows = np.repeat(q[None, :], 3, axis=0)
    rows[:, m.joint("panda_finger_joint1").index] = [0.0, 0.02, 0.04]
    assert m.apply_mimic(rows)[:, finger2.index] == pytest.approx([0.0, 0.02, 0.04])
    assert m.to_pin(rows) == pytest.approx(np.array([m.to_pin(r) for r in rows]))


def test_panda_random_states_respect_limits_and_mimic(panda_model):
    m = panda_model
    rng = np.random.default_rng(7)
    for _ in range(20):
        q = m.random_state(rng)
        assert m.within_limits(q)
        assert q[m.joint("panda_finger_joint2").index] == q[m.joint("panda_finger_joint1").index]


# ---------------------------------------------------------------- ur5
def test_ur5_manipulator_chain_and_home(ur5_model):
    m = ur5_model
    group = m.group("manipulator")
    assert group.joint_names == (
        "shoulder_pan_joint",
        "shoulder_lift_joint",
        "elbow_joint",
        "wrist_1_joint",
        "wrist_2_joint",
        "wrist_3_joint",
    )
    assert (group.base_link, group.tip_link) == ("base_link", "tool0")
    assert m.named_state("manipulator", "home").positions == pytest.approx(
        [0, -1.5707, 1.5707, -1.5707, -1.5707, 0]
    )
    assert m.within_limits(m.state_with(m.default_state(), m.named_state("manipulator", "home")))
    assert m.instances[0].velocity_scaling == 1.0  # no joint_limits.yaml


def test_unknown_group_lists_the_known_ones(ur5_model):
    with pytest.raises(UnknownNameError, match=r"unknown group 'arm'; known: 'manipulator'"):
        ur5_model.group("arm")
