"""The search for a path with OMPL: the group's joints as a bounded real-vector space,
the planner's own state and edge checks, restarts of a stuck tree search, OMPL's
generators seeded per attempt.

References: Kuffner & LaValle, "RRT-Connect: An Efficient Approach to Single-Query Path
Planning", ICRA 2000; Şucan, Moll & Kavraki, "The Open Motion Planning Library", 2012.
"""

from __future__ import annotations

import time
from collections.abc import Callable

import numpy as np

from taskrunner.errors import PlanningCancelledError, PlanningTimeoutError
from taskrunner.planning.request import DEFAULT_RANGE, PlannerOptions
from taskrunner.robot import RobotModel
from taskrunner.robot.model import Group

__all__ = ["OPTIMIZING", "Checks", "import_ompl", "search_path"]

Checks = Callable[[set[bytes]], tuple[Callable[[np.ndarray], bool],
                                      Callable[[np.ndarray, np.ndarray], bool], list[int]]]
"""The state check, the edge check and their counter of states checked, given the group
values (``tobytes()``) of states known to be valid."""

_SINGLE_GOAL = {"PRM", "PRMstar"}
# Tree planners that stop at their first path: these restart (PlannerOptions.restart).
_RESTARTING = {"RRTConnect", "RRT", "KPIECE1", "BKPIECE1", "LBKPIECE1"}
OPTIMIZING = {"RRTstar", "InformedRRTstar", "SORRTstar", "PRMstar", "BITstar", "FMT", "BFMT"}


def import_ompl():  # type: ignore[no-untyped-def]
    """Import OMPL once, quietly (its import fails silently when broken: pitfall 7)."""
    from ompl import base as ob
    from ompl import geometric as og
    from ompl import util as ou

    ou.setLogLevel(ou.LogLevel.LOG_ERROR)
    return ob, og, ou


def search_path(model: RobotModel, group: Group, start: np.ndarray,
                goals: list[tuple[int, np.ndarray]], options: PlannerOptions,
                should_stop: Callable[[], bool] | None, deadline: float, checks: Checks
                ) -> tuple[np.ndarray, float, int]:
    """Search a path of ``group`` from ``start`` to one of ``goals`` (full states, with
    the index of their goal) with ``options.planner``, its attempts restarted as
    :attr:`PlannerOptions.restart` says, until ``deadline`` (``time.perf_counter()``).

    Args:
        checks: the state check, edge check and check counter over the group's values,
            given the states already found valid (see ``MotionPlanner._checks``).

    Returns:
        The path's waypoints (the group's values), the seconds OMPL searched and the
        states checked.

    Raises:
        PlanningCancelledError: ``should_stop`` said so.
        PlanningTimeoutError: no path within the attempts and the deadline.
    """
    ob, og, ou = import_ompl()
    idx = group.joint_indices
    if options.planner in _SINGLE_GOAL and len(goals) > 1:
        # PRM's goal-watching thread calls the (Python) validity checker while holding
        # its graph lock, and the search thread holds the GIL waiting for that lock:
        # with several goal states they deadlock. Give it the nearest goal only.
        goals = [min(goals, key=lambda g: float(np.linalg.norm(g[1][idx] - start[idx])))]
    n = len(idx)
    # States found valid during this search (start, goals, tree nodes): an edge ending
    # at one does not check it again.
    known = {np.ascontiguousarray(q[idx], dtype=float).tobytes()
             for q in [start] + [g for _, g in goals]}
    is_valid, edge_valid, count = checks(known)
    lower = model.lower[idx].copy()
    upper = model.upper[idx].copy()
    # Continuous joints: one turn around wherever the start and goals are.
    ends = np.vstack([start[idx]] + [g[idx] for _, g in goals])
    lower = np.where(np.isfinite(lower), lower, np.minimum(ends.min(axis=0), -np.pi))
    upper = np.where(np.isfinite(upper), upper, np.maximum(ends.max(axis=0), np.pi))

    space = ob.RealVectorStateSpace(n)
    bounds = ob.RealVectorBounds(n)
    for k in range(n):
        bounds.setLow(k, float(lower[k]))
        bounds.setHigh(k, float(upper[k]))
    space.setBounds(bounds)
    # OMPL wants a fraction in (0, 1): a gripper's few centimetres of travel are
    # shorter than one segment.
    space.setLongestValidSegmentFraction(
        min(0.5, options.longest_valid_segment / space.getMaximumExtent()))
    setup = og.SimpleSetup(space)
    values = np.empty(n)
    rng = range(n)

    def ompl_valid(state) -> bool:  # type: ignore[no-untyped-def]
        for k in rng:
            values[k] = state[k]
        return bool(is_valid(values))

    setup.setStateValidityChecker(ompl_valid)
    si = setup.getSpaceInformation()
    a_values = np.empty(n)
    b_values = np.empty(n)

    def ompl_edge(s1, s2) -> bool:  # type: ignore[no-untyped-def]
        for k in rng:
            a_values[k] = s1[k]
            b_values[k] = s2[k]
        return bool(edge_valid(a_values, b_values))

    validator = _edge_validator(ob)(si, ompl_edge)
    si.setMotionValidator(validator)
    start_state = space.allocState()
    for k in rng:
        start_state[k] = float(start[idx[k]])
    setup.setStartState(start_state)
    goal_states = []
    for _, q in goals:
        state = space.allocState()
        for k in rng:
            state[k] = float(q[idx[k]])
        goal_states.append(state)
    if len(goal_states) == 1:
        setup.setGoalState(goal_states[0])
    else:
        goal_set = ob.GoalStates(si)
        for state in goal_states:
            goal_set.addState(state)
        setup.setGoal(goal_set)
    if options.planner in OPTIMIZING:
        objective = ob.PathLengthOptimizationObjective(si)
        if not options.refine:
            objective.setCostThreshold(objective.infiniteCost())
        setup.setOptimizationObjective(objective)

    planning_time = 0.0
    cancelled = [False]

    def stop() -> bool:
        if should_stop is not None and should_stop():
            cancelled[0] = True
        return cancelled[0]

    restarts = options.restart > 0 and options.planner in _RESTARTING
    for attempt in range(options.attempts):
        attempt_end = min(time.perf_counter() + options.planning_time, deadline)
        run = 0
        while True:
            budget = attempt_end - time.perf_counter()
            if budget <= 0.0:
                break
            # A tree search that has not connected after its share of state checks
            # starts again from scratch, with twice the share each time: its run
            # times are heavy-tailed, and a fresh tree is often faster than a stuck
            # one. Counted in checks, not seconds, so the same seed gives the same
            # path whatever the machine's load.
            allowed = options.restart * 2**run if restarts else 0
            run_start = count[0]
            _seed_ompl(ou, options.seed + attempt + 7919 * run)
            planner = getattr(og, str(options.planner))(si)
            if hasattr(planner, "setRange"):
                planner.setRange(_range(group, options))
            setup.setPlanner(planner)
            setup.setup()
            ptc = ob.timedPlannerTerminationCondition(budget)
            if not (options.refine and options.planner in OPTIMIZING):
                ptc = ob.plannerOrTerminationCondition(
                    ptc, ob.exactSolnPlannerTerminationCondition(setup.getProblemDefinition()))
            if should_stop is not None:
                ptc = ob.plannerOrTerminationCondition(ptc, ob.PlannerTerminationCondition(stop))
            if allowed:
                ptc = ob.plannerOrTerminationCondition(ptc, ob.PlannerTerminationCondition(
                    lambda begun=run_start, limit=allowed: count[0] - begun >= limit))
            t0 = time.perf_counter()
            status = setup.solve(ptc)
            planning_time += time.perf_counter() - t0
            if cancelled[0]:
                raise PlanningCancelledError(f"planning for group {group.name!r} was cancelled")
            if setup.haveExactSolutionPath() and "EXACT" in status.asString().upper():
                path = setup.getSolutionPath()
                # Copy now: the path's states die with the next solve() or clear()
                # (pitfall 1).
                states = np.array([[path.getState(i)[k] for k in rng]
                                   for i in range(path.getStateCount())])
                return states, planning_time, count[0]
            setup.clear()
            if not (allowed and count[0] - run_start >= allowed):
                break  # out of time (or never restarting): the next attempt
            run += 1
    raise PlanningTimeoutError(
        f"no path for group {group.name!r} found by {options.planner} in "
        f"{options.attempts} attempt(s) of {options.planning_time:g} s")


_VALIDATOR: list[type] = []


def _edge_validator(ob) -> type:  # type: ignore[no-untyped-def]
    """An OMPL motion validator class that checks a whole edge with one Python call."""
    if not _VALIDATOR:
        class EdgeValidator(ob.MotionValidator):  # type: ignore[misc, name-defined]
            def __init__(self, si, check) -> None:  # type: ignore[no-untyped-def]
                super().__init__(si)
                self._check = check

            def checkMotion(self, s1, s2) -> bool:  # type: ignore[no-untyped-def]
                return bool(self._check(s1, s2))

        _VALIDATOR.append(EdgeValidator)
    return _VALIDATOR[0]


def _range(group: Group, options: PlannerOptions) -> float:
    """The tree growth step for ``options.planner`` (see :attr:`PlannerOptions.range`)."""
    if options.range > 0.0:
        return float(options.range)
    settings = group.planner
    if settings is not None and settings.range > 0.0 and settings.planner == options.planner:
        return settings.range
    return DEFAULT_RANGE


def _seed_ompl(ou, seed: int) -> None:  # type: ignore[no-untyped-def]
    """Reseed OMPL's generators (it logs an error when sampling has already started; the
    reseeding works regardless, so the message is silenced)."""
    level = ou.getLogLevel()
    ou.setLogLevel(ou.LogLevel.LOG_NONE)
    try:
        ou.RNG.setSeed(int(seed) % (2**31 - 1) + 1)
    finally:
        ou.setLogLevel(level)
