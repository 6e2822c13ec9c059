"""PUT /cells/{id}/poses/{name}: teach the current state as a named pose, use it in a task,
keep it across a restart; refusals for protected names, bad names and busy cells."""

from __future__ import annotations

import pytest
from apitest import AUTH, NO_TOKEN, make_settings, wait_until_done
from fastapi.testclient import TestClient

from taskrunner.api import create_app

GO_TAUGHT = """\
task: go_taught
cell: ../robots/cells/servo_arm_table.yaml
steps:
  - go: {group: arm, to: Candle}
  - go: {group: arm, to: bench_spot}
"""


def move_to_candle(client, timeout: float = 20.0):
    answer = client.post("/runs", json={"yaml": GO_TAUGHT.replace("bench_spot", "Candle"),
                                        "backend": "mock"}, headers=AUTH)
    assert answer.status_code == 202, answer.text
    assert wait_until_done(client, answer.json()["run_id"], timeout)["status"] == "succeeded"


def test_teach_stores_the_backends_state_and_tasks_use_it(client):
    move_to_candle(client)
    answer = client.put("/cells/servo_arm_table/poses/bench_spot",
                        json={"group": "arm", "backend": "mock"}, headers=AUTH)
    assert answer.status_code == 200, answer.text
    pose = answer.json()
    assert pose["group"] == "arm" and pose["name"] == "bench_spot"
    assert pose["joints"]["Revolute 1"] == pytest.approx(1.5708)
    assert set(pose["joints"]) == {f"Revolute {i}" for i in range(1, 6)}
    detail = client.get("/cells/servo_arm_table", headers=AUTH).json()
    assert "bench_spot" in str(detail)
    # A task naming the taught pose is valid and runs.
    run = client.post("/runs", json={"yaml": GO_TAUGHT, "backend": "mock"}, headers=AUTH)
    assert run.status_code == 202, run.text
    assert wait_until_done(client, run.json()["run_id"])["status"] == "succeeded"


def test_taught_poses_survive_a_restart(settings):
    with TestClient(headers=AUTH, app=create_app(settings)) as client:
        move_to_candle(client)
        assert client.put("/cells/servo_arm_table/poses/bench_spot",
                          json={"group": "arm", "backend": "mock"},
                          headers=AUTH).status_code == 200
    with TestClient(headers=AUTH, app=create_app(make_settings(settings.state_dir))) as client:
        run = client.post("/runs", json={"yaml": GO_TAUGHT, "backend": "mock"}, headers=AUTH)
        assert run.status_code == 202, run.text
        assert wait_until_done(client, run.json()["run_id"])["status"] == "succeeded"


def test_teach_refusals(client):
    body = {"group": "arm", "backend": "mock"}
    assert client.put("/cells/servo_arm_table/poses/x", json=body,
                      headers=NO_TOKEN).status_code == 401
    answer = client.put("/cells/servo_arm_table/poses/home", json=body, headers=AUTH)
    assert answer.status_code == 409 and "robot or cell files" in answer.text
    answer = client.put("/cells/servo_arm_table/poses/9lives", json=body, headers=AUTH)
    assert answer.status_code == 422 and "'name' must be" in answer.text
    answer = client.put("/cells/servo_arm_table/poses/spot", json={"group": "amr"}, headers=AUTH)
    assert answer.status_code == 422 and "unknown group 'amr'" in answer.text
    answer = client.put("/cells/nowhere/poses/spot", json=body, headers=AUTH)
    assert answer.status_code == 404


def test_plan_reaches_a_taught_pose_when_planning_in_worker_processes(tmp_path):
    # The workers load the cell from its files; the taught pose exists only in the
    # server's model, so /plan must send its joint values, not its name.
    # planner_nice=0: the test is about what /plan sends, not about priorities (a worker at
    # the default nice 10 beside 4 spinning processes gets a sliver of a core: its first
    # run was still going after 20 s). The run's deadline bounds a hang only: its first
    # plan waits for the spawned worker to import the libraries and load the cell (at
    # nice 0 with 4 spinning processes: 4.8-6.2 s).
    settings = make_settings(tmp_path / "state", planner="worker", planner_nice=0)
    with TestClient(headers=AUTH, app=create_app(settings)) as client:
        move_to_candle(client, timeout=120.0)
        assert client.put("/cells/servo_arm_table/poses/bench_spot",
                          json={"group": "arm", "backend": "mock"},
                          headers=AUTH).status_code == 200
        answer = client.post("/plan", json={"cell": "servo_arm_table", "group": "arm",
                                            "to": "bench_spot", "backend": "mock"})
        assert answer.status_code == 200, answer.text
        plan = answer.json()
        assert plan["positions"][-1][0] == pytest.approx(1.5708, abs=1e-6)
        unknown = client.post("/plan", json={"cell": "servo_arm_table", "group": "arm",
                                             "to": "nowhere", "backend": "mock"})
        assert unknown.status_code == 422 and "bench_spot" in unknown.json()["detail"]
