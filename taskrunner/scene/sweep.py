"""Exact collision checking of joint-space paths by conservative advancement.

A path is a polyline in the state space (rad or m). Between two states, every point of
every collision geometry moves by at most ``sum_j r_j |dq_j|``, where ``r_j`` is the
*lever arm* of joint ``j`` for that geometry (an upper bound on the distance from the
joint's axis to any point of the geometry, computed once from the geometry's bounding
sphere and the kinematic chain at its longest reach) and a prismatic joint moves it by
``|dq_j|``. For a pair of bodies only the joints that move one and not the other count.

:class:`PathVerifier` walks a path pair by pair: it measures the pair's distance ``d``
(coal, exact geometry of the scene's checker), then skips ahead as far as the pair's
displacement bound stays below ``d`` (conservative advancement: Schwarzer, Saha &
Latombe, "Exact collision checking of robot paths", WAFR 2002 / IEEE T-RO 2005; Mirtich's
conservative advancement for rigid bodies). Far pairs are checked a few times per path,
close ones often; where a pair comes closer than ``margin`` the step is ``margin`` of
displacement, and both ends must be free.

Guarantee (for the polyline, with the scene's geometry, allowances applied): if
:meth:`PathVerifier.verify` accepts a path, no checked pair overlaps at any check, and
between checks no pair can penetrate deeper than ``margin / 2`` (m); wherever the pair's
clearance at its last check exceeded ``margin``, it cannot touch at all.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from taskrunner.robot import RobotModel
from taskrunner.scene.collision import CollisionChecker

__all__ = ["PathVerification", "PathVerifier", "lever_arms"]

_DISTANCE_SLACK = 1e-6  # m: GJK's distance tolerance; measured distances are reduced by it
_EARLY = 0.25  # a pair due within this fraction of its last step is checked with the others


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
        fraction: where the first contact is, as ``segment + t`` (waypoint index plus
            the fraction of the next segment); None for a valid path.
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
        margin: m; the displacement step used where a pair is closer than this, and twice
            the deepest penetration the verification can miss there.
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
        self._pair_levers = (levers[first] * ~moves[second]
                             + levers[second] * ~moves[first]) if pairs \
            else np.zeros((0, robot.nq))

    @property
    def pair_levers(self) -> np.ndarray:
        """``(n_pairs, nq)``: how far each joint can move one body of a pair relative to
        the other (m/rad, m/m), per unit of joint motion."""
        return self._pair_levers

    def verify(self, states: np.ndarray) -> PathVerification:
        """Verify the polyline through full state vectors ``states`` (``(n, nq)``).

        Returns:
            A :class:`PathVerification`; ``valid`` False names the first contact found.
        """
        import time

        t0 = time.perf_counter()
        states = np.atleast_2d(np.asarray(states, dtype=float))
        n_pairs = len(self._names)
        if n_pairs == 0:
            return PathVerification(True, 0, 0, time.perf_counter() - t0)
        steps = np.abs(np.diff(states, axis=0))                      # (segments, nq)
        motion = np.zeros((n_pairs, len(states)))                   # cumulative bound, m
        np.cumsum(self._pair_levers @ steps.T, axis=1, out=motion[:, 1:])
        end = float(len(states) - 1)
        due = np.zeros(n_pairs)                  # path position by which each pair is checked
        last_step = np.full(n_pairs, np.inf)     # m of displacement allowed at the last check
        queries = evaluated = 0
        model, data = self.robot.model, self._data
        geometry, geometry_data = self._geometry, self._geometry_data
        to_pin = self.robot.to_pin
        while True:
            active = due <= end
            if not active.any():
                break
            s = float(due[active].min())
            segment = min(int(s), len(states) - 2) if len(states) > 1 else 0
            frac = s - segment
            here = motion[:, segment] + frac * (motion[:, min(segment + 1, len(states) - 1)]
                                                - motion[:, segment])
            # Check now every active pair due here or soon (early checks are always safe).
            due_motion = _motion_at(motion, due)
            pick = active & ((due <= s) | (due_motion - here <= _EARLY * last_step))
            q = states[segment] if len(states) == 1 else \
                states[segment] + frac * (states[segment + 1] - states[segment])
            pin.updateGeometryPlacements(model, data, geometry, geometry_data, to_pin(q))
            evaluated += 1
            for k in np.flatnonzero(pick):
                queries += 1
                d = float(pin.computeDistance(geometry, geometry_data, int(k)).min_distance)
                d -= _DISTANCE_SLACK
                if d <= 0.0:
                    return PathVerification(False, queries, evaluated, time.perf_counter() - t0,
                                            s, self._names[k], q.copy())
                step = max(d, self.margin)
                last_step[k] = step
                due[k] = _position_of(motion[k], here[k] + step, s)
        return PathVerification(True, queries, evaluated, time.perf_counter() - t0)


def _motion_at(motion: np.ndarray, positions: np.ndarray) -> np.ndarray:
    """Each pair's cumulative motion bound at its own path position (clipped to the end)."""
    last = motion.shape[1] - 1
    p = np.clip(positions, 0.0, float(last))
    seg = np.minimum(p.astype(int), max(last - 1, 0))
    frac = p - seg
    rows = np.arange(motion.shape[0])
    nxt = np.minimum(seg + 1, last)
    return motion[rows, seg] + frac * (motion[rows, nxt] - motion[rows, seg])


def _position_of(cumulative: np.ndarray, target: float, after: float) -> float:
    """The furthest path position whose cumulative bound is at most ``target`` (past the
    end: beyond it), and never before ``after``."""
    last = len(cumulative) - 1
    if target >= cumulative[-1]:
        return last + 1.0
    seg = int(np.searchsorted(cumulative, target, side="right")) - 1
    span = cumulative[seg + 1] - cumulative[seg]
    position = seg + (target - cumulative[seg]) / span if span > 0 else float(seg + 1)
    return max(position, after)
