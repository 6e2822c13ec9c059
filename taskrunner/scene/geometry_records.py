"""The path verifier's view of a robot (:mod:`taskrunner.scene.path_verifier`): its
kinematic tree, kept per robot model, with the packed record of each geometry object
(lever arms, bounding sphere and box, exact core shape: :data:`GEOMETRY`), kept for the
robot's own links and for primitive shapes so that a new scene revision builds only what
changed; and the compiled forward kinematics of one verifier's geometry.
"""

from __future__ import annotations

import math
import weakref
from dataclasses import dataclass

import coal
import numpy as np
import pinocchio as pin

from taskrunner.collision.frames import ORIGIN, ROTATION
from taskrunner.collision.geometry import GEOMETRY
from taskrunner.collision.tree import KinematicTree
from taskrunner.robot import RobotModel
from taskrunner.scene.distance_bounds import (
    _FR_COLUMNS,
    _SHAPE_BOX,
    _SHAPE_CYLINDER,
    _SHAPE_HULL,
    _SHAPE_NONE,
    _SHAPE_SPHERE,
    _farthest_point_centre,
    _forward,
)
from taskrunner.scene.mesh_pieces import mesh_pieces


@dataclass(frozen=True)
class _Record:
    """One geometry object's rows of the packed arrays, and its lever arms."""

    name: str
    levers: np.ndarray
    geometry: np.ndarray  # a GEOMETRY record (0-d); its points' place is the verifier's
    points: np.ndarray | None = None
    pieces: tuple[np.ndarray, ...] = ()  # a mesh's convex pieces' points (its own frame)


class _Tree(KinematicTree):
    """The robot's kinematic tree (:class:`~taskrunner.collision.tree.KinematicTree`: the
    compiled forward kinematics covers revolute, continuous and prismatic joints; anything
    else leaves ``supported`` False), and the records of its links' geometry objects,
    kept across scene revisions."""

    def __init__(self, robot: RobotModel) -> None:
        super().__init__(robot)
        # By (kind, joint, placement, dimensions) for primitives, (object id, joint,
        # placement) for a link's other geometry.
        self._records: dict[tuple[object, ...], tuple[object, _Record]] = {}

    def record(self, geometry_object: pin.GeometryObject) -> _Record:
        """The packed rows of a geometry object. Kept for a robot link's geometry (the
        robot's own, never edited: the same object, joint and placement give the same
        rows) and for a primitive shape (box, sphere, cylinder, capsule, cone: keyed by its
        kind, dimensions, joint and placement, not by the coal object, which each scene
        revision makes anew), so that a scene edit only builds the rows of what it
        changed."""
        name = geometry_object.name
        geometry = geometry_object.geometry
        joint = int(geometry_object.parentJoint)
        shape = _shape_key(geometry)
        placement = np.asarray(geometry_object.placement.homogeneous).tobytes()
        key: tuple[object, ...]
        if shape is not None:
            # A primitive's rows follow from its kind, dimensions, joint and placement: the
            # same for the new coal object a scene revision makes of an unchanged body.
            key = (type(geometry).__name__, joint, placement, shape)
        elif joint > 0 and name.rpartition("/")[0] in self.links:
            key = (id(geometry), joint, placement)
        else:
            return self._build_record(geometry_object)
        kept = self._records.get(key)
        if kept is not None:
            record = kept[1]
            return record if record.name == name else _Record(name, record.levers, record.geometry,
                                                              record.points, record.pieces)
        record = self._build_record(geometry_object)
        if len(self._records) > 4096:
            self._records.clear()
        self._records[key] = (geometry, record)   # the geometry kept: its id stays its own
        return record

    def _build_record(self, geometry_object: pin.GeometryObject) -> _Record:
        geometry = geometry_object.geometry
        levers = self.levers(geometry_object)          # computes the local AABB
        row = np.zeros((), dtype=GEOMETRY)
        row["placement"][:9] = np.asarray(geometry_object.placement.rotation).reshape(9)
        row["placement"][9:] = geometry_object.placement.translation
        centre, radius = _enclosing_sphere(geometry)
        row["centre"] = centre
        row["radius"] = radius
        # The geometry's bounding box in its own frame (a box geometry: itself).
        low = np.asarray(geometry.aabb_local.min_, dtype=float)
        high = np.asarray(geometry.aabb_local.max_, dtype=float)
        has_box = bool(np.isfinite(low).all() and np.isfinite(high).all())
        if has_box:
            row["half"] = 0.5 * (high - low)
            row["box"] = 0.5 * (high + low)
        # Shapes whose support function the kernels evaluate exactly (or of a shape that
        # contains them): a box, a cylinder (about z) or a sphere from its bounding box,
        # centred on it; a convex hull from its vertices; each grown by its swept sphere
        # radius.
        shape, points = _SHAPE_NONE, None
        pieces: tuple[np.ndarray, ...] = ()
        swept = float(geometry.getSweptSphereRadius()) \
            if hasattr(geometry, "getSweptSphereRadius") else 0.0
        kind = type(geometry)
        half = row["half"]
        if not has_box or np.any(row["box"] != 0.0):
            pass
        elif kind is coal.Box:
            shape = _SHAPE_BOX
        elif kind is coal.Cylinder and half[0] == half[1]:
            shape = _SHAPE_CYLINDER
        elif kind is coal.Sphere:
            shape = _SHAPE_SPHERE
            swept += float(half.max())
        if isinstance(geometry, coal.ConvexBase):
            vertices = np.asarray(geometry.points(), dtype=float)
            if vertices.ndim == 2 and vertices.shape[1] == 3 and len(vertices) \
                    and np.isfinite(vertices).all():
                shape, points = _SHAPE_HULL, np.ascontiguousarray(vertices)
        elif isinstance(geometry, coal.BVHModelBase) and swept == 0.0 \
                and 0 < geometry.num_vertices <= _MESH_VERTICES:
            # A mesh (checked as its triangles) lies in the convex hull of its vertices,
            # and a point set's support function is its hull's: the hull's separation from
            # another shape is a lower bound on the mesh's distance to it.
            hull = _hull_vertices(np.asarray(geometry.vertices(), dtype=float))
            if hull is not None and len(hull) <= _MESH_HULL_POINTS:
                shape, points = _SHAPE_HULL, hull
                # Its convex pieces hold it more closely than that hull where it is concave.
                cut = mesh_pieces(geometry)
                if len(cut) > 1 and sum(len(p) for p in cut) <= _MESH_HULL_POINTS:
                    pieces = cut
        row["swept"] = swept if math.isfinite(swept) and swept >= 0.0 else 0.0
        if not (math.isfinite(swept) and swept >= 0.0):
            shape, pieces = _SHAPE_NONE, ()
        row["joint"] = int(geometry_object.parentJoint)
        row["has_box"] = int(has_box)
        row["shape"] = shape
        return _Record(geometry_object.name, levers, row, points, pieces)


def _shape_key(geometry: coal.CollisionGeometry) -> tuple[float, ...] | None:
    """A primitive shape's dimensions (None for anything else)."""
    kind = type(geometry)
    if kind not in (coal.Box, coal.Sphere, coal.Cylinder, coal.Capsule, coal.Cone):
        return None
    swept = float(geometry.getSweptSphereRadius()) \
        if hasattr(geometry, "getSweptSphereRadius") else 0.0
    if swept != 0.0:
        return None  # inflated: built each time (rare)
    if kind is coal.Box:
        return tuple(float(v) for v in geometry.halfSide)
    if kind is coal.Sphere:
        return (float(geometry.radius),)
    if kind is coal.Cylinder or kind is coal.Capsule or kind is coal.Cone:
        return (float(geometry.radius), float(geometry.halfLength))
    return None


# A mesh whose vertices' hull has more vertices than this is left to coal: the kernels'
# support function visits every vertex (a scanned part of 100k triangles: coal's BVH).
_MESH_HULL_POINTS = 1024
# Nor is the hull of a mesh of more vertices than this computed (a scene object's rows are
# built at each scene revision; a link's once per robot).
_MESH_VERTICES = 50_000


def _hull_vertices(vertices: np.ndarray) -> np.ndarray | None:
    """The vertices of the convex hull of ``vertices`` (``(n, 3)``; all of them where the
    hull is flat or degenerate: the same support function), or None for no finite point."""
    if vertices.ndim != 2 or vertices.shape[1] != 3 or not len(vertices) \
            or not np.isfinite(vertices).all():
        return None
    from scipy.spatial import ConvexHull, QhullError  # only where a mesh is verified

    try:
        kept = vertices[ConvexHull(vertices).vertices]
    except (QhullError, ValueError):  # flat, or fewer than 4 points: all of them serve
        kept = vertices
    return np.ascontiguousarray(kept)


# Per robot model (by identity; the model is not hashable): a weak reference and its tree.
_TREES: dict[int, tuple[weakref.ref, _Tree]] = {}


def _tree(robot: RobotModel) -> _Tree:
    """The robot's :class:`_Tree`, built once per robot model."""
    kept = _TREES.get(id(robot))
    if kept is not None and kept[0]() is robot and kept[1].model is robot.model \
            and kept[1].nq == robot.nq:
        return kept[1]
    tree = _Tree(robot)
    key = id(robot)

    def forget(reference: weakref.ref) -> None:
        if key in _TREES and _TREES[key][0] is reference:
            del _TREES[key]

    _TREES[key] = (weakref.ref(robot, forget), tree)
    return tree


class _Kinematics:
    """Forward kinematics of one verifier's geometry (compiled)."""

    def __init__(self, tree: _Tree, geometries: np.ndarray) -> None:
        self.joints = tree.joints
        self.geometries = geometries
        self.supported = tree.supported

    def buffer(self) -> np.ndarray:
        """Work array of the kernels' frames (see ``_FR_*``)."""
        return np.zeros((self.joints.shape[0] + self.geometries.shape[0], _FR_COLUMNS))

    def frames(self, q: np.ndarray) -> np.ndarray:
        """The frames at state ``q`` (see :meth:`poses`)."""
        frames = self.buffer()
        _forward(np.ascontiguousarray(q, dtype=float), self.joints, self.geometries, frames)
        return frames

    def poses(self, q: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """World rotations and origins of the joints, then of the geometries, at ``q``."""
        frames = self.frames(q)
        n = self.joints.shape[0]
        return (frames[:n, ROTATION:ROTATION + 9].reshape(n, 3, 3),
                frames[:n, ORIGIN:ORIGIN + 3],
                frames[n:, ROTATION:ROTATION + 9].reshape(-1, 3, 3),
                frames[n:, ORIGIN:ORIGIN + 3])


def _enclosing_sphere(geometry: coal.CollisionGeometry) -> tuple[np.ndarray, float]:
    """A sphere containing ``geometry`` (its frame): for a convex hull or a mesh, one
    around its vertices (Badoiu-Clarkson centre, radius to the farthest vertex), which
    contains their convex hull; otherwise the sphere around its bounding box."""
    centre = np.array(geometry.aabb_center, dtype=float)
    radius = float(geometry.aabb_radius)
    points = None
    if isinstance(geometry, coal.Convex):
        points = np.asarray(geometry.points(), dtype=float)
    elif isinstance(geometry, coal.BVHModelBase) and geometry.num_vertices > 0:
        points = np.asarray(geometry.vertices(), dtype=float)
    if points is None or points.ndim != 2 or len(points) == 0 or not np.isfinite(points).all():
        return centre, radius
    candidate = np.ascontiguousarray(centre)
    reach = _farthest_point_centre(np.ascontiguousarray(points), candidate, 100)
    reach = reach * (1.0 + 1e-12) + 1e-12          # rounding: never inside a vertex
    if reach < radius:
        return candidate, reach
    return centre, radius
