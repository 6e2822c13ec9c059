"""Issue 29's plan-burst probe: 30 concurrent ``/plan`` requests used to start a planning
process each (33 processes, 2.9 GB); now ``max_planners`` plan at once, ``work_queue``
wait, the rest are answered 503 at once, and idle planners are closed."""

from __future__ import annotations

import os
import threading
import time
from pathlib import Path

from apitest import make_settings, served
from test_control_under_load import _request

from taskrunner.api import create_app

PLAN = {"cell": "servo_arm_pair", "group": "left_arm", "to": "HandOff",
        "planning_time": 1.0, "seed": 3}


# Processes below the server that are not planners: multiprocessing's resource tracker
# (one per process, started with its first spawned child and kept), and a first run's
# compilation of the kernels in the background (one per kernel cache, and its helper: a
# planner on a machine where they are not compiled yet starts it and plans with coal
# meanwhile; it ends by itself). Under load the compilation outlasted the burst's first
# plans: counted, it made 3 "planners" of 2.
_NOT_PLANNERS = (b"resource_tracker", b"taskrunner.planning.warmup", b"_compile_alone")


def _descendants(pid: int) -> set[int]:
    """The processes below ``pid`` (from /proc), but those of :data:`_NOT_PLANNERS`."""
    children: dict[int, list[int]] = {}
    for entry in os.listdir("/proc"):
        if entry.isdigit():
            try:
                stat = Path(f"/proc/{entry}/stat").read_text()
                parent = int(stat.rsplit(")", 1)[1].split()[1])
            except (OSError, IndexError, ValueError):
                continue
            if stat.rsplit(")", 1)[1].split()[0] != "Z":  # not a reaped-to-be zombie
                children.setdefault(parent, []).append(int(entry))
    found: set[int] = set()
    todo = [pid]
    while todo:
        for child in children.get(todo.pop(), []):
            found.add(child)
            todo.append(child)
    return {p for p in found if not any(name in _cmdline(p) for name in _NOT_PLANNERS)}


def _cmdline(pid: int) -> bytes:
    try:
        return Path(f"/proc/{pid}/cmdline").read_bytes()
    except OSError:
        return b""


def test_a_burst_of_plans_starts_at_most_max_planners_processes_and_refuses_the_excess(
        tmp_path: Path):
    settings = make_settings(tmp_path / "state", planner="worker", max_planners=2,
                             work_queue=8, planner_idle_s=1.0, plan_timeout_s=120.0)
    app = create_app(settings)
    with served(app) as port:
        before = _descendants(os.getpid())
        most: list[int] = []
        sampling = threading.Event()

        def sample() -> None:
            while not sampling.is_set():
                most.append(len(_descendants(os.getpid()) - before))
                time.sleep(0.05)

        answers: list[tuple[float, int, dict]] = []

        def client() -> None:
            status, _, body, _ = _request(port, "POST", "/plan", PLAN, timeout=180)
            answers.append((time.monotonic(), status, body))

        sampler = threading.Thread(target=sample)
        sampler.start()
        clients = [threading.Thread(target=client) for _ in range(30)]
        for thread in clients:
            thread.start()
        for thread in clients:
            thread.join(300)
        deadline = time.monotonic() + 60  # idle planners closed after planner_idle_s
        while _descendants(os.getpid()) - before and time.monotonic() < deadline:
            time.sleep(0.2)
        left = _descendants(os.getpid()) - before
        sampling.set()
        sampler.join()

    codes = sorted(status for _, status, _ in answers)
    planned = [t for t, status, _ in answers if status == 200]
    refused = [(t, body) for t, status, body in answers if status == 503]
    assert len(answers) == 30 and set(codes) <= {200, 503}, codes
    # 2 planning at once and 8 waiting are served; the other 20 refused.
    assert len(planned) == 10 and len(refused) == 20, codes
    assert all("busy" in body["detail"] for _, body in refused)
    # Refused while the first plans were still being made, not after them.
    assert max(t for t, _ in refused) < min(planned)
    # Never more planning processes than max_planners (the old server started 30).
    assert 1 <= max(most) <= settings.max_planners, max(most)
    assert not left, f"planning processes left after planner_idle_s: {sorted(left)}"
