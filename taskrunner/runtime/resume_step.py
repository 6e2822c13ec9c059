"""``--from STEP`` of a resumed run: which step of the task it names, the leaves skipped to
get there, and the check of the rest of the task from the world as it is.

A resumed run may start at a step of the task's top level other than where it stopped:
one it reached (it goes back there: the leaves finished before it are replayed, the rest
run again) or one after (the leaves between are skipped: each replayed as a success it
never had). Either way the rest of the task, from that step on, is first dry-run by the
check a run gets (:func:`taskrunner.tree.check.check_from`) from where the robot and the
objects are now; a problem refuses the resume, with the step and the reason.
"""

from __future__ import annotations

from pathlib import Path
from typing import TYPE_CHECKING

from py_trees.common import Status
from py_trees.composites import Sequence

from taskrunner.runtime.checkpoint import Checkpoint, position, preorder, scene_state
from taskrunner.tree.behaviours import TaskLeaf

if TYPE_CHECKING:
    from taskrunner.runtime.runner import Runner
    from taskrunner.tasks import Problem, TaskSpec

__all__ = ["check_rest", "skipped_leaves", "top_index", "top_step"]


def _names_location(step: str, file: str | Path | None, line: int | None) -> bool:
    if file is None or line is None:
        return False
    return step in (f"{file}:{line}", f"{Path(file).name}:{line}")


def top_step(spec: TaskSpec, step: str) -> int | None:
    """The index in ``spec.steps`` of the step named ``step`` (its label, as in
    ``pick cube``, or its ``file:line``), None if no top-level step is."""
    for index, node in enumerate(spec.steps):
        loc = node.loc
        if step == node.label or _names_location(step, loc.file if loc else None,
                                                 loc.line if loc else None):
            return index
    return None


def top_index(point: Checkpoint) -> int | None:
    """The top-level step a checkpoint's leaf belongs to (the root's child on its way)."""
    return point.position[0].get("child") if point.position else None


def skipped_leaves(runner: Runner, replay: list[Checkpoint], upto: int
                   ) -> tuple[list[Checkpoint], str | None]:
    """The leaves not finished before top-level step ``upto``, each as a checkpoint
    with a SUCCESS it never had (the world as it is now): replayed, they bring the tree
    to that step. Only plain sequences of leaves can be skipped: else the reason.
    """
    root = runner.tree
    if len(root.children) != len(runner.spec.steps):
        return [], "the task's steps are not the children of its tree's root"
    finished = {p.leaf for p in replay}
    first = top_index(replay[-1]) if replay else 0
    index = {node.id: i for i, node in enumerate(preorder(root))}
    scene = scene_state(runner.scene)
    skipped: list[Checkpoint] = []
    for child in root.children[first or 0:upto]:  # the stopped step's rest, then whole steps
        for node in preorder(child):
            if node.children and not isinstance(node, Sequence):
                return [], (f"{type(node).__name__.lower()} {node.name!r} lies on the way "
                            "(only plain steps can be skipped)")
            if node.children:
                continue
            if not isinstance(node, TaskLeaf):
                return [], f"{node.name!r} is not a step's leaf"
            if index[node.id] in finished:
                continue
            skipped.append(_skipped(node, index[node.id], scene, replay))
    return skipped, None


def _skipped(leaf: TaskLeaf, at: int, scene: dict, replay: list[Checkpoint]) -> Checkpoint:
    held = replay[-1].held if replay else {}
    return Checkpoint(0, at, leaf.name, leaf.location, Status.SUCCESS.value, scene,
                      dict(held), position(leaf), skipped=True)


def check_rest(runner: Runner, start: int) -> list[Problem]:
    """The check's problems of the task's steps from top-level step ``start`` on, dry-run
    from the runner's scene as it is now."""
    from taskrunner.tree.check import check_from

    spec = runner.spec
    rest = spec.model_copy(update={"steps": tuple(spec.steps[start:])})
    return check_from(rest, runner.cell, runner.scene, seed=runner.ctx.seed)
