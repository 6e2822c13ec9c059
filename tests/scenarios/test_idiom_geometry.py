"""The geometry under the pick / place / hand-over idioms (taskrunner.tree.grasps and
taskrunner.tree.reach), checked on the shipped cells without planning."""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.scene import scene_from_cell
from taskrunner.shapes import Box, Cylinder
from taskrunner.tree.context import TaskContext
from taskrunner.tree.grasps import (
    hand_links,
    handover_grasps,
    release_poses,
    side_grasps,
    symmetries,
    top_grasps,
)
from taskrunner.tree.reach import approximate, orientation_error, wrist_roll

CELLS = DATA_ROOT / "robots" / "cells"
BAR = Box((0.025, 0.025, 0.08))


def context(cell_name: str) -> TaskContext:
    cell = load_cell(CELLS / f"{cell_name}.yaml")
    return TaskContext(cell, scene_from_cell(cell), None, None)  # type: ignore[arg-type]


def test_panda_hand_links_include_the_finger_that_mimics_the_other():
    links = hand_links(context("panda_table"), "arm")
    assert {"panda_leftfinger", "panda_rightfinger", "panda_hand"} <= set(links)
    assert not any("link7" in link for link in links)


def test_symmetries_keep_the_shape_and_its_z_line():
    assert len(symmetries(BAR)) == 8  # square cross-section: quarter turns, and flips
    assert len(symmetries(Box((0.02, 0.03, 0.05)))) == 4  # half turns only
    assert len(symmetries(Cylinder(0.01, 0.05))) == 16
    extent = np.array(BAR.size)
    for rotation in symmetries(BAR):
        assert np.abs(rotation) @ extent == pytest.approx(extent)
        assert abs(rotation[2, 2]) == pytest.approx(1.0)


def test_side_grasps_point_into_each_face_and_close_horizontally():
    placed = pin.SE3(pin.rpy.rpyToMatrix(0.0, 0.0, 0.4), np.array([0.3, 0.1, 0.79]))
    grasps = side_grasps(placed, BAR)
    assert len(grasps) == 8
    # A flat box is closed on across its narrow way only (2 cm), from its ends.
    flat = side_grasps(placed, Box((0.02, 0.06, 0.03)))
    assert len(flat) == 4
    for grasp in flat:
        assert abs(grasp.rotation[:, 1] @ placed.rotation[:, 0]) == pytest.approx(1.0)
    for grasp in grasps:
        z, y = grasp.rotation[:, 2], grasp.rotation[:, 1]
        assert abs(z[2]) < 1e-9 and abs(y[2]) < 1e-9  # horizontal: no finger under it
        inward = placed.translation - grasp.translation
        assert z @ inward > 0  # pointing into the object, 7.5 mm past the face
        assert np.linalg.norm(inward) == pytest.approx(0.0125 - 0.0075)


def test_top_grasps_of_a_lying_bar_go_down_its_vertical_axis():
    lying = pin.SE3(pin.rpy.rpyToMatrix(0.0, math.pi / 2, 0.0), np.array([0.0, 0.0, 0.7635]))
    grasps = top_grasps(lying, BAR)
    assert len(grasps) == 2  # across the bar, both ways; never along its 8 cm
    for grasp in grasps:
        assert grasp.rotation[:, 2] == pytest.approx([0.0, 0.0, -1.0])
        # 7.5 mm below the top face (the bar is 2.5 cm thick lying down), not 2 cm.
        assert grasp.translation[2] == pytest.approx(0.7635 + 0.0125 - 0.0075)
        # Fingers close across the bar, never along it.
        assert abs(grasp.rotation[:, 1] @ lying.rotation[:, 2]) < 1e-9


def test_handover_grasps_take_the_free_end_across_from_the_takers_side():
    upright = pin.SE3(np.eye(3), np.array([0.0, 0.0, 0.9]))
    held_at = np.array([0.0, 0.0, 0.02])  # the holder grips the upper end
    grasps = handover_grasps(upright, BAR, held_at)
    assert len(grasps) == 8
    for grasp in grasps:
        assert grasp.translation[2] == pytest.approx(0.9 - 0.04 + 0.02)  # 2 cm from the end
        assert abs(grasp.rotation[:, 0] @ np.array([0.0, 0.0, 1.0])) == pytest.approx(1.0)
    # A taker standing at +x takes it from its own side: pointing toward -x.
    mine = handover_grasps(upright, BAR, held_at, taker=np.array([0.5, 0.0, 0.75]))
    assert len(mine) == 2
    for grasp in mine:
        assert grasp.rotation[:, 2] == pytest.approx([-1.0, 0.0, 0.0])


def test_release_poses_put_the_held_object_on_its_target():
    grip = pin.SE3(pin.rpy.rpyToMatrix(0.1, -0.2, 0.3), np.array([0.01, 0.0, 0.02]))
    target = pin.SE3(pin.rpy.rpyToMatrix(0.0, math.pi / 2, 0.0), np.array([0.1, 0.0, 0.76]))
    for tool in release_poses(target, grip, BAR):
        placed = tool * grip
        assert placed.translation == pytest.approx(target.translation)
        # The same footprint: the bar's long axis on the target's.
        assert abs(placed.rotation[:, 2] @ target.rotation[:, 2]) == pytest.approx(1.0)


def test_servo_arm_rolls_its_wrist_about_the_grasp_axis():
    ctx = context("servo_arm_table")
    model = ctx.scene.robot
    index, _ = wrist_roll(model, "arm", "tool0", ctx.scene.state)
    assert model.joint_names[index] == "Revolute 5"
    assert wrist_roll(model, "arm", "gripper_base_1", ctx.scene.state) is not None
    # The palm's base link is not on the roll axis' far end: no roll for the upper arm.
    assert wrist_roll(model, "arm", "arm_link_1", ctx.scene.state) is None


def test_short_arm_reaches_the_grasp_point_exactly_and_closes_across_its_plane():
    ctx = context("servo_arm_table")
    model = ctx.scene.robot
    cube = pin.SE3(np.eye(3), np.array([0.19, 0.0, 0.7625]))
    grasps = top_grasps(cube, Box((0.025, 0.025, 0.025)))
    found = approximate(model, "arm", "tool0", grasps, ctx.scene.state, seed=1, grasping=True)
    best = found[0]
    data = model.model.createData()
    pin.framesForwardKinematics(model.model, data, model.to_pin(best.q))
    tool = data.oMf[model.frame_id("tool0")]
    assert tool.translation == pytest.approx(grasps[best.wanted].translation, abs=1e-4)
    # The cube lies on the arm's own plane (y = 0): the fingers close along y, so a
    # pitch the arm cannot match turns the tool about the closing axis only.
    assert abs(tool.rotation[:, 1] @ np.array([0.0, 1.0, 0.0])) == pytest.approx(1.0, abs=1e-6)
    assert best.angle == pytest.approx(
        orientation_error(tool, grasps[best.wanted], grasping=True))
    assert [a.angle for a in found] == sorted(a.angle for a in found)
