"""Poses in the Python API as a task file writes them: ``Pose.from_rpy`` (radians, URDF's
fixed X-Y-Z), and ``{"xyz", "rpy" | "quat", "frame"}`` mappings wherever a pose is taken,
checked with the task file's model and messages; unknown names get a "did you mean"."""

from __future__ import annotations

import math
import sys

import numpy as np
import pinocchio as pin
import pytest

import taskrunner
from taskrunner import Pose
from taskrunner.errors import InputError, TaskSpecError, UnknownNameError, did_you_mean
from taskrunner.types import pose_from_xyz_rpy


def test_pose_from_rpy_is_in_radians_about_fixed_x_then_y_then_z():
    pose = Pose.from_rpy([0.1, 0.2, 0.3], [math.pi / 2, 0.0, math.pi / 2], frame="table")
    assert pose.xyz == (0.1, 0.2, 0.3) and pose.frame == "table"
    expected = pin.rpy.rpyToMatrix(math.pi / 2, 0.0, math.pi / 2)
    np.testing.assert_allclose(pose.se3.rotation, expected, atol=1e-12)
    # fixed axes: R = Rz(yaw) Ry(pitch) Rx(roll); x maps to y after a quarter yaw
    np.testing.assert_allclose(pose.se3.rotation @ [1, 0, 0], [0, 1, 0], atol=1e-12)
    assert pose_from_xyz_rpy([0.1, 0.2, 0.3], [math.pi / 2, 0.0, math.pi / 2],
                             "table") == pose
    assert Pose.from_rpy().quat == (0.0, 0.0, 0.0, 1.0)


@pytest.mark.parametrize("rpy", [(0.0, 1.0), (0.0, 0.0, float("nan")), "abc", None])
def test_pose_from_rpy_refuses_anything_but_three_finite_angles(rpy):
    with pytest.raises(InputError, match=r"'rpy' must be 3 finite numbers roll, pitch, yaw "
                                         r"in radians \(got "):
        Pose.from_rpy([0, 0, 0], rpy)


@pytest.fixture(scope="module")
def table():
    with taskrunner.load_workcell("servo_arm_table") as cell:
        yield cell


@pytest.fixture(scope="module")
def panda():
    with taskrunner.load_workcell("panda") as cell:
        yield cell


def _tip(cell, group, plan):
    return cell.link_pose(cell.model.group(group).tip_link, plan.end)


def test_plan_takes_a_task_files_pose_mapping_with_rpy_or_quat(panda):
    tip = panda.model.group("arm").tip_link
    ready = panda.model.named_state("arm", "ready")
    # a reachable pose: the tip at 'ready', lowered by 5 cm
    here = panda.link_pose(tip, ready)
    xyz = [here.xyz[0], here.xyz[1], here.xyz[2] - 0.05]
    rpy = [float(a) for a in pin.rpy.matrixToRpy(here.se3.rotation)]
    by_rpy = panda.plan("arm", pose={"xyz": xyz, "rpy": rpy}, start=ready, seed=1)
    by_quat = panda.plan("arm", pose={"xyz": xyz, "quat": list(here.quat)},
                         start=ready, seed=1)
    by_pose = panda.plan("arm", pose=Pose.from_rpy(xyz, rpy), start=ready, seed=1)
    for plan in (by_rpy, by_quat, by_pose):
        reached = _tip(panda, "arm", plan)
        np.testing.assert_allclose(reached.xyz, xyz, atol=1e-3)
        angle = np.linalg.norm(pin.log3(reached.se3.rotation.T @ here.se3.rotation))
        assert angle < 1e-2, f"orientation off by {angle} rad"


def test_a_mapping_without_an_orientation_is_a_position_target_as_in_a_task_file(table):
    target = [0.15, 0.0, 0.9]
    plan = table.plan("arm", pose={"xyz": target})
    np.testing.assert_allclose(_tip(table, "arm", plan).xyz, target, atol=1e-3)


def test_plan_cartesian_takes_mappings_as_waypoints(table):
    start = table.plan("arm", position=(0.15, 0.0, 0.9)).end
    lower = [0.15, 0.0, 0.88]
    line = table.plan_cartesian("arm", [{"xyz": lower}], start=start)
    assert line.fraction == pytest.approx(1.0)
    np.testing.assert_allclose(_tip(table, "arm", line).xyz, lower, atol=2e-3)
    with pytest.raises(InputError, match=r"'waypoints\[0\]' without 'rpy' or 'quat' .* "
                                         r"frame 'world' \(got 'tool0'\)"):
        table.plan_cartesian("arm", {"xyz": lower, "frame": "tool0"}, start=start)


@pytest.mark.parametrize(("pose", "message"), [
    ({"xyz": [0.1, 0.2]}, "'pose.xyz' must have 3 values (got 2)"),
    ({"xyz": [0, 0, 1], "rpy": [0, 0]}, "'pose.rpy' must have 3 values (got 2)"),
    ({"xyz": [0, 0, 1], "rpy": [0, 0, 0], "quat": [0, 0, 0, 1]},
     "'pose' takes only one of 'rpy' or 'quat'"),
    ({"xyz": [0, 0, 1], "quat": [0, 0, 0, 2]},
     "'pose.quat' must be a unit quaternion [x, y, z, w] (got norm 2)"),
    ({"xzy": [0, 0, 1]}, "'xzy' is not a field of 'pose'; did you mean 'xyz'?"),
])
def test_a_bad_pose_mapping_gets_the_task_files_message_at_the_callers_line(
        table, pose, message):
    with pytest.raises(TaskSpecError) as caught:
        line = sys._getframe().f_lineno + 1
        table.plan("arm", pose=pose)
    assert str(caught.value) == f"{__file__}:{line}: {message}"


def test_a_pose_that_is_neither_a_pose_nor_a_mapping_is_refused(table):
    with pytest.raises(InputError, match=r"'pose' must be a taskrunner.Pose or a mapping "
                                         r"\{xyz, rpy \| quat, frame\} \(got 'home'\)"):
        table.plan("arm", pose="home")


def test_unknown_names_in_python_get_a_did_you_mean(table):
    with pytest.raises(UnknownNameError, match=r"unknown group 'amr'; did you mean 'arm'\? "
                                               r"\(known: 'arm', 'gripper'\)"):
        table.plan("amr", to="home")
    with pytest.raises(UnknownNameError, match=r"'hme'; did you mean 'home'\?"):
        table.plan("arm", to="hme")
    with pytest.raises(UnknownNameError, match=r"unknown link 'tool_0'; did you mean 'tool0'\?"):
        table.link_pose("tool_0")
    with pytest.raises(InputError, match=r"did you mean 'servo_arm_table'\?"):
        taskrunner.load_workcell("servo_arm_tabel")
    # nothing close: the known names only
    with pytest.raises(UnknownNameError, match=r"unknown group 'xyz'; known: 'arm', 'gripper'$"):
        table.plan("xyz", to="home")


def test_one_suggestion_helper_serves_task_files_and_errors():
    from taskrunner.tasks import problem

    assert problem.did_you_mean is did_you_mean
    assert did_you_mean("pik", ["pick", "place"]) == "; did you mean 'pick'?"
    assert did_you_mean("zzz", ["pick", "place"], "verbs") == "; verbs: 'pick', 'place'"
    assert did_you_mean("zzz", ["pick"]) == ""
