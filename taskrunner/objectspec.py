"""The scene object as files write it, defined once: a name, a shape with its sizes, a
placement, the links that may touch it, and what a physics backend needs.

:class:`ObjectFields` holds the fields and their checks; a task file's
:class:`~taskrunner.tasks.nodes.ObjectSpec` (with its line, a mesh path relative to the
task file) and a cell file's :class:`~taskrunner.robot.cell.ObjectSpec` derive from it.
Units: m, kg, kg/m³.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import BaseModel, Field, model_validator

from taskrunner.materials import Density, Friction, Kilograms, check_material
from taskrunner.posespec import PoseFields
from taskrunner.validation import PositiveMetres, Scale

__all__ = ["SHAPE_FIELDS", "ObjectFields", "Scales", "Shape", "Size"]

Shape = Literal["box", "cylinder", "sphere", "mesh"]
Size = Annotated[tuple[PositiveMetres, ...], Field(min_length=3, max_length=3)]
Scales = Annotated[tuple[Scale, ...], Field(min_length=3, max_length=3)]
SHAPE_FIELDS: dict[str, tuple[str, ...]] = {
    "box": ("size",), "cylinder": ("radius", "length"), "sphere": ("radius",),
    "mesh": ("file", "scale"),
}
"""The fields each shape takes (the others are refused)."""


class ObjectFields(BaseModel):
    """A scene object: its shape, sizes, placement and physics."""

    name: str = Field(min_length=1)
    """Unique name of the object."""
    shape: Shape
    """box (size), cylinder (radius, length along z), sphere (radius) or mesh (file, scale)."""
    size: Size | None = None
    """Full lengths of a box along x, y, z (m)."""
    radius: PositiveMetres | None = None
    """Radius of a cylinder or sphere (m)."""
    length: PositiveMetres | None = None
    """Length of a cylinder along its z axis (m)."""
    file: str | None = None
    """Mesh file: a package:// URI or a path relative to the task file."""
    scale: Scales | None = None
    """Scale of a mesh along x, y, z (default 1, 1, 1)."""
    pose: PoseFields = PoseFields()
    """Placement of the object's centre (mesh origin)."""
    touch_links: tuple[str, ...] = ()
    """Links allowed to touch the object."""
    mass: Kilograms | None = None
    """Mass (kg), for the mujoco backend (others ignore it); default from 'density'."""
    density: Density | None = None
    """Density (kg/m³), for the mujoco backend when 'mass' is not given (default 600)."""
    friction: Friction | None = None
    """Friction for the mujoco backend: sliding, or [sliding, torsional, rolling] (default 1)."""

    @model_validator(mode="after")
    def _fields_match_shape(self) -> ObjectFields:
        needs = {"box": ("size",), "cylinder": ("radius", "length"), "sphere": ("radius",),
                 "mesh": ("file",)}[self.shape]
        missing = [f for f in needs if getattr(self, f) is None]
        if missing:
            raise ValueError(f"needs {' and '.join(repr(m) for m in missing)} for a {self.shape}")
        foreign = [f for fields in SHAPE_FIELDS.values() for f in fields
                   if f not in SHAPE_FIELDS[self.shape] and getattr(self, f) is not None]
        if foreign:
            raise ValueError(f"has {', '.join(repr(f) for f in dict.fromkeys(foreign))}, "
                             f"which a {self.shape} does not take")
        if self.size is not None and min(self.size) <= 0:
            raise ValueError(f"'size' must be > 0 in every axis (got {list(self.size)})")
        check_material(self)
        return self
