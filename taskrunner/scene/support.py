"""What an object rests on: the gap below it, found by lowering it until it touches.

An object put down must rest on something: a world object's top surface (a table) or
another object (the cube below it in a stack). :func:`gap_below` answers how far the
object could be lowered straight down before it touches another body, by conservative
advancement: the object moves down by its distance to that body (coal's signed
distance), which can never pass through it, until the distance is below
:data:`CONTACT` or the object has gone :data:`SEARCH_DEPTH` down. A body beside the
object (a wall, the next cube) is never reached by lowering, so it does not count.
"""

from __future__ import annotations

import math
from collections.abc import Iterable
from dataclasses import dataclass

import coal
import numpy as np
import pinocchio as pin

__all__ = ["CONTACT", "SEARCH_DEPTH", "Support", "gap_below"]

CONTACT = 1e-5
"""Distance (m) at which two bodies count as touching."""
SEARCH_DEPTH = 1.0
"""How far down (m) a support is looked for."""
_MAX_STEPS = 200


@dataclass(frozen=True)
class Support:
    """The nearest body below an object.

    Attributes:
        gap: how far the object can be lowered before it touches ``below`` (m; 0 when it
            touches or overlaps it already; ``inf`` when nothing is below).
        below: the name of that body, or None when nothing is within
            :data:`SEARCH_DEPTH` below.
    """

    gap: float
    below: str | None


def _drop(geometry: coal.CollisionGeometry, placed: pin.SE3, other: coal.CollisionGeometry,
          at: pin.SE3) -> float:
    """How far ``geometry`` at ``placed`` moves down before touching ``other`` at ``at``
    (m; inf beyond :data:`SEARCH_DEPTH`)."""
    request = coal.DistanceRequest()
    there = coal.Transform3s(at.rotation, at.translation)
    down = 0.0
    for _ in range(_MAX_STEPS):
        moved = placed.translation - np.array([0.0, 0.0, down])
        result = coal.DistanceResult()
        distance = coal.distance(geometry, coal.Transform3s(placed.rotation, moved), other,
                                 there, request, result)
        if distance <= CONTACT:
            return down
        down += distance
        if down > SEARCH_DEPTH:
            break
    return math.inf


def gap_below(geometry: coal.CollisionGeometry, placed: pin.SE3,
              others: Iterable[tuple[str, coal.CollisionGeometry, pin.SE3]]) -> Support:
    """The nearest body below an object of ``geometry`` at world pose ``placed``.

    Args:
        others: the bodies it may rest on: ``(name, geometry, world pose)``.
    """
    best = Support(math.inf, None)
    for name, other, at in others:
        gap = _drop(geometry, placed, other, at)
        if gap < best.gap:
            best = Support(gap, name)
    return best
