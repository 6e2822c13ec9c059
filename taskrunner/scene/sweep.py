"""Exact collision checking of joint-space paths by conservative advancement.

A path is a polyline in the state space (rad or m). Over a stretch of it, every point of
a collision geometry moves by at most ``sum_j r_j |dq_j|``, where ``r_j`` is the *lever
arm* of joint ``j`` for that geometry (a bound on the distance from the joint's axis to
any point of the geometry) and a prismatic joint moves it by ``|dq_j|``; for a pair of
bodies only the joints that move one and not the other count (the others move both
rigidly together). :func:`lever_arms` gives full-reach lever arms, valid anywhere
(computed once from the chain and the geometry's bounding sphere). Where the robot's
joints are revolute, continuous or prismatic, the verifier takes them at the state where
a pair was measured instead (the distance from the axis to the body's bounding sphere
centre, plus its radius; compiled forward kinematics), grown over the step by what the
joints between that axis and the body contribute (they are what moves the body relative
to the axis), and never above the full-reach value. This gives each measured position
``s`` of a pair a bound ``B(s, t)`` (m) on how far any point of one body moves relative
to the other until a later position ``t``; it is a path length, so it splits at any
``u`` in between into parts that bound the motion before and after ``u``.

:class:`PathVerifier` walks a path pair by pair (Schwarzer, Saha & Latombe, "Adaptive
dynamic collision checking for single and multiple articulated robots in complex
environments", IEEE T-RO 2005), measuring a lower bound ``d`` on a pair's distance at
chosen positions only. Two measurements ``(s, d_s)`` and ``(t, d_t)``, ``s < t``, *cover*
the stretch between them when

    ``B(s, t) <= max(d_s + d_t, margin)``  and  ``d_s, d_t > 0``.

Proof sketch. At a position ``u`` between, every point of one body has moved by at most
``a`` relative to the other since ``s`` and by at most ``b`` until ``t``, with
``a + b <= B(s, t)``. Moving a set by at most ``a`` changes its distance to another set
by at most ``a``, so the pair's distance at ``u`` is at least ``max(d_s - a, d_t - b)``.
If ``a + b <= d_s + d_t`` one of the two terms is ``>= 0``: they do not overlap at
``u``. Otherwise ``a + b <= margin``; a point of one body inside the other at ``u`` is
within ``a`` of where it was at ``s`` (outside, at least ``d_s`` away) and within ``b``
of where it is at ``t``, so it is at most ``min(a - d_s, b - d_t) < margin / 2`` deep. A
pair whose measurements (the first at the path's start, the last with
``B(s, end) <= d_s``, so that its distance cannot reach 0 before the end) cover the path
pairwise is therefore free, except for penetrations shallower than ``margin / 2`` where
it came within ``margin``.

The walk is adaptive per pair: after a measurement ``(s, d)`` that extends the covered
stretch, the next one is optimistic, where the bound reaches ``(1 + GAIN) d`` (at least
``margin``), since a pair's distance rarely falls as fast as its bound allows; if that
one does not cover the gap with the last, measurements at ``d`` steps fill it from the
left (each is covered whatever it measures: the walk always advances). Pairs whose bound
``B`` is the same function (the same joints move one body and not the other, with the same
lever arms: a link and each of the world objects) are walked as one *unit*: its
measurement is the least of its pairs' lower bounds, a lower bound on each pair's
distance, so the coverage above holds for every pair of it, and a link near one shelf
board of ten is scheduled once, not ten times. Units due at
nearby positions share one forward kinematics (a geometry is placed only when a pair of
it is measured). A measurement is a lower bound on the distance: far pairs take a cheap
one, computed in compiled code (bounding spheres, bounding boxes: see
:func:`_lower_bound`); below :data:`CHEAP_FROM`, a pair of boxes and convex hulls takes
the separation of the shapes themselves along their boxes' face normals and a few
directions of Gilbert's iteration (exact support functions: :func:`_support_bound`) when
that is at least :data:`EXACT_FROM`; only otherwise does the verifier ask coal for the
exact distance of the scene checker's geometry. The walk runs compiled (numba,
``cache=True``: compiled once per machine), in one call until some pairs need coal's
distance and again after each such round (:func:`_walk`). The robot's
joint tree and the rows of its links' geometry (lever arms, bounding volumes) are kept per
robot model, with those of primitive scene shapes, so that the verifier of a new scene
revision builds only what changed.

Guarantee (for the polyline, with the scene's geometry, allowances applied): if
:meth:`PathVerifier.verify` accepts a path, every measured pair was more than 1 µm apart
(coal's GJK tolerance is subtracted from every exact distance), and between measurements
no pair can penetrate deeper than ``margin / 2`` (m); wherever the two measurements
around a position summed more than the motion between them, the pair cannot touch there.
"""

from __future__ import annotations

import math
import threading
import time
import weakref
from dataclasses import dataclass

import coal
import numpy as np
import pinocchio as pin

from taskrunner.collision.frames import AXIS, ORIGIN, ROTATION, compose, inline, jit, joint_frames
from taskrunner.collision.geometry import GEOMETRY, ShapeKind
from taskrunner.collision.tree import KinematicTree
from taskrunner.errors import ArgumentError
from taskrunner.robot import RobotModel
from taskrunner.scene.collision import VERIFY_MARGIN, CollisionChecker

__all__ = ["CHEAP_FROM", "EXACT_FROM", "GAIN", "PathVerification", "PathVerifier", "lever_arms"]

_DISTANCE_SLACK = 1e-6  # m: GJK's distance tolerance; measured distances are reduced by it
_EARLY = 0.25  # a pair due within this fraction of its step is measured with the others
GAIN = 1.0  # optimistic step: (1 + GAIN) times the last distance (see the module's text)
_BISECTIONS = 4  # at most this many evaluations to place a step inside a segment
_CLOSE = 0.1  # a step placed within this fraction short of its bound is close enough

# Columns of the walk state (a float array, one row per unit: pairs whose motion bound is
# the same function, see :func:`_group_pairs`; its lever arms on the left and on the right
# follow): the measurements on the left and right of a gap, and while a unit's members wait
# for coal's distances, the least distance of those in and how many are pending. When each
# unit is due next, and from where it may be measured early, are rows 0 and 1 of the
# schedule (inf: done).
_HAS_L, _PL, _DL, _HAS_R, _PR, _DR, _UMIN, _UPENDING = range(8)
_COLUMNS = 8
CHEAP_FROM = 0.01  # m: a pair whose cheap lower bound is at least this takes it, not coal's
# m: below CHEAP_FROM, a pair of boxes and convex hulls takes the bound from their support
# functions (:func:`_support_bound`) if it is at least this; coal's distance otherwise.
EXACT_FROM = 0.001
_SUPPORT_STEPS = 4  # at most this many directions refined by Gilbert's iteration
_SUPPORT_TOLERANCE = 0.05  # ... until the bound is within this fraction of the distance


def lever_arms(robot: RobotModel, geometry_model: pin.GeometryModel) -> np.ndarray:
    """Per geometry object and state-vector joint, a bound on how far the joint moves it.

    Returns:
        ``(n_geometries, robot.nq)``: for a revolute or continuous joint, an upper bound
        (m/rad) on the distance from its axis to any point of the geometry (through the
        chain at full reach: joint offsets plus the full travel of prismatic joints in
        between, then the geometry's bounding sphere); for a prismatic joint 1 (m/m);
        0 where the joint does not move the geometry (world objects, other branches).
    """
    tree = _tree(robot)
    levers = np.zeros((len(geometry_model.geometryObjects), robot.nq))
    for g, geometry_object in enumerate(geometry_model.geometryObjects):
        levers[g] = tree.levers(geometry_object)
    return levers


@dataclass(frozen=True)
class PathVerification:
    """What :meth:`PathVerifier.verify` found.

    Attributes:
        valid: no checked pair overlaps anywhere along the path (see the module's guarantee).
        distance_queries: exact pair distances computed (coal).
        states: states at which forward kinematics ran.
        seconds: wall time of the verification.
        fraction: where the contact is, as ``segment + t`` (waypoint index plus the
            fraction of the next segment); None for a valid path.
        pair: the geometry names of that contact; None for a valid path.
        state: the full state vector there; None for a valid path.
        bounds: lower bounds taken instead of coal's exact distance (far pairs: bounding
            volumes; closer pairs of boxes and convex hulls: their support functions).
    """

    valid: bool
    distance_queries: int
    states: int
    seconds: float
    fraction: float | None = None
    pair: tuple[str, str] | None = None
    state: np.ndarray | None = None
    bounds: int = 0


class PathVerifier:
    """Verifies paths against one collision checker (one scene revision).

    Args:
        robot: the robot model.
        checker: the scene's checker (its geometry and pairs, allowances applied).
        margin: m; where two measurements of a pair do not cover the motion between them
            by distance, they must be less than this apart in motion bound (both free);
            twice the deepest penetration the verification can miss there.

    What depends on the robot alone (its joint tree, the lever arms and bounding volumes
    of its links' geometry) is kept per robot model and reused by the verifiers of later
    scene revisions; only the world and attached objects and the pairs are built anew.
    The exact distances are the checker's (:meth:`CollisionChecker.pair_distances`, on
    its own pinocchio data: no second copy of coal's per-pair solvers is made), so a
    verifier is used like its checker, by one thread at a time.
    """

    def __init__(self, robot: RobotModel, checker: CollisionChecker,
                 margin: float = VERIFY_MARGIN) -> None:
        if not (math.isfinite(margin) and margin > 0):
            raise ArgumentError(f"'margin' must be a positive number of metres (got {margin!r})")
        self.robot = robot
        self.margin = margin
        self._checker = checker
        self._geometry = checker.geometry_model
        tree = _tree(robot)
        self._tree = tree
        records = [tree.record(obj) for obj in self._geometry.geometryObjects]
        nq = robot.nq
        count = len(records)
        self._geometry_names = [r.name for r in records]
        levers = np.array([r.levers for r in records]).reshape(count, nq)
        geometries = np.zeros(count, dtype=GEOMETRY)
        hulls = [r.points for r in records if r.points is not None]
        self._points = np.ascontiguousarray(np.vstack(hulls)) if hulls else np.zeros((0, 3))
        start = 0
        for g, r in enumerate(records):
            geometries[g] = r.geometry
            if r.points is not None:
                geometries["first_point"][g] = start
                geometries["point_count"][g] = len(r.points)
                start += len(r.points)
        self._geometries = geometries
        self._levers = levers
        pairs = np.array([(p.first, p.second) for p in self._geometry.collisionPairs],
                         dtype=np.int64).reshape(-1, 2)
        first, second = pairs[:, 0].copy(), pairs[:, 1].copy()
        self._first, self._second = first, second
        self._pair_levers = np.zeros((len(first), nq))
        self._pair_i = np.zeros((len(first), _PI_JOINTS + 4 * nq), dtype=np.int64)
        _pair_rows(first, second, levers, tree.order, tree.revolute, tree.state_joint,
                   tree.supported, self._pair_levers, self._pair_i)
        # Pairs that move alike (a link and each world object: the same joints, lever arms)
        # are walked as one unit, measured together, their least distance its measurement.
        unit_of = np.zeros(len(first), dtype=np.int64)
        representative = np.zeros(len(first), dtype=np.int64)
        units = _group_pairs(self._pair_i, self._pair_levers, unit_of, representative)
        self._unit_of = unit_of
        self._members = np.argsort(unit_of, kind="stable").astype(np.int64)
        self._unit_from = np.zeros(units + 1, dtype=np.int64)
        np.cumsum(np.bincount(unit_of, minlength=units), out=self._unit_from[1:])
        self._unit_i = self._pair_i[representative[:units]].copy()
        self._unit_levers = self._pair_levers[representative[:units]].copy()
        self._kinematics = _Kinematics(tree, self._geometries)
        self._settings = np.zeros(_S_COUNT)
        self._settings[:5] = (margin, _DISTANCE_SLACK, GAIN, _EARLY,
                              CHEAP_FROM if tree.supported else np.inf)
        self._settings[_S_PER_STATE] = 1.0 if tree.supported else 0.0
        self._settings[_S_BAD] = -1.0
        self._settings[_S_EXACT_FROM] = EXACT_FROM
        self._busy = threading.Lock()
        self._buffers = self._new_buffers()

    @property
    def pair_levers(self) -> np.ndarray:
        """``(n_pairs, nq)``: how far each joint can move one body of a pair relative to
        the other (m/rad, m/m), per unit of joint motion, anywhere (at full reach)."""
        return self._pair_levers

    @property
    def configuration_dependent(self) -> bool:
        """True when lever arms are taken at each measured state (every joint of the
        robot is revolute, continuous or prismatic); else the full-reach bounds serve."""
        return self._tree.supported

    def _pair_name(self, k: int) -> tuple[str, str]:
        return (self._geometry_names[int(self._first[k])],
                self._geometry_names[int(self._second[k])])

    def segment_bounds(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """Per pair, the bound (m) the verifier uses on how far any point of one body
        moves relative to the other along the straight segment from state ``a`` to ``b``
        (lever arms taken at ``a``)."""
        states = np.ascontiguousarray(np.vstack([a, b]).astype(float))
        cumulative = np.zeros_like(states)
        cumulative[1] = np.abs(states[1] - states[0])
        out = np.zeros(len(self._first))
        kin = self._kinematics
        frames = kin.frames(states[0])
        _segment_bounds(cumulative, self._geometries, self._pair_i, self._pair_levers, frames,
                        kin.joints.shape[0], self._tree.supported, out)
        return out

    def lower_bounds(self, q: np.ndarray) -> np.ndarray:
        """Per pair, the cheap bound on its distance (m) at state ``q`` that the verifier
        uses for far pairs (bounding spheres and boxes): where positive, the pair is at
        least that far apart. ``-inf`` without compiled kinematics."""
        out = np.full(len(self._first), -np.inf)
        if not self._tree.supported:
            return out
        kin = self._kinematics
        frames = kin.frames(np.asarray(q, dtype=float))
        _lower_bounds(self._pair_i, self._geometries, frames, kin.joints.shape[0], out)
        return out

    def support_bounds(self, q: np.ndarray) -> np.ndarray:
        """Per pair, the bound on its distance (m) at state ``q`` that the verifier takes
        from the shapes' support functions below :data:`CHEAP_FROM` (pairs of boxes and
        convex hulls; ``-inf`` for other shapes or without compiled kinematics): where
        positive, the pair is at least that far apart."""
        out = np.full(len(self._first), -np.inf)
        if not self._tree.supported:
            return out
        kin = self._kinematics
        frames = kin.frames(np.asarray(q, dtype=float))
        _support_bounds(self._pair_i, self._geometries, frames, self._points,
                        kin.joints.shape[0], out)
        return out

    def verify(self, states: np.ndarray) -> PathVerification:
        """Verify the polyline through full state vectors ``states`` (``(n, nq)``).

        Returns:
            A :class:`PathVerification`; ``valid`` False names a contact found.
        """
        t0 = time.perf_counter()
        states = np.asarray(states, dtype=float)
        if states.ndim == 1:
            states = states[None, :]
        nq = self.robot.nq
        if states.ndim != 2 or states.shape[1] != nq or len(states) == 0:
            raise ArgumentError(f"states must be an (n, {nq}) array of full state "
                             f"vectors (got shape {states.shape})")
        n_pairs = len(self._first)
        if n_pairs == 0:
            if not np.isfinite(states).all():
                row = int(np.flatnonzero(~np.isfinite(states).all(axis=1))[0])
                raise ArgumentError(f"state {row} of the path to verify is not finite: {states[row]}")
            return PathVerification(True, 0, 0, time.perf_counter() - t0)
        states = np.ascontiguousarray(states)
        cumulative = np.empty_like(states)                    # per joint, sum of |dq|
        own = self._busy.acquire(blocking=False)              # else: a concurrent call
        try:
            walk, schedule, picked, selected, distances, q, frames, settings = \
                self._buffers if own else self._new_buffers()
            settings[:] = self._settings
            kin = self._kinematics
            walked = (kin.joints, self._geometries, self._points,
                      self._pair_i, self._unit_i, self._unit_levers, self._members,
                      self._unit_from, self._unit_of, states, cumulative, frames, walk,
                      schedule, picked, selected, distances, q, settings)
            queries = evaluated = 0
            pair_distances, to_pin = self._checker.pair_distances, self.robot.to_pin
            while True:
                count = _walk(*walked)
                if count <= 0:
                    break
                pair_distances(to_pin(q), selected[:count].tolist(), distances)
                evaluated += 1
                queries += count
            if count == _NOT_FINITE:
                row = int(settings[_S_BAD])
                raise ArgumentError(f"state {row} of the path to verify is not finite: {states[row]}")
            states_count = max(evaluated, int(settings[_S_STATES]))
            if count < 0:
                bad = int(selected[int(settings[_S_BAD])])
                return PathVerification(False, queries, states_count, time.perf_counter() - t0,
                                        float(settings[_S_AT]), self._pair_name(bad), q.copy(),
                                        int(settings[_S_BOUNDS]))
            return PathVerification(True, queries, states_count, time.perf_counter() - t0,
                                    bounds=int(settings[_S_BOUNDS]))
        finally:
            if own:
                self._busy.release()

    def _new_buffers(self) -> tuple[np.ndarray, ...]:
        """Work arrays of :func:`_walk`: walk state and schedule (per unit), the units
        picked, the pairs selected for coal's distances, those distances, the state, its
        frames, the settings."""
        n_pairs, n_units, nq = len(self._first), len(self._unit_i), self.robot.nq
        return (np.zeros((n_units, _COLUMNS + 2 * nq)), np.zeros((2, n_units)),
                np.zeros(n_units, dtype=np.int64), np.zeros(n_pairs, dtype=np.int64),
                np.zeros(n_pairs), np.zeros(nq), self._kinematics.buffer(), np.zeros(_S_COUNT))


# Columns of the packed arrays the kernels read (one row per joint, geometry or pair).
# The geometries' records (taskrunner.collision.geometry.GEOMETRY): their core shapes.
_SHAPE_NONE, _SHAPE_BOX, _SHAPE_HULL = int(ShapeKind.NONE), int(ShapeKind.BOX), int(ShapeKind.HULL)
_SHAPE_CYLINDER, _SHAPE_SPHERE = int(ShapeKind.CYLINDER), int(ShapeKind.SPHERE)
# pair_i (n_pairs, 3 + 4 nq): the pair's geometries, how many joints count, then per
# such joint (deepest first): its state index, code, the geometry it moves, its joint id.
_PI_FIRST, _PI_SECOND, _PI_COUNT, _PI_JOINTS = range(4)
# frames (n_joints + n_geometries, 19): a joint's frame row (world rotation, origin and
# axis: :mod:`taskrunner.collision.frames`); a geometry's world rotation and origin, then
# its bounding sphere centre and bounding box centre.
_FR_CENTRE, _FR_BOX = 12, 15
# The walk places a geometry only when a pair of it is measured: column _FR_PLACED of its
# row holds the count of compiled states when it was placed (inf: a world object's, fixed).
_FR_PLACED = 18
_FR_COLUMNS = 19
# settings: margin, slack, gain, early, cheap-from; compiled states, cheap bounds; exact
# distances pending (count, position); per-state lever arms; the contact (index into the
# selected pairs) or the first state that is not finite; the walk started.
_S_STATES, _S_BOUNDS, _S_PENDING, _S_AT, _S_PER_STATE, _S_BAD, _S_STARTED = 5, 6, 7, 8, 9, 10, 11
_S_EXACT_FROM, _S_SUPPORTS = 12, 13  # below CHEAP_FROM, coal's distance below this; bounds so
_S_COUNT = 14
_NOT_FINITE = -2  # what :func:`_walk` returns for a state that is not finite


@dataclass(frozen=True)
class _Record:
    """One geometry object's rows of the packed arrays, and its lever arms."""

    name: str
    levers: np.ndarray
    geometry: np.ndarray  # a GEOMETRY record (0-d); its points' place is the verifier's
    points: np.ndarray | None = None


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
                                                              record.points)
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
        row["swept"] = swept if math.isfinite(swept) and swept >= 0.0 else 0.0
        if not (math.isfinite(swept) and swept >= 0.0):
            shape = _SHAPE_NONE
        row["joint"] = int(geometry_object.parentJoint)
        row["has_box"] = int(has_box)
        row["shape"] = shape
        return _Record(geometry_object.name, levers, row, points)


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


# ---------------------------------------------------------------------- kernels
# The entry points (called from Python) are compiled functions of their own, and so are
# the helpers (``inline``, ``jit``): each compiled once and called, not inlined into every
# caller (inlined, the first compilation took 38 % longer for no measurable speed).
@jit
def _forward(q, joints, geometries, frames):  # type: ignore[no-untyped-def]
    """World frames of the joints and the geometries at state ``q`` (into ``frames``,
    columns ``_FR_*``: geometry ``g`` is row ``n_joints + g``)."""
    joint_frames(q, joints, frames)
    nj = joints.shape[0]
    for g in range(geometries.shape[0]):
        _geometry_frame(g, geometries, frames, nj)


@inline
def _geometry_frame(g, geometries, frames, nj):  # type: ignore[no-untyped-def]
    """Geometry ``g``'s world frame, bounding sphere and box centres (row ``nj + g`` of
    ``frames``) from its joint's frame."""
    jid = geometries[g].joint
    row = nj + g
    compose(frames, row, jid, geometries[g].placement)
    for a in range(3):
        centre = frames[row, ORIGIN + a]
        box = frames[row, ORIGIN + a]
        for b in range(3):
            centre += frames[row, 3 * a + b] * geometries[g].centre[b]
            box += frames[row, 3 * a + b] * geometries[g].box[b]
        frames[row, _FR_CENTRE + a] = centre
        frames[row, _FR_BOX + a] = box


@inline
def _place(g, geometries, frames, nj, stamp):  # type: ignore[no-untyped-def]
    """Place geometry ``g`` at the state of the joint frames (compiled state ``stamp``)."""
    _geometry_frame(g, geometries, frames, nj)
    frames[nj + g, _FR_PLACED] = np.inf if geometries[g].joint == 0 else stamp


@jit
def _farthest_point_centre(points, centre, iterations):  # type: ignore[no-untyped-def]
    """Badoiu-Clarkson: move ``centre`` (in place) towards the farthest point, with
    shrinking steps; returns the distance from the final centre to the farthest point."""
    for i in range(iterations + 1):
        best, farthest = -1.0, 0
        for p in range(points.shape[0]):
            d = 0.0
            for a in range(3):
                d += (points[p, a] - centre[a]) ** 2
            if d > best:
                best, farthest = d, p
        if i == iterations:
            return math.sqrt(best)
        for a in range(3):
            centre[a] += (points[farthest, a] - centre[a]) / (i + 2)
    return 0.0


@inline
def _sphere_to_box(frames, row, radius, box, geometries, nj):  # type: ignore[no-untyped-def]
    """Distance from the bounding sphere of frames row ``row`` (radius ``radius``) to
    geometry ``box``'s bounding box (negative: may overlap)."""
    other = nj + box
    outside = 0.0
    for b in range(3):
        local = -geometries[box].box[b]
        for a in range(3):
            local += frames[other, 3 * a + b] * (frames[row, _FR_CENTRE + a]
                                                 - frames[other, ORIGIN + a])
        excess = abs(local) - geometries[box].half[b]
        if excess > 0.0:
            outside += excess * excess
    return math.sqrt(outside) - radius


@inline
def _box_gap(a, b, geometries, frames, nj):  # type: ignore[no-untyped-def]
    """The largest gap between the projections of geometries ``a``'s and ``b``'s bounding
    boxes on their six face normals: a lower bound on their distance where positive.

    Along a unit normal ``n``, the gap is ``|(c_a - c_b) . n|`` less each box's half
    extent projected on ``n``; with ``C = R_a^T R_b`` the projections of one box's axes on
    the other's normals are the entries of ``C`` (its own: 0 or 1)."""
    ra, rb = nj + a, nj + b
    best = -np.inf
    for axis in range(3):
        along_a = 0.0               # the centres' offset along a's and b's normals
        along_b = 0.0
        for m in range(3):
            t = frames[ra, _FR_BOX + m] - frames[rb, _FR_BOX + m]
            along_a += t * frames[ra, 3 * m + axis]
            along_b += t * frames[rb, 3 * m + axis]
        gap_a = abs(along_a) - geometries[a].half[axis]
        gap_b = abs(along_b) - geometries[b].half[axis]
        for j in range(3):
            c_aj = 0.0              # C[axis, j] and C[j, axis]
            c_ja = 0.0
            for m in range(3):
                c_aj += frames[ra, 3 * m + axis] * frames[rb, 3 * m + j]
                c_ja += frames[ra, 3 * m + j] * frames[rb, 3 * m + axis]
            gap_a -= geometries[b].half[j] * abs(c_aj)
            gap_b -= geometries[a].half[j] * abs(c_ja)
        if gap_a > best:
            best = gap_a
        if gap_b > best:
            best = gap_b
    return best


@inline
def _sphere_gap(a, b, geometries, frames, nj):  # type: ignore[no-untyped-def]
    """The distance of geometries ``a``'s and ``b``'s bounding spheres (placed): the first
    of :func:`_lower_bound`'s bounds, which is at least this."""
    ra, rb = nj + a, nj + b
    gap = 0.0
    for i in range(3):
        gap += (frames[ra, _FR_CENTRE + i] - frames[rb, _FR_CENTRE + i]) ** 2
    return math.sqrt(gap) - geometries[a].radius - geometries[b].radius


@inline
def _lower_bound(a, b, geometries, frames, nj):  # type: ignore[no-untyped-def]
    """A lower bound on the distance of geometries ``a`` and ``b`` where positive: the
    best of their bounding spheres' distance, each sphere's distance to the other's
    bounding box and the boxes' separation along their face normals."""
    ra, rb = nj + a, nj + b
    gap = 0.0
    for i in range(3):
        gap += (frames[ra, _FR_CENTRE + i] - frames[rb, _FR_CENTRE + i]) ** 2
    best = math.sqrt(gap) - geometries[a].radius - geometries[b].radius
    if geometries[b].has_box != 0:
        value = _sphere_to_box(frames, ra, geometries[a].radius, b, geometries, nj)
        if value > best:
            best = value
    if geometries[a].has_box != 0:
        value = _sphere_to_box(frames, rb, geometries[b].radius, a, geometries, nj)
        if value > best:
            best = value
    if geometries[a].has_box != 0 and geometries[b].has_box != 0:
        value = _box_gap(a, b, geometries, frames, nj)
        if value > best:
            best = value
    return best


@jit
def _support(g, dx, dy, dz, geometries, frames, points, nj):  # type: ignore[no-untyped-def]
    """The point of geometry ``g``'s core (see ``_SHAPE_*``; without the radius it is
    grown by) furthest along the world direction ``(dx, dy, dz)``."""
    row = nj + g
    # The direction in the geometry's frame (its rotation's columns are its axes).
    lx = frames[row, 0] * dx + frames[row, 3] * dy + frames[row, 6] * dz
    ly = frames[row, 1] * dx + frames[row, 4] * dy + frames[row, 7] * dz
    lz = frames[row, 2] * dx + frames[row, 5] * dy + frames[row, 8] * dz
    shape = geometries[g].shape
    if shape != _SHAPE_HULL:
        px = py = pz = 0.0
        if shape == _SHAPE_BOX:
            px = geometries[g].half[0] if lx >= 0.0 else -geometries[g].half[0]
            py = geometries[g].half[1] if ly >= 0.0 else -geometries[g].half[1]
            pz = geometries[g].half[2] if lz >= 0.0 else -geometries[g].half[2]
        elif shape == _SHAPE_CYLINDER:
            radial = math.sqrt(lx * lx + ly * ly)
            if radial > 0.0:
                px = geometries[g].half[0] * lx / radial
                py = geometries[g].half[0] * ly / radial
            pz = geometries[g].half[2] if lz >= 0.0 else -geometries[g].half[2]
        ox, oy, oz = frames[row, _FR_BOX], frames[row, _FR_BOX + 1], frames[row, _FR_BOX + 2]
    else:
        first = geometries[g].first_point
        best = -np.inf
        px = py = pz = 0.0
        for v in range(first, first + geometries[g].point_count):
            value = points[v, 0] * lx + points[v, 1] * ly + points[v, 2] * lz
            if value > best:
                best = value
                px, py, pz = points[v, 0], points[v, 1], points[v, 2]
        ox, oy, oz = (frames[row, ORIGIN], frames[row, ORIGIN + 1],
                      frames[row, ORIGIN + 2])
    return (ox + frames[row, 0] * px + frames[row, 1] * py + frames[row, 2] * pz,
            oy + frames[row, 3] * px + frames[row, 4] * py + frames[row, 5] * pz,
            oz + frames[row, 6] * px + frames[row, 7] * py + frames[row, 8] * pz)


@jit
def _support_bound(a, b, geometries, frames, points, nj):  # type: ignore[no-untyped-def]
    """A lower bound on the distance of geometries ``a`` and ``b`` where positive, from
    their support functions (boxes and convex hulls; -inf for other shapes).

    For any unit direction ``n``, ``min over a of n.a - max over b of n.b`` is at most
    their distance (they are separated by at least that along ``n``); the points are the
    shapes' own (a box's corners, a hull's vertices), so the bound is exact for the
    direction. The directions tried: the face normals of the boxes among them, a cylinder's
    axis and the direction from its axis towards the other's centre, the centres' offset,
    then the best of those refined by Gilbert's iteration on the difference ``A - B`` (its point
    closest to the origin, approached over segments), until the bound is within
    ``_SUPPORT_TOLERANCE`` of the distance estimate or after ``_SUPPORT_STEPS``. Each swept
    sphere radius is subtracted."""
    if geometries[a].shape == _SHAPE_NONE or geometries[b].shape == _SHAPE_NONE:
        return -np.inf
    ra, rb = nj + a, nj + b
    swept = geometries[a].swept + geometries[b].swept
    best = -np.inf
    vx = vy = vz = 0.0
    # The offset of the bounding spheres' centres, from A to B.
    nx = frames[rb, _FR_CENTRE] - frames[ra, _FR_CENTRE]
    ny = frames[rb, _FR_CENTRE + 1] - frames[ra, _FR_CENTRE + 1]
    nz = frames[rb, _FR_CENTRE + 2] - frames[ra, _FR_CENTRE + 2]
    # Face normals of the boxes, a cylinder's axis and the direction away from it towards
    # the other's centre (all pointing from A to B), and the offset itself.
    for side in range(3):
        for axis in range(4):
            if side < 2:
                if axis == 3:
                    continue
                owner = ra if side == 0 else rb
                shape = geometries[owner - nj].shape
                if shape == _SHAPE_CYLINDER and axis < 2:
                    ux, uy, uz = frames[owner, 2], frames[owner, 5], frames[owner, 8]
                    if axis == 1:     # the offset less its part along the axis
                        along = ux * nx + uy * ny + uz * nz
                        ux, uy, uz = nx - along * ux, ny - along * uy, nz - along * uz
                        length = math.sqrt(ux * ux + uy * uy + uz * uz)
                        if not length > 0.0:
                            continue
                        ux, uy, uz = ux / length, uy / length, uz / length
                elif shape == _SHAPE_BOX:
                    ux, uy, uz = frames[owner, axis], frames[owner, 3 + axis], frames[owner, 6 + axis]
                else:
                    continue
                if ux * nx + uy * ny + uz * nz < 0.0:
                    ux, uy, uz = -ux, -uy, -uz
            else:
                if axis > 0:
                    break
                length = math.sqrt(nx * nx + ny * ny + nz * nz)
                if not length > 0.0:
                    continue
                ux, uy, uz = nx / length, ny / length, nz / length
            # Separation along u: min over B of u.b - max over A of u.a.
            ax, ay, az = _support(a, ux, uy, uz, geometries, frames, points, nj)
            bx, by, bz = _support(b, -ux, -uy, -uz, geometries, frames, points, nj)
            gap = (bx - ax) * ux + (by - ay) * uy + (bz - az) * uz
            if gap > best:
                best = gap
                vx, vy, vz = bx - ax, by - ay, bz - az      # a point of B - A
    # Gilbert: v, a point of B - A (its norm: at least the distance), moves towards the
    # origin's nearest; the directions v/|v|.
    for _ in range(_SUPPORT_STEPS):
        length = math.sqrt(vx * vx + vy * vy + vz * vz)
        if not length > 0.0 or length - best <= _SUPPORT_TOLERANCE * length:
            break
        ux, uy, uz = vx / length, vy / length, vz / length
        ax, ay, az = _support(a, ux, uy, uz, geometries, frames, points, nj)
        bx, by, bz = _support(b, -ux, -uy, -uz, geometries, frames, points, nj)
        wx, wy, wz = bx - ax, by - ay, bz - az
        gap = wx * ux + wy * uy + wz * uz
        if gap > best:
            best = gap
        if length - gap <= _SUPPORT_TOLERANCE * length:
            break
        # The point of the segment [v, w] nearest the origin.
        dx, dy, dz = wx - vx, wy - vy, wz - vz
        dd = dx * dx + dy * dy + dz * dz
        if not dd > 0.0:
            break
        t = -(vx * dx + vy * dy + vz * dz) / dd
        if t <= 0.0:
            break
        if t > 1.0:
            t = 1.0
        vx, vy, vz = vx + t * dx, vy + t * dy, vz + t * dz
    return best - swept


@inline
def _levers_here(k, pair_i, pair_levers, geometries, frames, nj, per_state, walk, column):  # type: ignore[no-untyped-def]
    """Pair ``k``'s lever arms at the state of ``frames`` (into ``walk[k, column + j]``,
    for the joints that count): for a revolute joint, the distance from its axis to the
    moved body's bounding sphere centre plus the radius (never more than the full-reach
    bound); otherwise the full-reach bound."""
    nq = pair_levers.shape[1]
    for i in range(pair_i[k, _PI_COUNT]):
        j = pair_i[k, _PI_JOINTS + i]
        full = pair_levers[k, j]
        value = full
        if per_state and pair_i[k, _PI_JOINTS + nq + i] >= 3 and full != 0.0:
            g = pair_i[k, _PI_JOINTS + 2 * nq + i]
            jid = pair_i[k, _PI_JOINTS + 3 * nq + i]
            along = 0.0
            length2 = 0.0
            for a in range(3):
                v = frames[nj + g, _FR_CENTRE + a] - frames[jid, ORIGIN + a]
                along += v * frames[jid, AXIS + a]
                length2 += v * v
            off_axis = length2 - along * along
            lever = math.sqrt(off_axis if off_axis > 0.0 else 0.0) + geometries[g].radius
            if lever < full:
                value = lever
        walk[k, column + j] = value


@inline
def _cumulative_at(cumulative, position, out):  # type: ignore[no-untyped-def]
    n = cumulative.shape[0]
    if n == 1:
        for j in range(cumulative.shape[1]):
            out[j] = 0.0
        return
    seg = int(position)
    if seg > n - 2:
        seg = n - 2
    frac = position - seg
    for j in range(cumulative.shape[1]):
        out[j] = cumulative[seg, j] + frac * (cumulative[seg + 1, j] - cumulative[seg, j])


@inline
def _bound(cumulative, pair_i, pair_levers, k, c0, walk, column, position):  # type: ignore[no-untyped-def]
    """Pair ``k``'s motion bound (m) from the path position whose cumulative joint motion
    is ``c0`` to ``position``, with the lever arms ``walk[k, column + j]`` taken at the
    former.

    A revolute joint's lever arm grows by at most how far the joints below it (same
    body, deeper in the tree) move the body relative to its axis, which is their own
    contribution: the joints are taken deepest first."""
    nq = pair_levers.shape[1]
    n = cumulative.shape[0]
    seg = int(position)
    if seg > n - 2:
        seg = n - 2
    frac = position - seg
    share_first = 0.0                   # what each body's deeper joints contributed
    share_second = 0.0
    total = 0.0
    for i in range(pair_i[k, _PI_COUNT]):
        j = pair_i[k, _PI_JOINTS + i]
        code = pair_i[k, _PI_JOINTS + nq + i]
        if n == 1:
            c1 = 0.0
        else:
            c1 = cumulative[seg, j] + frac * (cumulative[seg + 1, j] - cumulative[seg, j])
        moved = c1 - c0[j]
        if moved <= 0.0:
            continue
        first = code % 2 == 1
        lever = walk[k, column + j]
        if code >= 3:
            lever += share_first if first else share_second
            if lever > pair_levers[k, j]:
                lever = pair_levers[k, j]
        contribution = lever * moved
        if first:
            share_first += contribution
        else:
            share_second += contribution
        total += contribution
    return total


@inline
def _position_for(cumulative, pair_i, pair_levers, k, start, c0, walk, step, to_end):  # type: ignore[no-untyped-def]
    """A path position after ``start`` where pair ``k``'s motion bound from ``start`` (lever
    arms: the left ones of ``walk``) is at most ``step`` (> 0), and close to the furthest
    one: the last node where it is, then within that node's segment to ``_CLOSE`` of
    ``step``, or as far as ``_BISECTIONS`` evaluations get. ``to_end``: the bound from
    ``start`` to the path's end."""
    last = cumulative.shape[0] - 1
    if to_end <= step:
        return float(last)
    left = _COLUMNS
    lo_node = int(start) + 1      # first node after start
    lo, f_lo = start, 0.0         # no motion yet
    if lo_node == last:           # the bound there is ``to_end``
        f_node = to_end
    else:
        f_node = _bound(cumulative, pair_i, pair_levers, k, c0, walk, left, float(lo_node))
    if f_node <= step:
        hi_node, f_hi = last, to_end   # bound(lo_node) <= step < bound(hi_node)
        while hi_node - lo_node > 1:
            mid = (lo_node + hi_node) // 2
            f_mid = _bound(cumulative, pair_i, pair_levers, k, c0, walk, left, float(mid))
            if f_mid <= step:
                lo_node, f_node = mid, f_mid
            else:
                hi_node, f_hi = mid, f_mid
        lo, f_lo = float(lo_node), f_node
        hi = float(hi_node)
    else:
        hi, f_hi = float(lo_node), f_node
    # Regula falsi, keeping the bracket: bound(lo) <= step < bound(hi).
    for _ in range(_BISECTIONS):
        if f_lo >= (1.0 - _CLOSE) * step or f_hi <= f_lo:
            break
        width = hi - lo
        mid = lo + width * (step - f_lo) / (f_hi - f_lo)
        if mid < lo + _CLOSE * width:
            mid = lo + _CLOSE * width
        if mid > hi - _CLOSE * width:
            mid = hi - _CLOSE * width
        f_mid = _bound(cumulative, pair_i, pair_levers, k, c0, walk, left, mid)
        if f_mid <= step:
            lo, f_lo = mid, f_mid
        else:
            hi, f_hi = mid, f_mid
    if lo <= start:
        # Never stay put (the walk must advance): halve towards the start; the bound is
        # continuous and 0 there, so this ends.
        for _ in range(200):
            mid = 0.5 * (lo + hi)
            if mid <= start:
                break
            if _bound(cumulative, pair_i, pair_levers, k, c0, walk, left, mid) <= step:
                return mid
            hi = mid
    return lo


@inline
def _pick(walk, schedule, selected, states, q):  # type: ignore[no-untyped-def]
    """The next position to evaluate (the earliest due pair's), the pairs measured there
    (written to ``selected``: due there, or due soon and past their early position) and
    the state there (written to ``q``). Count 0: done."""
    n_pairs = walk.shape[0]
    due, early_at = schedule[0], schedule[1]
    s = np.inf
    for k in range(n_pairs):
        if due[k] < s:
            s = due[k]
    if s == np.inf:
        return 0, 0.0
    count = 0
    for k in range(n_pairs):
        # Measuring early (after the last measurement) is always sound.
        if due[k] <= s or (early_at[k] <= s and walk[k, _PL] < s and walk[k, _HAS_L] != 0.0):
            selected[count] = k
            count += 1
    n = states.shape[0]
    seg = int(s)
    if seg > n - 2:
        seg = max(n - 2, 0)
    frac = s - seg
    for j in range(states.shape[1]):
        if n == 1:
            q[j] = states[0, j]
        else:
            q[j] = states[seg, j] + frac * (states[seg + 1, j] - states[seg, j])
    return count, s


@jit
def _measure(k, d, s, cumulative, pair_i, pair_levers, geometries, frames, nj, walk, schedule, c0,  # type: ignore[no-untyped-def]
             settings):
    """Take a lower bound ``d`` > 0 on pair ``k``'s distance at position ``s`` (the state
    of ``frames``) and schedule the pair's next measurement. A called function, not
    inlined: the walk takes measurements in two places (a unit's exact distances, its
    cheap bounds), and inlined twice it took the kernels' first compilation from about
    8 to 24 s of CPU (the call costs about 1 % of a verification)."""
    margin, gain, early = settings[0], settings[2], settings[3]
    per_state = settings[_S_PER_STATE] != 0.0
    nq = cumulative.shape[1]
    left, right = _COLUMNS, _COLUMNS + nq
    last = float(cumulative.shape[0] - 1)
    if walk[k, _HAS_L] == 0.0:
        extends = True
    else:
        _cumulative_at(cumulative, walk[k, _PL], c0)
        moved = _bound(cumulative, pair_i, pair_levers, k, c0, walk, left, s)
        extends = moved <= max(walk[k, _DL] + d, margin)
    if extends:                      # covered from the left: extends the stretch
        walk[k, _HAS_L] = 1.0
        walk[k, _PL] = s
        walk[k, _DL] = d
        _levers_here(k, pair_i, pair_levers, geometries, frames, nj, per_state, walk, left)
    else:                            # a gap: this one waits on the right
        walk[k, _HAS_R] = 1.0
        walk[k, _PR] = s
        walk[k, _DR] = d
        _levers_here(k, pair_i, pair_levers, geometries, frames, nj, per_state, walk, right)
    start = walk[k, _PL]
    # After a gap, the test below is the one that just failed (same start, lever arms
    # and position): skipped.
    if extends:
        _cumulative_at(cumulative, start, c0)
    if extends and walk[k, _HAS_R] != 0.0:
        moved = _bound(cumulative, pair_i, pair_levers, k, c0, walk, left, walk[k, _PR])
        if moved <= max(walk[k, _DL] + walk[k, _DR], margin):
            walk[k, _HAS_R] = 0.0
            walk[k, _PL] = walk[k, _PR]
            walk[k, _DL] = walk[k, _DR]
            for i in range(pair_i[k, _PI_COUNT]):
                j = pair_i[k, _PI_JOINTS + i]
                walk[k, left + j] = walk[k, right + j]
            start = walk[k, _PL]
            _cumulative_at(cumulative, start, c0)
    d_left = walk[k, _DL]
    to_end = _bound(cumulative, pair_i, pair_levers, k, c0, walk, left, last)
    if walk[k, _HAS_R] != 0.0:
        # Fill the gap from the left: this step is covered whatever the distance there.
        step = max(d_left, margin)
    else:
        if to_end <= d_left:
            schedule[0, k] = np.inf  # done: its distance cannot reach 0 before the end
            schedule[1, k] = np.inf
            return
        step = max(d_left * (1.0 + gain), margin)
    due = _position_for(cumulative, pair_i, pair_levers, k, start, c0, walk, step, to_end)
    schedule[0, k] = due
    schedule[1, k] = start + (1.0 - early) * (due - start)


@jit
def _walk(joints, geometries, points, pair_i, unit_i, unit_levers, members,  # type: ignore[no-untyped-def]
          unit_from, unit_of, states, cumulative, frames, walk, schedule, picked, selected,
          distances, q, settings):
    """Walk the path through ``states`` until some pairs need an exact distance: returns
    their count (in ``selected``; the position in ``settings[_S_AT]``, its state in ``q``,
    its frames in ``frames``). The caller writes their distances to ``distances`` and
    calls again, which takes them first. Returns 0 when every pair is done, -1 for a
    contact (``settings[_S_BAD]``: its index into ``selected``), ``_NOT_FINITE`` for a
    state that is not finite (its row in ``settings[_S_BAD]``). The first call fills
    ``cumulative`` (per joint, the sum of ``|dq|`` up to each state) and resets ``walk``.

    The walk schedules units (``unit_i``, ``unit_levers``: rows like ``pair_i``'s and the
    pair lever arms, one per unit; the pairs of unit ``u`` are ``members[unit_from[u]:
    unit_from[u + 1]]``, ``unit_of`` the reverse): a unit's measurement is the least of
    its pairs' lower bounds. Pairs whose cheap lower bound is at least ``settings[4]``
    take it as their measurement."""
    nj = joints.shape[0]
    n, nq = states.shape
    if settings[_S_STARTED] == 0.0:
        settings[_S_STARTED] = 1.0
        for i in range(n):
            for j in range(nq):
                if not math.isfinite(states[i, j]):
                    settings[_S_BAD] = i
                    return _NOT_FINITE
        for j in range(nq):
            cumulative[0, j] = 0.0
        for i in range(1, n):
            for j in range(nq):
                cumulative[i, j] = cumulative[i - 1, j] + abs(states[i, j] - states[i - 1, j])
        for k in range(walk.shape[0]):
            for column in range(_COLUMNS):
                walk[k, column] = 0.0
            schedule[0, k] = 0.0                   # every unit is measured at the start
            schedule[1, k] = 0.0
        for g in range(geometries.shape[0]):
            frames[nj + g, _FR_PLACED] = -1.0      # not placed
    c0 = np.empty(nq)
    per_state = settings[_S_PER_STATE] != 0.0
    cheap_from = settings[4]
    exact_from = settings[_S_EXACT_FROM]
    slack = settings[1]
    s = settings[_S_AT]
    # First the exact distances the caller measured (if any): each unit whose pairs are all
    # in takes the least distance as its measurement.
    count = int(settings[_S_PENDING])
    settings[_S_PENDING] = 0.0
    for i in range(count):
        k = selected[i]
        d = distances[i] - slack
        if not d > 0.0:  # also NaN
            settings[_S_BAD] = i
            return -1
        u = unit_of[k]
        if d < walk[u, _UMIN]:
            walk[u, _UMIN] = d
        walk[u, _UPENDING] -= 1.0
    for i in range(count):
        u = unit_of[selected[i]]
        if walk[u, _UPENDING] == 0.0:
            walk[u, _UPENDING] = -1.0  # measured once
            _measure(u, walk[u, _UMIN], s, cumulative, unit_i, unit_levers, geometries, frames, nj,
                     walk, schedule, c0, settings)
    # Then on along the path.
    while True:
        picks, s = _pick(walk, schedule, picked, states, q)
        if picks == 0:
            return 0
        settings[_S_AT] = s
        if per_state:
            joint_frames(q, joints, frames)
            settings[_S_STATES] += 1.0
        stamp = settings[_S_STATES]
        exact = 0
        for i in range(picks):
            u = picked[i]
            least = np.inf
            pending = 0
            first, last = unit_from[u], unit_from[u + 1]
            if not per_state:
                for m in range(first, last):
                    selected[exact] = members[m]
                    exact += 1
                    pending += 1
                walk[u, _UMIN] = least
                walk[u, _UPENDING] = pending
                continue
            # The pairs' bounding sphere gaps first (``distances`` serves as scratch: the
            # caller's distances were taken above); then, from the nearest on, the full
            # bound of each pair whose gap is below the least bound so far: the others'
            # bounds (at least their gap) cannot lower the unit's measurement.
            nearest = first
            for m in range(first, last):
                k = members[m]
                a, b = pair_i[k, _PI_FIRST], pair_i[k, _PI_SECOND]
                if frames[nj + a, _FR_PLACED] < stamp:
                    _place(a, geometries, frames, nj, stamp)
                if frames[nj + b, _FR_PLACED] < stamp:
                    _place(b, geometries, frames, nj, stamp)
                distances[m] = _sphere_gap(a, b, geometries, frames, nj)
                if distances[m] < distances[nearest]:
                    nearest = m
            for t in range(first - 1, last):
                m = nearest if t < first else t
                if (t >= first and m == nearest) or distances[m] >= least:
                    continue
                k = members[m]
                a, b = pair_i[k, _PI_FIRST], pair_i[k, _PI_SECOND]
                d = _lower_bound(a, b, geometries, frames, nj)
                if d < cheap_from or not d > 0.0:
                    bound = _support_bound(a, b, geometries, frames, points, nj)
                    if bound > d:
                        d = bound
                    if not (bound > -np.inf and d >= exact_from):
                        selected[exact] = k
                        exact += 1
                        pending += 1
                        continue
                    settings[_S_SUPPORTS] += 1.0
                settings[_S_BOUNDS] += 1.0
                if d < least:
                    least = d
            if pending == 0:
                _measure(u, least, s, cumulative, unit_i, unit_levers, geometries, frames, nj, walk,
                         schedule, c0, settings)
            else:
                walk[u, _UMIN] = least
                walk[u, _UPENDING] = pending
        if exact > 0:
            settings[_S_PENDING] = exact
            return exact


@jit
def _segment_bounds(cumulative, geometries, pair_i, pair_levers, frames, nj, per_state, out):  # type: ignore[no-untyped-def]
    """Per pair, the motion bound from the first state to the second (``cumulative``:
    their cumulative joint motion), lever arms taken at the first (its ``frames``)."""
    nq = cumulative.shape[1]
    walk = np.zeros((pair_i.shape[0], _COLUMNS + 2 * nq))
    c0 = np.zeros(nq)
    for k in range(pair_i.shape[0]):
        _levers_here(k, pair_i, pair_levers, geometries, frames, nj, per_state, walk, _COLUMNS)
        out[k] = _bound(cumulative, pair_i, pair_levers, k, c0, walk, _COLUMNS, 1.0)


@jit
def _lower_bounds(pair_i, geometries, frames, nj, out):  # type: ignore[no-untyped-def]
    """Per pair, :func:`_lower_bound` at the state of ``frames``."""
    for k in range(pair_i.shape[0]):
        out[k] = _lower_bound(pair_i[k, _PI_FIRST], pair_i[k, _PI_SECOND], geometries,
                              frames, nj)


@jit
def _support_bounds(pair_i, geometries, frames, points, nj, out):  # type: ignore[no-untyped-def]
    """Per pair, :func:`_support_bound` at the state of ``frames``."""
    for k in range(pair_i.shape[0]):
        out[k] = _support_bound(pair_i[k, _PI_FIRST], pair_i[k, _PI_SECOND], geometries,
                                frames, points, nj)


@jit
def _group_pairs(pair_i, pair_levers, unit_of, representative):  # type: ignore[no-untyped-def]
    """Sort the pairs into units of pairs whose motion bound is the same function (the
    same joints counting, each with the same code, moved geometry and lever arms; the
    codes may all name the other body, which bounds alike): ``unit_of[k]`` is pair ``k``'s
    unit, ``representative[u]`` the first pair of unit ``u``. Returns the count of units.
    A link and each world object form such pairs: one unit per link."""
    nq = pair_levers.shape[1]
    units = 0
    for k in range(pair_i.shape[0]):
        count = pair_i[k, _PI_COUNT]
        found = -1
        for u in range(units):
            r = representative[u]
            if pair_i[r, _PI_COUNT] != count:
                continue
            same = True
            for j in range(nq):
                if pair_levers[r, j] != pair_levers[k, j]:
                    same = False
                    break
            if not same:
                continue
            flip = count > 0 and (pair_i[r, _PI_JOINTS + nq] % 2) != (pair_i[k, _PI_JOINTS + nq] % 2)
            for i in range(count):
                code_r = pair_i[r, _PI_JOINTS + nq + i]
                code_k = pair_i[k, _PI_JOINTS + nq + i]
                if flip:
                    code_k = code_k + 1 if code_k % 2 == 1 else code_k - 1
                if (pair_i[r, _PI_JOINTS + i] != pair_i[k, _PI_JOINTS + i] or code_r != code_k
                        or pair_i[r, _PI_JOINTS + 2 * nq + i] != pair_i[k, _PI_JOINTS + 2 * nq + i]
                        or pair_i[r, _PI_JOINTS + 3 * nq + i] != pair_i[k, _PI_JOINTS + 3 * nq + i]):
                    same = False
                    break
            if same:
                found = u
                break
        if found < 0:
            representative[units] = k
            found = units
            units += 1
        unit_of[k] = found
    return units


@jit
def _pair_rows(first, second, levers, order, revolute, state_joint, supported,  # type: ignore[no-untyped-def]
               pair_levers, pair_i):
    """Per pair, its lever arms (``pair_levers``) and its row of ``pair_i``.

    Joints moving both bodies of a pair move them rigidly together: they do not count;
    a joint that moves one body only counts with that body's lever arm. The joints that
    count are listed deepest in the tree first, with their codes: 1 or 2 if the joint
    moves the pair's first or second body only, 3 or 4 likewise for a revolute joint
    whose lever arm is taken per state (``supported``). The joints of the same body
    deeper in the tree lie between such a joint and the body: they move the body relative
    to its axis, so its lever arm grows by at most what they contribute."""
    nq = levers.shape[1]
    for k in range(first.shape[0]):
        a, b = first[k], second[k]
        pair_i[k, _PI_FIRST] = a
        pair_i[k, _PI_SECOND] = b
        count = 0
        for index in range(nq):
            j = order[index]
            moves_a = levers[a, j] > 0.0
            moves_b = levers[b, j] > 0.0
            if moves_a == moves_b:
                continue
            owner = a if moves_a else b
            pair_levers[k, j] = levers[owner, j]
            code = 1 if moves_a else 2
            if supported and revolute[j] != 0:
                code += 2
            pair_i[k, _PI_JOINTS + count] = j
            pair_i[k, _PI_JOINTS + nq + count] = code
            pair_i[k, _PI_JOINTS + 2 * nq + count] = owner
            pair_i[k, _PI_JOINTS + 3 * nq + count] = state_joint[j]
            count += 1
        pair_i[k, _PI_COUNT] = count
