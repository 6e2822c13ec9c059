"""A cancel gets through whatever else clients ask, and heavy work is bounded (admission)."""

from __future__ import annotations

import asyncio
import http.client
import json
import threading
import time
from pathlib import Path
from typing import Any

import pytest
from apitest import AUTH, make_settings, served
from test_runs import GO_CANDLE

from taskrunner.api import create_app
from taskrunner.api.admission import Admission, ServerBusyError


# ----------------------------------------------------------------- Admission alone
def test_admission_runs_capacity_at_once_queues_the_next_and_refuses_beyond():
    async def scenario() -> tuple[list[str], int, int]:
        admission = Admission("plans", capacity=2, queue=1, wait_s=5.0, setting="max_planners")
        release = asyncio.Event()
        log: list[str] = []

        async def work(name: str) -> None:
            try:
                async with admission.slot():
                    log.append(f"start {name}")
                    await release.wait()
            except ServerBusyError as exc:
                log.append(f"busy {name}: {exc.retry_after_s:g}")

        tasks = [asyncio.create_task(work(n)) for n in "abcd"]
        await asyncio.sleep(0.05)
        running, waiting = admission.running, admission.waiting
        release.set()
        await asyncio.gather(*tasks)
        return log, running, waiting

    log, running, waiting = asyncio.run(scenario())
    assert (running, waiting) == (2, 1)
    assert log[:3] == ["start a", "start b", "busy d: 5"]
    assert log[3] == "start c"  # the queued one ran once a turn was free


def test_admission_refuses_a_request_that_waited_past_its_limit_and_frees_turns_on_errors():
    async def scenario() -> tuple[str, int]:
        admission = Admission("checks", capacity=1, queue=4, wait_s=0.1, setting="check_workers")
        hold = asyncio.Event()

        async def holder() -> None:
            async with admission.slot():
                await hold.wait()
                raise RuntimeError("the work failed")

        first = asyncio.create_task(holder())
        await asyncio.sleep(0.01)
        with pytest.raises(ServerBusyError) as waited:
            async with admission.slot():
                pass
        hold.set()
        with pytest.raises(RuntimeError):
            await first
        async with admission.slot():  # the failed work gave its turn back
            pass
        return str(waited.value), admission.running

    message, running = asyncio.run(scenario())
    assert "waited 0.1 s" in message and "'check_workers'" in message
    assert running == 0


@pytest.mark.parametrize("kwargs", [{"capacity": 0, "queue": 1, "wait_s": 1.0},
                                    {"capacity": 1, "queue": -1, "wait_s": 1.0},
                                    {"capacity": 1, "queue": 1, "wait_s": float("nan")}])
def test_admission_refuses_nonsense_limits(kwargs: dict[str, Any]):
    with pytest.raises(ValueError):
        Admission("x", setting="s", **kwargs)


# ----------------------------------------------------------------- a real server
SLOW_S = 4.0  # how long each flooding request's work takes


class SlowWork:
    """Stands in for the server's request work: every call holds its thread ``SLOW_S``
    (as a slow load, check or preview does), then fails as work past its limit does."""

    def __init__(self) -> None:
        self.calls = 0
        self._lock = threading.Lock()

    def call(self, function: Any, *args: Any) -> Any:
        with self._lock:
            self.calls += 1
        time.sleep(SLOW_S)
        from taskrunner.api.requestwork import WorkLimitError

        raise WorkLimitError("slow on purpose")

    def close(self) -> None:
        pass


def _request(port: int, method: str, path: str, body: Any = None,
             timeout: float = 60.0) -> tuple[int, dict[str, str], Any, float]:
    start = time.monotonic()
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
    try:
        conn.request(method, path, body=None if body is None else json.dumps(body),
                     headers={**AUTH, "Content-Type": "application/json"})
        answer = conn.getresponse()
        data = answer.read()
        return (answer.status, dict(answer.getheaders()),
                json.loads(data) if data else None, time.monotonic() - start)
    finally:
        conn.close()


def test_a_cancel_gets_through_a_burst_of_slow_requests_and_stops_the_motion(tmp_path: Path):
    """60 slow requests (more than the framework's 40 shared threads) made a cancel wait
    for them and answer "already ended": now the cancel is answered while they are held,
    the run ends cancelled mid-motion, and what the server cannot take is refused 503."""
    settings = make_settings(tmp_path / "state", sim_speed=0.5, work_queue=8,
                             check_workers=2)
    app = create_app(settings)
    with served(app) as port:
        status, _, started, _ = _request(port, "POST", "/runs",
                                         {"yaml": GO_CANDLE, "backend": "sim",
                                          "check": False})
        assert status == 202, started
        run_id = started["run_id"]
        deadline = time.monotonic() + 30
        while True:  # moving: its first motion planned and sent
            _, _, run, _ = _request(port, "GET", f"/runs/{run_id}")
            if any(e["kind"] == "planned" for e in run["events"]):
                break
            assert time.monotonic() < deadline, run
            time.sleep(0.05)
        app.state.work = SlowWork()  # from now on (the lifespan's own is closed with it)

        flood: list[tuple[int, dict[str, str], Any, float]] = []
        paths = ["/tasks/check", "/viewer/tasks/tree", "/runs"]

        def slow_client(k: int) -> None:
            body = {"task": "pick_place", "backend": "mock"} if k % 3 == 2 \
                else {"task": "pick_place"}
            flood.append(_request(port, "POST", paths[k % 3], body))

        clients = [threading.Thread(target=slow_client, args=(k,)) for k in range(60)]
        for client in clients:
            client.start()
        time.sleep(0.5)  # the burst has arrived and holds what it can
        reference_start = time.monotonic()
        status, _, cancelled, cancel_s = _request(port, "POST", f"/runs/{run_id}/cancel")
        _, _, state, state_s = _request(port, "GET", f"/runs/{run_id}")
        assert time.monotonic() - reference_start < SLOW_S, "answered only after the burst"
        for client in clients:
            client.join(60)
        final = state
        deadline = time.monotonic() + 20
        while final["status"] == "running" and time.monotonic() < deadline:
            time.sleep(0.05)
            _, _, final, _ = _request(port, "GET", f"/runs/{run_id}")

    assert status == 202, cancelled
    # Answered while the burst's work was still held (each holds SLOW_S): the old server
    # answered after it, with 409 "already ended".
    assert cancel_s < SLOW_S / 2 and state_s < SLOW_S / 2, (cancel_s, state_s)
    assert final["status"] == "cancelled" and final["exit_code"] == 130
    codes = sorted(code for code, *_ in flood)
    busy = [(headers, body) for code, headers, body, _ in flood if code == 503]
    # check_workers (2) at once and work_queue (8) waiting: the rest refused at once.
    assert len(busy) == 60 - 10, codes
    assert all(int(headers["retry-after"]) >= 1 and "busy" in body["detail"]
               for headers, body in busy)
    assert app.state.work.calls <= 10, app.state.work.calls


# ----------------------------------------------------------------- the control port
def test_the_control_port_serves_cancel_and_run_state_only(tmp_path: Path):
    from taskrunner.api.serving import ControlOnly

    settings = make_settings(tmp_path / "state", sim_speed=0.5)
    app = create_app(settings)
    with served(app) as port, served(ControlOnly(app), lifespan="off") as control:
        status, _, started, _ = _request(port, "POST", "/runs",
                                         {"yaml": GO_CANDLE, "backend": "sim",
                                          "check": False})
        run_id = started["run_id"]
        assert _request(control, "GET", "/health")[0] == 200
        refused = _request(control, "GET", "/cells")
        assert refused[0] == 404 and "main port" in refused[2]["detail"]
        assert _request(control, "POST", "/runs", {"task": "pick_place"})[0] == 404
        conn = http.client.HTTPConnection("127.0.0.1", control, timeout=10)
        conn.request("POST", f"/runs/{run_id}/cancel")  # no token: the app's rule holds
        assert conn.getresponse().status == 401
        conn.close()
        status, _, cancelled, _ = _request(control, "POST", f"/runs/{run_id}/cancel")
        assert status == 202, cancelled
        deadline = time.monotonic() + 20
        while (state := _request(control, "GET", f"/runs/{run_id}")[2])["status"] == "running":
            assert time.monotonic() < deadline
            time.sleep(0.05)
        assert state["status"] == "cancelled"
        assert _request(control, "POST", f"/runs/{run_id}/cancel")[0] == 409
        assert _request(control, "GET", "/runs/no-such-run")[0] == 404


def test_run_task_serve_opens_the_control_port_beside_the_main_one(tmp_path: Path):
    import os
    import subprocess
    import sys

    from test_server import REPO_ROOT, free_port

    port, control = free_port(), free_port()
    env = {**os.environ, "PYTHONPATH": str(REPO_ROOT), "TASKRUNNER_TOKEN": AUTH[
        "Authorization"].split()[1]}
    server = subprocess.Popen(
        [sys.executable, "-m", "taskrunner.cli", "serve", "--port", str(port),
         "--control-port", str(control), "--planner", "inprocess", "--data-dir",
         str(tmp_path), "--log-level", "warning"],
        env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    try:
        deadline = time.monotonic() + 60
        while True:  # both listening (the control port may answer first)
            try:
                if _request(control, "GET", "/health", timeout=1)[0] == 200 \
                        and _request(port, "GET", "/health", timeout=1)[0] == 200:
                    break
            except OSError:
                pass
            assert server.poll() is None and time.monotonic() < deadline, "no control port"
            time.sleep(0.1)
        assert _request(port, "GET", "/cells")[0] == 200
        assert _request(control, "GET", "/cells")[0] == 404
        assert _request(control, "GET", "/runs/nope")[0] == 404
    finally:
        server.terminate()
        out, _ = server.communicate(timeout=30)
    assert f"control port: http://127.0.0.1:{control}" in out
