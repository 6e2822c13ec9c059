"""Self-collision of a freshly loaded robot: its default state and its named poses.

A robot whose default state (or a named pose) is in self-collision plans nothing from
there: the collision matrix of its SRDF is incomplete, or the geometry is wrong. Loading
warns, naming the colliding link pairs and suggesting ``run-task collision-matrix``, the
Setup Assistant's "Self-Collisions" step.

The check uses the model's own collision geometry (meshes as triangle meshes), skipping
the pairs the SRDF disables and adjacent links, on pinocchio and coal only: the robot
layer does not depend on the scene. The scene checks a link mesh as its convex hull only
where that adds no collision at a named pose (see :mod:`taskrunner.scene.linkgeometry`).
"""

from __future__ import annotations

import coal
import numpy as np
import pinocchio as pin

from taskrunner.robot.model import RobotModel
from taskrunner.robot.notes import LoadWarning

__all__ = ["self_colliding_pairs", "self_collision_warnings"]

_MAX_PAIRS_SHOWN = 6


def self_colliding_pairs(robot: RobotModel, q: np.ndarray,
                         geometry: pin.GeometryModel | None = None) -> list[tuple[str, str]]:
    """Link pairs in collision at state ``q``, sorted; disabled and adjacent pairs and
    pairs within one link are not checked.

    Args:
        robot: the model.
        q: its state vector.
        geometry: the link geometry to check (default: the model's own, meshes as
            triangle meshes).
    """
    return _SelfCheck(robot, geometry).pairs(q)


class _SelfCheck:
    """The pair check of :func:`self_colliding_pairs`, built once for many states."""

    def __init__(self, robot: RobotModel, geometry: pin.GeometryModel | None = None) -> None:
        self._robot = robot
        geometry = geometry if geometry is not None else robot.collision_model
        objects = geometry.geometryObjects
        frames = robot.model.frames
        links = [frames[g.parentFrame].name for g in objects]
        self._checked = pin.GeometryModel()
        for g in objects:
            self._checked.addGeometryObject(g)
        self._pairs: list[tuple[str, str]] = []
        for i in range(len(links)):
            for j in range(i + 1, len(links)):
                if links[i] == links[j] or frozenset((links[i], links[j])) in (
                        robot.disabled_collisions):
                    continue
                self._checked.addCollisionPair(pin.CollisionPair(i, j))
                self._pairs.append((links[i], links[j]))
        self._data = robot.model.createData()
        self._geometry_data = self._checked.createData()

    def pairs(self, q: np.ndarray) -> list[tuple[str, str]]:
        if not self._pairs or not pin.computeCollisions(
                self._robot.model, self._data, self._checked, self._geometry_data,
                self._robot.to_pin(q), False):
            return []
        found = {tuple(sorted(self._pairs[k]))
                 for k, result in enumerate(self._geometry_data.collisionResults)
                 if result.isCollision()}
        return sorted((a, b) for a, b in found)


def self_collision_warnings(robot: RobotModel, start: np.ndarray | None = None,
                            start_name: str | None = None) -> list[LoadWarning]:
    """Warnings for a start state in self-collision and for each named pose (set on top
    of that start) that adds a colliding pair.

    Args:
        robot: the model.
        start: the state to check and to set named poses on (default: the default state
            with the robots' ``initial_positions.yaml`` applied).
        start_name: how to call it in messages.
    """
    source = robot.instances[0].source if len(robot.instances) == 1 else None
    warnings: list[LoadWarning] = []
    if start is None:
        start = robot.default_state()
        if robot.initial_values:
            start = robot.state_with(start, robot.initial_values)
            start_name = start_name or "the start state (initial_positions.yaml)"
    start_name = start_name or "the default state (every joint at 0, clipped to its limits)"

    def report(what: str, pairs: list[tuple[str, str]], tail: str = "") -> None:
        shown = ", ".join(f"{a}–{b}" for a, b in pairs[:_MAX_PAIRS_SHOWN])
        more = f" and {len(pairs) - _MAX_PAIRS_SHOWN} more" if len(pairs) > _MAX_PAIRS_SHOWN else ""
        geometry = _geometry_words(robot, [n for pair in pairs[:_MAX_PAIRS_SHOWN] for n in pair])
        warnings.append(LoadWarning(
            f"{what} is in self-collision ({shown}{more}; {geometry}){tail}: nothing can be "
            "planned from there; if these links cannot touch, the SRDF's collision matrix is "
            "incomplete: "
            "run `run-task collision-matrix ROBOT --write SRDF`", source))

    check = _SelfCheck(robot)
    start_pairs = check.pairs(start)
    if start_pairs:
        report(start_name, start_pairs, "; its named poses were not checked")
        return warnings
    hands = {eef.group: eef.parent_link for eef in robot.end_effectors.values()}
    for group, poses in robot.named_states.items():
        if robot.groups[group].robot is None:
            continue  # a cell's group spanning robots: not one robot's self-collision
        # A hand's pose says nothing of where the arm is: only the hand's own links (and
        # the link it hangs from) are checked against each other.
        own = _moved_links(robot, group) | {hands[group]} if group in hands else None
        aliases = robot.pose_aliases.get(group, {})
        for name, values in poses.items():
            if name in aliases:
                continue
            pairs = check.pairs(robot.state_with(start, values))
            if own is not None:
                pairs = [(a, b) for a, b in pairs if a in own and b in own]
            if pairs:
                report(f"named pose {name!r} of group {group!r}", pairs)
    return warnings


def _geometry_words(robot: RobotModel, links: list[str]) -> str:
    """``exact meshes``, ``primitive shapes`` or both: what these links were checked as."""
    frames = robot.model.frames
    meshes = {frames[g.parentFrame].name for g in robot.collision_model.geometryObjects
              if isinstance(g.geometry, coal.BVHModelBase)}
    kinds = {"exact meshes" if link in meshes else "primitive shapes" for link in links}
    return " and ".join(sorted(kinds))


def _moved_links(robot: RobotModel, group: str) -> set[str]:
    """Links whose placement depends on a joint of ``group``."""
    model = robot.model
    joint_ids = {model.getJointId(name) for name in robot.groups[group].joint_names}
    moved = set()
    for frame in model.frames:
        if frame.type != pin.BODY:
            continue
        joint = frame.parentJoint
        while joint != 0:
            if joint in joint_ids:
                moved.add(frame.name)
                break
            joint = model.parents[joint]
    return moved
