"""The first run on a machine: it plans with coal alone while the planner's kernels compile
in the background (nothing waited for, no warm-up recorded), and the next runs load them;
``run-task warm-up`` leaves nothing for a run to compile. Each test compiles the kernels
once, into a fresh cache of its own."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import threading
import time
from pathlib import Path

import pytest

from taskrunner.runtime.session import COAL_NOTE, WARM_UP_NOTE


def _env(cache: Path) -> dict[str, str]:
    env = dict(os.environ, XDG_CACHE_HOME=str(cache), NUMBA_CACHE_DIR=str(cache / "numba"))
    env.pop("TASKRUNNER_RUNS_DIR", None)
    return env


def _run_task(args: list[str], cache: Path, cwd: Path) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "taskrunner.cli", *args], env=_env(cache),
                          cwd=cwd, capture_output=True, text=True, timeout=900)


def _record(output: str, cwd: Path) -> dict:
    line = next(text for text in output.splitlines() if text.strip().startswith("record:"))
    path = cwd / line.split("record:", 1)[1].strip()  # relative: to the run's folder
    return json.loads(path.read_text(encoding="utf-8"))


def _cache_files(cache: Path) -> dict[str, bytes]:
    """numba's index and code files under ``cache``, with their contents."""
    return {str(p.relative_to(cache)): p.read_bytes() for p in sorted(cache.rglob("*"))
            if p.suffix in (".nbi", ".nbc")}


@pytest.mark.slow
def test_a_run_on_a_fresh_cache_plans_with_coal_while_the_kernels_compile_behind_it(tmp_path):
    cache = tmp_path / "cache"
    done = _run_task(["pick_place", "--plain", "--backend", "mock", "--runs-dir", "runs"],
                     cache, tmp_path)
    assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
    # Nothing waited for: the run says why its plans use coal, and records no warm-up.
    assert COAL_NOTE in done.stdout and WARM_UP_NOTE not in done.stdout
    record = _record(done.stdout, tmp_path)
    assert record["warm_up_s"] is None
    expectations = [e["data"]["expectations"] for e in record["events"]
                    if "expectations" in e.get("data", {})]
    assert expectations and expectations[-1]["met"] is True  # collision_free among them
    lines = done.stdout.splitlines()
    note = next(k for k, text in enumerate(lines) if COAL_NOTE in text)
    first = next(k for k, text in enumerate(lines) if "task 'pick_place' on cell" in text)
    assert note < first
    # The compilation it started finishes by itself and leaves the kernels for the next run.
    env = _env(cache)
    finished = subprocess.run(
        [sys.executable, "-c", "import sys, time\n"
         "from taskrunner.planning.warmup import compiling_pid, kernels_ready\n"
         "idle = 0.0  # s with no compilation running (it may not hold its lock yet)\n"
         "while not kernels_ready() and idle < 30.0:\n"
         "    idle = 0.0 if compiling_pid() is not None else idle + 0.2\n"
         "    time.sleep(0.2)\n"
         "sys.exit(0 if kernels_ready() else 1)"],
        env=env, timeout=900)
    assert finished.returncode == 0
    assert _cache_files(cache)
    again = _run_task(["pick_place", "--plain", "--backend", "mock", "--runs-dir", "runs"],
                      cache, tmp_path)
    assert again.returncode == 0 and COAL_NOTE not in again.stdout


@pytest.mark.slow
def test_after_warm_up_a_run_compiles_nothing_and_waits_for_nothing(tmp_path):
    cache = tmp_path / "cache"
    warm = _run_task(["warm-up"], cache, tmp_path)
    assert warm.returncode == 0, warm.stdout + warm.stderr
    assert "compiling the planner's kernels" in warm.stdout
    compiled = _cache_files(cache)
    assert compiled
    again = _run_task(["warm-up"], cache, tmp_path)
    assert again.returncode == 0 and "are ready" in again.stdout
    # A robot of primitives (the servo arm) and one of meshes (the Panda).
    for task in ("pick_place", "pick_place_panda"):
        done = _run_task([task, "--plain", "--backend", "mock", "--runs-dir", "runs"],
                         cache, tmp_path)
        assert done.returncode == 0, done.stdout[-3000:] + done.stderr[-3000:]
        assert WARM_UP_NOTE not in done.stdout
        assert _record(done.stdout, tmp_path)["warm_up_s"] is None
    assert _cache_files(cache) == compiled  # no kernel compiled (or recompiled) by the runs


class _Process:
    exitcode = None
    pid = None  # no /proc entry to read: the worker's wait counts wall-clock time

    def is_alive(self) -> bool:
        return True

    def kill(self) -> None:
        pass

    def join(self, timeout: float | None = None) -> None:
        pass


@pytest.mark.parametrize("first", ["loaded", "compiling"])
def test_a_worker_says_whether_it_compiles_and_for_how_long(first: str):
    import multiprocessing as mp

    from taskrunner.planning.worker import PlanningWorker

    ours, theirs = mp.Pipe()

    def speak() -> None:
        theirs.send((first, "servo_arm", 0.1))
        time.sleep(0.05)
        theirs.send(("ready", "servo_arm", 0.15))

    threading.Thread(target=speak, daemon=True).start()
    worker = PlanningWorker.__new__(PlanningWorker)
    worker.source, worker._process, worker._conn, worker._ready = "x", _Process(), ours, False
    worker._lock, worker._start_timeout = threading.Lock(), 5.0
    told: list[bool] = []
    seconds = worker.wait_ready(on_compile=lambda: told.append(True))
    assert worker._ready and worker.model_name == "servo_arm"
    if first == "compiling":
        assert told == [True] and seconds > 0 and worker.compile_time == seconds
    else:
        assert told == [] and seconds == 0.0
