"""Cartesian paths: straight lines of a link, cut short (never raised) by IK, collisions or jumps."""

from __future__ import annotations

import itertools

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.errors import (
    InputError,
    InvalidStateError,
    StartInCollisionError,
    UnknownNameError,
)
from taskrunner.kinematics import frame_pose
from taskrunner.planning.cartesian import (
    CartesianOptions,
    CartesianPlanner,
    compute_cartesian_path,
    compute_relative_cartesian_path,
    relative_pose,
)
from taskrunner.planning.planner import interpolate_path
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.scene import Scene, scene_from_cell
from taskrunner.shapes import Box
from taskrunner.types import Pose

TCP = "panda_hand_tcp"


@pytest.fixture(scope="module")
def ready(panda_model):
    """The Panda's ``default`` pose: TCP at about (0.307, 0, 0.487), pointing down."""
    return panda_model.state_with(
        panda_model.default_state(), panda_model.named_state("arm_and_hand", "default"))


@pytest.fixture(scope="module")
def scene(panda_model, ready):
    scene = Scene(panda_model)
    scene.set_state(ready)
    return scene


@pytest.fixture(scope="module")
def planner(scene):
    return CartesianPlanner(scene)


@pytest.fixture(scope="module")
def blocked(scene):
    """A thin plate across the line 10 cm straight down from the ready TCP."""
    blocked = scene.copy()
    blocked.add_object("plate", Box((0.1, 0.1, 0.01)), Pose((0.307, 0.0, 0.40)))
    return blocked


@pytest.fixture(scope="module")
def servo(repo_root):
    """The servo-arm cell, arm at PickUp (tool0 3.5 cm above the table, pointing down)."""
    scene = scene_from_cell(load_cell(DATA_ROOT / "robots" / "cells" / "servo_arm_table.yaml"))
    model = scene.robot
    scene.set_state(model.state_with(scene.state, model.named_state("arm", "PickUp")))
    return scene


def full_states(result, model):
    return [model.state_with(result.start, dict(zip(result.path.names, row)))
            for row in result.path.waypoints]


def distance_to_segment(p, a, b):
    ab = b - a
    s = np.clip(np.dot(p - a, ab) / np.dot(ab, ab), 0.0, 1.0)
    return float(np.linalg.norm(p - (a + s * ab)))


def rotation_angle(ra, rb):
    return float(np.linalg.norm(pin.log3(ra.T @ rb)))


# ---------------------------------------------------------------- straight lines
def test_panda_moves_10_cm_straight_down_keeping_its_orientation(planner, panda_model, ready):
    start = frame_pose(panda_model, ready, TCP, data=panda_model.model.createData())
    goal = pin.SE3(start.rotation, start.translation - np.array([0.0, 0.0, 0.1]))
    result = planner.compute("arm", goal)
    assert result.fraction == 1.0 and result.stop_reason is None and result.complete
    assert result.message == "" and result.waypoints_reached == 1
    assert len(result.path) == 21 and result.ik_solves == 20  # 10 cm at 5 mm
    assert result.path.names == panda_model.group("arm").joint_names
    np.testing.assert_array_equal(result.start, ready)
    data = panda_model.model.createData()
    previous = start.translation
    for q in full_states(result, panda_model):
        pose = frame_pose(panda_model, q, TCP, data=data)
        assert distance_to_segment(pose.translation, start.translation, goal.translation) < 1e-5
        assert rotation_angle(pose.rotation, start.rotation) < 1e-5
        assert np.linalg.norm(pose.translation - previous) <= 0.005 + 1e-5
        previous = pose.translation
    assert np.allclose(frame_pose(panda_model, result.end, TCP, data=data).translation,
                       goal.translation, atol=1e-5)
    np.testing.assert_array_equal(result.end, full_states(result, panda_model)[-1])


def test_same_request_gives_the_same_path(planner, scene):
    a = planner.compute_relative("arm", (0.05, 0.05, -0.05), frame="world")
    b = compute_relative_cartesian_path(scene, "arm", (0.05, 0.05, -0.05), frame="world")
    np.testing.assert_array_equal(a.path.waypoints, b.path.waypoints)
    assert a.fraction == b.fraction == 1.0


def test_path_through_several_waypoints_follows_each_segment(planner, panda_model, ready):
    data = panda_model.model.createData()
    start = frame_pose(panda_model, ready, TCP, data=data)
    corners = [start.translation + np.array(d) for d in
               [(0.0, 0.0, -0.05), (0.0, 0.08, -0.05), (0.05, 0.08, 0.0)]]
    waypoints = [pin.SE3(start.rotation, c) for c in corners]
    result = planner.compute("arm", waypoints)
    assert result.fraction == 1.0 and result.waypoints_reached == 3
    segments = list(zip([start.translation, *corners[:-1]], corners))
    for q in full_states(result, panda_model):
        p = frame_pose(panda_model, q, TCP, data=data).translation
        assert min(distance_to_segment(p, a, b) for a, b in segments) < 1e-5
    # Every corner is itself a point of the path.
    points = [frame_pose(panda_model, q, TCP, data=data).translation
              for q in full_states(result, panda_model)]
    for corner in corners:
        assert min(np.linalg.norm(p - corner) for p in points) < 1e-5


def test_rotation_is_slerped_about_the_fixed_tcp(planner, panda_model, ready):
    data = panda_model.model.createData()
    start = frame_pose(panda_model, ready, TCP, data=data)
    result = planner.compute_relative("arm", (0, 0, 0), offset_rpy=(0, 0, 0.5))
    assert result.fraction == 1.0
    assert len(result.path) == 11  # 0.5 rad at 0.05 rad per step
    angles = []
    for q in full_states(result, panda_model):
        pose = frame_pose(panda_model, q, TCP, data=data)
        assert np.linalg.norm(pose.translation - start.translation) < 1e-5
        angles.append(rotation_angle(start.rotation, pose.rotation))
    np.testing.assert_allclose(angles, np.linspace(0.0, 0.5, 11), atol=1e-5)


# ---------------------------------------------------------------- relative moves
def test_relative_move_along_the_tool_z_goes_down_when_the_tool_points_down(scene):
    start = scene.link_pose(TCP).se3
    target = relative_pose(scene, TCP, (0.0, 0.0, 0.05), frame="link").se3
    np.testing.assert_allclose(target.translation, start.translation + 0.05 * start.rotation[:, 2],
                               atol=1e-9)
    assert target.translation[2] == pytest.approx(start.translation[2] - 0.05, abs=1e-4)
    np.testing.assert_allclose(target.rotation, start.rotation, atol=1e-9)


def test_relative_move_in_world_adds_the_offset_to_the_world_position(scene):
    start = scene.link_pose(TCP).se3
    target = relative_pose(scene, TCP, (0.0, 0.0, 0.1), offset_rpy=(0.0, 0.0, 0.3),
                           frame="world").se3
    np.testing.assert_allclose(target.translation, start.translation + [0, 0, 0.1], atol=1e-9)
    np.testing.assert_allclose(target.rotation,
                               pin.rpy.rpyToMatrix(0, 0, 0.3) @ start.rotation, atol=1e-9)


def test_relative_paths_in_tool_and_world_frames_reach_their_targets(planner, panda_model, scene):
    data = panda_model.model.createData()
    start = scene.link_pose(TCP).se3
    down = planner.compute_relative("arm", (0.0, 0.0, 0.05), frame="link")
    up = planner.compute_relative("arm", (0.0, 0.0, 0.1), frame="world")
    assert down.fraction == up.fraction == 1.0
    assert frame_pose(panda_model, down.end, TCP, data=data).translation[2] == pytest.approx(
        start.translation[2] - 0.05, abs=1e-4)
    np.testing.assert_allclose(frame_pose(panda_model, up.end, TCP, data=data).translation,
                               start.translation + [0, 0, 0.1], atol=1e-5)


def test_waypoint_in_a_link_frame_is_taken_at_the_start_state(planner, scene):
    in_tool = planner.compute("arm", Pose((0.0, 0.0, 0.05), frame=TCP))
    relative = planner.compute_relative("arm", (0.0, 0.0, 0.05), frame="link")
    np.testing.assert_allclose(in_tool.path.waypoints, relative.path.waypoints, atol=1e-12)


def test_servo_arm_follows_a_line_down_with_position_only_ik(servo):
    model = servo.robot
    planner = CartesianPlanner(servo)
    # Lift tool0 8 cm first: PickUp is too close to the table to go 5 cm down.
    lifted = planner.compute_relative("arm", (0, 0, 0.08), frame="world", link="tool0")
    assert lifted.fraction == 1.0
    data = model.model.createData()
    start = frame_pose(model, lifted.end, "tool0", data=data)
    result = planner.compute_relative("arm", (0, 0, -0.05), frame="world", link="tool0",
                                      start=lifted.end)
    assert result.fraction == 1.0 and len(result.path) == 11
    goal = start.translation - [0, 0, 0.05]
    for q in full_states(result, model):
        pose = frame_pose(model, q, "tool0", data=data)
        assert distance_to_segment(pose.translation, start.translation, goal) < 1e-5
    # The orientation is free but changes smoothly: no step turns the tool more than 3°.
    rotations = [frame_pose(model, q, "tool0", data=data).rotation
                 for q in full_states(result, model)]
    assert max(rotation_angle(a, b) for a, b in itertools.pairwise(rotations)) < 0.05


# ---------------------------------------------------------------- cut short
def test_obstacle_across_the_line_stops_the_path_before_it(blocked, panda_model):
    result = compute_relative_cartesian_path(blocked, "arm", (0, 0, -0.1), frame="world")
    assert result.stop_reason == "collision"
    assert 0.3 < result.fraction < 1.0
    assert "plate" in result.message and "collision between" in result.message
    assert "% of the path" in result.message
    assert result.waypoints_reached == 0
    group = panda_model.group("arm")
    q = result.start.copy()
    for values in interpolate_path(np.array(result.path.waypoints), 0.002):
        q[group.joint_indices] = values
        assert not blocked.in_collision(q)


def test_without_collision_avoidance_the_path_goes_through_the_obstacle(blocked):
    result = compute_relative_cartesian_path(blocked, "arm", (0, 0, -0.1), frame="world",
                                             options=CartesianOptions(avoid_collisions=False))
    assert result.fraction == 1.0 and result.collision_checks == 0
    assert blocked.in_collision(result.end)


def test_unreachable_waypoint_stops_where_ik_fails(planner, scene):
    result = planner.compute("arm", Pose((0.3, 0.0, 2.0), (1.0, 0.0, 0.0, 0.0)))
    assert result.stop_reason == "ik"
    assert 0.1 < result.fraction < 0.5
    assert "no IK solution" in result.message and "panda_hand_tcp" in result.message
    assert len(result.path) >= 2


def test_relative_jump_threshold_cuts_at_the_first_large_step(planner):
    # Threshold 1: any step above the mean step is a "jump".
    result = planner.compute_relative("arm", (0.0, 0.0, 0.1),
                                      options=CartesianOptions(jump_threshold=1.0))
    assert result.stop_reason == "jump" and result.fraction < 1.0
    assert "jump_threshold" in result.message
    assert result.fraction == pytest.approx((len(result.path) - 1) / 20)
    lenient = planner.compute_relative("arm", (0.0, 0.0, 0.1),
                                       options=CartesianOptions(jump_threshold=5.0))
    assert lenient.fraction == 1.0


def test_absolute_joint_step_limit_reports_a_jump_naming_the_joint(planner):
    result = planner.compute_relative("arm", (0.0, 0.0, 0.1),
                                      options=CartesianOptions(max_joint_step=0.001))
    assert result.stop_reason == "jump" and result.fraction == 0.0
    assert len(result.path) == 1 and "panda_joint" in result.message


def test_second_segment_blocked_keeps_the_first_waypoint(blocked, panda_model, ready):
    start = frame_pose(panda_model, ready, TCP, data=panda_model.model.createData())
    side = pin.SE3(start.rotation, start.translation + [0.0, 0.1, 0.0])
    result = compute_cartesian_path(blocked, "arm", [side, pin.SE3(start), pin.SE3(
        start.rotation, start.translation - [0.0, 0.0, 0.1])])
    assert result.stop_reason == "collision" and result.waypoints_reached == 2
    assert 2 / 3 < result.fraction < 1.0  # three segments of 10 cm


# ---------------------------------------------------------------- bad input
def test_bad_input_raises(planner, scene):
    target = scene.link_pose(TCP)
    with pytest.raises(UnknownNameError):
        planner.compute("legs", target)
    with pytest.raises(UnknownNameError):
        planner.compute("arm", target, link="no_such_link")
    with pytest.raises(UnknownNameError):
        planner.compute("arm", Pose((0, 0, 0.1), frame="nowhere"))
    with pytest.raises(InputError):
        planner.compute("arm", [])
    with pytest.raises(InputError):
        planner.compute("arm", [np.eye(4)])
    with pytest.raises(InvalidStateError):
        planner.compute("arm", target, start=np.zeros(3))
    with pytest.raises(InputError):
        relative_pose(scene, TCP, (0, 0, 0.1), frame="tool")


def test_start_in_collision_raises_naming_the_pair(scene):
    crowded = scene.copy()
    crowded.add_object("block", Box((0.05, 0.05, 0.05)), Pose(frame=TCP))
    with pytest.raises(StartInCollisionError) as info:
        compute_relative_cartesian_path(crowded, "arm", (0, 0, 0.05))
    assert any("block" in pair for pair in info.value.pairs)
    # Without collision avoidance the start is not checked.
    result = compute_relative_cartesian_path(crowded, "arm", (0, 0, 0.05),
                                             options=CartesianOptions(avoid_collisions=False))
    assert result.fraction == 1.0


@pytest.mark.parametrize("field, value", [
    ("eef_step", 0.0), ("max_rotation_step", -1.0), ("jump_threshold", -0.5),
    ("max_joint_step", 0.0), ("collision_resolution", float("nan")), ("tolerance", True),
    ("avoid_collisions", 1), ("position_only", "yes"),
])
def test_options_reject_bad_values(field, value):
    with pytest.raises(ValueError, match=field):
        CartesianOptions(**{field: value})
