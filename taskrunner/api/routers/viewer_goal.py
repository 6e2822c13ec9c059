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
import time
from typing import Annotated, Any, Literal, cast

import pinocchio as pin
from fastapi import APIRouter, Depends, Request, Response, status
from pydantic import Field, model_validator
from starlette.concurrency import run_in_threadpool

from taskrunner.api.admission import Admission
from taskrunner.api.auth import require_read, require_write
from taskrunner.api.cells import CellRegistry, CellSession, PoseConflictError
from taskrunner.api.dependencies import (
    get_cells,
    get_checking,
    get_manager,
    get_planning,
    get_settings,
    get_work,
)
from taskrunner.api.requestwork import RequestWork, load_request
from taskrunner.api.routers.plan import _plan
from taskrunner.api.runs import RunManager
from taskrunner.api.schemas import (
    MAX_JOINTS,
    Backend,
    ErrorBody,
    Integer,
    Number,
    PlanBody,
    PlanResponse,
    RunAccepted,
    _Request,
)
from taskrunner.api.settings import Settings
from taskrunner.errors import InputError, InvalidStateError
from taskrunner.posespec import Position, TransformFields
from taskrunner.tasks.nodes import ObjectSpec
from taskrunner.tree.compiler import object_shape
from taskrunner.viewer.goal import GoalSolver, Obstacle

__all__ = ["MAX_OBSTACLES", "START_TOLERANCE", "router"]

router = APIRouter(tags=["viewer"])
_ERRORS: dict[int | str, dict[str, Any]] = {
    401: {"model": ErrorBody}, 404: {"model": ErrorBody}, 409: {"model": ErrorBody},
    422: {"model": ErrorBody}, 503: {"model": ErrorBody}}
_NAME = Field(min_length=1, max_length=128)
_SIZE_M = 10.0  # no obstacle is larger
MAX_OBSTACLES = 32
"""Most obstacles one request may add."""
_OBJECT_NAME = r"^[A-Za-z_][A-Za-z0-9_\-]{0,63}$"

START_TOLERANCE = 0.01
"""rad or m: how far the arm may be from a plan's first point for Execute (MoveIt's
``trajectory_execution/allowed_start_tolerance``)."""


class GoalPose(_Request, TransformFields):
    """A link's world pose: ``xyz`` (m) and ``quat`` (x, y, z, w) or ``rpy`` (rad; neither:
    the identity): the pose model of task and cell files and of ``POST /plan``, with its
    bounds and messages."""

    xyz: Position
    """Translation (m, world frame)."""
    link: str | None = Field(default=None, max_length=128,
                             description="the link to aim (default: the group's tip)")

    def quaternion(self) -> tuple[float, float, float, float]:
        """The orientation as a unit quaternion x, y, z, w."""
        if self.quat is not None:
            x, y, z, w = self.quat
            return x, y, z, w
        x, y, z, w = (float(v) for v in pin.Quaternion(self.rotation()).coeffs())
        return x, y, z, w


class ObstacleBody(_Request, TransformFields):
    """A box, cylinder or sphere the page adds to the cell for its goals, plans and
    Executes (the fields of a task file's object, its pose a world ``xyz`` and ``quat`` or
    ``rpy`` of the one pose model)."""

    name: str = Field(pattern=_OBJECT_NAME)
    shape: Literal["box", "cylinder", "sphere"]
    size: list[Number] | None = Field(default=None, min_length=3, max_length=3,
                                      description="a box's full lengths (m)")
    radius: Number | None = Field(default=None, gt=0, le=_SIZE_M / 2, description="m")
    length: Number | None = Field(default=None, gt=0, le=_SIZE_M,
                                  description="a cylinder's, along its z (m)")
    xyz: Position
    """Translation (m, world frame)."""

    @model_validator(mode="after")
    def _fields_of_shape(self) -> ObstacleBody:
        wanted = {"box": {"size"}, "cylinder": {"radius", "length"}, "sphere": {"radius"}}
        given = {f for f in ("size", "radius", "length") if getattr(self, f) is not None}
        if given != wanted[self.shape]:
            raise ValueError(f"a {self.shape} takes {' and '.join(sorted(wanted[self.shape]))}"
                             f" (got {', '.join(sorted(given)) or 'none'})")
        if self.size is not None and not all(0 < v <= _SIZE_M for v in self.size):
            raise ValueError(f"'size' must be lengths in (0, {_SIZE_M:g}] m (got {self.size})")
        return self

    def task_object(self) -> dict[str, Any]:
        """The obstacle as a task file's object."""
        out: dict[str, Any] = {"name": self.name, "shape": self.shape}
        for field in ("size", "radius", "length"):
            if getattr(self, field) is not None:
                out[field] = getattr(self, field)
        out["pose"] = {"xyz": list(self.xyz)} | {
            name: list(value) for name in ("quat", "rpy")
            if (value := getattr(self, name)) is not None}
        return out


def _obstacles(bodies: list[ObstacleBody]) -> list[Obstacle]:
    """The obstacles as scene objects, through the task language's own object model."""
    names = [b.name for b in bodies]
    twice = sorted({n for n in names if names.count(n) > 1})
    if twice:
        raise InputError(f"'obstacles': names must be unique (given twice: {', '.join(twice)})")
    specs = [ObjectSpec.model_validate(b.task_object()) for b in bodies]
    return [(spec.name, object_shape(spec), spec.pose.to_pose()) for spec in specs]


def _obstacles_field() -> Any:
    return Field(default_factory=list, max_length=MAX_OBSTACLES,
                 description="boxes, cylinders, spheres added to the cell for this request")


class GoalBody(_Request):
    """A goal state of one group: a link pose (solved by IK) or joint values."""

    group: str = _NAME
    pose: GoalPose | None = None
    joints: dict[str, Number] | None = Field(default=None, max_length=MAX_JOINTS)
    seed: dict[str, Number] = Field(
        default_factory=dict, max_length=MAX_JOINTS,
        description="joint values IK starts from and the other joints keep (rad or m)")
    obstacles: list[ObstacleBody] = _obstacles_field()

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
    obstacles: list[ObstacleBody] = _obstacles_field()


class ViewerPlanBody(PlanBody):
    """``POST /plan``'s body, with the page's obstacles."""

    obstacles: list[ObstacleBody] = _obstacles_field()


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
    obstacles = _obstacles(body.obstacles)
    if body.pose is not None:
        state = solver.solve_pose(body.group, body.pose.xyz, body.pose.quaternion(),
                                  body.pose.link, body.seed, obstacles)
    else:
        assert body.joints is not None
        state = solver.check_joints(body.group, body.joints, body.seed, obstacles=obstacles)
    return state.as_dict()


@router.post("/viewer/plan", response_model=PlanResponse, dependencies=[Depends(require_read)],
             responses={**_ERRORS, 413: {"model": ErrorBody}})
async def plan_with_obstacles(body: ViewerPlanBody,
                              cells: Annotated[CellRegistry, Depends(get_cells)],
                              settings: Annotated[Settings, Depends(get_settings)],
                              planning: Annotated[Admission, Depends(get_planning)]
                              ) -> Response:
    """``POST /plan`` with the page's ``obstacles`` added to the cell for this plan (the
    same planner, limits and admission: ``max_planners``, ``plan_timeout_s``)."""
    obstacles = _obstacles(body.obstacles)
    for name, _, _ in obstacles:
        if name in {o.name for o in cells.by_id(body.cell).cell.objects}:
            raise InputError(f"'obstacles': name {name!r} is taken by an object of the cell")
    async with planning.slot():
        limit = settings.plan_timeout_s
        work = RequestWork("inprocess", limit, 0, 1, setting="plan_timeout_s",
                           what="the plan took longer than {s} s")
        deadline = time.monotonic() + limit
        answer = await run_in_threadpool(work.call, _plan, body, cells, deadline, limit,
                                         obstacles)
    return Response(answer, media_type="application/json")


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
    state = _solver(request, cell_id, session).check_joints(
        body.group, body.joints, {}, obstacles=_obstacles(body.obstacles))
    if state.reason is not None:
        raise InvalidStateError(f"the goal cannot be planned to: {state.reason}")
    if body.start is not None:
        _check_start(session, body.backend, body.start)
    step: dict[str, Any] = {"group": state.group, "joints": dict(body.joints)}
    if body.velocity_scaling is not None:
        step["velocity_scaling"] = body.velocity_scaling
    # JSON is YAML: names and numbers travel quoted, never spliced into YAML text.
    task: dict[str, Any] = {"task": "goal_from_view",
                            "description": f"Move {state.group} to the goal set in the web view.",
                            "cell": cell_id}
    if body.obstacles:
        task["objects"] = [b.task_object() for b in body.obstacles]
    task["steps"] = [{"go": step}]
    text = json.dumps(task, indent=1)
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
