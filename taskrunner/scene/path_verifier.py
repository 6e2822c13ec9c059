"""Exact collision checking of joint-space paths by conservative advancement.

A path is a polyline in the state space (rad or m). Over a stretch of it, every point of
a collision geometry moves by at most ``sum_j r_j |dq_j|``, where ``r_j`` is the *lever
arm* of joint ``j`` for that geometry (a bound on the distance from the joint's axis to
any point of the geometry) and a prismatic joint moves it by ``|dq_j|``; for a pair of
bodies only the joints that move one and not the other count (the others move both
rigidly together). :func:`~taskrunner.collision.tree.lever_arms` gives full-reach lever arms, valid anywhere
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
``B`` is the same function (the same joints move one body and not the other, with the
same lever arms: a link and each of the world objects) are walked as one *unit*: its
measurement is the least of its pairs' lower bounds, a lower bound on each pair's
distance, so the coverage above holds for every pair of it, and a link near one shelf
board of ten is scheduled once, not ten times. Units due at nearby positions share one
forward kinematics (a geometry is placed only when a pair of it is measured). A
measurement is a lower bound on the distance: far pairs take a cheap one, computed in
compiled code (bounding spheres, bounding boxes: see
:func:`taskrunner.scene.distance_bounds._lower_bound`); below :data:`CHEAP_FROM`, a pair
of boxes and convex hulls takes the separation of the shapes themselves along their
boxes' face normals and a few directions of Gilbert's iteration (exact support functions:
:func:`taskrunner.scene.distance_bounds._support_bound`; a triangle mesh, whose one hull
bridges its hollows, by the least over its convex pieces, which together hold its surface:
:mod:`taskrunner.scene.mesh_pieces`) when that is at least :data:`EXACT_FROM`; only
otherwise does the verifier ask coal for the exact distance of the scene checker's geometry.
The walk runs compiled (numba, ``cache=True``: compiled once per machine), in one call
until some pairs need coal's distance and again after each such round
(:func:`taskrunner.scene.advancement._walk`). The robot's joint tree and the rows of its
links' geometry (lever arms, bounding volumes) are kept per robot model, with
those of primitive scene shapes, so that the verifier of a new scene revision builds only
what changed (:mod:`taskrunner.scene.geometry_records`).

Guarantee (for the polyline, with the scene's geometry, allowances applied): if
:meth:`PathVerifier.verify` accepts a path, every measured pair was more than 1 µm apart
(coal's GJK tolerance is subtracted from every exact distance), and between measurements
no pair can penetrate deeper than ``margin / 2`` (m); wherever the two measurements
around a position summed more than the motion between them, the pair cannot touch there.
"""

from __future__ import annotations

import copy
import math
import threading
import time
import weakref
from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from taskrunner.collision.geometry import GEOMETRY
from taskrunner.errors import ArgumentError
from taskrunner.robot import RobotModel
from taskrunner.scene.advancement import (
    _COLUMNS,
    _NOT_FINITE,
    _PI_JOINTS,
    _PL,
    _S_AT,
    _S_BAD,
    _S_BOUNDS,
    _S_CLEARANCE,
    _S_COUNT,
    _S_EXACT_FROM,
    _S_PER_STATE,
    _S_STATES,
    _group_pairs,
    _lower_bounds,
    _pair_rows,
    _segment_bounds,
    _support_bounds,
    _walk,
)
from taskrunner.scene.collision import VERIFY_MARGIN, CollisionChecker, RobotGeometry
from taskrunner.scene.distance_bounds import _SHAPE_HULL, _farthest_point_centre
from taskrunner.scene.geometry_records import _Kinematics, _Tree, _tree

if TYPE_CHECKING:
    import pinocchio as pin

__all__ = ["CHEAP_FROM", "EXACT_FROM", "GAIN", "PathVerification", "PathVerifier", "full_states"]

_DISTANCE_SLACK = 1e-6  # m: GJK's distance tolerance; measured distances are reduced by it
_EARLY = 0.25  # a pair due within this fraction of its step is measured with the others
GAIN = 1.0  # optimistic step: (1 + GAIN) times the last distance (see the module's text)

CHEAP_FROM = 0.01  # m: a pair whose cheap lower bound is at least this takes it, not coal's
# m: below CHEAP_FROM, a pair of boxes and convex hulls takes the bound from their support
# functions (:func:`_support_bound`) if it is at least this; coal's distance otherwise.
EXACT_FROM = 0.001


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
        pair_index: the contact's pair, as an index into the checker's collision pairs;
            None for a valid path.
        covered: where the contact's pair was last measured free with the stretch before
            it covered (a path position like ``fraction``): the pair first comes closer
            than the clearance between there and ``fraction``. None for a valid path.
    """

    valid: bool
    distance_queries: int
    states: int
    seconds: float
    fraction: float | None = None
    pair: tuple[str, str] | None = None
    state: np.ndarray | None = None
    bounds: int = 0
    pair_index: int | None = None
    covered: float | None = None


Observer = Callable[[float, np.ndarray, np.ndarray], None]
"""Called by :meth:`PathVerifier.verify` after each round of coal's exact distances: the
path position, the pairs measured (indices into the checker's collision pairs) and their
distances (m, as coal gives them). Both arrays are the verifier's own: copy to keep."""


class PathVerifier:
    """Verifies paths against one collision checker (one scene revision).

    Args:
        robot: the robot model.
        checker: the scene's checker (its geometry and pairs, allowances applied).
        margin: m; where two measurements of a pair do not cover the motion between them
            by distance, they must be less than this apart in motion bound (both free);
            twice the deepest penetration the verification can miss there.
        pairs: the pairs to verify, as indices into the checker's collision pairs
            (default: all of them), e.g. only the pairs of bodies of two arms moving at
            once (:mod:`taskrunner.collision.spacetime`).
        grouped: pairs that move alike are walked as one unit (see the module's text);
            False: each pair is its own unit (where few pairs would share one, as
            between two arms, the grouping costs more than it saves).

    What depends on the robot alone (its joint tree, the lever arms and bounding volumes
    of its links' geometry) is kept per robot model and reused by the verifiers of later
    scene revisions; only the world and attached objects and the pairs are built anew.
    The exact distances are the checker's (:meth:`CollisionChecker.pair_distances`, on
    its own pinocchio data: no second copy of coal's per-pair solvers is made), so a
    verifier is used like its checker, by one thread at a time.
    """

    def __init__(self, robot: RobotModel, checker: CollisionChecker,
                 margin: float = VERIFY_MARGIN, pairs: np.ndarray | None = None,
                 grouped: bool = True) -> None:
        if not (math.isfinite(margin) and margin > 0):
            raise ArgumentError(f"'margin' must be a positive number of metres (got {margin!r})")
        self.robot = robot
        self.margin = margin
        self._checker = checker
        self._geometry = checker.geometry_model
        tree = _tree(robot)
        self._tree = tree
        # The robot's links' rows are the same in every checker built from its geometry:
        # kept with it; only the scene's objects' rows are built here.
        part = checker.robot_geometry
        links = _LINK_ROWS.get(part)
        objects = self._geometry.geometryObjects
        if links is None or links.tree is not tree:
            links = _LINK_ROWS[part] = _rows(tree, [objects[g]
                                                    for g in range(part.geometry_count)])
        rest = _rows(tree, [objects[g] for g in range(part.geometry_count, len(objects))])
        self._geometry_names = links.names + rest.names
        self._levers = np.vstack([links.levers, rest.levers])
        # The scene's geometry objects' records (their indices are the collision model's),
        # then their meshes' convex pieces' (each part's points and pieces were numbered
        # from 0: moved to where its rows land here).
        rest_rows, rest_pieces = rest.geometries, rest.pieces
        if len(rest.points) and len(links.points):
            rest_rows, rest_pieces = rest_rows.copy(), rest_pieces.copy()
            for rows in (rest_rows, rest_pieces):
                rows["first_point"][rows["point_count"] > 0] += len(links.points)
        n_objects = len(links.names) + len(rest.names)
        geometries = _joined((links.geometries, rest_rows, links.pieces, rest_pieces))
        ranges = np.vstack([links.ranges, rest.ranges,
                            np.zeros((len(links.pieces) + len(rest.pieces), 2), dtype=np.int64)])
        ranges[:len(links.names), 0] += n_objects
        ranges[len(links.names):n_objects, 0] += n_objects + len(links.pieces)
        ranges[ranges[:, 1] == 0, 0] = 0
        # Per geometry, its pieces' first record and count; None without any (the kernels
        # are then compiled without the pieces' code: see advancement._walk).
        self._pieces: np.ndarray | None = ranges if ranges[:, 1].any() else None
        self._objects = n_objects
        # The links' hull points serve as they are where the scene's objects have none (boxes,
        # cylinders, spheres): no copy per scene revision.
        self._points = (np.ascontiguousarray(np.vstack([links.points, rest.points]))
                        if len(rest.points) else links.points)
        self._geometries = geometries
        self._every = checker.pair_geometries
        self._kinematics = _Kinematics(tree, self._geometries)
        self._use_pairs(np.arange(len(self._every), dtype=np.int64) if pairs is None
                        else self._pair_indices(pairs), grouped)

    def _pair_indices(self, pairs: np.ndarray) -> np.ndarray:
        ids = np.asarray(pairs, dtype=np.int64).reshape(-1)
        if len(ids) and not (0 <= ids.min() and ids.max() < len(self._every)):
            raise ArgumentError(f"'pairs' must index the checker's {len(self._every)} "
                                f"collision pairs")
        return ids

    def restricted(self, pairs: np.ndarray | None = None, grouped: bool = True,
                   margin: float | None = None) -> PathVerifier:
        """A verifier of ``pairs`` (indices into the checker's collision pairs; default:
        all of them) of this one's checker, with ``margin`` (default: this one's): it
        shares this one's geometry rows and kinematics (and, like it, the checker: one
        thread at a time); only the pairs' rows are built. ``grouped``: pairs that move
        alike are walked as one unit (see the module's text; False: each pair its own
        unit, where few would share one)."""
        if margin is not None and not (math.isfinite(margin) and margin > 0):
            raise ArgumentError(f"'margin' must be a positive number of metres (got {margin!r})")
        other = copy.copy(self)
        if margin is not None:
            other.margin = margin
        other._use_pairs(np.arange(len(self._every), dtype=np.int64) if pairs is None
                         else self._pair_indices(pairs), grouped)
        return other

    def _use_pairs(self, ids: np.ndarray, grouped: bool = True) -> None:
        """Build the rows of the pairs ``ids`` (indices into the checker's collision pairs),
        their units, the settings and the work arrays."""
        self._pair_ids = ids
        first = self._every[ids, 0].copy()
        second = self._every[ids, 1].copy()
        self._first, self._second = first, second
        rows = _pair_units(self._tree, self.robot.nq, first, second, self._levers, grouped)
        self._pair_levers, self._pair_i = rows.pair_levers, rows.pair_i
        self._unit_of, self._members, self._unit_from = rows.unit_of, rows.members, rows.unit_from
        self._unit_i, self._unit_levers = rows.unit_i, rows.unit_levers
        tree = self._tree
        self._settings = np.zeros(_S_COUNT)
        self._settings[:5] = (self.margin, _DISTANCE_SLACK, GAIN, _EARLY,
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
        convex hulls, a mesh's convex pieces; ``-inf`` for other shapes or without compiled
        kinematics): where positive, the pair is at least that far apart."""
        out = np.full(len(self._first), -np.inf)
        if not self._tree.supported:
            return out
        kin = self._kinematics
        frames = kin.frames(np.asarray(q, dtype=float))
        pieces = (self._pieces if self._pieces is not None
                  else np.zeros((len(self._geometries), 2), dtype=np.int64))
        _support_bounds(self._pair_i, self._geometries, frames, self._points, pieces,
                        kin.joints.shape[0], out)
        return out

    def verify(self, states: np.ndarray, clearance: float = 0.0, exact: bool = False,
               observe: Observer | None = None, gain: float = GAIN) -> PathVerification:
        """Verify the polyline through full state vectors ``states`` (``(n, nq)``).

        Args:
            clearance: m; a pair measured closer than this is a contact, and between
                measurements the pairs keep it (the bodies are verified as grown by it;
                the module's guarantee holds for them).
            exact: every measurement is coal's exact distance (no cheap lower bounds),
                so that the least distance an ``observe`` sees is the least measured.
            observe: called after each round of exact distances (:data:`Observer`).
            gain: how far past a measurement the next one is tried (see the module's
                text). 0: each measurement is where the last one's coverage ends, so
                that every pair is proven free up to where the walk has come: the
                contact found is then the first along the path, to within one step of
                its pair (the pairs measured at that position: the first of them).

        Returns:
            A :class:`PathVerification`; ``valid`` False names a contact found.
        """
        if not (math.isfinite(clearance) and clearance >= 0):
            raise ArgumentError(f"'clearance' must be a number of metres >= 0 "
                                f"(got {clearance!r})")
        if not (math.isfinite(gain) and gain >= 0):
            raise ArgumentError(f"'gain' must be a number >= 0 (got {gain!r})")
        t0 = time.perf_counter()
        states = full_states(states, self.robot.nq)
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
            settings[_S_CLEARANCE] = clearance
            settings[2] = gain
            if exact:
                settings[4] = settings[_S_EXACT_FROM] = np.inf
            kin = self._kinematics
            walked = (kin.joints, self._geometries, self._points, self._pieces,
                      self._pair_i, self._unit_i, self._unit_levers, self._members,
                      self._unit_from, self._unit_of, states, cumulative, frames, walk,
                      schedule, picked, selected, distances, q, settings)
            queries = evaluated = 0
            pair_distances, to_pin = self._checker.pair_distances, self.robot.to_pin
            ids = self._pair_ids
            while True:
                count = _walk(*walked)
                if count <= 0:
                    break
                measured = ids[selected[:count]]
                pair_distances(to_pin(q), measured.tolist(), distances)
                if observe is not None:
                    observe(float(settings[_S_AT]), measured, distances[:count])
                evaluated += 1
                queries += count
            if count == _NOT_FINITE:
                row = int(settings[_S_BAD])
                raise ArgumentError(f"state {row} of the path to verify is not finite: {states[row]}")
            states_count = max(evaluated, int(settings[_S_STATES]))
            if count < 0:
                bad = int(selected[int(settings[_S_BAD])])
                unit = int(self._unit_of[bad])
                return PathVerification(False, queries, states_count, time.perf_counter() - t0,
                                        float(settings[_S_AT]), self._pair_name(bad), q.copy(),
                                        int(settings[_S_BOUNDS]), int(ids[bad]),
                                        float(walk[unit, _PL]))
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
                np.zeros(n_pairs), np.zeros(nq), self._kinematics.buffer(),
                np.zeros(_S_COUNT))


@dataclass(frozen=True)
class _Rows:
    """Geometry rows of some geometry objects: names, lever arms ``(n, nq)``, records
    (:data:`GEOMETRY`, ``first_point`` into ``points``), hull points ``(m, 3)``, the
    records of their meshes' convex pieces (their points in ``points`` too) and per object
    the first of its pieces and their count ``(n, 2)``."""

    tree: object
    names: list[str]
    levers: np.ndarray
    geometries: np.ndarray
    points: np.ndarray
    pieces: np.ndarray
    ranges: np.ndarray


# Per robot geometry (immutable once built; kept while it lives): its links' rows.
_LINK_ROWS: weakref.WeakKeyDictionary[RobotGeometry, _Rows] = weakref.WeakKeyDictionary()


@dataclass(frozen=True)
class _PairUnits:
    """The rows of some pairs of geometry objects and their units (see
    :meth:`PathVerifier._use_pairs`). Shared by the verifiers of every scene revision
    with the same pairs: read, never written."""

    pair_levers: np.ndarray
    pair_i: np.ndarray
    unit_of: np.ndarray
    members: np.ndarray
    unit_from: np.ndarray
    unit_i: np.ndarray
    unit_levers: np.ndarray


# Per robot tree, the pairs' rows of its latest verifiers, by content: the pairs'
# geometries, every geometry's lever arms and the grouping. Two arms' verifiers of
# successive scene revisions mostly walk the same pairs: an object picked by one arm and
# placed back adds and removes the same ones.
_PAIR_UNITS: weakref.WeakKeyDictionary[_Tree, dict[bytes, _PairUnits]] = \
    weakref.WeakKeyDictionary()
_PAIR_UNITS_KEPT = 12


def _pair_units(tree: _Tree, nq: int, first: np.ndarray, second: np.ndarray,
                levers: np.ndarray, grouped: bool) -> _PairUnits:
    """The rows of the pairs ``(first[k], second[k])`` (geometry indices) with the
    geometries' lever arms ``levers``, and their units (:func:`_group_pairs`; each pair
    its own unit unless ``grouped``): kept per tree, the :data:`_PAIR_UNITS_KEPT` latest."""
    key = b"".join((b"g" if grouped else b"-", np.int64(len(first)).tobytes(),
                    first.tobytes(), second.tobytes(), np.ascontiguousarray(levers).tobytes()))
    kept = _PAIR_UNITS.get(tree)
    if kept is None:
        kept = _PAIR_UNITS[tree] = {}
    found = kept.pop(key, None)
    if found is None:
        pair_levers = np.zeros((len(first), nq))
        pair_i = np.zeros((len(first), _PI_JOINTS + 4 * nq), dtype=np.int64)
        _pair_rows(first, second, levers, tree.order, tree.revolute, tree.state_joint,
                   tree.supported, pair_levers, pair_i)
        # Pairs that move alike (a link and each world object: the same joints, lever
        # arms) are walked as one unit, measured together, their least distance its
        # measurement.
        unit_of = np.arange(len(first), dtype=np.int64)
        representative = unit_of.copy()
        units = (_group_pairs(pair_i, pair_levers, unit_of, representative)
                 if grouped else len(first))
        unit_from = np.zeros(units + 1, dtype=np.int64)
        np.cumsum(np.bincount(unit_of, minlength=units), out=unit_from[1:])
        found = _PairUnits(pair_levers, pair_i, unit_of,
                           np.argsort(unit_of, kind="stable").astype(np.int64), unit_from,
                           pair_i[representative[:units]].copy(),
                           pair_levers[representative[:units]].copy())
        if len(kept) >= _PAIR_UNITS_KEPT:
            kept.pop(next(iter(kept)))
    kept[key] = found  # the latest last
    return found


_RAW = np.dtype((np.void, GEOMETRY.itemsize))


def _joined(parts: tuple[np.ndarray, ...]) -> np.ndarray:
    """Geometry records of ``parts`` one after the other: their bytes joined (NumPy's
    concatenation of a structured dtype goes field by field, ~10x slower)."""
    return np.concatenate([part.view(_RAW) for part in parts]).view(GEOMETRY)


def _rows(tree: _Tree, objects: list[pin.GeometryObject]) -> _Rows:
    """The rows of ``objects`` (:meth:`_Tree.record` of each)."""
    records = [tree.record(obj) for obj in objects]
    geometries = np.zeros(len(records), dtype=GEOMETRY)
    hulls = []
    start = 0
    for g, r in enumerate(records):
        geometries[g] = r.geometry
        if r.points is not None:
            geometries["first_point"][g] = start
            geometries["point_count"][g] = len(r.points)
            start += len(r.points)
            hulls.append(r.points)
    pieces = np.zeros(sum(len(r.pieces) for r in records), dtype=GEOMETRY)
    ranges = np.zeros((len(records), 2), dtype=np.int64)
    p = 0
    for g, r in enumerate(records):
        ranges[g] = (p, len(r.pieces))
        for points in r.pieces:
            pieces[p] = _piece_record(geometries[g], points, start)
            start += len(points)
            hulls.append(points)
            p += 1
    levers = np.array([r.levers for r in records]).reshape(len(records), tree.nq)
    return _Rows(tree, [r.name for r in records], levers, geometries,
                 np.vstack(hulls) if hulls else np.zeros((0, 3)), pieces, ranges)


def _piece_record(parent: np.ndarray, points: np.ndarray, first_point: int) -> np.ndarray:
    """The record of a convex piece of mesh ``parent`` (its record): the hull of
    ``points`` (the mesh's frame), on the mesh's joint and placement, with its own
    bounding sphere and box; its vertices are rows ``first_point`` on of the points."""
    row = np.zeros((), dtype=GEOMETRY)
    row["joint"] = parent["joint"]
    row["placement"] = parent["placement"]
    row["shape"] = _SHAPE_HULL
    row["first_point"] = first_point
    row["point_count"] = len(points)
    low, high = points.min(axis=0), points.max(axis=0)
    row["has_box"] = 1
    row["half"] = 0.5 * (high - low)
    row["box"] = 0.5 * (high + low)
    centre = np.ascontiguousarray(row["box"], dtype=float).copy()
    reach = _farthest_point_centre(np.ascontiguousarray(points), centre, 100)
    row["centre"] = centre
    row["radius"] = reach * (1.0 + 1e-12) + 1e-12  # rounding: never inside a vertex
    return row


def full_states(states: np.ndarray, nq: int) -> np.ndarray:
    """``states`` as an ``(n, nq)`` float array of full state vectors (one vector: one
    row).

    Raises:
        ArgumentError: another shape, or no state.
    """
    states = np.asarray(states, dtype=float)
    if states.ndim == 1:
        states = states[None, :]
    if states.ndim != 2 or states.shape[1] != nq or len(states) == 0:
        raise ArgumentError(f"states must be an (n, {nq}) array of full state "
                            f"vectors (got shape {states.shape})")
    return states
