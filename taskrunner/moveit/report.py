"""Plan a MotionPlanRequest file in a scene and report it (``run-task plan``)."""

from __future__ import annotations

import os
import time
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from taskrunner.errors import InvalidStateError, PlanningError
from taskrunner.moveit.request_file import MotionPlanRequestFile, load_motion_plan_request
from taskrunner.moveit.scene_file import load_planning_scene
from taskrunner.planning.planner import MotionPlanner
from taskrunner.planning.request import PlanResult
from taskrunner.robot.cell import Cell
from taskrunner.robot.notes import LoadWarning
from taskrunner.scene import Scene, scene_from_cell

__all__ = ["PlanReport", "plan_files", "plan_request_file"]


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
                      timing: bool = True, planner: MotionPlanner | None = None,
                      start_state_max_bounds_error: float | None = None) -> PlanReport:
    """Plan ``request`` in a copy of ``scene`` (with the start state's attached objects).

    A planning failure is reported (``success`` False, ``error_kind``), not raised; so is
    a start state outside its bounds by more than ``start_state_max_bounds_error`` (rad or
    m; the request file's own value first, None: 0.05, see
    :mod:`taskrunner.moveit.start_bounds`).

    Raises:
        InputError: a goal's frame is unknown (file:line).
    """
    scene = scene.copy()
    request.apply_start(scene)
    started = time.perf_counter()
    try:
        plan_request = request.plan_request(scene, seed=seed, timing=timing,
                                            start_state_max_bounds_error=start_state_max_bounds_error)
    except InvalidStateError as exc:
        return PlanReport(False, request.group, request.options.planner or "default",
                          total_time=time.perf_counter() - started,
                          error_kind=type(exc).__name__, message=str(exc))
    name = plan_request.options.planner or "default"
    planner = planner if planner is not None and planner.scene is scene else MotionPlanner(scene)
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
    return PlanReport(not missed, request.group, result.planner or name, result.planning_time,
                      result.total_time, length, len(positions), duration,
                      "GoalConstraintsViolated" if missed else "", "; ".join(missed), result)


def plan_files(cell: Cell, request_path: str | os.PathLike[str],
               scene_path: str | os.PathLike[str] | None = None, *,
               robot: str | None = None, group: str | None = None, seed: int = 0,
               merge: bool | None = None, strict: bool | None = None,
               start_state_max_bounds_error: float | None = None,
               package_path: Sequence[Path] = (),
               ) -> tuple[PlanReport, list[LoadWarning]]:
    """Load ``cell``'s scene, apply a PlanningScene file, plan a MotionPlanRequest file
    (``strict``: what would be a warning is an error; ``start_state_max_bounds_error``: see
    :func:`plan_request_file`; ``package_path``: folders searched first for the packages
    of the scene's mesh resources).

    Returns:
        the report and every warning of both files.

    Raises:
        InputError, YamlError: an invalid file (file:line, field).
    """
    scene = scene_from_cell(cell)
    warnings: list[LoadWarning] = []
    if scene_path is not None:
        scene_file = load_planning_scene(scene_path, cell.model, robot=robot, strict=strict,
                                         package_path=package_path)
        scene_file.apply(scene, merge=merge)
        warnings += scene_file.warnings
    request = load_motion_plan_request(request_path, cell.model, robot=robot, group=group,
                                       strict=strict)
    report = plan_request_file(scene, request, seed=seed,
                               start_state_max_bounds_error=start_state_max_bounds_error)
    return report, warnings + request.warnings
