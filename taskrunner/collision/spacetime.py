"""Space-time verification: arms moving at once, checked against each other over time.

A *lane* is the work of one arm (or of one branch of a ``parallel``): timed trajectories
(:class:`TimedMotion`) of its joints, each with its start on a clock common to all lanes
(s). Outside its motions a lane rests: before its first motion where that motion starts,
between two where the earlier ended, after the last where it ended. Lanes drive disjoint
joints. :func:`verify_lanes` answers whether the lanes' bodies come closer than a
clearance at any instant, which pair first does and when (:class:`Conflict`), and the
least distance measured.

Every backend here plays a trajectory linearly between its samples
(:func:`~taskrunner.backends.base.sample_positions`), so between two consecutive sample
times of *any* lane the whole state moves on a straight line in joint space. Over a time
stretch, every point of a body moves, relative to a body of another lane, by at most
``B = sum_j r_j |dq_j|``, where ``r_j`` is the full-reach lever arm of joint ``j`` for
either body (:func:`~taskrunner.collision.tree.lever_arms`: an upper bound on the distance
from the joint's axis to any point of the body, 1 m/m for a prismatic joint). This is the
bound of the path verifier (:mod:`taskrunner.scene.path_verifier`) taken along time.

The walk is conservative advancement (as in Schwarzer, Saha & Latombe, IEEE T-RO 2005),
per pair of bodies of two lanes: a measurement ``d`` (coal's exact signed distance, m,
through the scene's :class:`~taskrunner.scene.collision.CollisionChecker`) at time ``s``
proves the pair at least ``clearance`` apart until the time ``t`` where ``B(s, t)``
reaches ``d - clearance``; the pair is measured again there. The pair is therefore never
closer than ``clearance`` between measurements, and a measurement below it is a
:class:`Conflict`, the first one moved back by bisection to within
:data:`TIME_TOLERANCE` of where the distance first drops below the clearance. Pairs
due at about the same time are measured together (one forward kinematics). Where a
pair's distance creeps toward the clearance so slowly that more than
:attr:`SpacetimeOptions.max_steps` measurements would be needed, the clearance is not
proven and that is reported as a conflict too: never a silent pass.

The verifier is independent of the planner and of the run: it reads trajectories and a
scene only, so a run record can be verified after the fact
(:mod:`taskrunner.tree.expect`).
"""

from __future__ import annotations

import math
import time
from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from taskrunner.collision.tree import lever_arms
from taskrunner.errors import ArgumentError, InvalidStateError
from taskrunner.types import JointTrajectory

if TYPE_CHECKING:  # the planning scene is above the collision core: passed in, not imported
    from taskrunner.scene import Scene

__all__ = ["LEAST_TOLERANCE", "TIME_TOLERANCE", "Conflict", "Lane", "LeastClearance",
           "SpacetimeOptions", "SpacetimeVerification", "TimedMotion", "least_clearance",
           "verify_lanes"]

TIME_TOLERANCE = 1e-3
"""s: a conflict's time is where the distance first drops below the clearance, within this."""
LEAST_TOLERANCE = 2e-4
"""m: :func:`least_clearance` brackets the least distance between lanes this tightly."""
_EARLY = 0.75  # a pair this far through its step is measured with the pairs due now
_SLACK = 1e-6  # m: coal's distance tolerance, taken off every measured distance


@dataclass(frozen=True)
class TimedMotion:
    """A trajectory of one lane, started at ``start`` (s, the common clock).

    Attributes:
        label: what the motion is, for reports (the task file:line and step).
    """

    trajectory: JointTrajectory
    start: float
    label: str | None = None

    @property
    def end(self) -> float:
        """When it ends (s, the common clock)."""
        return self.start + self.trajectory.duration


@dataclass(frozen=True)
class Lane:
    """The motions of one arm (one branch) in time order; they must not overlap."""

    name: str
    motions: tuple[TimedMotion, ...]


@dataclass(frozen=True)
class SpacetimeOptions:
    """How :func:`verify_lanes` verifies.

    Attributes:
        clearance: m; bodies of two lanes closer than this are a conflict (0: touching).
        max_steps: most measurements of one pair before it counts as not proven.
    """

    clearance: float = 0.0
    max_steps: int = 20000

    def __post_init__(self) -> None:
        if not (math.isfinite(self.clearance) and self.clearance >= 0):
            raise ArgumentError(f"'clearance' must be a number of metres >= 0 "
                             f"(got {self.clearance!r})")
        if self.max_steps < 1:
            raise ArgumentError(f"'max_steps' must be >= 1 (got {self.max_steps!r})")


@dataclass(frozen=True)
class Conflict:
    """Two lanes' bodies closer than the clearance.

    Attributes:
        time: s on the common clock, where the distance first drops below the clearance
            (within :data:`TIME_TOLERANCE`).
        bodies: the two bodies (link or object names), the first of ``lanes[0]``.
        lanes: the two lanes' names.
        motions: the label of each lane's motion running then (None: the lane rests).
        distance: m, measured there (negative: penetrating).
        proven: False where the pair was not measured below the clearance but its
            clearance could not be proven within :attr:`SpacetimeOptions.max_steps`.
    """

    time: float
    bodies: tuple[str, str]
    lanes: tuple[str, str]
    motions: tuple[str | None, str | None]
    distance: float
    proven: bool = True

    @property
    def depth(self) -> float:
        """How deep the bodies penetrate there (m, 0 where they do not touch)."""
        return max(0.0, -self.distance)

    def describe(self) -> str:
        """One line: when, which bodies of which motions, how close."""
        what = [m or f"{lane} at rest" for m, lane in zip(self.motions, self.lanes)]
        how = (f"{1e3 * self.depth:.1f} mm deep" if self.distance < 0
               else f"{1e3 * self.distance:.1f} mm apart")
        if not self.proven:
            how = "clearance not proven"
        return (f"{self.bodies[0]} ({what[0]}) and {self.bodies[1]} ({what[1]}) at "
                f"{self.time:.3f} s, {how}")


@dataclass(frozen=True)
class SpacetimeVerification:
    """What :func:`verify_lanes` found.

    Attributes:
        conflict: the first conflict in time, None when the lanes keep their clearance.
        min_distance: m, the least distance measured between two lanes' bodies (inf:
            no pair); the true least distance lies between the clearance and this.
        closest: the bodies measured at ``min_distance``, and ``closest_time`` when (s).
        distance_queries: exact pair distances computed.
        seconds: wall time of the verification.
    """

    conflict: Conflict | None
    min_distance: float
    closest: tuple[str, str] | None
    closest_time: float | None
    distance_queries: int
    seconds: float

    @property
    def ok(self) -> bool:
        """No conflict."""
        return self.conflict is None


def verify_lanes(scene: Scene, lanes: Sequence[Lane], window: tuple[float, float] | None = None,
                 options: SpacetimeOptions | None = None) -> SpacetimeVerification:
    """Verify that no two lanes' bodies come closer than the clearance (module text).

    Args:
        scene: the bodies (robot links, attached and world objects) and the allowed
            pairs; joints no lane moves stay at ``scene.state``. Only pairs of bodies
            of two different lanes are checked: a body is of the lane that moves the
            joint nearest above it (a finger: its gripper's lane, beside its arm's),
            else of a lane whose joints it carries (an arm's links, when only its
            gripper moves).
        lanes: at least two lanes for anything to be checked.
        window: the stretch of the common clock checked (s), default from the first
            motion's start to the last motion's end.

    Raises:
        InvalidStateError: two lanes move the same joint, or one lane's motions overlap
            in time.
    """
    started = time.perf_counter()
    options = options or SpacetimeOptions()
    timeline = _Timeline(scene, lanes, window)
    if timeline.empty:
        return SpacetimeVerification(None, math.inf, None, None, 0, time.perf_counter() - started)
    walk = _Walk(scene, timeline, options)
    conflict = walk.run()
    return SpacetimeVerification(conflict, walk.least, walk.least_pair, walk.least_time,
                                 walk.queries, time.perf_counter() - started)


@dataclass(frozen=True)
class LeastClearance:
    """The least distance between two lanes' bodies over a stretch of time
    (:func:`least_clearance`).

    Attributes:
        distance: m, measured (exact, at ``time``): the least distance is at most this
            and at least ``lower``.
        lower: m, proven: no two lanes' bodies come closer than this; ``-inf`` where
            they touch (``distance`` and ``time`` are then where they first do).
        bodies: the two bodies measured at ``distance`` (None: no pair of bodies).
        time: s on the common clock, where ``distance`` was measured.
        motions: the label of each body's lane's motion running then (None: it rests).
        lanes: the two bodies' lanes.
        distance_queries: exact pair distances computed; ``seconds`` the wall time.
    """

    distance: float
    lower: float
    bodies: tuple[str, str] | None
    time: float | None
    motions: tuple[str | None, str | None]
    lanes: tuple[str, str] | None
    distance_queries: int
    seconds: float


def least_clearance(scene: Scene, lanes: Sequence[Lane],
                    window: tuple[float, float] | None = None,
                    tolerance: float = LEAST_TOLERANCE) -> LeastClearance:
    """The least distance between two lanes' bodies over ``window`` (as
    :func:`verify_lanes`), bracketed within ``tolerance`` (m).

    :func:`verify_lanes` with a clearance ``c`` proves every pair at least ``c`` apart
    and measures exact distances on the way; the least one measured, ``m``, is an upper
    bound of the least distance. Verifying again with ``c = m - tolerance`` either proves
    the bracket ``[c, m]`` or measures a distance below ``c`` (a new, lower ``m``): each
    round lowers ``m`` by more than ``tolerance``, so the rounds end. Where the lanes'
    bodies touch, the first contact is reported (how deep they go is not measured).

    Raises:
        ArgumentError: ``tolerance`` is not a positive number of metres.
        InvalidStateError: as :func:`verify_lanes`.
    """
    if not (math.isfinite(tolerance) and tolerance > 0):
        raise ArgumentError(f"'tolerance' must be a positive number of metres "
                            f"(got {tolerance!r})")
    started = time.perf_counter()
    timeline = _Timeline(scene, lanes, window)
    queries = 0
    best: _Walk | None = None  # the walk that measured the least distance so far
    clearance, lower, ceiling = 0.0, -math.inf, math.inf
    while not timeline.empty:
        walk = _Walk(scene, timeline, SpacetimeOptions(clearance=clearance))
        if not walk.pairs:
            break
        conflict = walk.run()
        queries += walk.queries
        if best is None or walk.least < best.least:
            best = walk
        if conflict is None:
            lower = max(lower, clearance)
            if best.least - lower <= tolerance or clearance + tolerance >= ceiling:
                break
            clearance = best.least - tolerance
        elif clearance == 0.0:
            # Touching or penetrating (or not even 0 proven): nothing is proven.
            lower = -math.inf
            break
        else:
            if not conflict.proven:  # too close to the least distance to prove it
                ceiling = clearance
            clearance = max(0.0, min(best.least, clearance) - tolerance)
    if best is None or best.least_index is None:
        return LeastClearance(math.inf, math.inf, None, None, (None, None), None, queries,
                              time.perf_counter() - started)
    _, a, b = best.pairs[best.least_index]
    owners = (int(best.owner[a]), int(best.owner[b]))
    at = float(best.least_time or 0.0)
    return LeastClearance(best.least, lower, best.least_pair, at,
                          (timeline.motion_label(owners[0], at),
                           timeline.motion_label(owners[1], at)),
                          (timeline.lanes[owners[0]].name, timeline.lanes[owners[1]].name),
                          queries, time.perf_counter() - started)


class _Timeline:
    """The full state over the common clock: linear between the event times."""

    def __init__(self, scene: Scene, lanes: Sequence[Lane],
                 window: tuple[float, float] | None) -> None:
        model = scene.robot
        self.lanes = list(lanes)
        self.columns: list[np.ndarray] = []
        seen: dict[str, str] = {}
        for lane in self.lanes:
            names = sorted({n for m in lane.motions for n in m.trajectory.names})
            for name in names:
                if name in seen and seen[name] != lane.name:
                    raise InvalidStateError(f"lanes {seen[name]!r} and {lane.name!r} both "
                                            f"move joint {name!r}")
                seen[name] = lane.name
            ordered = sorted(lane.motions, key=lambda m: m.start)
            for a, b in zip(ordered, ordered[1:]):
                if b.start < a.end - TIME_TOLERANCE:  # (records round times to 0.1 ms)
                    raise InvalidStateError(f"lane {lane.name!r}: {b.label or 'a motion'} "
                                            f"starts at {b.start:.3f} s, before "
                                            f"{a.label or 'the one before'} ends "
                                            f"({a.end:.3f} s)")
            self.columns.append(model.indices(tuple(names)) if names else
                                np.zeros(0, dtype=np.int64))
        motions = [m for lane in self.lanes for m in lane.motions]
        moving = sum(1 for lane in self.lanes if lane.motions)
        self.empty = moving == 0 or len(self.lanes) < 2
        if self.empty:
            return
        t0 = min(m.start for m in motions) if window is None else window[0]
        t1 = max(m.end for m in motions) if window is None else window[1]
        times = {t0, t1}
        for m in motions:
            for t in m.start + np.asarray(m.trajectory.times, dtype=float):
                if t0 < t < t1:
                    times.add(float(t))
        self.times = np.array(sorted(times))
        base = scene.state.copy()
        for lane in self.lanes:  # before its first motion, a joint is where that one starts
            for motion in sorted(lane.motions, key=lambda m: m.start, reverse=True):
                base[model.indices(motion.trajectory.names)] = motion.trajectory.positions[0]
        states = np.repeat(base[None, :], len(self.times), axis=0)
        for lane in self.lanes:
            for motion in sorted(lane.motions, key=lambda m: m.start):
                # From its start on (held at its end after), each where the last left it.
                rows = self.times >= motion.start
                local = self.times[rows] - motion.start
                trajectory = motion.trajectory
                idx = model.indices(trajectory.names)
                states[np.ix_(rows, idx)] = np.column_stack(
                    [np.interp(local, trajectory.times, trajectory.positions[:, j])
                     for j in range(len(idx))])
        for row in range(len(states)):
            model.apply_mimic(states[row])
        self.states = states
        # Per joint, how far it has moved since t0 (rad or m): the motion bound's integrand.
        steps = np.abs(np.diff(states, axis=0))
        self.travel = np.vstack([np.zeros(model.nq), np.cumsum(steps, axis=0)])

    def state(self, t: float) -> np.ndarray:
        """The full state at ``t`` (linear between event times)."""
        k = min(max(int(np.searchsorted(self.times, t, side="right")) - 1, 0), len(self.times) - 2)
        span = self.times[k + 1] - self.times[k]
        s = 0.0 if span <= 0 else min(1.0, max(0.0, (t - self.times[k]) / span))
        return self.states[k] + s * (self.states[k + 1] - self.states[k])

    def motion_label(self, lane: int, t: float) -> str | None:
        motion, _ = _at(self.lanes[lane], t)
        if motion is None or not (motion.start <= t <= motion.end):
            return None
        return motion.label or "a motion"


def _at(lane: Lane, t: float) -> tuple[TimedMotion | None, float]:
    """The motion that sets the lane's joints at ``t`` and the time on its own clock."""
    ordered = sorted(lane.motions, key=lambda m: m.start)
    if not ordered:
        return None, 0.0
    current = ordered[0]
    for motion in ordered:
        if motion.start <= t:
            current = motion
    return current, t - current.start


class _Walk:
    """Conservative advancement of every pair of two lanes' bodies along the timeline."""

    def __init__(self, scene: Scene, timeline: _Timeline, options: SpacetimeOptions) -> None:
        model = scene.robot
        self.model, self.timeline, self.options = model, timeline, options
        self.checker = checker = scene.checker
        geometry = checker.geometry_model
        pin_model = model.model
        owner = np.full(len(geometry.geometryObjects), -1, dtype=np.int64)
        # A body is of the lane whose moved joint is nearest above it; a body no lane's
        # joint moves, of the lane that carries it (a gripper lane: its arm's links).
        moved: dict[int, int] = {}
        carried: dict[int, int] = {}
        for lane_index, columns in enumerate(timeline.columns):
            for index in columns:
                jid = int(pin_model.getJointId(model.joint_names[int(index)]))
                moved[jid] = lane_index
                while jid > 0:
                    carried.setdefault(jid, lane_index)
                    jid = int(pin_model.parents[jid])
        for g, obj in enumerate(geometry.geometryObjects):
            chain = []
            jid = int(obj.parentJoint)
            while jid > 0:
                chain.append(jid)
                jid = int(pin_model.parents[jid])
            found = next((moved[j] for j in chain if j in moved), None)
            if found is None:
                found = next((carried[j] for j in chain if j in carried), None)
            if found is not None:
                owner[g] = found
        self.owner = owner
        self.names = [_body_name(obj, pin_model) for obj in geometry.geometryObjects]
        pairs = []
        for k, pair in enumerate(geometry.collisionPairs):
            a, b = int(pair.first), int(pair.second)
            if owner[a] >= 0 and owner[b] >= 0 and owner[a] != owner[b]:
                pairs.append((k, a, b) if owner[a] < owner[b] else (k, b, a))
        self.pairs = pairs
        levers = _levers(model, geometry)
        # Per pair, the motion bound's weight of each joint: either body's lever arm.
        weights = np.array([levers[a] + levers[b] for _, a, b in pairs]).reshape(len(pairs),
                                                                                 model.nq)
        self.bound = timeline.travel @ weights.T  # (n_times, n_pairs), non-decreasing
        self.queries = 0
        self.least = math.inf
        self.least_pair: tuple[str, str] | None = None
        self.least_time: float | None = None
        self.least_index: int | None = None
        self._out = np.zeros(max(1, len(pairs)))

    def bound_at(self, t: float) -> np.ndarray:
        times = self.timeline.times
        k = min(max(int(np.searchsorted(times, t, side="right")) - 1, 0), len(times) - 2)
        span = times[k + 1] - times[k]
        s = 0.0 if span <= 0 else min(1.0, max(0.0, (t - times[k]) / span))
        return self.bound[k] + s * (self.bound[k + 1] - self.bound[k])

    def time_of(self, pair: int, level: float) -> float:
        """The first time the pair's motion bound reaches ``level`` (inf: never)."""
        column = self.bound[:, pair]
        if level > column[-1]:
            return math.inf
        k = int(np.searchsorted(column, level, side="left"))
        if k == 0:
            return float(self.timeline.times[0])
        lo, hi = column[k - 1], column[k]
        s = 0.0 if hi <= lo else (level - lo) / (hi - lo)
        t0, t1 = self.timeline.times[k - 1], self.timeline.times[k]
        return float(t0 + s * (t1 - t0))

    def times_of(self, pairs: np.ndarray, levels: np.ndarray) -> np.ndarray:
        """:meth:`time_of` of each of ``pairs`` at its level in ``levels``, at once."""
        column = self.bound[:, pairs]
        times = self.timeline.times
        k = np.count_nonzero(column < levels, axis=0)  # searchsorted, side="left"
        upper = np.minimum(k, len(times) - 1)
        lower = np.maximum(upper - 1, 0)
        cols = np.arange(len(pairs))
        lo, hi = column[lower, cols], column[upper, cols]
        with np.errstate(invalid="ignore", divide="ignore"):
            s = np.where(hi <= lo, 0.0, (levels - lo) / (hi - lo))
        out = times[lower] + s * (times[upper] - times[lower])
        out = np.where(k == 0, times[0], out)
        return np.where(levels > column[-1], math.inf, out)

    def measure(self, t: float, pairs: Sequence[int]) -> np.ndarray:
        q = self.timeline.state(t)
        out = self._out[:len(pairs)]
        self.checker.pair_distances(self.model.to_pin(q), [self.pairs[p][0] for p in pairs], out)
        self.queries += len(pairs)
        distances = out - _SLACK
        if len(distances):
            i = int(np.argmin(distances))
            if distances[i] < self.least:
                p = int(pairs[i])
                _, a, b = self.pairs[p]
                self.least, self.least_pair, self.least_time = (
                    float(distances[i] + _SLACK), (self.names[a], self.names[b]), float(t))
                self.least_index = p
        return distances.copy()

    def run(self) -> Conflict | None:
        clearance = self.options.clearance
        n = len(self.pairs)
        if n == 0:
            return None
        t_end = float(self.timeline.times[-1])
        last = np.full(n, float(self.timeline.times[0]))
        due = last.copy()  # every pair measured at the start
        steps = np.zeros(n, dtype=np.int64)
        while True:
            now = float(due.min())
            if not math.isfinite(now):
                return None
            reach = due - last
            pick = np.flatnonzero((due <= now) | ((now - last) >= _EARLY * reach))
            distances = self.measure(now, pick.tolist())
            steps[pick] += 1
            # The next time each pair must be measured: where its motion bound has grown
            # by its distance less the clearance (all picked pairs at once).
            levels = self.bound_at(now)[pick] + (distances - clearance)
            nxt = self.times_of(pick, levels)
            following = np.where(nxt > t_end, math.inf, np.maximum(nxt, now))
            touching = distances < clearance + _SLACK  # at the clearance: no step is safe
            endless = steps[pick] > self.options.max_steps
            stuck = following == now  # no progress possible: d is at the clearance
            failed = np.flatnonzero(touching | endless | stuck)
            if len(failed):
                i = int(failed[0])
                p, d = int(pick[i]), float(distances[i])
                if touching[i]:
                    return self.conflict(p, float(last[p]), now, d)
                if endless[i]:
                    return self.conflict(p, float(last[p]), now, d, proven=False)
                return self.conflict(p, now, now, d, proven=False)
            last[pick] = now
            due[pick] = following
            if now >= t_end:
                return None

    def conflict(self, pair: int, free: float, bad: float, distance: float,
                 proven: bool = True) -> Conflict:
        """The conflict of ``pair``, moved back toward ``free`` (where it kept its
        clearance) by bisection on exact distances."""
        clearance = self.options.clearance
        if proven:
            while bad - free > TIME_TOLERANCE:
                mid = 0.5 * (free + bad)
                d = float(self.measure(mid, [pair])[0])
                if d < clearance:
                    bad, distance = mid, d
                else:
                    free = mid
        _, a, b = self.pairs[pair]
        la, lb = int(self.owner[a]), int(self.owner[b])
        lanes = self.timeline.lanes
        return Conflict(bad, (self.names[a], self.names[b]), (lanes[la].name, lanes[lb].name),
                        (self.timeline.motion_label(la, bad), self.timeline.motion_label(lb, bad)),
                        distance, proven)


_LEVERS: dict[int, tuple[object, np.ndarray]] = {}  # id(geometry model) -> (it, levers)


def _levers(model, geometry) -> np.ndarray:  # type: ignore[no-untyped-def]
    """:func:`~taskrunner.collision.tree.lever_arms` of a checker's geometry model, kept for
    the few latest models (a scene's checker lives until the scene is edited)."""
    key = id(geometry)
    found = _LEVERS.get(key)
    if found is not None and found[0] is geometry:
        return found[1]
    if len(_LEVERS) >= 8:
        _LEVERS.pop(next(iter(_LEVERS)))
    levers = lever_arms(model, geometry)
    _LEVERS[key] = (geometry, levers)
    return levers


def _body_name(obj, pin_model) -> str:  # type: ignore[no-untyped-def]
    """A geometry's body: its link's name for a robot link, else the object's name."""
    frame = int(obj.parentFrame)
    if 0 <= frame < len(pin_model.frames):
        name = str(obj.name)
        link = str(pin_model.frames[frame].name)
        return link if name.startswith(link) else name
    return str(obj.name)
