"""The run journal: every event written before it is passed on, fsync'd before each motion
is sent and at the end (what a power loss keeps), not after every event."""

from __future__ import annotations

import json
import os
import textwrap

from taskrunner.backends.mock import MockBackend
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.events import EventLog
from taskrunner.runtime.records import (
    SYNC_KINDS,
    RecordFile,
    RunRecord,
    journal_path,
    load_record,
    new_run_id,
)
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks import load_task


class FsyncSpy:
    """Stands in for os.fsync: records what each fsync'd file held at that moment."""

    def __init__(self, monkeypatch) -> None:
        self.calls: list[tuple[str, str]] = []  # (path, text: "" for a folder)
        self._real = os.fsync
        monkeypatch.setattr(os, "fsync", self)

    def __call__(self, fd: int) -> None:
        path = os.readlink(f"/proc/self/fd/{fd}")
        text = open(path, encoding="utf-8").read() if os.path.isfile(path) else ""
        self.calls.append((path, text))
        self._real(fd)

    def journal_syncs(self, journal) -> list[list[dict]]:
        """The journal's lines as each fsync of it saw them."""
        return [[json.loads(line) for line in text.splitlines()]
                for path, text in self.calls if path == str(journal)]


def record(events: EventLog | None = None) -> RunRecord:
    return RunRecord(new_run_id(), "t", "t.yaml", "cell", "mock", {},
                     events=list(events.events()) if events else [])


def test_events_are_written_at_once_and_fsynced_at_a_planned_event(tmp_path, monkeypatch):
    spy = FsyncSpy(monkeypatch)
    log = EventLog()
    file = RecordFile(record(), tmp_path / "runs")
    log.subscribe(file.append)
    # nothing yet: no record JSON until the end (its folder is fsync'd with the journal's
    # first sync)
    assert spy.calls == [] and not file.path.exists()
    before = len(spy.calls)
    log.emit("run_started", "go")
    log.emit("node_started", node="pick")
    log.emit("message", "retry")
    # written (another reader sees them: a killed process loses none), not fsync'd
    lines = journal_path(file.path).read_text().splitlines()
    assert [json.loads(line).get("kind") for line in lines[1:]] == [
        "run_started", "node_started", "message"]
    assert len(spy.calls) == before and file.syncs == 0
    log.emit("planned", node="pick", duration=1.0)
    synced = spy.journal_syncs(file.journal)
    assert len(synced) == 1 and file.syncs == 1
    assert [e.get("kind") for e in synced[0][1:]] == [
        "run_started", "node_started", "message", "planned"]
    assert spy.calls[-1][0] == str(file.path.parent)  # the folder, with the first sync only
    log.emit("motion", node="pick")
    log.emit("planned", node="open", duration=0.0)  # already there: nothing is sent
    assert file.syncs == 1
    log.emit("planned", node="place", duration=1.0)
    assert file.syncs == 2 and spy.calls[-1][0] == str(file.journal)
    log.emit("run_finished", status="succeeded")
    assert file.syncs == 3
    assert [e["kind"] for e in spy.journal_syncs(file.journal)[-1][1:]][-3:] == [
        "planned", "planned", "run_finished"]
    file.finish()
    assert not file.journal.exists()
    assert load_record(file.path).status == "running"  # as the record handed in said


def test_sync_kinds_are_the_event_before_a_motion_and_the_end():
    assert SYNC_KINDS == {"planned", "run_finished"}


def test_a_run_fsyncs_the_journal_before_each_trajectory_goes_to_the_backend(
        tmp_path, monkeypatch):
    spy = FsyncSpy(monkeypatch)
    path = tmp_path / "task.yaml"
    cell_file = DATA_ROOT / "robots" / "cells" / "servo_arm_table.yaml"
    path.write_text(f"task: t\ncell: {cell_file}\n" + textwrap.dedent("""\
        steps:
          - go: {group: arm, to: Candle}
          - wait: {seconds: 0.01}
          - go: {group: arm, to: ready}
        """))
    spec = load_task(path)
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = MockBackend(names, dict(zip(names, cell.start_state())))
    runner = Runner(spec, cell, backend, InProcessPlanner(),
                    RunOptions(runs_dir=tmp_path / "runs"))
    on_disk_at_send: list[list[str]] = []
    execute = backend.execute

    def spying_execute(trajectory):
        journal = runner._file.journal
        synced = spy.journal_syncs(journal)
        on_disk_at_send.append([e.get("kind") for e in synced[-1]] if synced else [])
        return execute(trajectory)

    monkeypatch.setattr(backend, "execute", spying_execute)
    finished = runner.run()
    assert finished.status == "succeeded", finished.error
    assert len(on_disk_at_send) == 2
    planned = [e for e in finished.events if e.kind == "planned"]
    for k, kinds in enumerate(on_disk_at_send):
        # everything up to the motion's planned event was fsync'd before it was sent
        assert kinds.count("planned") == k + 1 and kinds[-1] == "planned", kinds
    assert len(planned) == 2
    # one fsync per motion, one at the end, the folder once; not one per event
    assert runner_syncs(spy, finished) <= 3 < len(finished.events)
    again = load_record(tmp_path / "runs" / f"{finished.run_id}.json")
    assert [e.as_dict() for e in again.events] == [e.as_dict() for e in finished.events]


def runner_syncs(spy: FsyncSpy, finished: RunRecord) -> int:
    return sum(1 for p, _ in spy.calls if p.endswith(f"{finished.run_id}.events.jsonl"))
