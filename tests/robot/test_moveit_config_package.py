"""A MoveIt config package, as the Setup Assistant writes it, loads with one call.

The fixture workspace is tests/robot/fixtures/ws/src: mini_description (xacro, an STL)
and mini_moveit_config (.setup_assistant, SRDF, kinematics.yaml, joint_limits.yaml).
The mini arm: j1 continuous (yaw), j2 revolute (pitch), j3 prismatic, tool0 fixed.
"""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.errors import RobotDescriptionError, YamlError
from taskrunner.robot import PackageMap, load_description, load_robot


def tool0(model, q):
    data = model.model.createData()
    pin.framesForwardKinematics(model.model, data, model.to_pin(q))
    return data.oMf[model.frame_id("tool0")].translation.copy()


def expected_tool0(yaw, pitch, lift, tool_length=0.05):
    """tool0 in the world: shoulder 0.15 m up, then 0.2 + lift + 0.1 + tool_length along
    the pitched, yawed z axis."""
    reach = 0.2 + lift + 0.1 + tool_length
    return np.array([
        reach * np.sin(pitch) * np.cos(yaw),
        reach * np.sin(pitch) * np.sin(yaw),
        0.15 + reach * np.cos(pitch),
    ])


@pytest.fixture
def ws_copy(tmp_path):
    """A writable copy of the fixture workspace; returns its src folder."""
    shutil.copytree(Path(__file__).parent / "fixtures" / "ws", tmp_path / "ws")
    return tmp_path / "ws" / "src"


def test_moveit_config_folder_loads_with_one_call(mini_config_dir, mini_model):
    description = load_description(mini_config_dir)
    assert description.name == "mini"
    assert description.source == mini_config_dir
    assert description.urdf.source.name == "mini.urdf.xacro"
    assert description.srdf is not None and description.srdf.path.name == "mini.srdf"
    assert description.kinematics_path == mini_config_dir / "config" / "kinematics.yaml"
    assert mini_model.name == "mini"
    assert mini_model.joint_names == ("j1", "j2", "j3")
    assert [j.type for j in mini_model.joints] == ["continuous", "revolute", "prismatic"]
    assert mini_model.warnings == []


def test_groups_tips_end_effector_and_ik_settings(mini_model):
    arm = mini_model.group("arm")
    assert arm.joint_names == ("j1", "j2", "j3")
    assert (arm.base_link, arm.tip_link) == ("base_link", "tool0")
    assert arm.end_effector == "tool"
    assert arm.position_only_ik is True
    assert arm.kinematics.timeout == pytest.approx(0.05)
    assert arm.kinematics.attempts == 3
    assert mini_model.group("lift").joint_names == ("j3",)
    assert mini_model.group("lift").kinematics is None
    upper = mini_model.group("upper")  # a group of links: their parent joints move
    assert upper.joint_names == ("j2", "j3")
    assert upper.links == ("link2", "link3")


def test_joint_limits_yaml_overrides_the_urdf_where_enabled(mini_model):
    j1, j2, j3 = mini_model.joints
    assert (j1.lower, j1.upper) == (-np.inf, np.inf)  # continuous: unbounded
    assert not j1.bounded
    assert (j1.max_velocity, j1.max_acceleration) == (2.0, 4.0)  # URDF says 3.0
    assert (j2.lower, j2.upper) == (-1.0, 1.0)  # URDF says [-1.5, 1.5]
    assert j2.max_velocity == 1.0  # has_velocity_limits: false keeps the URDF's
    assert j2.max_acceleration == 3.0
    assert (j3.lower, j3.upper, j3.max_velocity) == (0.0, 0.1, 0.2)  # not in the yaml
    assert j3.max_acceleration == np.inf
    assert mini_model.lower.tolist() == [-np.inf, -1.0, 0.0]
    instance = mini_model.instances[0]
    assert (instance.velocity_scaling, instance.acceleration_scaling) == (0.5, 0.25)


def test_named_poses_and_adjacent_pairs(mini_model):
    assert mini_model.named_state("arm", "home").as_dict() == {"j1": 2.5, "j2": -0.5, "j3": 0.05}
    assert mini_model.named_state("lift", "up").as_dict() == {"j3": 0.1}
    disabled = mini_model.disabled_collisions
    assert disabled[frozenset({"base_link", "link2"})] == "Never"
    assert disabled[frozenset({"base_link", "link1"})] == "Adjacent"
    assert disabled[frozenset({"link2", "link3"})] == "Adjacent"


def test_continuous_joint_is_one_state_value_and_cos_sin_in_pinocchio(mini_model):
    m = mini_model
    assert m.nq == 3 and m.model.nq == 4
    q = np.array([0.7, -0.3, 0.04])
    q_pin = m.to_pin(q)
    assert q_pin == pytest.approx([np.cos(0.7), np.sin(0.7), -0.3, 0.04])
    assert m.from_pin(q_pin) == pytest.approx(q)
    # Angles beyond pi come back wrapped into (-pi, pi].
    assert m.from_pin(m.to_pin(np.array([2.5 + 2 * np.pi, 0.0, 0.0]))) == pytest.approx([2.5, 0, 0])
    assert m.from_pin(m.to_pin(np.array([-3.0, 0.0, 0.0]))) == pytest.approx([-3.0, 0, 0])
    # Jacobian columns: j1 has one velocity even though it has two configuration entries.
    assert m.model.nv == 3
    assert m.velocity_columns(["j1", "j2", "j3"]).tolist() == [0, 1, 2]


@pytest.mark.parametrize("q", [[0.0, 0.0, 0.0], [0.7, -0.3, 0.04], [-2.9, 0.9, 0.1], [2.5, -0.5, 0.05]])
def test_forward_kinematics_matches_the_geometry(mini_model, q):
    q = np.array(q)
    assert tool0(mini_model, q) == pytest.approx(expected_tool0(*q), abs=1e-12)


def test_continuous_joint_state_is_periodic_in_forward_kinematics(mini_model):
    q = np.array([0.4, 0.6, 0.02])
    shifted = q + [2 * np.pi, 0, 0]
    assert tool0(mini_model, shifted) == pytest.approx(tool0(mini_model, q), abs=1e-12)


def test_random_states_draw_continuous_joints_in_minus_pi_pi(mini_model):
    rng = np.random.default_rng(1)
    samples = np.array([mini_model.random_state(rng) for _ in range(200)])
    assert samples[:, 0].min() >= -np.pi and samples[:, 0].max() <= np.pi
    assert samples[:, 0].max() - samples[:, 0].min() > 5.0
    assert all(mini_model.within_limits(q) for q in samples)
    assert mini_model.default_state().tolist() == [0.0, 0.0, 0.0]


def test_meshes_resolve_through_package_uris(mini_model, mini_description_dir):
    by_link = {
        mini_model.model.frames[g.parentFrame].name: g for g in mini_model.collision_model.geometryObjects
    }
    assert set(by_link) == {"base_link", "link1", "link2", "link3"}
    mesh = by_link["link2"]
    assert Path(mesh.meshPath) == mini_description_dir / "meshes" / "tetra.stl"
    assert mesh.meshScale == pytest.approx([5, 5, 5])


def test_tags_for_ros_control_gazebo_and_transmissions_are_dropped(mini_config_dir, mini_model):
    root = load_description(mini_config_dir).urdf.root
    assert [child.tag for child in root if child.tag not in ("link", "joint")] == []
    for tag in ("ros2_control", "gazebo", "transmission"):
        assert f"<{tag}" not in mini_model.urdf_xml


def test_xacro_args_of_the_setup_assistant_are_passed_to_xacro(ws_copy):
    marker = ws_copy / "mini_moveit_config" / ".setup_assistant"
    marker.write_text(marker.read_text().replace('xacro_args: ""', 'xacro_args: "tool_length:=0.25"'))
    m = load_robot(ws_copy / "mini_moveit_config")
    assert tool0(m, np.zeros(3)) == pytest.approx(expected_tool0(0, 0, 0, tool_length=0.25))


def test_description_package_folder_may_differ_from_its_package_name(ws_copy):
    (ws_copy / "mini_description").rename(ws_copy / "desc")
    m = load_robot(ws_copy / "mini_moveit_config")
    assert m.joint_names == ("j1", "j2", "j3")


def test_explicit_package_map_entry_locates_the_description(ws_copy, tmp_path):
    moved = tmp_path / "far" / "away"
    shutil.move(ws_copy / "mini_description", moved)
    m = load_robot(ws_copy / "mini_moveit_config", PackageMap({"mini_description": moved}))
    assert m.joint_names == ("j1", "j2", "j3")


def test_description_package_that_cannot_be_found_is_named(ws_copy):
    shutil.rmtree(ws_copy / "mini_description")
    marker = ws_copy / "mini_moveit_config" / ".setup_assistant"
    with pytest.raises(YamlError) as info:
        load_robot(ws_copy / "mini_moveit_config")
    message = str(info.value)
    assert message.startswith(f"{marker}:3: 'URDF': package 'mini_description' not found")


def test_xacro_find_of_an_unknown_package_names_it_and_the_file(ws_copy):
    xacro_file = ws_copy / "mini_description" / "urdf" / "mini.urdf.xacro"
    xacro_file.write_text(xacro_file.read_text().replace("$(find mini_description)", "$(find mini_macros)"))
    with pytest.raises(RobotDescriptionError) as info:
        load_robot(ws_copy / "mini_moveit_config")
    message = str(info.value)
    assert message.startswith(f"{xacro_file}: $(find …): package 'mini_macros' not found")


def test_malformed_included_xacro_names_the_included_file_and_line(ws_copy):
    macros = ws_copy / "mini_description" / "urdf" / "mini_macros.xacro"
    text = macros.read_text()
    macros.write_text(text.replace("</link>", "</lnk>"))
    line = next(i for i, s in enumerate(text.splitlines(), 1) if "</link>" in s)
    with pytest.raises(RobotDescriptionError) as info:
        load_robot(ws_copy / "mini_moveit_config")
    assert str(info.value) == f"{macros}:{line}: invalid XML: mismatched tag"


def test_xacro_expression_error_names_the_file_and_the_expression(ws_copy):
    xacro_file = ws_copy / "mini_description" / "urdf" / "mini.urdf.xacro"
    xacro_file.write_text(xacro_file.read_text().replace("$(arg tool_length)", "tool_lenght"))
    with pytest.raises(RobotDescriptionError) as info:
        load_robot(ws_copy / "mini_moveit_config")
    message = str(info.value)
    assert message.startswith(f"{xacro_file}: xacro expansion failed: ")
    assert "tool_lenght" in message


def test_setup_assistant_file_without_its_section_is_refused(ws_copy):
    marker = ws_copy / "mini_moveit_config" / ".setup_assistant"
    marker.write_text("something_else: {}\n")
    with pytest.raises(YamlError) as info:
        load_robot(ws_copy / "mini_moveit_config")
    assert str(info.value) == f"{marker}:1: missing 'moveit_setup_assistant_config'"


def test_setup_assistant_urdf_that_does_not_exist_is_named(ws_copy):
    marker = ws_copy / "mini_moveit_config" / ".setup_assistant"
    marker.write_text(marker.read_text().replace("urdf/mini.urdf.xacro", "urdf/gone.urdf.xacro"))
    with pytest.raises(YamlError) as info:
        load_robot(ws_copy / "mini_moveit_config")
    message = str(info.value)
    assert message.startswith(f"{marker}:2: URDF not found: ")
    assert message.endswith("gone.urdf.xacro")


def test_folder_that_is_no_robot_is_refused(tmp_path):
    with pytest.raises(RobotDescriptionError) as info:
        load_robot(tmp_path)
    assert str(info.value) == (
        f"{tmp_path}: folder holds neither a robot.yaml nor a MoveIt config package (.setup_assistant, "
        "launch/planning_context.launch, or config/*.srdf with config/*.urdf.xacro)"
    )


def test_limit_violations_name_the_joint_value_and_limits(mini_model):
    q = np.array([10.0, 1.2, 0.05])  # j1 is continuous: 10 rad is fine
    assert not mini_model.within_limits(q)
    assert mini_model.limit_violations(q) == [
        "joint 'j2' = 1.2 is above its upper bound 1 by 0.2 rad"]
    assert mini_model.within_limits(mini_model.state_with(q, {"j2": 0.9}))


def test_a_tiny_excess_is_shown_with_enough_digits_and_round_off_is_within(mini_model):
    """Fetch's wrist at -3.1416 against a bound of -pi: 7.3e-06 rad out, and the message
    says so (at 4 decimals value and bound looked equal); round-off passes both checks."""
    lower = mini_model.joint("j2").lower
    q = mini_model.state_with(mini_model.default_state(), {"j2": lower - 2.6e-6})
    assert not mini_model.within_limits(q)
    (line,) = mini_model.limit_violations(q)
    assert line == f"joint 'j2' = {lower - 2.6e-6:.10g} is below its lower bound {lower:.10g} " \
                   "by 2.6e-06 rad"
    q = mini_model.state_with(q, {"j2": lower - 1e-12})
    assert mini_model.within_limits(q) and mini_model.limit_violations(q) == []


def test_missing_xacro_include_names_the_including_file_and_the_missing_one(ws_copy):
    xacro_file = ws_copy / "mini_description" / "urdf" / "mini.urdf.xacro"
    xacro_file.write_text(xacro_file.read_text().replace("mini_macros.xacro", "mini_macro.xacro"))
    with pytest.raises(RobotDescriptionError) as info:
        load_robot(ws_copy / "mini_moveit_config")
    message = str(info.value)
    assert message.startswith(f"{xacro_file}: xacro expansion failed: No such file or directory: ")
    assert "mini_macro.xacro" in message
