"""A cell's scene holds its objects, allows their touch links and starts at the start poses."""

from __future__ import annotations

import numpy as np
import pytest

from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.scene import scene_from_cell


@pytest.fixture(scope="module")
def servo_scene(repo_root):
    return scene_from_cell(load_cell(DATA_ROOT / "robots" / "cells" / "servo_arm_table.yaml"))


def test_cell_scene_has_the_objects_and_the_start_state(servo_scene):
    assert set(servo_scene.object_names) == {"table", "tray"}
    assert servo_scene.state[:5] == pytest.approx([0.8, -0.8, -1.2, -0.8, -2.6])
    assert not servo_scene.in_collision()


def test_cell_scene_allows_the_base_on_the_table_but_not_the_gripper(servo_scene):
    assert servo_scene.collision_allowed("table", "base_link")
    assert not servo_scene.collision_allowed("table", "gripper_base_1")
    # Folding the arm down into the table top is a collision with the table.
    q = servo_scene.state.copy()
    q[1] = -0.2  # shoulder leaned far forward
    q[2] = -0.3
    pairs = {frozenset((c.a, c.b)) for c in servo_scene.collisions(q)}
    assert any("table" in pair for pair in pairs)


@pytest.mark.parametrize("cell", ["servo_arm_pair", "panda_table", "panda_pair"])
def test_every_shipped_cell_starts_collision_free(repo_root, cell):
    scene = scene_from_cell(load_cell(DATA_ROOT / "robots" / "cells" / f"{cell}.yaml"))
    assert not scene.in_collision()
    assert np.isfinite(scene.min_distance().distance)
