"""Collision queries on one pinocchio GeometryModel holding the robot and the scene.

Every collision body (a robot link, a world object, an attached object) contributes
geometry objects to a single ``pin.GeometryModel``; world objects hang on the universe
joint (0), attached objects on their link's joint. The collision pairs are all pairs of
geometry objects of different bodies, minus pairs of two world objects (they never move
relative to each other), minus the allowed body pairs.

A state check runs pinocchio's forward kinematics and a broadphase pass with coal's naive
manager (an AABB test per pair, then GJK on the overlapping ones). Measured on the Panda
with five scene boxes (``benchmarks/collision_bench.py``) this is several times faster than
pinocchio's pairwise ``computeCollisions`` (which runs the narrow phase on every pair),
and faster than the dynamic-AABB-tree and sweep-and-prune managers at these sizes (tens of
bodies), whose upkeep costs more than it prunes: about 6 µs against 16 µs (AABB tree) and
55 µs (pairwise) per Panda state. Past about 100 scene objects the naive manager's
quadratic AABB pass loses to sweep-and-prune (``SSaP``: 38 µs against 65 µs at 200 boxes).
(``BroadPhaseManager_DynamicAABBTreeArrayCollisionManager`` gives wrong verdicts in
pinocchio 4.1: 7 % of Panda states disagreed with the pairwise check. Avoid it.)

The checker is immutable: a scene rebuilds it after every edit, which also avoids the
pitfall of a ``GeometryData`` or broadphase manager outliving an edit of its model.
"""

from __future__ import annotations

import math
from collections.abc import Collection, Sequence
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
import pinocchio as pin

__all__ = ["Body", "Clearance", "CollisionChecker", "Contact"]


@dataclass(frozen=True)
class Contact:
    """Two bodies in collision.

    Attributes:
        a, b: link or object names (sorted, ``a < b``).
        depth: penetration depth (m, ≥ 0) of their deepest overlapping geometry pair;
            exact for convex shapes, the depth of one triangle for BVH meshes.
    """

    a: str
    b: str
    depth: float


class Clearance(NamedTuple):
    """The closest pair of bodies: ``distance, (a, b) = scene.min_distance(q)``.

    Attributes:
        distance: m; negative when the bodies overlap (signed distance for convex shapes,
            0 or a shallow triangle depth for BVH meshes); ``inf`` with no pairs to check.
        pair: their names (sorted), or None when there are no pairs to check.
    """

    distance: float
    pair: tuple[str, str] | None


@dataclass(frozen=True)
class Body:
    """One collision body: a name and the geometry objects that make it up.

    Attributes:
        name: link or object name; allowances and results refer to bodies by this name.
        geometries: pinocchio geometry objects (parent joint, frame and placement set).
        static: True for a world object, fixed in the world frame; two static bodies
            are never checked against each other.
    """

    name: str
    geometries: tuple[pin.GeometryObject, ...]
    static: bool = False


class CollisionChecker:
    """Self and world collision checks of one robot model against fixed scene bodies.

    Args:
        model: the robot's pinocchio model.
        bodies: every collision body (robot links first, by convention).
        allowed: body pairs that may touch, as ``frozenset({a, b})``.
    """

    def __init__(
        self,
        model: pin.Model,
        bodies: Sequence[Body],
        allowed: Collection[frozenset[str]],
    ) -> None:
        self._model = model
        self._geometry = pin.GeometryModel()
        self._body_of: list[str] = []
        owners: list[Body] = []
        for body in bodies:
            for index, geometry in enumerate(body.geometries):
                copy = pin.GeometryObject(geometry)
                copy.name = f"{body.name}/{index}"
                self._geometry.addGeometryObject(copy)
                self._body_of.append(body.name)
                owners.append(body)
        count = len(owners)
        for i in range(count):
            for j in range(i + 1, count):
                a, b = owners[i], owners[j]
                if a.name == b.name or (a.static and b.static):
                    continue
                if frozenset((a.name, b.name)) in allowed:
                    continue
                self._geometry.addCollisionPair(pin.CollisionPair(i, j))
        self._pairs = [(p.first, p.second) for p in self._geometry.collisionPairs]
        # Fast path: its own Data, GeometryData and manager, built after the last edit.
        self._data = model.createData()
        self._geometry_data = self._geometry.createData()
        self._manager = pin.BroadPhaseManager_NaiveCollisionManager(
            model, self._geometry, self._geometry_data
        )
        # Slow path (reports): separate data with contact computation switched on.
        self._report_data = model.createData()
        self._report_geometry_data = self._geometry.createData()
        for request in self._report_geometry_data.collisionRequests:
            request.enable_contact = True
            request.num_max_contacts = 1

    @property
    def pair_count(self) -> int:
        """Number of geometry pairs checked (after allowances)."""
        return len(self._pairs)

    @property
    def geometry_model(self) -> pin.GeometryModel:
        """The combined geometry model (read it, do not edit it)."""
        return self._geometry

    def in_collision(self, q_pin: np.ndarray) -> bool:
        """True if any checked pair collides at pinocchio configuration ``q_pin``."""
        return bool(
            pin.computeCollisions(self._model, self._data, self._manager, q_pin, True)
        )

    def collisions(self, q_pin: np.ndarray) -> list[Contact]:
        """Every colliding body pair at ``q_pin``, deepest first (the narrow phase on all pairs)."""
        pin.computeCollisions(
            self._model, self._report_data, self._geometry, self._report_geometry_data, q_pin,
            False,
        )
        deepest: dict[tuple[str, str], float] = {}
        for k, (i, j) in enumerate(self._pairs):
            result = self._report_geometry_data.collisionResults[k]
            if not result.isCollision():
                continue
            depth = 0.0
            if result.numContacts():
                depth = max(0.0, -float(result.getContact(0).penetration_depth))
            a, b = sorted((self._body_of[i], self._body_of[j]))
            deepest[(a, b)] = max(depth, deepest.get((a, b), 0.0))
        contacts = [Contact(a, b, depth) for (a, b), depth in deepest.items()]
        return sorted(contacts, key=lambda c: (-c.depth, c.a, c.b))

    def min_distance(self, q_pin: np.ndarray) -> Clearance:
        """The closest checked body pair at ``q_pin`` and its distance (m)."""
        if not self._pairs:
            return Clearance(math.inf, None)
        pin.computeDistances(
            self._model, self._report_data, self._geometry, self._report_geometry_data, q_pin
        )
        results = self._report_geometry_data.distanceResults
        best_k = min(range(len(self._pairs)), key=lambda k: results[k].min_distance)
        i, j = self._pairs[best_k]
        a, b = sorted((self._body_of[i], self._body_of[j]))
        return Clearance(float(results[best_k].min_distance), (a, b))
