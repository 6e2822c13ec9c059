"""``/tasks/check``: the report of ``run-task check``; nothing moves."""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, Depends
from starlette.concurrency import run_in_threadpool

from taskrunner.api.admission import Admission
from taskrunner.api.auth import require_read
from taskrunner.api.dependencies import get_checking, get_settings, get_store, get_work
from taskrunner.api.requestwork import RequestWork, check_request
from taskrunner.api.schemas import CheckRequest, CheckResponse, ErrorBody
from taskrunner.api.settings import Settings
from taskrunner.api.store import RunStore

__all__ = ["router"]

router = APIRouter(prefix="/tasks", tags=["tasks"])


@router.post("/check", response_model=CheckResponse, dependencies=[Depends(require_read)],
             responses={401: {"model": ErrorBody}, 413: {"model": ErrorBody},
                        422: {"model": ErrorBody}, 503: {"model": ErrorBody}})
async def check(body: CheckRequest, settings: Annotated[Settings, Depends(get_settings)],
                work: Annotated[RequestWork, Depends(get_work)],
                store: Annotated[RunStore, Depends(get_store)],
                checking: Annotated[Admission, Depends(get_checking)]) -> CheckResponse:
    """Every problem of a task at once, each at its file:line (structure, names, then a
    kinematic dry run). A task with problems still answers 200, with ``ok`` false. Tasks,
    their includes and cells load only from the server's folders; an inline task is
    ``inline.yaml`` of the tasks folder, held in memory. A check past the server's time
    limit answers 422. Poses taught on the cell count, as they do for a run. When the
    server checks as many tasks as it allows and its queue is full: 503 with
    ``Retry-After``."""
    async with checking.slot():
        taught = await run_in_threadpool(store.taught_poses, settings.cells_dir)
        answer = await run_in_threadpool(work.call, check_request, settings.folder_policy(),
                                         settings.tasks_dir, body.task, body.yaml,
                                         body.parameters, body.seed, taught,
                                         settings.load_options())
    return CheckResponse.model_validate(answer)
