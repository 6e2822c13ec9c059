"""The single-file readers: URDF, SRDF, kinematics.yaml and joint_limits.yaml."""

from __future__ import annotations

import shutil
import textwrap
from pathlib import Path

import pytest

from taskrunner.errors import RobotDescriptionError
from taskrunner.robot import PackageMap, load_description, load_robot
from taskrunner.robot.moveit_yaml import read_joint_limits_yaml, read_kinematics_yaml
from taskrunner.robot.srdf import parse_srdf, read_srdf
from taskrunner.robot.urdf import read_urdf

TWO_LINKS = """\
<?xml version="1.0"?>
<robot name="two">
  <link name="base">
    <visual><geometry><mesh filename="{visual}"/></geometry></visual>
    <collision><geometry><mesh filename="{collision}"/></geometry></collision>
  </link>
  <link name="arm"><collision><geometry><sphere radius="0.05"/></geometry></collision></link>
  <joint name="q" type="revolute">
    <parent link="base"/><child link="arm"/>
    <axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/>
  </joint>
  <gazebo reference="base"/>
</robot>
"""


def write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(textwrap.dedent(text))
    return path


@pytest.fixture
def stl(tmp_path, mini_description_dir) -> Path:
    target = tmp_path / "robot" / "meshes" / "part.stl"
    target.parent.mkdir(parents=True)
    shutil.copy(mini_description_dir / "meshes" / "tetra.stl", target)
    return target


# ---------------------------------------------------------------- URDF
def test_relative_and_file_uri_mesh_paths_become_absolute(tmp_path, stl):
    urdf = write(
        tmp_path / "robot" / "urdf" / "two.urdf",
        TWO_LINKS.format(visual="../meshes/part.stl", collision=f"file://{stl}"),
    )
    description = read_urdf(urdf)
    meshes = [m.get("filename") for m in description.root.iter("mesh")]
    assert meshes == [str(urdf.parent / "../meshes/part.stl"), str(stl)]
    assert description.root.find("gazebo") is None
    assert description.root_link == "base"
    assert description.links == ["base", "arm"]
    assert description.joints == {"q": ("revolute", "base", "arm")}
    m = load_robot(urdf)
    assert m.collision_model.ngeoms == 2


def test_package_uri_meshes_use_the_given_package_map(tmp_path, stl):
    urdf = write(
        tmp_path / "robot" / "two.urdf",
        TWO_LINKS.format(visual="package://parts/part.stl", collision="package://parts/part.stl"),
    )
    description = read_urdf(urdf, PackageMap({"parts": stl.parent}))
    assert {m.get("filename") for m in description.root.iter("mesh")} == {str(stl)}


def test_errors_in_xacro_output_name_the_xacro_file_and_element_without_a_line(tmp_path):
    xacro_file = write(
        tmp_path / "robot" / "bad.urdf.xacro",
        """\
        <?xml version="1.0"?>
        <robot name="bad" xmlns:xacro="http://www.ros.org/wiki/xacro">
          <xacro:property name="parent" value="nowhere"/>
          <link name="a"/>
          <link name="b"/>
          <joint name="j" type="fixed"><parent link="${parent}"/><child link="b"/></joint>
        </robot>
        """,
    )
    with pytest.raises(RobotDescriptionError) as info:
        read_urdf(xacro_file)
    # Lines of the expanded text mean nothing to the user: no line, but the element's name.
    assert str(info.value) == f"{xacro_file}: joint 'j': parent link 'nowhere' is not defined"


def test_root_element_must_be_robot(tmp_path):
    path = write(tmp_path / "robot" / "x.urdf", "<?xml version='1.0'?>\n<model name='x'/>\n")
    with pytest.raises(RobotDescriptionError) as info:
        read_urdf(path)
    assert str(info.value) == f"{path}:2: root element must be <robot> (got <model>)"


def test_urdf_without_links_is_refused(tmp_path):
    path = write(tmp_path / "robot" / "x.urdf", "<robot name='x'>\n</robot>\n")
    with pytest.raises(RobotDescriptionError, match=r"x.urdf:1: URDF has no <link>"):
        read_urdf(path)


def test_bare_urdf_picks_up_an_srdf_of_the_same_stem_beside_it(tmp_path, stl):
    urdf = write(tmp_path / "robot" / "two.urdf", TWO_LINKS.format(visual=stl, collision=stl))
    write(
        tmp_path / "robot" / "two.srdf",
        """\
        <robot name="two">
          <group name="g"><joint name="q"/></group>
          <group_state name="mid" group="g"><joint name="q" value="0.5"/></group_state>
        </robot>
        """,
    )
    m = load_robot(urdf)
    assert m.group("g").joint_names == ("q",)
    assert m.named_state("g", "mid").as_dict() == {"q": 0.5}
    assert load_description(urdf).name == "two"


# ---------------------------------------------------------------- SRDF
def test_srdf_parts_keep_their_lines(mini_config_dir):
    srdf = read_srdf(mini_config_dir / "config" / "mini.srdf")
    assert srdf.robot_name == "mini"
    assert list(srdf.groups) == ["arm", "lift", "upper"]
    assert srdf.groups["arm"].chains == [("base_link", "tool0")]
    assert srdf.groups["arm"].line == 4
    home = srdf.group_states[0]
    assert (home.name, home.group, home.line) == ("home", "arm", 14)
    assert home.value_lines == {"j1": 15, "j2": 16, "j3": 17}
    assert srdf.virtual_joints[0].child_link == "base_link"
    assert srdf.end_effectors[0].parent_group == "arm"
    assert [(d.link1, d.link2, d.reason) for d in srdf.disabled_collisions] == [
        ("base_link", "link2", "Never")
    ]


def test_srdf_extras_of_moveit_are_accepted():
    srdf = parse_srdf(
        """\
        <robot name="r">
          <group name="g"><joint name="a"/></group>
          <group_state name="s" group="g"><joint name="a" value="0.25 0 0"/></group_state>
          <passive_joint name="p"/>
          <joint_property joint_name="a" property_name="angular_distance_weight" value="0.5"/>
          <disable_default_collisions link="l"/>
          <link_sphere_approximation link="l"/>
          <enable_collisions link1="a" link2="b" reason="Default"/>
        </robot>
        """
    )
    assert srdf.passive_joints == ["p"]
    assert srdf.group_states[0].values == {"a": 0.25}  # multi-DOF values: the first kept
    assert [(e.link1, e.link2) for e in srdf.enabled_collisions] == [("a", "b")]


def test_srdf_element_missing_a_required_attribute_names_it(tmp_path):
    path = write(tmp_path / "r.srdf", '<robot name="r">\n  <group name="g">\n    <chain base_link="a"/>\n  </group>\n</robot>\n')
    srdf = read_srdf(path)
    assert srdf.groups["g"].chains == []
    assert [str(w) for w in srdf.warnings] == [
        f"{path}:3: <chain> has no 'tip_link' attribute; a member of group 'g' skipped"]


def test_enable_collisions_reenables_a_disabled_pair(make_mini):
    robot = make_mini({"mini.srdf": ("</robot>", '  <enable_collisions link1="link2" link2="base_link" reason="x"/>\n</robot>')})
    assert frozenset({"base_link", "link2"}) not in robot.load().disabled_collisions


# ---------------------------------------------------------------- MoveIt YAML
def test_kinematics_yaml_in_ros2_parameter_form(tmp_path):
    path = write(
        tmp_path / "kinematics.yaml",
        """\
        /**:
          ros__parameters:
            robot_description_kinematics:
              arm:
                kinematics_solver: kdl_kinematics_plugin/KDLKinematicsPlugin
                kinematics_solver_timeout: 0.01
                position_only_ik: true
        """,
    )
    settings = read_kinematics_yaml(path)
    assert list(settings) == ["arm"]
    assert settings["arm"].position_only_ik is True
    assert settings["arm"].timeout == pytest.approx(0.01)
    assert settings["arm"].attempts == 10  # default
    assert settings["arm"].line == 4


def test_empty_kinematics_yaml_has_no_groups(tmp_path):
    assert read_kinematics_yaml(write(tmp_path / "kinematics.yaml", "# nothing\n")) == {}


def test_joint_limits_yaml_in_ros2_parameter_form(tmp_path):
    path = write(
        tmp_path / "joint_limits.yaml",
        """\
        /**:
          ros__parameters:
            robot_description_planning:
              default_velocity_scaling_factor: 0.1
              joint_limits:
                j1: {has_velocity_limits: true, max_velocity: 1.5}
        """,
    )
    config = read_joint_limits_yaml(path)
    assert config.default_velocity_scaling_factor == pytest.approx(0.1)
    assert config.default_acceleration_scaling_factor == 1.0
    assert config.joints["j1"].max_velocity == pytest.approx(1.5)
    assert config.joints["j1"].max_acceleration is None
    assert config.joints["j1"].line == 6


def test_disabled_limits_are_ignored_even_when_written(tmp_path):
    path = write(
        tmp_path / "joint_limits.yaml",
        """\
        joint_limits:
          j1:
            has_position_limits: false
            min_position: 0
            max_position: 0
            has_velocity_limits: false
            max_velocity: 0
            has_acceleration_limits: false
            max_acceleration: 0
        """,
    )
    override = read_joint_limits_yaml(path).joints["j1"]
    assert (override.min_position, override.max_position) == (None, None)
    assert (override.max_velocity, override.max_acceleration) == (None, None)


def test_joint_limits_yaml_without_joints_only_scales(tmp_path):
    config = read_joint_limits_yaml(write(tmp_path / "joint_limits.yaml", "default_velocity_scaling_factor: 0.4\n"))
    assert config.joints == {}
    assert config.default_velocity_scaling_factor == pytest.approx(0.4)

