"""Smoke test of an installed taskrunner, run from outside the checkout by .ci/run.

Starts ``run-task serve`` and runs ``pick_place`` through the REST API to its end, then
starts ``run-task firmware-sim`` and reads its two address lines. Exits non-zero on any
failure, printing what the child processes said.
"""

from __future__ import annotations

import json
import os
import select
import signal
import socket
import subprocess
import sys
import time
import urllib.request

TOKEN = "ci-smoke-token-0123456789"
OPENER = urllib.request.build_opener(urllib.request.ProxyHandler({}))


def free_port() -> int:
    with socket.socket() as sock:
        sock.bind(("127.0.0.1", 0))
        return int(sock.getsockname()[1])


def call(method: str, url: str, body: dict | None = None) -> dict:
    data = None if body is None else json.dumps(body).encode()
    request = urllib.request.Request(url, data=data, method=method, headers={
        "Authorization": f"Bearer {TOKEN}", "content-type": "application/json"})
    with OPENER.open(request, timeout=30) as answer:
        return json.loads(answer.read())


def stop(proc: subprocess.Popen[bytes]) -> str:
    if proc.poll() is None:
        proc.send_signal(signal.SIGTERM)
        try:
            proc.wait(15)
        except subprocess.TimeoutExpired:
            proc.kill()
            proc.wait(5)
    assert proc.stdout is not None
    return proc.stdout.read().decode(errors="replace") if not proc.stdout.closed else ""


def smoke_serve() -> None:
    port = free_port()
    env = {**os.environ, "TASKRUNNER_TOKEN": TOKEN, "TASKRUNNER_SIM_SPEED": "50"}
    proc = subprocess.Popen(["run-task", "serve", "--port", str(port), "--state-dir", "state"],
                            env=env, stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    base = f"http://127.0.0.1:{port}"
    try:
        deadline = time.monotonic() + 60
        while True:
            try:
                call("GET", f"{base}/health")
                break
            except OSError:
                if proc.poll() is not None or time.monotonic() > deadline:
                    raise SystemExit("serve did not answer /health:\n" + stop(proc)) from None
                time.sleep(0.2)
        run = call("POST", f"{base}/runs", {"task": "pick_place", "backend": "mock"})
        deadline = time.monotonic() + 120
        while True:
            detail = call("GET", f"{base}/runs/{run['run_id']}")
            if detail["status"] not in ("queued", "running"):
                break
            if time.monotonic() > deadline:
                raise SystemExit(f"run {run['run_id']} still {detail['status']} after 120 s")
            time.sleep(0.2)
        if detail["status"] != "succeeded":
            raise SystemExit(f"pick_place over the API ended {detail['status']}: "
                             f"{json.dumps(detail)[:2000]}")
        print(f"serve: pick_place over the API {detail['status']}")
    finally:
        stop(proc)


def smoke_firmware_sim() -> None:
    proc = subprocess.Popen(["run-task", "firmware-sim", "--speedup", "10"],
                            stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
    assert proc.stdout is not None
    data, deadline = b"", time.monotonic() + 300  # a cold build compiles the firmware
    try:
        while data.count(b"\n") < 2:
            ready, _, _ = select.select([proc.stdout], [], [], 1.0)
            if ready:
                chunk = os.read(proc.stdout.fileno(), 4096)
                if not chunk:
                    raise SystemExit(f"firmware-sim exited early: {data.decode()}")
                data += chunk
            if time.monotonic() > deadline:
                raise SystemExit(f"firmware-sim printed {data!r} in 300 s")
        pty, url = data.decode().splitlines()[:2]
        if not (pty.startswith("/dev/pts/") and url.startswith("http://127.0.0.1:")):
            raise SystemExit(f"firmware-sim printed {pty!r}, {url!r}")
        print(f"firmware-sim: {pty} / {url}")
    finally:
        stop(proc)


if __name__ == "__main__":
    smoke_serve()
    smoke_firmware_sim()
    sys.exit(0)
