"""Tool frames: where each arm grasps (declared, tool0, the end effector's parent link, or
derived from the fingers), the gripper's pose names, and 'grasp' on place and hand-over."""

from __future__ import annotations

import math
import shutil
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.cli import EXIT_OK, main
from taskrunner.errors import RobotDescriptionError, SceneError, TaskSpecError, YamlError
from taskrunner.kinematics import frame_pose
from taskrunner.robot.cell import load_cell, load_cell_or_robot
from taskrunner.robot.tools import Tool
from taskrunner.shapes import Box
from taskrunner.tree.check import check_task
from taskrunner.tree.context import resolve_arm
from taskrunner.tree.grasps import release_poses, releases_with_grasp
from taskrunner.types import Pose

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures"
SRC = FIXTURES / "moveit" / "src"
DUO_CELL = FIXTURES / "duo" / "duo_table.yaml"


@pytest.fixture(scope="module")
def duo():
    return load_cell(DUO_CELL)


def test_shipped_robots_keep_their_grasp_frames():
    servo = load_cell_or_robot("taskrunner/data/robots/cells/servo_arm_pair.yaml")
    assert {a: t.frame for a, t in servo.tools.items()} == {"left_arm": "left_tool0",
                                                           "right_arm": "right_tool0"}
    panda = load_cell_or_robot("taskrunner/data/robots/panda")
    tool = panda.tools["arm"]
    assert (tool.frame, tool.link, tool.open_pose, tool.closed_pose) == (
        "panda_hand_tcp", "panda_hand_tcp", "open", "closed")
    assert "parent link" in tool.origin


def test_derived_tcp_sits_between_the_fingertip_pads_closing_across_them(duo):
    tool = duo.tools["right_arm"]
    assert tool.frame == "right_hand_tcp" and tool.link == "right_flange"
    assert "derived" in tool.origin
    model = duo.model
    q = model.state_with(duo.start_state(), model.named_state("right_gripper", "open"))
    tcp = frame_pose(model, q, "right_hand_tcp")
    a = frame_pose(model, q, "right_finger_a").translation
    b = frame_pose(model, q, "right_finger_b").translation
    # Halfway between the fingers, the closing axis (y) along the line between them.
    across = (a - b) / np.linalg.norm(a - b)
    assert abs(abs(float(tcp.rotation[:, 1] @ across)) - 1) < 1e-9
    offset = tcp.translation - (a + b) / 2
    assert abs(float(offset @ across)) < 1e-9
    # The fingers are 5 cm long from 1.5 cm past the hand: tips 9.5 cm past the flange, the
    # TCP a fifth of their length back; z points out of the hand.
    np.testing.assert_allclose(tool.offset.translation, [0.0, 0.0, 0.085], atol=1e-9)
    np.testing.assert_allclose(tool.offset.rotation[:, 2], [0, 0, 1], atol=1e-9)
    # The hand is turned a quarter on the flange: its fingers close along the flange's x.
    np.testing.assert_allclose(np.abs(tool.offset.rotation[:, 1]), [1, 0, 0], atol=1e-9)


def test_declared_tcp_and_closing_axis_are_used_and_located(duo):
    tool = duo.tools["left_arm"]
    assert tool.frame == "left_hand_tcp" and tool.link == "left_flange"
    np.testing.assert_allclose(tool.offset.translation, [0, 0, 0.075])
    np.testing.assert_allclose(tool.offset.rotation[:, 1], [1, 0, 0], atol=1e-12)
    assert tool.origin == f"declared at {DUO_CELL}:11"
    assert (tool.open_pose, tool.closed_pose) == ("open", "close")


def test_an_arm_attaches_what_it_holds_to_the_link_its_tool_frame_is_on(duo):
    arm = resolve_arm(duo, "left_arm")
    assert arm.grasp_frame == "left_hand_tcp" and arm.holder == "left_flange"
    held = pin.SE3(np.eye(3), np.array([0.0, 0.0, 0.1]))  # in the flange
    grip = arm.grip(held)  # in the tool frame: 2.5 cm further along its z
    np.testing.assert_allclose(grip.translation, [0, 0, 0.025], atol=1e-12)
    servo = resolve_arm(load_cell_or_robot("taskrunner/data/robots/servo_arm"), "arm")
    assert servo.holder == servo.grasp_frame == "tool0"


def _duo_cell(tmp_path: Path, end_effectors: str) -> Path:
    text = DUO_CELL.read_text()
    head, _, tail = text.partition("    end_effectors:\n")
    rest = tail.split("start:", 1)[1]
    path = tmp_path / "fixtures" / "duo" / "cell.yaml"
    path.parent.mkdir(parents=True)
    shutil.copytree(SRC, tmp_path / "fixtures" / "moveit" / "src")
    path.write_text(head + end_effectors + "start:" + rest)
    return path


@pytest.mark.parametrize("block, line, message", [
    ("    end_effectors:\n      left_grip: {closing_axis: x}\n", 11,
     "end_effectors: 'left_grip' is not an end effector (end effectors: left_hand, right_hand)"),
    ("    end_effectors:\n      left_hand:\n        link: left_wrist\n", 12,
     "end_effectors.left_hand.link: 'left_wrist' is not a link of the robot"),
    ("    end_effectors:\n      left_hand:\n        closing_axis: x\n        closed: shut\n", 13,
     "end_effectors.left_hand.closed: 'shut' is not a named pose of gripper group "
     "'left_gripper' (poses: close, open)"),
    ("    end_effectors:\n      left_hand:\n        closing_axis: z\n", 11,
     "'closing_axis' must be across 'approach_axis' (default z) (got z and z)"),
    ("    end_effectors:\n      left_hand:\n        tcp_ofset: {xyz: [0, 0, 0.1]}\n", 12,
     "tcp_ofset: unknown field"),
])
def test_bad_end_effector_declarations_name_the_file_and_line(tmp_path, block, line, message):
    path = _duo_cell(tmp_path, block)
    with pytest.raises(YamlError) as caught:
        load_cell(path)
    assert f"{path}:{line}:" in str(caught.value)
    assert message in str(caught.value)


def test_a_manifest_declares_tools_and_a_cell_overrides_them_field_by_field(tmp_path):
    package = tmp_path / "src"
    shutil.copytree(SRC, package)
    (package / "duo_robot").mkdir()
    manifest = package / "duo_robot" / "robot.yaml"
    manifest.write_text(
        "name: duo\n"
        "urdf: package://duo_description/urdf/duo.urdf.xacro\n"
        "srdf: package://duo_moveit_config/config/duo.srdf\n"
        "end_effectors:\n"
        "  right_hand:\n"
        "    tcp_offset: {xyz: [0, 0, 0.09]}\n"
        "    closing_axis: [1, 0, 0]\n"
        "    open: open\n")
    alone = load_cell_or_robot(manifest)
    right = alone.tools["right_arm"]
    np.testing.assert_allclose(right.offset.translation, [0, 0, 0.09])
    assert right.origin == f"declared at {manifest}:5"
    cell = tmp_path / "cells" / "cell.yaml"
    cell.parent.mkdir()
    cell.write_text(
        "name: duo_cell\n"
        "robots:\n"
        "  - name: duo\n"
        f"    robot: {manifest}\n"
        "    prefix: a_\n"
        "    end_effectors:\n"
        "      right_hand: {tcp_offset: {xyz: [0, 0, 0.08]}}\n")
    placed = load_cell(cell).tools["a_right_arm"]
    assert placed.frame == "a_right_hand_tcp" and placed.link == "a_right_flange"
    np.testing.assert_allclose(placed.offset.translation, [0, 0, 0.08])  # the cell's
    np.testing.assert_allclose(placed.offset.rotation[:, 1], [1, 0, 0], atol=1e-12)  # manifest's


def test_a_gripper_without_open_or_closed_poses_says_which_it_has():
    tool = Tool("arm", "hand", "hand_group", "tcp", "flange", pin.SE3.Identity(), "open", None,
                "test", ("open", "pinch"))
    assert tool.gripper_pose("open") == "open"
    with pytest.raises(RobotDescriptionError) as caught:
        tool.gripper_pose("closed")
    assert ("gripper group 'hand_group' of arm 'arm' has no closed pose (looked for 'closed' "
            "or 'close'; its poses: open, pinch)") in str(caught.value)
    assert "{hand: {closed: POSE}}" in str(caught.value)


def test_place_grasp_keeps_the_releases_of_that_kind():
    bar = Box((0.03, 0.03, 0.10))
    target = pin.SE3(pin.rpy.rpyToMatrix(math.pi / 2, 0, 0), np.array([0.3, -0.2, 0.766]))
    # Held across its long axis near one end, the tool pointing into a side face.
    grip = pin.SE3(pin.rpy.rpyToMatrix(0, math.pi / 2, 0), np.array([0.0, 0.0, 0.04]))
    poses = release_poses(target, grip, bar)
    top = releases_with_grasp(poses, target, "top", "bar")
    side = releases_with_grasp(poses, target, "side", "bar")
    # Eight ways to lay the bar (its symmetries): two with the tool pointing down, four
    # sideways, two up from below (neither).
    assert (len(poses), len(top), len(side)) == (8, 2, 4)
    assert all(p.rotation[2, 2] < -0.7 for p in top)
    assert all(abs(p.rotation[2, 2]) < 0.71 for p in side)
    # An explicit grasp picks the one release that puts the tool there.
    wanted = target.inverse() * top[0]
    chosen = releases_with_grasp(poses, target, Pose.from_se3(wanted), "bar")
    assert len(chosen) == 1 and chosen[0].isApprox(top[0], 1e-9)
    far = Pose.from_se3(wanted * pin.SE3(np.eye(3), np.array([0.0, 0.0, 0.05])))
    with pytest.raises(SceneError, match=r"not held so that its tool can be at .grasp.*allowed: 10 mm"):
        releases_with_grasp(poses, target, far, "bar")
    with pytest.raises(TaskSpecError):
        releases_with_grasp(poses, target, "below", "bar")


def test_a_top_release_of_an_object_held_from_the_side_is_refused():
    cube = Box((0.04, 0.04, 0.04))
    target = pin.SE3(np.eye(3), np.array([0.3, 0.0, 0.77]))
    grip = pin.SE3(pin.rpy.rpyToMatrix(0, math.pi / 2, 0), np.zeros(3))  # tool horizontal
    poses = [p for p in release_poses(target, grip, cube)]
    with pytest.raises(SceneError, match="cannot be put down with a 'top' grasp"):
        releases_with_grasp(poses, target, "top", "cube")


def test_info_lists_each_arms_tool_frame(capsys):
    assert main(["info", str(DUO_CELL)]) == EXIT_OK
    out = capsys.readouterr().out
    assert "tools (TCP: the tool frame's origin; y closes, z approaches):" in out
    assert ("  left_arm (end effector left_hand): tool frame left_hand_tcp on left_flange at "
            "xyz [+0.0000, +0.0000, +0.0750]") in out
    assert "closes along +x, approaches along +z of right_flange" in out
    assert "gripper right_gripper: open open, closed close (derived from the fingers'" in out


def test_a_pick_with_a_gripper_that_has_no_open_pose_is_refused_at_its_line(tmp_path):
    cell = _duo_cell(tmp_path, "")
    srdf = tmp_path / "fixtures" / "moveit" / "src" / "duo_moveit_config" / "config" / "duo.srdf"
    srdf.write_text(srdf.read_text().replace('name="open"', 'name="release"'))
    cell.write_text(cell.read_text().replace(", left_gripper: open, right_gripper: open", ""))
    task = cell.parent / "task.yaml"
    task.write_text("task: t\ncell: cell.yaml\n"
                    "objects:\n  - {name: cube, shape: box, size: [0.04, 0.04, 0.04], "
                    "pose: {xyz: [0.32, 0.22, 0.7705]}}\n"
                    "steps:\n  - pick: {arm: left_arm, object: cube}\n")
    report = check_task(task)
    assert [(p.line, p.message) for p in report.problems] == [(
        6, "gripper group 'left_gripper' of arm 'left_arm' has no open pose (looked for "
           "'open' or 'opened'; its poses: close, release): name it as 'end_effectors: "
           "{left_hand: {open: POSE}}' in robot.yaml or on the robot in the cell")]


def test_a_cell_over_a_manifest_reports_each_field_in_its_own_file(tmp_path):
    package = tmp_path / "src"
    shutil.copytree(SRC, package)
    manifest = package / "robot.yaml"
    manifest.write_text(
        "urdf: package://duo_description/urdf/duo.urdf.xacro\n"
        "srdf: package://duo_moveit_config/config/duo.srdf\n"
        "end_effectors:\n"
        "  right_hand:\n"
        "    approach_axis: x\n"
        "    link: right_palm\n")
    cell = tmp_path / "cell.yaml"
    cell.write_text(f"name: c\nrobots:\n  - name: duo\n    robot: {manifest}\n"
                    "    end_effectors:\n      right_hand: {tcp_offset: {xyz: [0, 0, 0.1]}}\n")
    with pytest.raises(YamlError) as caught:
        load_cell(cell)  # the manifest's link, at the manifest's line
    assert str(caught.value).startswith(f"{manifest}:6: end_effectors.right_hand.link: "
                                        "'right_palm' is not a link of the robot")
    cell.write_text(cell.read_text().replace("tcp_offset: {xyz: [0, 0, 0.1]}", "closing_axis: x"))
    with pytest.raises(YamlError) as caught:
        load_cell(cell)  # the two files disagree: said at the cell's entry
    assert str(caught.value).startswith(
        f"{cell}:6: end_effectors.right_hand: 'closing_axis' must be across 'approach_axis'")
    assert f"(with the robot's own declaration at {manifest}:4)" in str(caught.value)
