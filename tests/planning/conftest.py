"""Scenes shared by the planning tests."""

from __future__ import annotations

import pytest
from plan_helpers import READY, SHELF

from taskrunner.robot.cell import load_cell
from taskrunner.scene import Scene, scene_from_cell
from taskrunner.shapes import Box
from taskrunner.types import Pose


@pytest.fixture
def shelf_scene(panda_model) -> Scene:
    """The Panda at 'ready' with a table and a shelf in front of it."""
    scene = Scene(panda_model)
    for name, size, xyz in SHELF:
        scene.add_object(name, Box(size), Pose(xyz))
    scene.allow_collision("panda_link0", "table")
    scene.set_state(READY)
    return scene


@pytest.fixture(scope="session")
def servo_pair_cell(robots_dir):
    return load_cell(robots_dir / "cells" / "servo_arm_pair.yaml")


@pytest.fixture
def servo_pair_scene(servo_pair_cell) -> Scene:
    return scene_from_cell(servo_pair_cell)
