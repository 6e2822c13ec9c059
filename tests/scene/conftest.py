"""Fixtures of the scene tests: the Panda's ready pose and a table-and-shelf cell."""

from __future__ import annotations

from collections.abc import Callable

import numpy as np
import pytest

from taskrunner.robot import RobotModel
from taskrunner.scene import Scene
from taskrunner.shapes import Box
from taskrunner.types import Pose

# The table the Panda stands on (its base bolted to it) and a shelf in front of it.
TABLE_AND_SHELF = [
    ("table", (1.2, 1.2, 0.04), (0.3, 0.0, -0.02)),
    ("shelf_left", (0.3, 0.02, 0.6), (0.75, -0.3, 0.3)),
    ("shelf_right", (0.3, 0.02, 0.6), (0.75, 0.3, 0.3)),
    ("shelf_board", (0.3, 0.6, 0.02), (0.75, 0.0, 0.3)),
    ("shelf_top", (0.3, 0.62, 0.02), (0.75, 0.0, 0.61)),
]

ArmState = Callable[..., np.ndarray]


@pytest.fixture
def ready(panda_model: RobotModel) -> np.ndarray:
    """The Panda's ``default`` named pose (arm bent over, hand pointing down)."""
    return panda_model.state_with(
        panda_model.default_state(), panda_model.named_state("arm_and_hand", "default")
    )


@pytest.fixture
def arm(panda_model: RobotModel, ready: np.ndarray) -> ArmState:
    """``arm(joint2=1.6, joint4=-0.5)``: the ready pose with some ``panda_jointN`` changed."""

    def state(**joints: float) -> np.ndarray:
        return panda_model.state_with(ready, {f"panda_{n}": v for n, v in joints.items()})

    return state


@pytest.fixture
def empty_scene(panda_model: RobotModel, ready: np.ndarray) -> Scene:
    scene = Scene(panda_model)
    scene.set_state(ready)
    return scene


@pytest.fixture
def cell(empty_scene: Scene) -> Scene:
    """The Panda on a table with a shelf in front of it."""
    for name, size, xyz in TABLE_AND_SHELF:
        empty_scene.add_object(name, Box(size), Pose(xyz))
    empty_scene.allow_collision("panda_link0", "table")
    return empty_scene
