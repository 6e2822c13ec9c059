"""``/runs``: start, list, inspect, cancel runs, and follow their events live (SSE)."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Any

from fastapi import APIRouter, Depends, Header, HTTPException, Query, Response, status
from pydantic import BaseModel, ConfigDict, Field
from starlette.concurrency import run_in_threadpool

from taskrunner.api.admission import Admission, ControlExecutor
from taskrunner.api.auth import require_read, require_write
from taskrunner.api.cells import CellRegistry
from taskrunner.api.dependencies import (
    get_cells,
    get_checking,
    get_control,
    get_manager,
    get_settings,
    get_store,
    get_streams,
    get_work,
)
from taskrunner.api.detail import DEFAULT_LIMIT, MAX_LIMIT
from taskrunner.api.requestwork import (
    RequestWork,
    inline_path,
    load_request,
    precheck_request,
)
from taskrunner.api.runs import RunManager
from taskrunner.api.schemas import (
    ErrorBody,
    RunAccepted,
    RunCreate,
    RunDetail,
    RunStatus,
    RunSummary,
)
from taskrunner.api.settings import Settings
from taskrunner.api.store import RunStore
from taskrunner.api.streams import EventStream, RunStreams
from taskrunner.errors import InputError
from taskrunner.tasks.problem import raise_for_problems

__all__ = ["router"]

router = APIRouter(prefix="/runs", tags=["runs"])

_ERRORS: dict[int | str, dict[str, Any]] = {
    401: {"model": ErrorBody}, 404: {"model": ErrorBody}, 409: {"model": ErrorBody},
    413: {"model": ErrorBody}, 422: {"model": ErrorBody}, 503: {"model": ErrorBody}}


@router.post("", status_code=status.HTTP_202_ACCEPTED, response_model=RunAccepted,
             dependencies=[Depends(require_write)], responses=_ERRORS)
async def start_run(body: RunCreate, response: Response,
                    settings: Annotated[Settings, Depends(get_settings)],
                    manager: Annotated[RunManager, Depends(get_manager)],
                    cells: Annotated[CellRegistry, Depends(get_cells)],
                    work: Annotated[RequestWork, Depends(get_work)],
                    store: Annotated[RunStore, Depends(get_store)],
                    checking: Annotated[Admission, Depends(get_checking)]) -> RunAccepted:
    """Start a task (a file of the tasks folder, or inline YAML) on a cell's backend.

    The task is checked first (``check``, default true): a task with problems answers 422
    with every problem and nothing moves. Answers 202 at once with the run id; the run
    goes on in the background. A run that needs an arm (joints) a run in flight moves is
    refused with 409: runs are not queued. Loading and checking the task share
    ``check_workers`` with ``/tasks/check``; beyond them and the ``work_queue``: 503 with
    ``Retry-After``.
    """
    async with checking.slot():
        # Loaded within the limits (time, memory) and folders of request work.
        spec, task_file, text = await run_in_threadpool(
            work.call, load_request, settings.folder_policy(), settings.tasks_dir,
            body.task, body.yaml, body.parameters)
        if body.check and body.cell is None:
            # Check first, as run-task does: a task that cannot succeed moves nothing.
            # (On another cell than its own, the names are checked when the run starts.)
            taught = await run_in_threadpool(store.taught_poses, settings.cells_dir)
            raise_for_problems(await run_in_threadpool(
                work.call, precheck_request, settings.folder_policy(), settings.tasks_dir,
                body.task, body.yaml, body.parameters, body.seed, taught,
                settings.load_options()))
    if body.cell is not None:
        spec = spec.model_copy(update={"cell": cells.path_of(body.cell)})
    live = await run_in_threadpool(
        lambda: manager.start(spec, body.backend, seed=body.seed, task_text=text,
                              task_file=task_file, speed=body.speed))
    url = f"/runs/{live.run_id}"
    response.headers["Location"] = url
    return RunAccepted(run_id=live.run_id, status=RunStatus.RUNNING, url=url)


@router.get("", response_model=list[RunSummary], dependencies=[Depends(require_read)],
            responses=_ERRORS)
async def list_runs(manager: Annotated[RunManager, Depends(get_manager)],
                    status: RunStatus | None = None,
                    limit: Annotated[int, Query(ge=1, le=1000)] = 100) -> Response:
    """Runs, newest first, optionally of one status."""
    # Pre-serialised (the JSON of list[RunSummary]) and cached until a run is written;
    # the database is only read off the event loop.
    body = manager.listing.fresh(status, limit)
    if body is None:
        body = await run_in_threadpool(manager.listing.body, status, limit)
    return Response(body, media_type="application/json")


@router.get("/{run_id}", response_model=RunDetail, dependencies=[Depends(require_read)],
            responses=_ERRORS)
async def get_run(run_id: str, manager: Annotated[RunManager, Depends(get_manager)],
                  control: Annotated[ControlExecutor, Depends(get_control)],
                  since: Annotated[int, Query(ge=0, description="show the events with seq "
                                                                "> since")] = 0,
                  limit: Annotated[int, Query(ge=1, le=MAX_LIMIT, description="show at most "
                                              "this many events")] = DEFAULT_LIMIT
                  ) -> Response:
    """A run: status, the node running now (with its file:line), the tree, the result and
    a page of its events: those with seq > ``since``, at most ``limit``; ``events_more``
    says whether more follow (ask again with ``since`` = the last seq shown)."""
    # Polls of live runs without a query are answered before routing, from their cached
    # bodies (api.fastpath); what reaches this is a recorded run (database), a page, or
    # a first build.
    body = await control.run(manager.detail, run_id, since, limit)
    return Response(body, media_type="application/json")


@router.post("/{run_id}/cancel", status_code=status.HTTP_202_ACCEPTED,
             response_model=RunAccepted, dependencies=[Depends(require_write)],
             responses=_ERRORS)
async def cancel_run(run_id: str, manager: Annotated[RunManager, Depends(get_manager)],
                     control: Annotated[ControlExecutor, Depends(get_control)]
                     ) -> RunAccepted:
    """Stop a run: the motion stops where it is and the run ends as cancelled (409 if it
    has already ended). Follow its events or poll it to see it end."""
    # A run in flight is cancelled here, on the event loop (no thread to wait for, so no
    # burst of other requests can hold the stop back); an ended or unknown run is looked
    # up in the database on the control threads.
    live = manager.cancel_live(run_id)
    if live is None:
        live = await control.run(manager.cancel, run_id)
    return RunAccepted(run_id=run_id, status=live.record.status,  # type: ignore[arg-type]
                       url=f"/runs/{run_id}")


class RunResume(BaseModel):
    """What the operator says about the world when resuming (see ``run-task resume``)."""

    model_config = ConfigDict(extra="forbid")

    objects: dict[str, list[float]] = Field(
        default_factory=dict, max_length=64,
        description="objects lying at a pose now: name -> [x, y, z] or [x, y, z, qx, qy, "
                    "qz, qw] (m, world frame)")
    released: list[str] = Field(default_factory=list, max_length=64,
                                description="held objects no longer held")
    held: list[str] = Field(default_factory=list, max_length=64,
                            description="held objects confirmed still in their gripper")
    from_step: str | None = Field(default=None, max_length=255,
                                  description="resume at this step (name or file:line)")


@router.post("/{run_id}/resume", status_code=status.HTTP_202_ACCEPTED,
             response_model=RunAccepted, dependencies=[Depends(require_write)],
             responses=_ERRORS)
async def resume_run(run_id: str, body: RunResume, response: Response,
                     settings: Annotated[Settings, Depends(get_settings)],
                     manager: Annotated[RunManager, Depends(get_manager)],
                     cells: Annotated[CellRegistry, Depends(get_cells)],
                     work: Annotated[RequestWork, Depends(get_work)],
                     checking: Annotated[Admission, Depends(get_checking)]) -> RunAccepted:
    """Continue an ended run (failed, cancelled, interrupted) from where it stopped, with
    the arm where the cell's backend reports it: a new run whose record ``resumes`` this
    one. Refused with 422 and what to do when it cannot be resumed safely (its task file
    changed, a held object's state unknown on this backend: say ``held``, ``released``
    or ``objects``); 409 if its arm is in use."""
    from taskrunner.runtime.resume import ResumeOptions, plan_resume
    from taskrunner.types import Pose

    poses = {}
    for name, values in body.objects.items():
        if len(values) not in (3, 7):
            raise InputError(f"'objects.{name}' must be [x, y, z] or [x, y, z, qx, qy, qz, "
                             f"qw] (got {len(values)} numbers)")
        poses[name] = Pose(tuple(values[:3]), tuple(values[3:]) or (0.0, 0.0, 0.0, 1.0))  # type: ignore[arg-type]
    record = await run_in_threadpool(manager.record, run_id)
    options = ResumeOptions(objects=poses, released=tuple(body.released),
                            held=tuple(body.held), from_step=body.from_step)
    task_file = Path(record.task_file)
    task: str | None = None  # None: inline YAML, its text as the record keeps it
    if task_file != inline_path(settings.tasks_dir):
        try:
            task = str(task_file.resolve().relative_to(settings.tasks_dir.resolve()))
        except ValueError:
            raise InputError(f"cannot resume run {run_id}: its task file {task_file} is "
                             "not in the server's tasks folder") from None
    async with checking.slot():
        spec, loaded_file, text = await run_in_threadpool(
            work.call, load_request, settings.folder_policy(), settings.tasks_dir,
            task, record.task_text if task is None else None, record.parameters)
    cell = (cells.path_of(record.cell) if "/" not in record.cell else Path(record.cell))
    spec = spec.model_copy(update={"cell": cell})
    # A run of this server process: its cell's backend (a physics world) went on since.
    plan = plan_resume(record, spec, options, same_world=manager.live(run_id) is not None)
    live = await run_in_threadpool(
        lambda: manager.start(spec, record.backend, task_text=text, task_file=loaded_file,
                              resume=plan))
    url = f"/runs/{live.run_id}"
    response.headers["Location"] = url
    return RunAccepted(run_id=live.run_id, status=RunStatus.RUNNING, url=url)


async def _events_start(run_id: str, manager: Annotated[RunManager, Depends(get_manager)],
                        last_event_id: Annotated[str | None, Header()] = None,
                        after: Annotated[int | None, Query(ge=0)] = None) -> int:
    """The seq to stream after (``Last-Event-ID``, else ``?after=N``, else 0), checked
    before the stream starts: a bad value is 422, an unknown run 404."""
    start = after or 0
    if last_event_id is not None:
        try:
            start = int(last_event_id)
        except ValueError:
            raise HTTPException(422, f"'Last-Event-ID' must be an event seq, an integer "
                                     f"(got {last_event_id!r})") from None
        if start < 0:
            raise HTTPException(422, f"'Last-Event-ID' must be >= 0 (got {start})")
    manager.record(run_id)  # RunNotFoundError: 404
    return start


@router.get("/{run_id}/events", response_class=EventStream, status_code=status.HTTP_200_OK,
            dependencies=[Depends(require_read)],
            responses={**_ERRORS, 200: {"description": "the run's events, as Server-Sent "
                                                       "Events, to the end of the run"}})
async def run_events(run_id: str, manager: Annotated[RunManager, Depends(get_manager)],
                     streams: Annotated[RunStreams, Depends(get_streams)],
                     start: Annotated[int, Depends(_events_start)]) -> EventStream:
    """The run's events as Server-Sent Events (``id`` = the event's seq, ``event`` = its
    kind, ``data`` = the event as JSON), from the first one or from after
    ``Last-Event-ID`` (or ``?after=N``); the stream ends after ``run_finished``. An idle
    stream sends a comment now and then, so that proxies keep it open.

    A client that falls more than ``stream_max_lag`` events behind is sent a last
    ``dropped`` event naming the ``Last-Event-ID`` to resume from, and the stream ends;
    one that takes no bytes for ``stream_send_timeout_s`` is disconnected. Neither slows
    the run or the other clients (see ``api.streams``).
    """
    return EventStream(streams, manager, run_id, start)
