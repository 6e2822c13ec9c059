"""Which lane each body is of, and the pairs of bodies of two lanes, for the space-time
verifier (:mod:`taskrunner.collision.spacetime`): a body is of the lane that moves the
joint nearest above it, else of the lane that carries it (an arm's links, where only its
gripper moves); an object lying in the world is of the lane that set it down (or takes
it). Kept per robot model and per checker, so that the verifications of one schedule
build each once.
"""

from __future__ import annotations

import weakref
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

if TYPE_CHECKING:
    import pinocchio as pin

    from taskrunner.robot import RobotModel
    from taskrunner.scene.collision import CollisionChecker

__all__ = ["Owners", "body_name", "joint_lanes", "lane_owners"]


@dataclass(frozen=True)
class Owners:
    """Which lane each body is of (:attr:`owner`, per geometry object; -1: none), and
    the checker's pairs of bodies of two different lanes: their indices (ascending) and
    each one's two geometries, the first of the lower lane. Read, never written."""

    owner: np.ndarray
    pair_ids: np.ndarray
    firsts: np.ndarray
    seconds: np.ndarray
    uncounted: np.ndarray | None = None  # per checker pair: its distance not kept


# Per robot geometry (one per robot model, shared by the checkers of every scene
# revision; kept while it lives): the lanes of each joint (:func:`joint_lanes`), by the
# lanes' state columns (the arrays themselves: the same joints, the same kept array), the
# latest few.
_JOINT_LANES: weakref.WeakKeyDictionary[object, dict[tuple[int, ...], tuple[
    tuple[np.ndarray, ...], tuple[np.ndarray, np.ndarray]]]] = weakref.WeakKeyDictionary()
_JOINT_LANES_KEPT = 8


def joint_lanes(model: RobotModel, checker: CollisionChecker,
                columns: Sequence[np.ndarray]) -> tuple[np.ndarray, np.ndarray]:
    """Per pinocchio joint of ``model``, for lanes moving the state columns ``columns``
    (one array a lane): the lane of the nearest joint at or above it that a lane moves,
    and the first lane (in order) moving a joint at or below it (that it carries), else
    that of its parent (-1: none). Kept per robot model (its checkers' shared geometry)."""
    part = checker.robot_geometry
    key = tuple(map(id, columns))
    kept = _JOINT_LANES.get(part)
    if kept is None:
        kept = _JOINT_LANES[part] = {}
    found = kept.get(key)
    if found is not None and all(a is b for a, b in zip(found[0], columns)):
        return found[1]
    pin_model = model.model
    parents = list(pin_model.parents)  # parents come before children
    none = len(columns)
    moved = [-1] * len(parents)
    carried = [none] * len(parents)
    for lane_index, lane_columns in enumerate(columns):
        for index in lane_columns.tolist():
            jid = int(pin_model.getJointId(model.joint_names[index]))
            moved[jid] = lane_index
            carried[jid] = min(carried[jid], lane_index)
    for jid in range(len(parents) - 1, 0, -1):  # children first: up the tree
        parent = parents[jid]
        if carried[jid] < carried[parent]:
            carried[parent] = carried[jid]
    carried[0] = none  # the world is of no lane
    for jid in range(1, len(parents)):  # parents first: down the tree
        parent = parents[jid]
        if moved[jid] < 0:
            moved[jid] = moved[parent]
        if carried[jid] == none:
            carried[jid] = carried[parent]
    moved_at = np.array(moved, dtype=np.int64)
    carried_at = np.array(carried, dtype=np.int64)
    carried_at[carried_at == none] = -1
    if len(kept) >= _JOINT_LANES_KEPT:
        kept.pop(next(iter(kept)))
    kept[key] = (tuple(columns), (moved_at, carried_at))
    return moved_at, carried_at


def lane_owners(model: RobotModel, checker: CollisionChecker, columns: Sequence[np.ndarray],
                only: Sequence[frozenset[str]] | None = None,
                without: frozenset[str] = frozenset(),
                lying: Mapping[str, int] | None = None,
                uncounted: frozenset[str] = frozenset()) -> Owners:
    """The :class:`Owners` of lanes moving the state columns ``columns`` (one array a
    lane) for ``checker``'s bodies and pairs: the objects ``lying`` of their lanes, the
    pairs those of the space-time walk's ``only`` and ``without``. Kept per checker."""
    moved_at, carried_at = joint_lanes(model, checker, columns)
    key = (id(moved_at), only, without, tuple(sorted((lying or {}).items())), uncounted)
    kept = _OWNERS.get(checker)
    if kept is None:
        kept = _OWNERS[checker] = {}
    found = kept.get(key)
    if found is not None and found[0] is moved_at:
        return found[1]
    joints = checker.geometry_joints
    # A body is of the lane whose moved joint is nearest above it; a body no lane's
    # joint moves, of the lane that carries it (a gripper lane: its arm's links).
    owner = np.where(moved_at[joints] >= 0, moved_at[joints], carried_at[joints])
    every = checker.pair_geometries
    keep = np.ones(len(every), dtype=bool)
    skipped = None
    if only is not None or without or lying or uncounted:
        bodies = _object_bodies(checker, model)
        first = checker.robot_geometry.geometry_count
        for g, body in enumerate(bodies, first):
            if lying and body in lying:
                owner[g] = lying[body]
        if lying:
            # An object lying in the world against another lane's links only: an object
            # the other lane holds may be set on it (a stack), as that lane's plan has it.
            put = np.zeros(len(owner), dtype=bool)
            put[first:] = [body in lying for body in bodies]
            a, b = every[:, 0], every[:, 1]
            keep &= ~((put[a] & (b >= first)) | (put[b] & (a >= first)))

        def touching(names: frozenset[str]) -> np.ndarray:
            mask = np.zeros(len(owner), dtype=bool)
            mask[first:] = [body in names for body in bodies]
            return mask[every[:, 0]] | mask[every[:, 1]]

        if without:
            keep &= ~touching(without)
        for names in only or ():
            keep &= touching(names)
        skipped = touching(uncounted) if uncounted else None
    oa, ob = owner[every[:, 0]], owner[every[:, 1]]
    ids = np.flatnonzero((oa >= 0) & (ob >= 0) & (oa != ob) & keep)
    swap = oa[ids] > ob[ids]  # the first body of each pair: of the lower lane
    owners = Owners(owner, ids, np.where(swap, every[ids, 1], every[ids, 0]),
                    np.where(swap, every[ids, 0], every[ids, 1]), skipped)
    if len(kept) >= _OWNERS_KEPT:
        kept.pop(next(iter(kept)))
    kept[key] = (moved_at, owners)
    return owners


# Per checker (kept while it lives): the owners of the latest few walks (:func:`lane_owners`).
_OWNERS: weakref.WeakKeyDictionary[object, dict[tuple[object, ...], tuple[np.ndarray, Owners]]] \
    = weakref.WeakKeyDictionary()
_OWNERS_KEPT = 8
# Per checker (kept while it lives): the bodies of its objects' geometries, in order.
_OBJECT_BODIES: weakref.WeakKeyDictionary[object, list[str]] = weakref.WeakKeyDictionary()


def _object_bodies(checker: CollisionChecker, model: RobotModel) -> list[str]:
    """The body (object name) of each of ``checker``'s geometries after the robot's."""
    found = _OBJECT_BODIES.get(checker)
    if found is None:
        objects = checker.geometry_model.geometryObjects
        found = _OBJECT_BODIES[checker] = [
            body_name(objects[g], model.model)
            for g in range(checker.robot_geometry.geometry_count, len(objects))]
    return found


def body_name(obj: pin.GeometryObject, pin_model: pin.Model) -> str:
    """A geometry's body: its link's name for a robot link, else the object's name."""
    name = str(obj.name)
    frame = int(obj.parentFrame)
    if 0 <= frame < len(pin_model.frames):
        link = str(pin_model.frames[frame].name)
        if name.startswith(link):
            return link
    body, _, index = name.rpartition("/")  # an object's geometries: 'name/index'
    return body if body and index.isdigit() else name
