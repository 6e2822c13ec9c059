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
"""

from __future__ import annotations

import hashlib
import threading
import weakref
from collections import OrderedDict
from collections.abc import Hashable, Sequence

import numpy as np

from taskrunner.planning.request import Goal, JointGoal, NamedGoal, PoseGoal
from taskrunner.robot.model import RobotModel
from taskrunner.scene import Scene
from taskrunner.types import Pose

__all__ = ["DIGITS", "SIZE", "choice_key", "chosen", "forget", "goals_key", "model_key", "remember",
           "rounded"]

DIGITS = 6
"""Decimals (of m and rad) the numbers of a key are rounded to."""
SIZE = 1024
"""Choices kept (the least recently used dropped first)."""

_CHOICES: OrderedDict[tuple[Hashable, ...], np.ndarray] = OrderedDict()
_LOCK = threading.Lock()
_MODEL_KEYS: dict[int, tuple[weakref.ref, str]] = {}


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
               goals: tuple[Hashable, ...], seed: int) -> tuple[Hashable, ...]:
    """The key of a motion's choice (see the module docstring).

    Args:
        leaf: the leaf's name (not its file:line: a task file loaded by a relative path
            and by its absolute one is the same task).
        goals: the key of its goals (:func:`goals_key`, or a staged list's own key).
        seed: the planner seed of the request (pose goals' IK searches use it).
    """
    objects = tuple(
        (o.name, repr(o.shape), o.attached_to, tuple(o.touch_links), _pose_key(o.pose))
        for o in scene.objects)
    allowed = tuple(sorted(tuple(sorted(p)) for p in scene.snapshot().allowed))
    return (group, leaf, goals, seed, rounded(scene.state), objects, allowed)


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
    full = (model_key(model), *key)
    with _LOCK:
        hit = _CHOICES.get(full)
        if hit is None or len(hit) != model.nq:
            return None
        _CHOICES.move_to_end(full)
        return hit


def forget() -> None:
    """Drop every remembered choice."""
    with _LOCK:
        _CHOICES.clear()
