"""A CLI record file is written once, at the run's end; until then the journal is the run."""

from __future__ import annotations

import json

import pytest

from taskrunner.errors import InputError
from taskrunner.runtime.events import EventLog
from taskrunner.runtime.records import (
    RecordFile,
    RunRecord,
    journal_path,
    load_record,
    new_run_id,
    save_record,
)


def new_record() -> RunRecord:
    return RunRecord(new_run_id(), "t", "t.yaml", "cell", "mock", {"speed": 0.5},
                     task_text="task: t\n")


def test_a_run_in_flight_has_no_record_file_and_is_read_from_its_journal(tmp_path):
    log = EventLog()
    record = new_record()
    log.subscribe(record.events.append)
    file = RecordFile(record, tmp_path / "runs")
    log.subscribe(file.append)
    log.emit("run_started", status="running")
    log.emit("node_started", node="go")
    assert not file.path.exists()
    live = load_record(file.path)  # this process writes it: still running
    assert live.status == "running" and live.error is None
    assert (live.task_text, live.parameters) == ("task: t\n", {"speed": 0.5})
    assert [e.kind for e in live.events] == ["run_started", "node_started"]
    record.status, record.exit_code = "succeeded", 0
    log.emit("run_finished", status="succeeded")
    file.finish()
    assert json.loads(file.path.read_text())["status"] == "succeeded"
    assert not file.journal.exists() and len(load_record(file.path).events) == 3


def test_a_journal_whose_writer_is_gone_reads_as_interrupted(tmp_path):
    record = new_record()
    file = RecordFile(record, tmp_path / "runs")
    file.append(EventLog().emit("run_started"))
    lines = file.journal.read_text().splitlines()
    header = json.loads(lines[0])
    header["pid"] = 2**22 + 12345  # no such process
    file.journal.write_text("\n".join([json.dumps(header), *lines[1:]]) + "\n")
    again = load_record(file.journal)
    assert again.status == "interrupted" and "ended without finishing" in (again.error or "")
    assert [e.kind for e in again.events] == ["run_started"]


def test_a_record_of_the_earlier_layout_still_merges_its_journal(tmp_path):
    record = new_record()  # a JSON saying running, written at the start, as before
    path = save_record(record, tmp_path)
    journal_path(path).write_text(
        json.dumps({"journal": 1, "run_id": record.run_id, "host": "elsewhere", "pid": 1})
        + "\n" + json.dumps(EventLog().emit("run_started").as_dict()) + "\n")
    again = load_record(path)
    assert again.status == "running"  # another host: its writer may live
    assert [e.kind for e in again.events] == ["run_started"]
    path.unlink()
    with pytest.raises(InputError, match="no record head"):
        load_record(path)
    journal_path(path).unlink()
    with pytest.raises(FileNotFoundError):
        load_record(path)
