"""The goal states a goal offers: what the planner searches towards and what
``run-task check`` checks (one implementation for both).

A joint or named goal is one state (the start with the group's goal values); a pose goal
is up to ``PlannerOptions.goal_samples`` distinct IK solutions, seeded from the start.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import replace

import numpy as np
import pinocchio as pin

from taskrunner.errors import IkFailedError, InvalidStateError
from taskrunner.kinematics import IkOptions, IkSolver
from taskrunner.planning.request import Goal, JointGoal, NamedGoal, PlannerOptions, PoseGoal
from taskrunner.robot.model import Group
from taskrunner.scene import Scene

__all__ = ["goal_states", "pose_goal_states"]


def goal_states(goal: Goal, group: Group, start: np.ndarray, options: PlannerOptions,
                scene: Scene, solver: Callable[[Group, str | None], IkSolver]
                ) -> list[np.ndarray]:
    """The full state vectors ``goal`` offers ``group`` from ``start`` (limits and
    collisions not checked).

    Args:
        goal: a joint, named or pose goal.
        group: the planned group of ``scene.robot``.
        start: the full start state; a pose in a link's or an object's frame is taken
            there, and IK is seeded from it.
        options: the request's options (``seed``, ``goal_samples``).
        scene: the scene the goal is in (its robot, and its frames for a pose).
        solver: the IK solver of a group for a frame (None: the group's tip), kept by the
            caller between goals.

    Raises:
        UnknownNameError: a joint or named pose that does not exist.
        InvalidStateError: joints that are not active joints of the group.
        IkFailedError: a pose goal without a solution.
    """
    model = scene.robot
    if isinstance(goal, JointGoal | NamedGoal):
        values = (goal.values if isinstance(goal, JointGoal)
                  else model.named_state(group.name, goal.name).as_dict())
        outside = [n for n in values if n not in group.joint_names]
        if outside:
            for name in outside:
                model.joint(name)  # UnknownNameError for a joint that does not exist
            raise InvalidStateError(f"joints {outside} are not active joints of group "
                                    f"{group.name!r} ({', '.join(group.joint_names)})")
        return [model.state_with(start, values)]
    if isinstance(goal, PoseGoal):
        # A pose in a link's or an object's frame is taken at the start state.
        target = scene.to_world(goal.pose, start)
        return pose_goal_states(solver(group, goal.link), group, goal, target, start, options)
    raise TypeError(f"unsupported goal type {type(goal).__name__}")


def pose_goal_states(solver: IkSolver, group: Group, goal: PoseGoal, target: pin.SE3,
                     start: np.ndarray, options: PlannerOptions) -> list[np.ndarray]:
    """The goal states a pose goal offers the planner: up to ``options.goal_samples``
    distinct IK solutions of ``target`` (world) for ``solver``'s frame, from ``start``.

    Raises:
        IkFailedError: no solution.
    """
    settings = group.kinematics
    ik_options = IkOptions(
        tolerance=goal.tolerance, seed=options.seed, position_only=goal.position_only,
        num_solutions=options.goal_samples,
        # Several distinct solutions need more restarts than one does. A budget of
        # attempts, no time: the same goal states on an idle and on a busy machine.
        attempts=max(settings.attempts if settings else 0, 20 * options.goal_samples),
    )
    if goal.position_only is False and group.position_only_ik:
        return _full_pose_on_short_arm(solver, target, start, ik_options)
    return [s.q for s in solver.solve_all(target, seed_q=start, options=ik_options)]


def _full_pose_on_short_arm(solver: IkSolver, target: pin.SE3, start: np.ndarray,
                            options: IkOptions) -> list[np.ndarray]:
    """Full-pose IK for an arm with fewer than six joints (position-only by default).

    The poses such an arm reaches form a thin set that random restarts rarely land
    on; solving the position first and then the whole pose from there, locally, does.
    """
    positions = solver.solve_all(target.translation, seed_q=start, options=replace(
        options, position_only=True, num_solutions=4 * options.num_solutions))
    found: list[np.ndarray] = []
    best: IkFailedError | None = None
    for candidate in positions:
        try:
            full = solver.solve(target, seed_q=candidate.q, options=replace(
                options, position_only=False, attempts=1, num_solutions=1))
        except IkFailedError as exc:
            best = exc if best is None or (exc.best_error or 0) < (best.best_error or 0) \
                else best
            continue
        if all(np.max(np.abs(full.q - q)) > options.min_distance for q in found):
            found.append(full.q)
        if len(found) >= options.num_solutions:
            break
    if not found:
        assert best is not None
        raise best
    return found
