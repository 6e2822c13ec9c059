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
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from taskrunner.backends.base import Backend
from taskrunner.backends.sim import SimBackend, SimOptions
from taskrunner.errors import ArgumentError, ConflictError, InputError, NotFoundError
from taskrunner.folders import FileKind, FolderPolicy
from taskrunner.kinds import BackendKind
from taskrunner.resources import cell_files
from taskrunner.robot.cell import Cell, load_cell
from taskrunner.robot.options import LoadOptions
from taskrunner.runtime.session import make_backend
from taskrunner.scene import Scene
from taskrunner.taught import apply_taught

__all__ = ["BACKENDS", "CellNotFoundError", "CellRegistry", "CellSession", "PoseConflictError"]

_CLOSE_WAIT = 1.0  # s: a new worker's start looks again for idle ones this often

log = logging.getLogger(__name__)

BACKENDS = tuple(kind.value for kind in BackendKind)


class CellNotFoundError(NotFoundError):
    """No cell file of that id in the cells folder."""

    def __init__(self, cell_id: str, known: list[str]) -> None:
        self.cell_id = cell_id
        self.known = known
        shown = ", ".join(repr(k) for k in known) or "none"
        super().__init__(f"unknown cell {cell_id!r}; known: {shown}")


class PoseConflictError(ConflictError):
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
    # Idle planning workers, each with the time.monotonic() it was given back at.
    idle_planners: list[tuple[Any, float]] = field(default_factory=list)
    last_scene: Scene | None = None
    lock: threading.Lock = field(default_factory=threading.Lock)
    taught: set[tuple[str, str]] = field(default_factory=set)
    servo_port: str | None = None
    servo_url: str | None = None
    firmware_speedup: float = 1.0
    options: LoadOptions | None = None
    # Idle workers being closed now (:meth:`reap_planners`), and the condition (on ``lock``)
    # a new worker's start waits on until they have ended.
    closing: int = 0
    closed: threading.Condition = field(init=False)

    def __post_init__(self) -> None:
        self.closed = threading.Condition(self.lock)

    def teach(self, group: str, name: str, joints: dict[str, float]) -> None:
        """Make ``name`` a named pose of ``group`` in this cell's model (runs compiled from
        now on resolve it here and send the joint values to the planner)."""
        self.cell.model.named_states.setdefault(group, {})[name] = dict(joints)
        self.taught.add((group, name))

    def backend(self, kind: str) -> Backend:
        """The cell's backend of ``kind``, made on first use: mock and sim at the cell's
        start state, serial and http on the servos of the cell's one robot (its
        hardware.yaml; the port and URL the server is set up with) where they are,
        feetech on the buses of the cell's ``<cell>.hardware.yaml`` (its ports and
        calibration files; the server's servo port is the ESP32's, not used).

        Raises:
            InputError: a servo backend the cell or the server is not set up for.
            BackendError: the servos' port or URL does not answer as the firmware does.
        """
        if kind not in BACKENDS:
            raise ArgumentError(f"'backend' must be one of {', '.join(BACKENDS)} (got {kind!r})")
        with self.lock:
            if kind not in self.backends:
                if kind == "http" and not self.servo_url:
                    raise InputError("this server drives no servos over http: its "
                                     "'servo_url' setting (TASKRUNNER_SERVO_URL) is not set")
                self.backends[kind] = make_backend(
                    kind, self.cell, self.speeds.get(kind),
                    port=self.servo_port if kind != "feetech" else None,
                    url=self.servo_url, firmware_speedup=self.firmware_speedup)
            return self.backends[kind]

    def sim_at_speed(self, speed: float, busy: bool) -> None:
        """Make the cell's sim backend play at ``speed`` (a new controller at the joint
        state of the old one). ``busy``: runs move the cell now.

        Raises:
            PoseConflictError: runs move the cell at another speed (409).
        """
        current = self.backend("sim")
        if (self.speeds.get("sim") or 1.0) == speed:
            return
        if busy:
            raise PoseConflictError(f"runs move cell {self.cell.name!r} now: its sim speed "
                                    "changes only while it is still (or ask for the same "
                                    "speed)")
        state = current.joint_state()
        with self.lock:
            fresh = SimBackend(list(state.names), dict(zip(state.names, state.positions)),
                               SimOptions(speed=speed))
            old, self.backends["sim"] = self.backends["sim"], fresh
            self.speeds = {**self.speeds, "sim": speed}  # this cell's only
        old.close()

    def take_planner(self) -> Any:
        """A plan service for one user at a time (give it back with :meth:`give_planner`)."""
        if self.planner_kind == "inprocess":
            from taskrunner.planning.service import InProcessPlanner

            return InProcessPlanner()
        with self.lock:
            # Not one process more than the workers in use and idle: where idle ones are
            # being closed, a new one starts once they have ended (a close takes a few
            # ms; up to 10 s for a worker that does not stop).
            while True:
                if self.idle_planners:
                    worker, _ = self.idle_planners.pop()
                    # The worker sends a scene snapshot when (id(scene), revision)
                    # changes; a new run's scene may reuse a freed scene's id: make it
                    # send one.
                    worker._sent_scene = None
                    return worker
                if not self.closing:
                    break
                self.closed.wait(timeout=_CLOSE_WAIT)
        from taskrunner.planning.worker import PlanningWorker

        return PlanningWorker(self.key, wait_ready=False, nice=self.planner_nice,
                              options=self.options)

    def give_planner(self, planner: Any) -> None:
        if self.planner_kind == "inprocess":
            planner.close()
            return
        with self.lock:
            self.idle_planners.append((planner, time.monotonic()))
            self.closed.notify_all()  # a start waiting on a close takes this one instead

    def reap_planners(self, idle_s: float) -> int:
        """Close the planning workers idle for ``idle_s`` or longer; how many."""
        now = time.monotonic()
        with self.lock:
            old = [p for p, since in self.idle_planners if now - since >= idle_s]
            self.idle_planners = [(p, since) for p, since in self.idle_planners
                                  if now - since < idle_s]
            self.closing += len(old)
        try:
            for planner in old:
                planner.close()
        finally:
            with self.lock:
                self.closing -= len(old)
                self.closed.notify_all()
        return len(old)

    def close(self) -> None:
        with self.lock:
            for backend in self.backends.values():
                backend.close()
            for planner, _ in self.idle_planners:
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
                 policy: FolderPolicy | None = None, servo_port: str | None = None,
                 servo_url: str | None = None, firmware_speedup: float = 1.0,
                 options: LoadOptions | None = None) -> None:
        self.cells_dir = cells_dir
        self.options = options
        self.policy = policy
        self.servo_port = servo_port
        self.servo_url = servo_url
        self.firmware_speedup = firmware_speedup
        self._store = store
        self._speeds = speeds
        self._planner_kind = planner_kind
        self._planner_nice = planner_nice
        self._sessions: dict[Path, CellSession] = {}
        self._lock = threading.Lock()

    def ids(self) -> list[str]:
        """The ids of the cell files, sorted: the cells a task names by name too
        (:func:`~taskrunner.resources.cell_files`: ``servo_arm_pair.hardware.yaml`` is
        not one); a symlink out of the folders the policy allows is not a cell."""
        return [name for name, p in cell_files(self.cells_dir).items()
                if self.policy is None or self.policy.allows(p, FileKind.CELL)]

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
        cell = load_cell(path, policy=self.policy, options=self.options)
        fresh = CellSession(path, cell, self._speeds, self._planner_kind, self._planner_nice,
                            servo_port=self.servo_port, servo_url=self.servo_url,
                            firmware_speedup=self.firmware_speedup, options=self.options)
        if self._store is not None:
            for pose in apply_taught(cell, self._store.taught_poses(self.cells_dir)):
                fresh.taught.add((pose.group, pose.name))
        with self._lock:
            session = self._sessions.setdefault(path, fresh)
        settle_heap()  # the cell lives as long as the server
        return session

    def by_id(self, cell_id: str) -> CellSession:
        return self.session(self.path_of(cell_id))

    def loaded(self, path: Path) -> CellSession | None:
        with self._lock:
            return self._sessions.get(path.resolve())

    def reap_planners(self, idle_s: float) -> int:
        """Close every cell's planning workers idle for ``idle_s`` or longer; how many."""
        with self._lock:
            sessions = list(self._sessions.values())
        return sum(session.reap_planners(idle_s) for session in sessions)

    def close(self) -> None:
        with self._lock:
            sessions = list(self._sessions.values())
            self._sessions.clear()
        for session in sessions:
            session.close()
