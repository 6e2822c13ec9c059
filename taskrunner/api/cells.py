"""The cells the server drives: loaded once, one backend per cell and kind, planners pooled.

Every run on a cell drives the same backend (per kind: ``sim`` or ``mock``), so the
robot's state is one and consistent: two runs on different arms of one cell are two
trajectories over disjoint joints of one controller. Planning workers are pooled per cell:
a run takes one for its whole length and gives it back, so the next run of that cell
does not wait for a process to load the model, and two runs never share one.
"""

from __future__ import annotations

import gc
import logging
import threading
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from taskrunner.backends.base import Backend
from taskrunner.folders import FolderPolicy
from taskrunner.robot.cell import Cell, load_cell
from taskrunner.runtime.session import make_backend
from taskrunner.scene import Scene

__all__ = ["BACKENDS", "CellNotFoundError", "CellRegistry", "CellSession", "PoseConflictError"]

log = logging.getLogger(__name__)

BACKENDS = ("sim", "mock")


class CellNotFoundError(LookupError):
    """No cell file of that id in the cells folder."""

    def __init__(self, cell_id: str, known: list[str]) -> None:
        self.cell_id = cell_id
        self.known = known
        shown = ", ".join(repr(k) for k in known) or "none"
        super().__init__(f"unknown cell {cell_id!r}; known: {shown}")


class PoseConflictError(RuntimeError):
    """A pose cannot be taught now: the name belongs to the robot files, or runs move the
    cell (HTTP 409)."""


@dataclass
class CellSession:
    """One loaded cell with its backends, its idle planners and its last scene."""

    key: Path
    cell: Cell
    speeds: dict[str, float | None]
    planner_kind: str
    planner_nice: int = 0
    backends: dict[str, Backend] = field(default_factory=dict)
    idle_planners: list[Any] = field(default_factory=list)
    last_scene: Scene | None = None
    lock: threading.Lock = field(default_factory=threading.Lock)
    taught: set[tuple[str, str]] = field(default_factory=set)

    def teach(self, group: str, name: str, joints: dict[str, float]) -> None:
        """Make ``name`` a named pose of ``group`` in this cell's model (runs compiled from
        now on resolve it here and send the joint values to the planner)."""
        self.cell.model.named_states.setdefault(group, {})[name] = dict(joints)
        self.taught.add((group, name))

    def backend(self, kind: str) -> Backend:
        """The cell's backend of ``kind``, made at the cell's start state on first use."""
        if kind not in BACKENDS:
            raise ValueError(f"'backend' must be one of {', '.join(BACKENDS)} (got {kind!r})")
        with self.lock:
            if kind not in self.backends:
                self.backends[kind] = make_backend(kind, self.cell, self.speeds.get(kind))
            return self.backends[kind]

    def take_planner(self) -> Any:
        """A plan service for one user at a time (give it back with :meth:`give_planner`)."""
        if self.planner_kind == "inprocess":
            from taskrunner.planning.service import InProcessPlanner

            return InProcessPlanner()
        with self.lock:
            if self.idle_planners:
                worker = self.idle_planners.pop()
                # The worker sends a scene snapshot when (id(scene), revision) changes; a
                # new run's scene may reuse a freed scene's id: make it send one.
                worker._sent_scene = None
                return worker
        from taskrunner.planning.worker import PlanningWorker

        return PlanningWorker(self.key, wait_ready=False, nice=self.planner_nice)

    def give_planner(self, planner: Any) -> None:
        if self.planner_kind == "inprocess":
            planner.close()
            return
        with self.lock:
            self.idle_planners.append(planner)

    def close(self) -> None:
        with self.lock:
            for backend in self.backends.values():
                backend.close()
            for planner in self.idle_planners:
                planner.close()
            self.backends.clear()
            self.idle_planners.clear()


def settle_heap() -> None:
    """Move every object alive now out of the garbage collector's reach (``gc.freeze``).

    A server's long-lived objects (imported modules, the app, loaded cells: 100,000+)
    made each full collection pause every thread for 50-120 ms, the tail of the request
    latency. Frozen objects are never scanned again; garbage is collected first, so
    none is frozen. Call it after loading something that lives as long as the server.
    """
    gc.collect()
    gc.freeze()


class CellRegistry:
    """Cells by id (file name in ``cells_dir`` without ``.yaml``) and by path."""

    def __init__(self, cells_dir: Path, speeds: dict[str, float | None],
                 planner_kind: str, store: Any = None, planner_nice: int = 0,
                 policy: FolderPolicy | None = None) -> None:
        self.cells_dir = cells_dir
        self.policy = policy
        self._store = store
        self._speeds = speeds
        self._planner_kind = planner_kind
        self._planner_nice = planner_nice
        self._sessions: dict[Path, CellSession] = {}
        self._lock = threading.Lock()

    def ids(self) -> list[str]:
        """The ids of the cell files, sorted."""
        return sorted(p.stem for p in self.cells_dir.glob("*.yaml"))

    def path_of(self, cell_id: str) -> Path:
        """The file of cell ``cell_id``.

        Raises:
            CellNotFoundError: no such cell file (ids are plain file names).
        """
        known = self.ids()
        if cell_id not in known:
            raise CellNotFoundError(cell_id, known)
        return (self.cells_dir / f"{cell_id}.yaml").resolve()

    def id_of(self, path: Path) -> str:
        """The id of a cell file: its stem inside ``cells_dir``, else its path."""
        path = path.resolve()
        return path.stem if path.parent == self.cells_dir.resolve() else str(path)

    def session(self, path: Path) -> CellSession:
        """The session of the cell file ``path``, loading it on first use.

        Raises:
            YamlError, RobotDescriptionError: the cell is invalid.
        """
        path = path.resolve()
        with self._lock:
            session = self._sessions.get(path)
        if session is not None:
            return session
        # Outside the lock (loading meshes takes a while); under the folder policy: a
        # task may name any cell file, only those of the allowed folders load.
        cell = load_cell(path, policy=self.policy)
        fresh = CellSession(path, cell, self._speeds, self._planner_kind, self._planner_nice)
        if self._store is not None:
            for group, name, joints, _ in self._store.poses(self.id_of(path)):
                if group in cell.model.groups and all(
                        j in cell.model.group(group).joint_names for j in joints) \
                        and cell.model.within_limits(cell.model.state_with(
                            cell.model.default_state(), joints)):
                    fresh.teach(group, name, joints)
                else:
                    log.warning("taught pose %r of group %r no longer fits cell %s: skipped",
                                name, group, path)
        with self._lock:
            session = self._sessions.setdefault(path, fresh)
        settle_heap()  # the cell lives as long as the server
        return session

    def by_id(self, cell_id: str) -> CellSession:
        return self.session(self.path_of(cell_id))

    def loaded(self, path: Path) -> CellSession | None:
        with self._lock:
            return self._sessions.get(path.resolve())

    def close(self) -> None:
        with self._lock:
            sessions = list(self._sessions.values())
            self._sessions.clear()
        for session in sessions:
            session.close()
