"""The robots' collision geometry for the page, as the planner checks it.

The geometry comes from the collision core itself (:func:`taskrunner.scene.geometry.link_bodies`,
the bodies every :class:`~taskrunner.scene.Scene` of the cell is built from, with each
robot's choice of exact meshes, convex hulls or primitives), never from a second reading
of the URDF or the mesh files. Each shape is given in its link's frame, so the page hangs it
under the link it draws and it moves with the arm.
"""

from __future__ import annotations

from typing import Any

import coal
import numpy as np
import pinocchio as pin

from taskrunner.robot.cell import Cell
from taskrunner.scene.geometry import link_bodies
from taskrunner.scene.linkgeometry import plan_link_geometry

__all__ = ["MAX_TRIANGLES", "describe_collision"]

MAX_TRIANGLES = 200_000
"""Most triangles of exact meshes one answer carries; past them a mesh is sent as the
box that bounds it, and said so (``bounded: true``)."""

_DIGITS = 6  # µm: finer than any clearance the planner keeps


def _pose(placement: pin.SE3) -> dict[str, list[float]]:
    q = pin.Quaternion(placement.rotation)
    return {"xyz": [round(float(v), _DIGITS) for v in placement.translation],
            "quat": [round(float(v), _DIGITS) for v in (q.x, q.y, q.z, q.w)]}


def _flat(values: np.ndarray) -> list[float]:
    return [round(float(v), _DIGITS) for v in np.asarray(values, dtype=float).ravel()]


def _shape(geometry: coal.CollisionGeometry, budget: list[int]) -> dict[str, Any]:
    """A coal shape as JSON: box, sphere, cylinder and capsule (along z) by their sizes, a
    convex hull by its points, a triangle mesh by its vertices and triangles."""
    if isinstance(geometry, coal.Box):
        return {"type": "box", "size": _flat(2.0 * np.asarray(geometry.halfSide))}
    if isinstance(geometry, coal.Sphere):
        return {"type": "sphere", "radius": round(float(geometry.radius), _DIGITS)}
    if isinstance(geometry, coal.Cylinder):
        return {"type": "cylinder", "radius": round(float(geometry.radius), _DIGITS),
                "length": round(2.0 * float(geometry.halfLength), _DIGITS)}
    if isinstance(geometry, coal.Capsule):
        return {"type": "capsule", "radius": round(float(geometry.radius), _DIGITS),
                "length": round(2.0 * float(geometry.halfLength), _DIGITS)}
    if isinstance(geometry, coal.ConvexBase):
        return {"type": "hull", "points": _flat(np.asarray(geometry.points()))}
    if isinstance(geometry, coal.BVHModelBase):
        n = int(geometry.num_tris)
        if n <= budget[0]:
            budget[0] -= n
            triangles = [int(geometry.tri_indices(k)[i]) for k in range(n) for i in range(3)]
            return {"type": "mesh", "vertices": _flat(np.asarray(geometry.vertices())),
                    "triangles": triangles}
        geometry.computeLocalAABB()
        box = geometry.aabb_local
        low, high = np.asarray(box.min_), np.asarray(box.max_)
        return {"type": "box", "size": _flat(high - low), "centre": _flat((high + low) / 2),
                "bounded": True}
    return {"type": "unknown", "class": type(geometry).__name__}


def describe_collision(cell: Cell) -> dict[str, Any]:
    """The collision geometry of the cell's robots: ``links``, each with ``link`` (its
    name in the cell's merged URDF), ``kind`` (exact mesh, convex hull or primitive: the
    robot's choice) and ``shapes`` (``pose`` in the link's frame, m and xyzw, and the
    shape); links without collision geometry are absent."""
    model = cell.model
    plan = plan_link_geometry(model)
    budget = [MAX_TRIANGLES]
    links = []
    for body in link_bodies(model):
        shapes = []
        for geometry in body.geometries:
            frame = model.model.frames[geometry.parentFrame]
            in_link = frame.placement.inverse() * geometry.placement
            shapes.append({"pose": _pose(in_link), **_shape(geometry.geometry, budget)})
        links.append({"link": body.name, "kind": plan.kind(body.name), "shapes": shapes})
    return {"links": links}
