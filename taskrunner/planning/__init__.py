"""Motion planning: OMPL paths, Cartesian paths and toppra timing for a scene's groups."""

from __future__ import annotations

from taskrunner.planning.cartesian import (
    CartesianOptions,
    CartesianPlanner,
    CartesianResult,
    compute_cartesian_path,
    compute_relative_cartesian_path,
    relative_pose,
)
from taskrunner.planning.planner import MotionPlanner
from taskrunner.planning.request import (
    PLANNERS,
    Goal,
    JointGoal,
    NamedGoal,
    PlannerOptions,
    PlanRequest,
    PlanResult,
    PoseGoal,
)

__all__ = [
    "PLANNERS",
    "CartesianOptions",
    "CartesianPlanner",
    "CartesianResult",
    "compute_cartesian_path",
    "compute_relative_cartesian_path",
    "relative_pose",
    "Goal",
    "JointGoal",
    "MotionPlanner",
    "NamedGoal",
    "PlanRequest",
    "PlanResult",
    "PlannerOptions",
    "PoseGoal",
]
