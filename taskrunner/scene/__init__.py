"""The planning scene: world and attached objects, allowed collisions, collision checks.

The self-collision matrix generator (MoveIt Setup Assistant style) is a tool module of
its own: :mod:`taskrunner.scene.acm` (``python -m taskrunner.scene.acm ROBOT``).
"""

from __future__ import annotations

from taskrunner.scene.collision import Clearance, Contact
from taskrunner.scene.from_cell import scene_from_cell
from taskrunner.scene.objects import SceneObject, SceneSnapshot
from taskrunner.scene.scene import Scene, SceneOptions

__all__ = [
    "Clearance",
    "Contact",
    "Scene",
    "SceneObject",
    "SceneOptions",
    "SceneSnapshot",
    "scene_from_cell",
]
