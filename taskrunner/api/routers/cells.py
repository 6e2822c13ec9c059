"""``/cells``: the cells, their robots, groups, poses and objects, and their live state."""

from __future__ import annotations

import re
from typing import Annotated, Any

from fastapi import APIRouter, Depends

from taskrunner.api.auth import require_read, require_write
from taskrunner.api.cells import BACKENDS, CellRegistry, PoseConflictError
from taskrunner.api.dependencies import get_cells, get_manager, get_store
from taskrunner.api.runs import RunManager
from taskrunner.api.schemas import (
    CellDetail,
    CellState,
    CellSummary,
    ErrorBody,
    TaughtPose,
    TeachRequest,
)
from taskrunner.api.store import RunStore
from taskrunner.errors import ArgumentError, TaskrunnerError
from taskrunner.yamlfile import load_yaml

__all__ = ["router"]

router = APIRouter(prefix="/cells", tags=["cells"], dependencies=[Depends(require_read)])
_ERRORS: dict[int | str, dict[str, Any]] = {
    401: {"model": ErrorBody}, 404: {"model": ErrorBody}, 422: {"model": ErrorBody}}


@router.get("", response_model=list[CellSummary], responses=_ERRORS)
def list_cells(cells: Annotated[CellRegistry, Depends(get_cells)]) -> list[CellSummary]:
    """The cell files of the cells folder (read without loading their robots)."""
    out = []
    for cell_id in cells.ids():
        try:  # the one YAML reader, with its limits (size, depth, aliases)
            doc = load_yaml(cells.cells_dir / f"{cell_id}.yaml")
        except (OSError, TaskrunnerError):
            doc = None
        doc = doc if isinstance(doc, dict) else {}
        out.append(CellSummary(id=cell_id, name=str(doc.get("name", cell_id)),
                               description=str(doc.get("description", ""))))
    return out


@router.get("/{cell_id}", response_model=CellDetail, responses=_ERRORS)
def get_cell(cell_id: str, cells: Annotated[CellRegistry, Depends(get_cells)]) -> CellDetail:
    """A cell's robots (placement in the world, m), groups with their named poses, and
    fixed objects."""
    cell = cells.by_id(cell_id).cell
    model = cell.model
    return CellDetail(
        id=cell_id, name=cell.name, description=cell.description,
        robots=[{"name": i.name, "prefix": i.prefix,  # type: ignore[misc]
                 "xyz": [float(v) for v in i.base.translation]} for i in model.instances],
        groups=[{"name": g.name, "joints": list(g.joint_names),  # type: ignore[misc]
                 "tip_link": g.tip_link, "poses": model.named_state_names(g.name)}
                for g in model.groups.values()],
        objects=[{"name": o.name, "shape": type(o.shape).__name__.lower(),  # type: ignore[misc]
                  "frame": o.frame, "xyz": [float(v) for v in o.pose.translation]}
                 for o in cell.objects])


@router.get("/{cell_id}/state", response_model=CellState, responses=_ERRORS)
def cell_state(cell_id: str, cells: Annotated[CellRegistry, Depends(get_cells)],
               manager: Annotated[RunManager, Depends(get_manager)],
               backend: str = "sim") -> CellState:
    """Joint positions (rad or m) as the cell's backend reports them now, the objects
    attached to its links (in the newest run's scene), and the runs in flight."""
    if backend not in BACKENDS:
        raise ArgumentError(f"'backend' must be one of {', '.join(BACKENDS)} (got {backend!r})")
    session = cells.by_id(cell_id)
    state = session.backend(backend).joint_state()
    running = manager.running_on(session)
    scene = running[-1].runner.scene if running else session.last_scene
    attached = [] if scene is None else [
        {"name": o.name, "link": o.attached_to} for o in scene.attached_objects()]
    return CellState(id=cell_id, backend=backend,
                     joints={n: float(v) for n, v in zip(state.names, state.positions)},
                     attached=attached,  # type: ignore[arg-type]
                     running=[r.run_id for r in running])


_POSE_NAME = re.compile(r"^[A-Za-z_][A-Za-z0-9_\-]{0,63}$")


@router.put("/{cell_id}/poses/{name}", response_model=TaughtPose,
            responses={**_ERRORS, 409: {"model": ErrorBody}},
            dependencies=[Depends(require_write)])
def teach_pose(cell_id: str, name: str, body: TeachRequest,
               cells: Annotated[CellRegistry, Depends(get_cells)],
               manager: Annotated[RunManager, Depends(get_manager)],
               store: Annotated[RunStore, Depends(get_store)]) -> TaughtPose:
    """Teach: store the group's joints as the cell's backend reports them now as named
    pose ``name`` (kept in the server's database, there after a restart). Tasks use it
    like any named pose. A pose of the robot's own files cannot be replaced (409); a
    taught one can. Refused while a run moves the group (409)."""
    if not _POSE_NAME.match(name):
        raise ArgumentError(f"'name' must be a letter or _ then letters, digits, _ or - "
                         f"(got {name!r})")
    if body.backend not in BACKENDS:
        raise ArgumentError(f"'backend' must be one of {', '.join(BACKENDS)} (got {body.backend!r})")
    session = cells.by_id(cell_id)
    model = session.cell.model
    group = model.group(body.group)
    existing = model.named_states.get(group.name, {})
    if name in existing and (group.name, name) not in session.taught:
        raise PoseConflictError(f"named pose {name!r} of group {group.name!r} comes from the robot "
                           "or cell files; pick another name")
    busy = [r.run_id for r in manager.moving_on(session)]
    if busy:
        raise PoseConflictError(f"runs {busy} are moving cell {cell_id!r}: teach when it is still")
    reported = session.backend(body.backend).joint_state()
    state = dict(zip(reported.names, reported.positions))
    joints = {j: float(state[j]) for j in group.joint_names}
    bad = model.limit_violations(model.state_with(model.default_state(), joints))
    if bad:
        raise ArgumentError("the current state is outside the joint limits: " + "; ".join(bad))
    taught = store.save_pose(cell_id, group.name, name, joints)
    session.teach(group.name, name, joints)
    return TaughtPose(cell=cell_id, group=group.name, name=name, joints=joints, taught=taught)
