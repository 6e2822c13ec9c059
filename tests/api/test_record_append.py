"""Run records on the server are append-only: an event is a row, written before anyone
sees it; a record's body is paged; a write costs the same at any length of run."""

from __future__ import annotations

import json
import sqlite3
import textwrap
from pathlib import Path

from apitest import AUTH, make_settings, wait_until_done
from fastapi.testclient import TestClient

from taskrunner.api import create_app
from taskrunner.api.detail import DEFAULT_LIMIT, StoredDetails
from taskrunner.api.fastpath import RunDetailFastPath
from taskrunner.api.store import RunStore, StoreJournal
from taskrunner.runtime.events import EventLog
from taskrunner.runtime.records import RunRecord

GO_TWICE = textwrap.dedent("""\
    task: go_twice
    cell: ../robots/cells/servo_arm_table.yaml
    steps:
      - go: {group: arm, to: Candle}
      - go: {group: arm, to: home}
    """)


def fastpath_of(app: object) -> RunDetailFastPath:
    layer = app.middleware_stack  # type: ignore[attr-defined]
    while not isinstance(layer, RunDetailFastPath):
        layer = layer.app
    return layer


def new_record(run_id: str = "r1") -> RunRecord:
    return RunRecord(run_id=run_id, task="t", task_file="", cell="c", backend="sim",
                     parameters={})


def journaled(store: RunStore, record: RunRecord) -> EventLog:
    log = EventLog()
    log.subscribe(record.events.append)
    log.set_journal(StoreJournal(store, record.run_id))
    store.save(record)
    return log


def test_every_event_is_a_row_before_it_is_kept_and_a_dead_servers_run_keeps_them(
        tmp_path: Path):
    store = RunStore(tmp_path / "runs.db")
    record = new_record()
    log = journaled(store, record)
    in_db_when_kept: list[int] = []
    log.subscribe(lambda e: in_db_when_kept.append(store.last_seq("r1")))
    log.emit("run_started", status="running")
    log.emit("node_started", node="go", location="t.yaml:3")
    log.emit("planned", node="go", duration=1.5, planning_time=0.01)
    assert in_db_when_kept == [1, 2, 3]
    # the server dies here: nobody writes the row again; the next server marks it
    again = RunStore(tmp_path / "runs.db")
    assert again.mark_interrupted() == 1
    loaded = again.load("r1")
    assert loaded is not None and loaded.status == "interrupted"
    assert [e.as_dict() for e in loaded.events] == [e.as_dict() for e in record.events]
    # the row holds the record's head only: events are not rewritten with it
    assert json.loads(again.load_row("r1")[0])["events"] == []  # type: ignore[index]
    store.close()
    again.close()


def test_a_page_of_events_says_whether_more_follow(tmp_path: Path):
    store = RunStore(tmp_path / "runs.db")
    log = journaled(store, new_record())
    for k in range(10):
        log.emit("message", f"m{k}")
    page, more = store.events("r1", after=3, limit=4)
    assert [e.seq for e in page] == [4, 5, 6, 7] and more
    page, more = store.events("r1", after=6, limit=4)
    assert [e.seq for e in page] == [7, 8, 9, 10] and not more
    stored = StoredDetails(store)
    body = json.loads(stored.body("r1", since=8, limit=1) or b"")
    assert [e["seq"] for e in body["events"]] == [9] and body["events_more"] is True
    body = json.loads(stored.body("r1") or b"")
    assert len(body["events"]) == 10 and body["events_more"] is False
    store.close()


def test_a_database_with_events_inside_records_is_moved_to_rows_once(tmp_path: Path):
    path = tmp_path / "runs.sqlite"
    old = sqlite3.connect(path)
    old.executescript("CREATE TABLE runs (run_id TEXT PRIMARY KEY, status TEXT NOT NULL, "
                      "task TEXT NOT NULL, cell TEXT NOT NULL, backend TEXT NOT NULL, "
                      "started TEXT NOT NULL, finished TEXT, record TEXT NOT NULL);")
    record = new_record("r0")
    log = EventLog()
    log.subscribe(record.events.append)
    log.emit("run_started")
    log.emit("run_finished", status="succeeded")
    record.status = "succeeded"
    old.execute("INSERT INTO runs VALUES ('r0', 'succeeded', 't', 'c', 'sim', 'x', NULL, ?)",
                (json.dumps(record.as_dict()),))
    old.commit()
    old.close()
    store = RunStore(path)
    loaded = store.load("r0")
    assert loaded is not None and [e.kind for e in loaded.events] == [
        "run_started", "run_finished"]
    assert json.loads(store.load_row("r0")[0])["events"] == []  # type: ignore[index]
    store.close()


def statements_per_event(store: RunStore, log: EventLog, count: int) -> list[tuple[int, int]]:
    """(SQL statements, bytes of SQL parameters) of each of ``count`` events emitted."""
    seen: list[str] = []
    store._appends.set_trace_callback(seen.append)
    store._db.set_trace_callback(seen.append)
    costs = []
    for k in range(count):
        seen.clear()
        log.emit("node_started", node=f"step {k % 10}", location="t.yaml:4")
        costs.append((len(seen), sum(len(s) for s in seen)))
    return costs


def test_an_event_costs_the_same_writes_at_event_5000_as_at_event_100(tmp_path: Path):
    store = RunStore(tmp_path / "runs.db")
    log = journaled(store, new_record())
    costs = statements_per_event(store, log, 5000)
    # one INSERT an event, of the same size but for the digits of its seq and time:
    # nothing grows with the run
    assert costs[99][0] == costs[2500][0] == costs[4999][0] == 1
    assert abs(costs[4999][1] - costs[99][1]) <= 8
    assert max(n for n, _ in costs) == 1
    log.emit("planned", node="go", duration=1.0)  # before a motion: fsync'd, 3 statements
    assert store.last_seq("r1") == 5001
    store.close()


def test_a_run_is_paged_live_and_recorded_and_a_query_goes_past_the_fast_path(
        tmp_path: Path):
    settings = make_settings(tmp_path / "state")
    with TestClient(headers=AUTH, app=create_app(settings)) as client:
        run_id = client.post("/runs", json={"yaml": GO_TWICE, "backend": "mock"},
                             headers=AUTH).json()["run_id"]
        whole = wait_until_done(client, run_id)
        assert whole["events_more"] is False and len(whole["events"]) < DEFAULT_LIMIT
        seqs = [e["seq"] for e in whole["events"]]
        fast = fastpath_of(client.app)
        served = fast.served
        page = client.get(f"/runs/{run_id}?since=2&limit=3").json()
        assert [e["seq"] for e in page["events"]] == seqs[2:5] and page["events_more"]
        assert fast.served == served  # a query string is the route's to answer
        last = client.get(f"/runs/{run_id}?since={seqs[-2]}").json()
        assert [e["seq"] for e in last["events"]] == seqs[-1:] and not last["events_more"]
        assert client.get(f"/runs/{run_id}?limit=0").status_code == 422
        assert client.get(f"/runs/{run_id}?since=-1").status_code == 422
        manager = client.app.state.manager
        manager.live(run_id).thread.join(10)
        manager.keep_finished = 0
        manager._forget_finished()
        assert manager.live(run_id) is None  # now from the database
        stored = client.get(f"/runs/{run_id}?since=2&limit=3").json()
        assert stored["events"] == page["events"] and stored["events_more"]
        assert client.get(f"/runs/{run_id}").json()["events"] == whole["events"]


def test_a_long_live_runs_default_body_stops_changing_with_its_events_and_pages_slice():
    from test_detail_cache import FakeClock, FakeRun

    from taskrunner.api.detail import RunDetailCache

    run = FakeRun()
    cache = RunDetailCache(run, tree_period_s=3600.0, clock=FakeClock())  # type: ignore[arg-type]
    for k in range(DEFAULT_LIMIT + 1):
        run.events.emit("message", f"m{k}")
    full = json.loads(cache.body())
    assert len(full["events"]) == DEFAULT_LIMIT and full["events_more"] is True
    builds = cache.builds
    for k in range(2000):  # the default body shows none of these: nothing to rebuild
        run.events.emit("message", f"later {k}")
    assert cache.fresh()[0] is not None and cache.body() and cache.builds == builds
    page = json.loads(cache.page(2990, 100))
    assert [e["seq"] for e in page["events"]] == list(range(2991, 3002))
    assert page["events_more"] is False and page["status"] == "running"
    assert len(cache._events) == 3001  # each event encoded once, for the pages that showed it


def test_a_server_stopping_records_its_runs_interrupted_with_exit_143(tmp_path: Path):
    from apitest import wait_for_event

    settings = make_settings(tmp_path / "state")
    loop = GO_TWICE.replace("steps:\n", "steps:\n  - repeat:\n      times: 50\n      do:\n") \
        .replace("  - go:", "        - go:")
    with TestClient(headers=AUTH, app=create_app(settings)) as client:
        run_id = client.post("/runs", json={"yaml": loop, "backend": "sim"},
                             headers=AUTH).json()["run_id"]
        wait_for_event(client, run_id, "planned")
    with TestClient(headers=AUTH, app=create_app(settings)) as client:
        run = client.get(f"/runs/{run_id}").json()
    assert (run["status"], run["exit_code"]) == ("interrupted", 143)
    assert run["events"][-1]["kind"] == "run_finished"
    assert run["events"][-1]["data"]["exit_code"] == 143
