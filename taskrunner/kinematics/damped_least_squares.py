"""Levenberg-Marquardt descent of one IK attempt, within joint limits.

Errors and Jacobians:

* full pose: ``e = log6(world_T_frame⁻¹ · world_T_target)`` (6-D, in the frame), with
  Jacobian ``Jlog6(iMd⁻¹) · J_local`` (STACK-NOTES 9; its two minus signs cancel).
  ``Jlog6`` is applied while ``‖e‖² > 1e-2`` only: below, it is the identity to within
  ‖e‖, and skipping it saves three calls per iteration at no measured cost;
* position only: ``e = p_target - p_frame`` (world axes), with the linear rows of the
  world-aligned Jacobian.

Step: ``dq = Jᵀ (J Jᵀ + λ I)⁻¹ e``, a 6x6 (or 3x3) Cholesky solve, with Sugihara's
damping (T. Sugihara, "Solvability-unconcerned inverse kinematics by the
Levenberg-Marquardt method", IEEE T-RO 27(5), 2011): ``λ = c·‖e‖² + w̄``, large far from
the target and vanishing near it, so the last iterations are Gauss-Newton steps and
converge quadratically. Steps are capped to 1.5 rad (or m) in norm. A step that would
cross a joint limit is solved again with those joints held exactly at the limit (their
columns removed, their move to the limit subtracted from ``e``), then clipped: the
attempt slides along the limits instead of sticking to them (35 % fewer iterations on
the Panda than clipping alone). Continuous joints are unbounded.

An attempt ends as soon as it stops making progress (``‖e‖²`` not below 0.8 × its best
for 3 iterations): restarting elsewhere is cheaper than crawling out of a local minimum.
It also ends when the call's time budget (:class:`~taskrunner.kinematics.deadline.Deadline`)
is used up, unless it is converging close to the target then (it progressed in this
iteration and ``‖e‖² ≤ 1e-2``, where convergence is quadratic): such an attempt may run
up to 5 more iterations (~0.1 ms) rather than be thrown away a few iterations from a
solution.

Every numpy or pinocchio call costs about a microsecond from Python, far more than the
arithmetic on these small matrices, so the loops below are written for few calls.
"""

from __future__ import annotations

import math
import time

import numpy as np
import pinocchio as pin
from numpy._core import umath
from scipy.linalg import lapack

from taskrunner.kinematics.deadline import Deadline
from taskrunner.kinematics.solved_joints import SolvedJoints

__all__ = ["DampedLeastSquares"]

# Tuned on the Panda, the UR5 and the servo arm (benchmarks/ik_bench.py).
DAMPING_GAIN = 0.02  # c in λ = c·‖e‖² + w̄
DAMPING_FLOOR = 1e-7  # w̄
MAX_STEP = 1.5  # rad (or m): norm cap of one step (1.0: 5 % more iterations, 2.0: no better)
JLOG_MIN = 1e-2  # ‖e‖² above which Jlog6 is applied
PROGRESS = 0.8  # an iteration progresses when it brings ‖e‖² below 0.8 × the best so far
STALL = 3  # iterations without progress before an attempt is abandoned
GRACE = 5  # iterations an attempt converging near the target may run past the deadline
_REDAMP = 1e-3  # added to λ when J Jᵀ + λ I is not numerically positive definite

_posv = lapack.dposv
_dot = np.dot
_clip = umath.clip  # type: ignore[attr-defined]  # the ufunc np.clip wraps: one call, NaN kept
_log6 = pin.log6
_jlog6 = pin.Jlog6
_compute_joint_jacobians = pin.computeJointJacobians
_update_frame_placement = pin.updateFramePlacement
_get_frame_jacobian = pin.getFrameJacobian
_LOCAL = pin.LOCAL
_LOCAL_WORLD_ALIGNED = pin.LOCAL_WORLD_ALIGNED


class DampedLeastSquares:
    """Descends one attempt from a state; holds the preallocated work arrays.

    Args:
        model: the pinocchio model.
        data: a pinocchio data of it, owned by the caller and used by nobody else.
        frame_id: the aimed frame.
        joints: the joints that move.
    """

    def __init__(self, model: pin.Model, data: pin.Data, frame_id: int, joints: SolvedJoints):
        self._model = model
        self._data = data
        self._frame_id = frame_id
        self._joints = joints
        self._lower = joints.lower
        self._upper = joints.upper
        self._A6 = np.empty((6, 6))
        self._A3 = np.empty((3, 3))
        self._diagonal6 = self._A6.reshape(-1)[::7]  # views of the diagonals
        self._diagonal3 = self._A3.reshape(-1)[::4]

    def descend_pose(self, q: np.ndarray, qa: np.ndarray, target: pin.SE3, deadline: Deadline,
                     iterations: int, tol2: float, rtol2: float) -> tuple[bool, int, float]:
        """Move ``qa`` (the solved joints' values; a view into ``q`` when the joints are
        ``direct``) towards a full pose.

        Args:
            q: the state vector (the other joints' values).
            qa: the solved joints' values, updated in place.
            target: world pose of the frame to reach.
            deadline: the call's time budget.
            iterations: iterations allowed.
            tol2, rtol2: squared position (m²) and rotation (rad²) tolerances.

        Returns:
            ``(converged, iterations used, lowest ‖e‖² seen)``.
        """
        model, data, frame_id = self._model, self._data, self._frame_id
        joints = self._joints
        direct, columns, mimic = joints.direct, joints.columns, bool(joints.mimic_columns)
        qp = q if direct else joints.sync(q, qa)
        near = 4.0 * max(tol2, rtol2)
        best = lowest = math.inf
        stalled = late = 0
        perf_counter = time.perf_counter
        for it in range(1, iterations + 1):
            _compute_joint_jacobians(model, data, qp)
            iMd = _update_frame_placement(model, data, frame_id).actInv(target)
            err = _log6(iMd).vector
            e2 = _dot(err, err)
            if e2 < near:
                t, w = iMd.translation, err[3:]
                if _dot(t, t) <= tol2 and _dot(w, w) <= rtol2:
                    return True, it, e2
            if e2 < lowest:
                lowest = e2
            if e2 < best * PROGRESS:
                best, stalled = e2, 0
            else:
                stalled += 1
                if stalled >= STALL:
                    return False, it, lowest
            if perf_counter() > deadline.wall and deadline.passed():
                if stalled or e2 > JLOG_MIN or late >= GRACE:
                    return False, it, lowest
                late += 1
            if mimic:
                J = self._jacobian(_LOCAL)
            else:
                J = _get_frame_jacobian(model, data, frame_id, _LOCAL)[:, columns]
            if e2 > JLOG_MIN:
                J = _dot(_jlog6(iMd.inverse()), J)
            self._step(J, err, e2, qa, self._A6, self._diagonal6)
            if not direct:
                qp = joints.sync(q, qa)
        return False, iterations, lowest

    def descend_position(self, q: np.ndarray, qa: np.ndarray, target: np.ndarray,
                         deadline: Deadline, iterations: int, tol2: float
                         ) -> tuple[bool, int, float]:
        """Like :meth:`descend_pose` for a world position (m) of the frame's origin."""
        model, data, frame_id = self._model, self._data, self._frame_id
        joints = self._joints
        direct, columns, mimic = joints.direct, joints.columns, bool(joints.mimic_columns)
        qp = q if direct else joints.sync(q, qa)
        best = lowest = math.inf
        stalled = late = 0
        perf_counter = time.perf_counter
        for it in range(1, iterations + 1):
            _compute_joint_jacobians(model, data, qp)
            err = target - _update_frame_placement(model, data, frame_id).translation
            e2 = _dot(err, err)
            if e2 <= tol2:
                return True, it, e2
            if e2 < lowest:
                lowest = e2
            if e2 < best * PROGRESS:
                best, stalled = e2, 0
            else:
                stalled += 1
                if stalled >= STALL:
                    return False, it, lowest
            if perf_counter() > deadline.wall and deadline.passed():
                if stalled or e2 > JLOG_MIN or late >= GRACE:
                    return False, it, lowest
                late += 1
            if mimic:
                J = self._jacobian(_LOCAL_WORLD_ALIGNED)[:3]
            else:
                J = _get_frame_jacobian(model, data, frame_id, _LOCAL_WORLD_ALIGNED)[:3, columns]
            self._step(J, err, e2, qa, self._A3, self._diagonal3)
            if not direct:
                qp = joints.sync(q, qa)
        return False, iterations, lowest

    def _jacobian(self, reference: pin.ReferenceFrame) -> np.ndarray:
        """The solved joints' columns, followers' motion added to their sources'."""
        full = _get_frame_jacobian(self._model, self._data, self._frame_id, reference)
        J = full[:, self._joints.columns]
        for k, column, multiplier in self._joints.mimic_columns:
            J[:, k] += multiplier * full[:, column]
        return J

    def _step(self, J: np.ndarray, err: np.ndarray, e2: float, qa: np.ndarray,
              A: np.ndarray, diagonal: np.ndarray) -> None:
        """One damped least-squares step of ``qa`` (in place), joint limits respected.

        ``A`` is the work matrix and ``diagonal`` a view of its diagonal.
        """
        damping = DAMPING_GAIN * e2 + DAMPING_FLOOR
        _dot(J, J.T, out=A)
        diagonal += damping
        _, y, info = _posv(A, err)
        if info:
            diagonal += _REDAMP
            _, y, _ = _posv(A, err)
        new = _dot(y, J)
        norm2 = _dot(new, new)
        if norm2 > MAX_STEP * MAX_STEP:
            new *= MAX_STEP / math.sqrt(norm2)
        new += qa
        lower, upper = self._lower, self._upper
        clipped = _clip(new, lower, upper)
        new -= clipped  # the overshoot past the limits: zero for joints within them
        if _dot(new, new) == 0.0:  # cheaper than a mask and .any()
            qa[:] = clipped
            return
        # Hold the joints that would cross a limit at it; let the others make up.
        over = new != 0.0
        clipped -= qa
        to_limit = clipped * over
        free = J * (new == 0.0)
        rest = err - _dot(J, to_limit)
        _dot(free, free.T, out=A)
        diagonal += damping
        _, y, info = _posv(A, rest)
        if info:
            diagonal += _REDAMP
            _, y, _ = _posv(A, rest)
        new = _dot(y, free)
        norm2 = _dot(new, new)
        if norm2 > MAX_STEP * MAX_STEP:
            new *= MAX_STEP / math.sqrt(norm2)
        new += to_limit
        new += qa
        _clip(new, lower, upper, out=qa)
