"""The shipped SO-101 (robots/so101): what its package promises, one verified motion, and
its pick-and-place on the physics backend (on mock, every shipped task runs in
tests/scenarios/test_outcomes.py and is checked in tests/tree/test_check.py)."""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from taskrunner.planning import MotionPlanner, NamedGoal, PlanRequest
from taskrunner.planning.request import TimingOptions
from taskrunner.resources import DATA_ROOT
from taskrunner.robot import load_robot
from taskrunner.robot.cell import load_cell
from taskrunner.scene import Scene, scene_from_cell

SO101 = DATA_ROOT / "robots" / "so101"
CELLS = DATA_ROOT / "robots" / "cells"
JOINTS = ("shoulder_pan", "shoulder_lift", "elbow_flex", "wrist_flex", "wrist_roll", "gripper")


@pytest.fixture(scope="module")
def so101():
    return load_robot(SO101)


def test_so101_has_lerobots_joint_names_groups_and_poses(so101):
    assert so101.joint_names == JOINTS  # LeRobot's motor names, in bus order (ids 1..6)
    assert so101.group("arm").joint_names == JOINTS[:5]
    assert so101.group("arm").position_only_ik  # five joints: no arbitrary pose
    assert so101.group("gripper").joint_names == ("gripper",)
    assert set(so101.named_state_names("arm")) == {"rest", "ready"}
    assert set(so101.named_state_names("gripper")) == {"open", "closed"}


def test_so101_gripper_poses_are_lerobots_percentages_of_the_urdf_range(so101):
    # docs/so101.md: q = lower + pct / 100 * (upper - lower); 0 % closed, 100 % open.
    i = so101.joint_names.index("gripper")
    lower, upper = so101.model.lowerPositionLimit[i], so101.model.upperPositionLimit[i]
    assert (lower, upper) == pytest.approx((-0.17453, 1.74533), abs=1e-5)
    closed = so101.named_state("gripper", "closed").as_dict()["gripper"]
    opened = so101.named_state("gripper", "open").as_dict()["gripper"]
    assert 100 * (closed - lower) / (upper - lower) == pytest.approx(0.0, abs=1e-3)
    assert 100 * (opened - lower) / (upper - lower) == pytest.approx(19.5, abs=0.1)


def test_so101_ships_every_mesh_its_urdf_names_and_its_licence():
    urdf = (SO101 / "urdf" / "so101.urdf").read_text()
    names = set(re.findall(r'filename="package://so101_description/meshes/([^"]+)"', urdf))
    assert len(names) == 13
    for name in names:
        mesh = SO101 / "meshes" / name
        # Binary STL: an 80-byte header, a triangle count, 50 bytes a triangle.
        data = mesh.read_bytes()
        assert len(data) == 84 + 50 * int.from_bytes(data[80:84], "little"), name
    assert "Apache License" in (SO101 / "LICENSE").read_text()
    assert "SO-ARM100" in (SO101 / "NOTICE").read_text()
    # Collision geometry is boxes only: no mesh is checked, none is a MuJoCo geom.
    root = ET.fromstring(urdf)
    shapes = {g.tag for c in root.iter("collision") for g in c.find("geometry")}
    assert shapes == {"box"}


def test_so101_named_poses_are_free_and_rest_is_where_it_starts(so101):
    scene = Scene(so101)
    q = so101.default_state()
    for group, pose in (("arm", "rest"), ("arm", "ready"), ("gripper", "open"),
                        ("gripper", "closed")):
        q = so101.state_with(q, so101.named_state(group, pose))
        assert not scene.in_collision(q), (group, pose)
    rest = so101.named_state("arm", "rest").as_dict()
    assert {j: so101.initial_values[j] for j in rest} == pytest.approx(rest)


def test_so101_plans_a_timed_verified_motion_from_rest_to_ready_on_its_table():
    cell = load_cell(CELLS / "so101_table.yaml")
    scene = scene_from_cell(cell)
    result = MotionPlanner(scene).plan(PlanRequest("arm", NamedGoal("ready"),
                                                   timing=TimingOptions()))
    model = cell.model
    ready = model.named_state("arm", "ready").as_dict()
    end = result.end[[model.joint_names.index(j) for j in ready]]
    assert end == pytest.approx(list(ready.values()), abs=1e-6)
    trajectory = result.trajectory
    assert trajectory is not None and trajectory.times[-1] > 0
    # Every sample within the STS3215 limits of joint_limits.yaml at its default 0.5 scaling.
    arm = [model.joint_names.index(j) for j in trajectory.names]
    limit = model.max_velocity[arm]
    assert np.all(np.abs(trajectory.velocities) <= 0.5 * limit + 1e-6)
    for row in trajectory.positions:
        q = result.start.copy()
        q[arm] = row
        assert not scene.in_collision(q)


def test_so101_pair_faces_the_arms_and_prefixes_them():
    cell = load_cell(CELLS / "so101_pair.yaml")
    model = cell.model
    assert model.group("left_arm").joint_names == tuple(f"left_{j}" for j in JOINTS[:5])
    assert len(model.group("both_arms").joint_names) == 10
    assert not Scene(model).in_collision(cell.start_state())
