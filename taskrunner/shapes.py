"""Geometric shapes of scene objects, as plain data (no collision library types).

Sizes are full lengths in metres (a box 0.1 wide is ``Box((0.1, …))``), centred on the
object's frame; a cylinder's axis is its local z, as in URDF.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from taskrunner.errors import ArgumentError

__all__ = ["Box", "Cylinder", "Mesh", "Shape", "Sphere"]


def _positive(name: str, value: float) -> float:
    value = float(value)
    if not value > 0.0:
        raise ArgumentError(f"'{name}' must be > 0 (got {value})")
    return value


@dataclass(frozen=True)
class Box:
    """An axis-aligned box; ``size`` is (x, y, z) full lengths in m."""

    size: tuple[float, float, float]

    def __post_init__(self) -> None:
        size = tuple(self.size)
        if len(size) != 3:
            raise ArgumentError(f"'size' must have 3 values x, y, z (got {len(size)})")
        object.__setattr__(self, "size", tuple(_positive("size", v) for v in size))


@dataclass(frozen=True)
class Cylinder:
    """A cylinder along local z: ``radius`` and full ``length`` in m."""

    radius: float
    length: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius", _positive("radius", self.radius))
        object.__setattr__(self, "length", _positive("length", self.length))


@dataclass(frozen=True)
class Sphere:
    """A sphere of ``radius`` m."""

    radius: float

    def __post_init__(self) -> None:
        object.__setattr__(self, "radius", _positive("radius", self.radius))


@dataclass(frozen=True)
class Mesh:
    """A triangle mesh file (STL, OBJ, DAE …) scaled per axis."""

    path: Path
    scale: tuple[float, float, float] = (1.0, 1.0, 1.0)

    def __post_init__(self) -> None:
        object.__setattr__(self, "path", Path(self.path))
        scale = tuple(self.scale)
        if len(scale) != 3:
            raise ArgumentError(f"'scale' must have 3 values (got {len(scale)})")
        object.__setattr__(self, "scale", tuple(_positive("scale", v) for v in scale))


Shape = Box | Cylinder | Sphere | Mesh
