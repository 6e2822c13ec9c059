"""What a motion plan is asked for, and what it answers.

A :class:`PlanRequest` names a group, an optional start state, one goal or several (any of
them will do) and :class:`PlannerOptions`. Goals are joint values, a named pose, or a pose
of a link (full pose, or position only) that the planner turns into a set of goal states
by sampling inverse kinematics.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, field

import numpy as np

from taskrunner.errors import ArgumentError
from taskrunner.planning.timing import TimingOptions
from taskrunner.robot.model import Group
from taskrunner.robot.moveit_yaml import OMPL_PLANNERS
from taskrunner.scene.collision import VERIFY_MARGIN
from taskrunner.types import JointPath, JointTrajectory, Pose

__all__ = [
    "Goal",
    "JointGoal",
    "NamedGoal",
    "PlanRequest",
    "PlanResult",
    "PlannerOptions",
    "PoseGoal",
    "group_planner",
]


@dataclass(frozen=True)
class JointGoal:
    """Joint values (rad or m). Joints of the group left out keep their start value."""

    values: Mapping[str, float]

    def __post_init__(self) -> None:
        if not self.values:
            raise ArgumentError("'values' must name at least one joint")
        object.__setattr__(self, "values", {str(k): float(v) for k, v in self.values.items()})


@dataclass(frozen=True)
class NamedGoal:
    """A named pose of the group (SRDF ``group_state`` or a cell pose)."""

    name: str


@dataclass(frozen=True)
class PoseGoal:
    """A pose of ``link`` (default: the group's tip), in the world frame or in the frame
    of a link or a scene object (taken at the start state).

    Attributes:
        position_only: aim the link's origin only; None follows the group's
            ``position_only_ik`` setting.
        tolerance: IK tolerance (m, and rad for the orientation).
    """

    pose: Pose
    link: str | None = None
    position_only: bool | None = None
    tolerance: float = 1e-4


Goal = JointGoal | NamedGoal | PoseGoal

# The geometric planners of the OMPL bindings that solve our queries (see OMPL_PLANNERS).
PLANNERS = OMPL_PLANNERS
DEFAULT_PLANNER = "RRTConnect"


def group_planner(group: Group) -> str:
    """The planner a request for ``group`` that names none uses: the group's default in
    ``ompl_planning.yaml`` when it is one of :data:`PLANNERS`, else RRTConnect."""
    return (group.planner.planner if group.planner is not None else None) or DEFAULT_PLANNER


DEFAULT_RANGE = 1.5
"""rad: the tree growth step of RRT-style planners unless a request or the group's
``ompl_planning.yaml`` gives one (see :attr:`PlannerOptions.range`)."""


@dataclass(frozen=True)
class PlannerOptions:
    """How to plan.

    Attributes:
        planner: OMPL planner by name (see ``PLANNERS``); empty (MoveIt's empty
            ``planner_id``): the group's default planner of its ``ompl_planning.yaml``
            (``default_planner_config``), else RRTConnect (see :func:`group_planner`).
        planning_time: seconds per attempt, a cap and not a target: every planner but
            the optimizing ones with ``refine`` returns at its first solution. 5 s by
            default (MoveIt's default), long enough for the hard benchmark classes. The
            searches of one request share ``planning_time * attempts`` of search: a finer
            search after the exact verification turned a path down gets what is left.
        attempts: independent attempts (each with ``planning_time``) before giving up.
        seed: seeds OMPL's sampling and the IK goal sampling: the same seed, scene and
            request give the same path.
        longest_valid_segment: largest joint-space step (rad, max over joints) between
            collision checks while planning. Coarse on purpose: the path returned is
            verified exactly, and where a path turns out to clip an obstacle between two
            checks the search runs again with half the step (down to
            0.0125 rad at least). 0.1 rad against 0.05 checks about 40 % fewer states for
            at most a few more searches: 10-30 % less time per plan on every class of
            the Panda, UR5 and TIAGo sets (``benchmarks/RESULTS.md``).
        validation_resolution: kept for callers that report it; the returned path is
            verified exactly instead (see ``verify_margin``).
        verify_margin: m; the returned path (and, with timing, the sampled trajectory) is
            verified by conservative advancement: no checked pair overlaps at any check,
            none can touch between checks where its clearance exceeded this margin, and
            none can penetrate deeper than ``verify_margin / 2`` anywhere.
        refine: let optimizing planners (RRTstar, BITstar, PRMstar …) use all their time
            to improve the path; by default every planner stops at its first solution.
        simplify: shortcut and smooth the path before returning it.
        goal_samples: IK solutions sampled as goal states for a pose goal.
        direct: first try the straight joint-space line from the start to each goal
            state (in the request's order), checked as the search checks an edge and then
            verified exactly; the search runs only when every such line is blocked. A
            free straight line is also the shortest path, so optimizing planners lose
            nothing by it.
        direct_only: with ``direct``, answer by a straight line or not at all: when every
            goal state's line is blocked, raise
            :class:`~taskrunner.errors.NoDirectPathError` instead of searching. A caller
            whose goal list is costly to compute asks this with its first goals, then
            with all of them if it must.
        range: rad; the longest edge RRT-style planners grow a tree by at once. 0 (the
            default): the ``range`` of the group's default planner configuration in
            ``ompl_planning.yaml`` when it gives one above 0, else :data:`DEFAULT_RANGE`
            (OMPL's own default, a fifth of the state space's extent, is 2.6 rad for
            the Panda and several times slower where the way out is narrow: see
            ``benchmarks/RESULTS.md``).
        restart: state checks after which a tree search (RRTConnect, RRT, the KPIECE
            family) that has found no path starts again with a new seed, each restart
            allowed twice as many; 0: never. Run times of these searches are
            heavy-tailed (Wedge & Branicky, "On heavy-tailed runtimes and restarts in
            rapidly-exploring random trees", AAAI 2008): on the hardest cage problems
            restarts cut the mean search 1.04 -> 0.67 s and the longest 5.8 -> 2.1 s.
            Counted in checks, not seconds, so a seed gives the same path at any load.
    """

    planner: str = ""
    planning_time: float = 5.0
    attempts: int = 1
    seed: int = 0
    longest_valid_segment: float = 0.1
    validation_resolution: float = 0.01
    verify_margin: float = VERIFY_MARGIN
    refine: bool = False
    simplify: bool = True
    goal_samples: int = 6
    direct: bool = True
    direct_only: bool = False
    range: float = 0.0
    restart: int = 20_000

    def __post_init__(self) -> None:
        if self.planner and self.planner not in PLANNERS:
            raise ArgumentError(f"'planner' must be one of {', '.join(PLANNERS)} (got {self.planner!r})")
        for name in ("planning_time", "longest_valid_segment", "validation_resolution",
                     "verify_margin"):
            value = getattr(self, name)
            if not (isinstance(value, (int, float)) and math.isfinite(value) and value > 0):
                raise ArgumentError(f"'{name}' must be a positive number (got {value!r})")
        if not (isinstance(self.range, (int, float)) and math.isfinite(self.range)
                and self.range >= 0):
            raise ArgumentError(f"'range' must be a number >= 0 (got {self.range!r})")
        if isinstance(self.restart, bool) or not isinstance(self.restart, int) or self.restart < 0:
            raise ArgumentError(f"'restart' must be an integer >= 0 (got {self.restart!r})")
        for name in ("attempts", "goal_samples"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, int) or value < 1:
                raise ArgumentError(f"'{name}' must be a positive integer (got {value!r})")
        if self.direct_only and not self.direct:
            raise ArgumentError("'direct_only' needs 'direct' (a straight line to try)")
        if isinstance(self.seed, bool) or not isinstance(self.seed, (int, np.integer)):
            raise ArgumentError(f"'seed' must be an integer (got {self.seed!r})")


@dataclass(frozen=True)
class PlanRequest:
    """A request to plan ``group`` from ``start`` (default: the scene's state) to a goal.

    ``goal`` may be a tuple of goals: the plan reaches whichever is found first. With
    ``timing``, the planner also times the path (toppra) and the result carries the
    trajectory: a planning worker then does that work too, not the caller's process.
    With ``timing`` and ``trajectory_json``, it also encodes the trajectory as JSON (a
    slow arm's has thousands of samples: formatting them costs milliseconds that a
    server answering other requests should not spend).
    """

    group: str
    goal: Goal | tuple[Goal, ...]
    start: np.ndarray | None = None
    options: PlannerOptions = field(default_factory=PlannerOptions)
    timing: TimingOptions | None = None
    trajectory_json: bool = False

    @property
    def goals(self) -> tuple[Goal, ...]:
        return self.goal if isinstance(self.goal, tuple) else (self.goal,)


@dataclass(frozen=True)
class PlanResult:
    """A collision-free path, verified exactly (see :class:`PlannerOptions`).

    Attributes:
        path: waypoints over the group's joints, from the start to the goal reached.
        start: the full state vector the path starts from (other joints stay as here).
        end: the full state vector at the end of the path.
        goal_index: which of the request's goals was reached.
        planning_time: seconds spent searching (all attempts).
        simplify_time: seconds spent shortcutting the path.
        total_time: wall time of the whole request (goal sampling, checks included).
        checks: collision checks made while searching.
        direct: the straight line from the start to the goal was free (no search ran:
            see :attr:`PlannerOptions.direct`).
        searches: searches run; more than one where the exact verification turned a
            path down (it is searched again with half the planning segment).
        verify_queries: pair distances computed to verify the path (and trajectory).
        verify_time: seconds spent verifying them (part of ``total_time``; with timing,
            the trajectory's verification comes on top of it).
        trajectory: the path timed with the request's ``timing`` (None without it).
        trajectory_json: with the request's ``trajectory_json``, the trajectory as one
            JSON object: ``{"times": [...], "positions": [[...], ...], "velocities":
            [[...], ...]}`` (s, rad or m, rad/s or m/s; one row per sample).
        compiled: checked with the planner's compiled kernels; False: with coal alone, while
            they compiled (:mod:`taskrunner.scene.coalpath`: the same guarantee).
    """

    path: JointPath
    start: np.ndarray
    end: np.ndarray
    goal_index: int
    planner: str
    planning_time: float
    simplify_time: float
    total_time: float
    checks: int
    direct: bool = False
    searches: int = 0
    verify_queries: int = 0
    verify_time: float = 0.0
    trajectory: JointTrajectory | None = None
    trajectory_json: bytes | None = None
    compiled: bool = True

