"""Runs in flight: each on its own thread, on its cell's shared backend, recorded in SQLite.

**Arms in use: refused, not queued.** A run declares the joints it can move (the groups
its steps move, :func:`~taskrunner.tasks.names.moved_groups`, and their joints). A run
whose joints overlap those of a run in flight on the same cell is refused with
:class:`ArmBusyError` (HTTP 409, naming the run that holds them); runs on disjoint joints
run at once. Refusing keeps the outcome of a request immediate and predictable: the
caller knows at once whether its run started and can retry or cancel the other run,
and a run never starts minutes later, when the situation it was meant for is gone.

Runs on different arms of one cell share the backend, so each sees the other's arm where
the controller reports it at every motion's start and end; the planner does not predict
where the other arm will be during a motion.
"""

from __future__ import annotations

import logging
import sqlite3
import threading
from dataclasses import dataclass, field
from typing import TYPE_CHECKING, Any

from taskrunner.api.cells import BACKENDS, CellRegistry, CellSession
from taskrunner.api.detail import DEFAULT_LIMIT, RunDetailCache, RunListCache, StoredDetails
from taskrunner.api.store import RunStore, StoreJournal
from taskrunner.errors import (
    ArgumentError,
    ConflictError,
    NotFoundError,
    TaskrunnerError,
    UnavailableError,
)
from taskrunner.kinds import RunStatus
from taskrunner.robot.options import LoadOptions
from taskrunner.runtime.events import EventLog, RunEvent
from taskrunner.runtime.records import RunRecord
from taskrunner.runtime.runner import EXIT_CODES, Runner, RunOptions
from taskrunner.tasks import check_names, raise_for_problems
from taskrunner.tasks.names import moved_groups
from taskrunner.tasks.spec import TaskSpec

if TYPE_CHECKING:
    from taskrunner.export.cellfeeds import CellFeeds
    from taskrunner.runtime.resume import ResumePlan

__all__ = ["ArmBusyError", "LiveRun", "RunManager", "RunNotFinishedError", "RunNotFoundError"]

_STOPPED = "the server stopped while the run was in flight"
_OUTLIVED = ("it did not stop within the server's shutdown timeout, so its row says "
             "'interrupted', with the events it appended before the database was closed")

log = logging.getLogger(__name__)


class RunNotFoundError(NotFoundError):
    """No run of that id, in flight or recorded."""

    def __init__(self, run_id: str) -> None:
        self.run_id = run_id
        super().__init__(f"unknown run {run_id!r}")


class RunNotFinishedError(ConflictError):
    """Cancelling a run that has already ended."""


class ArmBusyError(ConflictError):
    """A run would move joints that a run in flight moves."""

    def __init__(self, holder: str, joints: list[str]) -> None:
        self.holder = holder
        self.joints = joints
        shown = ", ".join(repr(j) for j in joints[:8])
        super().__init__(f"run {holder!r} is moving joint(s) {shown} of this cell; wait for "
                         "it to end or cancel it (runs that need an arm in use are refused, "
                         "not queued)")


@dataclass
class LiveRun:
    """A run this server started (kept for a while after it ends: see
    :class:`RunManager`'s ``keep_finished``)."""

    runner: Runner
    session: CellSession
    joints: frozenset[str]
    thread: threading.Thread | None = None
    final_tree: str | None = None
    planner: Any = None
    journal: StoreJournal | None = None
    feed: tuple[Any, Any] | None = None  # (CellFeed, its follow of this run)
    done: threading.Event = field(default_factory=threading.Event)
    detail: RunDetailCache = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        self.detail = RunDetailCache(self)

    @property
    def run_id(self) -> str:
        return self.runner.record.run_id

    @property
    def record(self) -> RunRecord:
        return self.runner.record

    @property
    def events(self) -> EventLog:
        return self.runner.events

    def tree(self) -> str:
        return self.final_tree if self.final_tree is not None else self.runner.snapshot()

    def current(self) -> tuple[str, str | None] | None:
        """The leaf running now and its file:line; None once the run has ended (its
        status set, even before its thread has finished recording it)."""
        if self.done.is_set() or self.record.status != "running":
            return None
        leaf = self.runner.current_leaf()
        return None if leaf is None else (leaf.name, leaf.location)


class RunManager:
    """Starts runs, refuses those whose arms are in use, records every run.

    A run stays in memory while it runs and, once ended, among the ``keep_finished``
    newest ended runs; older ones are answered from the database (record and final tree),
    so a server that runs for months holds no more than that many runs' trees, scenes
    and trajectories.
    """

    def __init__(self, cells: CellRegistry, store: RunStore, tick_hz: float = 100.0,
                 keep_finished: int = 32, feeds: CellFeeds | None = None) -> None:
        if keep_finished < 0:
            raise ArgumentError(f"'keep_finished' must be >= 0 (got {keep_finished})")
        self.cells = cells
        self.store = store
        self.tick_hz = tick_hz
        self.keep_finished = keep_finished
        self.feeds = feeds  # the live Foxglove feeds (serve --foxglove), one per cell
        self._runs: dict[str, LiveRun] = {}
        # Joints claimed per run in flight (or being built): (session, joints, run id).
        self._claims: dict[int, tuple[CellSession, frozenset[str], str]] = {}
        self._lock = threading.Lock()
        self._stopping = False
        self._stored = StoredDetails(store)
        self.listing = RunListCache(store)

    # ----------------------------------------------------------------- starting
    def start(self, spec: TaskSpec, backend: str, seed: int = 0, task_text: str | None = None,
              task_file: str | None = None, speed: float | None = None,
              resume: ResumePlan | None = None) -> LiveRun:
        """Check ``spec``'s names against its cell, claim its joints and start it
        (``resume``: continuing the run it was planned from, see
        :mod:`taskrunner.runtime.resume`).

        Raises:
            TaskSpecError: the task names what its cell does not have (every problem).
            YamlError, RobotDescriptionError: the cell is invalid.
            ArmBusyError: a run in flight moves some of the same joints.
            PoseConflictError: ``speed`` differs from that of sim runs in flight.
        """
        if backend not in BACKENDS:
            raise ArgumentError(f"'backend' must be one of {', '.join(BACKENDS)} (got {backend!r})")
        session = self.cells.session(spec.cell)
        raise_for_problems(check_names(spec, session.cell))
        joints = self._joints(spec, session)
        claim = object()
        with self._lock:
            if self._stopping:
                raise UnavailableError("the server is shutting down")
            self._claim_check(session, joints)
            if speed is not None and backend == "sim":
                busy = any(other is session for other, _, _ in self._claims.values())
                session.sim_at_speed(speed, busy)
            self._claims[id(claim)] = (session, joints, "(starting)")
        # Build the run outside the lock (scene and tree take a while), its joints claimed.
        planner = None
        try:
            machine = session.backend(backend)
            planner = session.take_planner()
            runner = Runner(spec, session.cell, machine, planner,
                            RunOptions(tick_hz=self.tick_hz, seed=seed, backend_name=backend,
                                       planner_times=True,
                                       load_options=(session.options or LoadOptions()).as_data()),
                            events=EventLog(), resume=resume)
        except BaseException:
            with self._lock:
                self._claims.pop(id(claim), None)
            if planner is not None:
                session.give_planner(planner)
            raise
        live = LiveRun(runner, session, joints, planner=planner)
        if task_text is not None:
            runner.record.task_text = task_text
        if task_file is not None:
            runner.record.task_file = task_file
        runner.record.cell = self.cells.id_of(session.key)
        with self._lock:
            self._claims.pop(id(claim), None)
            self._claims[id(live)] = (session, joints, live.run_id)
            self._runs[live.run_id] = live
        # Every event is appended to the database before anyone can see it (a server
        # killed mid-run keeps all a client was shown); the run's row is written now and
        # at its end, never in between.
        live.journal = StoreJournal(self.store, live.run_id)
        earlier = runner.events.set_journal(live.journal)
        try:
            self.store.save(live.record, events=earlier)
        except BaseException:
            with self._lock:
                self._claims.pop(id(live), None)
                self._runs.pop(live.run_id, None)
            session.give_planner(planner)
            raise
        if self.feeds is not None:  # the feed only queues the run's events: never waits
            feed = self.feeds.feed(runner.record.cell or "", session.cell)
            if feed is not None:
                live.feed = (feed, feed.attach(runner, joints))
        live.thread = threading.Thread(target=self._run, args=(live,), daemon=True,
                                       name=f"run-{live.run_id}")
        live.thread.start()
        return live

    def _joints(self, spec: TaskSpec, session: CellSession) -> frozenset[str]:
        model = session.cell.model
        groups: list[str] = []
        for step in spec.steps:
            groups += moved_groups(step, model)
        return frozenset(j for g in dict.fromkeys(groups) for j in model.group(g).joint_names)

    def _claim_check(self, session: CellSession, joints: frozenset[str]) -> None:
        for other, held, holder in self._claims.values():
            shared = sorted(joints & held) if other is session else []
            if shared:
                raise ArmBusyError(holder, shared)

    def _run(self, live: LiveRun) -> None:
        try:
            live.runner.run()
        except TaskrunnerError as exc:  # the runner turns ours into failures; be sure
            live.record.status, live.record.error = "failed", str(exc)
        finally:
            if self._stopping and live.record.status in ("cancelled", "running"):
                live.record.status = "interrupted"
                live.record.error = _STOPPED
            if live.feed is not None:
                live.feed[0].detach(live.feed[1])
            live.final_tree = live.runner.snapshot()
            live.session.last_scene = live.runner.scene
            live.session.give_planner(live.planner)
            # The row once more; events again only if an append failed on the way.
            failed = live.journal is not None and live.journal.failed > 0
            try:
                self.store.save(live.record, tree=live.final_tree,
                                events=None if failed else ())
            except sqlite3.Error as exc:
                # A run that outlived the server's wait at shutdown finds its database
                # closed (its row was written 'interrupted' then); a full disk fails the
                # same way. Either way the end is not recorded: say so, and let go.
                log.error("run %s ended %s but its final record was not written to %s (%s)%s",
                          live.run_id, live.record.status, self.store.path, exc,
                          f": {_OUTLIVED}" if self._stopping else "")
            finally:
                with self._lock:
                    self._claims.pop(id(live), None)
                live.done.set()
            self._forget_finished()

    def _forget_finished(self) -> None:
        """Drop the oldest ended runs beyond ``keep_finished`` (they are in the store)."""
        with self._lock:
            ended = [run_id for run_id, r in self._runs.items() if r.done.is_set()]
            for run_id in ended[:max(0, len(ended) - self.keep_finished)]:
                del self._runs[run_id]

    # ----------------------------------------------------------------- queries
    def live(self, run_id: str) -> LiveRun | None:
        with self._lock:
            return self._runs.get(run_id)

    def in_flight(self) -> int:
        """How many runs are in flight."""
        with self._lock:
            return sum(not r.done.is_set() for r in self._runs.values())

    def running_on(self, session: CellSession) -> list[LiveRun]:
        with self._lock:
            return [r for r in self._runs.values()
                    if r.session is session and not r.done.is_set()]

    def moving_on(self, session: CellSession) -> list[LiveRun]:
        """The runs on ``session`` that have not ended: a run whose record is final moves
        nothing more, though its thread may still be saving it (a client told the run
        succeeded may teach at once)."""
        with self._lock:
            return [r for r in self._runs.values() if r.session is session and not _ended(r)]

    def record(self, run_id: str) -> RunRecord:
        """The record of ``run_id``: live if this server runs it, else from the database.

        Raises:
            RunNotFoundError: no such run.
        """
        live = self.live(run_id)
        if live is not None:
            return live.record
        record = self.store.load(run_id)
        if record is None:
            raise RunNotFoundError(run_id)
        return record

    def detail(self, run_id: str, since: int = 0, limit: int = DEFAULT_LIMIT) -> bytes:
        """The ``GET /runs/{id}`` body (JSON of :class:`~api.schemas.RunDetail`) with the
        events of ``seq > since``, at most ``limit`` of them; the default page is rebuilt
        only if the run changed since it was last built. May block (database, rendering).

        Raises:
            RunNotFoundError: no such run.
            ValueError: ``since`` or ``limit`` out of range.
        """
        live = self.live(run_id)
        if live is not None:
            if (since, limit) == (0, DEFAULT_LIMIT):
                return live.detail.body()
            return live.detail.page(since, limit)
        body = self._stored.body(run_id, since, limit)
        if body is None:
            raise RunNotFoundError(run_id)
        return body

    def events_after(self, run_id: str, after: int) -> tuple[list[RunEvent], bool]:
        """Events with ``seq > after`` and whether more may come."""
        live = self.live(run_id)
        if live is not None:
            finished = live.done.is_set()
            return live.events.events(after), not finished
        if self.store.load_row(run_id) is None:
            raise RunNotFoundError(run_id)
        return self.store.events(run_id, after)[0], False

    # ----------------------------------------------------------------- control
    def cancel_live(self, run_id: str) -> LiveRun | None:
        """Cancel ``run_id`` if it is in flight on this server (never blocks: safe on the
        event loop); None if it is not (ended or unknown: see :meth:`cancel`)."""
        live = self.live(run_id)
        if live is None or _ended(live):
            return None
        live.runner.cancel()
        return live

    def cancel(self, run_id: str) -> LiveRun:
        """Stop a run in flight: its motion stops where it is, it ends as cancelled.

        Raises:
            RunNotFoundError: no such run.
            RunNotFinishedError: the run has already ended (the message says how).
        """
        live = self.live(run_id)
        if live is None:
            status = self.record(run_id).status
            raise RunNotFinishedError(f"run {run_id!r} has already ended ({status})")
        if _ended(live):
            raise RunNotFinishedError(f"run {run_id!r} has already ended ({live.record.status})")
        live.runner.cancel()
        return live

    def shutdown(self, timeout: float) -> None:
        """Cancel every run in flight and record each as interrupted, with exit code 143
        (terminated, 128 + SIGTERM: the server was told to stop, as a service manager
        stops it; the lifespan is not told which signal it was, so Ctrl-C at a server in
        a terminal is recorded the same)."""
        with self._lock:
            self._stopping = True
            runs = [r for r in self._runs.values() if not r.done.is_set()]
        for live in runs:
            live.runner.cancel(_STOPPED, EXIT_CODES["terminated"])
        for live in runs:
            if live.thread is not None:
                live.thread.join(timeout)
            if not live.done.is_set():  # stuck: record it all the same
                log.error("run %s did not stop within %.1f s of its cancel: recorded as "
                          "interrupted now, with the events it appended so far", live.run_id,
                          timeout)
                live.record.status = "interrupted"
                live.record.error = _STOPPED
                live.record.exit_code = EXIT_CODES["terminated"]
                self.store.save(live.record, tree=live.runner.snapshot())


def _ended(live: LiveRun) -> bool:
    """Whether a live run has ended: its thread is done, or its record already says how it
    ended (the record is final a moment before the thread lets go of the arm; a cancel in
    between is "already ended", never a second 202)."""
    return live.done.is_set() or live.record.status != RunStatus.RUNNING
