"""Run records: what was run, with which parameters, every event, and how it ended.

A record is a JSON file (``<runs_dir>/<run_id>.json``) written when the run starts and
again when it ends, so a run that dies halfway still leaves its task, parameters and the
events up to then. Writes are atomic (temporary file, then rename).
"""

from __future__ import annotations

import json
import os
import tempfile
import uuid
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import Any

from taskrunner.runtime.events import RunEvent

__all__ = ["RunRecord", "load_record", "new_run_id", "save_record"]

STATUSES = ("running", "succeeded", "failed", "cancelled", "interrupted")


def new_run_id() -> str:
    """A sortable, unique run id: UTC time plus a random suffix."""
    stamp = datetime.now(UTC).strftime("%Y%m%dT%H%M%S")
    return f"{stamp}-{uuid.uuid4().hex[:6]}"


@dataclass
class RunRecord:
    """Everything about one run.

    Attributes:
        status: running, succeeded, failed, cancelled or interrupted.
        exit_code: the CLI's exit code for this outcome (0, 3, 4, 130), None while running.
        task_text: the task file's text as it was run (includes are listed by path).
        error: the failure's message (with file:line), if it failed.
    """

    run_id: str
    task: str
    task_file: str
    cell: str
    backend: str
    parameters: dict[str, Any]
    task_text: str = ""
    status: str = "running"
    exit_code: int | None = None
    error: str | None = None
    started: str = field(default_factory=lambda: datetime.now(UTC).isoformat())
    finished: str | None = None
    events: list[RunEvent] = field(default_factory=list)

    def as_dict(self) -> dict[str, Any]:
        data = {k: v for k, v in vars(self).items() if k != "events"}
        data["events"] = [e.as_dict() for e in self.events]
        return data

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> RunRecord:
        fields = {k: v for k, v in data.items() if k != "events"}
        return cls(**fields, events=[RunEvent.from_dict(e) for e in data.get("events", [])])


def save_record(record: RunRecord, runs_dir: str | Path) -> Path:
    """Write ``record`` to ``runs_dir/<run_id>.json`` atomically; returns the path."""
    runs_dir = Path(runs_dir)
    runs_dir.mkdir(parents=True, exist_ok=True)
    path = runs_dir / f"{record.run_id}.json"
    fd, tmp = tempfile.mkstemp(dir=runs_dir, prefix=".record-", suffix=".json")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            json.dump(record.as_dict(), out, indent=1, default=_jsonable)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    return path


def load_record(path: str | Path) -> RunRecord:
    """Read a record written by :func:`save_record`."""
    with open(path, encoding="utf-8") as f:
        return RunRecord.from_dict(json.load(f))


def _jsonable(value: Any) -> Any:
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, Path):
        return str(value)
    raise TypeError(f"not JSON serialisable: {type(value).__name__}")
