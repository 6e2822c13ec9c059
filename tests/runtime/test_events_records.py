"""Run events are numbered and streamed; run records round-trip through JSON on disk."""

from __future__ import annotations

import json

import pytest

from taskrunner.runtime.events import EventLog, RunEvent
from taskrunner.runtime.records import RunRecord, load_record, new_run_id, save_record


def test_events_are_numbered_timed_and_passed_to_subscribers():
    clock = iter([10.0, 10.5, 11.25]).__next__
    log = EventLog(clock=clock)
    seen: list[RunEvent] = []
    log.subscribe(seen.append)
    log.emit("node_started", node="pick cube", location="tasks/pick_place.yaml:12")
    log.emit("planned", node="pick cube", planning_time=0.012, duration=2.5)
    assert [e.seq for e in seen] == [1, 2]
    assert [e.time for e in seen] == [0.5, 1.25]
    assert seen[1].data == {"planning_time": 0.012, "duration": 2.5}
    assert log.events(after=1) == seen[1:]


def test_an_unsubscribed_callback_hears_no_more():
    log = EventLog()
    seen: list[RunEvent] = []
    log.subscribe(seen.append)
    log.emit("message", "one")
    log.unsubscribe(seen.append)
    log.unsubscribe(seen.append)  # twice: no error
    log.emit("message", "two")
    assert [e.message for e in seen] == ["one"]


def test_an_unknown_event_kind_is_refused():
    with pytest.raises(ValueError, match="'kind' must be one of run_started"):
        EventLog().emit("node_exploded")


def test_records_round_trip_through_json(tmp_path):
    log = EventLog()
    log.emit("run_started", "go home")
    log.emit("run_finished", status="succeeded")
    record = RunRecord(new_run_id(), "go_home", "tasks/go_home.yaml", "servo_arm_table",
                       "mock", {"speed": 2.0}, task_text="task: go_home\n",
                       status="succeeded", exit_code=0, events=log.events())
    path = save_record(record, tmp_path / "runs")
    assert path.name == f"{record.run_id}.json"
    data = json.loads(path.read_text())
    assert data["events"][1]["status"] == "succeeded"
    again = load_record(path)
    assert again.as_dict() == record.as_dict()
    assert not list((tmp_path / "runs").glob(".record-*"))  # no temporary file left behind


def test_run_ids_are_unique_and_sortable():
    ids = [new_run_id() for _ in range(50)]
    assert len(set(ids)) == 50
    assert all(len(i.split("-")[0]) == 15 for i in ids)
