"""A run's duration with 300 event-stream clients following it, against none.

    python benchmarks/api_streams.py [--streams 300] [--task pick_place|repeat:N]
                                     [--backend sim|mujoco] [--repeats 1] [--grace 30]
                                     [--json]

Starts ``run-task serve`` on a free loopback port and runs ``--task`` on the sim backend
(real speed) ``--repeats`` times with no stream, then as many times with ``--streams``
clients following its events (``GET /runs/{id}/events``): half read every event, half
send the request and never read a byte. The clients live in a process of their own (an
asyncio loop), so their work does not share this process's GIL with the measuring.

Per run it reports the run's own duration (its ``run_finished`` time, on the server's
clock; for ``repeat:N``, from the end of the wait in which the clients connect), the CPU
time of the server (from the run's start), of its event-loop thread (over the measured
part) and of the client process, the latency of ``GET /health`` and ``GET /runs/{id}`` polled 10 times a second
meanwhile, how many events the readers received (each should get every event once), and
how many of the non-reading clients the server had closed ``--grace`` s after the run
ended. Target (issue 29): the run's duration with the streams within 10 % of none.
"""

from __future__ import annotations

import argparse
import asyncio
import http.client
import json
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import threading
import time

import numpy as np
from api_latency import TOKEN, _call, _cpu_seconds, _port, _start_server

TARGET = 0.10
_CONNECT_S = 3.0  # the repeat:N task's first step: a wait for the clients to connect


# ----------------------------------------------------------------- the client process
async def _reader(port: int, run_id: str, counts: list[int], k: int,
                  volume: list[int]) -> None:
    reader, writer = await asyncio.open_connection("127.0.0.1", port)
    writer.write(f"GET /runs/{run_id}/events HTTP/1.1\r\nHost: bench\r\n"
                 f"Authorization: Bearer {TOKEN}\r\n\r\n".encode())
    try:
        # Large reads, events counted by their "\nevent: " lines (the client's own CPU
        # competes with the server's for the machine's 2 cores: keep it small).
        tail = b""
        while chunk := await reader.read(1 << 18):
            volume[0] += len(chunk)
            data = tail + chunk
            counts[k] += data.count(b"\nevent: ")
            tail = data[-8:]
            counts[k] -= tail.count(b"\nevent: ")  # counted again with the next chunk
    except OSError:
        pass
    finally:
        writer.close()


async def _silent(port: int, run_id: str, closed: list[bool], k: int,
                  release: asyncio.Event) -> None:
    """Sends the request and reads nothing until ``release``; then drains the socket to
    learn whether the server had closed it."""
    reader, writer = await asyncio.open_connection("127.0.0.1", port, limit=2 ** 16)
    transport = writer.transport
    writer.write(f"GET /runs/{run_id}/events HTTP/1.1\r\nHost: bench\r\n"
                 f"Authorization: Bearer {TOKEN}\r\n\r\n".encode())
    transport.pause_reading()  # never read: the kernel's buffers fill, then the server's
    await release.wait()
    transport.resume_reading()
    try:
        while await asyncio.wait_for(reader.read(1 << 20), 5.0):
            pass
        closed[k] = True  # EOF: the server had closed it (its last bytes were buffered)
    except (TimeoutError, OSError):
        closed[k] = False
    finally:
        writer.close()


async def _clients(port: int, run_id: str, count: int) -> dict:
    readers, silent = count - count // 2, count // 2
    counts, closed = [0] * readers, [False] * silent
    release = asyncio.Event()
    volume = [0]
    tasks = [asyncio.create_task(_reader(port, run_id, counts, k, volume))
             for k in range(readers)]
    tasks += [asyncio.create_task(_silent(port, run_id, closed, k, release))
              for k in range(silent)]
    print("connected", flush=True)
    await asyncio.get_running_loop().run_in_executor(None, sys.stdin.readline)  # "release"
    release.set()
    await asyncio.wait(tasks, timeout=60)
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return {"readers": readers, "events_read": counts, "silent": silent,
            "silent_closed": sum(closed), "bytes_read": volume[0],
            "cpu_s": usage.ru_utime + usage.ru_stime}


def client_main(port: int, run_id: str, count: int) -> None:
    print(json.dumps(asyncio.run(_clients(port, run_id, count))), flush=True)


# ----------------------------------------------------------------- the measuring process
def _poll(port: int, run_id: str, stop: threading.Event, out: dict[str, list[float]]) -> None:
    conns = {path: http.client.HTTPConnection("127.0.0.1", port, timeout=60)
             for path in ("/health", f"/runs/{run_id}")}
    while not stop.wait(0.1):
        for path, conn in conns.items():
            t0 = time.perf_counter()
            try:
                _call(conn, "GET", path)
            except (OSError, http.client.HTTPException):
                conns[path] = conn = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
                continue
            out.setdefault(path.split("/")[1], []).append(1e3 * (time.perf_counter() - t0))


def _thread_cpu(pid: int, tid: int) -> float:
    """CPU time (s) of thread ``tid`` of process ``pid`` (the main thread: ``tid = pid``)."""
    fields = open(f"/proc/{pid}/task/{tid}/stat").read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def _repeat_task(times: int) -> str:
    """A run of many motions: ``times`` times out and back on the servo arm's table, after
    a wait in which the clients connect (the duration is measured from its end)."""
    return (f"task: stream_load\ncell: ../robots/cells/servo_arm_table.yaml\nsteps:\n"
            f"  - wait: {{seconds: {_CONNECT_S}}}\n"
            f"  - repeat:\n      times: {times}\n      do:\n"
            f"        - go: {{group: arm, to: Candle}}\n"
            f"        - go: {{group: arm, to: home}}\n")


def _one_run(port: int, server_pid: int, task: str, backend: str, streams: int,
             grace: float) -> dict:
    def control(method: str, url: str, body: dict | None = None) -> tuple[int, bytes]:
        return _call(http.client.HTTPConnection("127.0.0.1", port, timeout=60), method, url,
                     body)

    request: dict = {"task": task} if not task.startswith("repeat:") else \
        {"yaml": _repeat_task(int(task.split(":")[1])), "check": False}
    status, body = control("POST", "/runs", {**request, "backend": backend})
    assert status == 202, body
    run_id = json.loads(body)["run_id"]
    clients = None
    if streams:
        clients = subprocess.Popen(
            [sys.executable, __file__, "--client", str(port), run_id, str(streams)],
            stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True,
            env={**os.environ, "PYTHONPATH": os.path.dirname(__file__)})
        assert clients.stdout is not None and clients.stdin is not None
        assert clients.stdout.readline().strip() == "connected"
    cpu0 = _cpu_seconds(server_pid)[0]
    latencies: dict[str, list[float]] = {}
    stop = threading.Event()
    poller = threading.Thread(target=_poll, args=(port, run_id, stop, latencies), daemon=True)
    poller.start()
    loop0 = None  # the server's event loop thread's CPU time at the wait's end
    while True:
        run = json.loads(control("GET", f"/runs/{run_id}")[1])
        if loop0 is None and any(e["kind"] == "node_finished" for e in run["events"]):
            loop0 = _thread_cpu(server_pid, server_pid)
        if run["status"] != "running":
            break
        time.sleep(0.05)
    loop_cpu = _thread_cpu(server_pid, server_pid) - (loop0 or 0.0)
    stop.set()
    poller.join()
    events = run["events"]
    start = next(e["time"] for e in events if e["kind"] == "node_finished") \
        if task.startswith("repeat:") else 0.0  # the end of the wait
    result = {"status": run["status"], "events": len(events),
              "duration_s": events[-1]["time"] - start,
              "server_cpu_s": _cpu_seconds(server_pid)[0] - cpu0,
              "loop_cpu_s": loop_cpu}
    for name, ms in latencies.items():
        result[f"{name}_p99_ms"] = float(np.percentile(ms, 99))
        result[f"{name}_max_ms"] = float(max(ms))
    if clients is not None:
        time.sleep(grace)
        out, _ = clients.communicate("release\n", timeout=120)
        seen = json.loads(out.strip().splitlines()[-1])
        result.update(readers=seen["readers"],
                      readers_with_every_event=sum(n == result["events"]
                                                   for n in seen["events_read"]),
                      silent=seen["silent"], silent_closed_by_server=seen["silent_closed"],
                      mb_read=seen["bytes_read"] / 1e6, clients_cpu_s=seen["cpu_s"])
    return result


def main() -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--streams", type=int, default=300)
    parser.add_argument("--task", default="pick_place",
                        help="a shipped task (pick_place), or repeat:N: N times out to "
                             "Candle and back home (4 events a motion)")
    parser.add_argument("--backend", default="sim", help="sim (default) or mujoco (its "
                        "physics events are large: joints and object poses at 25 Hz)")
    parser.add_argument("--repeats", type=int, default=1)
    parser.add_argument("--grace", type=float, default=30.0,
                        help="s after the run's end before asking the non-reading clients "
                             "whether the server closed them (30)")
    parser.add_argument("--json", action="store_true")
    parser.add_argument("--client", nargs=3, help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.client:
        client_main(int(args.client[0]), args.client[1], int(args.client[2]))
        return 0
    port = _port()
    state = tempfile.mkdtemp(prefix="api-streams-")
    server = _start_server(port, state)
    rows: list[tuple[int, dict]] = []
    try:
        _one_run(port, server.pid, args.task, args.backend, 0, 0.0)  # warm-up: cell loaded, planner spawned
        for _ in range(args.repeats):
            for streams in (0, args.streams):
                rows.append((streams, _one_run(port, server.pid, args.task, args.backend, streams,
                                              args.grace)))
    finally:
        server.terminate()
        server.wait(30)
        shutil.rmtree(state, ignore_errors=True)
    print(f"{args.task} on {args.backend} at real speed; streams: half read, half never read")
    print(f"{'streams':>7} {'run s':>6} {'events':>6} {'health p99/max ms':>18} "
          f"{'run p99/max ms':>15} {'readers complete':>16} {'silent closed':>13} "
          f"{'MB read':>8} {'CPU s server/loop/clients':>25}")
    for streams, r in rows:
        print(f"{streams:>7} {r['duration_s']:>6.2f} {r['events']:>6} "
              f"{r['health_p99_ms']:>8.1f}/{r['health_max_ms']:<9.1f} "
              f"{r['runs_p99_ms']:>7.1f}/{r['runs_max_ms']:<7.1f} "
              f"{str(r.get('readers_with_every_event', '-')) + '/' + str(r.get('readers', '-')):>16} "
              f"{str(r.get('silent_closed_by_server', '-')) + '/' + str(r.get('silent', '-')):>13} "
              f"{r.get('mb_read', 0.0):>8.1f} "
              f"{r['server_cpu_s']:>9.2f}/{r['loop_cpu_s']:.2f}/"
              f"{r.get('clients_cpu_s', 0.0):<10.2f}")
    base = float(np.median([r["duration_s"] for s, r in rows if s == 0]))
    loaded = float(np.median([r["duration_s"] for s, r in rows if s]))
    ratio = loaded / base - 1.0
    verdict = "met" if ratio <= TARGET else "missed"
    print(f"target: run with {args.streams} streams within {TARGET:.0%} of none: {verdict} "
          f"({loaded:.2f} s vs {base:.2f} s, {ratio:+.1%})")
    if args.json:
        print(json.dumps({"task": args.task, "backend": args.backend, "streams": args.streams,
                          "runs": [{"streams": s, **r} for s, r in rows],
                          "slowdown": round(ratio, 4), "met": verdict == "met"}))
    return 0


if __name__ == "__main__":
    sys.exit(main())
