"""Goal states for a straight approach: reachable, and joined to the contact by a line.

A pick's pre-grasp (a place's pre-place, a hand-over's pre-grasp) is planned to; from
there the grasp frame moves in a straight line to the contact pose. An IK solution of the
pre-pose on the wrong branch can make that line impossible (a joint would have to jump),
so :func:`approach_goals` returns goal states whose line is followed point by point
first (without collision checks: those come with the real straight move).

Arms of six joints or more reach the poses exactly. An arm with fewer
(``position_only_ik``, like the 5-DOF servo arm) cannot put its tool at an arbitrary
pose: only the tool's position is planned, and its orientation is whatever the arm's
remaining freedom gives. For grasping and putting down that orientation still matters
(the fingers should close across the object's faces, a bar laid down should lie flat),
so :func:`approximate` chooses it as well as the arm allows:

1. position-only IK solutions are sampled for the point to be placed (the grasp frame's
   origin, or a held object's centre: then the frame's position follows from the
   orientation, found by a few fixed-point rounds);
2. when the group's last joint rolls the frame about its own z axis (a wrist roll, which
   does not move the frame's origin), it is turned to bring the closing axis (y) as near
   the wanted one as the pointing axis (z) allows;
3. a local full-pose solve is tried from the nearest approximation of each wanted pose:
   where that pose is reachable exactly, it is used;
4. the candidates nearest the wanted orientations come first. For a grasp, a turn about
   the closing axis counts little: the fingers stay flat on the same faces
   (:func:`orientation_error`).

For such an arm the pre-pose is the contact state moved along the line with the
orientation unchanged, checked point by point, so the straight approach can hold the
orientation all the way. Where the wrist cannot hold a candidate's orientation over the
whole line, its line is shortened (to 75, 50 or 25 %, :data:`LIFT_PARTS`) before a
candidate farther from the wanted orientation is taken: the object stays upright and the
approach is shorter. Where no candidate allows any of that, the moved poses are
approximated on their own and the approach follows the line by position only.

The goal list is computed as far as it is used (:class:`StagedGoals`: a planner nearly
always takes the first goal by its straight line), and the choice is remembered by its
inputs (model, poses, start state, seed), so ``run-task check``'s dry run and the run that
follows it choose once.
"""

from __future__ import annotations

import math
import threading
from collections import OrderedDict
from collections.abc import Callable, Hashable, Iterable, Iterator, Sequence
from dataclasses import dataclass
from typing import cast

import numpy as np
import pinocchio as pin

from taskrunner.errors import IkFailedError
from taskrunner.kinematics import IkOptions, IkSolver
from taskrunner.planning.request import Goal, JointGoal, PoseGoal
from taskrunner.robot.model import RobotModel
from taskrunner.tree import aiming
from taskrunner.tree.aiming import (
    Frames,
    aimed,
    nearest_orientation,
    offset_at,
    orientation_error,
)
from taskrunner.tree.choice import model_key, rounded
from taskrunner.types import Pose

__all__ = ["Approximation", "Lift", "StagedGoals", "approach_goals", "approximate",
           "approximate_goals", "forget", "orientation_error", "staged_approach_goals",
           "wrist_roll"]

Lift = Callable[[int, pin.SE3], np.ndarray]
"""``(index of a wanted pose, link pose reached there) -> world offset (m)``."""

SAMPLES = 8  # position-only IK solutions per distinct point
KEEP = 6  # joint goals returned
LIFT_PARTS = (1.0, 0.75, 0.5, 0.25)
"""Parts of a short arm's lift tried in turn for each candidate, nearest the wanted
orientation first: where the wrist cannot hold that orientation over the whole approach
(a 5-DOF arm holds its tool vertical in a thin band of heights), the approach is
shortened rather than the object tilted (as MoveIt Task Constructor's approach stages
take a ``min_distance`` to ``max_distance``)."""
LINE_STEP = 0.005  # m between the points a straight line is checked at (eef_step)
LINE_TURN = 0.05  # rad of turn between two such points (max_rotation_step)
MAX_JOINT_STEP = 0.2  # rad a joint may move between two points of a line (max_joint_step)
FULL_POSE_SOLUTIONS = 6  # IK solutions tried per pre-pose of a full-pose arm
_EXACT = IkOptions(position_only=False, attempts=1, tolerance=1e-5)
_LOCAL = IkOptions(position_only=True, attempts=1)
_largest, _absolute = np.maximum.reduce, np.absolute  # the ufuncs, without the wrappers
# m (and Frobenius norm of a rotation difference): a goal state equal to the start state
# puts the frame within the IK tolerance (1e-5) of its target; this is a hundred times that.
_AT_TARGET = 1e-3


@dataclass(frozen=True)
class Approximation:
    """One goal state and how far its frame's orientation is from the wanted pose's.

    Attributes:
        q: the full state vector.
        wanted: index of the wanted pose it approximates.
        angle: how far the frame's orientation is from the wanted one (rad, see
            :func:`orientation_error`).
    """

    q: np.ndarray
    wanted: int
    angle: float


def wrist_roll(model: RobotModel, group: str, link: str, q: np.ndarray) -> tuple[int, float] | None:
    """The group's last joint if it turns ``link`` about the link's own z axis without
    moving its origin: ``(state index, +1 or -1 for the turn's sense about z)``; else None."""
    joint = model.joint(model.group(group).joint_names[-1])
    if joint.type not in ("revolute", "continuous"):
        return None
    data = model.model.createData()
    frame = model.frame_id(link)

    def pose(values: np.ndarray) -> pin.SE3:
        pin.framesForwardKinematics(model.model, data, model.to_pin(values))
        return pin.SE3(data.oMf[frame])

    eps = 1e-4
    before = pose(q)
    turned = q.copy()
    turned[joint.index] += eps
    after = pose(turned)
    if np.linalg.norm(after.translation - before.translation) > 1e-7:
        return None
    omega = pin.log3(before.rotation.T @ after.rotation) / eps  # in the link frame
    if abs(abs(omega[2]) - 1.0) > 1e-3 or np.linalg.norm(omega[:2]) > 1e-3:
        return None
    return joint.index, math.copysign(1.0, omega[2])


_SOLVERS = threading.local()  # .models: {id(model): (the model, {(group, link): solver})}
_SOLVER_MODELS = 4
"""Models whose solvers a thread keeps (the most recently used): a solver holds its model,
so an unbounded cache kept every model a long-lived process (a server's check worker)
ever checked."""


def _solver(model: RobotModel, group: str, link: str) -> IkSolver:
    """The IK solver of ``link`` for ``group``, kept per model and thread: its seed table
    (built by the first search that restarts, ~5-10 ms) serves every later choice. A
    solver's answers do not depend on its earlier calls (its random draws restart from
    the call's seed), and it is not thread-safe, hence one per thread (dropped with it).
    The solvers of the :data:`_SOLVER_MODELS` models used last are kept."""
    models: OrderedDict[int, tuple[RobotModel, dict[tuple[str, str], IkSolver]]] | None = \
        getattr(_SOLVERS, "models", None)
    if models is None:
        models = _SOLVERS.models = OrderedDict()
    entry = models.get(id(model))
    if entry is None or entry[0] is not model:
        entry = models[id(model)] = (model, {})
        while len(models) > _SOLVER_MODELS:
            models.popitem(last=False)
    models.move_to_end(id(model))
    solver = entry[1].get((group, link))
    if solver is None:
        solver = entry[1][(group, link)] = IkSolver(model, group, frame=link)
    return solver


def forget_solvers() -> None:
    """Drop this thread's IK solvers: the next goal choice builds them anew."""
    _SOLVERS.models = OrderedDict()


_MEMO_SIZE = 512
_MEMO: OrderedDict[tuple[object, ...], object] = OrderedDict()
_MEMO_LOCK = threading.Lock()


def _remembered(model: RobotModel, key: tuple[object, ...], make: Callable[[], object]) -> object:
    """``make()``, remembered for ``model``'s content and ``key`` (the last
    :data:`_MEMO_SIZE` kept).

    The goal choice is a function of its inputs (the model, the poses, the start state,
    the seed; solvers' answers do not depend on their earlier calls), and a task is
    chosen for twice with the same ones: by ``run-task check``'s dry run and by the run
    that follows, in the same process or on a cell loaded again (a task given by a
    relative path, the REST API's session cell). The model counts by its content digest
    (:func:`~taskrunner.tree.choice.model_key`, as the check's goal choices do), not by
    its identity. Values are kept read-only and shared."""
    full = (model_key(model), *key)
    with _MEMO_LOCK:
        hit = _MEMO.get(full, _MISSING)
        if hit is not _MISSING:
            _MEMO.move_to_end(full)
            return hit
    value = make()
    with _MEMO_LOCK:
        _MEMO[full] = value
        while len(_MEMO) > _MEMO_SIZE:
            _MEMO.popitem(last=False)
    return value


_MISSING = object()


def forget() -> None:
    """Drop every remembered goal choice (see :func:`_remembered`)."""
    with _MEMO_LOCK:
        _MEMO.clear()


def _frozen(q: np.ndarray) -> np.ndarray:
    q.setflags(write=False)
    return q


def _bytes(pose: pin.SE3) -> bytes:
    return pose.homogeneous.tobytes()


def approach_goals(model: RobotModel, group: str, link: str, contact: Sequence[pin.SE3],
                   lift: Lift, start: np.ndarray, seed: int, point: np.ndarray | None = None,
                   grasping: bool = False, keep: int = KEEP) -> tuple[Goal, ...]:
    """Goals a straight line away from the contact poses of ``link`` (``lift``: see
    :data:`Lift`), from which the arm can follow that line back to the contact.

    Args:
        point: for a short arm, the point of ``link`` (its frame, m) placed exactly.
        grasping: the contact poses are grasps (see :func:`approximate_goals`).
        keep: goals returned (twice as many for a full-pose arm, whose goals differ
            more).

    Raises:
        IkFailedError: a short arm reaches no contact position.
    """
    return staged_approach_goals(model, group, link, contact, lift, start, seed, point,
                                 grasping, keep).all()


def staged_approach_goals(model: RobotModel, group: str, link: str, contact: Sequence[pin.SE3],
                          lift: Lift, start: np.ndarray, seed: int,
                          point: np.ndarray | None = None, grasping: bool = False,
                          keep: int = KEEP) -> StagedGoals:
    """:func:`approach_goals`' list, computed as far as it is asked for (see
    :class:`StagedGoals`): the IK searches now, the lines followed from their solutions
    as goals are taken.

    Raises:
        IkFailedError: a short arm reaches no contact position.
    """
    start = np.array(start, dtype=float)
    if model.group(group).position_only_ik:
        return _lifted(model, group, link, contact, start, seed, point, lift, grasping, keep)
    solver = _solver(model, group, link)
    options = IkOptions(position_only=False, num_solutions=FULL_POSE_SOLUTIONS, seed=seed,
                        attempts=20 * FULL_POSE_SOLUTIONS)
    pre = [pin.SE3(p.rotation, p.translation + np.asarray(lift(i, p), dtype=float))
           for i, p in enumerate(contact)]
    found: list[Iterator[np.ndarray]] = []
    for away, there in zip(pre, contact):
        def solve(away: pin.SE3 = away) -> tuple[np.ndarray, ...] | None:
            try:
                return tuple(_frozen(np.array(s.q)) for s in solver.solve_all(
                    away, seed_q=start, options=options))
            except IkFailedError:
                return None
        solutions = _remembered(model, ("solutions", group, link, _bytes(away), start.tobytes(),
                                        seed, FULL_POSE_SOLUTIONS), solve)
        if solutions is None:
            continue
        assert isinstance(solutions, tuple)
        found.append(_followers(model, group, link, solver, list(solutions), away, there))

    def otherwise() -> tuple[Goal, ...]:
        # No line can be followed: plan to the pre-poses anyway; the straight move will
        # say why it stops.
        return tuple(PoseGoal(Pose.from_se3(p), link=link, position_only=False) for p in pre)

    # Every contact pose's states in turn, so that one pose blocked by an obstacle (its
    # states in collision, which the planner drops) leaves the others to choose from.
    # The lines are followed as the goals are taken: those after the last goal kept are
    # never needed.
    here = Frames(model, link)(start).translation
    near = any(float(np.linalg.norm(p.translation - here)) <= _AT_TARGET for p in pre)
    return StagedGoals(model, group, _in_turn(found), 2 * keep, otherwise, whole=near,
                       key=_staged_key(group, link, contact, lift, seed, point, grasping, keep))


def _staged_key(group: str, link: str, contact: Sequence[pin.SE3], lift: Lift, seed: int,
                point: np.ndarray | None, grasping: bool, keep: int) -> tuple[Hashable, ...]:
    """What a staged goal list is computed from, but the start state (see
    :attr:`StagedGoals.key`): the lift by its offsets at the contact poses themselves."""
    return ("staged", group, link, tuple(rounded(p.homogeneous) for p in contact),
            tuple(rounded(lift(i, p)) for i, p in enumerate(contact)), seed,
            None if point is None else rounded(point), grasping, keep)


class StagedGoals:
    """A goal list of joint goals computed as far as it is asked for.

    :meth:`all` is the whole list (at most ``keep`` distinct states, in order; or
    ``otherwise()`` when there is none). :meth:`first` is its first goal alone, computed
    without the rest, unless the start state may be one of the later goals (a planner
    answers "already there" before it tries the first goal's line): then it is the whole
    list too. A planner that reaches the first goal by its straight line
    (:attr:`~taskrunner.planning.request.PlannerOptions.direct_only`) answers as it
    would with the whole list; where it does not, ask again with :meth:`all` (the rest is
    computed from where :meth:`first` stopped).
    """

    def __init__(self, model: RobotModel, group: str, states: Iterator[np.ndarray], keep: int,
                 otherwise: Callable[[], tuple[Goal, ...]], whole: bool = False,
                 key: tuple[Hashable, ...] = ()) -> None:
        self.key = key
        """What the list is computed from but the start state (contact poses, the lift's
        offsets there, seed, options; numbers rounded as :func:`~taskrunner.tree.choice.
        rounded` rounds them): with the start state and the scene, the key of the goal
        state the check chose among them (:mod:`taskrunner.tree.choice`)."""
        self._idx = model.group(group).joint_indices
        self._names = model.group(group).joint_names
        self._states, self._keep, self._otherwise = states, keep, otherwise
        self._chosen: list[np.ndarray] = []
        self._goals: list[JointGoal] = []
        self._whole = whole
        self._all: tuple[Goal, ...] | None = None

    @property
    def complete(self) -> bool:
        """:meth:`first` is (or was) the whole list."""
        return self._whole or self._all is not None

    def first(self) -> tuple[Goal, ...]:
        """The first goal alone, or the whole list (see the class docstring)."""
        if self._whole or (not self._goals and not self._take()):
            return self.all()
        return (self._goals[0],)

    def all(self) -> tuple[Goal, ...]:
        """The whole list."""
        if self._all is None:
            while self._take():
                pass
            self._all = tuple(self._goals) if self._goals else self._otherwise()
        return self._all

    def _take(self) -> bool:
        """Add the next distinct state as a goal; False when the list is full or the
        states have run out."""
        if len(self._goals) >= self._keep:
            return False
        idx = self._idx
        for q in self._states:
            if any(np.max(np.abs(q[idx] - c[idx])) < 1e-3 for c in self._chosen):
                continue
            self._chosen.append(q)
            self._goals.append(JointGoal(dict(zip(self._names, q[idx]))))
            return True
        return False


def _followers(model: RobotModel, group: str, link: str, solver: IkSolver,
               states: list[np.ndarray], away: pin.SE3, there: pin.SE3) -> Iterator[np.ndarray]:
    """The states (at ``away``) from which the line to ``there`` can be followed, in order."""
    for q in states:
        if _line(model, group, link, solver, q, away, there) is not None:
            yield q


def _line(model: RobotModel, group: str, link: str, solver: IkSolver, q: np.ndarray,
          start: pin.SE3, end: pin.SE3, rotation: np.ndarray | None = None) -> np.ndarray | None:
    """:func:`_follows`, remembered (see :func:`_remembered`)."""
    def follow() -> np.ndarray | None:
        reached = _follows(solver, q, start, end, rotation)
        return None if reached is None else _frozen(reached)
    key = ("line", group, link, q.tobytes(), _bytes(start), _bytes(end),
           None if rotation is None else rotation.tobytes(), LINE_STEP, LINE_TURN, MAX_JOINT_STEP)
    return cast(np.ndarray | None, _remembered(model, key, follow))


def _in_turn(iterators: list[Iterator[np.ndarray]]) -> Iterator[np.ndarray]:
    """The first item of each iterator in order, then the second of each, and so on
    (an iterator that runs out is left out of later turns)."""
    active = list(iterators)
    while active:
        still = []
        for items in active:
            item = next(items, None)
            if item is not None:
                yield item
                still.append(items)
        active = still


def _follows(solver: IkSolver, q: np.ndarray, start: pin.SE3, end: pin.SE3,
             rotation: np.ndarray | None = None) -> np.ndarray | None:
    """The state at ``end`` reached from ``q`` (at ``start``) along the straight line
    between them, solved point by point without jumps (orientation: slerp, or
    ``rotation`` held); None where the line cannot be followed."""
    origin, first = start.translation, start.rotation
    delta = end.translation - origin
    turn = pin.log3(first.T @ end.rotation)
    steps = max(1, math.ceil(max(np.linalg.norm(delta) / LINE_STEP,
                                 np.linalg.norm(turn) / LINE_TURN)))
    idx = np.asarray(solver.group.joint_indices)
    for k in range(1, steps + 1):
        s = k / steps
        held = rotation if rotation is not None else first @ pin.exp3(s * turn)
        try:
            nxt = solver.solve_near(pin.SE3(held, origin + s * delta), seed_q=q, options=_EXACT)
        except IkFailedError:
            return None
        if _largest(_absolute(nxt[idx] - q[idx])) > MAX_JOINT_STEP:  # np.abs(...).max()
            return None
        q = nxt
    return q


def _joint_goals(model: RobotModel, group: str, states: Iterable[np.ndarray], keep: int
                 ) -> tuple[JointGoal, ...]:
    """Up to ``keep`` distinct states as joint goals of ``group``, in order."""
    idx = model.group(group).joint_indices
    names = model.group(group).joint_names
    goals: list[JointGoal] = []
    chosen: list[np.ndarray] = []
    for q in states:
        if any(np.max(np.abs(q[idx] - c[idx])) < 1e-3 for c in chosen):
            continue
        chosen.append(q)
        goals.append(JointGoal(dict(zip(names, q[idx]))))
        if len(goals) >= keep:
            break
    return tuple(goals)


def approximate_goals(model: RobotModel, group: str, link: str, wanted: Sequence[pin.SE3],
                      start: np.ndarray, seed: int, point: np.ndarray | None = None,
                      lift: Lift | None = None, grasping: bool = False,
                      keep: int = KEEP) -> tuple[JointGoal, ...]:
    """Joint goals of ``group`` that put ``point`` (fixed in ``link``'s frame, m; default
    its origin) where each wanted pose of ``link`` puts it, exactly, with ``link``'s
    orientation as near that pose's as the arm allows (see the module docstring).

    Args:
        lift: for goals a straight move away from the wanted poses (a pre-grasp): maps
            ``(index of the wanted pose, link pose reached there)`` to the world offset
            (m) of the goal from that pose. The goals are then the states reached there
            with the *same* orientation, so that the straight move between the two can
            hold it; where no such state exists, the wanted poses are moved by the offset
            and approximated as they are.
        grasping: the wanted poses are grasps: a turn about their closing axis (y) keeps
            the fingers flat on the same faces, so it counts for a tenth only (an arm
            whose pitch cannot match closes across its own plane, not along it).

    Raises:
        IkFailedError: no wanted position is within reach.
    """
    if lift is None:
        states = [a.q for a in approximate(model, group, link, wanted, start, seed, point,
                                           grasping)]
        return _joint_goals(model, group, states, keep)
    goals = _lifted(model, group, link, wanted, np.array(start, dtype=float), seed, point, lift,
                    grasping, keep).all()
    return cast(tuple[JointGoal, ...], goals)  # joint goals, or _joint_goals' when none


def _lifted(model: RobotModel, group: str, link: str, wanted: Sequence[pin.SE3],
            start: np.ndarray, seed: int, point: np.ndarray | None, lift: Lift,
            grasping: bool, keep: int) -> StagedGoals:
    """States a lift away from the approximations of ``wanted``, orientation unchanged,
    joined to them by a straight line the arm can follow holding that orientation (at
    most :data:`KEEP` of them, their lines followed as they are taken)."""
    solver = _solver(model, group, link)
    candidates = _approximations(model, group, link, wanted, start, seed, point, grasping)

    def away(item: Approximation, reached: pin.SE3, part: float = 1.0) -> pin.SE3:
        return pin.SE3(reached.rotation, reached.translation
                       + part * np.asarray(lift(item.wanted, reached), dtype=float))

    def states() -> Iterator[np.ndarray]:
        # Wanted poses that differ by a turn the arm cannot make can give the same
        # candidate state: its line (a function of the state and the lift) is followed once.
        followed: dict[tuple[bytes, bytes], np.ndarray | None] = {}
        count = 0
        for item, reached in candidates:
            if count >= KEEP:
                return
            for part in LIFT_PARTS:
                there = away(item, reached, part)
                key = (item.q.tobytes(), there.translation.tobytes())
                if key in followed:
                    q = followed[key]
                else:
                    q = followed[key] = _line(model, group, link, solver, item.q, reached,
                                              there, rotation=reached.rotation)
                if q is not None:
                    count += 1
                    yield q
                    break

    def otherwise() -> tuple[Goal, ...]:
        # No line can be followed: the moved poses approximated on their own.
        moved = [pin.SE3(p.rotation, p.translation + np.asarray(lift(i, p), dtype=float))
                 for i, p in enumerate(wanted)]
        return _joint_goals(model, group, [a.q for a in approximate(
            model, group, link, moved, start, seed, point, grasping)], keep)

    # A goal state holds its candidate's orientation at its lifted position (within the
    # IK tolerance): the start state can be one only where its frame is there.
    now = Frames(model, link)(start)
    near = any(np.linalg.norm(reached.rotation - now.rotation) <= _AT_TARGET
               and np.linalg.norm(away(item, reached).translation - now.translation) <= _AT_TARGET
               for item, reached in candidates)
    return StagedGoals(model, group, states(), keep, otherwise, whole=near,
                       key=_staged_key(group, link, wanted, lift, seed, point, grasping, keep))


def approximate(model: RobotModel, group: str, link: str, wanted: Sequence[pin.SE3],
                start: np.ndarray, seed: int, point: np.ndarray | None = None,
                grasping: bool = False) -> list[Approximation]:
    """Every candidate of :func:`approximate_goals`, nearest the wanted orientation first
    (``angle``: see :func:`orientation_error`). Their states are read-only: the same
    inputs give the same (remembered) arrays.

    Raises:
        IkFailedError: no wanted position is within reach.
    """
    return [item for item, _ in _approximations(model, group, link, wanted, start, seed, point,
                                                 grasping)]


def _approximations(model: RobotModel, group: str, link: str, wanted: Sequence[pin.SE3],
                    start: np.ndarray, seed: int, point: np.ndarray | None = None,
                    grasping: bool = False) -> list[tuple[Approximation, pin.SE3]]:
    """:func:`approximate`'s candidates, each with its frame's pose (the forward
    kinematics its angle was measured on, for the caller to reuse); remembered (see
    :func:`_remembered`: their states read-only, the poses not to be changed)."""
    start = np.asarray(start, dtype=float)
    key = ("approximations", group, link, b"".join(_bytes(p) for p in wanted), start.tobytes(),
           seed, None if point is None else np.asarray(point, dtype=float).tobytes(), grasping,
           SAMPLES, aiming.FIXED_POINT_ROUNDS, aiming.FREE_TURN_WEIGHT)

    def compute() -> tuple[tuple[Approximation, pin.SE3], ...]:
        found = _compute_approximations(model, group, link, wanted, start, seed, point,
                                        grasping)
        for item, _ in found:
            _frozen(item.q)
        return tuple(found)
    return list(cast(tuple[tuple[Approximation, pin.SE3], ...], _remembered(model, key, compute)))


def _compute_approximations(model: RobotModel, group: str, link: str,
                            wanted: Sequence[pin.SE3], start: np.ndarray, seed: int,
                            point: np.ndarray | None = None, grasping: bool = False
                            ) -> list[tuple[Approximation, pin.SE3]]:
    offset = np.zeros(3) if point is None else np.asarray(point, dtype=float)
    solver = _solver(model, group, link)
    fk = Frames(model, link)
    roll = wrist_roll(model, group, link, np.asarray(start, dtype=float))

    def candidate(q: np.ndarray, i: int, frame: pin.SE3 | None = None
                  ) -> tuple[Approximation, pin.SE3]:
        reached = fk(q) if frame is None else frame
        return Approximation(q, i, orientation_error(reached, wanted[i], grasping)), reached

    sample = IkOptions(position_only=True, num_solutions=SAMPLES, seed=seed,
                       attempts=20 * SAMPLES)
    local, exact = _LOCAL, _EXACT
    out: list[tuple[Approximation, pin.SE3]] = []
    failure: IkFailedError | None = None
    misses: list[float] = []  # the point's distance from its target where a re-aim failed
    targets: dict[tuple[float, ...], list[int]] = {}
    for i, pose in enumerate(wanted):
        spot = pose.translation + pose.rotation @ offset
        targets.setdefault(tuple(np.round(spot, 6)), []).append(i)
    for spot, members in targets.items():
        goal = np.array(spot)
        try:
            solutions = solver.solve_all(goal - offset_at(fk, start, offset), seed_q=start,
                                         options=sample)
        except IkFailedError as exc:
            failure = exc
            continue
        # Each solution's orientation, for the first wrist roll towards every wanted pose.
        turned = [fk(s.q).rotation for s in solutions] if roll is not None else None
        for i in members:
            found = []
            for k, s in enumerate(solutions):
                there = aimed(fk, roll, grasping, s.q, wanted[i], goal, offset, solver, local,
                              None if turned is None else turned[k], misses)
                if there is not None:
                    found.append(candidate(there[0], i, there[1]))
            out += found
            if not found:
                continue
            # Where the wanted pose is reachable exactly, a local full-pose solve from the
            # nearest approximation finds it.
            best = min(found, key=lambda a: a[0].angle)[0].q
            try:
                q = solver.solve_near(wanted[i], seed_q=best, options=exact)
            except IkFailedError:
                # Not reachable exactly (a pose a degree off the arm's reach, as an object
                # held a little askew asks for): the nearest orientation the arm allows
                # with the point held, rather than whichever random sample was nearest.
                nearer = nearest_orientation(fk, solver, best, wanted[i], goal, offset,
                                              grasping, local)
                if nearer is not None:
                    out.append(candidate(nearer[0], i, nearer[1]))
                continue
            out.append(candidate(q, i))
    if not out:
        if failure is not None:
            raise failure
        # Position-only solutions were found, but none could be re-aimed so that the
        # point (away from the frame's origin) is on its target: the nearest miss is the
        # residual (an IkFailedError always has one: a missing one read as nan).
        residual = min(misses) if misses else math.inf
        xyz = ", ".join(f"{v:.4f}" for v in next(iter(targets)))
        raise IkFailedError(f"no state of group {group!r} puts the point "
                            f"{np.round(offset, 4).tolist()} (m) of frame {link!r}, target "
                            f"position ({xyz}) (m, world): best residual {residual:.4g} m "
                            "after re-aiming every position-only solution",
                            best_error=residual)
    out.sort(key=lambda a: a[0].angle)
    return out
