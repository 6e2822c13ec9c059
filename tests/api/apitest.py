"""Helpers of the API tests (imported by the tests and by conftest.py)."""

from __future__ import annotations

import socket
import threading
import time
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from fastapi.testclient import TestClient

from taskrunner.api import Settings

TOKEN = "test-token-0123456789"
AUTH = {"Authorization": f"Bearer {TOKEN}"}
NO_TOKEN = {"Authorization": ""}  # overrides a client's default token


def make_settings(state_dir: Path, **overrides: Any) -> Settings:
    values: dict[str, Any] = {"token": TOKEN, "data_dir": state_dir, "planner": "inprocess",
                              "shutdown_timeout_s": 10.0,
                              "check_isolation": "inprocess"}
    values.update(overrides)
    return Settings(**values)




def wait_until_done(client: TestClient, run_id: str, timeout: float = 20.0) -> dict[str, Any]:
    """Poll GET /runs/{id} until the run has ended (at most ``timeout`` s)."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        body = client.get(f"/runs/{run_id}", headers=AUTH).json()
        if body["status"] != "running":
            return body
        time.sleep(0.02)
    raise AssertionError(f"run {run_id} still running after {timeout} s")


def wait_for_event(client: TestClient, run_id: str, kind: str,
                   timeout: float = 20.0) -> dict[str, Any]:
    """Poll until the run has an event of ``kind``; returns the run."""
    deadline = time.monotonic() + timeout
    while time.monotonic() < deadline:
        body = client.get(f"/runs/{run_id}", headers=AUTH).json()
        if any(e["kind"] == kind for e in body["events"]):
            return body
        time.sleep(0.01)
    raise AssertionError(f"run {run_id}: no {kind!r} event after {timeout} s")


def parse_sse(text: str) -> list[dict[str, str]]:
    """The events of an SSE body: each as its fields (id, event, data)."""
    out = []
    for block in text.strip().split("\n\n"):
        fields: dict[str, str] = {}
        for line in block.splitlines():
            if line.startswith(":"):
                continue
            key, _, value = line.partition(": ")
            fields[key] = value
        if fields:
            out.append(fields)
    return out


@contextmanager
def served(app: Any, **config: Any) -> Iterator[int]:
    """``app`` served by a real uvicorn on a free loopback port (in a thread), for tests
    of what only a real socket shows; yields the port, stops the server after."""
    import uvicorn

    with socket.socket() as probe:
        probe.bind(("127.0.0.1", 0))
        port = int(probe.getsockname()[1])
    server = uvicorn.Server(uvicorn.Config(app, host="127.0.0.1", port=port,
                                           log_level="error", **config))
    thread = threading.Thread(target=server.run, daemon=True)
    thread.start()
    try:
        deadline = time.monotonic() + 20
        while not server.started:
            assert thread.is_alive() and time.monotonic() < deadline, "server did not start"
            time.sleep(0.02)
        yield port
    finally:
        server.should_exit = True
        thread.join(10)
