"""Collision geometry: scene shapes and robot links as coal objects.

Scene objects are plain :mod:`taskrunner.shapes`; this module turns them into coal
geometry (meshes through coal's mesh loader). Robot link meshes can be replaced by their
convex hulls: GJK on a hull is several times faster than a BVH traversal, and the hull
gives a true signed distance when two bodies overlap (a BVH only reports 0 or a shallow
triangle depth). For a non-convex link mesh the hull is fatter: which links get hulls is
each robot's choice (:mod:`taskrunner.scene.linkgeometry`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path

import coal
import numpy as np
import pinocchio as pin

from taskrunner.errors import MissingMeshError, SceneError
from taskrunner.kinds import CollisionChoice
from taskrunner.robot import RobotModel
from taskrunner.scene.collision import Body
from taskrunner.scene.hullfit import convex_hull
from taskrunner.scene.linkgeometry import DEFAULT_HULL_TOLERANCE, HULL, link_hull, plan_link_geometry
from taskrunner.scene.objects import SceneObject
from taskrunner.shapes import Box, Cylinder, Mesh, Shape, Sphere
from taskrunner.textfile import file_problem, resolve_path

__all__ = [
    "LinkGeometry",
    "MeshCache",
    "convex_hull",
    "link_bodies",
    "object_geometry",
    "robot_link_geometry",
    "shape_geometry",
]


class MeshCache:
    """Loads mesh files once per (path, scale); the loaded geometry is shared, never edited."""

    def __init__(self) -> None:
        self._meshes: dict[tuple[Path, tuple[float, float, float]], coal.CollisionGeometry] = {}

    def load(self, mesh: Mesh) -> coal.CollisionGeometry:
        """The BVH of ``mesh`` (vertices scaled, in the mesh file's own frame, m).

        Raises:
            MissingMeshError: the file does not exist.
            SceneError: the file exists but coal cannot read it.
        """
        path = resolve_path(mesh.path.expanduser(), MissingMeshError)
        key = (path, mesh.scale)
        if key in self._meshes:
            return self._meshes[key]
        problem = file_problem(path)  # a FIFO or /proc file would hang or flood coal
        if problem == "file not found":
            raise MissingMeshError("mesh file of a scene object not found", path)
        if problem is not None:
            raise MissingMeshError(f"mesh file of a scene object: {problem}", path)
        try:
            geometry = coal.MeshLoader().load(str(path), np.array(mesh.scale, dtype=float))
        except Exception as exc:  # coal raises ValueError with assimp's text
            first_line = str(exc).strip().splitlines()[-1] if str(exc).strip() else repr(exc)
            raise SceneError(f"{path}: coal could not load the mesh ({first_line})") from None
        if geometry.num_tris == 0:
            raise SceneError(f"{path}: mesh has no triangles")
        self._meshes[key] = geometry
        return geometry


def shape_geometry(shape: Shape, meshes: MeshCache) -> coal.CollisionGeometry:
    """The coal geometry of a scene shape, centred on the object's frame.

    Raises:
        SceneError: ``shape`` is not a :data:`~taskrunner.shapes.Shape`, or a mesh is unreadable.
        MissingMeshError: a mesh file does not exist.
    """
    if isinstance(shape, Box):
        return coal.Box(*shape.size)
    if isinstance(shape, Sphere):
        return coal.Sphere(shape.radius)
    if isinstance(shape, Cylinder):
        return coal.Cylinder(shape.radius, shape.length)
    if isinstance(shape, Mesh):
        return meshes.load(shape)
    raise SceneError(
        f"'shape' must be a Box, Cylinder, Sphere or Mesh (got {type(shape).__name__})"
    )


@dataclass(frozen=True)
class LinkGeometry:
    """One collision body of a robot link.

    Attributes:
        link: the link's name.
        geometry: its pinocchio geometry object (placement relative to the parent joint).
    """

    link: str
    geometry: pin.GeometryObject


def robot_link_geometry(robot: RobotModel, collision: bool | str | Mapping[str, str] | None = None,
                        tolerance: float = DEFAULT_HULL_TOLERANCE) -> tuple[LinkGeometry, ...]:
    """Copies of the robot's collision geometry, each link's meshes as chosen by
    :func:`~taskrunner.scene.linkgeometry.plan_link_geometry`.

    Args:
        robot: the model; its own :attr:`~taskrunner.robot.RobotModel.collision_model`
            is left untouched.
        collision: exact, convex or auto for every robot (True means convex and False
            exact), or by instance name; None: each robot's own choice.
        tolerance: how far a hull may stand off its mesh under auto (m).
    """
    if isinstance(collision, bool):
        collision = CollisionChoice.CONVEX if collision else CollisionChoice.EXACT
    plan = plan_link_geometry(robot, collision, tolerance)
    out = []
    for index, source in enumerate(robot.collision_model.geometryObjects):
        link = robot.model.frames[source.parentFrame].name
        geometry = source.geometry
        if plan.kind(link) == HULL and isinstance(geometry, coal.BVHModelBase):
            geometry = link_hull(robot, index) or geometry
        copy = pin.GeometryObject(
            source.name, source.parentJoint, source.parentFrame, source.placement, geometry
        )
        out.append(LinkGeometry(link, copy))
    return tuple(out)


def link_bodies(robot: RobotModel, collision: bool | str | Mapping[str, str] | None = None,
                tolerance: float = DEFAULT_HULL_TOLERANCE) -> tuple[Body, ...]:
    """The robot's links with geometry as collision bodies (see :func:`robot_link_geometry`)."""
    grouped: dict[str, list[pin.GeometryObject]] = {}
    for link in robot_link_geometry(robot, collision, tolerance):
        grouped.setdefault(link.link, []).append(link.geometry)
    return tuple(Body(name, tuple(geometries)) for name, geometries in grouped.items())


def object_geometry(
    robot: RobotModel, obj: SceneObject, geometry: coal.CollisionGeometry
) -> pin.GeometryObject:
    """A scene object as a pinocchio geometry object: on the universe joint for a world
    object, on its link's joint (placement relative to that joint) when attached."""
    if obj.attached_to is None:
        return pin.GeometryObject(obj.name, 0, robot.frame_id("world"), obj.pose.se3, geometry)
    frame_id = robot.frame_id(obj.attached_to)
    frame = robot.model.frames[frame_id]
    placement = frame.placement * obj.pose.se3
    return pin.GeometryObject(obj.name, frame.parentJoint, frame_id, placement, geometry)
