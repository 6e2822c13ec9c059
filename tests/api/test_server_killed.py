"""A real server killed outright (SIGKILL) mid-run: its next start shows every event a
client had received, over SSE or by polling, and the run as interrupted."""

from __future__ import annotations

import http.client
import json
import os
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

from apitest import TOKEN
from test_server import REPO_ROOT, free_port, request

LOOP = textwrap.dedent("""\
    task: loop
    cell: ../robots/cells/servo_arm_table.yaml
    steps:
      - repeat:
          times: 200
          do:
            - go: {group: arm, to: Candle}
            - go: {group: arm, to: home}
    """)


def start_server(data_dir: Path, port: int) -> subprocess.Popen[str]:
    env = {**os.environ, "PYTHONPATH": str(REPO_ROOT), "TASKRUNNER_SIM_SPEED": "5"}
    env.pop("TASKRUNNER_NO_AUTH", None)
    server = subprocess.Popen(
        [sys.executable, "-m", "taskrunner.cli", "serve", "--host", "127.0.0.1", "--port",
         str(port), "--token", TOKEN, "--state-dir", str(data_dir), "--planner", "inprocess",
         "--log-level", "warning"],
        cwd=REPO_ROOT, env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    deadline = time.monotonic() + 30
    while True:
        try:
            if request(port, "GET", "/health", timeout=1.0)[0] == 200:
                return server
        except OSError:
            pass
        assert server.poll() is None, server.stdout.read() if server.stdout else ""
        assert time.monotonic() < deadline, "the server did not answer within 30 s"
        time.sleep(0.1)


def receive_events(port: int, run_id: str, count: int) -> list[dict]:
    """The run's SSE events, at least ``count`` and to a ``planned`` one (mid-step: the
    step's events are not all in yet), the stream left open."""
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
    conn.request("GET", f"/runs/{run_id}/events",
                 headers={"Accept": "text/event-stream", "Authorization": f"Bearer {TOKEN}"})
    answer = conn.getresponse()
    assert answer.status == 200
    events: list[dict] = []
    while len(events) < count or events[-1]["kind"] != "planned":
        line = answer.fp.readline().decode()
        assert line, "the stream ended early"
        if line.startswith("data: "):
            events.append(json.loads(line[6:]))
    return events


def test_a_killed_server_keeps_every_event_a_client_had_received(tmp_path: Path):
    port = free_port()
    server = start_server(tmp_path, port)
    try:
        status, accepted = request(port, "POST", "/runs", {"yaml": LOOP, "backend": "sim"})
        assert status == 202, accepted
        run_id = accepted["run_id"]
        streamed = receive_events(port, run_id, 25)
        status, polled = request(port, "GET", f"/runs/{run_id}")
        assert status == 200 and polled["status"] == "running"
        server.send_signal(signal.SIGKILL)
        server.wait(30)
    finally:
        if server.poll() is None:
            server.kill()
            server.wait(30)
    received = {e["seq"]: e for e in [*streamed, *polled["events"]]}
    assert len(received) >= 25 and polled["events"][-1]["seq"] >= streamed[-1]["seq"]
    again = start_server(tmp_path, port)
    try:
        status, run = request(port, "GET", f"/runs/{run_id}?limit=10000")
        assert status == 200, run
    finally:
        again.terminate()
        again.wait(30)
    assert run["status"] == "interrupted" and "server stopped" in run["error"]
    kept = {e["seq"]: e for e in run["events"]}
    assert [seq for seq in received if seq not in kept] == []
    for seq, event in received.items():
        assert kept[seq] == event  # the same event, field for field
    assert sorted(kept) == list(range(1, len(kept) + 1))  # no gap
