"""Checkpoints: after each leaf that finishes, what a run needs to go on from there.

Every leaf of the tree that ends with SUCCESS or FAILURE is followed, in the run's
event log and so in its journal, by a ``checkpoint`` event (:class:`Checkpointer`) holding:

* ``leaf``: the leaf's index in the compiled tree (pre-order, the root 0), its name and
  file:line in the event's ``node`` and ``location``, its outcome in ``status``;
* ``position``: the composites around it as they stand (``retry`` attempts failed so far,
  ``repeat`` successes so far, a ``fallback``'s branch, a sequence's child), for a reader;
  a resumed run does not set them, it reaches them by replaying the leaves' outcomes in
  order (:mod:`taskrunner.runtime.resume`);
* ``scene``: the planning scene in full: every joint, every object (shape, pose, the link
  carrying it and the links it may touch), the scene's allowances with their reasons;
  ``held``: which arm holds which object.

A ``timeout:`` that fires gets a checkpoint of its own (``leaf``: the decorator's index,
``status`` FAILURE, ``cut``: the leaves it stopped while they ran). A resumed run's record
begins with the checkpoints it replayed (``replayed``: the run that finished them;
``skipped``: leaves ``--from`` skipped), so it can be resumed alone.

The run's head in the record says which task it was (``task_sha256``: the task file's
text as run; ``tree_sha256``: the compiled tree's shape, which an include, the cell or a
parameter also changes). The journal writes each checkpoint to the file before the next
leaf starts (a killed process loses none) and fsyncs it with the next motion's ``planned``
event (see :mod:`taskrunner.runtime.records`).

The checkpoint is emitted by a subscriber of the ``node_finished`` event: its ``seq``
follows that event's, but subscribers after the checkpointer are handed the checkpoint
before the ``node_finished`` (order by ``seq`` where it matters).
"""

from __future__ import annotations

import hashlib
from collections.abc import Iterator
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any

import py_trees
from py_trees.behaviour import Behaviour
from py_trees.common import Status

from taskrunner.errors import TaskrunnerError
from taskrunner.runtime.replay import object_data, object_of
from taskrunner.scene.objects import SceneSnapshot
from taskrunner.tree.behaviours import TaskLeaf
from taskrunner.tree.timeout import TaskTimeout
from taskrunner.types import JointState

if TYPE_CHECKING:
    from taskrunner.runtime.events import EventLog, RunEvent
    from taskrunner.runtime.records import RunRecord
    from taskrunner.scene import Scene
    from taskrunner.tree.context import TaskContext

__all__ = ["Checkpoint", "Checkpointer", "checkpoints_of", "held_objects", "preorder",
           "restore_scene", "scene_state", "text_sha256", "tree_sha256"]


def preorder(root: Behaviour) -> Iterator[Behaviour]:
    """The nodes of a tree, parents before their children, children in order."""
    yield root
    for child in root.children:
        yield from preorder(child)


def tree_sha256(root: Behaviour) -> str:
    """A hash of the tree's shape: each node's depth, class and name, in pre-order."""
    lines = []

    def walk(node: Behaviour, depth: int) -> None:
        lines.append(f"{depth} {type(node).__name__} {node.name}")
        for child in node.children:
            walk(child, depth + 1)

    walk(root, 0)
    return hashlib.sha256("\n".join(lines).encode()).hexdigest()


def text_sha256(text: str) -> str:
    """The hash a record keeps of its task file's text."""
    return hashlib.sha256(text.encode()).hexdigest()


# ----------------------------------------------------------------------------- scene
def scene_state(scene: Scene) -> dict[str, Any]:
    """The scene in full, JSON-ready (exact numbers: a resumed run plans from them)."""
    snapshot = scene.snapshot()
    reasons = scene.allowed_collisions()
    return {
        "joints": {n: float(v) for n, v in zip(snapshot.state.names, snapshot.state.positions)},
        "objects": [object_data(o, exact=True) for o in snapshot.objects],
        "allowed": [[a, b, reasons.get(frozenset((a, b)), "scene")]
                    for a, b in snapshot.allowed],
    }


def restore_scene(scene: Scene, data: dict[str, Any]) -> None:
    """Make ``scene`` what :func:`scene_state` wrote (objects, attachments, allowances
    with their reasons, joints)."""
    objects = tuple(object_of(o) for o in data.get("objects", ()))
    joints = data.get("joints", {})
    names = scene.robot.joint_names
    q = scene.robot.state_with(scene.state, {n: v for n, v in joints.items() if n in names})
    scene.restore(SceneSnapshot(scene.robot.name, JointState(names, q), objects))
    for a, b, reason in data.get("allowed", ()):
        scene.allow_collision(a, b, reason=reason)


def held_objects(ctx: TaskContext, scene: Scene | None = None) -> dict[str, str]:
    """Which arm holds each attached object (object name: arm group); an object attached
    to a link no arm grasps with is listed with that link's name."""
    scene = scene or ctx.scene
    holders: dict[str, str] = {}
    for group in ctx.cell.model.groups.values():
        if group.end_effector and group.tip_link:
            try:
                holders.setdefault(ctx.arm(group.name).holder, group.name)
            except TaskrunnerError:  # an arm without a usable tool holds nothing
                continue
    return {o.name: holders.get(o.attached_to or "", o.attached_to or "")
            for o in scene.objects if o.attached}


# ----------------------------------------------------------------------------- position
def position(leaf: Behaviour) -> list[dict[str, Any]]:
    """The composites above ``leaf``, from the root: each one's name and where it is
    (``child``: index of the child on the way to the leaf; ``retry``: attempts failed so
    far; ``repeat``: successes so far)."""
    out: list[dict[str, Any]] = []
    child, parent = leaf, leaf.parent
    while parent is not None:
        entry: dict[str, Any] = {"name": parent.name,
                                 "child": next(i for i, c in enumerate(parent.children)
                                               if c is child)}
        if isinstance(parent, py_trees.decorators.Retry):
            entry["retry"] = parent.failures
        elif isinstance(parent, py_trees.decorators.Repeat):
            entry["repeat"] = parent.success
        elif isinstance(parent, py_trees.composites.Selector):
            entry["fallback"] = entry["child"]
        out.append(entry)
        child, parent = parent, parent.parent
    return out[::-1]


class Checkpointer:
    """Emits a ``checkpoint`` event after every leaf's SUCCESS or FAILURE (module text).

    Subscribed to the run's event log: the ``node_finished`` event of a leaf is emitted
    in its ``terminate``, before the next leaf starts, so the scene then is the scene the
    next leaf starts from. The leaf is found by its name and file:line (two leaves alike:
    the one that was RUNNING; else the checkpoint names none and the run cannot be
    resumed past it).
    """

    def __init__(self, root: Behaviour, ctx: TaskContext, events: EventLog) -> None:
        self.ctx = ctx
        self.events = events
        self.index = {node.id: i for i, node in enumerate(preorder(root))}
        self.leaves = [n for n in preorder(root) if isinstance(n, TaskLeaf)]
        self.timeouts = [n for n in preorder(root) if isinstance(n, TaskTimeout)]
        self.cut: list[Behaviour] = []  # leaves stopped while running since the last one
        self.count = 0
        events.subscribe(self._on_event)

    def _on_event(self, event: RunEvent) -> None:
        if event.kind != "node_finished":
            return
        if event.status == Status.INVALID.value:  # stopped while running: a timeout's?
            self.cut += [leaf for leaf in self.leaves if leaf.name == event.node
                         and leaf.location == event.location and leaf.status == Status.RUNNING]
            return
        if event.status not in (Status.SUCCESS.value, Status.FAILURE.value):
            return
        found = [leaf for leaf in self.leaves if leaf.name == event.node
                 and leaf.location == event.location]
        if not found:
            self._timeout(event)  # or not a leaf at all (a decorator's own event)
            return
        if len(found) > 1:  # the one that ran over several ticks, if it is one of them
            found = [leaf for leaf in found if leaf.status == Status.RUNNING] or found
        self.count += 1
        leaf = found[0]
        self.cut = []
        held = held_objects(self.ctx)
        holding = ", ".join(f"{arm} holds {name!r}" for name, arm in held.items())
        self.events.emit(
            "checkpoint", f"after {event.node}: {holding or 'nothing held'}",
            node=event.node, location=event.location, status=event.status,
            leaf=self.index[leaf.id] if len(found) == 1 else None, done=self.count,
            position=position(leaf), scene=scene_state(self.ctx.scene), held=held)

    def _timeout(self, event: RunEvent) -> None:
        """A ``timeout:`` that fired: a checkpoint of the decorator (its FAILURE) with
        ``cut``, the leaves under it it stopped; a resumed run replays both (a fallback
        goes on with its next branch, a retry with its next attempt)."""
        found = [n for n in self.timeouts if n.name == event.node
                 and n.location == event.location and event.status == Status.FAILURE.value]
        if len(found) != 1:
            return
        node = found[0]
        under = {n.id for n in preorder(node)}
        cut = [self.index[leaf.id] for leaf in self.cut if leaf.id in under]
        self.cut = []
        self.count += 1
        held = held_objects(self.ctx)
        self.events.emit(
            "checkpoint", f"after {event.node}: timed out", node=event.node,
            location=event.location, status=event.status, leaf=self.index[node.id],
            done=self.count, position=position(node), scene=scene_state(self.ctx.scene),
            held=held, cut=cut)


@dataclass(frozen=True)
class Checkpoint:
    """One ``checkpoint`` event read back: ``leaf`` (pre-order index; None: the leaf
    could not be told from another of the same name and file:line), its ``status``, the
    ``scene`` after it, ``held`` objects (object: arm), ``seq`` of the event;
    ``run_id``: the run that finished the leaf, when not the record's own (a resumed
    run's record repeats the checkpoints it replayed); ``skipped``: a leaf that never ran,
    skipped by ``--from`` a step after it (its scene is the world when it was skipped);
    ``cut``: for a ``timeout:`` that fired (``leaf`` is then the decorator's index), the
    leaves it stopped while they ran."""

    seq: int
    leaf: int | None
    node: str
    location: str | None
    status: str
    scene: dict[str, Any]
    held: dict[str, str]
    position: list[dict[str, Any]]
    run_id: str | None = None
    skipped: bool = False
    cut: tuple[int, ...] = ()


def checkpoints_of(record: RunRecord) -> list[Checkpoint]:
    """The checkpoints of a record, in order."""
    return [Checkpoint(e.seq, e.data.get("leaf"), e.node or "", e.location, e.status or "",
                       e.data.get("scene") or {}, dict(e.data.get("held") or {}),
                       list(e.data.get("position") or []), e.data.get("replayed"),
                       bool(e.data.get("skipped")), tuple(e.data.get("cut") or ()))
            for e in record.events if e.kind == "checkpoint"]
