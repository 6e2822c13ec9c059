"""Inverse kinematics of a planning group: where to put its joints to reach a target.

:class:`IkSolver` aims one frame of a group (its tip link by default, or any link its
joints move) at a target pose, or at a target position only (arms with fewer than six
joints; automatic when the group's kinematics.yaml says ``position_only_ik``). It runs
attempts of damped least squares (:mod:`taskrunner.kinematics.damped_least_squares`):
the first from the seed state, the next from the stored configurations whose frame pose
is nearest the target (:class:`~taskrunner.kinematics.seed_table.SeedTable`), then from
random configurations within the limits (seeded ``np.random.default_rng``), until a
solution is found or the attempts are used up. The budget is a count, not a time, so that
the same request gives the same answer on an idle and on a busy machine: the attempts of
the call's options, else the group's kinematics.yaml budget (:func:`default_attempts`).
A time limit is an explicit option (``IkOptions.timeout``: the searching thread's CPU
time, capped at 4 × timeout of wall time; see :mod:`taskrunner.kinematics.deadline`).

Only the group's joints that move the aimed frame change; every other joint keeps its
value from the seed state, and mimic joints follow their source joints. A solution is
checked again from scratch before it is returned: within the joint limits (no margin),
position error ≤ tolerance (m) and rotation error ≤ rotation tolerance (rad).

The seed table is built by a solver's first restart (about 10 ms for 2000
configurations; that time is not counted against the call's timeout) or beforehand by
:meth:`IkSolver.seed_table`. A solver owns a private ``pin.Data``: use one solver per
thread.
"""

from __future__ import annotations

import math
import time
from collections.abc import Mapping
from typing import Any, TypeAlias

import numpy as np
import pinocchio as pin

from taskrunner.errors import IkFailedError, InputError
from taskrunner.kinematics.damped_least_squares import DampedLeastSquares
from taskrunner.kinematics.deadline import Deadline
from taskrunner.kinematics.ik_types import IkOptions, IkSolution
from taskrunner.kinematics.seed_table import SeedTable
from taskrunner.kinematics.solved_joints import SolvedJoints
from taskrunner.robot.model import Group, RobotModel
from taskrunner.robot.moveit_yaml import KinematicsSettings
from taskrunner.types import JointState, Pose

__all__ = ["ATTEMPT_SECONDS", "IkSolver", "IkTarget", "default_attempts", "is_reachable",
           "solve_ik"]

IkTarget: TypeAlias = pin.SE3 | Pose | np.ndarray
"""A world pose (SE3, 4x4 matrix, or :class:`Pose`), or a world position (3,) in m."""

ATTEMPT_SECONDS = 0.0002
"""The time one attempt stands for when a kinematics.yaml timeout is read as a budget of
attempts (s): a failing attempt of the Panda, the UR5, the Sawyer and the servo arm
takes 0.12-0.2 ms here (it stops when it no longer makes progress), a successful one
less. ``kinematics_solver_timeout: 0.005`` is thus 25 attempts."""
NEAREST_SEEDS = 25  # restarts from the seed table before random ones (6: 10-15 % more
# iterations on the hardest 1 % of Panda and UR5 targets; beyond 25 no better)
TABLE_SIZE = 2000  # configurations in the seed table (~10 ms to build)
TABLE_SEED = 20_111_986  # any fixed value; not 0, which callers use for their own draws


class IkSolver:
    """IK for one frame of one group; build once, call :meth:`solve` many times.

    Args:
        model: the robot model.
        group: the planning group (object or name) whose joints may move.
        frame: the link or frame to aim; default the group's ``tip_link``. Any frame
            moved by at least one of the group's joints is accepted.
        options: default options of every call (a call may pass its own).

    Attributes:
        frame: the aimed frame.
        joint_names: the group's joints that move it: the ones a search changes.
        settings: the group's kinematics.yaml settings (defaults when it has none).

    Raises:
        UnknownNameError: unknown group or frame.
        InputError: the group has no tip link and no frame was given, or no joint of the
            group moves the frame.
    """

    def __init__(self, model: RobotModel, group: Group | str, frame: str | None = None,
                 options: IkOptions | None = None):
        self.model = model
        self.group = model.group(group) if isinstance(group, str) else group
        if frame is None:
            if self.group.tip_link is None:
                raise InputError(
                    f"'frame' must be given for group {self.group.name!r}, which has no tip link"
                )
            frame = self.group.tip_link
        self.frame = frame
        self.options = options or IkOptions()
        self.settings = self.group.kinematics or KinematicsSettings()
        self._pin_model = model.model
        self._data = model.model.createData()
        self._frame_id = model.frame_id(frame)
        self._joints = SolvedJoints(model, self.group, self._frame_id)
        self.joint_names = self._joints.names
        self._descent = DampedLeastSquares(self._pin_model, self._data, self._frame_id,
                                           self._joints)
        self._group_indices = np.asarray(self.group.joint_indices, dtype=int)
        # solve_near skips the re-check where the solved joints are the state vector's
        # own slice (no followers to move) and none is continuous (no whole turns).
        self._exact_descent = self._joints.direct and not self._joints.has_continuous
        self._table: SeedTable | None = None
        self._generators: dict[int, tuple[np.random.Generator, Mapping[str, Any]]] = {}

    # ------------------------------------------------------------------ public API
    def solve(self, target: IkTarget, seed_q: np.ndarray | None = None,
              options: IkOptions | None = None) -> IkSolution:
        """One solution for ``target``.

        Args:
            target: world pose (SE3, 4x4 matrix, or :class:`Pose` in ``"world"`` or in a
                link's frame, that link taken at the seed state) or world position (3,), m.
            seed_q: state vector the search starts from and that the other joints keep;
                default: the model's default state with the solved joints at mid-range.
            options: this call's options (default: the solver's).

        Raises:
            IkFailedError: no solution within the limits and tolerances was found.
            InputError: a malformed target or seed.
            UnknownNameError: a :class:`Pose` in an unknown frame.
        """
        return self._search(target, seed_q, options or self.options, 1)[0]

    def solve_near(self, target: IkTarget, seed_q: np.ndarray | None = None,
                   options: IkOptions | None = None) -> np.ndarray:
        """The state vector of one solution found from ``seed_q`` alone: a local solve.

        The same state as ``solve(target, seed_q, options).q`` with ``options.attempts``
        taken as 1 (the seed state is the only start, whatever the options say), returned
        as a new writable array, without the :class:`IkSolution` around it: for callers
        that solve many nearby targets in a row (a line followed point by point). Targets,
        seeds, options, the checks of a solution and the errors are those of
        :meth:`solve`.

        Raises:
            IkFailedError: the attempt from the seed state found no solution within the
                limits and tolerances.
            InputError: a malformed target or seed.
            UnknownNameError: a :class:`Pose` in an unknown frame.
        """
        start = time.perf_counter()
        options = options or self.options
        deadline = Deadline.never() if options.timeout is None else Deadline(options.timeout)
        joints = self._joints
        q = self.seed_state(seed_q)
        position_only, se3, position = self._target(target, q, options.position_only)
        tol2 = options.tolerance**2
        # Without followers or continuous joints, a converged descent's state needs no
        # re-check: it is within the limits (the descent starts clipped and clips every
        # step) and its convergence test is the check's own, made on the forward
        # kinematics of this very state.
        q_seed = None if self._exact_descent else q.copy()
        qa = joints.values(q)
        if position_only:
            ok, used, residual = self._descent.descend_position(
                q, qa, position, deadline, options.max_iterations, tol2)
        else:
            ok, used, residual = self._descent.descend_pose(
                q, qa, se3, deadline, options.max_iterations, tol2, options.rotation_tol**2)
        if ok:
            if q_seed is None:
                return q
            solution = self._checked(q, qa, q_seed, se3, position, position_only, options)
            if solution is not None:
                return solution[0]
        raise self._failure(se3, position, position_only, math.sqrt(residual), 1, used,
                            time.perf_counter() - start, options)

    def solve_all(self, target: IkTarget, seed_q: np.ndarray | None = None,
                  options: IkOptions | None = None) -> list[IkSolution]:
        """Up to ``options.num_solutions`` distinct solutions, in the order found.

        Solutions are distinct by ``options.min_distance`` in joint space; after each one
        the search restarts from random configurations. It ends early when the attempts
        or the timeout run out, returning what it found.

        Raises:
            IkFailedError: not even one solution was found.
        """
        options = options or self.options
        return self._search(target, seed_q, options, options.num_solutions)

    def seed_state(self, seed_q: np.ndarray | None = None) -> np.ndarray:
        """The state a search starts from (a copy): ``seed_q`` with the solved joints
        clipped into their limits and mimic joints following, or the default seed."""
        joints = self._joints
        if seed_q is None:
            return joints.default_seed.copy()
        q = np.array(seed_q, dtype=float)
        if q.shape != (self.model.nq,):
            raise InputError(
                f"'seed_q' must be a state vector of shape ({self.model.nq},) (got {q.shape})"
            )
        if not math.isfinite(np.dot(q, q)):
            raise InputError(f"'seed_q' must be finite (got {q})")
        values = joints.values(q)
        np.minimum(values, joints.upper, out=values)
        np.maximum(values, joints.lower, out=values)
        if not joints.direct:
            q[joints.indices] = values
        return joints.apply_mimic(q)

    def seed_table(self) -> SeedTable | None:
        """The restart seeds (built on first use, ~10 ms), or None when joints outside
        the solved ones move the frame (the stored poses would not hold)."""
        joints = self._joints
        if self._table is None and joints.only_movers:
            rng = np.random.default_rng(TABLE_SEED)
            samples = joints.sample_lower + joints.sample_span * rng.random(
                (TABLE_SIZE, len(joints)))
            q = joints.default_seed.copy()

            def frame_pose_of(values: np.ndarray) -> pin.SE3:
                pin.forwardKinematics(self._pin_model, self._data, joints.sync(q, values))
                return pin.updateFramePlacement(self._pin_model, self._data, self._frame_id)

            self._table = SeedTable(samples, frame_pose_of)
        return self._table

    # ------------------------------------------------------------------ search
    def _search(self, target: IkTarget, seed_q: np.ndarray | None, options: IkOptions,
                wanted: int) -> list[IkSolution]:
        start = time.perf_counter()
        attempts = (options.attempts if options.attempts is not None
                    else default_attempts(self.settings))
        deadline = Deadline.never() if options.timeout is None else Deadline(options.timeout)
        joints, descent = self._joints, self._descent
        q_seed = self.seed_state(seed_q)
        position_only, se3, position = self._target(target, q_seed, options.position_only)
        tol2, rtol2 = options.tolerance**2, options.rotation_tol**2
        q = q_seed.copy()
        qa = joints.values(q)
        nearest: np.ndarray | None = None
        rng: np.random.Generator | None = None
        solutions: list[IkSolution] = []
        found: list[np.ndarray] = []  # their solved joints' values
        iterations, attempt, best = 0, 0, math.inf
        for attempt in range(1, attempts + 1):
            if attempt > 1:
                if not solutions and nearest is None:
                    if self._table is None and joints.only_movers:
                        # Built once per solver; not counted against the call's timeout.
                        built, built_cpu = time.perf_counter(), time.thread_time()
                        self.seed_table()
                        deadline.exclude(time.perf_counter() - built,
                                         time.thread_time() - built_cpu)
                    nearest = self._nearest_seeds(se3, position, position_only)
                if not solutions and nearest is not None and attempt - 2 < len(nearest):
                    qa[:] = nearest[attempt - 2]
                else:
                    if rng is None:
                        rng = self._rng(options.seed)
                    np.multiply(rng.random(len(qa)), joints.sample_span, out=qa)
                    qa += joints.sample_lower
            if position_only:
                ok, used, residual = descent.descend_position(
                    q, qa, position, deadline, options.max_iterations, tol2)
            else:
                ok, used, residual = descent.descend_pose(
                    q, qa, se3, deadline, options.max_iterations, tol2, rtol2)
            iterations += used
            best = min(best, residual)
            if ok:
                solution = self._checked(q, qa, q_seed, se3, position, position_only, options)
                values = None if solution is None else solution[0][joints.indices]
                if solution is not None and values is not None and all(
                    joints.distance(values, other) >= options.min_distance for other in found
                ):
                    found.append(values)
                    q_out, error, position_error, rotation_error = solution
                    q_out.setflags(write=False)
                    solutions.append(IkSolution(
                        q=q_out,
                        joint_state=JointState(self.group.joint_names, q_out[self._group_indices]),
                        error=error,
                        position_error=position_error,
                        rotation_error=rotation_error,
                        attempts=attempt,
                        iterations=iterations,
                        elapsed=time.perf_counter() - start,
                        frame=self.frame,
                    ))
                    if len(solutions) >= wanted:
                        break
            if time.perf_counter() > deadline.wall and deadline.passed():
                break
        if not solutions:
            raise self._failure(se3, position, position_only, math.sqrt(best), attempt,
                                iterations, time.perf_counter() - start, options)
        return solutions

    def _target(self, target: IkTarget, q_seed: np.ndarray, position_only: bool | None
                ) -> tuple[bool, pin.SE3 | None, np.ndarray]:
        """``(position only?, world pose or None, world position)`` of a target."""
        if isinstance(target, pin.SE3):
            se3 = target
        elif isinstance(target, Pose):
            se3 = target.se3
            if target.frame != "world":
                frame_id = self.model.frame_id(target.frame)
                pin.forwardKinematics(self._pin_model, self._data, self.model.to_pin(q_seed))
                se3 = pin.updateFramePlacement(self._pin_model, self._data, frame_id) * se3
        else:
            array = np.asarray(target, dtype=float)
            if array.shape == (3,):
                if position_only is False:
                    raise InputError(
                        "'target' must be a pose when position_only is False (got a position)"
                    )
                if not math.isfinite(np.dot(array, array)):
                    raise InputError(f"'target' must be finite (got {array})")
                return True, None, array.copy()
            if array.shape != (4, 4):
                raise InputError(
                    "'target' must be an SE3, a Pose, a 4x4 matrix or a position (3,) "
                    f"(got an array of shape {array.shape})"
                )
            se3 = pin.SE3(array)
        matrix = se3.homogeneous.reshape(-1)
        if not math.isfinite(np.dot(matrix, matrix)):
            raise InputError(f"'target' must be finite (got {se3})")
        _check_rotation(se3.rotation)
        if position_only is None:
            position_only = self.group.position_only_ik
        return position_only, se3, se3.translation.copy()

    def _nearest_seeds(self, se3: pin.SE3 | None, position: np.ndarray,
                       position_only: bool) -> np.ndarray:
        """Restart values from the seed table, nearest the target first (none without
        a table)."""
        table = self.seed_table()
        if table is None or NEAREST_SEEDS == 0:
            return np.empty((0, len(self._joints)))
        if position_only or se3 is None:
            return table.samples[table.nearest_to_position(position, NEAREST_SEEDS)]
        return table.samples[table.nearest_to_pose(se3, NEAREST_SEEDS)]

    def _rng(self, seed: int) -> np.random.Generator:
        """A generator in the state of ``np.random.default_rng(seed)``, reused between
        calls (building one costs more than an IK iteration)."""
        cached = self._generators.get(seed)
        if cached is None:
            generator = np.random.default_rng(seed)
            self._generators[seed] = (generator, generator.bit_generator.state)
            return generator
        generator, state = cached
        generator.bit_generator.state = state
        return generator

    def _checked(self, q: np.ndarray, qa: np.ndarray, q_seed: np.ndarray, se3: pin.SE3 | None,
                 position: np.ndarray, position_only: bool, options: IkOptions
                 ) -> tuple[np.ndarray, float, float, float | None] | None:
        """Check a converged state from scratch: ``(q, error, position error, rotation
        error)``, or None when it is outside the limits or the tolerances."""
        joints = self._joints
        out = q.copy()
        if joints.has_continuous or not joints.direct:
            out[joints.indices] = joints.wrap_near(qa, q_seed[joints.indices])
            joints.apply_mimic(out)
        if not joints.within_limits(out):
            return None
        pin_q = out if joints.identity_q else self.model.to_pin(out)
        pin.forwardKinematics(self._pin_model, self._data, pin_q)
        pose = pin.updateFramePlacement(self._pin_model, self._data, self._frame_id)
        if position_only or se3 is None:
            d = position - pose.translation
            position_error = math.sqrt(np.dot(d, d))
            if position_error > options.tolerance:
                return None
            return out, position_error, position_error, None
        iMd = pose.actInv(se3)
        t = iMd.translation
        err = pin.log6(iMd).vector
        w = err[3:]
        position_error, rotation_error = math.sqrt(np.dot(t, t)), math.sqrt(np.dot(w, w))
        if position_error > options.tolerance or rotation_error > options.rotation_tol:
            return None
        return out, math.sqrt(np.dot(err, err)), position_error, rotation_error

    def _failure(self, se3: pin.SE3 | None, position: np.ndarray, position_only: bool,
                 residual: float, attempts: int, iterations: int, elapsed: float,
                 options: IkOptions) -> IkFailedError:
        xyz = ", ".join(f"{v:.4f}" for v in position)
        if position_only or se3 is None:
            what = f"position ({xyz})"
            unit = f"m; tolerance {options.tolerance:g} m"
        else:
            quat = pin.Quaternion(se3.rotation)
            what = (f"pose xyz=({xyz}) "
                    f"quat_xyzw=({quat.x:.4f}, {quat.y:.4f}, {quat.z:.4f}, {quat.w:.4f})")
            unit = (f"norm of the SE3 log error, m and rad; tolerance {options.tolerance:g} m "
                    f"and {options.rotation_tol:g} rad")
        return IkFailedError(
            f"no IK solution for group {self.group.name!r}, frame {self.frame!r}, "
            f"target {what}: best residual {residual:.4g} ({unit}) after {attempts} "
            f"attempt(s), {iterations} iterations, {elapsed * 1e3:.1f} ms",
            best_error=residual,
        )


ROTATION_TOLERANCE = 1e-6
"""How far (Frobenius norm of ``RᵀR - I``) a target's rotation part may be from
orthonormal: a matrix that is not a rotation (scaled, sheared, a reflection) has no
SE3 log error, and the descent's residual would be meaningless (inf or nan)."""


def _check_rotation(rotation: np.ndarray) -> None:
    """Raise InputError unless ``rotation`` is a proper rotation (orthonormal, det +1)."""
    (a, b, c), (d, e, f), (g, h, i) = rotation.tolist()
    # RᵀR - I, entry by entry (Python floats: cheaper than numpy's calls on a 3x3).
    off = ((a * a + d * d + g * g - 1.0) ** 2 + (b * b + e * e + h * h - 1.0) ** 2
           + (c * c + f * f + i * i - 1.0) ** 2
           + 2.0 * ((a * b + d * e + g * h) ** 2 + (a * c + d * f + g * i) ** 2
                    + (b * c + e * f + h * i) ** 2))
    det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    if off > ROTATION_TOLERANCE**2 or det <= 0.0:
        raise InputError(
            "'target' must be a pose whose rotation is a proper rotation matrix "
            f"(orthonormal, determinant +1; got one {math.sqrt(off):.3g} from orthonormal, "
            f"determinant {det:.3g})")


def default_attempts(settings: KinematicsSettings) -> int:
    """The attempts of a call whose options give none, from a group's kinematics.yaml:
    ``kinematics_solver_attempts``, but no more than ``kinematics_solver_timeout`` stands
    for at :data:`ATTEMPT_SECONDS` an attempt (MoveIt's solvers restart until the timeout
    passes; counting the attempts instead gives the same answer on every machine). The
    defaults (0.005 s, 10 attempts) give 10."""
    return max(1, min(settings.attempts, math.ceil(settings.timeout / ATTEMPT_SECONDS - 1e-9)))


def solve_ik(model: RobotModel, group: Group | str, target: IkTarget, frame: str | None = None,
             seed_q: np.ndarray | None = None, options: IkOptions | None = None) -> IkSolution:
    """One IK solution (see :class:`IkSolver`; build a solver to call it repeatedly).

    Raises:
        IkFailedError: the target is unreachable within the limits and tolerances.
    """
    return IkSolver(model, group, frame, options).solve(target, seed_q)


def is_reachable(model: RobotModel, group: Group | str, target: IkTarget,
                 frame: str | None = None, seed_q: np.ndarray | None = None,
                 options: IkOptions | None = None) -> bool:
    """Whether :func:`solve_ik` finds a solution (within its attempts and timeout)."""
    try:
        solve_ik(model, group, target, frame, seed_q, options)
    except IkFailedError:
        return False
    return True
