"""A robot's sphere model: the conservative spheres of every collision geometry of every
link (:mod:`taskrunner.collision.spheres`), placed on the joint that carries them, as
records a compiled broad phase reads (:data:`SPHERE`).

By default the spheres cover the URDF's collision geometry as loaded into
``RobotModel.collision_model`` (meshes as surfaces, primitives as solids). Where the scene
checks a link as its convex hull (``collision: auto`` or ``convex``), pass the geometry it
checks (``shapes``): a hull contains its mesh, so spheres around the mesh do not contain
the hull, and a broad phase must cover what the exact check tests.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import coal
import numpy as np
import pinocchio as pin

from taskrunner.collision.spheres import GeometrySpheres, SphereOptions, fit_spheres
from taskrunner.errors import ArgumentError
from taskrunner.robot import RobotModel

__all__ = ["SPHERE", "RobotSpheres", "robot_spheres"]

SPHERE = np.dtype([
    ("joint", np.int64),             # the joint carrying it (pinocchio's index; 0: the world)
    ("geometry", np.int64),          # its geometry object in the robot's collision model
    ("centre", np.float64, (3,)),    # in the joint's frame (m)
    ("radius", np.float64),          # m
])
"""One sphere of a robot's sphere model."""


@dataclass(frozen=True)
class RobotSpheres:
    """Every collision geometry's spheres, by geometry object.

    Attributes:
        spheres: :data:`SPHERE` records, grouped by geometry in the collision model's order.
        fits: each geometry object's fit (in its own frame), in that order.
        links: each geometry object's link name, in that order.
    """

    spheres: np.ndarray
    fits: tuple[GeometrySpheres, ...]
    links: tuple[str, ...]

    def by_link(self) -> Mapping[str, tuple[int, float]]:
        """Per link: its sphere count and its largest looseness (m)."""
        out: dict[str, tuple[int, float]] = {}
        for link, fit in zip(self.links, self.fits, strict=True):
            count, loose = out.get(link, (0, 0.0))
            out[link] = (count + len(fit), max(loose, fit.looseness))
        return out

    def world_spheres(self, robot: RobotModel, q: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Sphere centres in the world (n, 3) and radii at the configuration ``q`` (the
        robot's full state, as ``RobotModel.to_pin`` takes it)."""
        data = robot.model.createData()
        pin.forwardKinematics(robot.model, data, robot.to_pin(q))
        centres = np.empty((len(self.spheres), 3))
        for joint in np.unique(self.spheres["joint"]):
            rows = self.spheres["joint"] == joint
            placement = data.oMi[int(joint)]
            centres[rows] = self.spheres["centre"][rows] @ placement.rotation.T + placement.translation
        return centres, self.spheres["radius"].copy()


def robot_spheres(robot: RobotModel, options: SphereOptions | None = None,
                  shapes: Sequence[coal.CollisionGeometry] | None = None) -> RobotSpheres:
    """The sphere model of every collision geometry of ``robot`` (fits cached by content).

    Args:
        robot: the model.
        options: how finely to cover (default :class:`SphereOptions`).
        shapes: the geometry each of the collision model's objects is checked with, in its
            order (a link's hull where the scene uses it); default: the objects' own.

    Raises:
        ArgumentError: ``shapes`` is not one per geometry object.
        SceneError: a geometry with no sphere model (a cone, plane, half-space, ellipsoid).
    """
    objects = robot.collision_model.geometryObjects
    if shapes is not None and len(shapes) != len(objects):
        raise ArgumentError(f"'shapes' must hold one geometry per collision object "
                            f"({len(objects)}) (got {len(shapes)})")
    rows = []
    fits, links = [], []
    frames = robot.model.frames
    for index, g in enumerate(objects):
        fit = fit_spheres(g.geometry if shapes is None else shapes[index], options)
        placement: pin.SE3 = g.placement
        centres = fit.centres @ placement.rotation.T + placement.translation
        for c, r in zip(centres, fit.radii, strict=True):
            rows.append((int(g.parentJoint), index, c, float(r)))
        fits.append(fit)
        links.append(frames[g.parentFrame].name)
    return RobotSpheres(np.array(rows, dtype=SPHERE), tuple(fits), tuple(links))
