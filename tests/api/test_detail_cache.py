"""Pre-serialised GET /runs/{id} and GET /runs bodies: identical to the response models'
JSON, rebuilt when events arrive, when the run ends and when the store is written."""

from __future__ import annotations

import json
import threading
from pathlib import Path

from apitest import AUTH, wait_until_done
from pydantic import TypeAdapter

from taskrunner.api.detail import RunDetailCache, RunListCache, StoredDetails, detail_body
from taskrunner.api.schemas import RunDetail, RunSummary
from taskrunner.api.store import RunStore
from taskrunner.runtime.events import EventLog
from taskrunner.runtime.records import RunRecord


class FakeClock:
    def __init__(self) -> None:
        self.now = 0.0

    def __call__(self) -> float:
        return self.now


class FakeRun:
    """What RunDetailCache reads of a LiveRun: record, done, current(), tree()."""

    def __init__(self) -> None:
        self.record = RunRecord(run_id="r1", task="t", task_file="t.yaml", cell="c",
                                backend="sim", parameters={"pose": "home"})
        self.events = EventLog()
        self.events.subscribe(self.record.events.append)
        self.done = threading.Event()
        self.leaf: tuple[str, str | None] | None = None
        self.tree_text = "-> root [*]"
        self.trees_rendered = 0

    def current(self) -> tuple[str, str | None] | None:
        return None if self.done.is_set() else self.leaf

    def tree(self) -> str:
        self.trees_rendered += 1
        return self.tree_text

    def finish(self, status: str) -> None:
        self.record.status, self.record.exit_code = status, 0
        self.events.emit("run_finished", status, status=status, exit_code=0)
        self.record.finished = "2026-01-01T00:00:00+00:00"
        self.tree_text = "-> root [✓]"
        self.done.set()


def reference(run: FakeRun) -> bytes:
    """The body FastAPI would make from the response model."""
    current = run.current()
    r = run.record
    body = {"run_id": r.run_id, "status": r.status, "task": r.task, "cell": r.cell,
            "backend": r.backend, "started": r.started, "finished": r.finished,
            "exit_code": r.exit_code, "error": r.error, "task_file": r.task_file,
            "parameters": dict(r.parameters),
            "current": None if current is None else {"node": current[0],
                                                     "location": current[1]},
            "tree": run.tree_text, "events": [e.as_dict() for e in r.events]}
    return TypeAdapter(RunDetail).dump_json(RunDetail(**body))


def test_the_cached_body_is_byte_identical_to_the_response_models_json():
    run = FakeRun()
    run.events.emit("run_started", "go", status="running", task="t", parameters={"a": 1.5})
    run.events.emit("node_started", node="go arm", location="t.yaml:4")
    run.leaf = ("go arm", "t.yaml:4")
    cache = RunDetailCache(run, clock=FakeClock())  # type: ignore[arg-type]
    assert cache.body() == reference(run)
    run.finish("succeeded")
    assert cache.body() == reference(run)
    assert detail_body(run.record) == reference_without_tree(run)


def reference_without_tree(run: FakeRun) -> bytes:
    body = json.loads(reference(run))
    body["tree"], body["current"] = None, None
    return TypeAdapter(RunDetail).dump_json(RunDetail(**body))


def test_the_body_is_reused_until_an_event_arrives_and_then_shows_it():
    run = FakeRun()
    run.events.emit("run_started", "go", status="running")
    cache = RunDetailCache(run, clock=FakeClock())  # type: ignore[arg-type]
    first = cache.body()
    assert cache.fresh() == (first, False) and cache.body() is first and cache.builds == 1
    run.events.emit("planned", node="go arm", planning_time=0.25)
    assert cache.fresh() == (None, False)
    second = cache.body()
    assert cache.builds == 2 and second == reference(run)
    assert [e["kind"] for e in json.loads(second)["events"]] == ["run_started", "planned"]
    assert cache.fresh()[0] is second


def test_the_body_changes_when_the_node_running_now_changes_without_an_event():
    run = FakeRun()
    cache = RunDetailCache(run, clock=FakeClock())  # type: ignore[arg-type]
    assert json.loads(cache.body())["current"] is None
    run.leaf = ("go arm", "t.yaml:4")
    assert cache.fresh() == (None, False)
    assert json.loads(cache.body())["current"] == {"node": "go arm", "location": "t.yaml:4"}


def test_the_tree_is_rendered_at_most_once_per_period_by_one_caller_after_answering():
    run, clock = FakeRun(), FakeClock()
    cache = RunDetailCache(run, tree_period_s=0.05, clock=clock)  # type: ignore[arg-type]
    first = cache.body()
    run.tree_text = "-> root [✓]"
    clock.now = 0.04
    assert cache.fresh() == (first, False) and run.trees_rendered == 1
    clock.now = 0.05  # due: the old body is still answered, one caller told to refresh
    assert cache.fresh() == (first, True)
    assert cache.fresh() == (first, False) and run.trees_rendered == 1
    cache.refresh()
    assert run.trees_rendered == 2
    body, refresh = cache.fresh()
    assert json.loads(body or b"")["tree"] == "-> root [✓]" and not refresh
    clock.now = 0.2  # due again but unchanged: rendered, not re-serialised
    builds = cache.builds
    assert cache.fresh()[1]
    cache.refresh()
    assert run.trees_rendered == 3 and cache.builds == builds


def test_a_refresh_claim_that_was_never_honoured_is_given_again():
    run, clock = FakeRun(), FakeClock()
    cache = RunDetailCache(run, tree_period_s=0.05, clock=clock)  # type: ignore[arg-type]
    cache.body()
    clock.now = 0.1
    assert cache.fresh()[1] and not cache.fresh()[1]
    clock.now = 2.0
    assert cache.fresh()[1]


def test_the_body_is_rebuilt_with_the_final_tree_and_result_when_the_run_ends():
    run = FakeRun()
    cache = RunDetailCache(run, tree_period_s=3600.0, clock=FakeClock())  # type: ignore[arg-type]
    assert json.loads(cache.body())["status"] == "running"
    run.finish("succeeded")
    assert cache.fresh() == (None, False)
    body = json.loads(cache.body())
    assert body["status"] == "succeeded" and body["exit_code"] == 0
    assert body["finished"] is not None and body["tree"] == "-> root [✓]"
    assert body["events"][-1]["kind"] == "run_finished"
    done = cache.body()
    cache._clock.now = 1e6  # type: ignore[attr-defined]
    assert cache.fresh() == (done, False)  # a finished run is never re-rendered by the clock


def test_the_body_is_rebuilt_when_the_status_changes_without_an_event():
    run = FakeRun()
    cache = RunDetailCache(run, tree_period_s=3600.0, clock=FakeClock())  # type: ignore[arg-type]
    cache.body()
    run.record.status = "interrupted"
    assert cache.fresh() == (None, False)
    assert json.loads(cache.body())["status"] == "interrupted" and run.trees_rendered == 2


def test_a_recorded_runs_body_follows_its_database_row(tmp_path: Path):
    store = RunStore(tmp_path / "runs.db")
    record = RunRecord(run_id="r1", task="t", task_file="", cell="c", backend="sim",
                       parameters={})
    store.save(record)
    stored = StoredDetails(store)
    first = stored.body("r1")
    assert first is not None and stored.body("r1") is first
    assert json.loads(first)["status"] == "running" and json.loads(first)["tree"] is None
    record.status = "interrupted"
    store.save(record)
    assert json.loads(stored.body("r1") or b"")["status"] == "interrupted"
    assert stored.body("nope") is None
    store.close()


def test_the_run_list_is_cached_until_the_store_is_written(tmp_path: Path):
    store = RunStore(tmp_path / "runs.db")
    listing = RunListCache(store)
    assert listing.body(None, 100) == b"[]"
    assert listing.fresh(None, 100) == b"[]"
    record = RunRecord(run_id="r1", task="t", task_file="", cell="c", backend="sim",
                       parameters={}, exit_code=3, error="boom")
    store.save(record)
    assert listing.fresh(None, 100) is None
    body = listing.body(None, 100)
    rows = TypeAdapter(list[RunSummary]).validate_json(body)
    assert [(r.run_id, r.exit_code, r.error) for r in rows] == [("r1", 3, "boom")]
    assert listing.fresh(None, 100) == body and listing.fresh("failed", 100) is None
    store.close()


def test_polling_a_run_over_http_shows_new_events_and_the_end(client):
    run_id = client.post("/runs", json={"task": "pick_place", "backend": "mock"},
                         headers=AUTH).json()["run_id"]
    seen = []
    while True:
        answer = client.get(f"/runs/{run_id}")
        assert answer.status_code == 200
        assert answer.headers["content-type"] == "application/json"
        body = answer.json()
        RunDetail.model_validate(body)
        seen.append(len(body["events"]))
        if body["status"] != "running":
            break
    final = wait_until_done(client, run_id)
    assert final["events"][-1]["kind"] == "run_finished" and "[✓]" in final["tree"]
    assert seen == sorted(seen)
    assert client.get(f"/runs/{run_id}").content == client.get(f"/runs/{run_id}").content
    listed = client.get("/runs").json()
    assert listed[0]["run_id"] == run_id and listed[0]["status"] == "succeeded"


def test_the_openapi_schema_still_documents_the_run_models(client):
    paths = client.get("/openapi.json").json()["paths"]
    one = paths["/runs/{run_id}"]["get"]["responses"]["200"]["content"]["application/json"]
    assert one["schema"]["$ref"].endswith("/RunDetail")
    many = paths["/runs"]["get"]["responses"]["200"]["content"]["application/json"]
    assert many["schema"]["items"]["$ref"].endswith("/RunSummary")
    assert "404" in paths["/runs/{run_id}"]["get"]["responses"]
