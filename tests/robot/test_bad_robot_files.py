"""Every kind of broken robot file gives a taskrunner error that points into the file.

Each case writes the mini robot (manifest + plain URDF + SRDF + MoveIt YAML) into
tmp_path with one edit and checks the whole message: it starts with ``path:line:`` (or
``path:`` where the loader has no line) and names the offending element.
"""

from __future__ import annotations

import logging

import pytest

from taskrunner.errors import (
    MissingMeshError,
    RobotDescriptionError,
    TaskrunnerError,
    YamlError,
)
from taskrunner.robot import PackageMap, load_robot


def test_unedited_mini_manifest_loads(make_mini):
    robot = make_mini()
    m = robot.load()
    assert m.joint_names == ("j1", "j2", "j3")
    assert m.group("arm").position_only_ik


# ---------------------------------------------------------------- meshes
def test_mimic_of_an_unknown_joint_is_a_warning_and_the_joint_moves_on_its_own(make_mini):
    """MoveIt logs such a mimic and loads the joint as an independent one (example-robot-data's
    alex_psyonic_hands has one)."""
    robot = make_mini({"mini.urdf": (
        '<limit effort="10" lower="0" upper="0.1" velocity="0.2"/>',
        '<limit effort="10" lower="0" upper="0.1" velocity="0.2"/>\n    <mimic joint="j7"/>')})
    m = robot.load()
    line = robot.line("mini.urdf", "<mimic", after='<joint name="j3"')
    assert m.warnings == [f"{robot.path('mini.urdf')}:{line}: joint 'j3' mimics 'j7', which is "
                          "not a joint; it moves on its own"]
    assert m.joint("j3").mimic is None


def test_a_limit_without_lower_and_upper_takes_urdf_s_zero_with_a_located_warning(make_mini):
    """URDF's <limit> defaults lower= and upper= to 0 (urdfdom, which MoveIt reads with):
    example-robot-data's centauro and quadruped give only effort= and velocity=. Loaded as
    MoveIt loads them, loudly; mini's joint_limits.yaml replaces j2's range, as MoveIt's
    does."""
    robot = make_mini({"mini.urdf": ('<limit effort="10" lower="-1.5" upper="1.5" velocity="1.0"/>',
                                     '<limit effort="10" velocity="1.0"/>')})
    m = robot.load()
    line = robot.line("mini.urdf", "<limit", after='<joint name="j2"')
    assert m.warnings == [f"{robot.path('mini.urdf')}:{line}: joint 'j2' (revolute): its <limit> "
                          "has no lower= or upper=; URDF's default is 0, so its range is [0, 0] "
                          "(it cannot move), as MoveIt reads it, unless joint_limits.yaml gives "
                          "its min_position and max_position"]
    assert (m.joint("j2").lower, m.joint("j2").upper) == (-1.0, 1.0)  # joint_limits.yaml's
    with pytest.raises(RobotDescriptionError, match=r"has no lower= or upper="):
        robot.load(strict=True)


def test_a_negative_mesh_scale_mirrors_and_a_zero_scale_is_an_error(make_mini, located):
    mirrored = make_mini({"mini.urdf": ('scale="5 5 5"', 'scale="-5 5 5"')})
    assert mirrored.load().warnings == []
    robot = make_mini({"mini.urdf": ('scale="5 5 5"', 'scale="0 5 5"')})
    error = robot.error(RobotDescriptionError)
    assert "<mesh> 'scale' must be non-zero" in str(error)


def test_missing_collision_mesh_is_an_error_naming_link_uri_and_folder(make_mini, located):
    robot = make_mini({"mini.urdf": ('tetra.stl" scale', 'nope.stl" scale')})
    error = robot.error(MissingMeshError)
    line = robot.line("mini.urdf", "<collision>", after='<link name="link2">')
    message = located(error, robot.path("mini.urdf"), line)
    package = robot.packages.find("mini_description")
    assert f"files missing from package 'mini_description' (its folder: {package})" in message
    assert (f"link 'link2': collision mesh 'package://mini_description/meshes/nope.stl' "
            f"(line {line}); looked at {package / 'meshes' / 'nope.stl'}") in message
    assert "--package-path DIR" in message and "--allow-missing-meshes" in message


def test_missing_collision_mesh_loads_with_the_opt_out_and_the_link_uses_its_visual(
        make_mini, caplog):
    robot = make_mini({"mini.urdf": ('tetra.stl" scale', 'nope.stl" scale')})
    with caplog.at_level(logging.WARNING):
        m = robot.load(allow_missing_meshes=True)
    assert len(m.warnings) == 1
    warning = m.warnings[0]
    assert warning.startswith(f"{robot.path('mini.urdf')}: robot 'mini' loaded WITHOUT 1 mesh "
                              "file(s) it names (--allow-missing-meshes): visual geometry used "
                              "for collisions: link2. Causes: files missing from package "
                              "'mini_description'")
    logged = [r.getMessage() for r in caplog.records if r.levelno == logging.WARNING]
    assert logged == [warning]  # one warning for the robot, logged once
    link2 = [g for g in m.collision_model.geometryObjects
             if m.model.frames[g.parentFrame].name == "link2"]
    assert len(link2) == 1 and "tetra.stl" in link2[0].meshPath
    assert "link2" not in m.links_without_collision_geometry()


def test_the_opt_out_is_not_undone_by_strict_mode(make_mini):
    robot = make_mini({"mini.urdf": ('tetra.stl" scale', 'nope.stl" scale')})
    m = robot.load(strict=True, allow_missing_meshes=True)
    assert len(m.warnings) == 1 and "loaded WITHOUT 1 mesh file(s)" in m.warnings[0]


def test_the_opt_out_comes_from_the_load_options_never_from_the_environment(
        make_mini, monkeypatch):
    from taskrunner.robot import LoadOptions, load_robot

    robot = make_mini({"mini.urdf": ('tetra.stl" scale', 'nope.stl" scale')})
    allowed = load_robot(robot.folder, robot.packages,
                         options=LoadOptions(allow_missing_meshes=True))
    assert "loaded WITHOUT" in allowed.warnings[0]
    # The variable is the command line's to read (LoadOptions.from_env); a loader does not.
    monkeypatch.setenv("TASKRUNNER_ALLOW_MISSING_MESHES", "1")
    robot.error(MissingMeshError)
    assert LoadOptions.from_env().allow_missing_meshes


def test_missing_collision_mesh_without_visual_leaves_the_link_without_geometry(make_mini):
    def edit(text: str) -> str:
        start = text.index('<link name="link2">')
        visual_start = text.index("<visual>", start)
        visual_end = text.index("</visual>", visual_start) + len("</visual>")
        text = text[:visual_start] + text[visual_end:]
        return text.replace('tetra.stl" scale', 'nope.stl" scale', 1)

    robot = make_mini({"mini.urdf": edit})
    assert "link 'link2': collision mesh" in str(robot.error(MissingMeshError))
    m = robot.load(allow_missing_meshes=True)
    assert "no collision geometry: link2." in m.warnings[0]
    assert "link2" in m.links_without_collision_geometry()


def test_collision_mesh_in_an_unknown_package_names_the_package_and_the_folders(
        make_mini, located):
    robot = make_mini({"mini.urdf": ("package://mini_description/meshes/tetra.stl\" scale",
                                     "package://mini_meshes/tetra.stl\" scale")})
    packages = PackageMap({"mini_description": robot.packages.find("mini_description")},
                          search_roots=[robot.folder.parent], environment=False)
    with pytest.raises(MissingMeshError) as info:
        load_robot(robot.folder, packages)
    line = robot.line("mini.urdf", "<collision>", after='<link name="link2">')
    message = located(info.value, robot.path("mini.urdf"), line)
    heading = next(row for row in message.splitlines() if "package 'mini_meshes'" in row)
    assert heading == f"  package 'mini_meshes' not found (searched: {robot.folder.parent}):"
    assert f"    link 'link2': collision mesh 'package://mini_meshes/tetra.stl' (line {line})" \
        in message.splitlines()


def test_missing_visual_only_mesh_is_an_error_and_loads_with_the_opt_out(make_mini, caplog):
    robot = make_mini({"mini.urdf": ('tetra.stl"/>', 'gone.stl"/>')})  # link1's visual
    line = robot.line("mini.urdf", "<visual>", after='<link name="link1">')
    assert f"link 'link1': visual mesh 'package://mini_description/meshes/gone.stl' " \
           f"(line {line})" in str(robot.error(MissingMeshError))
    with caplog.at_level(logging.WARNING):
        m = robot.load(allow_missing_meshes=True)
    assert m.joint_names == ("j1", "j2", "j3")
    assert len(m.warnings) == 1 and "visual dropped: link1." in m.warnings[0]
    logged = [r.getMessage() for r in caplog.records if r.levelno == logging.WARNING]
    assert logged == m.warnings  # logged once
    # The collision geometry of link1 (a cylinder) is still there.
    links = {m.model.frames[g.parentFrame].name for g in m.collision_model.geometryObjects}
    assert "link1" in links


def test_every_missing_mesh_is_listed_in_one_error_grouped_by_cause(make_mini):
    robot = make_mini({"mini.urdf": lambda text: text.replace(
        "package://mini_description/meshes/tetra.stl", "package://lost_pkg/tetra.stl", 2
    ).replace('tetra.stl" scale', 'nope.stl" scale')})
    message = str(robot.error(MissingMeshError))
    rows = message.splitlines()
    assert "3 mesh file(s) of robot 'mini' cannot be found" in rows[0]
    headings = [row for row in rows if row.startswith("  ") and not row.startswith("    ")]
    assert len(headings) == 2
    assert headings[0].startswith("  package 'lost_pkg' not found (searched: ")
    assert headings[1].startswith("  files missing from package 'mini_description'")
    listed = [row for row in rows if row.startswith("    link ")]
    assert [row.split(":")[0] for row in listed] == [
        "    link 'link1'", "    link 'link2'", "    link 'link2'"]
    assert sum("package://lost_pkg/tetra.stl" in row for row in listed) == 2


def test_a_robot_with_no_collision_geometry_is_refused_unless_allowed(make_mini):
    def strip(text: str) -> str:
        while "<collision>" in text:
            start = text.index("<collision>")
            text = text[:start] + text[text.index("</collision>") + len("</collision>"):]
        while "<visual>" in text:
            start = text.index("<visual>")
            text = text[:start] + text[text.index("</visual>") + len("</visual>"):]
        return text

    robot = make_mini({"mini.urdf": strip})
    error = robot.error(MissingMeshError)
    assert "robot 'mini' has no collision geometry at all" in str(error)
    assert error.path == robot.path("mini.urdf")
    m = robot.load(allow_missing_meshes=True)
    assert m.warnings == [f"{robot.path('mini.urdf')}: robot 'mini' has no collision geometry "
                          "at all (--allow-missing-meshes): nothing of it is collision-checked"]
    assert m.collision_model.ngeoms == 0


# ---------------------------------------------------------------- URDF structure
URDF_CASES = [
    pytest.param(
        ('<parent link="link1"/>', '<parent link="link7"/>'),
        '<joint name="j2"', None,
        "joint 'j2': parent link 'link7' is not defined",
        id="parent-link-missing",
    ),
    pytest.param(
        ('<child link="link3"/>', '<child link="link9"/>'),
        '<joint name="j3"', None,
        "joint 'j3': child link 'link9' is not defined",
        id="child-link-missing",
    ),
    pytest.param(
        ('<link name="link3">', '<link name="link3"'),
        "<visual>", '<link name="link3"',  # expat stops at the next tag, inside the start tag
        "invalid XML: not well-formed (invalid token)",
        id="malformed-xml",
    ),
    pytest.param(
        ('<link name="tool0"/>', '<link name="tool0"/>\n  <link name="link1"/>'),
        '<link name="link1"/>', None,
        "duplicate link 'link1'",
        id="duplicate-link",
    ),
    pytest.param(
        ('lower="-1.5" upper="1.5"', 'lower="1.5" upper="-1.5"'),
        '<joint name="j2"', None,
        "joint 'j2': lower limit 1.5 is above upper limit -1.5",
        id="limits-reversed",
    ),
    pytest.param(
        ('lower="-1.5"', 'lower="-1,5"'),
        '<limit', '<joint name="j2"',
        "joint 'j2': <limit> 'lower' must be a number (got '-1,5')",
        id="limit-not-a-number",
    ),
    pytest.param(
        ('<origin xyz="0 0 0.2"/>', '<origin xyz="0 0.2"/>'),
        '<origin', '<joint name="j3"',
        "joint 'j3': <origin> 'xyz' must be 3 numbers (got '0 0.2')",
        id="origin-two-numbers",
    ),
    pytest.param(
        ('<box size="0.02 0.02 0.1"/>', '<box size="0.02 0.02 O.1"/>'),
        '<box', '<link name="link3"',
        "link 'link3': <box> 'size' must be 3 numbers (got '0.02 0.02 O.1')",
        id="box-size-typo",
    ),
    pytest.param(
        ('<joint name="j2" type="revolute">', '<joint name="j2" type="revolving">'),
        '<joint name="j2"', None,
        "joint 'j2': 'type' must be one of revolute, continuous, prismatic, fixed (got 'revolving')",
        id="bad-joint-type",
    ),
    pytest.param(
        ('lower="-1.5" upper="1.5"', 'lower="-1e+16" upper="1e+16"'),
        '<limit', '<joint name="j2"',
        "joint 'j2': <limit> 'lower' must be a finite number within ±1e+09 (got -1e+16); a "
        'joint that turns without limit is type="continuous"',
        id="gazebo-export-no-limit",
    ),
    pytest.param(
        ('<limit effort="10" lower="-1.5" upper="1.5" velocity="1.0"/>', ''),
        '<joint name="j2"', None,
        "joint 'j2' (revolute) needs a <limit lower= upper= effort= velocity=> (URDF requires "
        "one; MoveIt refuses the file too)",
        id="revolute-without-limit",
    ),
    pytest.param(
        ('<limit effort="10" lower="-1.5" upper="1.5" velocity="1.0"/>',
         '<limit effort="10" lower="-1.5" upper="1.5"/>'),
        '<limit', '<joint name="j2"',
        "joint 'j2': <limit> needs velocity= (URDF requires effort and velocity; MoveIt refuses "
        "the file too)",
        id="limit-without-velocity",
    ),
    pytest.param(
        ('<limit effort="10" lower="-1.5" upper="1.5" velocity="1.0"/>',
         '<limit lower="-1.5" upper="1.5"/>'),
        '<limit', '<joint name="j2"',
        "joint 'j2': <limit> needs effort= and velocity= (URDF requires effort and velocity; "
        "MoveIt refuses the file too)",
        id="limit-without-effort-and-velocity",
    ),
    pytest.param(
        ('<limit effort="10" lower="-1.5" upper="1.5" velocity="1.0"/>',
         '<limit effort="10" lower="1.5" velocity="1.0"/>'),
        '<joint name="j2"', None,
        "joint 'j2': lower limit 1.5 is above upper limit 0.0 (URDF's default for the missing "
        "upper=)",
        id="limit-without-upper-below-lower",
    ),
    pytest.param(
        ('<parent link="link2"/>', '<parent link="link3"/>'),
        '<robot', None,
        "links not connected to the root 'base_link': ['link3', 'tool0']",
        id="joint-loops-on-its-child",
    ),
    pytest.param(
        ('<link name="tool0"/>', '<link name="tool0"/>\n  <link name="spare"/>'),
        '<robot', None,
        "URDF must form one tree with one root link (roots found: ['base_link', 'spare'])",
        id="two-roots",
    ),
    pytest.param(
        ('<child link="link1"/>', '<child link="link2"/>'),
        '<joint name="j2"', None,
        "link 'link2' is the child of two joints ('j1', 'j2')",
        id="link-with-two-parents",
    ),
]


@pytest.mark.parametrize(("edit", "needle", "after", "reason"), URDF_CASES)
def test_broken_urdf_is_reported_at_its_line(make_mini, located, edit, needle, after, reason):
    robot = make_mini({"mini.urdf": edit})
    error = robot.error(RobotDescriptionError)
    line = robot.line("mini.urdf", needle, after)
    assert located(error, robot.path("mini.urdf"), line) == f"{robot.path('mini.urdf')}:{line}: {reason}"


# ---------------------------------------------------------------- SRDF against the URDF
SRDF_CASES = [
    pytest.param(
        ('<joint name="j3"/>', '<joint name="mini_j3"/>'),
        '<joint name="mini_j3"/>',
        "group 'lift': joint 'mini_j3' is not a joint of the URDF",
        id="group-joint-missing",
    ),
    pytest.param(
        ('<link name="link3"/>', '<link name="link_3"/>'),
        '<link name="link_3"/>',
        "group 'upper': link 'link_3' is not a link of the URDF",
        id="group-link-missing",
    ),
    pytest.param(
        ('base_link="base_link" tip_link="tool0"', 'base_link="tool0" tip_link="base_link"'),
        '<chain ',
        "group 'arm': chain tip 'base_link' is not below base 'tool0' in the URDF tree",
        id="chain-upside-down",
    ),
    pytest.param(
        ('base_link="base_link" tip_link="tool0"', 'base_link="link2" tip_link="link1"'),
        '<chain ',
        "group 'arm': chain tip 'link1' is not below base 'link2' in the URDF tree",
        id="chain-tip-above-base",
    ),
    pytest.param(
        ('tip_link="tool0"', 'tip_link="tool_0"'),
        '<chain ',
        "group 'arm': chain link 'tool_0' is not a link of the URDF",
        id="chain-link-missing",
    ),
    pytest.param(
        ('<joint name="j2" value="-0.5"/>', '<joint name="j2" value="-1.2"/>'),
        '<joint name="j2" value=',
        "group_state 'home': joint 'j2' = -1.2 is below its lower bound -1 by 0.2 rad (limits "
        "[-1, 1]); named pose skipped",
        id="pose-outside-yaml-limits",
    ),
    pytest.param(
        ('<joint name="j3" value="0.1"/>', '<joint name="j3" value="0.25"/>'),
        '<joint name="j3" value="0.25"/>',
        "group_state 'up': joint 'j3' = 0.25 is above its upper bound 0.1 by 0.15 m (limits "
        "[0, 0.1]); named pose skipped",
        id="pose-outside-urdf-limits",
    ),
    pytest.param(
        ('<joint name="j3" value="0.1"/>', '<joint name="j2" value="0.1"/>'),
        '<joint name="j2" value="0.1"/>',
        "group_state 'up': joint 'j2' is not in group 'lift'",
        id="pose-joint-not-in-group",
    ),
    pytest.param(
        ('<group_state name="up" group="lift">', '<group_state name="up" group="lifter">'),
        '<group_state name="up"',
        "group_state 'up': group 'lifter' is not defined",
        id="pose-of-unknown-group",
    ),
    pytest.param(
        ('<joint name="j2" value="-0.5"/>', '<joint name="j2" value="minus one"/>'),
        '<joint name="j2" value=',
        "group_state 'home': joint 'j2' value must be a number (got 'minus one')",
        id="pose-value-not-a-number",
    ),
    pytest.param(
        ('parent_link="tool0"', 'parent_link="flange"'),
        "<end_effector",
        "end_effector 'tool': parent_link 'flange' is not a link of the URDF",
        id="end-effector-link-missing",
    ),
    pytest.param(
        ('<joint name="j3"/>', '<joint name="j3"/>\n    <group name="upper"/>\n    <group name="gripper"/>'),
        '<group name="gripper"/>',
        "group 'lift': subgroup 'gripper' is not defined in the SRDF",
        id="subgroup-missing",
    ),
    pytest.param(
        ('child_link="base_link"', 'child_link="link1"'),
        "<virtual_joint",
        "virtual_joint 'world_joint': child_link 'link1' is not the URDF's root link 'base_link'",
        id="virtual-joint-not-at-root",
    ),
    pytest.param(
        ("</group>", "</grop>"),
        "</grop>",
        "invalid XML: mismatched tag",
        id="malformed-xml",
    ),
    pytest.param(
        ('<group name="lift">', '<group name="arm">'),
        '<group name="arm">\n',
        "duplicate group 'arm'",
        id="duplicate-group",
    ),
    pytest.param(
        ("<chain ", "<chian "),
        "<chian",
        "group 'arm': unknown element <chian>",
        id="unknown-group-member",
    ),
    pytest.param(
        ("<end_effector ", "<end_efector "),
        "<end_efector",
        "unknown SRDF element <end_efector>",
        id="unknown-element",
    ),
]


# What MoveIt refuses too; everything else in SRDF_CASES MoveIt skips with a log line.
# MoveIt loads a named pose outside the limits (and fails to plan to it): a warning, the pose
# skipped.
SRDF_ERRORS = {"malformed-xml"}


@pytest.mark.parametrize(("edit", "needle", "reason"), SRDF_CASES)
def test_broken_srdf_is_reported_at_its_line(make_mini, located, edit, needle, reason, request):
    """Skipped content is a warning at its file:line (and the error of strict mode);
    what MoveIt refuses too is an error either way."""
    robot = make_mini({"mini.srdf": edit})
    path = robot.path("mini.srdf")
    lines = robot.text("mini.srdf").splitlines()
    first = needle.splitlines()[0]
    matches = [i for i, text in enumerate(lines, 1) if first in text]
    # A needle ending in a newline means "the last such line" (for duplicates).
    line = matches[-1] if needle.endswith("\n") else matches[0]
    if request.node.callspec.id in SRDF_ERRORS:
        error = robot.error(RobotDescriptionError)
        assert located(error, path, line) == f"{path}:{line}: {reason}"
        return
    warnings = robot.load().warnings
    assert any(w.startswith(f"{path}:{line}: {reason}") for w in warnings), warnings
    error = robot.error(RobotDescriptionError, strict=True)
    assert located(error, path, line).startswith(f"{path}:{line}: {reason}")


def test_disabled_collision_with_an_unknown_link_is_a_warning(make_mini):
    robot = make_mini({"mini.srdf": ('link1="base_link" link2="link2"', 'link1="base_link" link2="link_2"')})
    m = robot.load()
    line = robot.line("mini.srdf", "<disable_collisions")
    assert m.warnings == [
        f"{robot.path('mini.srdf')}:{line}: disable_collisions names unknown link(s) ['link_2']; "
        "entry ignored"
    ]


# ---------------------------------------------------------------- MoveIt YAML
def test_duplicate_key_in_kinematics_yaml_names_both_lines(make_mini, located):
    robot = make_mini({"kinematics.yaml": lambda t: t + "  kinematics_solver_timeout: 0.1\n"})
    error = robot.error(YamlError)
    path = robot.path("kinematics.yaml")
    first = robot.line("kinematics.yaml", "kinematics_solver_timeout")
    second = len(robot.text("kinematics.yaml").splitlines())
    assert located(error, path, second) == (
        f"{path}:{second}: duplicate key 'kinematics_solver_timeout' (first defined on line {first})"
    )


def test_duplicate_joint_in_joint_limits_yaml_names_both_lines(make_mini, located):
    robot = make_mini({"joint_limits.yaml": ("  j2:\n", "  j1:\n")})
    error = robot.error(YamlError)
    path = robot.path("joint_limits.yaml")
    lines = [i for i, s in enumerate(robot.text("joint_limits.yaml").splitlines(), 1) if s == "  j1:"]
    assert located(error, path, lines[1]) == (
        f"{path}:{lines[1]}: duplicate key 'j1' (first defined on line {lines[0]})"
    )


def test_joint_limits_for_a_prefixed_joint_name_the_urdf_lacks(make_mini, located):
    """Pitfall 14: configs copied from a prefixed setup name joints the URDF does not have."""
    robot = make_mini({"joint_limits.yaml": ("  j2:\n", "  mini_j2:\n")})
    error = robot.error(YamlError)
    path = robot.path("joint_limits.yaml")
    line = robot.line("joint_limits.yaml", "mini_j2:")
    assert located(error, path, line) == (
        f"{path}:{line}: joint 'mini_j2' is not a movable joint of robot 'mini' "
        "(movable joints: j1, j2, j3)"
    )


def test_joint_limits_for_a_fixed_joint_is_refused(make_mini, located):
    robot = make_mini({"joint_limits.yaml": ("  j2:\n", "  tool_joint:\n")})
    error = robot.error(YamlError)
    line = robot.line("joint_limits.yaml", "tool_joint:")
    assert "joint 'tool_joint' is not a movable joint" in located(error, robot.path("joint_limits.yaml"), line)


def test_kinematics_yaml_for_a_group_the_srdf_lacks_is_a_warning(make_mini, located):
    robot = make_mini({"kinematics.yaml": ("arm:\n", "manipulator:\n")})
    path = robot.path("kinematics.yaml")
    reason = "group 'manipulator' is not defined in the SRDF (groups: arm, lift, upper)"
    assert robot.load().warnings == [f"{path}:1: {reason}; its settings are not used"]
    error = robot.error(RobotDescriptionError, strict=True)
    assert located(error, path, 1) == f"{path}:1: {reason}; its settings are not used"


YAML_VALUE_CASES = [
    pytest.param(
        "kinematics.yaml", ("position_only_ik: true", "position_only_ik: yes please"),
        "position_only_ik", "'position_only_ik' must be true or false (got 'yes please')",
        id="position-only-not-bool",
    ),
    pytest.param(
        "kinematics.yaml", ("kinematics_solver_attempts: 3", "kinematics_solver_attempts: 2.5"),
        "kinematics_solver_attempts", "'kinematics_solver_attempts' must be an integer (got 2.5)",
        id="attempts-not-integer",
    ),
    pytest.param(
        "kinematics.yaml", ("kinematics_solver_timeout: 0.05", "kinematics_solver_timeout: -1"),
        "kinematics_solver_timeout", "'kinematics_solver_timeout' must be >= 0.0 (got -1)",
        id="negative-timeout",
    ),
    pytest.param(
        "kinematics.yaml", (None, "arm: [1, 2]\n"),
        "arm:", "group 'arm': settings must be a mapping (got [1, 2])",
        id="group-settings-not-mapping",
    ),
    pytest.param(
        "joint_limits.yaml", ("max_velocity: 2.0", "max_velocity: fast"),
        "max_velocity: fast", "'max_velocity' must be a number (got 'fast')",
        id="velocity-not-number",
    ),
    pytest.param(
        "joint_limits.yaml", ("min_position: -1.0", "min_position: 2.0"),
        "min_position", "joint 'j2': 'min_position' (2.0) is above 'max_position' (1.0)",
        id="min-above-max",
    ),
    pytest.param(
        "joint_limits.yaml", ("max_acceleration: 4.0", "max_acceleration: 0"),
        "max_acceleration: 0", "joint 'j1': 'max_acceleration' must be > 0 when its limit is enabled",
        id="zero-enabled-acceleration",
    ),
    pytest.param(
        "joint_limits.yaml", ("default_velocity_scaling_factor: 0.5", "default_velocity_scaling_factor: 1.5"),
        "default_velocity_scaling_factor", "'default_velocity_scaling_factor' must be in (0, 1] (got 1.5)",
        id="scaling-above-one",
    ),
    pytest.param(
        "joint_limits.yaml", (None, "- j1\n- j2\n"),
        "- j1", "joint_limits.yaml must be a mapping",
        id="not-a-mapping",
    ),
]


@pytest.mark.parametrize(("name", "edit", "needle", "reason"), YAML_VALUE_CASES)
def test_bad_moveit_yaml_value_is_reported_at_its_line(make_mini, located, name, edit, needle, reason):
    old, new = edit
    robot = make_mini({name: new if old is None else (old, new)})
    error = robot.error(YamlError)
    path = robot.path(name)
    line = robot.line(name, needle)
    assert located(error, path, line) == f"{path}:{line}: {reason}"


def test_joint_limits_yaml_with_only_scaling_factors_loads(make_mini):
    robot = make_mini({"joint_limits.yaml": "default_velocity_scaling_factor: 0.3\njoint_limits:\n"})
    m = robot.load()
    assert m.instances[0].velocity_scaling == pytest.approx(0.3)
    assert m.joint("j2").lower == -1.5  # the URDF's


# ---------------------------------------------------------------- the manifest
MANIFEST_CASES = [
    pytest.param(
        lambda t: t + "kinematic: kinematics.yaml\n", "kinematic:",
        "unknown field 'kinematic' (expected one of collision, end_effectors, hardware, initial_positions, joint_limits, "
        "kinematics, name, ompl_planning, pilz_cartesian_limits, srdf, urdf, xacro_args)",
        id="unknown-field",
    ),
    pytest.param(
        ("srdf: mini.srdf", "srdf: missing.srdf"), "srdf:",
        "'srdf': file not found: {folder}/missing.srdf",
        id="missing-srdf",
    ),
    pytest.param(
        ("urdf: mini.urdf", "urdf: package://nopkg/urdf/mini.urdf"), "urdf:",
        "'urdf': package 'nopkg' not found",
        id="unknown-package",
    ),
    pytest.param(
        ("urdf: mini.urdf\n", ""), "name:",
        "'urdf' is required",
        id="no-urdf",
    ),
    pytest.param(
        ("kinematics: kinematics.yaml", "kinematics: [kinematics.yaml]"), "kinematics:",
        "'kinematics' must be a file path (got ['kinematics.yaml'])",
        id="path-not-a-string",
    ),
    pytest.param(
        lambda t: t + "xacro_args: [a, b]\n", "xacro_args:",
        "'xacro_args' must be a mapping",
        id="xacro-args-not-mapping",
    ),
    pytest.param(
        lambda t: t + "name: other\n", "name: other",
        "duplicate key 'name' (first defined on line 1)",
        id="duplicate-key",
    ),
    pytest.param(
        "- urdf: mini.urdf\n", "- urdf",
        "robot manifest must be a mapping",
        id="not-a-mapping",
    ),
]


@pytest.mark.parametrize(("edit", "needle", "reason"), MANIFEST_CASES)
def test_broken_manifest_is_reported_at_its_line(make_mini, located, edit, needle, reason):
    robot = make_mini({"robot.yaml": edit})
    error = robot.error(YamlError)
    path = robot.path("robot.yaml")
    line = robot.line("robot.yaml", needle)
    message = located(error, path, line)
    assert message.startswith(f"{path}:{line}: {reason.format(folder=robot.folder)}")


def test_missing_robot_description_is_named(tmp_path):
    from taskrunner.robot import load_robot

    with pytest.raises(RobotDescriptionError) as info:
        load_robot(tmp_path / "nothing_here")
    assert str(info.value) == f"{tmp_path / 'nothing_here'}: robot description not found"


# ---------------------------------------------------------------- no bare tracebacks
FILES = ["robot.yaml", "mini.urdf", "mini.srdf", "kinematics.yaml", "joint_limits.yaml"]


@pytest.mark.parametrize("name", FILES)
@pytest.mark.parametrize("fraction", [0.1, 0.3, 0.5, 0.7, 0.9])
def test_truncated_file_gives_a_located_taskrunner_error_or_loads(make_mini, name, fraction):
    """Cut a file short anywhere: loading either works or raises one of our errors whose
    message starts with the path of a file of the robot, never a parser's traceback."""
    robot = make_mini({name: lambda t: t[: int(len(t) * fraction)]})
    try:
        robot.load()
    except TaskrunnerError as error:
        assert getattr(error, "path", None) is not None, f"no file in {error!r}"
        assert str(error).startswith(str(error.path))
        assert error.path.parent == robot.folder
