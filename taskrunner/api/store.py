"""Run records in SQLite: a row per run (the record without its events, as JSON, beside a
few columns) and a row per event, appended as it happens.

**Append-only.** A run's row is written when it starts and once more when it ends; each
event is one ``INSERT`` into ``events`` (:meth:`RunStore.append_event`, through a
:class:`StoreJournal` that the run's :class:`~taskrunner.runtime.events.EventLog` calls
before anyone can see the event: no stream or poll shows an event that is not in the
database). Nothing is rewritten as a run goes, so an event costs the same at the end of
a long run as at its start; a page of events (``seq > since``, ``limit`` of them) is read
through the primary key, whatever the run's length. Records of databases written before
this (events inside the run's JSON) are read as they are, merged with any event rows.

**What survives what.** The database is in WAL mode with ``synchronous=NORMAL``: a commit
is written to the WAL (handed to the operating system) before ``INSERT`` returns, so a
server killed at any point (SIGKILL, a crash, out of memory) keeps every event it
appended (about 10 µs a commit, no fsync). Against a power loss or a crash of the
operating system the WAL is fsync'd, as the CLI's journal is
(:data:`~taskrunner.runtime.records.SYNC_KINDS`), when a ``planned`` event of a motion is
appended (nothing moves before what led to it is on disk) and with the run's final row
(committed with ``synchronous=FULL``); events since the last of those may be lost then.
An fsync per event would cost over 10x more on a busy shared disk (a bare ``INSERT``: 118 µs
median, 4 ms p99, against 9 µs and 66 µs; ``benchmarks/api_record_cost.py``).
SQLite's automatic checkpoint (the WAL copied into the database, about every thousand
events) runs in the appending thread: a few ms once per thousand events. A checkpoint on
a thread of its own was tried: it cannot reset a WAL written to meanwhile, so the WAL
grew to 16 MB with no fewer slow appends (a fast repeat loop emits ~120 events/s).

:meth:`RunStore.mark_interrupted` (at a server's start) marks rows still ``running`` from a
previous server as ``interrupted``: no run is lost, and none claims to run when nothing
runs it; its events are all those it appended.
"""

from __future__ import annotations

import json
import logging
import sqlite3
import threading
from collections.abc import Iterable
from datetime import UTC, datetime
from pathlib import Path

from taskrunner.runtime.events import RunEvent
from taskrunner.runtime.records import RunRecord, needs_sync
from taskrunner.taught import TAUGHT_POSES_TABLE, TaughtPoses, taught_poses_from_rows

__all__ = ["RunStore", "StoreJournal"]

_log = logging.getLogger(__name__)

_SCHEMA = """
CREATE TABLE IF NOT EXISTS runs (
    run_id   TEXT PRIMARY KEY,
    status   TEXT NOT NULL,
    task     TEXT NOT NULL,
    cell     TEXT NOT NULL,
    backend  TEXT NOT NULL,
    started  TEXT NOT NULL,
    finished TEXT,
    record   TEXT NOT NULL,
    tree     TEXT
);
CREATE INDEX IF NOT EXISTS runs_status ON runs (status);
CREATE TABLE IF NOT EXISTS events (
    run_id   TEXT NOT NULL,
    seq      INTEGER NOT NULL,
    event    TEXT NOT NULL,
    PRIMARY KEY (run_id, seq)
) WITHOUT ROWID;
""" + TAUGHT_POSES_TABLE


class RunStore:
    """A SQLite file of run records, safe to use from several threads.

    Event appends have a connection (and lock) of their own, so a run's thread never
    waits for a query that another thread's request is running on the other one.
    """

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._lock = threading.Lock()
        self._db = sqlite3.connect(self.path, check_same_thread=False, isolation_level=None)
        self._db.execute("PRAGMA journal_mode=WAL")
        self._db.execute("PRAGMA synchronous=FULL")  # a run's start and end: rare, durable
        self._db.executescript(_SCHEMA)
        columns = {row[1] for row in self._db.execute("PRAGMA table_info(runs)")}
        if "tree" not in columns:  # a database from before final trees were kept
            self._db.execute("ALTER TABLE runs ADD COLUMN tree TEXT")
        self.version = 0  # bumped by every write of a run's row (lets readers cache queries)
        self._move_events_out_of_records()
        self._append_lock = threading.Lock()
        self._appends = sqlite3.connect(self.path, check_same_thread=False,
                                        isolation_level=None)
        self._appends.execute("PRAGMA synchronous=NORMAL")
        self.appended = 0  # events appended (for tests and stats)

    def save_pose(self, cell: str, group: str, name: str, joints: dict[str, float]) -> str:
        """Store (or replace) a taught named pose; returns when it was taught (ISO time)."""
        now = datetime.now(UTC).isoformat()
        with self._lock:
            self._db.execute(
                "INSERT OR REPLACE INTO taught_poses VALUES (?, ?, ?, ?, ?)",
                (cell, group, name, json.dumps(joints), now))
        return now

    def poses(self, cell: str) -> list[tuple[str, str, dict[str, float], str]]:
        """The taught poses of ``cell``: (group, name, joints, taught)."""
        with self._lock:
            rows = self._db.execute(
                "SELECT grp, name, joints, taught FROM taught_poses WHERE cell = ? "
                "ORDER BY taught", (cell,)).fetchall()
        return [(g, n, json.loads(j), t) for g, n, j, t in rows]

    def taught_poses(self, cells_dir: Path) -> TaughtPoses:
        """Every taught pose, by cell file (a cell id is a file of ``cells_dir``)."""
        with self._lock:
            rows = self._db.execute(
                "SELECT cell, grp, name, joints FROM taught_poses ORDER BY taught").fetchall()
        return taught_poses_from_rows(rows, cells_dir)

    def mark_interrupted(self) -> int:
        """Turn rows left ``running`` by a server that stopped into ``interrupted`` (their
        events are those appended before it stopped); returns how many."""
        now = datetime.now(UTC).isoformat()
        with self._lock:
            rows = self._db.execute("SELECT record FROM runs WHERE status = 'running'").fetchall()
            for (text,) in rows:
                record = RunRecord.from_dict(json.loads(text))
                record.status = "interrupted"
                record.error = record.error or "the server stopped while the run was in flight"
                record.finished = record.finished or now
                self._write(record, None, ())
        return len(rows)

    def save(self, record: RunRecord, tree: str | None = None,
             events: Iterable[RunEvent] | None = None) -> None:
        """Insert or replace ``record``'s row; with ``tree``, the behaviour tree as text at
        the end of the run (kept when later saves give none).

        Args:
            record: the run (its events are not rewritten: see ``events``).
            tree: the final tree text, or None to keep the one stored.
            events: events to append if not stored yet (by seq); None: the record's.
        """
        with self._lock:
            self._write(record, tree, record.events if events is None else events)

    def append_event(self, run_id: str, event: RunEvent, durable: bool = False) -> None:
        """Append ``event`` of run ``run_id`` (one row; a seq already stored is kept).

        When this returns the event is in the database file's WAL: a killed server keeps
        it. ``durable``: fsync it (and every event before it) too, against a power loss.

        Raises:
            sqlite3.Error: it could not be written (disk full, database locked for 5 s).
        """
        text = _event_text(event)
        with self._append_lock:
            if durable:
                self._appends.execute("PRAGMA synchronous=FULL")
            try:
                self._appends.execute("INSERT OR IGNORE INTO events VALUES (?, ?, ?)",
                                      (run_id, event.seq, text))
            finally:
                if durable:
                    self._appends.execute("PRAGMA synchronous=NORMAL")
            self.appended += 1

    def load(self, run_id: str) -> RunRecord | None:
        """The record of ``run_id`` with all its events, or None."""
        row = self.load_row(run_id)
        if row is None:
            return None
        record = RunRecord.from_dict(json.loads(row[0]))
        record.events = self.events(run_id)[0]
        return record

    def load_row(self, run_id: str) -> tuple[str, str | None] | None:
        """The record of ``run_id`` without its events, as the JSON text stored, and its
        final tree; or None."""
        with self._lock:
            row = self._db.execute("SELECT record, tree FROM runs WHERE run_id = ?",
                                   (run_id,)).fetchone()
        return None if row is None else (str(row[0]), row[1])

    def events(self, run_id: str, after: int = 0,
               limit: int | None = None) -> tuple[list[RunEvent], bool]:
        """The events of ``run_id`` with ``seq > after``, at most ``limit`` of them (None:
        all), in order; and whether more follow the last one returned."""
        query = "SELECT event FROM events WHERE run_id = ? AND seq > ? ORDER BY seq"
        args: tuple[object, ...] = (run_id, after)
        if limit is not None:
            query += " LIMIT ?"
            args = (*args, limit + 1)
        with self._lock:
            rows = self._db.execute(query, args).fetchall()
        more = limit is not None and len(rows) > limit
        return [RunEvent.from_dict(json.loads(text)) for (text,) in rows[:limit]], more

    def last_seq(self, run_id: str) -> int:
        """The seq of the last event stored for ``run_id`` (0: none)."""
        with self._lock:
            row = self._db.execute("SELECT max(seq) FROM events WHERE run_id = ?",
                                   (run_id,)).fetchone()
        return int(row[0] or 0)

    def summaries(self, status: str | None = None, limit: int = 100) -> list[dict[str, object]]:
        """The newest runs first (without their events), optionally of one status."""
        query = ("SELECT run_id, status, task, cell, backend, started, finished, "
                 "json_extract(record, '$.exit_code'), json_extract(record, '$.error') "
                 "FROM runs")
        args: tuple[object, ...] = ()
        if status is not None:
            query += " WHERE status = ?"
            args = (status,)
        query += " ORDER BY started DESC LIMIT ?"
        with self._lock:
            rows = self._db.execute(query, (*args, limit)).fetchall()
        out = []
        for run_id, st, task, cell, backend, started, finished, exit_code, error in rows:
            out.append({"run_id": run_id, "status": st, "task": task, "cell": cell,
                        "backend": backend, "started": started, "finished": finished,
                        "exit_code": exit_code, "error": error})
        return out

    def resumed_by(self, run_id: str) -> list[str]:
        """The runs whose record resumes ``run_id`` (``run-task resume``, POST
        /runs/{id}/resume), oldest first."""
        with self._lock:
            rows = self._db.execute("SELECT run_id FROM runs WHERE json_extract(record, "
                                    "'$.resumes') = ? ORDER BY started", (run_id,)).fetchall()
        return [str(row[0]) for row in rows]

    def close(self) -> None:
        with self._append_lock:
            self._appends.close()
        with self._lock:
            self._db.close()

    def _write(self, record: RunRecord, tree: str | None, events: Iterable[RunEvent]) -> None:
        head = {**record.as_dict(), "events": []}
        rows = [(record.run_id, e.seq, _event_text(e)) for e in list(events)]
        self._db.execute("BEGIN IMMEDIATE")
        try:
            self._db.execute(
                "INSERT INTO runs (run_id, status, task, cell, backend, started, finished, "
                "record, tree) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?) ON CONFLICT (run_id) DO "
                "UPDATE SET status = excluded.status, task = excluded.task, "
                "cell = excluded.cell, backend = excluded.backend, "
                "started = excluded.started, finished = excluded.finished, "
                "record = excluded.record, tree = COALESCE(excluded.tree, runs.tree)",
                (record.run_id, record.status, record.task, record.cell, record.backend,
                 record.started, record.finished, json.dumps(head, default=_jsonable), tree))
            self._db.executemany("INSERT OR IGNORE INTO events VALUES (?, ?, ?)", rows)
        except BaseException:
            self._db.execute("ROLLBACK")
            raise
        self._db.execute("COMMIT")
        self.version += 1

    def _move_events_out_of_records(self) -> None:
        """Records written before events had rows of their own keep them in their JSON:
        move them to rows (once, when such a database is opened)."""
        rows = self._db.execute(
            "SELECT record FROM runs WHERE json_array_length(record, '$.events') > 0"
        ).fetchall()
        for (text,) in rows:
            record = RunRecord.from_dict(json.loads(text))
            self._write(record, None, record.events)


class StoreJournal:
    """Appends a run's events to a :class:`RunStore` as they happen: the ``journal`` of its
    :class:`~taskrunner.runtime.events.EventLog`, called before the event is kept or shown.

    A failed append (disk full) does not stop the run (its motion must stay under
    control): it is logged as an error, counted in ``failed``, and the run's events are
    written again with its final record (``RunStore.save(record)``).
    """

    def __init__(self, store: RunStore, run_id: str) -> None:
        self.store = store
        self.run_id = run_id
        self.failed = 0

    def __call__(self, event: RunEvent) -> None:
        try:
            # run_finished needs no fsync of its own: the run's final row comes next,
            # committed with synchronous=FULL, which fsyncs the WAL with every event.
            durable = needs_sync(event) and event.kind != "run_finished"
            self.store.append_event(self.run_id, event, durable=durable)
        except sqlite3.Error as exc:
            self.failed += 1
            if self.failed == 1:
                _log.error("run %s: event %d not written to %s (%s); the run goes on, its "
                           "events are written again at its end", self.run_id, event.seq,
                           self.store.path, exc)


def _event_text(event: RunEvent) -> str:
    return json.dumps(event.as_dict(), default=_jsonable, separators=(",", ":"))


def _jsonable(value: object) -> object:
    if hasattr(value, "tolist"):
        return value.tolist()  # type: ignore[union-attr]
    if isinstance(value, Path):
        return str(value)
    return str(value)
