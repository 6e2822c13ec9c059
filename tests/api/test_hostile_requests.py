"""Hostile names and numbers sent to the API: every one a 4xx naming the field or the
file:line, never a 500, a traceback, a resolved server path or the server's PID (issue 29).

The inputs are those a probe of the server found answering 500 or accepted silently:
mesh and cell names over 255 bytes, NUL characters, lone surrogates and symlink loops;
booleans, NaN and Infinity where numbers belong; ``times: 2**63``; 60,000 parameters.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

import pytest
from apitest import AUTH, make_settings
from fastapi.testclient import TestClient

from taskrunner.api import create_app
from taskrunner.api.handlers import MAX_PROBLEMS
from taskrunner.api.schemas import MAX_PARAMETERS
from taskrunner.resources import cells_dir

CELL = "../robots/cells/servo_arm_table.yaml"
JSON = {"content-type": "application/json", **AUTH}
# The endpoints that load a task sent inline: each must refuse it the same way.
TASK_ENDPOINTS = ("/tasks/check", "/runs", "/viewer/tasks/tree", "/viewer/tasks/preview")


def _task(*, cell: str = CELL, objects: str = "", steps: str = "  - go: {group: arm, to: home}\n",
          ) -> str:
    return f"task: t\ncell: {cell}\n{objects}steps:\n{steps}"


def _mesh(file: str) -> str:
    return f"objects:\n  - {{name: part, shape: mesh, file: {file}, pose: {{xyz: [0.1, 0.1, 0.8]}}}}\n"


def _post(client: TestClient, endpoint: str, body: dict[str, Any]) -> Any:
    if endpoint == "/runs":
        body = {**body, "backend": "mock"}
    # ASCII JSON: a lone surrogate goes over the wire as its escape, as a client sends it.
    return client.post(endpoint, content=json.dumps(body).encode(), headers=JSON)


def _refused(answer: Any, *expected: str) -> str:
    """The text of an answer that refuses the request cleanly: 422 (or /tasks/check's 200
    with ok false), mentioning one of ``expected``, without a traceback or the PID."""
    text = answer.text
    assert answer.status_code in (200, 422), f"{answer.status_code}: {text[:2000]}"
    if answer.status_code == 200:
        assert answer.json()["ok"] is False, text[:2000]
    assert "Traceback" not in text and "Internal Server Error" not in text
    assert f"/proc/{os.getpid()}" not in text
    assert any(e in text for e in expected), f"none of {expected} in {text[:2000]}"
    return text


@pytest.fixture
def looped(tmp_path: Path) -> TestClient:
    """A server whose tasks folder holds a loop of two symlinks (``la`` → ``lb`` → ``la``)."""
    tasks = tmp_path / "tasks"
    tasks.mkdir()
    os.symlink(tasks / "la", tasks / "lb")
    os.symlink(tasks / "lb", tasks / "la")
    settings = make_settings(tmp_path / "state", tasks_dir=tasks)
    with TestClient(create_app(settings), headers=AUTH) as client:
        yield client


HOSTILE_TASKS = {
    "mesh name of 300 bytes": (_task(objects=_mesh("m" * 300 + ".stl")), "names end at 255"),
    "mesh name of 300 bytes in 100 é": (_task(objects=_mesh("é" * 150 + ".stl")),
                                         "names end at 255"),
    "mesh path of 5000 bytes": (_task(objects=_mesh("d/" * 2500 + "m.stl")), "paths end at 4095"),
    "mesh path with NUL": (_task(objects=_mesh('"a\\0b.stl"')), "NUL character"),
    "mesh in /proc/self": (_task(objects=_mesh("/proc/self/environ")), "'/proc/self/environ'"),
    "cell path with NUL": (_task(cell='"../robots/cells/servo\\0arm_table.yaml"'), "NUL"),
    "cell name of 300 bytes": (_task(cell="c" * 300 + ".yaml"), "c" * 300),
    "cell in /proc/self": (_task(cell="/proc/self/environ"), "'/proc/self/environ'"),
    "boolean in a pose": (_task(objects="objects:\n  - {name: b, shape: box, size: [0.02, 0.02, "
                                        "0.02], pose: {xyz: [0.2, true, 0.8]}}\n"),
                          "'objects[0].pose.xyz[1]' must be a number, not a boolean (got true)"),
    "boolean joint": (_task(steps='  - go: {group: arm, joints: {"Revolute 1": true}}\n'),
                      "must be a number, not a boolean"),
    "NaN joint": (_task(steps='  - go: {group: arm, joints: {"Revolute 1": .nan}}\n'),
                  "must be a finite number (got nan)"),
    "repeat 2**63 times": (_task(steps="  - repeat: {times: 9223372036854775808, do: "
                                       "[{wait: {seconds: 1}}]}\n"),
                           "'repeat.times' must be <= 1e+06"),
    "wait true seconds": (_task(steps="  - wait: {seconds: true}\n"),
                          "'wait.seconds' must be a number, not a boolean (got true)"),
    "timeout of inf": (_task(steps="  - timeout: {seconds: .inf, do: [{wait: {seconds: 1}}]}\n"),
                       "'timeout.seconds' must be a finite number"),
}


@pytest.mark.parametrize("endpoint", TASK_ENDPOINTS)
@pytest.mark.parametrize("case", list(HOSTILE_TASKS), ids=list(HOSTILE_TASKS))
def test_a_hostile_inline_task_is_refused_naming_it_on_every_endpoint(client, case, endpoint):
    yaml, expected = HOSTILE_TASKS[case]
    text = _refused(_post(client, endpoint, {"yaml": yaml}), expected)
    assert "inline.yaml:" in text  # located at the task's line


@pytest.mark.parametrize("endpoint", TASK_ENDPOINTS)
def test_a_mesh_through_a_symlink_loop_is_refused_not_a_500(looped, endpoint):
    cell = cells_dir() / "servo_arm_table.yaml"
    yaml = _task(cell=str(cell), objects=_mesh("la/part.stl"))
    text = _refused(_post(looped, endpoint, {"yaml": yaml}), "'la/part.stl'")
    assert "inline.yaml:4" in text


def test_a_path_is_named_as_the_request_wrote_it_not_resolved(client):
    yaml = _task(cell="../robots/cells/../cells/servo\x00arm_table.yaml".replace("\x00", "\\0"))
    yaml = yaml.replace("cell: ", 'cell: "', 1).replace(".yaml\n", '.yaml"\n', 1)
    [problem] = client.post("/tasks/check", json={"yaml": yaml}).json()["problems"]
    assert "'../robots/cells/../cells/servo\\x00arm_table.yaml'" in problem["message"]
    assert str(cells_dir()) not in problem["message"]


PLAN = {"cell": "servo_arm_table", "group": "arm"}
HOSTILE_PLANS = {
    "NaN joint": ('{"joints": {"Revolute 1": NaN}}', ["joints", "Revolute 1"], "finite"),
    "Infinity joint": ('{"joints": {"Revolute 1": Infinity}}', ["joints", "Revolute 1"],
                       "finite"),
    "boolean joint": ('{"joints": {"Revolute 1": true}}', ["joints", "Revolute 1"],
                      "not a boolean"),
    "boolean in a pose": ('{"pose": {"xyz": [0.2, 0, true]}}', ["pose", "xyz", 2],
                          "not a boolean"),
    "-Infinity in a pose": ('{"pose": {"xyz": [0.2, 0, -Infinity]}}', ["pose", "xyz", 2],
                            "finite"),
    "NaN rpy": ('{"pose": {"xyz": [0.2, 0, 0.8], "rpy": [NaN, 0, 0]}}', ["pose", "rpy", 0],
                "finite"),
    "1e999 planning time": ('{"to": "home", "planning_time": 1e999}', ["planning_time"],
                            "finite"),
    "boolean planning time": ('{"to": "home", "planning_time": true}', ["planning_time"],
                              "not a boolean"),
    "boolean seed": ('{"to": "home", "seed": true}', ["seed"], "not a boolean"),
    "text velocity scaling": ('{"to": "home", "velocity_scaling": "0.5"}',
                              ["velocity_scaling"], "valid number"),
}


@pytest.mark.parametrize("case", list(HOSTILE_PLANS), ids=list(HOSTILE_PLANS))
def test_a_plan_with_a_number_that_is_not_one_is_a_422_naming_the_field(client, case):
    extra, loc, message = HOSTILE_PLANS[case]
    body = json.dumps(PLAN)[:-1] + ", " + extra[1:]
    answer = client.post("/plan", content=body.encode(), headers=JSON)
    assert answer.status_code == 422, answer.text
    [error] = answer.json()["detail"]
    assert error["loc"] == ["body", *loc] and message in error["msg"], error


@pytest.mark.parametrize("field,value", [("speed", "true"), ("speed", "NaN"), ("seed", "true"),
                                         ("seed", "1.5")])
def test_a_run_request_number_that_is_not_one_is_a_422_naming_the_field(client, field, value):
    body = f'{{"task": "pick_place", "backend": "mock", "{field}": {value}}}'
    answer = client.post("/runs", content=body.encode(), headers=JSON)
    assert answer.status_code == 422, answer.text
    assert [e["loc"] for e in answer.json()["detail"]] == [["body", field]]


def test_60000_parameters_get_a_short_422_not_a_25_mb_answer(client):
    parameters = {f"p{i}": i for i in range(60_000)}
    body = json.dumps({"task": "pick_place", "parameters": parameters}).encode()
    assert len(body) > 900_000
    for endpoint in ("/tasks/check", "/runs"):
        answer = client.post(endpoint, content=body, headers=JSON)
        assert answer.status_code == 422, answer.text[:500]
        assert len(answer.content) < 2_000, len(answer.content)
        [error] = answer.json()["detail"]
        assert error["loc"] == ["body", "parameters"]
        assert f"at most {MAX_PARAMETERS} items" in error["msg"]


def test_an_error_answer_lists_at_most_a_hundred_problems_then_how_many_more(client):
    parameters = {f"p{i}": i for i in range(MAX_PARAMETERS)}
    answer = client.post("/runs", json={"task": "pick_place", "backend": "mock",
                                        "parameters": parameters})
    assert answer.status_code == 422
    problems = answer.json()["problems"]
    assert len(problems) == MAX_PROBLEMS + 1
    assert problems[-1]["message"] == f"and {MAX_PARAMETERS - MAX_PROBLEMS} more problems"
    assert len(answer.content) < 200_000, len(answer.content)


def test_a_request_holding_a_lone_surrogate_gets_a_422_that_encodes(client):
    mesh = json.dumps({"yaml": _task(objects=_mesh("a\udcffb.stl"))})  # "\\udcff" in JSON
    for endpoint, body in (("/tasks/check", r'{"task": "\ud800"}'), ("/tasks/check", mesh),
                           ("/runs", r'{"task": "pick_place", "backend": "mock", '
                                     r'"cell": "\ud800"}')):
        answer = client.post(endpoint, content=body.encode(), headers=JSON)
        assert answer.status_code == 422, answer.text
        [error] = answer.json()["detail"]
        assert error["loc"][-1] in ("task", "cell", "yaml") and "codec" not in answer.text
