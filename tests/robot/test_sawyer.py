"""The shipped Sawyer: sawyer_description's xacro loaded unchanged, its MoveIt config package
(ROS 1 layout), the modelled electric gripper, the collision matrix, planning between its
named poses in the sawyer_table cell."""

from __future__ import annotations

import numpy as np
import pinocchio as pin
import pytest

from taskrunner import load_workcell
from taskrunner.resources import cells_dir, robots_dir
from taskrunner.robot import load_robot
from taskrunner.robot.cell import load_cell
from taskrunner.robot.configpackage import find_config_files
from taskrunner.robot.packages import PackageMap
from taskrunner.scene.acm import generate_collision_matrix

DESCRIPTION = robots_dir() / "sawyer_description"
CONFIG = robots_dir() / "sawyer_moveit_config"
ARM = tuple(f"right_j{i}" for i in range(7))
FINGER_STROKE = 0.020833


@pytest.fixture(scope="module")
def bare():
    """The description's own top-level xacro, with its default arguments."""
    return load_robot(DESCRIPTION / "urdf" / "sawyer.urdf.xacro")


@pytest.fixture(scope="module")
def sawyer():
    return load_robot(CONFIG)


def frame_poses(model, q, frames):
    data = model.model.createData()
    pin.framesForwardKinematics(model.model, data, model.to_pin(q))
    return [data.oMf[model.frame_id(f)].copy() for f in frames]


def test_the_description_xacro_loads_as_published(bare):
    # Pedestal on (its default), no gripper: the arm's 7 joints and the head.
    assert set(bare.joint_names) == {*ARM, "head_pan"}
    for link in ("pedestal", "pedestal_feet", "controller_box", "right_hand", "head", "screen"):
        assert bare.has_link(link), link
    assert not bare.has_link("right_gripper_base")
    # Every visual mesh it names is shipped (the l4 stand-in included): nothing to warn about
    # but the zero state's self-collision, which only an SRDF can settle.
    assert [w for w in bare.warnings if "mesh" in w] == []


def test_the_config_package_is_read_as_a_ros1_moveit_config(sawyer):
    files = find_config_files(CONFIG, PackageMap(search_roots=[robots_dir()]))
    assert files.layout.startswith("ROS 1")
    assert files.urdf == CONFIG / "urdf" / "sawyer_with_gripper.urdf.xacro"
    assert files.srdf == CONFIG / "config" / "sawyer.srdf.xacro"
    assert files.srdf_args == {"tip_name": "right_gripper_tip"}
    assert {"kinematics", "joint_limits", "ompl_planning"} <= set(files.yaml)
    # The wrapper adds the gripper to the description's own top-level file.
    text = files.urdf.read_text(encoding="utf-8")
    assert '<xacro:include filename="$(find sawyer_description)/urdf/sawyer.urdf.xacro"/>' in text
    assert sawyer.warnings == []


def test_the_arm_moves_exactly_as_the_bare_description(bare, sawyer):
    rng = np.random.default_rng(3)
    frames = ["right_hand", "head", "right_l4"]
    for _ in range(20):
        q = sawyer.random_state(rng)
        values = dict(zip(sawyer.joint_names, q))
        q_bare = bare.default_state()
        q_bare[bare.indices(bare.joint_names)] = [values[n] for n in bare.joint_names]
        for a, b in zip(frame_poses(sawyer, q, frames), frame_poses(bare, q_bare, frames)):
            assert np.allclose(a.homogeneous, b.homogeneous, atol=1e-12)


def test_groups_poses_and_end_effector(sawyer):
    arm = sawyer.group("right_arm")
    assert arm.joint_names == ARM
    assert arm.tip_link == "right_gripper_tip"
    assert sawyer.group("right_gripper").joint_names == ("r_gripper_l_finger_joint",)
    assert sawyer.group("head").joint_names == ("head_pan",)
    assert "head_pan" not in arm.joint_names
    assert set(sawyer.named_state_names("right_arm")) == {"neutral", "zero_pose"}
    assert set(sawyer.named_state_names("right_gripper")) == {"open", "closed"}
    # neutral is sawyer_description's params/named_poses.yaml entry.
    neutral = sawyer.named_state("right_arm", "neutral")
    assert neutral.names == ARM
    assert neutral.positions == pytest.approx([0.0, -1.18, 0.0, 2.18, 0.0, 0.57, 3.3161])
    eef = sawyer.end_effectors["right_gripper"]
    assert (eef.parent_link, eef.group, eef.parent_group) == ("right_hand", "right_gripper",
                                                             "right_arm")


def test_the_gripper_opens_symmetrically_along_the_tool_y_axis(sawyer):
    pads = ["r_gripper_l_finger_tip", "r_gripper_r_finger_tip", "right_gripper_tip",
            "right_hand"]
    gaps = {}
    for pose in ("open", "closed"):
        q = sawyer.state_with(sawyer.default_state(), sawyer.named_state("right_gripper", pose))
        sawyer.apply_mimic(q)
        # The right finger mirrors the left (mimic, multiplier -1).
        right = q[sawyer.indices(["r_gripper_r_finger_joint"])][0]
        left = q[sawyer.indices(["r_gripper_l_finger_joint"])][0]
        assert right == pytest.approx(-left)
        l_pad, r_pad, tip, hand = frame_poses(sawyer, q, pads)
        in_tip = tip.actInv(l_pad).translation, tip.actInv(r_pad).translation
        # The pads lie on the tool's y axis, one each side at the same distance, at one
        # height along the tool's z.
        assert in_tip[0][1] > 0 > in_tip[1][1]
        assert in_tip[0][1] == pytest.approx(-in_tip[1][1], abs=1e-12)
        assert in_tip[0][0] == pytest.approx(0) and in_tip[1][0] == pytest.approx(0)
        assert in_tip[0][2] == pytest.approx(in_tip[1][2], abs=1e-12)
        gaps[pose] = in_tip[0][1] - in_tip[1][1]
        # The tool points away from the hand: 0.12 m out along the hand's z.
        assert hand.actInv(tip).translation == pytest.approx([0, 0, 0.12], abs=1e-9)
    assert gaps["open"] - gaps["closed"] == pytest.approx(2 * FINGER_STROKE)


def test_the_collision_matrix_is_what_run_task_collision_matrix_generates(sawyer):
    shipped = dict(sawyer.disabled_collisions)
    user = {pair for pair, reason in shipped.items() if reason == "User"}
    assert user == {frozenset(("head", "right_l2"))}
    generated = {e.pair: e.reason for e in generate_collision_matrix(sawyer, samples=2000)}
    # Adjacent and Default pairs do not depend on sampling: exactly the generated ones.
    for reason in ("Adjacent", "Default"):
        assert ({p for p, r in shipped.items() if r == reason}
                == {p for p, r in generated.items() if r == reason}), reason
    # Every shipped "Never" pair stays apart in these 2000 other samples too (the shipped
    # list came from 200000, which found more pairs that do touch).
    never = {p for p, r in shipped.items() if r == "Never"}
    assert never <= {p for p, r in generated.items() if r == "Never"}
    assert len(never) == 107


def test_the_cell_stands_the_pedestal_on_the_floor_before_the_table():
    cell = load_cell(cells_dir() / "sawyer_table.yaml")
    model = cell.model
    assert model.warnings == []
    # The start (neutral, gripper open) touches nothing: not the robot, table or pillars.
    scene = load_workcell(cells_dir() / "sawyer_table.yaml").scene
    assert set(scene.object_names) == {"table", "block_1", "block_2"}
    assert not scene.in_collision(cell.start_state())
    # The pedestal's feet box (0.31 m tall, centred 0.758 m below the base) ends at z = 0.
    base = model.instances[0].base.translation
    assert base[2] - 0.758 - 0.31 / 2 == pytest.approx(0.0)
    table = cell.object("table")
    assert table.pose.translation[2] + table.shape.size[2] / 2 == pytest.approx(0.75)
    # The grasp frame is the gripper's tip, declared in the cell.
    tool = cell.tools["right_arm"]
    assert tool.frame == "right_gripper_tip" and tool.open_pose == "open"


def test_plans_between_the_named_poses_avoid_the_table_and_pillars():
    cell = load_workcell("sawyer_table")
    scene = cell.scene
    for pose, seed in (("zero_pose", 1), ("neutral", 2)):
        plan = cell.plan("right_arm", to=pose, seed=seed)
        assert plan.fraction == 1.0 and plan.trajectory.duration > 0.5
        target = cell.model.named_state("right_arm", pose)
        assert [plan.end.as_dict()[j] for j in ARM] == pytest.approx(list(target.positions))
        for values in plan.path.waypoints:
            q = scene.state.copy()
            q[cell.model.indices(plan.path.names)] = values
            assert not scene.in_collision(q)
        cell.execute(plan)


def test_the_manifest_by_name_is_the_config_package_with_the_cells_tool():
    by_name = load_workcell("sawyer")
    cell = load_cell(cells_dir() / "sawyer_table.yaml")
    assert by_name.model.joint_names == cell.model.joint_names
    assert by_name.model.warnings == []
    ours, theirs = by_name.cell.tools["right_arm"], cell.tools["right_arm"]
    assert (ours.frame, ours.open_pose, ours.closed_pose) == (theirs.frame, theirs.open_pose,
                                                              theirs.closed_pose)
    assert np.allclose(ours.offset.homogeneous, theirs.offset.homogeneous)
