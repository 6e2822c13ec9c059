"""Exact path verification and the search's state checks with coal alone, no compiled code.

The planner's own checks (:mod:`taskrunner.scene.path_verifier`, :mod:`taskrunner.scene.screen`) run
numba kernels, which compile the first time on a machine (seconds of CPU). Until they are
there, a planner checks with these instead (:mod:`taskrunner.planning.warmup`): slower per
path, the same guarantee.

:class:`CoalPathVerifier` is conservative advancement (Schwarzer, Saha & Latombe, IEEE T-RO
2005) with the full-reach lever arms of :func:`taskrunner.collision.tree.lever_arms` and coal's
exact distances only: the path verifier's rule as it runs on robots whose joints its compiled
kinematics do not cover. Along the polyline, ``B(s, t) = sum_j L_j (C_j(t) - C_j(s))`` bounds
how far any point of one body of a pair moves relative to the other between positions ``s``
and ``t`` (``L_j``: the pair's lever arm of joint ``j``, counted where the joint moves one
body and not the other; ``C_j``: the joint's travel, ``sum |dq_j|``, up to a position). A
measurement ``d_s > 0`` (coal's distance less its 1 µm tolerance) at ``s`` is followed by one
at the ``t`` where ``B(s, t)`` reaches ``max(d_s, margin)``; if that one is positive too the
two cover the stretch between them (:mod:`taskrunner.scene.path_verifier`'s proof: no penetration
deeper than ``margin / 2``, none at all where ``B(s, t) <= d_s``). A pair is done at the
first measurement ``d_s >= B(s, end)``, or at the end. Pairs whose bound is the same
function (a link and each world object) are measured together, as one: the least of their
distances. Measurements are taken in order along the path, so a contact reported is the
first one found from the start.

:class:`CoalScreen` offers the :class:`~taskrunner.scene.screen.StateScreen` scans the search
calls, answered by the checker itself (the screen's own answers are the checker's: only
sooner).
"""

from __future__ import annotations

import heapq
import math
import time
from collections.abc import Callable

import numpy as np

from taskrunner.collision.tree import lever_arms
from taskrunner.errors import ArgumentError
from taskrunner.robot import RobotModel
from taskrunner.scene.collision import VERIFY_MARGIN, CollisionChecker
from taskrunner.scene.geometry_records import _tree
from taskrunner.scene.path_verifier import PathVerification, full_states

__all__ = ["CoalPathVerifier", "CoalScreen", "LineScan", "exact_line_scanner"]

_DISTANCE_SLACK = 1e-6  # m: coal's GJK tolerance, taken off every distance (as the verifier)
# A step is placed this fraction short of where the bound reaches its allowance, so that
# rounding in the bound's sums never places it beyond.
_SHORT = 1e-9


class CoalPathVerifier:
    """Verifies paths against one collision checker (one scene revision) with coal alone.

    Args:
        robot: the robot model.
        checker: the scene's checker (its geometry and pairs, allowances applied).
        margin: m; as :class:`~taskrunner.scene.path_verifier.PathVerifier`'s: twice the deepest
            penetration the verification can miss where a pair comes within it.

    ``verify`` answers as :meth:`taskrunner.scene.path_verifier.PathVerifier.verify` does (a
    :class:`~taskrunner.scene.path_verifier.PathVerification`; ``bounds`` is always 0: every
    measurement is coal's). Used like its checker, by one thread at a time.
    """

    def __init__(self, robot: RobotModel, checker: CollisionChecker,
                 margin: float = VERIFY_MARGIN) -> None:
        if not (math.isfinite(margin) and margin > 0):
            raise ArgumentError(f"'margin' must be a positive number of metres (got {margin!r})")
        self.robot = robot
        self.margin = margin
        self._checker = checker
        geometry = checker.geometry_model
        self._names = [obj.name for obj in geometry.geometryObjects]
        pairs = np.array([(p.first, p.second) for p in geometry.collisionPairs],
                         dtype=np.int64).reshape(-1, 2)
        levers = lever_arms(robot, geometry, _tree(robot)).reshape(len(self._names), robot.nq)
        first, second = levers[pairs[:, 0]], levers[pairs[:, 1]]
        moves_first, moves_second = first > 0.0, second > 0.0
        # A joint moving both bodies moves them together: only the others count.
        pair_levers = np.where(moves_first & ~moves_second, first,
                               np.where(moves_second & ~moves_first, second, 0.0))
        self._pairs = pairs
        if len(pairs):
            unit_levers, unit_of = np.unique(pair_levers, axis=0, return_inverse=True)
        else:
            unit_levers, unit_of = np.zeros((0, robot.nq)), np.zeros(0, dtype=np.int64)
        self._unit_levers = unit_levers
        unit_of = np.asarray(unit_of).reshape(-1)
        self._members = [np.flatnonzero(unit_of == u).tolist() for u in range(len(unit_levers))]

    def verify(self, states: np.ndarray) -> PathVerification:
        """Verify the polyline through full state vectors ``states`` (``(n, nq)``).

        Returns:
            A :class:`~taskrunner.scene.path_verifier.PathVerification`; ``valid`` False names
            the first contact found along the path.
        """
        t0 = time.perf_counter()
        states = full_states(states, self.robot.nq)
        finite = np.isfinite(states).all(axis=1)
        if not finite.all():
            row = int(np.flatnonzero(~finite)[0])
            raise ArgumentError(f"state {row} of the path to verify is not finite: {states[row]}")
        if len(self._pairs) == 0:
            return PathVerification(True, 0, 0, time.perf_counter() - t0)
        n = len(states)
        cumulative = np.zeros_like(states)
        np.cumsum(np.abs(np.diff(states, axis=0)), axis=0, out=cumulative[1:])
        # Per unit, its bound from the start to each waypoint (m): B(s, t) = reach(t) - reach(s).
        reach = cumulative @ self._unit_levers.T
        distances = np.zeros(len(self._pairs))
        pair_distances, to_pin = self._checker.pair_distances, self.robot.to_pin
        queries = placed = 0
        # Positions (waypoint, fraction of the next segment) with the units due there.
        due: list[tuple[int, float, int]] = [(0, 0.0, u) for u in range(len(self._members))]
        heapq.heapify(due)
        while due:
            i, f, _ = due[0]
            units = []
            while due and due[0][0] == i and due[0][1] == f:
                units.append(heapq.heappop(due)[2])
            q = states[i] if f == 0.0 else states[i] + f * (states[i + 1] - states[i])
            pairs = [k for u in units for k in self._members[u]]
            pair_distances(to_pin(q), pairs, distances)
            placed += 1
            queries += len(pairs)
            at = 0
            for u in units:
                count = len(self._members[u])
                measured = distances[at:at + count] - _DISTANCE_SLACK
                at += count
                nearest = int(np.argmin(measured))
                d = float(measured[nearest])
                if not d > 0.0:  # also NaN
                    k = self._members[u][nearest]
                    pair = (self._names[int(self._pairs[k, 0])], self._names[int(self._pairs[k, 1])])
                    return PathVerification(False, queries, placed, time.perf_counter() - t0,
                                            i + f, pair, np.array(q, dtype=float))
                column = reach[:, u]
                here = column[i] if f == 0.0 else column[i] + f * (column[i + 1] - column[i])
                if i == n - 1 or column[-1] - here <= d:
                    continue  # cannot come into contact before the end
                target = here + max(d, self.margin) * (1.0 - _SHORT)
                if target >= column[-1]:
                    heapq.heappush(due, (n - 1, 0.0, u))
                    continue
                # The segment where the bound reaches the target (a segment along which
                # it stays flat is passed over: nothing of the unit moves there).
                j = int(np.searchsorted(column, target, side="right")) - 1
                fraction = (target - column[j]) / (column[j + 1] - column[j])
                if j < i or (j == i and fraction <= f):
                    # Rounding left it where it is: a step of a 1e-12th of the segment
                    # (its bound far below the margin: covered whatever it measures).
                    j, fraction = i, f + (1.0 - f) * 1e-12
                heapq.heappush(due, (j, float(fraction), u))
        return PathVerification(True, queries, placed, time.perf_counter() - t0)


class CoalScreen:
    """The scans of :class:`~taskrunner.scene.screen.StateScreen` that the search calls,
    answered by the scene's checker alone (what the screen does on robots its compiled
    kinematics do not cover).

    Args:
        robot: the robot model.
        checker: the scene's checker.
    """

    def __init__(self, robot: RobotModel, checker: CollisionChecker) -> None:
        self.robot = robot
        self.checker = checker

    def scanner(self) -> Callable[[np.ndarray], int]:
        """The index of the first row of full states in collision, or -1."""
        first, to_pin = self.checker.first_in_collision, self.robot.to_pin
        return lambda states: first(to_pin(states))

    def line_scanner(self) -> Callable[[np.ndarray, np.ndarray, np.ndarray, np.ndarray, int, int],
                                         int]:
        """As :meth:`taskrunner.scene.screen.StateScreen.line_scanner`: writes rows
        ``begin`` on of ``rows`` as ``a + fractions[s] (b - a)`` in the columns ``first``
        to ``first + len(a)`` (``b`` at fraction 1) and returns the first in collision, or
        -1."""
        return exact_line_scanner(self.checker.first_in_collision, self.robot.to_pin)

    def segment_scanner(self, base: np.ndarray, first: int, table: np.ndarray,
                        resolution: float, fill: Callable[[int], None] | None = None) -> None:
        """None: the search checks its edges with :meth:`line_scanner` (the compiled
        segment scan is the screen's alone)."""
        return None

    def first_in_collision(self, states: np.ndarray) -> int:
        """The index of the first row of ``states`` (full state vectors) in collision, or -1."""
        return self.scanner()(np.ascontiguousarray(states, dtype=float))


LineScan = Callable[[np.ndarray, np.ndarray, np.ndarray, np.ndarray, int, int], int]


def exact_line_scanner(first_in: Callable[[np.ndarray], int],
                       to_pin: Callable[[np.ndarray], np.ndarray]) -> LineScan:
    """A segment scan (as :meth:`taskrunner.scene.screen.StateScreen.line_scanner`'s) by an exact checker's
    ``first_in`` (the index of the first pinocchio state in collision, or -1), in Python:
    the rows are written, then checked together."""

    def interpolated(rows: np.ndarray, fractions: np.ndarray, a: np.ndarray,
                     b: np.ndarray, first: int, begin: int) -> int:
        block = rows[begin:, first:first + len(a)]
        block[:] = a + fractions[begin:, None] * (b - a)
        block[fractions[begin:] == 1.0] = b
        hit = first_in(to_pin(rows[begin:]))
        return hit if hit < 0 else begin + hit

    return interpolated
