"""GET /runs/{id} latency with 50 concurrent clients on loopback while runs plan.

    python benchmarks/api_latency.py [--clients 50] [--seconds 10] [--repeats 3]
                                     [--client python|wrk] [--planners 2] [--rate HZ]
                                     [--streams N] [--json]

Starts ``run-task serve`` (planning in worker processes) on a free loopback port and puts
it under the load the target names:

* a sim run of pick_place (at real speed: it plans and moves for the whole measurement);
* ``--planners`` clients that keep planning workers busy with POST /plan, back to back:
  two real motions of the pair cell's left arm and a pose out of its reach, in turn (the
  ``plans`` column counts the answers in a window, ``planners`` the CPU the workers used);
* ``--streams`` clients following the run's events (Server-Sent Events), if asked;
* ``--clients`` keep-alive connections, each sending GET /runs/{id} as soon as its last
  answer came (closed loop: the heaviest load that many clients can make), or, with
  ``--rate``, that many times a second each (a dashboard or PLC polling).

Before measuring, it waits until every planner client has had an answer (worker
processes spawned, cells loaded) and polls for a second unrecorded. Each of
``--repeats`` windows is measured separately; the summary is the median window and the
worst. Target (issue 5): p99 <= 20 ms.

``--client python`` (default) polls from one asyncio event loop in this process
(uvloop), measuring each request from write to the last byte of the answer.
``--client wrk`` uses Debian's ``wrk`` (C, 2 threads; ``apt-get install wrk``).
Prints a table and, with ``--json``, one JSON line at the end.
"""

from __future__ import annotations

import argparse
import asyncio
import http.client
import json
import os
import shutil
import socket
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import numpy as np

REPO_ROOT = Path(__file__).resolve().parent.parent
TOKEN = "bench-token-0123456789"
HEADERS = {"Authorization": f"Bearer {TOKEN}", "Content-Type": "application/json"}
TARGET_P99_MS = 20.0
# What the planner clients ask for, in turn: two real motions (IK-free joint goals: OMPL,
# shortcutting, toppra, the trajectory back as JSON) and a pose out of reach (the IK
# tries all its restarts before the 422).
PLAN_REQUESTS = [{"cell": "servo_arm_pair", "group": "left_arm", "planning_time": 1.0, **goal}
                 for goal in ({"to": "HandOff"}, {"to": "PickUp"},
                              {"pose": {"xyz": [0.0, 0.6, 0.8]}})]


def _port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def _call(conn: http.client.HTTPConnection, method: str, url: str,
          body: dict | None = None) -> tuple[int, bytes]:
    conn.request(method, url, body=json.dumps(body) if body is not None else None,
                 headers=HEADERS)
    answer = conn.getresponse()
    return answer.status, answer.read()


class Streams:
    """Client threads following a run's events (GET /runs/{id}/events, SSE)."""

    def __init__(self, port: int, run_id: str, count: int) -> None:
        self.events = [0] * count
        self.threads = [threading.Thread(target=self._follow, args=(port, run_id, k),
                                         daemon=True) for k in range(count)]
        for t in self.threads:
            t.start()

    def _follow(self, port: int, run_id: str, k: int) -> None:
        conn = http.client.HTTPConnection("127.0.0.1", port, timeout=600)
        conn.request("GET", f"/runs/{run_id}/events", headers=HEADERS)
        answer = conn.getresponse()
        try:
            for line in answer:
                if line.startswith(b"event:"):
                    self.events[k] += 1
        except OSError:  # the server went away at the end
            pass


class Planners:
    """Client threads keeping the server's planners busy with POST /plan."""

    def __init__(self, port: int, count: int) -> None:
        self.port = port
        self.answered = [0] * count
        self.codes: dict[int, int] = {}
        self.stop = threading.Event()
        self.threads = [threading.Thread(target=self._loop, args=(k,), daemon=True)
                        for k in range(count)]
        for t in self.threads:
            t.start()

    def _loop(self, k: int) -> None:
        conn = http.client.HTTPConnection("127.0.0.1", self.port, timeout=120)
        turn = k
        while not self.stop.is_set():
            code, _ = _call(conn, "POST", "/plan", PLAN_REQUESTS[turn % len(PLAN_REQUESTS)])
            self.codes[code] = self.codes.get(code, 0) + 1
            self.answered[k] += 1
            turn += 1

    def wait_warm(self, timeout: float = 120.0) -> None:
        deadline = time.monotonic() + timeout
        while min(self.answered, default=1) == 0:
            if time.monotonic() > deadline:
                raise SystemExit("the planner clients had no answer in time")
            time.sleep(0.1)


async def _poll_async(port: int, path: str, clients: int, seconds: float,
                      record: bool, rate_hz: float = 0.0) -> np.ndarray:
    """``clients`` connections polling ``path`` for ``seconds``; latencies in ms.

    ``rate_hz`` 0: each client asks again as soon as it has its answer (closed loop).
    Otherwise each asks ``rate_hz`` times a second on a fixed schedule (seeded phases),
    and a latency runs from when the request was due, not when it could be sent: a
    stalled server is charged for the requests it kept waiting.
    """
    request = (f"GET {path} HTTP/1.1\r\nHost: 127.0.0.1:{port}\r\n"
               f"Authorization: Bearer {TOKEN}\r\n\r\n").encode()
    samples: list[float] = []
    end = time.monotonic() + seconds

    phases = np.random.default_rng(0).random(clients)

    async def one(k: int) -> None:
        reader, writer = await asyncio.open_connection("127.0.0.1", port)
        due = time.perf_counter() + (phases[k] / rate_hz if rate_hz else 0.0)
        try:
            while time.monotonic() < end:
                if rate_hz:
                    await asyncio.sleep(max(0.0, due - time.perf_counter()))
                    t0, due = due, due + 1.0 / rate_hz
                else:
                    t0 = time.perf_counter()
                writer.write(request)
                head = await reader.readuntil(b"\r\n\r\n")
                status = head[9:12]
                length = next(int(line.split(b":", 1)[1]) for line in head.split(b"\r\n")
                              if line.lower().startswith(b"content-length:"))
                await reader.readexactly(length)
                if record:
                    samples.append(time.perf_counter() - t0)
                if status != b"200":
                    raise RuntimeError(f"GET {path} answered {status.decode()}")
        finally:
            writer.close()

    await asyncio.gather(*(one(k) for k in range(clients)))
    return 1e3 * np.array(samples)


def _run_python(port: int, path: str, clients: int, seconds: float,
                rate_hz: float = 0.0) -> dict:
    try:
        import uvloop
        runner = uvloop.run
    except ImportError:  # pragma: no cover - uvloop is a dependency of the API
        runner = asyncio.run
    runner(_poll_async(port, path, clients, 1.0, False, rate_hz))  # warm-up
    ms = runner(_poll_async(port, path, clients, seconds, True, rate_hz))
    p50, p90, p99 = np.percentile(ms, [50, 90, 99])
    return {"requests": int(ms.size), "req_per_s": ms.size / seconds, "p50_ms": p50,
            "p90_ms": p90, "p99_ms": p99, "max_ms": float(ms.max())}


def _run_wrk(port: int, path: str, clients: int, seconds: float,
             rate_hz: float = 0.0) -> dict:
    url = f"http://127.0.0.1:{port}{path}"

    def wrk(duration: float) -> str:
        done = subprocess.run(
            ["wrk", "-t2", f"-c{clients}", f"-d{max(1, round(duration))}s", "--latency",
             "-H", f"Authorization: Bearer {TOKEN}", url],
            capture_output=True, text=True, timeout=duration + 60, check=True)
        return done.stdout

    wrk(1.0)  # warm-up
    text = wrk(seconds)
    result: dict = {}
    for line in text.splitlines():
        parts = line.split()
        if len(parts) == 2 and parts[0] in ("50%", "90%", "99%"):
            result[f"p{parts[0][:-1]}_ms"] = _ms(parts[1])
        elif line.startswith("Requests/sec:"):
            result["req_per_s"] = float(parts[1])
        elif line.strip().startswith("Latency") and len(parts) >= 4:
            result["max_ms"] = _ms(parts[3])
        elif "requests in" in line:
            result["requests"] = int(parts[0])
        elif "Non-2xx" in line or "Socket errors" in line:
            raise RuntimeError(f"wrk: {line.strip()}")
    return result


def _ms(value: str) -> float:
    """wrk's '1.23ms' / '456.00us' / '1.02s' as milliseconds."""
    for unit, scale in (("us", 1e-3), ("ms", 1.0), ("s", 1e3)):
        if value.endswith(unit):
            return float(value[: -len(unit)]) * scale
    return float(value)


def _cpu_seconds(pid: int) -> tuple[float, float]:
    """CPU time (user + system, s) of process ``pid`` and of its children (the planning
    workers), from /proc; (nan, nan) where /proc is not there."""
    tick = os.sysconf("SC_CLK_TCK")

    def own(p: int) -> float:
        fields = Path(f"/proc/{p}/stat").read_text().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / tick

    try:
        children = [int(c) for t in Path(f"/proc/{pid}/task").iterdir()
                    for c in (t / "children").read_text().split()]
        return own(pid), sum(own(c) for c in children)
    except OSError:
        return float("nan"), float("nan")


def _start_server(port: int, state: str) -> subprocess.Popen:
    env = {**os.environ, "PYTHONPATH": str(REPO_ROOT), "TASKRUNNER_SIM_SPEED": "1"}
    server = subprocess.Popen(
        [sys.executable, "-m", "taskrunner.cli", "serve", "--port", str(port), "--token",
         TOKEN, "--data-dir", state, "--log-level", "warning"],
        cwd=REPO_ROOT, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 60
    while True:
        try:
            if _call(http.client.HTTPConnection("127.0.0.1", port, timeout=1), "GET",
                     "/health")[0] == 200:
                return server
        except OSError:
            time.sleep(0.1)
        if time.monotonic() > deadline or server.poll() is not None:
            server.kill()
            raise SystemExit("the server did not start")


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--clients", type=int, default=50)
    parser.add_argument("--seconds", type=float, default=10.0, help="per window (10)")
    parser.add_argument("--repeats", type=int, default=3, help="measured windows (3)")
    parser.add_argument("--client", choices=("python", "wrk"), default="python")
    parser.add_argument("--planners", type=int, default=2,
                        help="clients keeping planners busy with POST /plan (2; 0: none)")
    parser.add_argument("--streams", type=int, default=0,
                        help="clients following the run's events (SSE) meanwhile (0)")
    parser.add_argument("--rate", type=float, default=0.0,
                        help="python client: polls per second per client on a fixed "
                             "schedule (0, default: closed loop, as fast as answered)")
    parser.add_argument("--json", action="store_true", help="end with one JSON line")
    args = parser.parse_args()
    if args.rate < 0 or (args.rate and args.client == "wrk"):
        raise SystemExit("--rate must be >= 0, and only with --client python")
    if args.client == "wrk" and shutil.which("wrk") is None:
        raise SystemExit("--client wrk needs wrk on PATH (apt-get install wrk)")
    port = _port()
    state = tempfile.mkdtemp(prefix="api-bench-")
    server = _start_server(port, state)
    planners = None
    try:
        def control(method: str, url: str, body: dict | None = None) -> tuple[int, bytes]:
            # a connection per call: an idle keep-alive one is closed by the server
            return _call(http.client.HTTPConnection("127.0.0.1", port, timeout=60), method,
                         url, body)

        windows = []
        for _ in range(args.repeats):
            # A fresh run per window, so each one plans and moves (pick_place at real
            # speed lasts longer than a window).
            status, body = control("POST", "/runs",
                                 {"task": "pick_place", "backend": "sim"})
            assert status == 202, body
            run_id = json.loads(body)["run_id"]
            if planners is None:
                planners = Planners(port, args.planners)
                planners.wait_warm()
            streams = Streams(port, run_id, args.streams)
            planned, codes = sum(planners.answered), dict(planners.codes)
            measure = _run_wrk if args.client == "wrk" else _run_python
            cpu0, t0 = _cpu_seconds(server.pid), time.monotonic()
            window = measure(port, f"/runs/{run_id}", args.clients, args.seconds, args.rate)
            cpu1, elapsed = _cpu_seconds(server.pid), time.monotonic() - t0
            _, body = control("GET", f"/runs/{run_id}")
            run = json.loads(body)
            window.update(run_status=run["status"], run_events=len(run["events"]),
                          plans_answered=sum(planners.answered) - planned,
                          plan_codes={str(c): n - codes.get(c, 0)
                                      for c, n in sorted(planners.codes.items())},
                          server_cpu=(cpu1[0] - cpu0[0]) / elapsed,
                          planners_cpu=(cpu1[1] - cpu0[1]) / elapsed,
                          streamed_events=sum(streams.events))
            windows.append(window)
            if run["status"] == "running":
                control("POST", f"/runs/{run_id}/cancel")
                while json.loads(control("GET", f"/runs/{run_id}")[1])["status"] \
                        == "running":
                    time.sleep(0.05)
    finally:
        if planners is not None:
            planners.stop.set()
        server.terminate()
        server.wait(30)
        shutil.rmtree(state, ignore_errors=True)
    _report(args, windows)
    return 0


def _report(args: argparse.Namespace, windows: list[dict]) -> None:
    pace = f"{args.rate:g} Hz each" if args.rate else "closed loop"
    print(f"GET /runs/{{id}}: {args.clients} {args.client} clients ({pace}), "
          f"{args.seconds:.0f} s windows, {args.planners} POST /plan client(s) planning, "
          f"{args.streams} event stream(s), "
          "a sim run of pick_place planning and moving")
    print(f"{'window':>6} {'req/s':>8} {'p50 ms':>7} {'p90 ms':>7} {'p99 ms':>7} "
          f"{'max ms':>7} {'plans':>6} {'CPU server':>10} {'planners':>8} "
          f"{'run (at the end)':>22}")
    for k, w in enumerate(windows, 1):
        run = f"{w['run_status']}, {w['run_events']} events"
        print(f"{k:>6} {w['req_per_s']:>8.0f} {w['p50_ms']:>7.1f} {w['p90_ms']:>7.1f} "
              f"{w['p99_ms']:>7.1f} {w.get('max_ms', float('nan')):>7.1f} "
              f"{w['plans_answered']:>6} {w['server_cpu']:>10.2f} {w['planners_cpu']:>8.2f} "
              f"{run:>22}")
    p99s = sorted(w["p99_ms"] for w in windows)
    median, worst = p99s[len(p99s) // 2], p99s[-1]
    verdict = "met" if median <= TARGET_P99_MS else "missed"
    print(f"target p99 <= {TARGET_P99_MS:.0f} ms: {verdict} (median window {median:.1f} ms, "
          f"worst {worst:.1f} ms)")
    if args.json:
        print(json.dumps({"clients": args.clients, "client": args.client, "rate_hz": args.rate,
                          "streams": args.streams,
                          "planners": args.planners, "seconds": args.seconds,
                          "windows": [{k: (round(v, 3) if isinstance(v, float) else v)
                                       for k, v in w.items()} for w in windows],
                          "p99_ms_median": round(median, 3), "p99_ms_worst": round(worst, 3),
                          "target_p99_ms": TARGET_P99_MS, "met": verdict == "met"}))


if __name__ == "__main__":
    sys.exit(main())
