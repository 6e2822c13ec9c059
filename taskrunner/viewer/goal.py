"""Goals set on the page, checked as the planner would: IK for a dragged tool frame, and
the joint limits and collisions of the goal state.

The page's interactive goal (RViz's MotionPlanning "goal state") is either a pose of a
group's tip link (or another link it moves), solved by :class:`~taskrunner.kinematics.ik.
IkSolver` from the page's current goal as the seed (so the goal moves continuously as it
is dragged), or joint values. Either way the answer is the group's joint values, the
tip's world pose at them and whether the state is one the planner accepts as a goal:
within the limits and collision-free against the cell's fixed objects (with the pairs
that touch, as the reason).
"""

from __future__ import annotations

import math
import threading
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass

import numpy as np
import pinocchio as pin

from taskrunner.errors import IkFailedError, InputError
from taskrunner.kinematics.fk import frame_pose
from taskrunner.kinematics.ik import IkSolver
from taskrunner.kinematics.ik_types import IkOptions
from taskrunner.robot.cell import Cell
from taskrunner.scene import Scene, scene_from_cell
from taskrunner.shapes import Shape
from taskrunner.types import Pose

__all__ = ["GoalSolver", "GoalState", "Obstacle"]

Obstacle = tuple[str, Shape, Pose]
"""An object added to the scene for one check: name, shape (:mod:`taskrunner.shapes`),
world pose."""

_MAX_SOLVERS = 16  # (group, link) pairs kept per cell


@dataclass(frozen=True)
class GoalState:
    """A goal state of one group, checked.

    Attributes:
        group: the group.
        link: the link whose pose was aimed at (or is reported).
        joints: the group's joints at the goal (rad or m).
        xyz, quat: the link's world pose at the goal (m; quaternion x, y, z, w).
        reachable: IK found a solution (always true for a joint goal).
        collision_free: no disallowed contact at the goal (self or the cell's objects).
        within_limits: every joint within its limits.
        reason: why the goal cannot be planned to (None: it can).
    """

    group: str
    link: str
    joints: dict[str, float]
    xyz: tuple[float, float, float]
    quat: tuple[float, float, float, float]
    reachable: bool
    collision_free: bool
    within_limits: bool
    reason: str | None

    def as_dict(self) -> dict[str, object]:
        return {"group": self.group, "link": self.link, "joints": self.joints,
                "xyz": list(self.xyz), "quat": list(self.quat), "reachable": self.reachable,
                "collision_free": self.collision_free, "within_limits": self.within_limits,
                "ok": self.reason is None, "reason": self.reason}


class GoalSolver:
    """IK and goal checks for one cell: a scene of its fixed objects and one IK solver
    per (group, link), used one call at a time (a lock: solvers and the scene hold
    state)."""

    def __init__(self, cell: Cell) -> None:
        self.cell = cell
        self._scene: Scene | None = None
        self._solvers: dict[tuple[str, str], IkSolver] = {}
        self._data = cell.model.model.createData()
        self._lock = threading.Lock()

    def solve_pose(self, group: str, xyz: Sequence[float], quat: Sequence[float],
                   link: str | None, seed: Mapping[str, float],
                   obstacles: Iterable[Obstacle] = ()) -> GoalState:
        """The group's joints that put ``link`` (default: its tip) at the world pose
        ``xyz`` (m), ``quat`` (x, y, z, w; normalised here), searched from ``seed``.
        Unreachable: the seed's joints, with IK's reason.

        Raises:
            UnknownNameError: an unknown group, link or seed joint.
            InputError: a zero quaternion, a link the group does not move, a group
                without a tip link and no link given.
        """
        model = self.cell.model
        spec = model.group(group)
        norm = math.sqrt(sum(float(v) ** 2 for v in quat))
        if not norm > 1e-9:
            raise InputError(f"'pose.quat' must be a non-zero quaternion (got {list(quat)})")
        x, y, z, w = (float(v) / norm for v in quat)
        target = pin.SE3(pin.Quaternion(w, x, y, z).toRotationMatrix(),
                         np.array([float(v) for v in xyz]))
        q_seed = self._seed_state(seed)
        with self._lock:
            solver = self._solver(spec.name, link)
            try:
                q = np.array(solver.solve(target, q_seed, IkOptions(seed=0)).q)
                failure = None
            except IkFailedError as exc:
                q, failure = q_seed, str(exc)
            return self._checked(spec.name, solver.frame, q, reachable=failure is None,
                                 reason=failure, obstacles=obstacles)

    def check_joints(self, group: str, joints: Mapping[str, float],
                     seed: Mapping[str, float], link: str | None = None,
                     obstacles: Iterable[Obstacle] = ()) -> GoalState:
        """The goal ``joints`` of ``group`` (the seed's values for the group's other
        joints) checked: limits, collisions, and ``link``'s (default: the tip's) pose.

        Raises:
            UnknownNameError: an unknown group, link or joint.
            InputError: a joint that is not one of the group's.
        """
        model = self.cell.model
        spec = model.group(group)
        own = set(spec.joint_names)
        for name in joints:
            model.joint(name)  # UnknownNameError names the known ones
            if name not in own:
                raise InputError(f"'joints': {name!r} is not a joint of group {spec.name!r} "
                                 f"(its joints: {', '.join(spec.joint_names)})")
        q = model.state_with(self._seed_state(seed), joints)
        frame = link or spec.tip_link or spec.joint_names[-1]
        model.frame_id(frame)
        with self._lock:
            return self._checked(spec.name, frame, q, reachable=True, reason=None,
                                 obstacles=obstacles)

    # ------------------------------------------------------------------ helpers
    def _seed_state(self, seed: Mapping[str, float]) -> np.ndarray:
        model = self.cell.model
        q = model.state_with(self.cell.start_state(), seed)
        return np.clip(q, model.lower, model.upper)

    def _solver(self, group: str, link: str | None) -> IkSolver:
        key = (group, link or "")
        solver = self._solvers.get(key)
        if solver is None:
            if len(self._solvers) >= _MAX_SOLVERS:
                self._solvers.pop(next(iter(self._solvers)))
            solver = self._solvers[key] = IkSolver(self.cell.model, group, link)
        return solver

    def scene_with(self, obstacles: Iterable[Obstacle]) -> Scene:
        """The cell's scene (shared: do not change it) or, with obstacles, a copy with
        them added.

        Raises:
            InputError: an obstacle named as an object of the cell or another obstacle.
        """
        if self._scene is None:
            self._scene = scene_from_cell(self.cell)
        extra = list(obstacles)
        if not extra:
            return self._scene
        scene = self._scene.copy()
        for name, shape, pose in extra:
            if name in scene.object_names:
                raise InputError(f"'obstacles': name {name!r} is taken by another object "
                                 "of the scene")
            scene.add_object(name, shape, pose)
        return scene

    def _checked(self, group: str, link: str, q: np.ndarray, reachable: bool,
                 reason: str | None, obstacles: Iterable[Obstacle] = ()) -> GoalState:
        model = self.cell.model
        spec = model.group(group)
        bad = model.limit_violations(q)
        scene = self.scene_with(obstacles)
        contacts = scene.collisions(q)
        if reason is None and bad:
            reason = "outside the joint limits: " + "; ".join(bad)
        if reason is None and contacts:
            pairs = ", ".join(f"{c.a} – {c.b} ({c.depth * 1000:.1f} mm deep)"
                              for c in contacts[:4])
            more = f" and {len(contacts) - 4} more" if len(contacts) > 4 else ""
            reason = (f"the goal is in collision: {pairs}{more}"
                      f"{scene.geometry_note(contacts[:4])}")
        pose = frame_pose(model, q, link, self._data)
        quat = pin.Quaternion(pose.rotation)
        return GoalState(
            group=group, link=link,
            joints={n: round(float(q[model.joint(n).index]), 9) for n in spec.joint_names},
            xyz=tuple(round(float(v), 9) for v in pose.translation),  # type: ignore[arg-type]
            quat=(float(quat.x), float(quat.y), float(quat.z), float(quat.w)),
            reachable=reachable, collision_free=not contacts, within_limits=not bad,
            reason=reason)
