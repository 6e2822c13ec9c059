"""The allowed-collision matrix: which pairs of bodies may touch, and why.

Bodies are robot links and scene objects, by name. Three sources allow a pair, in this
order of precedence (a later one names the reason when two agree):

1. the robot's SRDF ``disable_collisions`` entries (with the model's automatic
   "Adjacent" pairs), fixed for the model;
2. attachments: an attached object may touch its link and its ``touch_links``
   (reason ``"attached"``), for as long as it stays attached;
3. the scene's own allowances (a cube resting on a table), which the caller adds and
   withdraws.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping

from taskrunner.errors import SceneError
from taskrunner.scene.objects import SceneObject

__all__ = ["AllowedCollisions"]

ATTACHED = "attached"


class AllowedCollisions:
    """See the module docstring. Names are not checked here; the scene checks them.

    Args:
        robot_pairs: the model's allowed link pairs and reasons (``disabled_collisions``).
    """

    def __init__(self, robot_pairs: Mapping[frozenset[str], str]) -> None:
        self._robot = dict(robot_pairs)
        self._scene: dict[frozenset[str], str] = {}

    def copy(self) -> AllowedCollisions:
        other = AllowedCollisions.__new__(AllowedCollisions)
        other._robot = self._robot
        other._scene = dict(self._scene)
        return other

    @property
    def scene_pairs(self) -> tuple[tuple[str, str], ...]:
        """The scene's own allowances, each pair sorted, in the order they were made."""
        return tuple((min(pair), max(pair)) for pair in self._scene)

    def allow(self, a: str, b: str, reason: str = "scene") -> None:
        """Allow ``a`` and ``b`` to touch."""
        if a == b:
            raise SceneError(f"a body cannot be allowed to touch itself (got {a!r} twice)")
        self._scene[frozenset((a, b))] = reason

    def withdraw(self, a: str, b: str, attached: Iterable[SceneObject]) -> bool:
        """Withdraw the scene's allowance of ``a``–``b``; False if there was none.

        Raises:
            SceneError: the pair is allowed by the SRDF or an attachment instead.
        """
        pair = frozenset((a, b))
        if self._scene.pop(pair, None) is not None:
            return True
        reason = self.pairs(attached).get(pair)
        if reason is not None:
            raise SceneError(
                f"collision between {a!r} and {b!r} is allowed by {reason!r}, not by the scene"
            )
        return False

    def forget(self, body: str) -> None:
        """Drop the scene's allowances naming ``body`` (a removed object)."""
        self._scene = {pair: r for pair, r in self._scene.items() if body not in pair}

    def pairs(self, attached: Iterable[SceneObject]) -> dict[frozenset[str], str]:
        """Every allowed pair and its reason, given the attached objects."""
        out = dict(self._robot)
        for obj in attached:
            if obj.attached_to is not None:
                for link in (obj.attached_to, *obj.touch_links):
                    out[frozenset((obj.name, link))] = ATTACHED
        out.update(self._scene)
        return out
