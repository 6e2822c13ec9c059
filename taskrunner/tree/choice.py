"""The goal state ``run-task check`` chose for a motion, remembered for the run that follows.

A :class:`~taskrunner.tree.behaviours.MoveToGoal` usually offers its planner several goal
states (a pre-grasp's or pre-place's states, a pose's IK solutions), and the rest of its
step (the straight approach, the grasp, the place's descent, the outcome) can succeed from
some and fail from others. The planner alone would take whichever it reaches first: the
first state whose straight line is free, else the one OMPL's trees happen to meet. The
check's dry run follows the first collision-free state, and where the rest of the step
fails from it, the others; it remembers the state it followed to the end
(:func:`remember`). The run asks its planner for that state alone (:func:`chosen`), so
it reaches the very state the check judged: what the check accepts, the run executes.

A choice is remembered by the motion's inputs (:func:`choice_key`): the robot model (by
its content, :func:`model_key`), the group, the leaf's name, its goals, the planner seed, and the situation
(the robot state, the objects and the allowed contacts), the numbers rounded to
:data:`DIGITS` decimals (m, rad) so that a run whose backend reports the state the check
set, give or take the last bits of a float, finds it. The last :data:`SIZE` choices of
the process are kept; without one (a run with ``--no-check``, another situation) the
planner chooses as usual.

*In a branch of a ``parallel``* the check plays the branches one after another (each
from where the one before left the scene) while the run ticks them at once, so what the
other branches' arms and objects are doing when a motion is planned differs between the
two, and so did the order the branches drew their seeds in. Inside a branch, a motion's
seeds are therefore drawn from a stream of its own (:func:`step_seed`: the task's seed,
the branch's path of indices in the run's tree, the leaf and how many seeds it drew
before), and its key holds only its arm's part of the situation (:func:`arm_part`: the
joints of its group and end effector and all the joints they carry, the objects attached
to their links, the contacts allowed to them): the same in the check and in the run,
whatever order the branches are ticked or planned in. :func:`lookups` counts what the
run found.
"""

from __future__ import annotations

import hashlib
import threading
import weakref
from collections import OrderedDict
from collections.abc import Hashable, Sequence
from dataclasses import dataclass, replace

import numpy as np

from taskrunner.planning.request import Goal, JointGoal, NamedGoal, PoseGoal
from taskrunner.robot.model import RobotModel
from taskrunner.scene import Scene
from taskrunner.types import Pose

__all__ = ["DIGITS", "SIZE", "ArmPart", "Lookups", "arm_part", "choice_key", "chosen", "forget",
           "goals_key", "lookups", "model_key", "remember", "rounded", "step_seed"]

DIGITS = 6
"""Decimals (of m and rad) the numbers of a key are rounded to."""
SIZE = 1024
"""Choices kept (the least recently used dropped first)."""

_CHOICES: OrderedDict[tuple[Hashable, ...], np.ndarray] = OrderedDict()
_LOCK = threading.Lock()
_MODEL_KEYS: dict[int, tuple[weakref.ref, str]] = {}


@dataclass(frozen=True)
class Lookups:
    """What :func:`chosen` was asked since the last :func:`forget`: ``found`` keys had a
    choice, ``missed`` had none (the planner, or the run's own look-ahead, chose)."""

    found: int = 0
    missed: int = 0


_LOOKUPS = Lookups()


def lookups() -> Lookups:
    """The counts of :func:`chosen`'s answers since the last :func:`forget`."""
    return _LOOKUPS


@dataclass(frozen=True)
class ArmPart:
    """The part of the situation a motion of one arm in a branch of a ``parallel`` is
    keyed by: the state vector's ``indices`` of the joints that move the arm's links
    (its group's, its end effector's and every joint they carry), and those ``links``."""

    indices: tuple[int, ...]
    links: frozenset[str]


def arm_part(model: RobotModel, group: str) -> ArmPart:
    """The :class:`ArmPart` of ``group`` (an arm, with the end effectors mounted on it)."""
    pin_model = model.model
    names = list(model.group(group).joint_names)
    for effector in model.end_effectors.values():
        if effector.parent_group == group:
            names += model.group(effector.group).joint_names
    roots = {pin_model.getJointId(n) for n in names if pin_model.existJointName(n)}
    carried: set[int] = set()
    for joint in range(1, pin_model.njoints):
        up = joint
        while up > 0 and up not in roots:
            up = pin_model.parents[up]
        if up > 0:
            carried.add(joint)
    indices = tuple(i for i, n in enumerate(model.joint_names)
                    if pin_model.existJointName(n) and pin_model.getJointId(n) in carried)
    links = frozenset(f.name for f in pin_model.frames if int(f.parentJoint) in carried)
    return ArmPart(indices, links)


def step_seed(seed: int, branch: tuple[int, ...], leaf: str, count: int) -> int:
    """The seed of the ``count``-th draw (from 1) of leaf ``leaf`` in the branch at path
    ``branch`` (the indices of the branches around it in the run's tree, from the root)
    of a run seeded ``seed``: a function of these alone, so that the check and the run
    draw the same seeds whatever order they play the branches in (a 32-bit integer, as
    OMPL and numpy take it)."""
    text = repr((seed, branch, leaf, count)).encode()
    return int.from_bytes(hashlib.sha256(text).digest()[:4], "little")


def model_key(model: RobotModel) -> str:
    """A digest of what a goal choice depends on in ``model``: its kinematics (joint
    placements and limits), collision geometry (links' shapes, meshes and placements)
    and the collisions its SRDF disables. Equal for two loads of the same files, so that
    a run on a cell loaded again (a task given by a relative path, the REST API's
    session cell) finds the check's choices."""
    with _LOCK:
        hit = _MODEL_KEYS.get(id(model))
        if hit is not None and hit[0]() is model:
            return hit[1]
    digest = hashlib.sha256()

    def add(*parts: object) -> None:
        digest.update(repr(parts).encode())

    pin_model = model.model
    add(model.name, tuple(model.joint_names), rounded(model.lower), rounded(model.upper))
    for name, placement in zip(pin_model.names, pin_model.jointPlacements):
        add(name, rounded(placement.homogeneous))
    for go in model.collision_model.geometryObjects:
        # coal computes a shape's local box lazily (the path verifier asks for it): computed
        # here, so that the digest does not depend on whether anything asked before.
        compute = getattr(go.geometry, "computeLocalAABB", None)
        if compute is not None:
            compute()
        box = getattr(go.geometry, "aabb_local", None)
        extent = () if box is None else (rounded(box.min_), rounded(box.max_))
        add(go.name, int(go.parentJoint), rounded(go.placement.homogeneous), str(go.meshPath),
            rounded(go.meshScale), type(go.geometry).__name__, extent)
    add(sorted(tuple(sorted(pair)) for pair in model.disabled_collisions))
    key = digest.hexdigest()
    with _LOCK:
        for gone in [k for k, (ref, _) in _MODEL_KEYS.items() if ref() is None]:
            del _MODEL_KEYS[gone]
        _MODEL_KEYS[id(model)] = (weakref.ref(model), key)
    return key


def rounded(values: object) -> tuple[float, ...]:
    """``values`` (any array-like of numbers) as a tuple rounded to :data:`DIGITS`, with
    -0.0 as 0.0."""
    flat = np.asarray(values, dtype=float).ravel()
    moderate = np.abs(flat) < 1e9  # joint limits of continuous joints are huge
    return tuple(float(round(v, DIGITS)) + 0.0 if m else float(v)
                 for v, m in zip(flat.tolist(), moderate.tolist()))


def _pose_key(pose: Pose) -> tuple[Hashable, ...]:
    return (pose.frame, rounded(pose.se3.homogeneous))


def goals_key(goals: Goal | Sequence[Goal]) -> tuple[Hashable, ...]:
    """The key of a goal or a tuple of goals (joint values and poses rounded)."""
    out: list[Hashable] = []
    for goal in (goals if isinstance(goals, (tuple, list)) else (goals,)):
        if isinstance(goal, JointGoal):
            out.append(("joints", tuple(sorted((k, rounded([v])[0])
                                               for k, v in goal.values.items()))))
        elif isinstance(goal, NamedGoal):
            out.append(("named", goal.name))
        elif isinstance(goal, PoseGoal):
            out.append(("pose", goal.link, goal.position_only, goal.tolerance,
                        _pose_key(goal.pose)))
        else:
            out.append(("other", repr(goal)))
    return tuple(out)


def choice_key(scene: Scene, group: str, leaf: str,
               goals: tuple[Hashable, ...], seed: int,
               part: ArmPart | None = None) -> tuple[Hashable, ...]:
    """The key of a motion's choice (see the module docstring).

    Args:
        leaf: the leaf's name (not its file:line: a task file loaded by a relative path
            and by its absolute one is the same task).
        goals: the key of its goals (:func:`goals_key`, or a staged list's own key).
        seed: the planner seed of the request (pose goals' IK searches use it).
        part: in a branch of a ``parallel``, the arm's part of the situation
            (:func:`arm_part`): only its joints, the objects attached to its links and
            the contacts allowed to those count; None: the whole situation.
    """
    state = np.asarray(scene.state, dtype=float)
    allowed_pairs = list(scene.snapshot().allowed)
    objects_in = list(scene.objects)
    if part is not None:
        state = state[list(part.indices)]
        objects_in = [o for o in objects_in if o.attached_to in part.links]
        mine = part.links | {o.name for o in objects_in}
        allowed_pairs = [p for p in allowed_pairs if any(name in mine for name in p)]
    objects = tuple(
        (o.name, repr(o.shape), o.attached_to, tuple(o.touch_links), _pose_key(o.pose))
        for o in objects_in)
    allowed = tuple(sorted(tuple(sorted(p)) for p in allowed_pairs))
    return (group, leaf, goals, seed, rounded(state), objects, allowed)


def remember(model: RobotModel, key: tuple[Hashable, ...], q: np.ndarray) -> None:
    """Remember ``q`` (a full state vector) as the choice of ``key`` for ``model``."""
    value = np.array(q, dtype=float)
    value.setflags(write=False)
    full = (model_key(model), *key)
    with _LOCK:
        _CHOICES[full] = value
        _CHOICES.move_to_end(full)
        while len(_CHOICES) > SIZE:
            _CHOICES.popitem(last=False)


def chosen(model: RobotModel, key: tuple[Hashable, ...]) -> np.ndarray | None:
    """The state remembered for ``key`` and ``model`` (read-only), or None."""
    global _LOOKUPS
    full = (model_key(model), *key)
    with _LOCK:
        hit = _CHOICES.get(full)
        if hit is None or len(hit) != model.nq:
            _LOOKUPS = replace(_LOOKUPS, missed=_LOOKUPS.missed + 1)
            return None
        _LOOKUPS = replace(_LOOKUPS, found=_LOOKUPS.found + 1)
        _CHOICES.move_to_end(full)
        return hit


def forget() -> None:
    """Drop every remembered choice (and the counts of :func:`lookups`)."""
    global _LOOKUPS
    with _LOCK:
        _CHOICES.clear()
        _LOOKUPS = Lookups()
