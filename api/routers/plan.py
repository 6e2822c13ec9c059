"""``/plan``: plan one motion (a ``go`` or a ``move``) and time it; nothing moves."""

from __future__ import annotations

import math
from typing import Annotated

from fastapi import APIRouter, Depends
from starlette.concurrency import run_in_threadpool

from taskrunner.planning.request import JointGoal, NamedGoal, PlannerOptions, PlanRequest, PoseGoal
from taskrunner.planning.timing import TimingOptions, parameterize_path
from taskrunner.scene import scene_from_cell
from taskrunner.types import pose_from_xyz_rpy

from api.auth import require_read
from api.cells import CellRegistry
from api.dependencies import get_cells
from api.schemas import ErrorBody, PlanBody, PlanResponse

__all__ = ["router"]

router = APIRouter(tags=["plan"])
_ANSWER_TIMEOUT_S = 60.0  # planning_time is at most 30 s; the worker may be starting


@router.post("/plan", response_model=PlanResponse, dependencies=[Depends(require_read)],
             responses={401: {"model": ErrorBody}, 404: {"model": ErrorBody},
                        413: {"model": ErrorBody}, 422: {"model": ErrorBody}})
async def plan(body: PlanBody, cells: Annotated[CellRegistry, Depends(get_cells)]) -> PlanResponse:
    """Plan a collision-free motion of ``group`` from where the cell's backend is now
    (with the cell's fixed objects) to a named pose, joint values or a link pose, and
    time it (rad, s). Nothing moves. No path: 422 with the planner's reason."""
    return await run_in_threadpool(_plan, body, cells)


def _plan(body: PlanBody, cells: CellRegistry) -> PlanResponse:
    session = cells.by_id(body.cell)
    model = session.cell.model
    group = model.group(body.group)
    scene = scene_from_cell(session.cell)
    state = session.backend(body.backend).joint_state()
    scene.set_state(dict(zip(state.names, state.positions)))
    if body.to is not None:
        goal: JointGoal | NamedGoal | PoseGoal = NamedGoal(body.to)
    elif body.joints is not None:
        goal = JointGoal(body.joints)
    else:
        assert body.pose is not None
        pose = pose_from_xyz_rpy(body.pose.xyz, body.pose.rpy, body.pose.frame)
        goal = PoseGoal(pose, link=body.pose.link, position_only=body.pose.position_only)
    request = PlanRequest(group.name, goal, options=PlannerOptions(
        planning_time=body.planning_time, seed=body.seed))
    planner = session.take_planner()
    try:
        result = planner.submit(scene, request).result(_ANSWER_TIMEOUT_S)
    finally:
        session.give_planner(planner)
    trajectory = parameterize_path(model, result.path,
                                   TimingOptions(velocity_scaling=body.velocity_scaling))
    return PlanResponse(
        group=group.name, joint_names=list(trajectory.names),
        times=[float(t) for t in trajectory.times],
        positions=_rows(trajectory.positions), velocities=_rows(trajectory.velocities),
        duration=float(trajectory.duration), planning_time=float(result.planning_time),
        waypoints=len(result.path.waypoints))


def _rows(values: object) -> list[list[float]]:
    return [[float(v) if math.isfinite(v) else 0.0 for v in row] for row in values]  # type: ignore[attr-defined]
