"""``/tasks/check``: the report of ``run-task check``; nothing moves."""

from __future__ import annotations

from typing import Annotated

from fastapi import APIRouter, Depends
from starlette.concurrency import run_in_threadpool

from taskrunner.api.auth import require_read
from taskrunner.api.dependencies import get_settings
from taskrunner.api.handlers import problem_out
from taskrunner.api.schemas import CheckRequest, CheckResponse, ErrorBody
from taskrunner.api.settings import Settings
from taskrunner.api.tasksource import inline_path, task_file_for_check
from taskrunner.tree.check import check_task

__all__ = ["router"]

router = APIRouter(prefix="/tasks", tags=["tasks"])


@router.post("/check", response_model=CheckResponse, dependencies=[Depends(require_read)],
             responses={401: {"model": ErrorBody}, 413: {"model": ErrorBody},
                        422: {"model": ErrorBody}})
async def check(body: CheckRequest,
                settings: Annotated[Settings, Depends(get_settings)]) -> CheckResponse:
    """Every problem of a task at once, each at its file:line (structure, names, then a
    kinematic dry run). A task with problems still answers 200, with ``ok`` false."""
    return await run_in_threadpool(_check, body, settings)


def _check(body: CheckRequest, settings: Settings) -> CheckResponse:
    with task_file_for_check(settings.tasks_dir, body.task, body.yaml) as (path, temporary):
        report = check_task(path, body.parameters, seed=body.seed)
    problems = []
    for problem in report.problems:
        out = problem_out(problem)
        if temporary is not None and problem.path is not None \
                and problem.path.resolve() == temporary.resolve():
            shown = inline_path(settings.tasks_dir)
            out["file"] = str(shown)
            out["text"] = out["text"].replace(str(problem.path), str(shown), 1)
        problems.append(out)
    return CheckResponse(ok=not problems, cell=report.cell, steps=report.steps,
                         problems=problems)  # type: ignore[arg-type]
