"""``/plan``: plan one motion (a ``go`` or a ``move``) and time it; nothing moves."""

from __future__ import annotations

import time
from collections.abc import Sequence
from typing import Annotated

from fastapi import APIRouter, Depends, Response
from pydantic_core import to_json
from starlette.concurrency import run_in_threadpool

from taskrunner.api.admission import Admission
from taskrunner.api.auth import require_read
from taskrunner.api.cells import CellRegistry
from taskrunner.api.dependencies import get_cells, get_planning, get_settings
from taskrunner.api.requestwork import RequestWork, WorkLimitError
from taskrunner.api.schemas import ErrorBody, PlanBody, PlanResponse
from taskrunner.api.settings import Settings
from taskrunner.planning.request import JointGoal, PlannerOptions, PlanRequest, PoseGoal
from taskrunner.planning.timing import TimingOptions
from taskrunner.scene import scene_from_cell
from taskrunner.shapes import Shape
from taskrunner.types import Pose, pose_from_xyz_rpy

__all__ = ["router"]

router = APIRouter(tags=["plan"])


@router.post("/plan", response_model=PlanResponse, dependencies=[Depends(require_read)],
             responses={401: {"model": ErrorBody}, 404: {"model": ErrorBody},
                        413: {"model": ErrorBody}, 422: {"model": ErrorBody},
                        503: {"model": ErrorBody}})
async def plan(body: PlanBody, cells: Annotated[CellRegistry, Depends(get_cells)],
               settings: Annotated[Settings, Depends(get_settings)],
               planning: Annotated[Admission, Depends(get_planning)]) -> Response:
    """Plan a collision-free motion of ``group`` from where the cell's backend is now
    (with the cell's fixed objects) to a named pose, joint values or a link pose, and
    time it (rad, s). Nothing moves. No path: 422 with the planner's reason; no answer
    within the server's ``plan_timeout_s``: 422, and the search is stopped. At most
    ``max_planners`` plans and previews run at once and ``work_queue`` more wait; beyond
    that: 503 with ``Retry-After``."""
    async with planning.slot():
        limit = settings.plan_timeout_s
        # A thread with a deadline: the answer comes on time even if building the scene
        # or an in-process planner runs late (a worker process is also told to stop).
        work = RequestWork("inprocess", limit, 0, 1, setting="plan_timeout_s",
                           what="the plan took longer than {s} s")
        deadline = time.monotonic() + limit
        answer = await run_in_threadpool(work.call, _plan, body, cells, deadline, limit)
    return Response(answer, media_type="application/json")


def _plan(body: PlanBody, cells: CellRegistry, deadline: float, limit: float,
          obstacles: Sequence[tuple[str, Shape, Pose]] = ()) -> bytes:
    """The JSON of :class:`PlanResponse`, without validating it field by field: a slow
    arm's trajectory has thousands of samples, and validating or encoding each float
    here cost the server more than planning them. ``obstacles`` (name, shape, world
    pose) are added to the cell's objects for this plan only (the web view's)."""
    session = cells.by_id(body.cell)
    model = session.cell.model
    group = model.group(body.group)
    scene = scene_from_cell(session.cell)
    for name, shape, pose in obstacles:
        scene.add_object(name, shape, pose)
    state = session.backend(body.backend).joint_state()
    scene.set_state(dict(zip(state.names, state.positions)))
    if body.to is not None:  # resolved here: a worker's model lacks poses taught since
        goal: JointGoal | PoseGoal = JointGoal(model.named_state(group.name, body.to).as_dict())
    elif body.joints is not None:
        goal = JointGoal(body.joints)
    else:
        assert body.pose is not None
        target = body.pose
        pose = target.to_pose() if target.quat is not None else pose_from_xyz_rpy(
            target.xyz, target.rpy or (0.0, 0.0, 0.0), target.frame)  # rpy: as before, bit for bit
        goal = PoseGoal(pose, link=body.pose.link, position_only=body.pose.position_only)
    # The planner times the path and encodes it too: in a worker process, off this
    # process's GIL (the event loop answers other requests meanwhile).
    request = PlanRequest(group.name, goal, options=PlannerOptions(
        planning_time=body.planning_time, seed=body.seed),
        timing=TimingOptions(velocity_scaling=body.velocity_scaling,
                             sample_rate_hz=body.sample_rate_hz), trajectory_json=True)
    planner = session.take_planner()
    try:
        ticket = planner.submit(scene, request)
        result = ticket.result(max(0.0, deadline - time.monotonic()))
    except TimeoutError:
        ticket.cancel()
        planner.close()  # it may still be searching: not back into the pool
        raise WorkLimitError(f"the plan took longer than {limit:g} s; it was stopped "
                             "(server setting 'plan_timeout_s')") from None
    except BaseException:
        session.give_planner(planner)
        raise
    session.give_planner(planner)
    trajectory, encoded = result.trajectory, result.trajectory_json
    assert trajectory is not None and encoded is not None  # asked for with the request
    head = to_json({"group": group.name, "joint_names": list(trajectory.names),
                    "duration": float(trajectory.duration),
                    "planning_time": float(result.planning_time),
                    "waypoints": len(result.path.waypoints)})
    # {"group":...,"waypoints":N} + {"times":...,"velocities":[...]}: one object
    return b"".join((head[:-1], b",", encoded[1:]))
