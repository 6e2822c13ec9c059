"""Soak: minutes of mixed load against one ``run-task serve``, its resources sampled.

    python benchmarks/api_soak.py [--minutes 30] [--clients 16] [--control-port]
                                  [--sample-s 5] [--planner-idle-s 20] [--seed 0] [--json]

Starts ``run-task serve`` (planning in worker processes, sim at real speed, idle planners
closed after ``--planner-idle-s``) on a free loopback port, with ``--control-port`` a
control port too. After a warm-up (a recorded mock run, two checks at once, a preview, a
plan, a sim run, and mock runs until the server's memory of ended runs is full) and the
idle planners' reaping, the server's process tree is sampled: that is the baseline. Then, for ``--minutes``:

- ``--clients`` threads, in a process of their own, send a seeded mix back to back (with a
  short random pause): polls of the moving run and pages of a recorded one, listings,
  event streams of the moving run (half read to the end, half read the status line and
  never another byte), previews of pick_place, ``/plan`` of a real motion, task checks,
  and bad requests: wrong tokens, malformed bodies, hostile names (300-byte, NUL,
  ``../``), NaN and boolean numbers, an oversized ``Content-Length`` (413) and a body
  trickled a byte a second (408 after ``body_timeout_s``);
- this process starts a sim run of the servo arm (retrying 409/503), and once its first
  motion is sent, cancels it after 0.2-1 s (every fourth run ends on its own), timing the
  cancel on the port it is sent to (the control port with ``--control-port``) and checking
  it is effective (the run ends ``cancelled`` within 2 s);
- every ``--sample-s`` the server's tree (the server and its planning and checking
  processes) is read from /proc: resident memory, open descriptors, processes.

When the load stops, the benchmark waits for idle planners to be reaped, then samples
again. It prints the samples (one row every 30 s), latencies by kind, and one JSON line;
it exits 1 unless all of:

- **flat memory**: over the second half of the load, the resident memory of the server and
  of every process alive throughout it grows (least-squares line) by at most
  ``--rss-growth-mib`` in all;
- **nothing leaked**: after the load, at most the baseline's processes, and at most
  ``--fd-slack`` more open descriptors than the baseline;
- **cancels**: p99 <= 100 ms on the port they were sent to, every cancel effective.

Tracebacks in the server's log are counted and reported.
"""

from __future__ import annotations

import argparse
import json
import multiprocessing
import os
import random
import socket
import sys
import tempfile
import threading
import time
from collections import Counter, defaultdict
from pathlib import Path
from typing import Any

import numpy as np
from _server import TOKEN, TreeSample, call, free_port, sample_tree, start_server

TARGET_CANCEL_P99_MS = 100.0
KEEP_FINISHED = 32  # ended runs the server keeps in memory (RunManager's keep_finished)
MOVE = ("task: soak_go\ncell: ../robots/cells/servo_arm_table.yaml\nsteps:\n"
        "  - go: {group: arm, to: Candle}\n  - go: {group: arm, to: home}\n")
PLAN = {"cell": "servo_arm_pair", "group": "left_arm", "to": "HandOff", "planning_time": 1.0}
KINDS = {  # kind: weight in the clients' mix
    "poll": 30, "list": 12, "stream": 4, "preview": 3, "plan": 3, "check": 8, "bad": 14,
    "trickle": 1}
BAD = [  # (method, path, JSON body or raw bytes, token)
    ("GET", "/runs", None, "wrong-token-000000"),
    ("POST", "/plan", PLAN, "wrong-token-000000"),
    ("POST", "/tasks/check", b'{"task": "pick_pl', TOKEN),
    ("POST", "/runs", b"\xff\xfe\x00garbage", TOKEN),
    ("POST", "/tasks/check", b"[]", TOKEN),
    ("POST", "/tasks/check", {"task": "a" * 300}, TOKEN),
    ("POST", "/tasks/check", {"task": "pick\u0000place"}, TOKEN),
    ("POST", "/runs", {"task": "../../../../etc/passwd", "backend": "mock"}, TOKEN),
    ("POST", "/viewer/tasks/preview", {"task": "/proc/self/environ"}, TOKEN),
    ("POST", "/plan", {**PLAN, "planning_time": True}, TOKEN),
    ("POST", "/plan", b'{"cell": "servo_arm_pair", "group": "left_arm", "to": "HandOff", '
                      b'"planning_time": NaN}', TOKEN),
    ("POST", "/runs", {"task": "pick_place", "backend": "mock", "speed": 1e308}, TOKEN),
    ("GET", "/runs/" + "x" * 300, None, TOKEN),
    ("GET", "/cells/..%2F..%2Fetc%2Fpasswd", None, TOKEN),
]


# ----------------------------------------------------------------- the clients' process
def _raw(port: int, head: str, timeout: float = 60.0) -> socket.socket:
    sock = socket.create_connection(("127.0.0.1", port), timeout=timeout)
    sock.sendall(head.encode())
    return sock


def _status_of(sock: socket.socket) -> int:
    line = b""
    while b"\r\n" not in line:
        data = sock.recv(64 - len(line) if len(line) < 64 else 1)
        if not data:
            break
        line += data
    parts = line.split()
    return int(parts[1]) if len(parts) > 1 and parts[1].isdigit() else 0


def _stream(port: int, run_id: str, reads: bool) -> tuple[int, float]:
    """Follow a run's events: (status, seconds to the status line)."""
    head = (f"GET /runs/{run_id}/events HTTP/1.1\r\nHost: soak\r\n"
            f"Authorization: Bearer {TOKEN}\r\n\r\n")
    start = time.perf_counter()
    with _raw(port, head) as sock:
        code = _status_of(sock)
        seconds = time.perf_counter() - start
        if reads:  # to the end of the run (the server closes), at most a minute
            deadline = time.monotonic() + 60
            while time.monotonic() < deadline and sock.recv(65536):
                pass
        else:
            time.sleep(15)  # holds the stream and never reads another byte
        return code, seconds


def _oversized(port: int) -> int:
    head = (f"POST /tasks/check HTTP/1.1\r\nHost: soak\r\nAuthorization: Bearer {TOKEN}\r\n"
            "Content-Type: application/json\r\nContent-Length: 5000000\r\n\r\n")
    with _raw(port, head) as sock:
        return _status_of(sock)


def _trickle(port: int) -> int:
    head = (f"POST /tasks/check HTTP/1.1\r\nHost: soak\r\nAuthorization: Bearer {TOKEN}\r\n"
            "Content-Type: application/json\r\nContent-Length: 1000\r\n\r\n")
    with _raw(port, head) as sock:
        sock.settimeout(1.0)
        for _ in range(120):
            try:
                sock.sendall(b" ")
                return _status_of(sock)
            except TimeoutError:
                continue
            except OSError:
                return 0
        return 0


def _one(port: int, kind: str, rng: random.Random, moving: str, recorded: str
         ) -> int | tuple[int, float]:
    """One request of ``kind``: its status (or status and seconds, when the request's
    time is not the whole exchange's)."""
    if kind == "poll":
        if rng.random() < 0.5:
            return call(port, "GET", f"/runs/{moving or recorded}")[0]
        return call(port, "GET", f"/runs/{recorded}?since={rng.randrange(40)}&limit=20")[0]
    if kind == "list":
        return call(port, "GET", rng.choice(["/runs", "/cells", "/health", "/runs?limit=5"]))[0]
    if kind == "stream":
        return _stream(port, moving or recorded, reads=rng.random() < 0.5)
    if kind == "preview":
        return call(port, "POST", "/viewer/tasks/preview", {"task": "pick_place"})[0]
    if kind == "plan":
        return call(port, "POST", "/plan", PLAN)[0]
    if kind == "check":
        return call(port, "POST", "/tasks/check", {"task": "pick_place"})[0]
    if kind == "trickle":
        return _trickle(port)
    if rng.random() < 0.1:
        return _oversized(port)
    method, path, body, token = BAD[rng.randrange(len(BAD))]
    if isinstance(body, bytes):
        return call(port, method, path, raw=body, token=token)[0]
    return call(port, method, path, body, token=token)[0]


def _clients(port: int, clients: int, recorded: str, seed: int, moving: Any, stop: Any,
             out: Any) -> None:
    """The clients (in a process of their own): records of (time, kind, code, ms) sent to
    ``out`` in batches, then None."""
    names, weights = list(KINDS), list(KINDS.values())
    batch: list[tuple[float, str, int, float]] = []
    lock = threading.Lock()

    def client(k: int) -> None:
        rng = random.Random(seed * 1000 + k)
        while not stop.is_set():
            kind = rng.choices(names, weights)[0]
            start = time.perf_counter()
            try:
                answer = _one(port, kind, rng, moving.value.decode(), recorded)
            except OSError:
                answer = 0
            code, seconds = answer if isinstance(answer, tuple) else \
                (answer, time.perf_counter() - start)
            ms = seconds * 1000.0
            with lock:
                batch.append((time.monotonic(), kind, code, ms))
            time.sleep(rng.uniform(0.0, 0.2))

    threads = [threading.Thread(target=client, args=(k,), daemon=True) for k in range(clients)]
    for thread in threads:
        thread.start()
    while any(t.is_alive() for t in threads):
        time.sleep(2.0)
        with lock:
            done, batch[:] = list(batch), []
        out.put(done)
    with lock:
        out.put(list(batch))
    out.put(None)


# ----------------------------------------------------------------- runs and cancels
class Canceller(threading.Thread):
    """Sim runs started one after another, three of four cancelled mid-motion (timed)."""

    def __init__(self, port: int, control: int, moving: Any, seed: int) -> None:
        super().__init__(daemon=True)
        self.port, self.control, self.moving = port, control, moving
        self.rng = random.Random(seed)
        self.stop = threading.Event()
        self.cancels: list[tuple[float, float, bool]] = []  # (time, ms, effective)
        self.finished = 0
        self.starts_refused = Counter[int]()

    def _state(self, run_id: str) -> dict[str, Any]:
        return json.loads(call(self.control, "GET", f"/runs/{run_id}?limit=1000")[1])

    def run(self) -> None:
        cycle = 0
        while not self.stop.is_set():
            code, data, _ = call(self.port, "POST", "/runs",
                                 {"yaml": MOVE, "backend": "sim", "check": False})
            if code != 202:
                self.starts_refused[code] += 1
                time.sleep(0.2)
                continue
            run_id = json.loads(data)["run_id"]
            self.moving.value = run_id.encode()
            deadline = time.monotonic() + 120
            while True:
                run = self._state(run_id)
                if any(e["kind"] in ("planned", "motion") for e in run["events"]) or \
                        run["status"] != "running" or time.monotonic() > deadline:
                    break
                time.sleep(0.05)
            cycle += 1
            if cycle % 4 == 0 or run["status"] != "running":
                while self._state(run_id)["status"] == "running":
                    time.sleep(0.1)
                self.finished += 1
                continue
            time.sleep(self.rng.uniform(0.2, 1.0))
            code, data, seconds = call(self.control, "POST", f"/runs/{run_id}/cancel")
            if code == 409:  # it ended first: nothing to time
                continue
            effective = False
            deadline = time.monotonic() + 2.0
            while time.monotonic() < deadline:
                status = self._state(run_id)["status"]
                if status != "running":
                    effective = status == "cancelled"
                    break
                time.sleep(0.02)
            self.cancels.append((time.monotonic(), seconds * 1000.0, code == 202 and effective))
            while self._state(run_id)["status"] == "running":  # the arm is free again
                time.sleep(0.1)


# ----------------------------------------------------------------- judging
def _growth_mib(samples: list[tuple[float, TreeSample]]) -> dict[int, dict[str, float]]:
    """For each process alive in every sample: its resident memory (MiB) at the first and
    last sample and its growth (least-squares line over the samples' span)."""
    times = np.array([t for t, _ in samples])
    span = float(times[-1] - times[0])
    alive = set.intersection(*(set(s.rss_mib) for _, s in samples))
    out = {}
    for pid in sorted(alive):
        rss = [s.rss_mib[pid] for _, s in samples]
        slope = float(np.polyfit(times, rss, 1)[0])
        out[pid] = {"first": round(rss[0]), "last": round(rss[-1]),
                    "growth": round(slope * span, 1)}
    return out


def _settle(pid: int, idle_s: float, most: TreeSample | None = None) -> TreeSample:
    """The tree once idle planners are closed: sampled until its processes stop changing
    (and, given ``most``, are at most as many), within ``2 * idle_s + 30`` s."""
    time.sleep(idle_s * 1.25 + 2)  # the reaper looks every idle_s / 4
    deadline = time.monotonic() + idle_s + 30
    last, same = sample_tree(pid), 0
    while time.monotonic() < deadline:
        time.sleep(1.0)
        now = sample_tree(pid)
        same = same + 1 if now.processes == last.processes else 0
        last = now
        if same >= 3 and (most is None or now.processes <= most.processes):
            break
    return last


def _fd_kinds(tree: TreeSample) -> Counter[str]:
    """What the tree's open descriptors are (``socket``, ``pipe``, a file's path …)."""
    kinds: Counter[str] = Counter()
    for pid in tree.pids:
        try:
            fds = os.listdir(f"/proc/{pid}/fd")
        except OSError:
            continue
        for fd in fds:
            try:
                target = os.readlink(f"/proc/{pid}/fd/{fd}")
            except OSError:
                continue
            kinds[target.split(":[")[0] if ":[" in target else target] += 1
    return kinds


def _pct(values: list[float], q: float) -> float:
    return round(float(np.percentile(values, q)), 1) if values else float("nan")


def _warm_up(port: int) -> str:
    """A recorded mock run (its id), one of each kind of work, and as many more ended runs
    as the server keeps in memory (each holds its tree, scene and closed planner: the
    baseline is taken with that set full, as it stays under load)."""
    code, data, _ = call(port, "POST", "/runs", {"task": "pick_place", "backend": "mock"})
    if code != 202:
        raise SystemExit(f"POST /runs answered {code}: {data[:300]!r}")
    recorded = json.loads(data)["run_id"]
    while json.loads(call(port, "GET", f"/runs/{recorded}")[1])["status"] == "running":
        time.sleep(0.1)
    checks = [threading.Thread(target=call, args=(port, "POST", "/tasks/check",
                                                  {"task": "pick_place"})) for _ in range(2)]
    for thread in checks:
        thread.start()
    for thread in checks:
        thread.join()
    call(port, "POST", "/viewer/tasks/preview", {"task": "pick_place"})
    call(port, "POST", "/plan", PLAN)
    for k in range(KEEP_FINISHED + 1):
        code, data, _ = call(port, "POST", "/runs", {"yaml": MOVE, "check": False,
                                                     "backend": "sim" if k == 0 else "mock"})
        if code != 202:
            raise SystemExit(f"POST /runs answered {code}: {data[:300]!r}")
        run_id = json.loads(data)["run_id"]
        while json.loads(call(port, "GET", f"/runs/{run_id}")[1])["status"] == "running":
            time.sleep(0.05)
    return recorded


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--minutes", type=float, default=30.0)
    parser.add_argument("--clients", type=int, default=16)
    parser.add_argument("--control-port", action="store_true")
    parser.add_argument("--sample-s", type=float, default=5.0)
    parser.add_argument("--planner-idle-s", type=float, default=20.0)
    parser.add_argument("--rss-growth-mib", type=float, default=50.0)
    parser.add_argument("--fd-slack", type=int, default=4)
    parser.add_argument("--seed", type=int, default=0)
    parser.add_argument("--json", action="store_true")
    args = parser.parse_args()

    port = free_port()
    control = port
    while args.control_port and control == port:  # two free ports, not the same one twice
        control = free_port()
    context = multiprocessing.get_context("spawn")
    with tempfile.TemporaryDirectory() as state:
        log_path = Path(state) / "server.log"
        with open(log_path, "wb") as log:
            server = start_server(port, state, log=log, log_level="warning",
                                  env={"TASKRUNNER_PLANNER_IDLE_S": str(args.planner_idle_s)},
                                  control_port=control if args.control_port else None)
        try:
            recorded = _warm_up(port)
            baseline = _settle(server.pid, args.planner_idle_s)
            baseline_fds = _fd_kinds(baseline)
            moving = context.Array("c", 64)
            stop, out = context.Event(), context.Queue()
            clients = context.Process(target=_clients, daemon=True, args=(
                port, args.clients, recorded, args.seed, moving, stop, out))
            canceller = Canceller(port, control, moving, args.seed)
            records: list[tuple[float, str, int, float]] = []
            samples: list[tuple[float, TreeSample]] = []
            t0 = time.monotonic()
            clients.start()
            canceller.start()
            print(f"{'t s':>6} {'RSS srv':>8} {'RSS tree':>9} {'procs':>5} {'fds':>5} "
                  f"{'req/s':>6} {'p99 ms':>7} {'cancels':>7}", flush=True)
            printed = -30.0
            while (now := time.monotonic()) - t0 < args.minutes * 60:
                time.sleep(max(0.0, t0 + (len(samples) + 1) * args.sample_s - now))
                while not out.empty():
                    records += out.get()
                tree = sample_tree(server.pid)
                samples.append((time.monotonic(), tree))
                t = samples[-1][0] - t0
                if t - printed >= 30:
                    printed = t
                    window = [ms for when, kind, _, ms in records
                              if when > samples[-1][0] - 30 and kind != "trickle"]
                    print(f"{t:>6.0f} {tree.rss_mib.get(server.pid, 0):>8.0f} "
                          f"{tree.total_rss_mib:>9.0f} {tree.processes:>5} "
                          f"{tree.total_fds:>5} {len(window) / 30:>6.1f} "
                          f"{_pct(window, 99):>7} {len(canceller.cancels):>7}", flush=True)
            stop.set()
            canceller.stop.set()
            while (batch := out.get(timeout=120)) is not None:
                records += batch
            clients.join(30)
            canceller.join(150)
            end = _settle(server.pid, args.planner_idle_s, most=baseline)
            fds_added = _fd_kinds(end) - baseline_fds
        finally:
            server.terminate()
            server.wait(30)
        tracebacks = log_path.read_text(errors="replace").count("Traceback")

    second = [(t, s) for t, s in samples if t - t0 >= args.minutes * 30]
    by_pid = _growth_mib(second)
    growth = sum(row["growth"] for row in by_pid.values())
    server_growth = by_pid.get(server.pid, {}).get("growth", 0.0)
    by_kind: dict[str, list[float]] = defaultdict(list)
    codes: dict[str, Counter[int]] = defaultdict(Counter)
    for _, kind, code, ms in records:
        by_kind[kind].append(ms)
        codes[kind][code] += 1
    cancel_ms = [ms for _, ms, _ in canceller.cancels]
    effective = sum(ok for *_, ok in canceller.cancels)
    rss_server = [s.rss_mib.get(server.pid, 0.0) for _, s in samples]
    result: dict[str, Any] = {
        "benchmark": "api_soak", "minutes": args.minutes, "clients": args.clients,
        "cancels_on": "control port" if args.control_port else "main port",
        "samples": len(samples), "requests": len(records),
        "latency_ms": {k: {"n": len(v), "p50": _pct(v, 50), "p99": _pct(v, 99),
                           "codes": dict(sorted(codes[k].items()))}
                       for k, v in sorted(by_kind.items())},
        "cancel_ms": {"n": len(cancel_ms), "effective": effective, "p50": _pct(cancel_ms, 50),
                      "p99": _pct(cancel_ms, 99),
                      "max": round(max(cancel_ms), 1) if cancel_ms else None},
        "runs_finished": canceller.finished,
        "starts_refused": dict(canceller.starts_refused),
        "rss_server_mib": {"start": round(rss_server[0]), "max": round(max(rss_server)),
                           "end": round(rss_server[-1])},
        "rss_tree_mib": {"min": round(min(s.total_rss_mib for _, s in samples)),
                         "max": round(max(s.total_rss_mib for _, s in samples))},
        "second_half_growth_mib": round(growth, 1),
        "second_half_server_growth_mib": round(server_growth, 1),
        "second_half_by_process": {("server" if pid == server.pid else str(pid)): row
                                   for pid, row in by_pid.items()},
        "processes": {"baseline": baseline.processes,
                      "max": max(s.processes for _, s in samples), "end": end.processes},
        "fds": {"baseline": baseline.total_fds,
                "max": max(s.total_fds for _, s in samples), "end": end.total_fds,
                "added": dict(fds_added)},
        "server_tracebacks": tracebacks,
        "cpus": os.cpu_count(), "load": [round(v, 2) for v in os.getloadavg()],
    }
    checks = {
        "flat_memory": bool(growth <= args.rss_growth_mib),
        "no_process_leak": end.processes <= baseline.processes,
        "no_fd_leak": end.total_fds <= baseline.total_fds + args.fd_slack,
        "cancel_p99": bool(bool(cancel_ms) and np.percentile(cancel_ms, 99) <= TARGET_CANCEL_P99_MS
                           and effective == len(cancel_ms)),
    }
    result["met"] = checks
    print(f"\n{'kind':>8} {'n':>6} {'p50 ms':>8} {'p99 ms':>8}  codes")
    for kind, row in result["latency_ms"].items():
        print(f"{kind:>8} {row['n']:>6} {row['p50']:>8} {row['p99']:>8}  {row['codes']}")
    c = result["cancel_ms"]
    print(f"{'cancel':>8} {c['n']:>6} {c['p50']:>8} {c['p99']:>8}  "
          f"effective {effective}/{len(cancel_ms)} on the {result['cancels_on']}")
    print(f"memory growth over the second half: {growth:.1f} MiB (server {server_growth:.1f}); "
          f"processes {baseline.processes} -> {end.processes}; "
          f"fds {baseline.total_fds} -> {end.total_fds} (more: {dict(fds_added)}); "
          f"server tracebacks {tracebacks}")
    print("over the second half, by process (MiB first -> last, growth): " + "; ".join(
        f"{name} {row['first']} -> {row['last']} ({row['growth']:+})"
        for name, row in result["second_half_by_process"].items()))
    print("met: " + ", ".join(f"{k} {'yes' if v else 'NO'}" for k, v in checks.items()))
    if args.json:
        print(json.dumps(result))
    return 0 if all(checks.values()) else 1


if __name__ == "__main__":
    sys.exit(main())
