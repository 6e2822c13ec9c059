"""The browser view: the page at ``/`` and the data it reads under ``/viewer``.

The page and its bundle (``/``, ``/viewer/static/…``) load without a token: they hold no
data. Everything else follows the API's rules: reads need the token unless the server
opens them (``open_reads``). The page asks for the token, keeps it in the tab's session
storage and sends it as a bearer header (events too: it reads the SSE stream with
``fetch``), never in a URL.

Mesh files are served only from the folders of meshes of robots in the cells this server
has loaded; the path is resolved (symlinks followed), then checked to be inside such a
folder, and only mesh and texture files are served.
"""

from __future__ import annotations

import re
import threading
from pathlib import Path
from typing import Annotated, Any

from fastapi import APIRouter, Depends, HTTPException, Request
from fastapi.responses import FileResponse, JSONResponse
from starlette.concurrency import run_in_threadpool

from taskrunner.api.admission import Admission
from taskrunner.api.auth import require_read
from taskrunner.api.cells import CellRegistry
from taskrunner.api.dependencies import (
    get_cells,
    get_checking,
    get_manager,
    get_planning,
    get_settings,
    get_work,
)
from taskrunner.api.requestwork import RequestWork, load_request
from taskrunner.api.runs import RunManager
from taskrunner.api.schemas import CheckRequest, ErrorBody
from taskrunner.api.settings import Settings
from taskrunner.folders import FileKind
from taskrunner.runtime.replay import scene_data
from taskrunner.viewer import STATIC_DIR
from taskrunner.viewer.describe import (
    MESH_TYPES,
    MeshRoots,
    describe_cell,
    describe_replay,
    describe_tree,
)

__all__ = ["router"]

router = APIRouter(tags=["viewer"])
_ERRORS: dict[int | str, dict[str, Any]] = {401: {"model": ErrorBody}, 404: {"model": ErrorBody},
                                            422: {"model": ErrorBody}}
_STATIC_NAME = re.compile(r"^[A-Za-z0-9_][A-Za-z0-9_.-]{0,100}$")
_STATIC_TYPES = {".html": "text/html; charset=utf-8", ".js": "text/javascript; charset=utf-8",
                 ".css": "text/css; charset=utf-8", ".map": "application/json",
                 ".svg": "image/svg+xml", ".png": "image/png"}
_NOT_FOUND = "no such file"


class TaskRequest(CheckRequest):
    """A task for the view: a file of the tasks folder or inline YAML, with parameters
    and a planner seed (as ``/tasks/check`` takes it)."""


def _static(name: str) -> FileResponse:
    if not _STATIC_NAME.match(name):
        raise HTTPException(404, _NOT_FOUND)
    path = (STATIC_DIR / name).resolve()
    kind = _STATIC_TYPES.get(path.suffix)
    if kind is None or not path.is_relative_to(STATIC_DIR) or not path.is_file():
        raise HTTPException(404, _NOT_FOUND)
    return FileResponse(path, media_type=kind, headers={"Cache-Control": "no-cache"})


@router.get("/", include_in_schema=False)
async def page() -> FileResponse:
    """The page (no token needed: it holds no data)."""
    return _static("index.html")


@router.get("/viewer/static/{name}", include_in_schema=False)
async def static_file(name: str) -> FileResponse:
    """The page's bundle and style sheet (no token needed)."""
    return _static(name)


@router.get("/viewer/cells/{cell_id}", dependencies=[Depends(require_read)], responses=_ERRORS)
def view_cell(cell_id: str, request: Request,
              cells: Annotated[CellRegistry, Depends(get_cells)]) -> JSONResponse:
    """A cell for the 3D view: its merged URDF (robots prefixed and placed; meshes as
    URLs under ``/viewer/meshes``), robots, joints with their limits, groups with their
    named poses (joint values), start state and fixed objects."""
    session = cells.by_id(cell_id)
    body = describe_cell(session.cell, cell_id, _mesh_roots(request, cells))
    return JSONResponse(body)


@router.get("/viewer/cells/{cell_id}/collision", dependencies=[Depends(require_read)],
            responses=_ERRORS)
def view_collision(cell_id: str, cells: Annotated[CellRegistry, Depends(get_cells)]
                   ) -> JSONResponse:
    """The robots' collision geometry as the planner checks it (each robot's exact
    meshes, convex hulls or primitives), each shape in its link's frame."""
    from taskrunner.viewer.collision import describe_collision

    return JSONResponse(describe_collision(cells.by_id(cell_id).cell))


def _mesh_roots(request: Request, cells: CellRegistry) -> MeshRoots:
    """The mesh folders of the cells loaded now (cells load, never unload)."""
    state = request.app.state
    lock = state.__dict__.setdefault("viewer_lock", threading.Lock())
    with lock:
        loaded = [s.cell for s in (cells.loaded(cells.cells_dir / f"{i}.yaml")
                                   for i in cells.ids()) if s is not None]
        roots = MeshRoots.of_cells(loaded)
        state.viewer_mesh_roots = roots
        return roots


@router.get("/viewer/meshes/{root}/{path:path}", dependencies=[Depends(require_read)],
            responses={401: {"model": ErrorBody}, 404: {"model": ErrorBody}})
def mesh_file(root: str, path: str, request: Request,
              cells: Annotated[CellRegistry, Depends(get_cells)]) -> FileResponse:
    """A mesh (STL, DAE, OBJ) or texture file of a robot in a loaded cell. Anything else,
    or a path out of the robot's mesh folder, is 404."""
    roots: MeshRoots | None = getattr(request.app.state, "viewer_mesh_roots", None)
    found = roots.file(root, path) if roots is not None else None
    if found is None:  # a cell loaded since: look again
        found = _mesh_roots(request, cells).file(root, path)
    if found is None:
        raise HTTPException(404, _NOT_FOUND)
    return FileResponse(found, media_type=MESH_TYPES[found.suffix.lower()])


@router.get("/viewer/tasks", dependencies=[Depends(require_read)], responses=_ERRORS)
def list_tasks(settings: Annotated[Settings, Depends(get_settings)]) -> list[str]:
    """The task files of the tasks folder, by name (without ``.yaml``)."""
    folder = settings.tasks_dir
    policy = settings.folder_policy()
    return sorted(p.stem for p in Path(folder).glob("*.yaml")
                  if policy.allows(p, FileKind.TASK))


@router.post("/viewer/tasks/tree", dependencies=[Depends(require_read)], responses=_ERRORS)
async def task_tree(body: TaskRequest, settings: Annotated[Settings, Depends(get_settings)],
                    cells: Annotated[CellRegistry, Depends(get_cells)],
                    work: Annotated[RequestWork, Depends(get_work)],
                    checking: Annotated[Admission, Depends(get_checking)]) -> JSONResponse:
    """The task compiled into its behaviour tree, each node with its file:line, the id
    of its cell, and the ``scene`` it starts in (joints, and the objects of the cell and
    of the task's file with their shapes and poses). Nothing is planned or moved."""
    async with checking.slot():
        spec, _, _ = await run_in_threadpool(work.call, load_request,
                                             settings.folder_policy(), settings.tasks_dir,
                                             body.task, body.yaml, body.parameters)
        tree, cell_id, scene = await run_in_threadpool(_compile, spec, cells)
    return JSONResponse({"task": spec.name, "cell": cell_id, "tree": tree, "scene": scene})


def _compile(spec: Any, cells: CellRegistry) -> tuple[dict[str, Any], str, dict[str, Any]]:
    from taskrunner.backends.mock import MockBackend
    from taskrunner.planning.service import InProcessPlanner
    from taskrunner.runtime.runner import Runner

    session = cells.session(spec.cell)
    cell = session.cell
    names = cell.model.joint_names
    backend = MockBackend(names, dict(zip(names, cell.start_state())))
    runner = Runner(spec, cell, backend, InProcessPlanner())  # compiled, never run
    scene = scene_data(runner.scene.snapshot())
    return describe_tree(runner.tree), cells.id_of(session.key), scene


@router.post("/viewer/tasks/preview", dependencies=[Depends(require_read)], responses=_ERRORS)
async def task_preview(body: TaskRequest,
                       settings: Annotated[Settings, Depends(get_settings)],
                       cells: Annotated[CellRegistry, Depends(get_cells)],
                       work: Annotated[RequestWork, Depends(get_work)],
                       planning: Annotated[Admission, Depends(get_planning)]) -> JSONResponse:
    """Plan only: the task run on a private mock controller from its cell's start state
    (nothing of the cell moves), each motion planned and timed as a run would; answers
    the motions and scenes as a replay, and how the dry run ended. Stopped past the
    server's ``plan_timeout_s``. Previews share ``max_planners`` with ``/plan``; beyond
    them and the ``work_queue``: 503 with ``Retry-After``."""
    async with planning.slot():
        return await run_in_threadpool(_preview, body, settings, cells, work)


def _preview(body: TaskRequest, settings: Settings, cells: CellRegistry,
             work: RequestWork) -> JSONResponse:
    from taskrunner.backends.mock import MockBackend
    from taskrunner.runtime.runner import Runner, RunOptions
    from taskrunner.tree.start import task_start

    spec, _, _ = work.call(load_request, settings.folder_policy(), settings.tasks_dir,
                           body.task, body.yaml, body.parameters)
    session = cells.session(spec.cell)
    cell = session.cell
    names = cell.model.joint_names
    planner = session.take_planner()
    try:
        start = task_start(spec, cell).q  # the check's start: a scene file's robot_state
        runner = Runner(spec, cell, MockBackend(names, dict(zip(names, start))),
                        planner, RunOptions(seed=body.seed, backend_name="preview",
                                            planner_times=True))
        timer = threading.Timer(settings.plan_timeout_s, runner.cancel,
                                kwargs={"reason": "the preview took longer than the server's "
                                                  "plan_timeout_s"})
        timer.start()
        try:
            record = runner.run()
        finally:
            timer.cancel()
    finally:
        session.give_planner(planner)
    answer = describe_replay(record)
    answer["cell"] = cells.id_of(session.key)
    answer["tree"] = describe_tree(runner.tree)
    answer["events"] = [e.as_dict() for e in record.events if e.kind != "motion"]
    return JSONResponse(answer)


@router.get("/viewer/runs/{run_id}/replay", dependencies=[Depends(require_read)],
            responses=_ERRORS)
def run_replay(run_id: str, manager: Annotated[RunManager, Depends(get_manager)]
               ) -> JSONResponse:
    """A run's motions (trajectories, the scene each started in, how far each got) and
    its first and final scenes, for the page's replay; the run it ``resumes`` and the runs
    ``resumed_by`` it (one story, linked both ways)."""
    record = manager.record(run_id)
    answer = describe_replay(record)
    answer["resumes"] = record.resumes or None
    answer["resumed_by"] = manager.store.resumed_by(run_id)
    return JSONResponse(answer)


@router.get("/viewer/runs/{run_id}/tree", dependencies=[Depends(require_read)],
            responses=_ERRORS)
def run_tree(run_id: str, manager: Annotated[RunManager, Depends(get_manager)]
             ) -> JSONResponse:
    """The compiled tree of a run this server holds in memory, each node with its
    file:line and status (404 for older runs: their tree is in ``GET /runs/{id}`` as
    text)."""
    live = manager.live(run_id)
    if live is None:
        manager.record(run_id)  # 404 if unknown
        raise HTTPException(404, f"run {run_id!r} is no longer in memory; its tree is the "
                                 "text of GET /runs/{id}")
    return JSONResponse({"run_id": run_id, "tree": describe_tree(live.runner.tree)})
