"""Run records in SQLite: one row per run, the whole record as JSON beside a few columns.

Rows are written when a run starts, as its steps finish and when it ends, so a server
that dies halfway leaves every run with its events up to then. :meth:`RunStore.open`
marks rows still ``running`` from a previous server as ``interrupted``: no run is lost,
and none claims to run when nothing runs it.
"""

from __future__ import annotations

import json
import sqlite3
import threading
from datetime import UTC, datetime
from pathlib import Path

from taskrunner.runtime.records import RunRecord
from taskrunner.taught import TaughtPoses, taught_poses_from_rows

__all__ = ["RunStore"]

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
CREATE TABLE IF NOT EXISTS taught_poses (
    cell     TEXT NOT NULL,
    grp      TEXT NOT NULL,
    name     TEXT NOT NULL,
    joints   TEXT NOT NULL,
    taught   TEXT NOT NULL,
    PRIMARY KEY (cell, grp, name)
);
"""


class RunStore:
    """A SQLite file of run records, safe to use from several threads."""

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        self.path.parent.mkdir(parents=True, exist_ok=True)
        self._lock = threading.Lock()
        self._db = sqlite3.connect(self.path, check_same_thread=False, isolation_level=None)
        self._db.execute("PRAGMA journal_mode=WAL")
        self._db.executescript(_SCHEMA)
        columns = {row[1] for row in self._db.execute("PRAGMA table_info(runs)")}
        if "tree" not in columns:  # a database from before final trees were kept
            self._db.execute("ALTER TABLE runs ADD COLUMN tree TEXT")
        self.version = 0  # bumped by every write (lets readers cache query results)

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
        """Turn rows left ``running`` by a server that stopped into ``interrupted``;
        returns how many."""
        now = datetime.now(UTC).isoformat()
        with self._lock:
            rows = self._db.execute("SELECT record FROM runs WHERE status = 'running'").fetchall()
            for (text,) in rows:
                record = RunRecord.from_dict(json.loads(text))
                record.status = "interrupted"
                record.error = record.error or "the server stopped while the run was in flight"
                record.finished = record.finished or now
                self._write(record)
        return len(rows)

    def save(self, record: RunRecord, tree: str | None = None) -> None:
        """Insert or replace ``record``; with ``tree``, the behaviour tree as text at the
        end of the run (kept when later saves give none)."""
        with self._lock:
            self._write(record, tree)

    def load(self, run_id: str) -> RunRecord | None:
        """The record of ``run_id``, or None."""
        with self._lock:
            row = self._db.execute("SELECT record FROM runs WHERE run_id = ?",
                                   (run_id,)).fetchone()
        return None if row is None else RunRecord.from_dict(json.loads(row[0]))

    def load_row(self, run_id: str) -> tuple[str, str | None] | None:
        """The record of ``run_id`` as the JSON text stored and its final tree, or None."""
        with self._lock:
            row = self._db.execute("SELECT record, tree FROM runs WHERE run_id = ?",
                                   (run_id,)).fetchone()
        return None if row is None else (str(row[0]), row[1])

    def summaries(self, status: str | None = None, limit: int = 100) -> list[dict[str, object]]:
        """The newest runs first (without their events), optionally of one status."""
        # The exit code and error come out of the JSON in SQLite: parsing every whole
        # record (all its events) in Python made listing runs slow.
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

    def close(self) -> None:
        with self._lock:
            self._db.close()

    def _write(self, record: RunRecord, tree: str | None = None) -> None:
        text = json.dumps(record.as_dict(), default=_jsonable)
        self._db.execute(
            "INSERT INTO runs (run_id, status, task, cell, backend, started, finished, "
            "record, tree) VALUES (?, ?, ?, ?, ?, ?, ?, ?, ?) ON CONFLICT (run_id) DO UPDATE "
            "SET status = excluded.status, task = excluded.task, cell = excluded.cell, "
            "backend = excluded.backend, started = excluded.started, "
            "finished = excluded.finished, record = excluded.record, "
            "tree = COALESCE(excluded.tree, runs.tree)",
            (record.run_id, record.status, record.task, record.cell, record.backend,
             record.started, record.finished, text, tree))
        self.version += 1


def _jsonable(value: object) -> object:
    if hasattr(value, "tolist"):
        return value.tolist()  # type: ignore[union-attr]
    if isinstance(value, Path):
        return str(value)
    return str(value)
