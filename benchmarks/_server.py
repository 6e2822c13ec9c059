"""What the API benchmarks share: a ``run-task serve`` on a free loopback port, a timed
request, and the server's process tree read from /proc (processes, memory, descriptors).

Imported by ``api_control.py`` and ``api_soak.py`` (run as scripts from this folder).
"""

from __future__ import annotations

import http.client
import json
import os
import socket
import subprocess
import sys
import time
from dataclasses import dataclass
from pathlib import Path
from typing import IO

__all__ = ["REPO_ROOT", "TOKEN", "TreeSample", "call", "free_port", "sample_tree",
           "start_server"]

REPO_ROOT = Path(__file__).resolve().parent.parent
TOKEN = "bench-token-0123456789"
_PAGE_MIB = os.sysconf("SC_PAGE_SIZE") / 2**20


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


def call(port: int, method: str, path: str, body: object = None, token: str | None = TOKEN,
         timeout: float = 120.0, raw: bytes | None = None) -> tuple[int, bytes, float]:
    """One request on a connection of its own: (status, body, seconds from the request's
    write to the answer's last byte). ``raw`` is sent as the body as it is (malformed
    bodies); otherwise ``body`` as JSON."""
    headers = {"Content-Type": "application/json"}
    if token is not None:
        headers["Authorization"] = f"Bearer {token}"
    data = raw if raw is not None else None if body is None else json.dumps(body).encode()
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
    start = time.perf_counter()
    try:
        conn.request(method, path, body=data, headers=headers)
        answer = conn.getresponse()
        out = answer.read()
        return answer.status, out, time.perf_counter() - start
    finally:
        conn.close()


def start_server(port: int, state: str, *, env: dict[str, str] | None = None,
                 control_port: int | None = None, log_level: str = "critical",
                 log: IO[bytes] | None = None) -> subprocess.Popen:
    """``run-task serve`` (worker planners, sim at real speed) with the benchmarks' token
    and ``env`` (``TASKRUNNER_*`` settings) on ``port``, answering ``/health``; its output
    to ``log`` (default: dropped)."""
    environ = {**os.environ, "PYTHONPATH": str(REPO_ROOT), "TASKRUNNER_SIM_SPEED": "1",
               **(env or {})}
    out = log if log is not None else subprocess.DEVNULL
    server = subprocess.Popen(
        [sys.executable, "-m", "taskrunner.cli", "serve", "--port", str(port), "--token",
         TOKEN, "--data-dir", state, "--log-level", log_level,
         *(["--control-port", str(control_port)] if control_port else [])],
        cwd=REPO_ROOT, env=environ, stdout=out, stderr=out)
    deadline = time.monotonic() + 90
    while True:
        try:
            if call(port, "GET", "/health", timeout=1)[0] == 200:
                return server
        except OSError:
            time.sleep(0.1)
        if time.monotonic() > deadline or server.poll() is not None:
            code = server.poll()
            server.kill()
            raise SystemExit("the server did not start in 90 s" if code is None else
                             f"the server exited with {code} while starting")


@dataclass(frozen=True)
class TreeSample:
    """A process and its descendants at one moment (from /proc)."""

    pids: tuple[int, ...]
    rss_mib: dict[int, float]  # resident memory of each process (MiB)
    fds: dict[int, int]  # open file descriptors of each process

    @property
    def processes(self) -> int:
        return len(self.pids)

    @property
    def total_rss_mib(self) -> float:
        return sum(self.rss_mib.values())

    @property
    def total_fds(self) -> int:
        return sum(self.fds.values())


def sample_tree(pid: int) -> TreeSample:
    """``pid`` and all its descendants: their memory and open descriptors. A process that
    ends while it is read counts with what could be read of it."""
    children: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                with open(f"/proc/{entry}/stat") as f:
                    parent = int(f.read().rsplit(")", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                continue
            children.setdefault(parent, []).append(int(entry))
    todo, pids, rss, fds = [pid], [], {}, {}
    while todo:
        p = todo.pop()
        pids.append(p)
        try:
            with open(f"/proc/{p}/statm") as f:
                rss[p] = int(f.read().split()[1]) * _PAGE_MIB
            fds[p] = len(os.listdir(f"/proc/{p}/fd"))
        except OSError:
            pass
        todo += children.get(p, [])
    return TreeSample(tuple(pids), rss, fds)
