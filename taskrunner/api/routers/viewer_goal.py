"""The page's goal and Execute, as RViz's MotionPlanning panel has them.

``POST /viewer/cells/{id}/goal`` answers a goal state set on the page (a dragged tool
frame solved by IK, or joint values): the group's joints, the tip's pose, and why the
planner could not go there (unreachable, outside the limits, in collision). It is a read
(nothing moves) and shares ``check_workers`` with task checks. Planning is ``POST /plan``
with the goal's joints.

``POST /viewer/cells/{id}/execute`` (token required) moves the group to the goal on the
cell's backend as a run: planned again from where the arm is, with the seed and
velocity scaling of the preview, recorded, followed and cancelled (``POST
/runs/{id}/cancel``) like any run, its arm claimed against other runs. A plan made
from another start than the arm's is refused (409), as MoveIt refuses a trajectory whose
first point is off the current state.
"""

from __future__ import annotations

import json
import threading
from typing import Annotated, Any, cast

from fastapi import APIRouter, Depends, Request, Response, status
from pydantic import Field, model_validator
from starlette.concurrency import run_in_threadpool

from taskrunner.api.admission import Admission
from taskrunner.api.auth import require_read, require_write
from taskrunner.api.cells import CellRegistry, CellSession, PoseConflictError
from taskrunner.api.dependencies import get_cells, get_checking, get_manager, get_settings, get_work
from taskrunner.api.requestwork import RequestWork, load_request
from taskrunner.api.runs import RunManager
from taskrunner.api.schemas import (
    MAX_JOINTS,
    Backend,
    ErrorBody,
    Integer,
    Number,
    RunAccepted,
    _Request,
)
from taskrunner.api.settings import Settings
from taskrunner.errors import InvalidStateError
from taskrunner.viewer.goal import GoalSolver

__all__ = ["START_TOLERANCE", "router"]

router = APIRouter(tags=["viewer"])
_ERRORS: dict[int | str, dict[str, Any]] = {
    401: {"model": ErrorBody}, 404: {"model": ErrorBody}, 409: {"model": ErrorBody},
    422: {"model": ErrorBody}, 503: {"model": ErrorBody}}
_NAME = Field(min_length=1, max_length=128)
_REACH_M = 100.0  # no cell is larger: a coordinate beyond this is a mistake

START_TOLERANCE = 0.01
"""rad or m: how far the arm may be from a plan's first point for Execute (MoveIt's
``trajectory_execution/allowed_start_tolerance``)."""


class GoalPose(_Request):
    xyz: list[Number] = Field(min_length=3, max_length=3, description="m, world frame")
    quat: list[Number] = Field(min_length=4, max_length=4,
                               description="x, y, z, w (normalised by the server)")
    link: str | None = Field(default=None, max_length=128,
                             description="the link to aim (default: the group's tip)")

    @model_validator(mode="after")
    def _in_reach(self) -> GoalPose:
        if any(abs(v) > _REACH_M for v in self.xyz):
            raise ValueError(f"'xyz' must be within {_REACH_M:g} m of the world origin "
                             f"(got {self.xyz})")
        if any(abs(v) > 1.0 + 1e-6 for v in self.quat) or sum(v * v for v in self.quat) < 1e-12:
            raise ValueError(f"'quat' must be a unit quaternion x, y, z, w (got {self.quat})")
        return self


class GoalBody(_Request):
    """A goal state of one group: a link pose (solved by IK) or joint values."""

    group: str = _NAME
    pose: GoalPose | None = None
    joints: dict[str, Number] | None = Field(default=None, max_length=MAX_JOINTS)
    seed: dict[str, Number] = Field(
        default_factory=dict, max_length=MAX_JOINTS,
        description="joint values IK starts from and the other joints keep (rad or m)")

    @model_validator(mode="after")
    def _one_goal(self) -> GoalBody:
        if (self.pose is None) == (self.joints is None):
            raise ValueError("give exactly one goal: 'pose' or 'joints'")
        return self


class ExecuteBody(_Request):
    """Move a group to goal joint values on the cell's backend (a run)."""

    group: str = _NAME
    joints: dict[str, Number] = Field(min_length=1, max_length=MAX_JOINTS,
                                      description="the goal (rad or m)")
    backend: Backend = Field(default=cast(Backend, "sim"), description="whose arm moves")
    velocity_scaling: Number | None = Field(default=None, gt=0, le=1)
    seed: Integer = Field(default=0, ge=0, le=2**31 - 1)
    start: dict[str, Number] | None = Field(
        default=None, max_length=MAX_JOINTS,
        description="the plan's first point: refused (409) if the arm is elsewhere")


def _solver(request: Request, cell_id: str, session: CellSession) -> GoalSolver:
    """The cell's goal solver (one per loaded cell; cells load, never unload)."""
    state = request.app.state
    lock = state.__dict__.setdefault("viewer_goal_lock", threading.Lock())
    with lock:
        solvers: dict[str, GoalSolver] = state.__dict__.setdefault("viewer_goals", {})
        solver = solvers.get(cell_id)
        if solver is None or solver.cell is not session.cell:
            solver = solvers[cell_id] = GoalSolver(session.cell)
        return solver


@router.post("/viewer/cells/{cell_id}/goal", dependencies=[Depends(require_read)],
             responses=_ERRORS)
async def goal(cell_id: str, body: GoalBody, request: Request,
               cells: Annotated[CellRegistry, Depends(get_cells)],
               checking: Annotated[Admission, Depends(get_checking)]) -> dict[str, Any]:
    """A goal state checked as the planner would: ``joints`` (the group's, rad or m),
    ``xyz``/``quat`` (the link's world pose there), ``reachable``, ``within_limits``,
    ``collision_free``, ``ok`` and ``reason`` (why not). An unreachable pose answers the
    seed's joints with IK's reason. Nothing moves."""
    async with checking.slot():
        return await run_in_threadpool(_goal, cell_id, body, request, cells)


def _goal(cell_id: str, body: GoalBody, request: Request,
          cells: CellRegistry) -> dict[str, Any]:
    session = cells.by_id(cell_id)
    solver = _solver(request, cell_id, session)
    if body.pose is not None:
        state = solver.solve_pose(body.group, body.pose.xyz, body.pose.quat, body.pose.link,
                                  body.seed)
    else:
        assert body.joints is not None
        state = solver.check_joints(body.group, body.joints, body.seed)
    return state.as_dict()


@router.post("/viewer/cells/{cell_id}/execute", status_code=status.HTTP_202_ACCEPTED,
             response_model=RunAccepted, dependencies=[Depends(require_write)],
             responses=_ERRORS)
async def execute(cell_id: str, body: ExecuteBody, request: Request, response: Response,
                  settings: Annotated[Settings, Depends(get_settings)],
                  cells: Annotated[CellRegistry, Depends(get_cells)],
                  manager: Annotated[RunManager, Depends(get_manager)],
                  work: Annotated[RequestWork, Depends(get_work)],
                  checking: Annotated[Admission, Depends(get_checking)]) -> RunAccepted:
    """Move ``group`` to ``joints`` on the cell's ``backend``: a run of one ``go`` step,
    planned from where the arm is with ``seed`` and ``velocity_scaling``; follow it as
    any run and stop it with ``POST /runs/{id}/cancel``. A goal outside the limits or
    in collision: 422 with the reason. ``start`` given and the arm more than 0.01 rad
    or m from it: 409 (plan again). A run in flight moving the group: 409."""
    async with checking.slot():
        spec, text = await run_in_threadpool(_execute_spec, cell_id, body, request, cells,
                                             settings, work)
    live = await run_in_threadpool(
        lambda: manager.start(spec, body.backend, seed=body.seed, task_text=text))
    url = f"/runs/{live.run_id}"
    response.headers["Location"] = url
    return RunAccepted.model_validate({"run_id": live.run_id, "status": "running", "url": url})


def _execute_spec(cell_id: str, body: ExecuteBody, request: Request, cells: CellRegistry,
                  settings: Settings, work: RequestWork) -> tuple[Any, str]:
    session = cells.by_id(cell_id)
    state = _solver(request, cell_id, session).check_joints(body.group, body.joints, {})
    if state.reason is not None:
        raise InvalidStateError(f"the goal cannot be planned to: {state.reason}")
    if body.start is not None:
        _check_start(session, body.backend, body.start)
    step: dict[str, Any] = {"group": state.group, "joints": dict(body.joints)}
    if body.velocity_scaling is not None:
        step["velocity_scaling"] = body.velocity_scaling
    # JSON is YAML: names and numbers travel quoted, never spliced into YAML text.
    text = json.dumps({"task": "goal_from_view",
                       "description": f"Move {state.group} to the goal set in the web view.",
                       "cell": cell_id, "steps": [{"go": step}]}, indent=1)
    spec, _, _ = work.call(load_request, settings.folder_policy(), settings.tasks_dir, None,
                           text, {})
    return spec.model_copy(update={"cell": cells.path_of(cell_id)}), text


def _check_start(session: CellSession, backend: str, start: dict[str, float]) -> None:
    model = session.cell.model
    for name in start:
        model.joint(name)  # UnknownNameError names the known ones
    reported = session.backend(backend).joint_state()
    now = dict(zip(reported.names, reported.positions))
    off = [f"{name!r} is at {now[name]:.4f}, the plan starts at {value:.4f}"
           for name, value in start.items()
           if name in now and abs(now[name] - value) > START_TOLERANCE]
    if off:
        raise PoseConflictError("the arm is no longer where the plan starts ("
                                + "; ".join(off) + "): plan again")
