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

A state check calls the manager's ``update`` and ``collide`` with a stop-at-first-collision
callback directly: pinocchio's ``computeCollisions(model, data, manager, q)`` does the same
work, but finding that overload among its many costs about 1.6 µs a call, against about
1 µs for the three direct calls (0.6 to 0.9 µs saved of 4.5). Measured on the Panda cell
(``benchmarks/collision_bench.py``, cumulative medians): forward kinematics 0.6 µs,
geometry placements 0.15, the manager's update (poses and AABBs of every object) 1.2, the
broadphase pass (AABB tests, pair look-ups) 1.4, the narrow phase (GJK on the 2 to 3
pairs whose AABBs overlap) 0.5.

The checker is immutable: a scene builds a new one after every edit, which also avoids the
pitfall of a ``GeometryData`` or broadphase manager outliving an edit of its model. What
depends only on the robot is built once per scene (and shared by its copies) as a
:class:`RobotGeometry`: its link geometry objects, in a model each checker copies before
adding the scene's objects; the pair lists are cached by the bodies and allowances, so
moving an object reuses its pairs. The report data (contacts and distances) is made on the
first report. A rebuild then costs the copy, the new objects, one ``GeometryData`` (most of
it: coal's solvers for every pair) and the manager: about a third of a build from nothing
(0.4 to 0.7 ms against 1.1 to 2.2 ms on the Panda cell with 5 to 20 objects).
"""

from __future__ import annotations

import math
from collections.abc import Collection, Sequence
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
import pinocchio as pin

from taskrunner.errors import ArgumentError

__all__ = ["VERIFY_MARGIN", "Body", "Clearance", "CollisionChecker", "Contact", "RobotGeometry"]

VERIFY_MARGIN = 2e-6
"""m: the path verifier's default margin (:class:`taskrunner.scene.path_verifier.PathVerifier`):
nothing on a verified path penetrates deeper than half of it, coal's distance tolerance."""


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


_MASK_CACHE_SIZE = 64


class RobotGeometry:
    """The robot's share of every collision checker of a scene: its link geometry objects
    (named ``link/k``), in a geometry model that has no pairs yet.

    It depends only on the robot model and the choice of link geometry, so a scene builds
    it once and every checker after an edit starts from a copy of it, adding only the
    scene's objects and the pairs (robot and scene) that the allowances leave. It is never
    edited after construction, and the checkers made from it never edit it either.

    Args:
        model: the robot's pinocchio model.
        bodies: the robot's collision bodies (its links with geometry).
    """

    def __init__(self, model: pin.Model, bodies: Sequence[Body]) -> None:
        self.model = model
        self.bodies = tuple(bodies)
        self._template = pin.GeometryModel()
        self._body_of: tuple[str, ...] = tuple(_add_bodies(self._template, self.bodies))
        self._static = tuple(body.static for body in self.bodies for _ in body.geometries)
        self._joints: np.ndarray | None = None
        # Pair masks by (the other bodies' names, kinds and sizes; the allowances): moving
        # an object, or coming back to an earlier attachment, finds its pairs here.
        self._masks: dict[tuple[object, ...],
                          tuple[np.ndarray, tuple[tuple[int, int], ...], np.ndarray]] = {}

    @property
    def geometry_count(self) -> int:
        """How many geometry objects the robot's links have (the first of every checker
        built from this)."""
        return len(self._body_of)

    @property
    def geometry_joints(self) -> np.ndarray:
        """Per geometry object of the robot's links, the pinocchio joint carrying it
        (read-only)."""
        if self._joints is None:
            joints = np.array([obj.parentJoint for obj in self._template.geometryObjects],
                              dtype=np.int64)
            joints.setflags(write=False)
            self._joints = joints
        return self._joints

    def _pairs(self, bodies: Sequence[Body], allowed: Collection[frozenset[str]],
               body_of: Sequence[str], static: Sequence[bool]
               ) -> tuple[np.ndarray, tuple[tuple[int, int], ...], np.ndarray]:
        """The pair mask and pairs of the robot with ``bodies``, as tuples and as an
        ``(n, 2)`` array (cached, read-only)."""
        key = (tuple((b.name, b.static, len(b.geometries)) for b in bodies), frozenset(allowed))
        found = self._masks.get(key)
        if found is None:
            mask = _pair_mask(body_of, static, allowed)
            first, second = np.nonzero(mask)  # row-major: the order of the model's pairs
            mask.setflags(write=False)
            array = np.column_stack([first, second]).astype(np.int64).reshape(-1, 2)
            array.setflags(write=False)
            found = (mask, tuple(zip(first.tolist(), second.tolist())), array)
            if len(self._masks) >= _MASK_CACHE_SIZE:
                self._masks.clear()  # one call: safe with copies of the scene in other threads
            self._masks[key] = found
        return found

    def checker(self, bodies: Sequence[Body], allowed: Collection[frozenset[str]]) -> CollisionChecker:
        """A checker of the robot against ``bodies`` (world and attached objects, after
        the robot's links) with the allowed body pairs ``allowed``."""
        return CollisionChecker(self.model, bodies, allowed, robot=self)


def _add_bodies(geometry: pin.GeometryModel, bodies: Sequence[Body]) -> list[str]:
    """Add copies of the bodies' geometry objects (named ``body/k``) to ``geometry``;
    returns the body name of each."""
    owners: list[str] = []
    for body in bodies:
        for index, geometry_object in enumerate(body.geometries):
            copy = pin.GeometryObject(geometry_object)
            copy.name = f"{body.name}/{index}"
            geometry.addGeometryObject(copy)
            owners.append(body.name)
    return owners


def _pair_mask(body_of: Sequence[str], static: Sequence[bool],
               allowed: Collection[frozenset[str]]) -> np.ndarray:
    """Upper-triangular boolean matrix over the geometry objects: True for a pair to
    check (different bodies, not both static, not an allowed body pair)."""
    index: dict[str, int] = {}
    body = np.array([index.setdefault(name, len(index)) for name in body_of], dtype=np.intp)
    allowed_bodies = np.zeros((len(index), len(index)), dtype=bool)
    for pair in allowed:
        if len(pair) != 2:
            continue
        a, b = pair
        ia, ib = index.get(a), index.get(b)
        if ia is not None and ib is not None:
            allowed_bodies[ia, ib] = allowed_bodies[ib, ia] = True
    fixed = np.array(static, dtype=bool)
    mask = body[:, None] != body[None, :]
    mask &= ~(fixed[:, None] & fixed[None, :])
    mask &= ~allowed_bodies[body[:, None], body[None, :]]
    return np.triu(mask, 1)


class CollisionChecker:
    """Self and world collision checks of one robot model against fixed scene bodies.

    Args:
        model: the robot's pinocchio model.
        bodies: every collision body (robot links first, by convention); with ``robot``,
            only the bodies besides the robot's.
        allowed: body pairs that may touch, as ``frozenset({a, b})``.
        robot: the robot's geometry, built once and shared (see :class:`RobotGeometry`);
            its geometry objects come first.
    """

    def __init__(
        self,
        model: pin.Model,
        bodies: Sequence[Body],
        allowed: Collection[frozenset[str]],
        robot: RobotGeometry | None = None,
    ) -> None:
        if robot is None:
            robot = RobotGeometry(model, ())
        elif robot.model is not model:
            raise ArgumentError("the robot geometry was built for another pinocchio model")
        self._geometry = robot._template.copy()
        body_of = list(robot._body_of)
        static = list(robot._static)
        body_of += _add_bodies(self._geometry, bodies)
        static += [body.static for body in bodies for _ in body.geometries]
        self._model = model
        self._body_of = body_of
        self._robot = robot
        mask, self._pairs, self._pair_array = robot._pairs(bodies, allowed, body_of, static)
        self._joint_array: np.ndarray | None = None
        if len(body_of):
            self._geometry.setCollisionPairs(mask)
        # Fast path: its own Data, GeometryData, manager and callback (stop at the first
        # collision), calling the manager's methods directly rather than pinocchio's
        # overloaded computeCollisions, whose dispatch costs more than a third of a check.
        self._data = model.createData()
        self._geometry_data = self._geometry.createData()
        self._manager = pin.BroadPhaseManager_NaiveCollisionManager(
            model, self._geometry, self._geometry_data
        )
        self._callback = pin.CollisionCallBackDefault(
            self._manager.getGeometryModel(), self._manager.getGeometryData(), True
        )
        self._place = pin.updateGeometryPlacements
        self._update = self._manager.update
        self._collide = self._manager.collide
        # pinocchio makes every pair's distance request alike, signed by default.
        requests = self._geometry_data.distanceRequests
        self._signed = len(requests) == 0 or bool(requests[0].enable_signed_distance)
        # Slow path (reports): separate data with contact computation, made on first use.
        self._report: tuple[pin.Data, pin.GeometryData] | None = None

    @property
    def pair_count(self) -> int:
        """Number of geometry pairs checked (after allowances)."""
        return len(self._pairs)

    @property
    def robot_geometry(self) -> RobotGeometry:
        """The robot's share of this checker: its geometry objects come first, the same
        in every checker built from it."""
        return self._robot

    @property
    def pair_geometries(self) -> np.ndarray:
        """``(pair_count, 2)``: the two geometry objects (indices into
        :attr:`geometry_model`'s) of each checked pair, in the model's pair order
        (read-only)."""
        return self._pair_array

    @property
    def geometry_joints(self) -> np.ndarray:
        """Per geometry object, the pinocchio joint carrying it (0: the world;
        read-only)."""
        if self._joint_array is None:
            objects = self._geometry.geometryObjects
            first = self._robot.geometry_count  # the robot's links': the same in every checker
            array = np.concatenate([self._robot.geometry_joints, np.array(
                [objects[g].parentJoint for g in range(first, len(objects))], dtype=np.int64)])
            array.setflags(write=False)
            self._joint_array = array
        return self._joint_array

    @property
    def geometry_model(self) -> pin.GeometryModel:
        """The combined geometry model (read it, do not edit it)."""
        return self._geometry

    def in_collision(self, q_pin: np.ndarray) -> bool:
        """True if any checked pair collides at pinocchio configuration ``q_pin``."""
        self._place(self._model, self._data, self._geometry, self._geometry_data, q_pin)
        self._update(False)
        callback = self._callback
        self._collide(callback)
        return bool(callback.collision)

    def first_in_collision(self, q_pins: np.ndarray) -> int:
        """The index of the first row of ``q_pins`` (pinocchio configurations, one per
        row) in collision, or -1: :meth:`in_collision` over the rows in one call."""
        place, update, collide, callback = self._place, self._update, self._collide, self._callback
        model, data, geometry, geometry_data = (self._model, self._data, self._geometry,
                                                self._geometry_data)
        for i, q_pin in enumerate(q_pins):
            place(model, data, geometry, geometry_data, q_pin)
            update(False)
            collide(callback)
            if callback.collision:
                return i
        return -1

    def pairs_collide(self, q_pin: np.ndarray, pairs: Sequence[int] | np.ndarray) -> bool:
        """True if any of the checked pairs ``pairs`` (indices into the geometry model's
        collision pairs) collides at ``q_pin``: the narrow phase on those pairs only, in
        order, stopping at the first in collision."""
        self._place(self._model, self._data, self._geometry, self._geometry_data, q_pin)
        collide, geometry, geometry_data = pin.computeCollision, self._geometry, self._geometry_data
        for k in pairs:
            if collide(geometry, geometry_data, int(k)):
                return True
        return False

    def pair_distances(self, q_pin: np.ndarray, pairs: Sequence[int], out: np.ndarray) -> None:
        """The signed distances (m, negative: penetration) of the checked pairs ``pairs``
        (indices into the geometry model's collision pairs) at ``q_pin``, into ``out``."""
        self._place(self._model, self._data, self._geometry, self._geometry_data, q_pin)
        if not self._signed:
            # pinocchio's requests compute signed distances by default; make sure.
            for request in self._geometry_data.distanceRequests:
                request.enable_signed_distance = True
            self._signed = True
        compute, geometry, geometry_data = pin.computeDistance, self._geometry, self._geometry_data
        for i, k in enumerate(pairs):
            out[i] = compute(geometry, geometry_data, int(k)).min_distance

    def _report_data(self) -> tuple[pin.Data, pin.GeometryData]:
        if self._report is None:
            geometry_data = self._geometry.createData()
            for request in geometry_data.collisionRequests:
                request.enable_contact = True
                request.num_max_contacts = 1
            self._report = (self._model.createData(), geometry_data)
        return self._report

    def collisions(self, q_pin: np.ndarray) -> list[Contact]:
        """Every colliding body pair at ``q_pin``, deepest first (the narrow phase on all pairs)."""
        data, geometry_data = self._report_data()
        pin.computeCollisions(self._model, data, self._geometry, geometry_data, q_pin, False)
        deepest: dict[tuple[str, str], float] = {}
        for k, (i, j) in enumerate(self._pairs):
            result = geometry_data.collisionResults[k]
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
        data, geometry_data = self._report_data()
        pin.computeDistances(self._model, data, self._geometry, geometry_data, q_pin)
        results = geometry_data.distanceResults
        best_k = min(range(len(self._pairs)), key=lambda k: results[k].min_distance)
        i, j = self._pairs[best_k]
        a, b = sorted((self._body_of[i], self._body_of[j]))
        return Clearance(float(results[best_k].min_distance), (a, b))
