"""Whether a place's target is free: the object put there overlaps no other world object.

A place sets its object down at the target; where another object already stands (a
crate on the spot), a full-pose arm's descent collides on the way, but a short arm's is
allowed to let its object touch the world while it is set down, and would push it into
the other one. The place idiom therefore checks its target before it moves (a leaf of
its subtree), and ``run-task check`` plays that very leaf: check and run refuse the same
targets.
"""

from __future__ import annotations

import pinocchio as pin

from taskrunner.errors import SceneError
from taskrunner.scene import Contact, Scene, SceneObject
from taskrunner.scene.collision import Body, CollisionChecker
from taskrunner.scene.geometry import MeshCache, object_geometry, shape_geometry
from taskrunner.types import Pose

__all__ = ["OVERLAP_TOLERANCE", "check_target_free", "target_overlap"]

OVERLAP_TOLERANCE = 0.001
"""Penetration (m) up to which an object put down touches, rather than overlaps, another."""


def target_overlap(scene: Scene, name: str, target: pin.SE3,
                   meshes: MeshCache | None = None) -> Contact | None:
    """The deepest overlap (beyond :data:`OVERLAP_TOLERANCE`) of object ``name`` put at
    world pose ``target`` with another world object, or None. (World objects are never
    checked against each other in a run's motions.)"""
    model = scene.robot
    cache = meshes if meshes is not None else MeshCache()

    def body(obj: SceneObject, static: bool) -> Body:
        geometry = shape_geometry(obj.shape, cache)
        return Body(obj.name, (object_geometry(model, obj, geometry),), static)

    placed = SceneObject(name, scene.object(name).shape, Pose.from_se3(target))
    bodies = [body(placed, False)] + [body(o, True) for o in scene.objects
                                      if o.name != name and not o.attached]
    checker = CollisionChecker(model.model, bodies, scene.allowed_collisions())
    contacts = [c for c in checker.collisions(model.to_pin(scene.state))
                if c.depth > OVERLAP_TOLERANCE]
    return max(contacts, key=lambda c: c.depth) if contacts else None


def check_target_free(scene: Scene, name: str, target: pin.SE3,
                      meshes: MeshCache | None = None) -> None:
    """Raise where object ``name`` put at ``target`` would overlap another object.

    Raises:
        SceneError: ``target occupied by 'crate' (9 mm overlap)``.
    """
    found = target_overlap(scene, name, target, meshes)
    if found is not None:
        other = found.a if found.b == name else found.b
        raise SceneError(f"target occupied by {other!r} ({1e3 * found.depth:.0f} mm overlap)")
