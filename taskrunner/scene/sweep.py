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
left (each is covered whatever it measures: the walk always advances). Pairs due at
nearby positions share one forward kinematics. A measurement is a lower bound on the
distance: far pairs take a cheap one, computed in compiled code (bounding spheres,
bounding boxes: see :func:`_lower_bound`); only below :data:`CHEAP_FROM` does
the verifier ask coal for the exact distance of the scene checker's geometry. The walk
runs compiled (numba, ``cache=True``: compiled once per machine).

Guarantee (for the polyline, with the scene's geometry, allowances applied): if
:meth:`PathVerifier.verify` accepts a path, every measured pair was more than 1 µm apart
(coal's GJK tolerance is subtracted from every exact distance), and between measurements
no pair can penetrate deeper than ``margin / 2`` (m); wherever the two measurements
around a position summed more than the motion between them, the pair cannot touch there.
"""

from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass

import coal
import numpy as np
import pinocchio as pin

from taskrunner.resources import user_cache_dir
from taskrunner.robot import RobotModel
from taskrunner.scene.collision import CollisionChecker

if not os.environ.get("NUMBA_CACHE_DIR"):
    # Before numba's import: an installed package's own folder may be read-only.
    os.environ["NUMBA_CACHE_DIR"] = str(user_cache_dir() / "numba")

import numba

if not numba.config.CACHE_DIR:  # type: ignore[attr-defined]  # numba was imported first
    numba.config.CACHE_DIR = os.environ["NUMBA_CACHE_DIR"]  # type: ignore[attr-defined]

__all__ = ["CHEAP_FROM", "GAIN", "PathVerification", "PathVerifier", "lever_arms"]

_DISTANCE_SLACK = 1e-6  # m: GJK's distance tolerance; measured distances are reduced by it
_EARLY = 0.25  # a pair due within this fraction of its step is measured with the others
GAIN = 1.0  # optimistic step: (1 + GAIN) times the last distance (see the module's text)
_BISECTIONS = 12  # at most this many evaluations to place a step inside a segment
_CLOSE = 0.02  # a step placed within this fraction short of its bound is close enough

# Columns of the per-pair walk state (a float array, one row per pair).
_HAS_L, _PL, _DL, _HAS_R, _PR, _DR, _DUE, _EARLY_AT, _DONE = range(9)
_COLUMNS = 9
_REVOLUTE, _PRISMATIC = 1, 2
CHEAP_FROM = 0.01  # m: a pair whose cheap lower bound is at least this takes it, not coal's


def lever_arms(robot: RobotModel, geometry_model: pin.GeometryModel) -> np.ndarray:
    """Per geometry object and state-vector joint, a bound on how far the joint moves it.

    Returns:
        ``(n_geometries, robot.nq)``: for a revolute or continuous joint, an upper bound
        (m/rad) on the distance from its axis to any point of the geometry (through the
        chain at full reach: joint offsets plus the full travel of prismatic joints in
        between, then the geometry's bounding sphere); for a prismatic joint 1 (m/m);
        0 where the joint does not move the geometry (world objects, other branches).
    """
    model = robot.model
    levers = np.zeros((len(geometry_model.geometryObjects), robot.nq))
    state_index: dict[int, int] = {}
    prismatic = set()
    prismatic_travel = np.zeros(model.njoints)
    for joint in robot.joints:
        jid = int(model.getJointId(joint.name))
        state_index[jid] = joint.index
        if joint.type == "prismatic":
            prismatic.add(jid)
            prismatic_travel[jid] = max(abs(joint.lower), abs(joint.upper))
    for g, geometry_object in enumerate(geometry_model.geometryObjects):
        geometry = geometry_object.geometry
        geometry.computeLocalAABB()
        centre = geometry_object.placement.act(np.asarray(geometry.aabb_center, dtype=float))
        reach = float(np.linalg.norm(centre)) + float(geometry.aabb_radius)
        jid = int(geometry_object.parentJoint)
        while jid > 0:
            if jid in state_index:
                levers[g, state_index[jid]] = 1.0 if jid in prismatic else reach
            # Reach from the parent joint's origin: this joint's offset and travel added.
            reach += float(np.linalg.norm(model.jointPlacements[jid].translation))
            reach += prismatic_travel[jid]
            jid = int(model.parents[jid])
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
        bounds: cheap lower bounds taken instead of an exact distance (far pairs).
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
    """

    def __init__(self, robot: RobotModel, checker: CollisionChecker,
                 margin: float = 5e-4) -> None:
        if not (math.isfinite(margin) and margin > 0):
            raise ValueError(f"'margin' must be a positive number of metres (got {margin!r})")
        self.robot = robot
        self.margin = margin
        self._geometry = checker.geometry_model
        self._geometry_data = self._geometry.createData()
        for request in self._geometry_data.distanceRequests:
            request.enable_signed_distance = True
        self._data = robot.model.createData()
        levers = lever_arms(robot, self._geometry)
        moves = levers > 0
        pairs = [(p.first, p.second) for p in self._geometry.collisionPairs]
        self._names = [(self._geometry.geometryObjects[i].name,
                        self._geometry.geometryObjects[j].name) for i, j in pairs]
        first = np.array([i for i, _ in pairs], dtype=np.int64)
        second = np.array([j for _, j in pairs], dtype=np.int64)
        nq = robot.nq
        # Joints moving both bodies of a pair move them rigidly together: they do not count.
        self._pair_levers = np.ascontiguousarray(
            levers[first] * ~moves[second] + levers[second] * ~moves[first]) if pairs \
            else np.zeros((0, nq))
        # Whose lever arm counts for each pair and joint: the body that joint moves.
        self._owner = np.full((len(pairs), nq), -1, dtype=np.int64)
        if pairs:
            self._owner[moves[first] & ~moves[second]] = np.broadcast_to(
                first[:, None], (len(pairs), nq))[moves[first] & ~moves[second]]
            self._owner[moves[second] & ~moves[first]] = np.broadcast_to(
                second[:, None], (len(pairs), nq))[moves[second] & ~moves[first]]
        self._first, self._second = first, second
        self._kinematics = _Kinematics(robot, self._geometry, levers)
        self._below = self._kinematics.below(self._owner, first)
        self._order = self._kinematics.deepest_first()

    @property
    def pair_levers(self) -> np.ndarray:
        """``(n_pairs, nq)``: how far each joint can move one body of a pair relative to
        the other (m/rad, m/m), per unit of joint motion, anywhere (at full reach)."""
        return self._pair_levers

    @property
    def configuration_dependent(self) -> bool:
        """True when lever arms are taken at each measured state (every joint of the
        robot is revolute, continuous or prismatic); else the full-reach bounds serve."""
        return self._kinematics.supported

    def segment_bounds(self, a: np.ndarray, b: np.ndarray) -> np.ndarray:
        """Per pair, the bound (m) the verifier uses on how far any point of one body
        moves relative to the other along the straight segment from state ``a`` to ``b``
        (lever arms taken at ``a``)."""
        states = np.ascontiguousarray(np.vstack([a, b]).astype(float))
        cumulative = np.zeros_like(states)
        cumulative[1] = np.abs(states[1] - states[0])
        n_pairs = len(self._names)
        nq = self.robot.nq
        lever_rows = np.zeros((n_pairs, nq))
        kin = self._kinematics
        frames = kin.frames(states[0])
        out = np.zeros(n_pairs)
        for k in range(n_pairs):
            if kin.supported:
                _levers_at(k, self._owner, self._pair_levers, kin.arrays, frames, lever_rows[k])
            else:
                lever_rows[k] = self._pair_levers[k]
            out[k] = _bound(cumulative, self._pair_levers, self._below, self._order, k,
                            cumulative[0], lever_rows[k], 1.0, np.zeros(nq), np.zeros(nq))
        return out

    def lower_bounds(self, q: np.ndarray) -> np.ndarray:
        """Per pair, the cheap bound on its distance (m) at state ``q`` that the verifier
        uses for far pairs (bounding spheres and boxes): where positive, the pair is at
        least that far apart. ``-inf`` without compiled kinematics."""
        kin = self._kinematics
        out = np.full(len(self._names), -np.inf)
        if not kin.supported:
            return out
        frames = kin.frames(np.asarray(q, dtype=float))
        for k in range(len(out)):
            out[k] = _lower_bound(self._first[k], self._second[k], kin.arrays, frames)
        return out

    def verify(self, states: np.ndarray) -> PathVerification:
        """Verify the polyline through full state vectors ``states`` (``(n, nq)``).

        Returns:
            A :class:`PathVerification`; ``valid`` False names a contact found.
        """
        t0 = time.perf_counter()
        states = np.ascontiguousarray(np.atleast_2d(np.asarray(states, dtype=float)))
        if states.ndim != 2 or states.shape[1] != self.robot.nq or len(states) == 0:
            raise ValueError(f"states must be an (n, {self.robot.nq}) array of full state "
                             f"vectors (got shape {states.shape})")
        if not np.isfinite(states).all():
            row = int(np.flatnonzero(~np.isfinite(states).all(axis=1))[0])
            raise ValueError(f"state {row} of the path to verify is not finite: {states[row]}")
        n_pairs = len(self._names)
        if n_pairs == 0:
            return PathVerification(True, 0, 0, time.perf_counter() - t0)
        cumulative = np.zeros_like(states)                      # per joint, sum of |dq|
        np.cumsum(np.abs(np.diff(states, axis=0)), axis=0, out=cumulative[1:])
        nq = states.shape[1]
        walk = np.zeros((n_pairs, _COLUMNS))
        lever_left = np.zeros((n_pairs, nq))
        lever_right = np.zeros((n_pairs, nq))
        selected = np.zeros(n_pairs, dtype=np.int64)
        distances = np.zeros(n_pairs)
        q = np.zeros(nq)
        kin = self._kinematics
        frames = kin.buffers()
        walked = (cumulative, self._pair_levers, self._below, self._order, self._owner,
                  self._first, self._second, walk, lever_left, lever_right)
        # margin, slack, gain, early, cheap-from; counts: compiled states, cheap bounds
        settings = np.array([self.margin, _DISTANCE_SLACK, GAIN, _EARLY,
                             CHEAP_FROM if kin.supported else np.inf, 0.0, 0.0])
        queries = evaluated = 0
        model, data = self.robot.model, self._data
        geometry, geometry_data = self._geometry, self._geometry_data
        to_pin = self.robot.to_pin
        compute = pin.computeDistance
        while True:
            count, s = _advance(walked, kin.arrays, frames, selected, states, q, kin.supported,
                                settings)
            if count == 0:
                break
            pin.updateGeometryPlacements(model, data, geometry, geometry_data, to_pin(q))
            evaluated += 1
            for i in range(count):
                distances[i] = compute(geometry, geometry_data, int(selected[i])).min_distance
            queries += count
            bad = _update(walked, kin.arrays, frames, selected, distances, count, s,
                          kin.supported, settings)
            if bad >= 0:
                return PathVerification(False, queries, max(evaluated, int(settings[5])),
                                        time.perf_counter() - t0, float(s),
                                        self._names[int(selected[bad])], q.copy(),
                                        int(settings[6]))
        return PathVerification(True, queries, max(evaluated, int(settings[5])),
                                time.perf_counter() - t0, bounds=int(settings[6]))


class _Kinematics:
    """The robot's joint tree and the bounding spheres of the collision geometry, as
    arrays for the compiled kernels (forward kinematics of revolute, continuous and
    prismatic joints; anything else leaves ``supported`` False)."""

    def __init__(self, robot: RobotModel, geometry_model: pin.GeometryModel,
                 levers: np.ndarray) -> None:
        model = robot.model
        n = model.njoints
        self.parent = np.array([int(p) for p in model.parents], dtype=np.int64)
        self.joint_kind = np.zeros(n, dtype=np.int64)
        self.state_index = np.full(n, -1, dtype=np.int64)
        self.placement_rotation = np.zeros((n, 3, 3))
        self.placement_translation = np.zeros((n, 3))
        self.axis = np.zeros((n, 3))
        self.state_joint = np.full(robot.nq, -1, dtype=np.int64)
        self.depth = np.zeros(n, dtype=np.int64)
        for joint in robot.joints:
            jid = int(model.getJointId(joint.name))
            self.state_index[jid] = joint.index
            self.state_joint[joint.index] = jid
        data = model.createData()
        pin.forwardKinematics(model, data, pin.neutral(model))
        supported = True
        for jid in range(1, n):
            placement = model.jointPlacements[jid]
            self.placement_rotation[jid] = placement.rotation
            self.placement_translation[jid] = placement.translation
            self.depth[jid] = self.depth[self.parent[jid]] + 1
            subspace = np.asarray(data.joints[jid].S, dtype=float)
            if subspace.size != 6 or "Mimic" in model.joints[jid].shortname() \
                    or self.state_index[jid] < 0:
                supported = False
                continue
            linear, angular = subspace.reshape(6)[:3], subspace.reshape(6)[3:]
            if np.linalg.norm(angular) > 0.5 and np.linalg.norm(linear) < 1e-12:
                self.joint_kind[jid] = _REVOLUTE
                self.axis[jid] = angular / np.linalg.norm(angular)
            elif np.linalg.norm(linear) > 0.5 and np.linalg.norm(angular) < 1e-12:
                self.joint_kind[jid] = _PRISMATIC
                self.axis[jid] = linear / np.linalg.norm(linear)
            else:
                supported = False
        self.supported = supported
        count = len(geometry_model.geometryObjects)
        self.geometry_joint = np.zeros(count, dtype=np.int64)
        self.geometry_rotation = np.zeros((count, 3, 3))
        self.geometry_translation = np.zeros((count, 3))
        self.geometry_centre = np.zeros((count, 3))      # bounding sphere, geometry frame
        self.geometry_radius = np.zeros(count)
        # Each geometry's bounding box in its own frame (a box geometry: itself).
        self.geometry_box = np.zeros(count, dtype=np.int64)
        self.box_half = np.zeros((count, 3))
        self.box_centre = np.zeros((count, 3))
        for g, geometry_object in enumerate(geometry_model.geometryObjects):
            geometry = geometry_object.geometry
            geometry.computeLocalAABB()
            self.geometry_joint[g] = int(geometry_object.parentJoint)
            self.geometry_rotation[g] = geometry_object.placement.rotation
            self.geometry_translation[g] = geometry_object.placement.translation
            self.geometry_centre[g], self.geometry_radius[g] = _enclosing_sphere(geometry)
            low = np.asarray(geometry.aabb_local.min_, dtype=float)
            high = np.asarray(geometry.aabb_local.max_, dtype=float)
            if np.isfinite(low).all() and np.isfinite(high).all():
                self.geometry_box[g] = 1
                self.box_half[g] = 0.5 * (high - low)
                self.box_centre[g] = 0.5 * (high + low)
        self.arrays = (self.parent, self.joint_kind, self.state_index, self.placement_rotation,
                       self.placement_translation, self.axis, self.state_joint,
                       self.geometry_joint, self.geometry_rotation, self.geometry_translation,
                       self.geometry_centre, self.geometry_radius, self.geometry_box,
                       self.box_half, self.box_centre)

    def buffers(self) -> tuple[np.ndarray, ...]:
        """Work arrays: joint rotations and origins, geometry rotations, origins and
        bounding sphere centres (world)."""
        n, count = len(self.parent), len(self.geometry_joint)
        return (np.zeros((n, 3, 3)), np.zeros((n, 3)), np.zeros((count, 3, 3)),
                np.zeros((count, 3)), np.zeros((count, 3)))

    def frames(self, q: np.ndarray) -> tuple[np.ndarray, ...]:
        """The frames of :meth:`buffers` at state ``q``."""
        frames = self.buffers()
        _forward(np.ascontiguousarray(q, dtype=float), self.arrays, frames)
        return frames

    def deepest_first(self) -> np.ndarray:
        """State joint indices, deepest in the joint tree first."""
        depth = np.array([self.depth[j] if j >= 0 else 0 for j in self.state_joint])
        return np.argsort(-depth, kind="stable").astype(np.int64)

    def below(self, owner: np.ndarray, first: np.ndarray) -> np.ndarray:
        """``(n_pairs, nq)``, per pair and joint: 0 if the joint does not count for the
        pair; 1 or 2 if it moves the pair's first or second body only; 3 or 4 likewise
        for a revolute joint whose lever arm is taken per state. The joints of the same
        body deeper in the tree lie between such a joint and the body: they move the body
        relative to its axis, so its lever arm grows by at most what they contribute."""
        n_pairs, nq = owner.shape
        out = np.where(owner < 0, 0, np.where(owner == first[:, None], 1, 2)).astype(np.int64)
        if self.supported:
            revolute = np.array([j >= 0 and self.joint_kind[j] == _REVOLUTE
                                 for j in self.state_joint])
            out[(out > 0) & revolute[None, :]] += 2
        return out


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
_jit = numba.njit(cache=True, nogil=True, error_model="numpy")


@_jit
def _forward(q, arrays, frames):  # type: ignore[no-untyped-def]
    """World frames of the joints and the geometries, and the geometry bounding sphere
    centres, at state ``q`` (into ``frames``)."""
    (parent, joint_kind, state_index, placement_rotation, placement_translation, axis, _,
     geometry_joint, geometry_rotation, geometry_translation, geometry_centre, _, _, _,
     _) = arrays
    rotations, origins, geo_rotations, geo_origins, centres = frames
    for a in range(3):
        for b in range(3):
            rotations[0, a, b] = 1.0 if a == b else 0.0
        origins[0, a] = 0.0
    local = np.zeros((3, 3))
    row = np.zeros(3)
    for jid in range(1, parent.shape[0]):
        p = parent[jid]
        # Parent frame times the joint's placement.
        for a in range(3):
            origins[jid, a] = origins[p, a]
            for b in range(3):
                origins[jid, a] += rotations[p, a, b] * placement_translation[jid, b]
                total = 0.0
                for c in range(3):
                    total += rotations[p, a, c] * placement_rotation[jid, c, b]
                rotations[jid, a, b] = total
        value = q[state_index[jid]] if state_index[jid] >= 0 else 0.0
        if joint_kind[jid] == _PRISMATIC:
            for a in range(3):
                for b in range(3):
                    origins[jid, a] += rotations[jid, a, b] * axis[jid, b] * value
        elif joint_kind[jid] == _REVOLUTE:
            # Rodrigues: the joint's rotation about its (local) axis.
            x, y, z = axis[jid, 0], axis[jid, 1], axis[jid, 2]
            c, s = math.cos(value), math.sin(value)
            t = 1.0 - c
            local[0, 0] = c + x * x * t
            local[0, 1] = x * y * t - z * s
            local[0, 2] = x * z * t + y * s
            local[1, 0] = y * x * t + z * s
            local[1, 1] = c + y * y * t
            local[1, 2] = y * z * t - x * s
            local[2, 0] = z * x * t - y * s
            local[2, 1] = z * y * t + x * s
            local[2, 2] = c + z * z * t
            for a in range(3):
                for b in range(3):
                    total = 0.0
                    for cc in range(3):
                        total += rotations[jid, a, cc] * local[cc, b]
                    row[b] = total
                for b in range(3):
                    rotations[jid, a, b] = row[b]
    for g in range(geometry_joint.shape[0]):
        jid = geometry_joint[g]
        for a in range(3):
            total = origins[jid, a]
            for b in range(3):
                total += rotations[jid, a, b] * geometry_translation[g, b]
                value = 0.0
                for c in range(3):
                    value += rotations[jid, a, c] * geometry_rotation[g, c, b]
                geo_rotations[g, a, b] = value
            geo_origins[g, a] = total
        for a in range(3):
            total = geo_origins[g, a]
            for b in range(3):
                total += geo_rotations[g, a, b] * geometry_centre[g, b]
            centres[g, a] = total


@_jit
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


@_jit
def _levers_at(k, owner, pair_levers, arrays, frames, out):  # type: ignore[no-untyped-def]
    """Pair ``k``'s lever arms at the state of ``frames``: for a revolute joint, the
    distance from its axis to the moved body's bounding sphere centre plus the radius
    (never more than the full-reach bound); otherwise the full-reach bound."""
    joint_kind, axis, state_joint, geometry_radius = arrays[1], arrays[5], arrays[6], arrays[11]
    rotations, origins, centres = frames[0], frames[1], frames[4]
    for j in range(pair_levers.shape[1]):
        full = pair_levers[k, j]
        out[j] = full
        g = owner[k, j]
        jid = state_joint[j]
        if full == 0.0 or g < 0 or jid < 0 or joint_kind[jid] != _REVOLUTE:
            continue
        along = 0.0
        length2 = 0.0
        for a in range(3):
            world_axis = 0.0
            for b in range(3):
                world_axis += rotations[jid, a, b] * axis[jid, b]
            v = centres[g, a] - origins[jid, a]
            along += v * world_axis
            length2 += v * v
        off_axis = length2 - along * along
        lever = math.sqrt(off_axis if off_axis > 0.0 else 0.0) + geometry_radius[g]
        if lever < full:
            out[j] = lever
    return out


@_jit
def _sphere_to_box(centre, radius, box, arrays, frames):  # type: ignore[no-untyped-def]
    """Distance from a sphere to geometry ``box``'s bounding box (negative: may overlap)."""
    half, box_centre = arrays[13], arrays[14]
    geo_rotations, geo_origins = frames[2], frames[3]
    outside = 0.0
    for b in range(3):
        local = -box_centre[box, b]
        for a in range(3):
            local += geo_rotations[box, a, b] * (centre[a] - geo_origins[box, a])
        excess = abs(local) - half[box, b]
        if excess > 0.0:
            outside += excess * excess
    return math.sqrt(outside) - radius


@_jit
def _box_gap(a, b, arrays, frames):  # type: ignore[no-untyped-def]
    """The largest gap between the projections of geometries ``a``'s and ``b``'s bounding
    boxes on their six face normals: a lower bound on their distance where positive."""
    half, box_centre = arrays[13], arrays[14]
    geo_rotations, geo_origins = frames[2], frames[3]
    ca = np.empty(3)
    cb = np.empty(3)
    for i in range(3):
        ca[i] = geo_origins[a, i]
        cb[i] = geo_origins[b, i]
        for j in range(3):
            ca[i] += geo_rotations[a, i, j] * box_centre[a, j]
            cb[i] += geo_rotations[b, i, j] * box_centre[b, j]
    best = -np.inf
    for side in range(2):
        owner = a if side == 0 else b
        for axis in range(3):
            # Unit normal: column ``axis`` of the owner's rotation.
            gap = 0.0
            for i in range(3):
                gap += (ca[i] - cb[i]) * geo_rotations[owner, i, axis]
            gap = abs(gap)
            for j in range(3):
                dot_a = 0.0
                dot_b = 0.0
                for i in range(3):
                    dot_a += geo_rotations[a, i, j] * geo_rotations[owner, i, axis]
                    dot_b += geo_rotations[b, i, j] * geo_rotations[owner, i, axis]
                gap -= half[a, j] * abs(dot_a) + half[b, j] * abs(dot_b)
            if gap > best:
                best = gap
    return best


@_jit
def _lower_bound(a, b, arrays, frames):  # type: ignore[no-untyped-def]
    """A lower bound on the distance of geometries ``a`` and ``b`` where positive: the
    best of their bounding spheres' distance, each sphere's distance to the other's
    bounding box and the boxes' separation along their face normals."""
    radius, has_box = arrays[11], arrays[12]
    centres = frames[4]
    gap = 0.0
    for i in range(3):
        gap += (centres[a, i] - centres[b, i]) ** 2
    best = math.sqrt(gap) - radius[a] - radius[b]
    if has_box[b] != 0:
        value = _sphere_to_box(centres[a], radius[a], b, arrays, frames)
        if value > best:
            best = value
    if has_box[a] != 0:
        value = _sphere_to_box(centres[b], radius[b], a, arrays, frames)
        if value > best:
            best = value
    if has_box[a] != 0 and has_box[b] != 0:
        value = _box_gap(a, b, arrays, frames)
        if value > best:
            best = value
    return best


@_jit
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


@_jit
def _bound(cumulative, pair_levers, below, order, k, c0, lever_row, position,  # type: ignore[no-untyped-def]
           c1, share):
    """Pair ``k``'s motion bound (m) from the path position whose cumulative joint motion
    is ``c0`` to ``position``, with the lever arms ``lever_row`` taken at the former
    (``c1``, ``share``: work arrays).

    A revolute joint's lever arm grows by at most how far the joints below it (same
    body, deeper in the tree: see :meth:`_Kinematics.below`) move the body relative to
    its axis, which is their own contribution: deepest joints first."""
    nq = cumulative.shape[1]
    _cumulative_at(cumulative, position, c1)
    share[0] = 0.0                      # what each body's deeper joints contributed
    share[1] = 0.0
    total = 0.0
    for index in range(nq):
        j = order[index]
        code = below[k, j]
        moved = c1[j] - c0[j]
        if code == 0 or moved <= 0.0:
            continue
        body = (code - 1) % 2
        lever = lever_row[j]
        if code >= 3:
            lever += share[body]
            if lever > pair_levers[k, j]:
                lever = pair_levers[k, j]
        contribution = lever * moved
        share[body] += contribution
        total += contribution
    return total


@_jit
def _position_for(cumulative, pair_levers, below, order, k, start, c0, lever_row,  # type: ignore[no-untyped-def]
                  step, c1, share, to_end):
    """A path position after ``start`` where pair ``k``'s motion bound from ``start`` is
    at most ``step`` (> 0), and close to the furthest one: the last node where it is, then
    within that node's segment to ``_CLOSE`` of ``step``, or as far as ``_BISECTIONS``
    evaluations get. ``to_end``: the bound from ``start`` to the path's end."""
    last = cumulative.shape[0] - 1
    if to_end <= step:
        return float(last)
    lo_node = int(start) + 1      # first node after start
    lo, f_lo = start, 0.0         # no motion yet
    f_node = _bound(cumulative, pair_levers, below, order, k, c0, lever_row, float(lo_node),
                    c1, share)
    if f_node <= step:
        hi_node, f_hi = last, to_end   # bound(lo_node) <= step < bound(hi_node)
        while hi_node - lo_node > 1:
            mid = (lo_node + hi_node) // 2
            f_mid = _bound(cumulative, pair_levers, below, order, k, c0, lever_row,
                           float(mid), c1, share)
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
        f_mid = _bound(cumulative, pair_levers, below, order, k, c0, lever_row, mid, c1, share)
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
            if _bound(cumulative, pair_levers, below, order, k, c0, lever_row, mid,
                      c1, share) <= step:
                return mid
            hi = mid
    return lo


@_jit
def _pick(walk, selected, states, q):  # type: ignore[no-untyped-def]
    """The next position to evaluate (the earliest due pair's), the pairs measured there
    (written to ``selected``: due there, or due soon and past their early position) and
    the state there (written to ``q``). Count 0: done."""
    n_pairs = walk.shape[0]
    s = np.inf
    for k in range(n_pairs):
        if walk[k, _DONE] == 0.0 and walk[k, _DUE] < s:
            s = walk[k, _DUE]
    if s == np.inf:
        return 0, 0.0
    count = 0
    for k in range(n_pairs):
        if walk[k, _DONE] != 0.0:
            continue
        # Measuring early (after the last measurement) is always sound.
        if walk[k, _DUE] <= s or (walk[k, _EARLY_AT] <= s and walk[k, _PL] < s
                                  and walk[k, _HAS_L] != 0.0):
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


@_jit
def _measure(walked, k, d, s, here, scratch, settings):  # type: ignore[no-untyped-def]
    """Take a lower bound ``d`` > 0 on pair ``k``'s distance at position ``s`` (lever
    arms ``here`` there) and schedule the pair's next measurement."""
    cumulative, pair_levers, below, order, _, _, _, walk, lever_left, lever_right = walked
    margin, gain, early = settings[0], settings[2], settings[3]
    c0, c1, share = scratch[0], scratch[1], scratch[2]
    nq = cumulative.shape[1]
    last = float(cumulative.shape[0] - 1)
    if walk[k, _HAS_L] == 0.0:
        extends = True
    else:
        _cumulative_at(cumulative, walk[k, _PL], c0)
        moved = _bound(cumulative, pair_levers, below, order, k, c0, lever_left[k], s, c1, share)
        extends = moved <= max(walk[k, _DL] + d, margin)
    if extends:                      # covered from the left: extends the stretch
        walk[k, _HAS_L] = 1.0
        walk[k, _PL] = s
        walk[k, _DL] = d
        for j in range(nq):
            lever_left[k, j] = here[j]
    else:                            # a gap: this one waits on the right
        walk[k, _HAS_R] = 1.0
        walk[k, _PR] = s
        walk[k, _DR] = d
        for j in range(nq):
            lever_right[k, j] = here[j]
    start = walk[k, _PL]
    _cumulative_at(cumulative, start, c0)
    if walk[k, _HAS_R] != 0.0:
        moved = _bound(cumulative, pair_levers, below, order, k, c0, lever_left[k],
                       walk[k, _PR], c1, share)
        if moved <= max(walk[k, _DL] + walk[k, _DR], margin):
            walk[k, _HAS_R] = 0.0
            walk[k, _PL] = walk[k, _PR]
            walk[k, _DL] = walk[k, _DR]
            for j in range(nq):
                lever_left[k, j] = lever_right[k, j]
            start = walk[k, _PL]
            _cumulative_at(cumulative, start, c0)
    d_left = walk[k, _DL]
    to_end = _bound(cumulative, pair_levers, below, order, k, c0, lever_left[k], last, c1, share)
    if walk[k, _HAS_R] != 0.0:
        # Fill the gap from the left: this step is covered whatever the distance there.
        step = max(d_left, margin)
    else:
        if to_end <= d_left:
            walk[k, _DONE] = 1.0     # its distance cannot reach 0 before the end
            return
        step = max(d_left * (1.0 + gain), margin)
    due = _position_for(cumulative, pair_levers, below, order, k, start, c0,
                        lever_left[k], step, c1, share, to_end)
    walk[k, _DUE] = due
    walk[k, _EARLY_AT] = start + (1.0 - early) * (due - start)


@_jit
def _levers_here(walked, k, arrays, frames, per_state, here):  # type: ignore[no-untyped-def]
    pair_levers, owner = walked[1], walked[4]
    if per_state:
        _levers_at(k, owner, pair_levers, arrays, frames, here)
    else:
        for j in range(pair_levers.shape[1]):
            here[j] = pair_levers[k, j]


@_jit
def _advance(walked, arrays, frames, selected, states, q, per_state, settings):  # type: ignore[no-untyped-def]
    """Walk on to the next position where some pair needs an exact distance: returns
    their count (in ``selected``) and the position (state in ``q``, its frames in
    ``frames``); 0 when every pair is done. Pairs whose cheap lower bound is at least
    ``settings[4]`` take it as their measurement."""
    first, second = walked[5], walked[6]
    nq = q.shape[0]
    here = np.empty(nq)
    scratch = np.empty((3, nq))
    cheap_from = settings[4]
    while True:
        count, s = _pick(walked[7], selected, states, q)
        if count == 0 or not per_state:
            return count, s
        _forward(q, arrays, frames)
        settings[5] += 1.0
        exact = 0
        for i in range(count):
            k = selected[i]
            bound = _lower_bound(first[k], second[k], arrays, frames)
            if bound >= cheap_from:
                settings[6] += 1.0
                _levers_here(walked, k, arrays, frames, per_state, here)
                _measure(walked, k, bound, s, here, scratch, settings)
            else:
                selected[exact] = k
                exact += 1
        if exact > 0:
            return exact, s


@_jit
def _update(walked, arrays, frames, selected, distances, count, s, per_state,  # type: ignore[no-untyped-def]
            settings):
    """Take the exact distances measured at position ``s`` (frames of its state in
    ``frames``). Returns the index (into ``selected``) of a pair in contact, or -1."""
    nq = walked[0].shape[1]
    here = np.empty(nq)
    scratch = np.empty((3, nq))
    slack = settings[1]
    for i in range(count):
        k = selected[i]
        d = distances[i] - slack
        if not d > 0.0:  # also NaN
            return i
        _levers_here(walked, k, arrays, frames, per_state, here)
        _measure(walked, k, d, s, here, scratch, settings)
    return -1
