"""API parity with the command line: one set of taught poses for runs and checks, every
backend (mock, sim, serial, http), a sim speed per run."""

from __future__ import annotations

import sys
import time
from pathlib import Path

import pytest
from apitest import AUTH, make_settings, wait_until_done
from fastapi.testclient import TestClient

from taskrunner import resources
from taskrunner.api import create_app
from taskrunner.robot.cell import load_cell

sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "backends"))
from firmware_host import build_host, running_host

CELL = "../robots/cells/servo_arm_table.yaml"
GO_BENCH = f"task: t\ncell: {CELL}\nsteps:\n  - go: {{group: arm, to: bench}}\n"
GO_CANDLE = f"task: c\ncell: {CELL}\nsteps:\n  - go: {{group: arm, to: Candle}}\n"


def test_a_taught_pose_is_known_to_check_as_to_runs(client):
    before = client.post("/tasks/check", json={"yaml": GO_BENCH}).json()
    assert before["ok"] is False and "'bench'" in before["problems"][0]["message"]
    run = client.post("/runs", json={"yaml": GO_CANDLE, "backend": "mock"})
    assert wait_until_done(client, run.json()["run_id"])["status"] == "succeeded"
    taught = client.put("/cells/servo_arm_table/poses/bench",
                        json={"group": "arm", "backend": "mock"})
    assert taught.status_code == 200, taught.text
    after = client.post("/tasks/check", json={"yaml": GO_BENCH}).json()
    assert after["ok"] is True, after
    run = client.post("/runs", json={"yaml": GO_BENCH, "backend": "mock"})
    assert wait_until_done(client, run.json()["run_id"])["status"] == "succeeded"


def test_a_run_asks_for_a_sim_speed(tmp_path: Path):
    settings = make_settings(tmp_path / "state", sim_speed=1.0)
    with TestClient(create_app(settings), headers=AUTH) as client:
        started = time.monotonic()
        run = client.post("/runs", json={"yaml": GO_CANDLE, "backend": "sim", "speed": 200})
        assert run.status_code == 202, run.text
        body = wait_until_done(client, run.json()["run_id"], timeout=30)
        assert body["status"] == "succeeded"
        assert time.monotonic() - started < 15  # at speed 1 the motion alone takes longer
        bad = client.post("/runs", json={"yaml": GO_CANDLE, "backend": "sim", "speed": 0})
        assert bad.status_code == 422


def test_the_http_backend_needs_the_server_set_up_for_it(client):
    answer = client.post("/runs", json={"task": "go_home", "backend": "http"})
    assert answer.status_code == 422 and "servo_url" in answer.json()["detail"]


@pytest.mark.parametrize("kind", ["serial", "http"])
def test_runs_drive_the_servos_over_serial_and_http(tmp_path: Path, kind: str):
    binary = build_host()
    with running_host(binary, 50.0) as host:
        settings = make_settings(tmp_path / "state", servo_port=host.pty, servo_url=host.url,
                                 firmware_speedup=50.0)
        with TestClient(create_app(settings), headers=AUTH) as client:
            run = client.post("/runs", json={"yaml": GO_CANDLE, "backend": kind})
            assert run.status_code == 202, run.text
            body = wait_until_done(client, run.json()["run_id"], timeout=60)
            assert body["status"] == "succeeded", body.get("error")
            assert body["backend"] == kind
            state = client.get("/cells/servo_arm_table/state", params={"backend": kind})
            assert state.status_code == 200
            candle = load_cell(resources.cells_dir() / "servo_arm_table.yaml").model \
                .named_state("arm", "Candle").as_dict()
            for joint, value in candle.items():  # the servos report the pose (1° steps)
                assert state.json()["joints"][joint] == pytest.approx(value, abs=0.03), joint


def test_the_command_line_can_read_the_poses_the_api_taught(tmp_path: Path):
    from taskrunner.taught import read_taught_poses
    from taskrunner.tree.check import check_task

    settings = make_settings(tmp_path / "state")
    with TestClient(create_app(settings), headers=AUTH) as client:
        run = client.post("/runs", json={"yaml": GO_CANDLE, "backend": "mock"})
        assert wait_until_done(client, run.json()["run_id"])["status"] == "succeeded"
        assert client.put("/cells/servo_arm_table/poses/bench",
                          json={"group": "arm", "backend": "mock"}).status_code == 200
    task = resources.tasks_dir() / "go_home.yaml"
    bench = tmp_path / "bench.yaml"
    bench.write_text(task.read_text().replace("to: home", "to: bench")
                     .replace("../robots/", f"{resources.robots_dir()}/"))
    assert not check_task(bench).ok
    assert check_task(bench, taught=read_taught_poses(settings.db_path, settings.cells_dir)).ok
    assert read_taught_poses(tmp_path / "none.sqlite", settings.cells_dir).by_cell == {}


def test_a_run_on_the_physics_backend_succeeds_through_the_api(client):
    run = client.post("/runs", json={"task": "pick_place", "backend": "mujoco"})
    assert run.status_code == 202, run.text
    body = wait_until_done(client, run.json()["run_id"], timeout=120)
    assert body["status"] == "succeeded", body.get("error")
