"""Tokens, body limits and error answers: 401, 404, 409, 413, 422 with file:line."""

from __future__ import annotations

from pathlib import Path

import pytest
from apitest import AUTH, NO_TOKEN, TOKEN, make_settings
from fastapi.testclient import TestClient

from taskrunner.api import Settings, create_app


def test_endpoints_that_change_state_need_the_token(client):
    for method, url in (("post", "/runs"), ("post", "/runs/x/cancel")):
        answer = client.request(method, url, json={"task": "go_home"}, headers=NO_TOKEN)
        assert answer.status_code == 401, url
        assert answer.headers["www-authenticate"] == "Bearer"
    wrong = client.post("/runs", json={"task": "go_home"}, headers={"Authorization": "Bearer no"})
    assert wrong.status_code == 401 and wrong.json()["detail"] == "invalid bearer token"


def test_reads_need_the_token_unless_the_setting_opens_them(tmp_path: Path):
    with TestClient(headers=AUTH, app=create_app(make_settings(tmp_path / "a"))) as client:
        for method, url, body in (
                ("get", "/runs", None), ("get", "/cells", None),
                ("get", "/cells/servo_arm_table", None), ("get", "/runs/x", None),
                ("get", "/runs/x/events", None), ("get", "/cells/servo_arm_table/state", None),
                ("post", "/tasks/check", {"task": "go_home"}),
                ("post", "/plan", {"cell": "servo_arm_table", "group": "arm", "to": "home"})):
            assert client.request(method, url, json=body, headers=NO_TOKEN).status_code \
                == 401, url
        assert client.get("/runs", headers=AUTH).status_code == 200
        assert client.get("/health", headers=NO_TOKEN).status_code == 200  # never needs one
        assert client.get("/openapi.json", headers=NO_TOKEN).status_code == 200  # docs: open
    opened = make_settings(tmp_path / "b", open_reads=True)
    with TestClient(headers=AUTH, app=create_app(opened)) as client:
        assert client.get("/runs", headers=NO_TOKEN).status_code == 200
        assert client.post("/runs", json={"task": "go_home"}, headers=NO_TOKEN).status_code \
            == 401


def test_open_reads_is_settable_from_the_environment():
    assert Settings.from_env({}).open_reads is False
    assert Settings.from_env({"TASKRUNNER_OPEN_READS": "1"}).open_reads is True


def test_without_a_configured_token_the_app_makes_one(tmp_path: Path):
    app = create_app(Settings(state_dir=tmp_path))
    token = app.state.token
    assert isinstance(token, str) and len(token) >= 32
    with TestClient(app) as client:
        assert client.post("/runs/x/cancel", headers=NO_TOKEN).status_code == 401
        answer = client.post("/runs/x/cancel", headers={"Authorization": f"Bearer {token}"})
        assert answer.status_code == 404


def test_running_open_needs_no_token(tmp_path: Path):
    with TestClient(headers=AUTH, app=create_app(Settings(state_dir=tmp_path, auth=False))) as client:
        assert client.post("/runs/x/cancel").status_code == 404
        assert client.get("/health").json()["auth"] is False


def test_a_too_large_body_is_refused_with_413(tmp_path: Path):
    with TestClient(headers=AUTH, app=create_app(make_settings(tmp_path, max_body_bytes=1000))) as client:
        answer = client.post("/runs", json={"yaml": "x" * 2000}, headers=AUTH)
        assert answer.status_code == 413
        assert "at most 1000 bytes" in answer.json()["detail"]


def _streamed(*parts: bytes):
    """A request body sent in chunks, without Content-Length."""
    yield from parts


def test_a_streamed_body_over_the_limit_is_refused_with_413_and_one_under_it_is_read(
        tmp_path: Path):
    headers = {**AUTH, "content-type": "application/json"}
    with TestClient(headers=AUTH, app=create_app(make_settings(tmp_path, max_body_bytes=1000))) as client:
        big = _streamed(b'{"yaml": "', *[b"x" * 100] * 40, b'"}')
        answer = client.post("/tasks/check", content=big, headers=headers)
        assert answer.status_code == 413
        assert "at most 1000 bytes" in answer.json()["detail"]
        small = _streamed(b'{"task": ', b'"go_home"}')
        answer = client.post("/tasks/check", content=small, headers=headers)
        assert answer.status_code == 200, answer.text
        assert answer.json()["ok"] is True


def test_invalid_task_yaml_answers_422_with_file_and_line(client):
    yaml = "task: t\ncell: ../robots/cells/servo_arm_table.yaml\nsteps:\n  - fly: {to: moon}\n"
    answer = client.post("/runs", json={"yaml": yaml}, headers=AUTH)
    assert answer.status_code == 422
    body = answer.json()
    assert body["location"].endswith("tasks/inline.yaml:4")
    assert body["problems"][0]["line"] == 4 and "fly" in body["problems"][0]["message"]


def test_a_task_naming_what_the_cell_lacks_answers_422_with_every_problem(client):
    yaml = ("task: t\ncell: ../robots/cells/servo_arm_table.yaml\nsteps:\n"
            "  - go: {group: arm, to: nowhere}\n  - pick: {arm: leg, object: cube}\n")
    answer = client.post("/runs", json={"yaml": yaml, "backend": "mock"}, headers=AUTH)
    assert answer.status_code == 422
    lines = [p["line"] for p in answer.json()["problems"]]
    assert lines == [4, 5, 5]
    assert client.get("/runs").json() == []  # nothing started


@pytest.mark.parametrize("body, fragment", [
    ({}, "exactly one of 'task'"),
    ({"task": "go_home", "yaml": "task: t"}, "exactly one of 'task'"),
    ({"task": "go_home", "backend": "real"}, "backend"),
    ({"task": "go_home", "colour": "red"}, "colour"),
    ({"task": "../README.md"}, "file name in the tasks folder"),
    ({"task": "no_such_task"}, "known: "),
    ({"task": "pick_place", "parameters": {"pick_x": 9.0}}, "pick_x"),
    ({"task": "go_home", "cell": "atlantis"}, "unknown cell 'atlantis'"),
])
def test_bad_run_requests_answer_4xx_with_the_reason(client, body, fragment):
    answer = client.post("/runs", json=body, headers=AUTH)
    assert answer.status_code in (404, 422)
    assert fragment in str(answer.json()["detail"])


def test_a_body_that_is_not_json_answers_422(client):
    answer = client.post("/runs", content=b"{not json", headers={
        **AUTH, "Content-Type": "application/json"})
    assert answer.status_code == 422


def test_openapi_schema_and_docs_are_served(client):
    schema = client.get("/openapi.json").json()
    assert {"/runs", "/runs/{run_id}", "/runs/{run_id}/cancel", "/runs/{run_id}/events",
            "/tasks/check", "/cells", "/cells/{cell_id}", "/cells/{cell_id}/state",
            "/health"} <= set(schema["paths"])
    assert client.get("/docs").status_code == 200


def test_the_token_must_be_long_enough():
    with pytest.raises(ValueError, match="'token' must be at least 8 characters"):
        Settings(token="short")
    assert len(TOKEN) >= 8


@pytest.mark.parametrize("nice", [-1, 20, 2.5, True, "ten"])
def test_the_planners_niceness_must_be_an_integer_from_0_to_19(nice):
    with pytest.raises(ValueError, match="'planner_nice' must be an integer from 0 to 19"):
        Settings(planner_nice=nice)


@pytest.mark.parametrize(("variable", "text", "message"), [
    ("TASKRUNNER_PLANNER_NICE", "low", "TASKRUNNER_PLANNER_NICE: 'planner_nice' must be an "
                                       "integer"),
    ("TASKRUNNER_MAX_BODY_BYTES", "1e6", "TASKRUNNER_MAX_BODY_BYTES: 'max_body_bytes' must be "
                                         "a positive integer"),
    ("TASKRUNNER_SIM_SPEED", "fast", "TASKRUNNER_SIM_SPEED: 'sim_speed' must be a positive "
                                     "number"),
    ("TASKRUNNER_CHECK_TIMEOUT_S", "-1", "'check_timeout_s' must be a positive number"),
    ("TASKRUNNER_PLANNER_NICE", "25", "'planner_nice' must be an integer from 0 to 19")])
def test_bad_environment_values_are_named(variable, text, message):
    with pytest.raises(ValueError, match=message) as raised:
        Settings.from_env({variable: text})
    assert repr(text) in str(raised.value) or text in str(raised.value)


def test_settings_from_the_environment():
    settings = Settings.from_env({"TASKRUNNER_PLANNER_NICE": "5", "TASKRUNNER_SIM_SPEED": "2",
                                  "TASKRUNNER_MAX_BODY_BYTES": "2048"})
    assert (settings.planner_nice, settings.sim_speed, settings.max_body_bytes) == (5, 2.0, 2048)
    assert Settings().planner_nice == 10
