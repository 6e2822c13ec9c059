"""GET /runs/{id} latency with 50 concurrent clients on loopback while runs plan.

Starts ``run-task serve`` (planning in worker processes) on a free loopback port, starts
a long sim run of pick_place, keeps a planner busy with POST /plan requests, and has 50
client threads (one keep-alive connection each) poll GET /runs/{id} for ``--seconds``.
Prints p50 / p95 / p99 / max in ms. Target (issue 5): p99 <= 20 ms.

    python benchmarks/api_latency.py [--clients 50] [--seconds 10] [--client python|wrk]

``--client python`` (default) polls from 50 Python threads: their own GIL time is part of
what they measure. ``--client wrk`` uses Debian's ``wrk`` load generator (C, 2 threads,
50 connections), which measures the server alone (``apt-get install wrk``).
"""

from __future__ import annotations

import argparse
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


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--clients", type=int, default=50)
    parser.add_argument("--seconds", type=float, default=10.0)
    parser.add_argument("--client", choices=("python", "wrk"), default="python")
    parser.add_argument("--planners", type=int, default=2,
                        help="client threads keeping the planner busy with POST /plan "
                             "(0: measure without that load)")
    args = parser.parse_args()
    port = _port()
    state = tempfile.mkdtemp(prefix="api-bench-")
    env = {**os.environ, "PYTHONPATH": str(REPO_ROOT), "TASKRUNNER_SIM_SPEED": "1"}
    server = subprocess.Popen(
        [sys.executable, "-m", "taskrunner.cli", "serve", "--port", str(port), "--token",
         TOKEN, "--state-dir", state, "--log-level", "warning"],
        cwd=REPO_ROOT, env=env, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 60
        while True:
            try:
                if _call(http.client.HTTPConnection("127.0.0.1", port, timeout=1), "GET",
                         "/health")[0] == 200:
                    break
            except OSError:
                time.sleep(0.1)
            if time.monotonic() > deadline:
                raise SystemExit("server did not start")
        control = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
        status, body = _call(control, "POST", "/runs", {"task": "pick_place", "backend": "sim"})
        assert status == 202, body
        run_id = json.loads(body)["run_id"]
        stop = threading.Event()

        def keep_planning() -> None:
            conn = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
            while not stop.is_set():  # an unreachable pose: the planner searches its full time
                _call(conn, "POST", "/plan", {"cell": "servo_arm_pair", "group": "left_arm",
                                              "pose": {"xyz": [0.0, 0.6, 0.8]},
                                              "planning_time": 1.0})

        planners = [threading.Thread(target=keep_planning, daemon=True)
                    for _ in range(args.planners)]
        for t in planners:
            t.start()
        time.sleep(1.0)
        if args.client == "wrk":
            return _run_wrk(args, port, run_id, stop)
        samples: list[list[float]] = [[] for _ in range(args.clients)]

        def poll(k: int) -> None:
            conn = http.client.HTTPConnection("127.0.0.1", port, timeout=10)
            end = time.monotonic() + args.seconds
            while time.monotonic() < end:
                t0 = time.perf_counter()
                code, _ = _call(conn, "GET", f"/runs/{run_id}")
                samples[k].append(time.perf_counter() - t0)
                assert code == 200

        clients = [threading.Thread(target=poll, args=(k,)) for k in range(args.clients)]
        for t in clients:
            t.start()
        for t in clients:
            t.join()
        stop.set()
        _, body = _call(http.client.HTTPConnection("127.0.0.1", port, timeout=10), "GET",
                        f"/runs/{run_id}")
        run = json.loads(body)
        ms = 1e3 * np.concatenate([np.array(s) for s in samples])
        p50, p95, p99 = np.percentile(ms, [50, 95, 99])
        print(f"GET /runs/{{id}}: {args.clients} clients, {len(ms)} requests in "
              f"{args.seconds:.0f} s ({len(ms) / args.seconds:.0f}/s) while a sim run and "
              f"{args.planners} /plan client(s) plan: p50 {p50:.1f} ms, p95 {p95:.1f} ms, "
              f"p99 {p99:.1f} ms, max {ms.max():.1f} ms (the run: {run['status']}, "
              f"{len(run['events'])} events, at the end)")
        return 0
    finally:
        server.terminate()
        server.wait(30)
        shutil.rmtree(state, ignore_errors=True)


def _run_wrk(args: argparse.Namespace, port: int, run_id: str, stop: threading.Event) -> int:
    if shutil.which("wrk") is None:
        raise SystemExit("--client wrk needs wrk on PATH (apt-get install wrk)")
    done = subprocess.run(
        ["wrk", "-t2", f"-c{args.clients}", f"-d{args.seconds:.0f}s", "--latency",
         "-H", f"Authorization: Bearer {TOKEN}", f"http://127.0.0.1:{port}/runs/{run_id}"],
        capture_output=True, text=True, timeout=args.seconds + 60)
    stop.set()
    text = done.stdout
    percentiles = {}
    for line in text.splitlines():
        parts = line.split()
        if len(parts) == 2 and parts[0].endswith("%") and parts[0][:-1].replace(".", "").isdigit():
            percentiles[parts[0]] = _ms(parts[1])
    rate = next((line.split()[1] for line in text.splitlines()
                 if line.startswith("Requests/sec:")), "?")
    errors = [line.strip() for line in text.splitlines() if "Non-2xx" in line or "errors" in line]
    print(f"GET /runs/{{id}} (wrk, {args.clients} connections, {args.seconds:.0f} s, "
          f"{args.planners} /plan client(s) planning, a sim run executing): {rate} req/s; "
          + ", ".join(f"p{k[:-1]} {v:.1f} ms" for k, v in percentiles.items())
          + (f"; {'; '.join(errors)}" if errors else ""))
    return 0


def _ms(value: str) -> float:
    """wrk's '1.23ms' / '456.00us' / '1.02s' as milliseconds."""
    for unit, scale in (("us", 1e-3), ("ms", 1.0), ("s", 1e3)):
        if value.endswith(unit):
            return float(value[: -len(unit)]) * scale
    return float(value)


if __name__ == "__main__":
    sys.exit(main())
