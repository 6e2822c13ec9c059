"""Plain-data descriptions of scene objects and of a whole scene.

These hold no collision-library types, so they pickle and travel to a planner
worker process, which rebuilds the scene with :meth:`taskrunner.scene.Scene.from_snapshot`.
"""

from __future__ import annotations

from dataclasses import dataclass

from taskrunner.errors import ArgumentError
from taskrunner.shapes import Shape
from taskrunner.types import JointState, Pose

__all__ = ["SceneObject", "SceneSnapshot"]


@dataclass(frozen=True)
class SceneObject:
    """An object of the scene.

    Attributes:
        name: unique among objects and robot links.
        shape: its geometry, centred on the object's frame.
        pose: the object's frame; in the world frame for a world object, in the frame of
            link ``attached_to`` for an attached one.
        attached_to: the link carrying it, or None for an object fixed in the world.
        touch_links: links besides ``attached_to`` it may touch while attached (fingers).
    """

    name: str
    shape: Shape
    pose: Pose
    attached_to: str | None = None
    touch_links: tuple[str, ...] = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "touch_links", tuple(self.touch_links))
        expected = self.attached_to or "world"
        if self.pose.frame != expected:
            raise ArgumentError(f"'pose.frame' must be {expected!r} (got {self.pose.frame!r})")
        if self.attached_to is None and self.touch_links:
            raise ArgumentError(
                f"'touch_links' must be empty for a world object (got {self.touch_links})"
            )

    @property
    def attached(self) -> bool:
        return self.attached_to is not None


@dataclass(frozen=True)
class SceneSnapshot:
    """Everything needed to rebuild a scene on the same robot model.

    Attributes:
        robot: the model's name, checked when the snapshot is restored.
        state: the robot state (every joint of the model).
        objects: world and attached objects, in the order they were added.
        allowed: body pairs the scene allows to touch on top of the robot's SRDF
            (attachment allowances are implied by ``objects`` and not repeated here).
    """

    robot: str
    state: JointState
    objects: tuple[SceneObject, ...] = ()
    allowed: tuple[tuple[str, str], ...] = ()

    def __post_init__(self) -> None:
        object.__setattr__(self, "objects", tuple(self.objects))
        object.__setattr__(
            self, "allowed", tuple(tuple(sorted(pair)) for pair in self.allowed)  # type: ignore[misc]
        )
