"""Options and results of inverse kinematics (see :mod:`taskrunner.kinematics.ik`)."""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from taskrunner.errors import ArgumentError
from taskrunner.types import JointState

__all__ = ["IkOptions", "IkSolution"]


def _check_positive(name: str, value: float | None, integer: bool = False) -> None:
    if value is None:
        return
    kind = "a positive integer" if integer else "a positive number"
    allowed = (int, np.integer) if integer else (int, float, np.integer, np.floating)
    if isinstance(value, bool) or not isinstance(value, allowed):
        raise ArgumentError(f"'{name}' must be {kind} (got {value!r})")
    if not math.isfinite(value) or value <= 0:
        raise ArgumentError(f"'{name}' must be {kind} (got {value!r})")


@dataclass(frozen=True)
class IkOptions:
    """How an IK call searches. None means "from the group's kinematics.yaml settings".

    Attributes:
        tolerance: largest accepted position error (m): the distance between the frame's
            origin and the target's. Also the rotation tolerance unless
            ``rotation_tolerance`` is given.
        rotation_tolerance: largest accepted rotation error (rad): the angle of the
            rotation from the frame's orientation to the target's. Position and rotation
            are checked separately, not as one norm. Default: ``tolerance``.
        max_iterations: Levenberg-Marquardt iterations per attempt (an attempt that stops
            making progress is abandoned earlier).
        timeout: an optional time limit of the whole call (s), on top of its attempts.
            None (the default): none; the call is bounded by its attempts and iterations
            alone, so the same request gives the same answer on an idle and on a busy
            machine. Given, it is counted in the searching thread's CPU time (a call is
            not cut short while its process waits for a CPU) and a call never runs
            longer than 4 × timeout of wall time; no attempt starts after it, and an
            attempt converging close to the target when it passes may finish (at most 5
            more iterations, ~0.1 ms). A time limit makes the answer depend on the
            machine's speed and load.
        attempts: starts allowed: the seed state, then up to 25 stored configurations
            whose frame pose is nearest the target, then random configurations. None:
            the group's kinematics.yaml budget (:func:`~taskrunner.kinematics.ik.
            default_attempts`: ``kinematics_solver_attempts``, at most one attempt per
            0.2 ms of ``kinematics_solver_timeout``; 10 when the group has no entry).
        seed: seed of the ``np.random.default_rng`` that draws the random restarts (the
            ones after the solver's stored configurations nearest the target); the same
            seed, seed state and target give the same solutions (unless a ``timeout``
            cuts the search).
        position_only: aim the frame's origin only (3 constraints; for arms with fewer
            than 6 joints). None: the group's ``position_only_ik`` setting, or True when
            the target is a bare position.
        num_solutions: how many distinct solutions :meth:`IkSolver.solve_all` looks for.
        min_distance: two solutions are distinct when the Euclidean distance between
            their joint vectors (rad or m; continuous joints compared modulo 2 pi) is at
            least this.
    """

    tolerance: float = 1e-5
    rotation_tolerance: float | None = None
    max_iterations: int = 100
    timeout: float | None = None
    attempts: int | None = None
    seed: int = 0
    position_only: bool | None = None
    num_solutions: int = 1
    min_distance: float = 0.1

    def __post_init__(self) -> None:
        _check_positive("tolerance", self.tolerance)
        _check_positive("rotation_tolerance", self.rotation_tolerance)
        _check_positive("max_iterations", self.max_iterations, integer=True)
        _check_positive("timeout", self.timeout)
        _check_positive("attempts", self.attempts, integer=True)
        _check_positive("num_solutions", self.num_solutions, integer=True)
        if isinstance(self.seed, bool) or not isinstance(self.seed, (int, np.integer)):
            raise ArgumentError(f"'seed' must be an integer (got {self.seed!r})")
        if self.position_only is not None and not isinstance(self.position_only, bool):
            raise ArgumentError(f"'position_only' must be True, False or None (got {self.position_only!r})")
        if not isinstance(self.min_distance, (int, float)) or not self.min_distance >= 0:
            raise ArgumentError(f"'min_distance' must be a number >= 0 (got {self.min_distance!r})")

    @property
    def rotation_tol(self) -> float:
        """The rotation tolerance in force (rad)."""
        return self.tolerance if self.rotation_tolerance is None else self.rotation_tolerance


@dataclass(frozen=True)
class IkSolution:
    """One IK solution, checked to be within the joint limits and the tolerances.

    Attributes:
        q: the full state vector (rad or m; read-only): the group's joints solved, mimic
            joints following them, every other joint as in the seed state.
        joint_state: the group's active joints at the solution, in the group's order.
        error: the residual: norm of the 6-D SE3 log error (m and rad mixed) for a full
            pose, the position error (m) when position-only.
        position_error: distance from the frame's origin to the target's (m).
        rotation_error: angle between the frame's and the target's orientation (rad);
            None when the search was position-only.
        attempts: starts used (1 = found from the seed state).
        iterations: Levenberg-Marquardt iterations over all attempts.
        elapsed: wall time of the call up to this solution (s).
        frame: the link or frame that was aimed.
    """

    q: np.ndarray
    joint_state: JointState
    error: float
    position_error: float
    rotation_error: float | None
    attempts: int
    iterations: int
    elapsed: float
    frame: str
