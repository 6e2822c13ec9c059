"""Cartesian paths: a link moved along straight lines through world poses.

:class:`CartesianPlanner` follows MoveIt's ``computeCartesianPath``. Between consecutive
waypoints (the first segment starts at the link's pose in the start state) the link's
position moves on a straight line and its orientation turns by slerp, both linear in
one path parameter. Each segment is cut into equal steps no longer than ``eef_step`` (m)
and ``max_rotation_step`` (rad); each step's pose is solved by IK seeded with the
previous solution, one local attempt without restarts, so the arm never switches to
another branch of solutions. Arms with fewer than six joints (``position_only_ik`` in
kinematics.yaml) follow the line with position-only IK: the orientation is left free,
and stays continuous since every solve starts from the previous one.

A path that cannot be completed is cut short, never raised: it ends at the last point
reached and :attr:`CartesianResult.fraction` < 1 says how far it got, with the reason
(``"ik"``, ``"collision"`` or ``"jump"``) and a message naming the step or the bodies.

The fraction is the share of the path's length achieved, the length of a segment being
the larger of its translation (m) and its rotation (rad) times ``eef_step /
max_rotation_step``, so that a pure rotation counts too. (MoveIt weights every waypoint
equally instead of by length.)
"""

from __future__ import annotations

import itertools
import math
import time
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from typing import TypeAlias

import numpy as np
import pinocchio as pin

from taskrunner.errors import (
    ArgumentError,
    IkFailedError,
    InputError,
    InvalidStateError,
    StartInCollisionError,
)
from taskrunner.kinds import StopReason
from taskrunner.kinematics import IkOptions, IkSolver
from taskrunner.robot.model import Group
from taskrunner.scene import Scene
from taskrunner.types import JointPath, Pose

__all__ = [
    "CartesianOptions",
    "CartesianPlanner",
    "CartesianResult",
    "Waypoint",
    "compute_cartesian_path",
    "compute_relative_cartesian_path",
    "relative_pose",
]

Waypoint: TypeAlias = Pose | pin.SE3
"""A pose of the moving link: an SE3 in the world frame, or a :class:`Pose` in the world,
a robot link's frame (taken at the start state) or a scene object's frame."""

_largest, _absolute = np.maximum.reduce, np.absolute  # the ufuncs, without np.max's wrapper
MIN_STEPS_FOR_JUMP_TEST = 10  # MoveIt's MIN_STEPS_FOR_JUMP_THRESH: fewer steps, no mean


@dataclass(frozen=True)
class CartesianOptions:
    """How a Cartesian path is followed and when it is cut.

    Attributes:
        eef_step: largest translation of the link between two IK points (m).
        max_rotation_step: largest rotation of the link between two IK points (rad).
        jump_threshold: MoveIt's relative jump test; 0 disables it. Once the path is
            computed, it is cut before the first joint-space step (sum of the active
            joints' absolute moves) larger than ``jump_threshold`` times the mean step of
            the path. Needs at least 10 steps; shorter paths are not tested.
        max_joint_step: absolute jump test: the path stops before a step in which any
            joint moves more than this (rad, or m for prismatic joints); None disables
            it. It must exceed what one ``eef_step`` legitimately costs (about 0.01-0.05
            rad on the shipped arms at the default step).
        avoid_collisions: stop before the first state in collision, checked at every IK
            point and between consecutive points every ``collision_resolution``.
        collision_resolution: largest joint move (rad or m) between two collision checks
            along the joint-space segment joining consecutive IK points.
        position_only: aim the link's origin only, leaving its orientation free. None:
            the group's ``position_only_ik`` setting.
        tolerance: IK position tolerance (m) at every point.
        rotation_tolerance: IK rotation tolerance (rad); default ``tolerance``.
    """

    eef_step: float = 0.005
    max_rotation_step: float = 0.05
    jump_threshold: float = 0.0
    max_joint_step: float | None = 0.2
    avoid_collisions: bool = True
    collision_resolution: float = 0.01
    position_only: bool | None = None
    tolerance: float = 1e-5
    rotation_tolerance: float | None = None

    def __post_init__(self) -> None:
        for name in ("eef_step", "max_rotation_step", "collision_resolution", "tolerance",
                     "max_joint_step", "rotation_tolerance"):
            value = getattr(self, name)
            if value is None and name in ("max_joint_step", "rotation_tolerance"):
                continue
            if not _is_number(value) or not math.isfinite(value) or value <= 0:
                raise ArgumentError(f"'{name}' must be a positive number (got {value!r})")
        if (not _is_number(self.jump_threshold) or not math.isfinite(self.jump_threshold)
                or self.jump_threshold < 0):
            raise ArgumentError(f"'jump_threshold' must be a number >= 0 (got {self.jump_threshold!r})")
        if not isinstance(self.avoid_collisions, bool):  # ValueError like every option check
            raise ArgumentError(
                f"'avoid_collisions' must be a bool (got {self.avoid_collisions!r})")
        if self.position_only is not None and not isinstance(self.position_only, bool):
            raise ArgumentError(
                f"'position_only' must be True, False or None (got {self.position_only!r})")


@dataclass(frozen=True)
class CartesianResult:
    """A Cartesian path, complete or cut short.

    Attributes:
        path: the group's active joints at every IK point reached, the start first.
        fraction: share of the path's Cartesian length achieved, in [0, 1] (see the
            module docstring); exactly 1.0 when complete.
        start: the full state vector the path starts from (other joints stay as here).
        end: the full state vector at the last point of ``path``.
        stop_reason: None when complete, else ``"ik"`` (no IK solution near the previous
            point), ``"collision"`` or ``"jump"``.
        message: what stopped the path, for people (empty when complete).
        waypoints_reached: how many of the waypoints the path reached.
        ik_solves: IK calls made.
        collision_checks: state checks made.
        elapsed: wall time of the computation (s).
    """

    path: JointPath
    fraction: float
    start: np.ndarray
    end: np.ndarray
    stop_reason: StopReason | None
    message: str
    waypoints_reached: int
    ik_solves: int
    collision_checks: int
    elapsed: float

    @property
    def complete(self) -> bool:
        """True when the whole path was achieved."""
        return self.stop_reason is None


@dataclass(frozen=True)
class _Point:
    """One IK target along the path: its waypoint, path fraction and pose."""

    waypoint: int
    fraction: float
    rotation: np.ndarray
    position: np.ndarray


class CartesianPlanner:
    """Computes Cartesian paths in a scene; keeps one IK solver per (group, link).

    The planner reads the scene (objects, allowances, current state) at every call. Not
    thread-safe: give each thread its own planner and :meth:`Scene.copy`.
    """

    def __init__(self, scene: Scene) -> None:
        self.scene = scene
        self._data = scene.robot.model.createData()
        self._solvers: dict[tuple[str, str | None], IkSolver] = {}

    def compute(self, group: Group | str, waypoints: Waypoint | Sequence[Waypoint],
                link: str | None = None, options: CartesianOptions | None = None,
                start: np.ndarray | None = None) -> CartesianResult:
        """Move ``link`` in straight lines through ``waypoints``.

        Args:
            group: the planning group whose joints move.
            waypoints: one pose or several, passed through in order (see :data:`Waypoint`).
            link: the link that follows the lines; default the group's tip link.
            options: steps, jump tests, collision avoidance, tolerances.
            start: full state vector to start from; default the scene's state.

        Raises:
            UnknownNameError: an unknown group, link or waypoint frame.
            InputError: no waypoints, a waypoint of the wrong type, or a link the group
                does not move.
            InvalidStateError: a start of the wrong length or outside the joint limits.
            StartInCollisionError: the start collides (only with ``avoid_collisions``).
        """
        t0 = time.perf_counter()
        options = options or CartesianOptions()
        model = self.scene.robot
        group = model.group(group) if isinstance(group, str) else group
        solver = self._solver(group.name, link)
        q = self._start_state(start)
        checker = self.scene.checker if options.avoid_collisions else None
        if checker is not None and checker.in_collision(model.to_pin(q)):
            contacts = self.scene.collisions(q)
            raise StartInCollisionError(
                f"start state of group {group.name!r} is in collision: {_describe(contacts)}"
                f"{self.scene.geometry_note(contacts[:1])}", [(c.a, c.b) for c in contacts])
        position_only = (group.position_only_ik if options.position_only is None
                         else options.position_only)
        poses = [self._frame_pose(solver.frame, q)]
        poses += [self._world_pose(w, q) for w in _as_list(waypoints)]
        ik_options = IkOptions(tolerance=options.tolerance,
                               rotation_tolerance=options.rotation_tolerance,
                               attempts=1, position_only=position_only)
        idx = group.joint_indices
        to_pin = model.to_pin
        rows, fractions, states = [q[idx]], [0.0], [q]
        stop: StopReason | None = None
        message = ""
        solves = checks = 0
        for point in _points(poses, options, position_only):
            solves += 1
            target = (point.position if position_only
                      else pin.SE3(point.rotation, point.position))
            try:
                q_next = solver.solve_near(target, q, ik_options)
            except IkFailedError as error:
                stop = StopReason.IK
                xyz = ", ".join(f"{v:.4f}" for v in point.position)
                residual = "" if error.best_error is None else (
                    f"; best residual {error.best_error:.3g}")
                message = (f"no IK solution for {solver.frame!r} near the previous point at "
                           f"{_percent(point.fraction)} of the path (towards waypoint "
                           f"{point.waypoint + 1} of {len(poses) - 1}), target position "
                           f"({xyz}){residual}")
                break
            if options.max_joint_step is not None:
                moves = np.abs(q_next[idx] - q[idx])
                k = int(moves.argmax())
                if moves[k] > options.max_joint_step:
                    stop = StopReason.JUMP
                    message = (f"joint {group.joint_names[k]!r} would move {moves[k]:.3f} "
                               f"between consecutive points at {_percent(point.fraction)} of "
                               f"the path (max_joint_step {options.max_joint_step:g})")
                    break
            if checker is not None:
                # The states every collision_resolution between q and q_next (q excluded),
                # as interpolate_path makes them (np.linspace(0, 1, count + 1)[1:]'s values,
                # without its overhead).
                delta = q_next - q
                count = max(1, math.ceil(float(_largest(_absolute(delta)))
                                         / options.collision_resolution))
                along = np.arange(1.0, count + 1.0)
                along *= 1.0 / count
                along[-1] = 1.0
                dense = q + along[:, None] * delta
                first = checker.first_in_collision(to_pin(dense))  # in order, to the first hit
                hit = None if first < 0 else first + 1
                checks += count if hit is None else hit
                if hit is not None:
                    at = fractions[-1] + hit / count * (point.fraction - fractions[-1])
                    stop = StopReason.COLLISION
                    message = (f"collision between {_describe(self.scene.collisions(dense[hit - 1]))}"
                               f" at {_percent(at)} of the path")
                    break
            q = q_next
            rows.append(q[idx])
            fractions.append(point.fraction)
            states.append(q)
        jump = _relative_jump(rows, options.jump_threshold)
        if jump is not None:
            k, step, mean = jump
            stop = StopReason.JUMP
            message = (f"joint-space step of {step:.4f} at {_percent(fractions[k + 1])} of the "
                       f"path exceeds jump_threshold {options.jump_threshold:g} x the mean "
                       f"step {mean:.4f}")
            del rows[k + 1:], fractions[k + 1:], states[k + 1:]
        fraction = 1.0 if stop is None else fractions[-1]
        bounds = _cumulative_lengths(poses, options, position_only)
        reached = (len(poses) - 1 if stop is None
                   else int(np.count_nonzero(bounds[1:] <= fraction + 1e-12)))
        return CartesianResult(
            path=JointPath(group.joint_names, np.array(rows)), fraction=fraction,
            start=states[0], end=states[-1], stop_reason=stop, message=message,
            waypoints_reached=reached, ik_solves=solves, collision_checks=checks,
            elapsed=time.perf_counter() - t0)

    def compute_relative(self, group: Group | str, offset_xyz: Sequence[float],
                         offset_rpy: Sequence[float] = (0.0, 0.0, 0.0), frame: str = "link",
                         link: str | None = None, options: CartesianOptions | None = None,
                         start: np.ndarray | None = None) -> CartesianResult:
        """Move ``link`` in a straight line by an offset (see :func:`relative_pose`)."""
        model = self.scene.robot
        group = model.group(group) if isinstance(group, str) else group
        solver = self._solver(group.name, link)
        q = self._start_state(start)
        target = relative_pose(self.scene, solver.frame, offset_xyz, offset_rpy, frame, start=q)
        return self.compute(group, target, solver.frame, options, q)

    # ------------------------------------------------------------------ internals
    def _solver(self, group: str, link: str | None) -> IkSolver:
        key = (group, link)
        solver = self._solvers.get(key)
        if solver is None:
            solver = self._solvers[key] = IkSolver(self.scene.robot, group, frame=link)
        return solver

    def _start_state(self, start: np.ndarray | None) -> np.ndarray:
        model = self.scene.robot
        if start is None:
            q = self.scene.state.copy()
        else:
            q = np.array(start, dtype=float)
            if q.shape != (model.nq,):
                raise InvalidStateError(f"'start' must have {model.nq} values, one per joint of "
                                        f"{model.name!r} (got shape {q.shape})")
            if not np.all(np.isfinite(q)):
                raise InvalidStateError(f"'start' must be finite (got {q})")
            model.apply_mimic(q)
        bad = model.limit_violations(q)
        if bad:
            raise InvalidStateError("start state outside the joint limits: " + "; ".join(bad))
        return q

    def _frame_pose(self, frame: str, q: np.ndarray) -> pin.SE3:
        model = self.scene.robot
        pin.forwardKinematics(model.model, self._data, model.to_pin(q))
        return pin.SE3(pin.updateFramePlacement(model.model, self._data, model.frame_id(frame)))

    def _world_pose(self, waypoint: Waypoint, q: np.ndarray) -> pin.SE3:
        """World transform of a waypoint, link frames taken at state ``q``."""
        if isinstance(waypoint, pin.SE3):
            return pin.SE3(waypoint)
        if not isinstance(waypoint, Pose):
            raise InputError(f"'waypoints' must be Pose or pinocchio SE3 values "
                             f"(got {type(waypoint).__name__})")
        return self.scene.to_world(waypoint, q)


def relative_pose(scene: Scene, link: str, offset_xyz: Sequence[float],
                  offset_rpy: Sequence[float] = (0.0, 0.0, 0.0), frame: str = "link",
                  start: np.ndarray | None = None) -> Pose:
    """World pose of ``link`` moved by an offset from where it is in ``start``.

    Args:
        scene: gives the robot model and, without ``start``, the state.
        link: the link (or model frame) that moves.
        offset_xyz: translation (m), along the link's axes (``frame="link"``) or the
            world's (``frame="world"``): "5 cm along the tool's z" is ``(0, 0, 0.05)``
            in ``"link"``; "10 cm up" is ``(0, 0, 0.1)`` in ``"world"``.
        offset_rpy: rotation (rad, roll-pitch-yaw) about the link's axes (``"link"``)
            or about world-aligned axes through the link's origin (``"world"``).
        frame: ``"link"`` or ``"world"``.
        start: full state vector; default the scene's state.

    Raises:
        UnknownNameError: unknown link.
        InputError: a bad offset or frame.
    """
    xyz = _vector3("offset_xyz", offset_xyz)
    rpy = _vector3("offset_rpy", offset_rpy)
    if frame not in ("link", "world"):
        raise InputError(f"'frame' must be 'link' or 'world' (got {frame!r})")
    model = scene.robot
    q = scene.state if start is None else np.asarray(start, dtype=float)
    if q.shape != (model.nq,):
        raise InputError(f"'start' must have {model.nq} values (got shape {q.shape})")
    data = model.model.createData()
    pin.forwardKinematics(model.model, data, model.to_pin(q))
    current = pin.updateFramePlacement(model.model, data, model.frame_id(link))
    rotation = pin.rpy.rpyToMatrix(*rpy)
    if frame == "link":
        moved = current * pin.SE3(rotation, xyz)
    else:
        moved = pin.SE3(rotation @ current.rotation, current.translation + xyz)
    return Pose.from_se3(moved)


def compute_cartesian_path(scene: Scene, group: Group | str,
                           waypoints: Waypoint | Sequence[Waypoint], link: str | None = None,
                           options: CartesianOptions | None = None,
                           start: np.ndarray | None = None) -> CartesianResult:
    """:meth:`CartesianPlanner.compute` on a new planner (building its IK solver costs
    about 1 ms: keep a :class:`CartesianPlanner` for repeated calls)."""
    return CartesianPlanner(scene).compute(group, waypoints, link, options, start)


def compute_relative_cartesian_path(scene: Scene, group: Group | str,
                                    offset_xyz: Sequence[float],
                                    offset_rpy: Sequence[float] = (0.0, 0.0, 0.0),
                                    frame: str = "link", link: str | None = None,
                                    options: CartesianOptions | None = None,
                                    start: np.ndarray | None = None) -> CartesianResult:
    """:meth:`CartesianPlanner.compute_relative` on a new planner."""
    return CartesianPlanner(scene).compute_relative(group, offset_xyz, offset_rpy, frame, link,
                                                    options, start)


# ---------------------------------------------------------------------- path geometry
def _relative_jump(rows: list[np.ndarray], threshold: float
                   ) -> tuple[int, float, float] | None:
    """MoveIt's relative jump test: ``(k, step, mean)`` for the first step ``k -> k+1``
    whose joint-space length (sum of the joints' absolute moves) exceeds ``threshold``
    times the mean step, or None (also when disabled or with too few steps)."""
    if threshold <= 0 or len(rows) <= MIN_STEPS_FOR_JUMP_TEST:
        return None
    steps = np.abs(np.diff(np.array(rows), axis=0)).sum(axis=1)
    mean = float(steps.mean())
    over = np.flatnonzero(steps > threshold * mean)
    return None if over.size == 0 else (int(over[0]), float(steps[over[0]]), mean)


def _segments(poses: list[pin.SE3], options: CartesianOptions, position_only: bool
              ) -> list[tuple[np.ndarray, np.ndarray, int, float]]:
    """Per segment: ``(translation, rotation vector (log3), steps, length)``."""
    ratio = options.eef_step / options.max_rotation_step
    out = []
    for a, b in itertools.pairwise(poses):
        dp = b.translation - a.translation
        dw = np.zeros(3) if position_only else pin.log3(a.rotation.T @ b.rotation)
        distance, angle = float(np.linalg.norm(dp)), float(np.linalg.norm(dw))
        # A hair under a whole number of steps is that number, not one more.
        steps = math.ceil(max(distance / options.eef_step, angle / options.max_rotation_step)
                          - 1e-9)
        out.append((dp, dw, max(steps, 0), max(distance, angle * ratio)))
    return out


def _cumulative_lengths(poses: list[pin.SE3], options: CartesianOptions,
                        position_only: bool) -> np.ndarray:
    """Path fraction at each pose (0 at the start, 1 at the last waypoint)."""
    lengths = np.array([s[3] for s in _segments(poses, options, position_only)])
    total = float(lengths.sum())
    if total == 0.0:
        return np.zeros(len(poses))
    return np.concatenate(([0.0], np.cumsum(lengths) / total))


def _points(poses: list[pin.SE3], options: CartesianOptions, position_only: bool
            ) -> Iterator[_Point]:
    """The IK targets: translation linear and rotation slerped along each segment."""
    segments = _segments(poses, options, position_only)
    total = sum(s[3] for s in segments)
    done = 0.0
    for w, (a, (dp, dw, steps, length)) in enumerate(zip(poses[:-1], segments)):
        for j in range(1, steps + 1):
            s = j / steps
            fraction = (done + s * length) / total if total > 0 else 1.0
            rotation = a.rotation if position_only else a.rotation @ pin.exp3(s * dw)
            yield _Point(w, min(fraction, 1.0), rotation, a.translation + s * dp)
        done += length


# ---------------------------------------------------------------------- small helpers
def _as_list(waypoints: Waypoint | Sequence[Waypoint]) -> list[Waypoint]:
    items = [waypoints] if isinstance(waypoints, (Pose, pin.SE3)) else list(waypoints)
    if not items:
        raise InputError("'waypoints' must hold at least one pose (got none)")
    return items


def _vector3(name: str, values: Sequence[float]) -> np.ndarray:
    try:
        array = np.array(values, dtype=float)
    except (TypeError, ValueError):
        raise InputError(f"'{name}' must be 3 numbers (got {values!r})") from None
    if array.shape != (3,) or not np.all(np.isfinite(array)):
        raise InputError(f"'{name}' must be 3 finite numbers (got {values!r})")
    return array


def _is_number(value: object) -> bool:
    return isinstance(value, (int, float, np.integer, np.floating)) and not isinstance(value, bool)


def _percent(fraction: float) -> str:
    # Floor, so that a path cut at 99.7 % never reads "100 %".
    return f"{math.floor(100.0 * fraction + 1e-9):.0f} %"


def _describe(contacts) -> str:  # type: ignore[no-untyped-def]
    if not contacts:
        return "no contact reported"
    first = f"{contacts[0].a} and {contacts[0].b}"
    more = f" (and {len(contacts) - 1} more pair(s))" if len(contacts) > 1 else ""
    return first + more
