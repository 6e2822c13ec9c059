"""A run's goal choice where the check's is not remembered: checked by the check's rule.

``run-task check`` follows, at each :class:`~taskrunner.tree.behaviours.MoveToGoal`, the
goal state the planner goes to when left to itself (else the first collision-free one)
and, where the rest of the step fails from it, the others
(:meth:`~taskrunner.tree.leafcheck.LeafPlayer.play`), and remembers the state it followed
(:mod:`taskrunner.tree.choice`); the run that follows plans to that state. That memory
is keyed by the exact situation (state, objects, goals to 6 decimals), so a run finds it
only right after a check in the same process, on a situation the check
predicted to the micrometre. Elsewhere (a physics backend, where a settled cube or a
gripper closed on an object is a little off the check's; a run after a check in another
process; a Python API run without a check) the planner chose by its own rule (the first
goal whose straight line is free, else whichever OMPL reached) and moved there even when
the rest of the step fails from there and the check's rule finds a state from which it
succeeds: 19 of 36 receiver grasp offsets of ``handoff_so101`` disagreed so on mock
(check accepts, run fails, or the reverse), and 2 of 13 checked spots of
``pick_place_so101`` failed on mujoco.

Such a leaf now plays the rest of its step in check mode from the planner's goal state
before it moves (:func:`rest_fails`), and where that fails, takes the state the check's
rule follows on the run's own situation (:func:`choose_as_the_check`), when one lets the
step succeed. The plays are on copies (nothing moves, no event is sent).
"""

from __future__ import annotations

from collections.abc import Hashable
from dataclasses import dataclass, replace

import numpy as np
import py_trees

from taskrunner.runtime.events import EventLog
from taskrunner.tree.behaviours import MoveToGoal
from taskrunner.tree.choice import chosen
from taskrunner.tree.clock import TaskClock
from taskrunner.tree.context import TaskContext
from taskrunner.tree.leafcheck import LeafPlayer, leaves_of
from taskrunner.tree.schedule import MotionSchedule

__all__ = ["choose_as_the_check", "rest_fails", "step_leaves"]


@dataclass(frozen=True)
class _Label:
    """What the leaf player reads of a step: its label (a leaf's name is ``label: stage``)."""

    label: str


def step_leaves(leaf: MoveToGoal) -> tuple[list[py_trees.behaviour.Behaviour], str]:
    """The leaves of ``leaf``'s step in order and the step's label: an idiom's sequence
    (its leaves are named ``<step label>: <stage>``), else the leaf alone."""
    parent = leaf.parent
    if (isinstance(parent, py_trees.composites.Sequence)
            and leaf.name.startswith(f"{parent.name}: ")):
        return leaves_of(parent), parent.name
    return [leaf], leaf.name


def _probe(ctx: TaskContext, state: np.ndarray | None = None) -> TaskContext:
    """A check's copy of ``ctx``: its scene copied (at ``state`` if given), no planner,
    backend, events, clock or schedule of the run's; the seed count kept."""
    scene = ctx.scene.copy()
    if state is not None:
        scene.set_state(state)
    return replace(ctx, scene=scene, planner=None, backend=None, events=EventLog(),
                   executed=[], clock=TaskClock(), schedule=MotionSchedule(), _cartesian={})


def rest_fails(leaf: MoveToGoal, after: TaskContext, end: np.ndarray) -> bool:
    """Whether the rest of ``leaf``'s step, played in check mode (other goal states
    explored as the check explores them), fails from the full state ``end`` its plan
    reached. ``after``: the context as it was once the leaf had drawn its planner seed."""
    leaves, label = step_leaves(leaf)
    _, failure = LeafPlayer(after.cell).play(leaves, leaves.index(leaf) + 1,
                                             _Label(label),  # type: ignore[arg-type]
                                             _probe(after, end))
    return failure is not None


def choose_as_the_check(leaf: MoveToGoal, before: TaskContext,
                        key: tuple[Hashable, ...]) -> np.ndarray | None:
    """The goal state of ``leaf`` that ``run-task check`` follows from the run's present
    situation (its choice ``key``, remembered as the check remembers it), where the rest
    of the step succeeds from it; else None. ``before``: as for :func:`rest_fails`."""
    leaves, label = step_leaves(leaf)
    now = replace(before, scene=leaf.ctx.scene)
    _, failure = LeafPlayer(now.cell).play(leaves, leaves.index(leaf),
                                           _Label(label),  # type: ignore[arg-type]
                                           _probe(now))
    if failure is not None:
        return None
    return chosen(leaf.ctx.scene.robot, key)
