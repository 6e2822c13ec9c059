"""Collision geometry: scene shapes and robot links as coal objects.

Scene objects are plain :mod:`taskrunner.shapes`; this module turns them into coal
geometry (meshes through coal's mesh loader). Robot link meshes can be replaced by their
convex hulls: GJK on a hull is several times faster than a BVH traversal, and the hull
gives a true signed distance when two bodies overlap (a BVH only reports 0 or a shallow
triangle depth). For a non-convex link mesh the hull is a conservative approximation.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import coal
import numpy as np
import pinocchio as pin
from scipy.spatial import ConvexHull, QhullError

from taskrunner.errors import MissingMeshError, SceneError
from taskrunner.robot import RobotModel
from taskrunner.scene.collision import Body
from taskrunner.scene.objects import SceneObject
from taskrunner.shapes import Box, Cylinder, Mesh, Shape, Sphere

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
        path = mesh.path.expanduser().resolve()
        key = (path, mesh.scale)
        if key in self._meshes:
            return self._meshes[key]
        if not path.is_file():
            raise MissingMeshError("mesh file of a scene object not found", path)
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


def convex_hull(mesh: coal.BVHModelBase) -> coal.Convex:
    """The convex hull of a triangle mesh's vertices, as a coal convex polytope.

    Built with scipy's Qhull because this coal wheel is compiled without it
    (``coal.WITH_QHULL`` is false, so ``buildConvexHull`` would keep every vertex).

    Raises:
        SceneError: the mesh is flat or degenerate (no 3-D hull).
    """
    vertices = np.array(mesh.vertices(), dtype=float)
    try:
        hull = ConvexHull(vertices)
    except (QhullError, ValueError) as exc:
        raise SceneError(f"mesh has no 3-D convex hull ({len(vertices)} vertices): {exc}") from None
    renumber = {int(v): i for i, v in enumerate(hull.vertices)}
    points = coal.StdVec_Vec3s()
    for v in hull.vertices:
        points.append(vertices[v])
    triangles = coal.StdVec_Triangle()
    for a, b, c in hull.simplices:
        triangles.append(coal.Triangle(renumber[int(a)], renumber[int(b)], renumber[int(c)]))
    return coal.Convex(points, triangles)


@dataclass(frozen=True)
class LinkGeometry:
    """One collision body of a robot link.

    Attributes:
        link: the link's name.
        geometry: its pinocchio geometry object (placement relative to the parent joint).
    """

    link: str
    geometry: pin.GeometryObject


def robot_link_geometry(robot: RobotModel, convex_meshes: bool) -> tuple[LinkGeometry, ...]:
    """Copies of the robot's collision geometry, meshes optionally replaced by hulls.

    The robot's own :attr:`~taskrunner.robot.RobotModel.collision_model` is left untouched.
    A degenerate mesh (a flat plate) keeps its BVH.
    """
    out = []
    for source in robot.collision_model.geometryObjects:
        geometry = source.geometry
        if convex_meshes and isinstance(geometry, coal.BVHModelBase):
            try:
                geometry = convex_hull(geometry)
            except SceneError:
                geometry = source.geometry
        copy = pin.GeometryObject(
            source.name, source.parentJoint, source.parentFrame, source.placement, geometry
        )
        out.append(LinkGeometry(robot.model.frames[source.parentFrame].name, copy))
    return tuple(out)


def link_bodies(robot: RobotModel, convex_meshes: bool) -> tuple[Body, ...]:
    """The robot's links with geometry as collision bodies (see :func:`robot_link_geometry`)."""
    grouped: dict[str, list[pin.GeometryObject]] = {}
    for link in robot_link_geometry(robot, convex_meshes):
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
