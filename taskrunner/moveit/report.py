"""Plan a MotionPlanRequest file in a scene and report it (``run-task plan``)."""

from __future__ import annotations

import time
from dataclasses import dataclass
from typing import Any

import numpy as np

from taskrunner.errors import PlanningError
from taskrunner.moveit.request_file import MotionPlanRequestFile
from taskrunner.planning.planner import MotionPlanner
from taskrunner.planning.request import PlanResult
from taskrunner.scene import Scene

__all__ = ["PlanReport", "plan_request_file"]


@dataclass(frozen=True)
class PlanReport:
    """What planning a request file gave.

    Attributes:
        success: a path was found, verified collision-free, and its end meets the goal
            constraints as written.
        error_kind: the error's class name on failure (``PlanningTimeoutError`` …).
        planning_time: s searching; ``total_time`` s for the whole request.
        path_length: joint-space length of the path (rad or m, Euclidean per segment).
        duration: s of the timed trajectory (0 without timing).
    """

    success: bool
    group: str
    planner: str
    planning_time: float = 0.0
    total_time: float = 0.0
    path_length: float = 0.0
    waypoints: int = 0
    duration: float = 0.0
    error_kind: str = ""
    message: str = ""
    result: PlanResult | None = None

    def to_json(self) -> dict[str, Any]:
        """A JSON-ready summary (no arrays)."""
        return {"success": self.success, "group": self.group, "planner": self.planner,
                "planning_time": self.planning_time, "total_time": self.total_time,
                "path_length": self.path_length, "waypoints": self.waypoints,
                "duration": self.duration, "error_kind": self.error_kind or None,
                "message": self.message}


def plan_request_file(scene: Scene, request: MotionPlanRequestFile, *, seed: int = 0,
                      timing: bool = True, planner: MotionPlanner | None = None) -> PlanReport:
    """Plan ``request`` in a copy of ``scene`` (with the start state's attached objects).

    A planning failure is reported (``success`` False, ``error_kind``), not raised.

    Raises:
        InputError: a goal's frame is unknown (file:line).
    """
    scene = scene.copy()
    request.apply_start(scene)
    plan_request = request.plan_request(scene, seed=seed, timing=timing)
    name = plan_request.options.planner
    planner = planner if planner is not None and planner.scene is scene else MotionPlanner(scene)
    started = time.perf_counter()
    try:
        result = planner.plan(plan_request)
    except PlanningError as exc:
        return PlanReport(False, request.group, name, total_time=time.perf_counter() - started,
                          error_kind=type(exc).__name__, message=str(exc))
    assert plan_request.start is not None
    missed = request.goal_violations(scene, plan_request.start, result.end)
    positions = np.asarray(result.path.waypoints)
    length = float(np.sum(np.linalg.norm(np.diff(positions, axis=0), axis=1))) if len(positions) > 1 else 0.0
    duration = result.trajectory.duration if result.trajectory is not None else 0.0
    return PlanReport(not missed, request.group, result.planner, result.planning_time,
                      result.total_time, length, len(positions), duration,
                      "GoalConstraintsViolated" if missed else "", "; ".join(missed), result)
