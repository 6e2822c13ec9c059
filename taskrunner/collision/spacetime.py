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
times of *any* lane the whole state moves on a straight line in joint space: over the
lanes' common clock, the full state is a polyline through the states at every sample
time of every lane. That polyline is verified by the path verifier
(:mod:`taskrunner.scene.path_verifier`: conservative advancement as in Schwarzer, Saha &
Latombe, IEEE T-RO 2005, compiled), on the pairs of bodies of two different lanes only,
each body grown by the clearance: a measurement ``d`` of a pair proves it at least
``clearance`` apart over the stretch where its motion bound (the lever arms of the joints
that move one body and not the other, times how far they turn) stays below
``d - clearance``; pairs far apart take cheap lower bounds (bounding volumes), close ones
coal's exact signed distance through the scene's
:class:`~taskrunner.scene.collision.CollisionChecker`. A pair measured closer than the
clearance is a :class:`Conflict`, moved back by bisection on exact distances to within
:data:`TIME_TOLERANCE` of where its distance first drops below the clearance (a contact
found with the walk's optimistic steps is first walked again up to there without them,
which proves every pair clear up to where it has come: the conflict is the first in
time). Between
measurements the verifier lets bodies come at most half its margin (1 µm) closer than it
proves: the clearance it is given is larger by that much, so that the lanes' bodies are
never closer than ``clearance``. The walk always advances (its steps are at least the
margin in motion bound), so it ends on every timeline.

The verifier is independent of the planner and of the run: it reads trajectories and a
scene only, so a run record can be verified after the fact
(:mod:`taskrunner.tree.expect`).

*Held objects.* A motion may say what its arm holds while it runs
(:attr:`TimedMotion.held`). The objects any motion holds are then verified where they are
at each instant: held, set down or not taken yet (:mod:`taskrunner.collision.held`); the
pairs involving them stretch by stretch of the clock where that changes, every other pair
once over the whole window in the scene as it is. Motions that say nothing (``held``
None) leave the scene's objects as they are: the walk is then the one above, unchanged.
"""

from __future__ import annotations

import copy
import math
import time
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, replace
from typing import TYPE_CHECKING

import numpy as np

from taskrunner.collision.held import HeldObjects, held_objects, lanes_state
from taskrunner.collision.owners import body_name, joint_lanes, lane_owners
from taskrunner.collision.samples import state_columns
from taskrunner.errors import ArgumentError, InvalidStateError
from taskrunner.types import JointTrajectory

if TYPE_CHECKING:  # the planning scene is above the collision core: passed in, not imported
    from taskrunner.scene import Scene, SceneObject

__all__ = ["LEAST_TOLERANCE", "TIME_TOLERANCE", "Conflict", "Lane", "LeastClearance",
           "SpacetimeOptions", "SpacetimeVerification", "TimedMotion", "lanes_state",
           "least_clearance", "verify_lanes"]

TIME_TOLERANCE = 1e-3
"""s: a conflict's time is where the distance first drops below the clearance, within this."""
LEAST_TOLERANCE = 2e-4
"""m: :func:`least_clearance` brackets the least distance between lanes this tightly."""
_SLACK = 1e-6  # m: coal's distance tolerance, taken off every measured distance


@dataclass(frozen=True)
class TimedMotion:
    """A trajectory of one lane, started at ``start`` (s, the common clock).

    Attributes:
        label: what the motion is, for reports (the task file:line and step).
        held: the objects attached while it runs (each ``attached_to`` its link, its
            pose in that link's frame); those attached to a link of this lane's are
            its lane's bodies (module text). Objects of other lanes are ignored, so the
            attached objects of the scene the motion started in may be given whole.
            None: not known (the scene's objects as they are).
    """

    trajectory: JointTrajectory
    start: float
    label: str | None = None
    held: tuple[SceneObject, ...] | None = None

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
        exact: every measurement is coal's exact distance, none a cheap lower bound, so
            that :attr:`SpacetimeVerification.min_distance` is the least distance
            measured over the whole timeline (slower where the arms are far apart).
    """

    clearance: float = 0.0
    exact: bool = False

    def __post_init__(self) -> None:
        if not (math.isfinite(self.clearance) and self.clearance >= 0):
            raise ArgumentError(f"'clearance' must be a number of metres >= 0 "
                             f"(got {self.clearance!r})")


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
    """

    time: float
    bodies: tuple[str, str]
    lanes: tuple[str, str]
    motions: tuple[str | None, str | None]
    distance: float

    @property
    def depth(self) -> float:
        """How deep the bodies penetrate there (m, 0 where they do not touch)."""
        return max(0.0, -self.distance)

    def describe(self) -> str:
        """One line: when, which bodies of which motions, how close."""
        what = [m or f"{lane} at rest" for m, lane in zip(self.motions, self.lanes)]
        how = (f"{1e3 * self.depth:.1f} mm deep" if self.distance < 0
               else f"{1e3 * self.distance:.1f} mm apart")
        return (f"{self.bodies[0]} ({what[0]}) and {self.bodies[1]} ({what[1]}) at "
                f"{self.time:.3f} s, {how}")


@dataclass(frozen=True)
class SpacetimeVerification:
    """What :func:`verify_lanes` found.

    Attributes:
        conflict: the first conflict in time, None when the lanes keep their clearance.
        min_distance: m, the least exact distance measured between two lanes' bodies
            (inf: none measured: no pair, or every pair far enough apart for cheap
            bounds, unless :attr:`SpacetimeOptions.exact`); the true least distance lies
            between the clearance and this.
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
    held = _held(scene, lanes, timeline)
    if held is None:
        conflict, walks = _walk_apart(scene, timeline, options)
    else:
        # Every pair of no object that changes over the whole window, then those of one,
        # stretch by stretch (module text).
        conflict, walks = _walk_apart(scene, timeline, options, None, held.changing,
                                      held.resting)
        for stretch in held.stretches:  # in time order
            end = stretch.end if conflict is None else min(stretch.end, conflict.time)
            if end < stretch.start or (conflict is not None and stretch.start >= conflict.time):
                break
            found, more = _walk_apart(stretch.scene,
                                      timeline.cut(stretch.start, end, stretch.frozen),
                                      options, (held.changing,), frozenset(), stretch.lanes)
            walks += more
            if found is not None:  # before the other pairs' first conflict, if any
                conflict = found
                break
    least = min(walks, key=lambda w: w.least)
    return SpacetimeVerification(conflict, least.least, least.least_pair, least.least_time,
                                 sum(w.queries for w in walks), time.perf_counter() - started)


def _walk_apart(scene: Scene, timeline: _Timeline, options: SpacetimeOptions,
                only: tuple[frozenset[str], ...] | None = None,
                without: frozenset[str] = frozenset(), lying: Mapping[str, int] | None = None
                ) -> tuple[Conflict | None, list[_Walk]]:
    """Walk the pairs of :class:`_Walk`'s ``only`` and ``without``: those of the objects
    ``lying`` in the world (of their lanes) with no clearance (not to be touched, as a
    plan keeps off the world; their distances not in :attr:`_Walk.least`), the others
    with the clearance. The first conflict, and the walks."""
    names = frozenset(lying or ())
    walks = [_Walk(scene, timeline, options, only, without | names, lying)]
    if names:
        walks.append(_Walk(scene, timeline, replace(options, clearance=0.0),
                           (*(only or ()), names), without, lying, uncounted=names))
    conflict = None
    for walk in walks:
        conflict = _earlier(conflict, walk.run())
    return conflict, walks


def _earlier(a: Conflict | None, b: Conflict | None) -> Conflict | None:
    """The earlier of two conflicts (None: none)."""
    return b if a is None or (b is not None and b.time < a.time) else a


def _held(scene: Scene, lanes: Sequence[Lane], timeline: _Timeline) -> HeldObjects | None:
    """The objects the lanes' motions hold, and the stretches where that changes
    (:func:`~taskrunner.collision.held.held_objects`)."""
    t0, t1 = float(timeline.times[0]), float(timeline.times[-1])
    return held_objects(scene, lanes, (t0, t1),
                        joint_lanes(scene.robot, scene.checker, timeline.columns),
                        lambda t: timeline.state(t) if t0 <= t <= t1
                        else lanes_state(scene, lanes, t))


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
    round lowers the clearance tried by at least ``tolerance`` and never below what was
    proven, so the rounds end. Where the lanes' bodies touch, the first contact is
    reported (how deep they go is not measured). Every measurement is exact
    (:attr:`SpacetimeOptions.exact`).

    Raises:
        ArgumentError: ``tolerance`` is not a positive number of metres.
        InvalidStateError: as :func:`verify_lanes`.
    """
    if not (math.isfinite(tolerance) and tolerance > 0):
        raise ArgumentError(f"'tolerance' must be a positive number of metres "
                            f"(got {tolerance!r})")
    started = time.perf_counter()
    whole = _Timeline(scene, lanes, window)
    held = None if whole.empty else _held(scene, lanes, whole)
    # The pairs of the arms and what they hold (what lies in the world is not measured):
    # those of no object that changes over the whole window, those of one stretch by
    # stretch (module text).
    pieces: list[tuple[Scene, _Timeline, tuple[frozenset[str], ...] | None,
                       frozenset[str], Mapping[str, int]]] = []
    if not whole.empty:
        pieces.append((scene, whole, None, held.named - held.steady if held else frozenset(),
                       {}))
    for s in held.stretches if held else ():
        assert held is not None
        lies = frozenset(s.lanes)
        if held.changing - lies:
            pieces.append((s.scene, whole.cut(s.start, s.end, s.frozen), (held.changing - lies,),
                           lies, s.lanes))
    queries = 0
    best: _Walk | None = None  # the walk that measured the least distance so far
    timeline: _Timeline | None = None  # its timeline
    clearance, lower = 0.0, -math.inf
    while pieces:
        # Each piece of the timeline (one, unless what the lanes hold changes), in time
        # order: the first conflict stops the round.
        walked = conflict = False
        for piece_scene, piece, only, without, lying in pieces:
            walk = _Walk(piece_scene, piece, SpacetimeOptions(clearance=clearance, exact=True),
                         only=only, without=without, lying=lying)
            if not walk.pair_count:
                continue
            walked = True
            found = walk.run()
            queries += walk.queries
            if best is None or walk.least < best.least:
                best, timeline = walk, piece
            if found is not None:
                conflict = True
                break
        if not walked or best is None:
            break
        if not conflict:
            lower = max(lower, clearance)
            following = best.least - tolerance
        elif clearance == 0.0:
            # Touching or penetrating: nothing is proven.
            lower = -math.inf
            break
        else:
            following = max(0.0, min(best.least, clearance) - tolerance)
        if following <= lower:  # the bracket [lower, least] is within the tolerance
            break
        clearance = following
    if best is None or best.least_index is None or timeline is None:
        return LeastClearance(math.inf, math.inf, None, None, (None, None), None, queries,
                              time.perf_counter() - started)
    a, b = best.bodies(best.least_index)
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
        self.lanes, self.model = list(lanes), model
        self.columns: list[np.ndarray] = []
        seen: dict[str, str] = {}
        placed: list[list[TimedMotion]] = []  # per lane, its motions in time order
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
            self.columns.append(state_columns(model, names))
            placed.append(ordered)
        motions = [m for lane in self.lanes for m in lane.motions]
        moving = sum(1 for lane in self.lanes if lane.motions)
        self.empty = moving == 0 or len(self.lanes) < 2
        if self.empty:
            return
        t0 = min(m.start for m in motions) if window is None else window[0]
        t1 = max(m.end for m in motions) if window is None else window[1]
        # The sample times inside the window: of the motions running in it only.
        stamps = np.concatenate([np.zeros(0), *(m.start + m.trajectory.times for m in motions
                                                 if m.start < t1 and m.end > t0)])
        times = np.sort(np.concatenate([[t0, t1], stamps[(stamps > t0) & (stamps < t1)]]))
        self.times = times = times[np.concatenate([[True], times[1:] != times[:-1]])]
        base = scene.state.copy()
        lanes_kept = []
        for ordered_lane in placed:
            # A motion whose joints a later one sets from the timeline's first row on
            # leaves nothing in it (the lane's motions before the window, mostly).
            settled: set[str] = set()
            kept = []  # latest first, with its joints' state columns
            for motion in reversed(ordered_lane):
                moved = motion.trajectory.names
                if not settled.issuperset(moved):
                    kept.append((motion, state_columns(model, moved)))
                if motion.start <= times[0]:
                    settled.update(moved)
            # Before its first motion, a joint is where that one starts (one a motion
            # left out moves is set from the first row on).
            for motion, idx in kept:
                base[idx] = motion.trajectory.positions[0]
            lanes_kept.append(kept)
        states = np.repeat(base[None, :], len(times), axis=0)
        for kept in lanes_kept:
            for motion, idx in reversed(kept):
                # From its start on (held at its end after), each where the last left it:
                # the times are sorted, so the rows from its start on are a tail.
                first = int(np.searchsorted(times, motion.start, side="left"))
                local = times[first:] - motion.start
                trajectory = motion.trajectory
                if not len(local):
                    continue
                if local[0] >= trajectory.times[-1]:  # ended before them: where it ends
                    states[first:, idx] = trajectory.positions[-1]
                    continue
                for j, column in enumerate(idx.tolist()):
                    states[first:, column] = np.interp(local, trajectory.times,
                                                       trajectory.positions[:, j])
        self.states = model.apply_mimic(states)

    def cut(self, a: float, b: float,
            frozen: tuple[np.ndarray, np.ndarray] | None = None) -> _Timeline:
        """The timeline from ``a`` to ``b`` (s, within this one's): its rows between,
        the states at both ends; ``frozen``: state columns kept at these values."""
        piece = copy.copy(self)
        inside = (self.times > a) & (self.times < b)
        piece.times = np.unique(np.concatenate([[a, b], self.times[inside]]))
        rows = np.flatnonzero(inside)
        piece.states = np.vstack([self.state(a)[None, :], self.states[rows],
                                  self.state(b)[None, :]]) if b > a else self.state(a)[None, :]
        if frozen is not None:
            piece.states[:, frozen[0]] = frozen[1]
            piece.states = self.model.apply_mimic(piece.states)
        return piece

    def prefix(self, position: float) -> tuple[np.ndarray, Callable[[float], float]]:
        """The rows of :attr:`states` up to ``position`` (as :meth:`time_at`), the state
        there last, and what a position along them is along the whole."""
        n = len(self.states)
        k = min(max(int(position), 0), max(n - 2, 0))
        frac = position - k
        if n == 1 or frac <= 0.0:
            return self.states[:k + 1], lambda at: at
        # As the path verifier interpolates a position: the same state to the last bit.
        last = self.states[k] + frac * (self.states[k + 1] - self.states[k])
        return (np.vstack([self.states[:k + 1], last[None, :]]),
                lambda at: at if at <= k else k + (at - k) * frac)

    def time_at(self, position: float) -> float:
        """The time (s) of a position along :attr:`states` (row index plus the fraction
        of the way to the next row), as the path verifier reports them."""
        n = len(self.times)
        if n == 1:
            return float(self.times[0])
        k = min(max(int(position), 0), n - 2)
        return float(self.times[k] + (position - k) * (self.times[k + 1] - self.times[k]))

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
    """Every pair of two lanes' bodies along the timeline, on the path verifier's
    compiled walk (module text)."""

    def __init__(self, scene: Scene, timeline: _Timeline, options: SpacetimeOptions,
                 only: Sequence[frozenset[str]] | None = None,
                 without: frozenset[str] = frozenset(),
                 lying: Mapping[str, int] | None = None,
                 uncounted: frozenset[str] = frozenset()) -> None:
        """``only``: the pairs with an object of each of these (default: every pair),
        none with one of ``without``; ``lying``: world objects of a lane (by name);
        ``uncounted``: objects whose distances are not kept in :attr:`least`."""
        model = scene.robot
        self.scene, self.model, self.timeline, self.options = scene, model, timeline, options
        self.checker = checker = scene.checker
        owners = lane_owners(model, checker, timeline.columns, only, without, lying or {},
                             uncounted)
        self.uncounted = owners.uncounted
        self.owner = owners.owner
        # The checker's pairs walked (ascending), and each one's bodies, the first of
        # the lower lane.
        self.pair_ids, self.firsts, self.seconds = owners.pair_ids, owners.firsts, owners.seconds
        self.queries = 0
        self.least = math.inf
        self.least_pair: tuple[str, str] | None = None
        self.least_time: float | None = None
        self.least_index: int | None = None
        self._out = np.zeros(max(1, len(self.pair_ids)))

    @property
    def pair_count(self) -> int:
        """How many pairs of two lanes' bodies are walked."""
        return len(self.pair_ids)

    def local(self, pair: int) -> int:
        """The index into :attr:`pair_ids` of the checker's pair ``pair``."""
        return int(np.searchsorted(self.pair_ids, pair))

    def bodies(self, p: int) -> tuple[int, int]:
        """The geometries of walked pair ``p``, the first of the lower lane."""
        return int(self.firsts[p]), int(self.seconds[p])

    def name(self, g: int) -> str:
        """The body of geometry ``g`` (its link's name, or the object's)."""
        return body_name(self.checker.geometry_model.geometryObjects[g], self.model.model)

    def run(self) -> Conflict | None:
        """Walk the pairs over the timeline: the first conflict, or None. With the
        options' ``exact``, every measurement is coal's distance (else far pairs take
        cheap lower bounds), so that :attr:`least` is the least distance measured."""
        if not self.pair_count:
            return None
        verifier = self.scene.pair_verifier(self.pair_ids)
        # Between measurements the verifier lets bodies grown by the clearance overlap by
        # at most half its margin: grown by that much more, they keep the clearance.
        clearance = self.options.clearance + 0.5 * verifier.margin
        exact = self.options.exact
        found = verifier.verify(self.timeline.states, clearance, exact, self._observe)
        queries = found.distance_queries
        if not found.valid and found.fraction is not None:
            # Its optimistic steps may have passed another pair's first contact: the way up
            # to this one walked again without them (every pair proven clear up to where
            # the walk has come), so that the conflict found is the first in time.
            rows, along = self.timeline.prefix(found.fraction)
            first = verifier.verify(rows, clearance, exact,
                                    lambda at, pairs, d: self._observe(along(at), pairs, d),
                                    gain=0.0)
            queries += first.distance_queries
            if not first.valid and first.fraction is not None:
                found = replace(first, fraction=along(first.fraction), covered=along(
                    first.covered if first.covered is not None else first.fraction))
        self.queries += queries
        if found.valid:
            return None
        assert found.pair_index is not None and found.fraction is not None
        pair = self.local(found.pair_index)
        bad = self.timeline.time_at(found.fraction)
        free = self.timeline.time_at(found.covered if found.covered is not None
                                     else found.fraction)
        return self.conflict(pair, free, bad, float(self.measure(bad, [pair])[0]))

    def _observe(self, position: float, pairs: np.ndarray, distances: np.ndarray) -> None:
        """A round of the verifier's exact distances, at a timeline position (a few
        pairs a round, mostly: their least taken as Python floats, cheaper than numpy's)."""
        if len(distances) and min(distances.tolist()) < self.least:
            self._observe_at(self.timeline.time_at(position), pairs, distances)

    def measure(self, t: float, pairs: Sequence[int]) -> np.ndarray:
        """The exact distances of ``pairs`` (indices into :attr:`pairs`) at ``t`` (m,
        coal's tolerance taken off)."""
        q = self.timeline.state(t)
        out = self._out[:len(pairs)]
        ids = self.pair_ids[np.asarray(pairs, dtype=np.int64)]
        self.checker.pair_distances(self.model.to_pin(q), ids.tolist(), out)
        self.queries += len(pairs)
        self._observe_at(t, ids, out)
        return out - _SLACK

    def _observe_at(self, t: float, pairs: np.ndarray, distances: np.ndarray) -> None:
        """Exact distances of ``pairs`` (checker pairs) at ``t``: the least of them kept
        if the least so far."""
        if not len(distances):
            return
        if self.uncounted is not None:
            distances = np.where(self.uncounted[pairs], np.inf, distances)
        i = int(np.argmin(distances))
        if distances[i] < self.least:
            p = self.local(int(pairs[i]))
            a, b = self.bodies(p)
            self.least, self.least_pair = float(distances[i]), (self.name(a), self.name(b))
            self.least_time, self.least_index = float(t), p

    def conflict(self, pair: int, free: float, bad: float, distance: float) -> Conflict:
        """The conflict of ``pair``, moved back toward ``free`` (where it kept its
        clearance) by bisection on exact distances."""
        clearance = self.options.clearance
        while bad - free > TIME_TOLERANCE:
            mid = 0.5 * (free + bad)
            d = float(self.measure(mid, [pair])[0])
            if d < clearance:
                bad, distance = mid, d
            else:
                free = mid
        a, b = self.bodies(pair)
        la, lb = int(self.owner[a]), int(self.owner[b])
        lanes = self.timeline.lanes
        return Conflict(bad, (self.name(a), self.name(b)), (lanes[la].name, lanes[lb].name),
                        (self.timeline.motion_label(la, bad), self.timeline.motion_label(lb, bad)),
                        distance)
