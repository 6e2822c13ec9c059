"""A planning scene holding a cell's robots and fixed objects."""

from __future__ import annotations

from taskrunner.robot.cell import Cell
from taskrunner.scene.scene import Scene, SceneOptions
from taskrunner.types import Pose

__all__ = ["scene_from_cell"]


def scene_from_cell(cell: Cell, options: SceneOptions | None = None) -> Scene:
    """A scene with the cell's model, its objects (each allowed to touch its
    ``touch_links``) and the robots at the cell's start state."""
    scene = Scene(cell.model, options)
    scene.set_state(cell.start_state())
    for obj in cell.objects:
        scene.add_object(obj.name, obj.shape, Pose.from_se3(obj.pose, obj.frame))
        for link in obj.touch_links:
            scene.allow_collision(obj.name, link, reason="cell")
    return scene
