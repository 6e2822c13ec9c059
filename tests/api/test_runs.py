"""POST/GET /runs, cancel, SSE replay, arms in use, records surviving a restart."""

from __future__ import annotations

import json
import textwrap
import time
from pathlib import Path

from apitest import AUTH, make_settings, parse_sse, wait_for_event, wait_until_done
from fastapi.testclient import TestClient

from taskrunner.api import create_app
from taskrunner.api.store import RunStore
from taskrunner.runtime.records import RunRecord

GO_CANDLE = textwrap.dedent("""\
    task: go_candle
    cell: ../robots/cells/servo_arm_table.yaml
    steps:
      - go: {group: arm, to: Candle}
      - go: {group: arm, to: home}
    """)


def pair_task(arm: str, pose: str) -> str:
    """A go of one arm of the pair, slowed to 2 % of the servo speeds (~20 s of motion):
    long enough, even at sim x40, for both runs to be seen running at once."""
    return (f"task: {arm}_{pose}\ncell: ../robots/cells/servo_arm_pair.yaml\n"
            f"steps:\n  - go: {{group: {arm}, to: {pose}, velocity_scaling: 0.02, "
            f"acceleration_scaling: 0.02}}\n")


def test_a_task_by_file_name_runs_to_success_on_the_mock_backend(client):
    answer = client.post("/runs", json={"task": "pick_place", "backend": "mock"}, headers=AUTH)
    assert answer.status_code == 202
    run_id = answer.json()["run_id"]
    assert answer.headers["location"] == f"/runs/{run_id}"
    run = wait_until_done(client, run_id)
    assert run["status"] == "succeeded" and run["exit_code"] == 0
    assert run["task"] == "pick_place" and run["cell"] == "servo_arm_table"
    assert run["task_file"].endswith("tasks/pick_place.yaml")
    assert run["events"][0]["kind"] == "run_started"
    assert run["events"][-1]["kind"] == "run_finished"
    assert "[✓]" in run["tree"] and run["current"] is None
    assert any(e["location"] and e["location"].endswith("pick_place.yaml:13")
               for e in run["events"])


def test_an_inline_task_runs_with_its_parameters_and_keeps_its_text(client):
    yaml = GO_CANDLE.replace("steps:", "parameters:\n  pose: {default: Candle, type: str}\n"
                             "steps:").replace("to: Candle", "to: \"${pose}\"")
    answer = client.post("/runs", json={"yaml": yaml, "backend": "mock",
                                        "parameters": {"pose": "home"}}, headers=AUTH)
    assert answer.status_code == 202, answer.text
    run = wait_until_done(client, answer.json()["run_id"])
    assert run["status"] == "succeeded"
    assert run["parameters"] == {"pose": "home"}
    assert run["task_file"].endswith("tasks/inline.yaml")


def test_runs_are_listed_newest_first_and_filtered_by_status(client):
    first = client.post("/runs", json={"task": "go_home", "backend": "mock"}, headers=AUTH)
    wait_until_done(client, first.json()["run_id"])
    listed = client.get("/runs").json()
    assert [r["run_id"] for r in listed] == [first.json()["run_id"]]
    assert client.get("/runs", params={"status": "succeeded"}).json() == listed
    assert client.get("/runs", params={"status": "failed"}).json() == []
    assert client.get("/runs", params={"status": "bogus"}).status_code == 422


def test_an_unknown_run_answers_404_everywhere(client):
    assert client.get("/runs/nope").status_code == 404
    assert client.get("/runs/nope/events").status_code == 404
    answer = client.post("/runs/nope/cancel", headers=AUTH)
    assert answer.status_code == 404 and "unknown run 'nope'" in answer.json()["detail"]


def test_cancel_stops_a_sim_run_mid_motion_and_records_it_cancelled(client):
    answer = client.post("/runs", json={"yaml": GO_CANDLE, "backend": "sim"}, headers=AUTH)
    run_id = answer.json()["run_id"]
    running = wait_for_event(client, run_id, "planned")
    deadline = time.monotonic() + 10
    while running["current"] is None and time.monotonic() < deadline:  # mid-tick: look again
        running = client.get(f"/runs/{run_id}").json()
    assert running["status"] == "running"
    assert running["current"]["node"] == "go arm"
    assert running["current"]["location"].endswith("inline.yaml:4")
    cancelled = client.post(f"/runs/{run_id}/cancel", headers=AUTH)
    assert cancelled.status_code == 202
    run = wait_until_done(client, run_id)
    assert run["status"] == "cancelled" and run["exit_code"] == 130
    again = client.post(f"/runs/{run_id}/cancel", headers=AUTH)
    assert again.status_code == 409 and "already ended (cancelled)" in again.json()["detail"]


def test_a_run_needing_an_arm_in_use_is_refused_with_409(client):
    first = client.post("/runs", json={"yaml": GO_CANDLE, "backend": "sim"}, headers=AUTH)
    run_id = first.json()["run_id"]
    second = client.post("/runs", json={"task": "pick_place", "backend": "mock"}, headers=AUTH)
    assert second.status_code == 409
    assert run_id in second.json()["detail"] and "'Revolute 1'" in second.json()["detail"]
    client.post(f"/runs/{run_id}/cancel", headers=AUTH)
    wait_until_done(client, run_id)
    third = client.post("/runs", json={"task": "go_home", "backend": "mock"}, headers=AUTH)
    assert third.status_code == 202


def test_runs_on_different_arms_of_one_cell_run_at_once_on_one_backend(tmp_path: Path):
    with TestClient(headers=AUTH, app=create_app(make_settings(tmp_path / "state", sim_speed=40.0))) as client:
        _run_both_arms(client)


def _run_both_arms(client: TestClient) -> None:
    left = client.post("/runs", json={"yaml": pair_task("left_arm", "HandOff"),
                                      "backend": "sim"}, headers=AUTH)
    right = client.post("/runs", json={"yaml": pair_task("right_arm", "PickUp"),
                                       "backend": "sim"}, headers=AUTH)
    assert left.status_code == right.status_code == 202, right.text
    state = client.get("/cells/servo_arm_pair/state").json()
    assert sorted(state["running"]) == sorted([left.json()["run_id"], right.json()["run_id"]])
    for answer in (left, right):
        assert wait_until_done(client, answer.json()["run_id"])["status"] == "succeeded"
    joints = client.get("/cells/servo_arm_pair/state").json()["joints"]
    assert abs(joints["left_Revolute 2"] - -1.7207) < 1e-3  # HandOff
    assert abs(joints["right_Revolute 2"] - -0.9417) < 1e-3  # PickUp


def test_the_event_stream_replays_from_last_event_id_to_the_end(client):
    run_id = client.post("/runs", json={"task": "pick_place", "backend": "mock"},
                         headers=AUTH).json()["run_id"]
    whole = parse_sse(client.get(f"/runs/{run_id}/events").text)  # follows it live
    assert whole[0]["event"] == "run_started" and whole[-1]["event"] == "run_finished"
    assert [int(e["id"]) for e in whole] == list(range(1, len(whole) + 1))
    rest = parse_sse(client.get(f"/runs/{run_id}/events",
                                headers={"Last-Event-ID": "10"}).text)
    assert [e["id"] for e in rest] == [e["id"] for e in whole[10:]]
    assert rest == whole[10:]
    by_query = parse_sse(client.get(f"/runs/{run_id}/events", params={"after": 10}).text)
    assert by_query == rest
    bad = client.get(f"/runs/{run_id}/events", headers={"Last-Event-ID": "x"})
    assert bad.status_code == 422


def test_a_stream_sleeps_until_the_run_emits(client):
    # Subscribed to the run (woken by the runner's thread), not polling. That a client
    # which leaves is unsubscribed is tested over a real socket (test_sse_wire.py): the
    # test client does not tell the app when a streamed response is closed early.
    run_id = client.post("/runs", json={"yaml": GO_CANDLE, "backend": "sim"},
                         headers=AUTH).json()["run_id"]
    live = client.app.state.manager.live(run_id)
    before = len(live.events._subscribers)
    with client.stream("GET", f"/runs/{run_id}/events") as stream:
        lines = stream.iter_lines()
        assert next(line for line in lines if line.startswith("event:")) == "event: run_started"
        assert len(live.events._subscribers) == before + 1
        client.post(f"/runs/{run_id}/cancel", headers=AUTH)
        assert any(line == "event: run_finished" for line in lines)  # the stream ends with it
    wait_until_done(client, run_id)
    assert len(live.events._subscribers) == before


def test_records_survive_a_restart_and_a_run_in_flight_is_recorded_interrupted(tmp_path: Path):
    settings = make_settings(tmp_path / "state")
    with TestClient(headers=AUTH, app=create_app(settings)) as client:
        done = client.post("/runs", json={"task": "go_home", "backend": "mock"},
                           headers=AUTH).json()["run_id"]
        finished = wait_until_done(client, done)
        flying = client.post("/runs", json={"yaml": GO_CANDLE, "backend": "sim"},
                             headers=AUTH).json()["run_id"]
        wait_for_event(client, flying, "planned")
    with TestClient(headers=AUTH, app=create_app(settings)) as client:
        again = client.get(f"/runs/{done}").json()
        assert again["status"] == "succeeded"
        assert again["tree"] == finished["tree"] and "[✓]" in again["tree"]
        assert again["events"] == finished["events"]
        stopped = client.get(f"/runs/{flying}").json()
        assert stopped["status"] == "interrupted" and stopped["finished"] is not None
        assert stopped["tree"] and stopped["current"] is None
        replay = parse_sse(client.get(f"/runs/{done}/events").text)
        assert len(replay) == len(finished["events"])


def test_rows_left_running_by_a_dead_server_are_marked_interrupted(tmp_path: Path):
    settings = make_settings(tmp_path / "state")
    store = RunStore(settings.db_path)
    store.save(RunRecord(run_id="r1", task="t", task_file="", cell="c", backend="sim",
                         parameters={}))
    store.close()
    with TestClient(headers=AUTH, app=create_app(settings)) as client:
        run = client.get("/runs/r1").json()
    assert run["status"] == "interrupted"
    assert "server stopped" in run["error"]


def test_only_the_newest_ended_runs_stay_in_memory_the_others_come_from_the_store(
        tmp_path: Path):
    settings = make_settings(tmp_path / "state")
    with TestClient(headers=AUTH, app=create_app(settings)) as client:
        manager = client.app.state.manager
        manager.keep_finished = 2
        runs = []
        for _ in range(4):
            run_id = client.post("/runs", json={"task": "go_home", "backend": "mock"},
                                 headers=AUTH).json()["run_id"]
            runs.append(wait_until_done(client, run_id))
            manager.live(run_id).thread.join(10)  # its end is recorded, older runs dropped
        assert [manager.live(r["run_id"]) is not None for r in runs] == \
            [False, False, True, True]
        for run in runs:  # the same answer, live or from the store
            assert client.get(f"/runs/{run['run_id']}").json() == run
        events = parse_sse(client.get(f"/runs/{runs[0]['run_id']}/events").text)
        assert len(events) == len(runs[0]["events"])
        assert [r["run_id"] for r in client.get("/runs").json()] == \
            [r["run_id"] for r in reversed(runs)]


def test_a_database_from_before_final_trees_were_kept_is_upgraded(tmp_path: Path):
    import sqlite3

    path = tmp_path / "runs.sqlite"
    old = sqlite3.connect(path)
    old.executescript("CREATE TABLE runs (run_id TEXT PRIMARY KEY, status TEXT NOT NULL, "
                      "task TEXT NOT NULL, cell TEXT NOT NULL, backend TEXT NOT NULL, "
                      "started TEXT NOT NULL, finished TEXT, record TEXT NOT NULL);")
    record = RunRecord(run_id="r0", task="t", task_file="", cell="c", backend="sim",
                       parameters={})
    old.execute("INSERT INTO runs VALUES ('r0', 'succeeded', 't', 'c', 'sim', 'x', NULL, ?)",
                (json.dumps(record.as_dict()),))
    old.commit()
    old.close()
    store = RunStore(path)
    assert store.load_row("r0")[1] is None
    store.save(record, tree="-> root")
    store.save(record)  # a later save without a tree keeps it
    assert store.load_row("r0")[1] == "-> root"
    store.close()


def test_an_ended_run_shows_no_current_node_even_before_its_thread_has_finished():
    from types import SimpleNamespace

    from taskrunner.api.runs import LiveRun

    record = RunRecord(run_id="r1", task="t", task_file="", cell="c", backend="sim",
                       parameters={})
    leaf = SimpleNamespace(name="go arm", location="t.yaml:4")
    live = LiveRun(SimpleNamespace(record=record, current_leaf=lambda: leaf), None,
                   frozenset())
    record.status = "running"
    assert live.current() == ("go arm", "t.yaml:4")
    record.status = "succeeded"  # set by the runner; done is set a moment later
    assert live.current() is None


PLACE_OUT_OF_REACH = textwrap.dedent("""\
    task: place_far
    cell: ../robots/cells/servo_arm_table.yaml
    objects:
      - {name: cube, shape: box, size: [0.025, 0.025, 0.025], pose: {xyz: [0.19, 0.04, 0.7625]}}
    steps:
      - pick: {arm: arm, object: cube, grasp: top}
      - place: {arm: arm, object: cube, at: {xyz: [1.5, 0.0, 0.7635]}}
    """)


def test_a_run_whose_check_fails_starts_nothing_and_lists_every_problem(client):
    before = client.get("/runs", headers=AUTH).json()
    answer = client.post("/runs", json={"yaml": PLACE_OUT_OF_REACH, "backend": "mock"},
                         headers=AUTH)
    assert answer.status_code == 422, answer.text
    body = answer.json()
    assert body["problems"] and body["problems"][0]["line"] == 7
    assert "reach" in body["problems"][0]["message"]
    assert client.get("/runs", headers=AUTH).json() == before  # no run was started


def test_check_false_skips_the_check_and_the_run_fails_where_it_cannot_go_on(client):
    answer = client.post("/runs", json={"yaml": PLACE_OUT_OF_REACH, "backend": "mock",
                                        "check": False}, headers=AUTH)
    assert answer.status_code == 202, answer.text
    run = wait_until_done(client, answer.json()["run_id"])
    assert run["status"] == "failed"
