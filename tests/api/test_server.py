"""A real server: ``run-task serve`` on a loopback port, pick_place followed over SSE."""

from __future__ import annotations

import http.client
import json
import os
import socket
import sqlite3
import subprocess
import sys
import time
from pathlib import Path

from apitest import TOKEN

REPO_ROOT = Path(__file__).resolve().parents[2]


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def request(port: int, method: str, url: str, body: dict | None = None,
            timeout: float = 90.0) -> tuple[int, dict]:
    # Generous: on a busy machine the server's first check (a worker process starting,
    # importing the planner) can take tens of seconds; the test is of answers, not speed.
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
    try:
        headers = {"Authorization": f"Bearer {TOKEN}", "Content-Type": "application/json"}
        conn.request(method, url, body=json.dumps(body) if body is not None else None,
                     headers=headers)
        answer = conn.getresponse()
        return answer.status, json.loads(answer.read() or b"null")
    finally:
        conn.close()


def follow_events(port: int, run_id: str, timeout: float) -> list[dict]:
    """Read the run's SSE stream to its end (``timeout`` s per read at most)."""
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
    events: list[dict] = []
    try:
        conn.request("GET", f"/runs/{run_id}/events",
                     headers={"Accept": "text/event-stream", "Authorization": f"Bearer {TOKEN}"})
        answer = conn.getresponse()
        assert answer.status == 200
        assert answer.getheader("content-type").startswith("text/event-stream")
        for raw in answer:
            line = raw.decode().rstrip("\n")
            if line.startswith("data: "):
                events.append(json.loads(line[6:]))
    finally:
        conn.close()
    return events


def test_a_real_server_runs_pick_place_and_streams_it_to_the_end(tmp_path: Path):
    port = free_port()
    env = {**os.environ, "PYTHONPATH": str(REPO_ROOT), "TASKRUNNER_SIM_SPEED": "200"}
    env.pop("TASKRUNNER_NO_AUTH", None)
    server = subprocess.Popen(
        [sys.executable, "-m", "taskrunner.cli", "serve", "--host", "127.0.0.1", "--port",
         str(port), "--token", TOKEN, "--state-dir", str(tmp_path), "--log-level", "warning"],
        cwd=REPO_ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        deadline = time.monotonic() + 30
        while True:
            try:
                status, body = request(port, "GET", "/health", timeout=1.0)
                if status == 200:
                    break
            except OSError:
                pass
            assert server.poll() is None, server.stdout.read() if server.stdout else ""
            assert time.monotonic() < deadline, "the server did not answer within 30 s"
            time.sleep(0.1)
        status, accepted = request(port, "POST", "/runs", {"task": "pick_place",
                                                            "backend": "sim"})
        assert status == 202, accepted
        run_id = accepted["run_id"]
        events = follow_events(port, run_id, timeout=60.0)
        assert [e["seq"] for e in events] == list(range(1, len(events) + 1))
        assert events[0]["kind"] == "run_started"
        assert events[-1]["kind"] == "run_finished" and events[-1]["status"] == "succeeded"
        status, run = request(port, "GET", f"/runs/{run_id}")
        assert status == 200 and run["status"] == "succeeded"
        assert [e["seq"] for e in run["events"]] == [e["seq"] for e in events]
    finally:
        server.terminate()
        output, _ = server.communicate(timeout=90)
    assert f"\nexport TASKRUNNER_TOKEN={TOKEN}\n" in output
    assert "made for this session" not in output
    with sqlite3.connect(tmp_path / "runs.sqlite") as db:
        stored = json.loads(db.execute("SELECT record FROM runs WHERE run_id = ?",
                                       (run_id,)).fetchone()[0])
        rows = db.execute("SELECT count(*) FROM events WHERE run_id = ?", (run_id,)).fetchone()
    assert stored["status"] == "succeeded" and stored["exit_code"] == 0
    assert rows[0] == len(events)  # an event a row (the record's row has none)


def test_serve_makes_and_prints_a_token_when_none_is_configured(tmp_path, monkeypatch, capsys):
    import uvicorn

    from taskrunner.cli import main

    served = []
    monkeypatch.setattr(uvicorn, "run", lambda app, **kw: served.append((app, kw)))
    monkeypatch.delenv("TASKRUNNER_TOKEN", raising=False)
    monkeypatch.delenv("TASKRUNNER_NO_AUTH", raising=False)
    assert main(["serve", "--port", "8123", "--state-dir", str(tmp_path)]) == 0
    out = capsys.readouterr().out
    [(app, options)] = served
    assert options["host"] == "127.0.0.1" and options["port"] == 8123
    assert "token (made for this session; set TASKRUNNER_TOKEN to fix it)" in out
    # a line to paste into a shell, so that the README's curl lines work as written
    assert f"\nexport TASKRUNNER_TOKEN={app.state.token}\n" in out
    assert options["http"].__name__ == "HeaderTimeoutProtocol"
    assert main(["serve", "--no-auth", "--state-dir", str(tmp_path)]) == 0
    assert served[1][0].state.token is None and "OPEN: no token needed" in capsys.readouterr().out
    assert main(["serve", "--token", "short", "--state-dir", str(tmp_path)]) == 2
