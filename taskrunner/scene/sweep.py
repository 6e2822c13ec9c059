"""Exact collision checking of joint-space paths by conservative advancement.

A path is a polyline in the state space (rad or m). Between two states, every point of
every collision geometry moves by at most ``sum_j r_j |dq_j|``, where ``r_j`` is the
*lever arm* of joint ``j`` for that geometry (an upper bound on the distance from the
joint's axis to any point of the geometry, computed once from the geometry's bounding
sphere and the kinematic chain at its longest reach) and a prismatic joint moves it by
``|dq_j|``. For a pair of bodies only the joints that move one and not the other count.
Summed along the path this gives each pair a non-decreasing *motion bound* ``M(s)`` (m)
of the path position ``s``: between positions ``s`` and ``t`` no point of one body moves
by more than ``M(t) - M(s)`` relative to the other.

:class:`PathVerifier` walks a path pair by pair (Schwarzer, Saha & Latombe, "Adaptive
dynamic collision checking for single and multiple articulated robots in complex
environments", IEEE T-RO 2005): it measures a pair's distance ``d`` with coal (the exact
geometry of the scene's checker) at chosen positions only. Two measurements ``(s, d_s)``
and ``(t, d_t)`` of a pair, ``s < t``, *cover* the stretch between them when

    ``M(t) - M(s) <= max(d_s + d_t, margin)``  and  ``d_s, d_t > 0``.

Proof sketch. At a position ``u`` between, every point of one body has moved by at most
``a = M(u) - M(s)`` relative to the other since ``s`` and by at most ``b = M(t) - M(u)``
until ``t`` (``a + b = M(t) - M(s)``). Moving a set by at most ``a`` changes its distance
to another set by at most ``a``, so the pair's distance at ``u`` is at least
``max(d_s - a, d_t - b)``. If ``a + b <= d_s + d_t`` one of the two terms is ``>= 0``:
they do not overlap at ``u``. Otherwise ``a + b <= margin``; a point of one body inside
the other at ``u`` is within ``a`` of where it was at ``s`` (outside, at least ``d_s``
away) and within ``b`` of where it is at ``t``, so it is at most
``min(a - d_s, b - d_t) < margin / 2`` deep. A pair whose measurements (the first at
the path's start, the last at its end or with ``M(end) - M(s) <= d_s``, so that its
distance cannot reach 0 before the end) cover the path pairwise is therefore free,
except for penetrations shallower than ``margin / 2`` where it came within ``margin``.

The walk is adaptive per pair: after a measurement ``(s, d)`` that extends the covered
stretch, the next one is optimistic, where the motion bound has grown by ``(1 + GAIN) d``
(at least ``margin``), since a pair's distance rarely falls as fast as its bound allows;
if that one does not cover the gap with the last, measurements at ``d`` steps fill it from
the left (each reaches the previous one's bound, at least ``margin``: the walk always
advances). Far pairs are measured a few times per path, close ones often; pairs due at
nearby positions share one forward kinematics. The scheduling runs compiled (numba,
``cache=True``); the distances are coal's, through pinocchio.

Guarantee (for the polyline, with the scene's geometry, allowances applied): if
:meth:`PathVerifier.verify` accepts a path, every measured pair was more than 1 µm apart
(coal's GJK tolerance is subtracted from every distance), and between measurements no pair
can penetrate deeper than ``margin / 2`` (m); wherever the two measurements around a
position summed more than the motion between them, the pair cannot touch there at all.
"""

from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from taskrunner.resources import user_cache_dir
from taskrunner.robot import RobotModel
from taskrunner.scene.collision import CollisionChecker

if not os.environ.get("NUMBA_CACHE_DIR"):
    # Before numba's import: an installed package's own folder may be read-only.
    os.environ["NUMBA_CACHE_DIR"] = str(user_cache_dir() / "numba")

import numba

if not numba.config.CACHE_DIR:  # numba was imported before this module set the variable
    numba.config.CACHE_DIR = os.environ["NUMBA_CACHE_DIR"]

__all__ = ["GAIN", "PathVerification", "PathVerifier", "lever_arms"]

_DISTANCE_SLACK = 1e-6  # m: GJK's distance tolerance; measured distances are reduced by it
_EARLY = 0.25  # a pair due within this fraction of its step is measured with the others
GAIN = 1.0  # optimistic step: (1 + GAIN) times the last distance (see the module's text)
_SHRINK = 1e-9  # fill steps aim this fraction short, so rounding never misses coverage

# Columns of the per-pair walk state (a float array, one row per pair).
_HAS_L, _ML, _DL, _HAS_R, _MR, _DR, _DUE, _TARGET, _DONE, _MEND = range(10)
_COLUMNS = 10


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
        distance_queries: pair distances computed.
        states: states at which forward kinematics ran.
        seconds: wall time of the verification.
        fraction: where the contact is, as ``segment + t`` (waypoint index plus the
            fraction of the next segment); None for a valid path.
        pair: the geometry names of that contact; None for a valid path.
        state: the full state vector there; None for a valid path.
    """

    valid: bool
    distance_queries: int
    states: int
    seconds: float
    fraction: float | None = None
    pair: tuple[str, str] | None = None
    state: np.ndarray | None = None


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
        first = np.array([i for i, _ in pairs], dtype=int)
        second = np.array([j for _, j in pairs], dtype=int)
        # Joints moving both bodies of a pair move them rigidly together: they do not count.
        self._pair_levers = np.ascontiguousarray(
            levers[first] * ~moves[second] + levers[second] * ~moves[first]) if pairs \
            else np.zeros((0, robot.nq))

    @property
    def pair_levers(self) -> np.ndarray:
        """``(n_pairs, nq)``: how far each joint can move one body of a pair relative to
        the other (m/rad, m/m), per unit of joint motion."""
        return self._pair_levers

    def verify(self, states: np.ndarray) -> PathVerification:
        """Verify the polyline through full state vectors ``states`` (``(n, nq)``).

        Returns:
            A :class:`PathVerification`; ``valid`` False names a contact found.
        """
        t0 = time.perf_counter()
        states = np.ascontiguousarray(np.atleast_2d(np.asarray(states, dtype=float)))
        n_pairs = len(self._names)
        if n_pairs == 0:
            return PathVerification(True, 0, 0, time.perf_counter() - t0)
        cumulative = np.zeros_like(states)                      # per joint, sum of |dq|
        np.cumsum(np.abs(np.diff(states, axis=0)), axis=0, out=cumulative[1:])
        levers = self._pair_levers
        walk = np.zeros((n_pairs, _COLUMNS))
        walk[:, _MEND] = levers @ cumulative[-1]
        selected = np.zeros(n_pairs, dtype=np.int64)
        distances = np.zeros(n_pairs)
        q = np.zeros(states.shape[1])
        queries = evaluated = 0
        model, data = self.robot.model, self._data
        geometry, geometry_data = self._geometry, self._geometry_data
        to_pin = self.robot.to_pin
        compute = pin.computeDistance
        while True:
            count, s = _pick(cumulative, levers, walk, selected, states, q, _EARLY)
            if count == 0:
                break
            pin.updateGeometryPlacements(model, data, geometry, geometry_data, to_pin(q))
            evaluated += 1
            for i in range(count):
                distances[i] = compute(geometry, geometry_data, int(selected[i])).min_distance
            queries += count
            bad = _update(cumulative, levers, walk, selected, distances, count, s,
                          self.margin, _DISTANCE_SLACK, GAIN, _SHRINK)
            if bad >= 0:
                return PathVerification(False, queries, evaluated, time.perf_counter() - t0,
                                        float(s), self._names[int(selected[bad])], q.copy())
        return PathVerification(True, queries, evaluated, time.perf_counter() - t0)


# ---------------------------------------------------------------------- kernels
_jit = numba.njit(cache=True, nogil=True, error_model="numpy")


@_jit
def _motion_at(cumulative, levers, k, position):  # type: ignore[no-untyped-def]
    """Pair ``k``'s motion bound (m) at path position ``position`` (``segment + t``)."""
    n = cumulative.shape[0]
    nq = cumulative.shape[1]
    if n == 1:
        return 0.0
    seg = int(position)
    if seg > n - 2:
        seg = n - 2
    frac = position - seg
    total = 0.0
    for j in range(nq):
        c = cumulative[seg, j] + frac * (cumulative[seg + 1, j] - cumulative[seg, j])
        total += levers[k, j] * c
    return total


@_jit
def _node_motion(cumulative, levers, k, i):  # type: ignore[no-untyped-def]
    total = 0.0
    for j in range(cumulative.shape[1]):
        total += levers[k, j] * cumulative[i, j]
    return total


@_jit
def _position_of(cumulative, levers, k, target):  # type: ignore[no-untyped-def]
    """The furthest path position where pair ``k``'s motion bound is at most ``target``."""
    last = cumulative.shape[0] - 1
    if _node_motion(cumulative, levers, k, last) <= target:
        return float(last)
    lo, hi = 0, last        # motion(lo) <= target < motion(hi)
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if _node_motion(cumulative, levers, k, mid) <= target:
            lo = mid
        else:
            hi = mid
    m_lo = _node_motion(cumulative, levers, k, lo)
    m_hi = _node_motion(cumulative, levers, k, hi)
    frac = (target - m_lo) / (m_hi - m_lo)
    if frac < 0.0:
        frac = 0.0
    if frac > 1.0:
        frac = 1.0
    return lo + frac


@_jit
def _pick(cumulative, levers, walk, selected, states, q, early):  # type: ignore[no-untyped-def]
    """The next position to evaluate (the earliest due pair's), the pairs measured there
    (written to ``selected``) and the state there (written to ``q``). Count 0: done."""
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
        due = walk[k, _DUE]
        take = due <= s
        if not take and walk[k, _HAS_L] != 0.0 and due > s:
            # Measuring early is always sound; it saves a forward kinematics.
            here = _motion_at(cumulative, levers, k, s)
            step = walk[k, _TARGET] - walk[k, _ML]
            take = here >= walk[k, _ML] and walk[k, _TARGET] - here <= early * step
        if take:
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
def _update(cumulative, levers, walk, selected, distances, count, s, margin, slack,
            gain, shrink):  # type: ignore[no-untyped-def]
    """Take the distances measured at position ``s``; schedule each pair's next
    measurement. Returns the index (into ``selected``) of a pair in contact, or -1."""
    for i in range(count):
        k = selected[i]
        d = distances[i] - slack
        if not d > 0.0:  # also NaN
            return i
        m = _motion_at(cumulative, levers, k, s)
        if walk[k, _HAS_L] == 0.0:
            walk[k, _HAS_L] = 1.0
            walk[k, _ML] = m
            walk[k, _DL] = d
        elif m - walk[k, _ML] <= max(walk[k, _DL] + d, margin):
            walk[k, _ML] = m            # covered from the left: extends the stretch
            walk[k, _DL] = d
        else:
            walk[k, _HAS_R] = 1.0       # a gap: this one waits on the right
            walk[k, _MR] = m
            walk[k, _DR] = d
        if walk[k, _HAS_R] != 0.0 and \
                walk[k, _MR] - walk[k, _ML] <= max(walk[k, _DL] + walk[k, _DR], margin):
            walk[k, _HAS_R] = 0.0
            walk[k, _ML] = walk[k, _MR]
            walk[k, _DL] = walk[k, _DR]
        m_left, d_left, m_end = walk[k, _ML], walk[k, _DL], walk[k, _MEND]
        if walk[k, _HAS_R] != 0.0:
            # Fill the gap from the left: this step is covered whatever the distance there.
            target = m_left + max(d_left, margin) * (1.0 - shrink)
        elif m_left + d_left >= m_end:
            walk[k, _DONE] = 1.0        # its distance cannot reach 0 before the end
            continue
        else:
            target = m_left + max(d_left * (1.0 + gain), margin)
            if target > m_end:
                target = m_end
        walk[k, _TARGET] = target
        walk[k, _DUE] = _position_of(cumulative, levers, k, target)
    return -1
