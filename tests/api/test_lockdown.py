"""The API loads only from its folders, runs no request-named xacro, holds inline tasks in
memory, and bounds the work a request causes (time, memory, slow headers)."""

from __future__ import annotations

import math
import os
import socket
import threading
import time
from pathlib import Path

import pytest
from apitest import AUTH, make_settings
from fastapi.testclient import TestClient

from taskrunner import resources
from taskrunner.api import Settings, create_app
from taskrunner.api.requestwork import RequestWork, WorkLimitError

SECRET = "SECRET-CONTENT-4f1c: do not show\nsecond: line\n"
CELL = "../robots/cells/servo_arm_table.yaml"


@pytest.fixture
def secret(tmp_path: Path) -> Path:
    path = tmp_path / "outside" / "secret.yaml"
    path.parent.mkdir()
    path.write_text(SECRET)
    return path


def _no_secret(answer) -> None:
    assert "SECRET-CONTENT" not in answer.text and "second" not in answer.text


# ---------------------------------------------------------------- folders
def test_an_inline_task_naming_a_cell_outside_the_folders_is_refused_unread(client, secret):
    yaml = f"task: t\ncell: {secret}\nsteps:\n  - go: {{group: arm, to: home}}\n"
    report = client.post("/tasks/check", json={"yaml": yaml})
    assert report.status_code == 200 and report.json()["ok"] is False
    [problem] = report.json()["problems"]
    assert problem["line"] == 2 and problem["file"].endswith("inline.yaml")
    assert "outside the folders this server loads cells from" in problem["message"]
    _no_secret(report)
    run = client.post("/runs", json={"yaml": yaml, "backend": "mock"})
    assert run.status_code == 422 and "outside the folders" in run.json()["detail"]
    _no_secret(run)


def test_an_include_outside_the_tasks_folder_is_refused_unread(client, secret):
    yaml = (f"task: t\ncell: {CELL}\nsteps:\n  - go: {{group: arm, to: home}}\n"
            f"  - include: {{file: {secret}}}\n")
    report = client.post("/tasks/check", json={"yaml": yaml})
    [problem] = report.json()["problems"]
    assert problem["line"] == 5 and "outside the folders this server loads tasks from" \
        in problem["message"]
    _no_secret(report)
    relative = yaml.replace(str(secret), "../../../../../../../../../" + str(secret))
    _no_secret(client.post("/tasks/check", json={"yaml": relative}))
    run = client.post("/runs", json={"yaml": yaml, "backend": "mock"})
    assert run.status_code == 422
    _no_secret(run)


@pytest.mark.parametrize("name", ["é" * 200, "a" * 251, "b" * 255])
def test_a_task_name_too_long_for_a_file_is_a_422_not_a_500(client, name):
    # Within the schema's 255 characters, but too many bytes for a file name with '.yaml'.
    for answer in (client.post("/runs", json={"task": name, "backend": "mock"}),
                   client.post("/tasks/check", json={"task": name})):
        assert answer.status_code == 422, answer.text
        assert "at most 250 bytes" in answer.text


def test_a_symlink_in_the_tasks_folder_pointing_outside_is_refused(tmp_path: Path, secret):
    tasks = tmp_path / "tasks"
    tasks.mkdir()
    (tasks / "evil.yaml").symlink_to(secret)
    (tasks / "looped.yaml").symlink_to(tasks / "looped.yaml")
    settings = make_settings(tmp_path / "state", tasks_dir=tasks)
    with TestClient(create_app(settings), headers=AUTH) as client:
        for name in ("evil", "looped"):
            answer = client.post("/tasks/check", json={"task": name})
            assert answer.status_code in (200, 422), answer.text
            assert "outside the folders" in answer.text or "must name a task file" \
                in answer.text
            _no_secret(answer)


def test_a_symlinked_cell_pointing_outside_is_not_listed_nor_read(tmp_path: Path, secret):
    cells = tmp_path / "cells"
    cells.mkdir()
    (cells / "leak.yaml").symlink_to(secret)
    settings = make_settings(tmp_path / "state", cells_dir=cells)
    with TestClient(create_app(settings), headers=AUTH) as client:
        assert client.get("/cells").json() == []
        answer = client.get("/cells/leak")
        assert answer.status_code == 404
        _no_secret(answer)


def _evil_cell(root: Path) -> tuple[Path, Path]:
    """A cells folder whose cell names a robot outside it, a xacro that would write
    ``MARKER`` (xacro's expression sandbox can be escaped); and the marker's path."""
    marker = root / "MARKER"
    (root / "robots" / "evil").mkdir(parents=True)
    (root / "cells").mkdir()
    (root / "robots" / "evil" / "evil.urdf.xacro").write_text(f"""<?xml version="1.0"?>
<robot xmlns:xacro="http://www.ros.org/wiki/xacro" name="evil">
  <xacro:property name="d" value="${{python.vars(python.type(load_yaml))['__globals__']}}"/>
  <xacro:property name="g" value="${{python.vars(python.type(d))['__get__'](d, load_yaml)}}"/>
  <link name="base${{'' if g['os'].system('touch {marker}') == 0 else ''}}"/>
</robot>
""")
    (root / "cells" / "evil.yaml").write_text(
        "name: evil\nrobots:\n  - {name: arm, robot: ../robots/evil/evil.urdf.xacro}\n")
    return root / "cells", marker


def test_a_cell_naming_a_robot_outside_the_robot_folders_runs_no_xacro(tmp_path: Path):
    cells, marker = _evil_cell(tmp_path / "site")
    tasks = tmp_path / "site" / "tasks"
    tasks.mkdir()
    (tasks / "t.yaml").write_text("task: t\ncell: ../cells/evil.yaml\n"
                                  "steps:\n  - go: {group: arm, to: home}\n")
    settings = make_settings(tmp_path / "state", tasks_dir=tasks, cells_dir=cells)
    with TestClient(create_app(settings), headers=AUTH) as client:
        check = client.post("/tasks/check", json={"task": "t"})
        assert "outside the folders this server loads robots from" in check.text, check.text
        for answer in (client.get("/cells/evil"),
                       client.post("/runs", json={"task": "t", "backend": "mock"}),
                       client.post("/plan", json={"cell": "evil", "group": "arm",
                                                  "to": "home"})):
            assert answer.status_code == 422, answer.text
            assert "robots[0].robot" in answer.json()["detail"]
    assert not marker.exists()


def test_robot_folders_are_a_setting_and_the_shipped_robots_load_by_default(tmp_path: Path):
    settings = Settings.from_env({"TASKRUNNER_ROBOTS_DIRS": f"{tmp_path}{os.pathsep}/opt/r"})
    assert settings.robots_dirs == (tmp_path.resolve(), Path("/opt/r"))
    assert Settings().robots_dirs == (resources.robots_dir().resolve(),)
    assert Settings().folder_policy().allows(resources.robots_dir() / "servo_arm",
                                             kind="robot")  # type: ignore[arg-type]


# ---------------------------------------------------------------- inline tasks
def test_inline_tasks_are_never_written_to_disk(client, monkeypatch):
    import taskrunner.tasks.loader as loader

    read: list[Path] = []
    real = loader.load_yaml
    monkeypatch.setattr(loader, "load_yaml", lambda path: read.append(Path(path)) or real(path))
    before = sorted(os.listdir(resources.tasks_dir()))
    yaml = f"task: t\ncell: {CELL}\nsteps:\n  - go: {{group: arm, to: nowhere}}\n"
    report = client.post("/tasks/check", json={"yaml": yaml}).json()
    assert report["problems"][0]["file"].endswith("inline.yaml")
    assert report["problems"][0]["line"] == 4
    assert all(not p.name.startswith(".") for p in read), read  # no temporary file read
    assert sorted(os.listdir(resources.tasks_dir())) == before
    # and no request can include it: inline.yaml exists only for the request sending it
    other = f"task: o\ncell: {CELL}\nsteps:\n  - include: {{file: inline.yaml}}\n"
    [problem] = client.post("/tasks/check", json={"yaml": other}).json()["problems"]
    assert "include cycle" in problem["message"] or "not found" in problem["message"]


# ---------------------------------------------------------------- time and memory
def test_a_check_past_the_time_limit_answers_422_at_the_limit(tmp_path, monkeypatch):
    import taskrunner.api.routers.tasks as tasks_router

    def slow(*args):
        time.sleep(3.0)

    monkeypatch.setattr(tasks_router, "check_request", slow)
    settings = make_settings(tmp_path / "state", check_timeout_s=0.3)
    with TestClient(create_app(settings), headers=AUTH) as client:
        started = time.monotonic()
        answer = client.post("/tasks/check", json={"task": "go_home"})
        assert time.monotonic() - started < 2.0
        assert answer.status_code == 422
        assert "longer than 0.3 s" in answer.json()["detail"]
        assert "check_timeout_s" in answer.json()["detail"]


def test_a_worker_process_past_the_limit_is_killed_and_replaced():
    work = RequestWork("process", timeout_s=60.0, memory_mb=512, workers=1)
    work.start()
    try:
        assert work.call(math.sqrt, 16.0) == 4.0  # the worker is up (imports done)
        work.timeout_s = 1.5
        started = time.monotonic()
        with pytest.raises(WorkLimitError, match="longer than 1.5 s"):
            work.call(time.sleep, 60)
        assert time.monotonic() - started < 4.0
        work.timeout_s = 60.0  # a new worker starts (imports) within this
        with pytest.raises(WorkLimitError, match="more memory"):
            work.call(bytearray, 2 * 1024 ** 3)
        assert work.call(math.sqrt, 9.0) == 3.0  # a new worker answers
    finally:
        work.close()


ALIAS_BOMB = f"""task: bomb
cell: {CELL}
x0: &a0 [lol, lol, lol, lol, lol, lol, lol, lol, lol]
x1: &a1 [*a0, *a0, *a0, *a0, *a0, *a0, *a0, *a0, *a0]
x2: &a2 [*a1, *a1, *a1, *a1, *a1, *a1, *a1, *a1, *a1]
x3: &a3 [*a2, *a2, *a2, *a2, *a2, *a2, *a2, *a2, *a2]
x4: &a4 [*a3, *a3, *a3, *a3, *a3, *a3, *a3, *a3, *a3]
x5: &a5 [*a4, *a4, *a4, *a4, *a4, *a4, *a4, *a4, *a4]
x6: &a6 [*a5, *a5, *a5, *a5, *a5, *a5, *a5, *a5, *a5]
x7: &a7 [*a6, *a6, *a6, *a6, *a6, *a6, *a6, *a6, *a6]
x8: &a8 [*a7, *a7, *a7, *a7, *a7, *a7, *a7, *a7, *a7]
steps: [*a8]
"""


def test_an_alias_bomb_sent_to_check_ends_within_the_limit_and_the_server_answers(tmp_path):
    settings = make_settings(tmp_path / "state", check_isolation="process",
                             check_timeout_s=5.0, check_memory_mb=1024)
    with TestClient(create_app(settings), headers=AUTH) as client:
        started = time.monotonic()
        answer = client.post("/tasks/check", json={"yaml": ALIAS_BOMB})
        elapsed = time.monotonic() - started
        assert elapsed < 10.0
        assert answer.status_code in (200, 422), answer.text
        assert answer.status_code == 422 or answer.json()["ok"] is False
        assert client.get("/health").status_code == 200
        good = client.post("/tasks/check", json={"task": "go_home"})
        assert good.status_code == 200 and good.json()["ok"] is True


def test_a_plan_past_the_time_limit_answers_422(tmp_path):
    settings = make_settings(tmp_path / "state", plan_timeout_s=0.001)
    with TestClient(create_app(settings), headers=AUTH) as client:
        answer = client.post("/plan", json={"cell": "servo_arm_table", "group": "arm",
                                            "to": "Candle", "backend": "mock"})
        assert answer.status_code == 422
        assert "plan_timeout_s" in answer.json()["detail"]


# ---------------------------------------------------------------- slow headers
async def _hello(scope, receive, send):
    assert scope["type"] == "http"
    await send({"type": "http.response.start", "status": 200,
                "headers": [(b"content-length", b"2")]})
    await send({"type": "http.response.body", "body": b"ok"})


def test_a_connection_trickling_its_headers_is_closed_with_408():
    import uvicorn

    from taskrunner.api.serving import header_timeout_protocol

    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = probe.getsockname()[1]
    config = uvicorn.Config(_hello, host="127.0.0.1", port=port, lifespan="off",
                            log_level="error", http=header_timeout_protocol(0.5))
    server = uvicorn.Server(config)
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    try:
        deadline = time.monotonic() + 10
        while not server.started:
            assert time.monotonic() < deadline
            time.sleep(0.02)
        with socket.create_connection(("127.0.0.1", port), timeout=5) as fast:
            fast.sendall(b"GET / HTTP/1.1\r\nHost: x\r\n\r\n")
            assert fast.recv(1024).startswith(b"HTTP/1.1 200")
        with socket.create_connection(("127.0.0.1", port), timeout=5) as slow:
            started = time.monotonic()
            slow.sendall(b"GET / HTTP/1.1\r\n")
            answer = b""
            for i in range(20):  # one header line every 0.2 s: never complete in time
                try:
                    slow.sendall(f"X-Slow-{i}: 1\r\n".encode())
                except OSError:
                    break
                time.sleep(0.2)
                slow.settimeout(0.01)
                try:
                    chunk = slow.recv(1024)
                except TimeoutError:
                    continue
                answer += chunk
                if not chunk or answer:
                    break
            assert answer.startswith(b"HTTP/1.1 408"), answer
            assert time.monotonic() - started < 2.0
    finally:
        server.should_exit = True
        thread.join(10)


# ---------------------------------------------------------------- settings
def test_every_setting_is_settable_from_the_environment(tmp_path: Path):
    env = {"TASKRUNNER_DATA_DIR": str(tmp_path / "data"), "TASKRUNNER_CHECK_TIMEOUT_S": "7",
           "TASKRUNNER_PLAN_TIMEOUT_S": "8", "TASKRUNNER_HEADER_TIMEOUT_S": "3",
           "TASKRUNNER_AUTH": "0", "TASKRUNNER_CHECK_ISOLATION": "inprocess",
           "TASKRUNNER_MOCK_SPEED": "4", "TASKRUNNER_TICK_HZ": "50"}
    settings = Settings.from_env(env)
    assert settings.data_dir == (tmp_path / "data").resolve() == settings.state_dir
    assert (settings.check_timeout_s, settings.plan_timeout_s, settings.header_timeout_s,
            settings.auth, settings.check_isolation, settings.mock_speed, settings.tick_hz) \
        == (7.0, 8.0, 3.0, False, "inprocess", 4.0, 50.0)
    assert settings.db_path == settings.data_dir / "runs.sqlite"
    old = Settings.from_env({"TASKRUNNER_STATE_DIR": str(tmp_path / "old"),
                             "TASKRUNNER_NO_AUTH": "1"})
    assert old.data_dir == (tmp_path / "old").resolve() and old.auth is False
    assert Settings(state_dir=tmp_path).data_dir == tmp_path.resolve()
    with pytest.raises(ValueError, match="'check_isolation' must be one of process, "
                                         "inprocess \\(got 'thread'\\)"):
        Settings.from_env({"TASKRUNNER_CHECK_ISOLATION": "thread"})
    with pytest.raises(ValueError, match="'plan_timeout_s' must be a positive number"):
        Settings(plan_timeout_s=0)
