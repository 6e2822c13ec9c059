"""Aiming a frame: the arm's joint states that put a frame's point on a target with the
frame's orientation as near a wanted one as the arm allows (re-aiming position-only IK
solutions, rolling a grasp about its axis), and how near an orientation is. Used by the
goal choice of :mod:`taskrunner.tree.reach`."""

from __future__ import annotations

import math

import numpy as np
import pinocchio as pin

from taskrunner.errors import IkFailedError
from taskrunner.kinematics import IkOptions, IkSolver
from taskrunner.robot.model import LIMIT_TOLERANCE, RobotModel

__all__ = ["FIXED_POINT_ROUNDS", "FREE_TURN_WEIGHT", "Frames", "about_z", "aimed",
           "nearest_orientation", "offset_at", "orientation_error", "rolled"]

FIXED_POINT_ROUNDS = 6
FREE_TURN_WEIGHT = 0.1  # weight of a grasp's turn about its closing axis (see orientation_error)

class Frames:
    """Forward kinematics of one frame (a private pin.Data): the joints' placements and
    that frame's only (the same arithmetic as every frame's)."""

    def __init__(self, model: RobotModel, link: str) -> None:
        self.model, self.data, self.frame = model, model.model.createData(), model.frame_id(link)
        self._pin_model, self._to_pin = model.model, model.to_pin

    def __call__(self, q: np.ndarray) -> pin.SE3:
        pin.forwardKinematics(self._pin_model, self.data, self._to_pin(q))
        return pin.updateFramePlacement(self._pin_model, self.data, self.frame)  # a copy


def nearest_orientation(fk: Frames, solver: IkSolver, q: np.ndarray, pose: pin.SE3,
                         goal: np.ndarray, offset: np.ndarray, grasping: bool,
                         local: IkOptions) -> tuple[np.ndarray, pin.SE3] | None:
    """The state nearest ``q`` that keeps ``offset`` (``link``'s frame, m) at ``goal``
    (world, m) with the frame's orientation as near ``pose``'s as the arm allows, and the
    frame's pose there; None where it is no nearer than ``q``.

    A descent of the orientation error (:func:`orientation_error`, a grasp's turn about
    its closing axis weighted as there) within the states that hold the point: damped
    Gauss-Newton steps projected on the null space of the point's Jacobian (both by
    finite differences over the solved joints), each followed by a position-only re-aim
    of the point and kept only where the error drops; halved where it does not. For an
    arm of fewer than six joints this is the pose's nearest reachable neighbour (a 5-DOF
    arm's tool a degree off vertical gives the vertical state, not a random posture).
    """
    indices = np.asarray(solver.group.joint_indices)
    names = solver.group.joint_names
    lower = np.array([solver.model.lower[k] for k in indices])
    upper = np.array([solver.model.upper[k] for k in indices])
    weights = np.array([1.0, FREE_TURN_WEIGHT if grasping else 1.0, 1.0])
    wanted_t = pose.rotation.T

    def error(frame: pin.SE3) -> np.ndarray:
        return weights * pin.log3(wanted_t @ frame.rotation)

    def reaimed(values: np.ndarray) -> tuple[np.ndarray, pin.SE3] | None:
        for _ in range(FIXED_POINT_ROUNDS + 1):
            frame = fk(values)
            target = goal - frame.rotation @ offset
            miss = target - frame.translation
            if float(miss @ miss) <= local.tolerance**2:
                return values, frame
            try:
                values = solver.solve_near(target, seed_q=values, options=local)
            except IkFailedError:
                return None
        return None

    frame = fk(q)
    start_angle = angle = orientation_error(frame, pose, grasping)
    if len(names) < 2:
        return None
    current = np.array(q, dtype=float)
    eye = np.eye(len(indices))
    for _ in range(REFINE_ROUNDS):
        if angle < REFINE_DONE:
            break
        e = error(frame)
        point = frame.translation + frame.rotation @ offset
        jp = np.empty((3, len(indices)))
        jr = np.empty((3, len(indices)))
        for k, index in enumerate(indices):
            moved = current.copy()
            moved[index] += _FD_STEP
            there = fk(moved)
            jp[:, k] = (there.translation + there.rotation @ offset - point) / _FD_STEP
            jr[:, k] = (error(there) - e) / _FD_STEP
        null = eye - np.linalg.pinv(jp, rcond=1e-6) @ jp
        a = jr @ null
        step = -null @ (a.T @ np.linalg.solve(a @ a.T + _REFINE_DAMPING * np.eye(3), e))
        improved = False
        for _ in range(4):  # the step, then halves of it
            values = current.copy()
            values[indices] = np.clip(current[indices] + step, lower, upper)
            found = reaimed(values)
            if found is not None:
                there_angle = orientation_error(found[1], pose, grasping)
                if there_angle < angle - 1e-9:
                    current, frame, angle = found[0], found[1], there_angle
                    improved = True
                    break
            step = step / 2
        if not improved:
            break
    if angle >= start_angle - 1e-9:
        return None
    return current, frame


REFINE_ROUNDS = 30  # descent steps of nearest_orientation
REFINE_DONE = 1e-6  # rad: an orientation this near needs no further step
_REFINE_DAMPING = 1e-6
_FD_STEP = 1e-7  # rad (or m) of a finite difference


def offset_at(fk: Frames, q: np.ndarray, offset: np.ndarray) -> np.ndarray:
    """``offset`` (link frame) in world axes at state ``q``."""
    return fk(q).rotation @ offset if offset.any() else np.zeros(3)


def aimed(fk: Frames, roll: tuple[int, float] | None, grasping: bool, q: np.ndarray,
           pose: pin.SE3, goal: np.ndarray, offset: np.ndarray, solver: IkSolver,
           local: IkOptions, rotation: np.ndarray | None = None,
           misses: list[float] | None = None) -> tuple[np.ndarray, pin.SE3 | None] | None:
    """``q`` with the wrist rolled toward ``pose`` and the point re-aimed at ``goal``, and
    the frame's pose there where it was computed (else None); None where the point cannot
    be re-aimed, its nearest miss (m) then appended to ``misses``. ``rotation``: the
    frame's orientation at ``q``, if known.

    The rounds stop at their fixed point: once the point is within the IK tolerance of
    ``goal`` after a roll, a re-aim would leave the state as it is, and so would the next
    roll (it depends on the other joints only)."""
    q = np.array(q, dtype=float)
    placed = bool(offset.any())  # a point away from the frame's origin
    for _ in range(FIXED_POINT_ROUNDS):
        if roll is not None:
            q = rolled(fk, roll, q, pose, solver.model, grasping, rotation)
            rotation = None  # known for the first state only
        if not placed:
            return q, None
        frame = fk(q)
        target = goal - frame.rotation @ offset
        miss = target - frame.translation
        if float(miss @ miss) <= local.tolerance**2:
            return q, frame
        try:
            q = solver.solve_near(target, seed_q=q, options=local)
        except IkFailedError as exc:
            if misses is not None:
                misses.append(math.sqrt(float(miss @ miss)) if exc.best_error is None
                              else exc.best_error)
            return None
    frame = fk(q)
    miss = np.linalg.norm(frame.translation + frame.rotation @ offset - goal)
    if miss < 1e-4:
        return q, frame
    if misses is not None:
        misses.append(float(miss))
    return None


def rolled(fk: Frames, roll: tuple[int, float], q: np.ndarray, pose: pin.SE3,
            model: RobotModel, grasping: bool, now: np.ndarray | None = None) -> np.ndarray:
    """``q`` with the wrist roll turned so the frame's y axis is nearest ``pose``'s (of the
    two closing senses, the one within the joint's limits and nearer the whole pose).

    The roll turns the frame about its own z axis without moving it (see
    :func:`wrist_roll`), so each candidate's orientation is the present one turned about z:
    no forward kinematics per candidate. Turns a whole revolution apart give one
    orientation; of those the first within the limits (the shortest turn) is kept.
    ``now``: the frame's orientation at ``q``, if known.
    """
    index, sense = roll
    if now is None:
        now = fk(q).rotation
    z, y = now[:, 2], now[:, 1]
    rotation = pose.rotation  # a copy, made once
    wanted = rotation[:, 1]
    want = wanted - (wanted @ z) * z
    if want @ want < 1e-12:
        return q
    # Python floats: the same IEEE arithmetic as numpy's scalars, without their overhead.
    (y0, y1, y2), (w0, w1, w2), (z0, z1, z2) = y.tolist(), want.tolist(), z.tolist()
    cross = (y1 * w2 - y2 * w1, y2 * w0 - y0 * w2, y0 * w1 - y1 * w0)
    turn = math.atan2(cross[0] * z0 + cross[1] * z1 + cross[2] * z2, float(y @ want))
    lower, upper = float(model.lower[index]), float(model.upper[index])
    at = float(q[index])
    best, best_error = q, math.inf
    errors: dict[int, float] = {}
    relative = rotation.T @ now  # the wanted orientation to the present one
    for extra in (0.0, math.pi, -math.pi, 2 * math.pi, -2 * math.pi):
        value = at + sense * (turn + extra)
        if not lower - LIMIT_TOLERANCE <= value <= upper + LIMIT_TOLERANCE:
            continue
        flipped = int(round(extra / math.pi)) % 2  # same orientation as extra = 0 or pi
        found = errors.get(flipped)
        if found is None:
            found = errors[flipped] = rotation_error(
                relative @ about_z(turn + math.pi * flipped), grasping)
        if found < best_error:
            best = q.copy()
            best[index] = min(max(value, lower), upper)
            best_error = found
    return best


def about_z(angle: float) -> np.ndarray:
    c, s = math.cos(angle), math.sin(angle)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def orientation_error(reached: pin.SE3, wanted: pin.SE3, grasping: bool = False) -> float:
    """How far ``reached``'s orientation is from ``wanted``'s (rad): the angle of the
    rotation between them; for a grasp, its turn about the wanted closing axis (y) counts
    for ``FREE_TURN_WEIGHT`` only."""
    return rotation_error(wanted.rotation.T @ reached.rotation, grasping)


def rotation_error(relative: np.ndarray, grasping: bool) -> float:
    """:func:`orientation_error` of the rotation ``wanted⁻¹ reached``."""
    turn = pin.log3(relative)
    if not grasping:
        return math.sqrt(turn.dot(turn))  # np.linalg.norm's own arithmetic
    return float(math.hypot(turn[0], turn[2]) + FREE_TURN_WEIGHT * abs(turn[1]))
