"""Run records: what was run, with which parameters, every event, and how it ended.

A record is a JSON file (``<runs_dir>/<run_id>.json``) written once, when the run ends,
atomically (temporary file, fsync, rename): a record file always tells how its run
ended, never that it is ``running``. While the run goes, a :class:`RecordFile` appends
every event to ``<run_id>.events.jsonl`` instead (one JSON object a line, after a header
line naming the process that writes it and holding the record's head: task, cell,
parameters, task text), the live truth of the run. What survives what:

* the process killed at any point (SIGKILL, a crash, out of memory): every event it
  announced, in the journal. Each event is written to the file (handed to the operating
  system) before it is passed on, and the operating system keeps what a dead process
  wrote. No record JSON is left claiming the run goes on: there is none.
* the machine losing power or its operating system crashing: every event up to the last
  motion sent to the backend. The journal is fsync'd when a ``planned`` event of a
  motion is appended (the event just before its trajectory goes to the backend: nothing
  moves before what led to it is on disk; not for one with duration 0, "already there",
  which sends nothing) and when the run ends (``run_finished``; the final record is
  written atomically and durably after it). Events since the last of those (the
  ``motion`` event itself, the steps after it until the next motion) may be lost.

Fsyncing at those points rather than after every event keeps a run's start from
waiting for a dozen disk flushes before its first motion (each one 0.1-10 ms, more on
a busy disk). The journal is removed once the final JSON is on disk.

:func:`load_record` reads a run in flight or killed from its journal (given the record's
path or the journal's): ``running`` while its writing process lives, else
``interrupted``. Records written by earlier versions (a JSON at the start saying
``running``, beside a journal) are read as before: the journal merged in, the status
corrected the same way.
"""

from __future__ import annotations

import json
import os
import socket
import tempfile
import threading
import uuid
from dataclasses import dataclass, field
from datetime import UTC, datetime
from pathlib import Path
from typing import TYPE_CHECKING, Any

from taskrunner.errors import InputError
from taskrunner.kinds import RunStatus
from taskrunner.runtime.events import RunEvent

if TYPE_CHECKING:
    from taskrunner.robot.options import LoadOptions

__all__ = ["SYNC_KINDS", "RecordFile", "RunRecord", "journal_path", "load_record", "needs_sync",
           "new_run_id", "save_record"]

STATUSES = tuple(status.value for status in RunStatus)


def new_run_id() -> str:
    """A sortable, unique run id: UTC time plus a random suffix."""
    stamp = datetime.now(UTC).strftime("%Y%m%dT%H%M%S")
    return f"{stamp}-{uuid.uuid4().hex[:6]}"


@dataclass
class RunRecord:
    """Everything about one run.

    Attributes:
        status: running, succeeded, failed, cancelled or interrupted (the process running
            it ended before the run did: killed, or a server stopped).
        exit_code: the CLI's exit code for this outcome (0, 3, 4, 130 cancelled, 143
            ended by SIGTERM), None while running.
        task_text: the task file's text as it was run (includes are listed by path).
        error: the failure's message (with file:line), if it failed.
        warm_up_s: seconds spent before the run started compiling the planner's kernels
            (the first run on a machine, :mod:`taskrunner.planning.warmup`); not task
            time. None: none was needed.
        task_sha256: hash of ``task_text``; ``tree_sha256``: of the compiled tree's
            shape (:mod:`taskrunner.runtime.checkpoint`); what a resume checks.
        resumes: the id of the run this one resumes (``run-task resume``), if any.
        load_options: how the cell's robots were loaded
            (:meth:`taskrunner.robot.options.LoadOptions.as_data`): what ``run-task
            resume`` loads them with again. None: not said (the defaults; a record made
            before records kept them).
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
    warm_up_s: float | None = None
    task_sha256: str = ""
    tree_sha256: str = ""
    resumes: str | None = None
    load_options: dict[str, Any] | None = None
    events: list[RunEvent] = field(default_factory=list)

    def loaded_with(self) -> LoadOptions | None:
        """How the run loaded its robots (``load_options``), None when the record does not
        say.

        Raises:
            InputError: the record's ``load_options`` are not valid, naming the run.
        """
        from taskrunner.errors import TaskrunnerError
        from taskrunner.robot.options import LoadOptions

        if not self.load_options:
            return None
        try:
            return LoadOptions.from_data(self.load_options)
        except TaskrunnerError as exc:
            raise InputError(f"run {self.run_id}: its load_options: {exc}") from None

    def as_dict(self) -> dict[str, Any]:
        data = {k: v for k, v in vars(self).items() if k != "events"}
        data["events"] = [e.as_dict() for e in self.events]
        return data

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> RunRecord:
        fields = {k: v for k, v in data.items() if k != "events"}
        return cls(**fields, events=[RunEvent.from_dict(e) for e in data.get("events", [])])


def save_record(record: RunRecord, runs_dir: str | Path, sync_folder: bool = True) -> Path:
    """Write ``record`` to ``runs_dir/<run_id>.json`` atomically and durably (fsync'd
    before the rename, the folder after; ``sync_folder`` False: the caller fsyncs the
    folder later); returns the path."""
    runs_dir = Path(runs_dir)
    runs_dir.mkdir(parents=True, exist_ok=True)
    path = runs_dir / f"{record.run_id}.json"
    fd, tmp = tempfile.mkstemp(dir=runs_dir, prefix=".record-", suffix=".json")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            json.dump(record.as_dict(), out, indent=1, default=_jsonable)
            out.flush()
            os.fsync(out.fileno())
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
    if sync_folder:
        _fsync_dir(runs_dir)
    return path


def journal_path(record_path: str | Path) -> Path:
    """The event journal beside a record: ``<run_id>.events.jsonl``."""
    record_path = Path(record_path)
    return record_path.with_name(record_path.stem + ".events.jsonl")


# A record's fields that say how its run went (not in a journal's head).
_OUTCOME = frozenset({"status", "exit_code", "error", "finished", "events"})

# Appending one of these fsyncs the journal (a ``planned`` one with duration 0 does not:
# nothing is sent; see the module docstring).
SYNC_KINDS = frozenset({"planned", "run_finished"})


def needs_sync(event: RunEvent) -> bool:
    """Whether a journal fsyncs when it appends ``event``: before a motion is sent (a
    ``planned`` event, unless its duration is 0: nothing is sent) and at the run's end."""
    return event.kind in SYNC_KINDS and not (event.kind == "planned"
                                             and event.data.get("duration") == 0)


class RecordFile:
    """A run's record on disk while it runs: the JSON plus an event journal.

    ``append`` is safe from several threads (events come from the tick thread and the
    backend's). When it returns, the event is written to the file (a killed process
    loses none), and fsync'd with all before it when its kind is in :data:`SYNC_KINDS`
    and it is not a ``planned`` event with duration 0 (see the module docstring for what
    survives a power loss).
    """

    def __init__(self, record: RunRecord, runs_dir: str | Path) -> None:
        self.record = record
        runs_dir = Path(runs_dir)
        runs_dir.mkdir(parents=True, exist_ok=True)
        self.path = runs_dir / f"{record.run_id}.json"  # written by finish(), not before
        self.journal = journal_path(self.path)
        self._lock = threading.Lock()
        self._out = open(self.journal, "a", encoding="utf-8")  # held open: one line an event
        # The folder is fsync'd with the journal's first sync (its entry).
        self._folder_synced = False
        self.syncs = 0  # fsyncs of the journal so far
        # What the run is, not how it went: a journal never says "running" either.
        head = {k: v for k, v in record.as_dict().items() if k not in _OUTCOME}
        header = {"journal": 1, "run_id": record.run_id, "host": socket.gethostname(),
                  "pid": os.getpid(), "process_start": _process_start(os.getpid()),
                  "record": head}
        self._write(header)
        for event in record.events:
            self._write(event.as_dict())

    def append(self, event: RunEvent) -> None:
        """Append ``event`` to the journal; fsync it before a motion and at the end."""
        with self._lock:
            if not self._out.closed:
                self._write(event.as_dict())
                if needs_sync(event):
                    self._sync()

    def sync(self) -> None:
        """Fsync the journal (and, the first time, its folder) now."""
        with self._lock:
            if not self._out.closed:
                self._sync()

    def finish(self) -> Path:
        """Write the final record (atomically), then drop the journal."""
        with self._lock:
            self._out.close()
        path = save_record(self.record, self.path.parent)
        self.journal.unlink(missing_ok=True)
        return path

    def _write(self, data: dict[str, Any]) -> None:
        self._out.write(json.dumps(data, default=_jsonable) + "\n")
        self._out.flush()

    def _sync(self) -> None:
        os.fsync(self._out.fileno())
        self.syncs += 1
        if not self._folder_synced:
            _fsync_dir(self.path.parent)  # the record's and the journal's entries
            self._folder_synced = True


def load_record(path: str | Path) -> RunRecord:
    """Read a record written by :func:`save_record` or a :class:`RecordFile`.

    ``path`` is the record's JSON or its journal (``<run_id>.events.jsonl``). A run
    without a JSON (in flight, or its process killed) is read from its journal:
    ``running`` while the process writing it lives, else ``interrupted`` with the reason
    in ``error``. Events of a journal left beside a JSON are merged in.

    Raises:
        FileNotFoundError: neither the record nor its journal exists.
        InputError: the journal has no record head (not written by a RecordFile).
    """
    path = Path(path)
    if path.name.endswith(".events.jsonl"):
        journal = path
        path = path.with_name(path.name[:-len(".events.jsonl")] + ".json")
    else:
        journal = journal_path(path)
    if not path.is_file() and journal.is_file():
        header, events = _read_journal(journal)
        if not isinstance(header.get("record"), dict):
            raise InputError("no record head in its first line (not a run's journal, or "
                             "one from before heads were kept)", journal, 1)
        record = RunRecord.from_dict({**header["record"], "events": []})
        record.status = "running"
        return _merged(record, header, events)
    with open(path, encoding="utf-8") as f:
        record = RunRecord.from_dict(json.load(f))
    if not journal.is_file():
        return record
    header, events = _read_journal(journal)
    return _merged(record, header, events)


def _merged(record: RunRecord, header: dict[str, Any], events: list[RunEvent]) -> RunRecord:
    """``record`` with a journal's events merged in; ``interrupted`` if it says
    ``running`` and the journal's writer is gone."""
    known = {e.seq for e in record.events}
    record.events = sorted([*record.events, *(e for e in events if e.seq not in known)],
                           key=lambda e: e.seq)
    if record.status == "running" and header and not _writer_alive(header):
        record.status = "interrupted"
        last = record.events[-1].time if record.events else 0.0
        record.error = (f"the process running it (pid {header.get('pid')}) ended without "
                        f"finishing the run; {len(record.events)} events recorded, the "
                        f"last at {last:.2f} s")
    return record


def _read_journal(path: Path) -> tuple[dict[str, Any], list[RunEvent]]:
    header: dict[str, Any] = {}
    events: list[RunEvent] = []
    with open(path, encoding="utf-8") as f:
        for line in f:
            try:
                data = json.loads(line)
            except json.JSONDecodeError:  # a line cut short by the kill: nothing after it
                break
            if "journal" in data:
                header = data
            else:
                events.append(RunEvent.from_dict(data))
    return header, events


def _writer_alive(header: dict[str, Any]) -> bool:
    """Whether the process that wrote a journal still runs (unknown on another host:
    assumed alive)."""
    if header.get("host") != socket.gethostname():
        return True
    pid = header.get("pid")
    if not isinstance(pid, int):
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        pass
    started = header.get("process_start")
    return started is None or _process_start(pid) == started


def _process_start(pid: int) -> int | None:
    """The process's start time in clock ticks since boot (Linux), to tell a reused pid."""
    try:
        stat = Path(f"/proc/{pid}/stat").read_text()
    except OSError:
        return None
    return int(stat.rpartition(")")[2].split()[19])


def _fsync_dir(folder: Path) -> None:
    try:
        fd = os.open(folder, os.O_RDONLY)
    except OSError:
        return
    try:
        os.fsync(fd)
    except OSError:
        pass
    finally:
        os.close(fd)


def _jsonable(value: Any) -> Any:
    if hasattr(value, "tolist"):
        return value.tolist()
    if isinstance(value, Path):
        return str(value)
    raise TypeError(f"not JSON serialisable: {type(value).__name__}")
