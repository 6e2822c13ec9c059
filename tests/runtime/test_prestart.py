"""The planning worker started before the run (taskrunner.runtime.prestart): which cell
a task file names, adoption by the run's worker, and stopping an early process nobody
needs."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from taskrunner.planning import JointGoal, PlanRequest
from taskrunner.planning.worker import PlanningWorker
from taskrunner.resources import resolve_cell, resolve_task
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.prestart import EarlyWorker, start_worker_early, task_cell
from taskrunner.scene import scene_from_cell


def _task(tmp_path: Path, text: str) -> Path:
    path = tmp_path / "tasks" / "t.yaml"
    path.parent.mkdir(exist_ok=True)
    path.write_text(text, encoding="utf-8")
    return path


def test_task_cell_reads_a_plain_cell_path_relative_to_the_task(tmp_path):
    cell = tmp_path / "cells" / "c.yaml"
    cell.parent.mkdir()
    cell.write_text("name: c\n", encoding="utf-8")
    assert task_cell(_task(tmp_path, "task: t\ncell: ../cells/c.yaml\nsteps: []\n")) == cell
    assert task_cell(_task(tmp_path, f"task: t\ncell: {cell}\n")) == cell
    assert task_cell(resolve_task("pick_place")) == resolve_cell("servo_arm_table").resolve()


@pytest.mark.parametrize("text", [
    "task: t\ncell: ../cells/missing.yaml\n",  # no such file
    "task: t\ncell: ${which}\nparameters: {which: {default: x}}\n",  # the loader's work
    "task: t\n",  # no cell
    "- a list\n- not a task\n",
    "task: [unclosed\n",  # not YAML
    "cell: 3\n",
])
def test_task_cell_leaves_everything_else_to_the_loader(tmp_path, text):
    assert task_cell(_task(tmp_path, text)) is None


def test_a_task_file_that_does_not_exist_starts_nothing(tmp_path):
    assert start_worker_early(tmp_path / "nope.yaml") is None


@pytest.mark.slow
def test_the_run_adopts_the_early_worker_and_plans_with_it():
    cell_path = resolve_cell("servo_arm_table").resolve()
    early = start_worker_early(resolve_task("pick_place"))
    assert isinstance(early, EarlyWorker) and early.source == cell_path
    process = early.process
    started = early.take(cell_path)
    assert started is not None and started[0] is process
    assert early.take(cell_path) is None  # taken once
    early.close()  # a no-op once adopted
    assert process.is_alive()
    pid = process.pid
    with PlanningWorker(cell_path, started=started) as worker:
        cell = load_cell(cell_path)
        scene = scene_from_cell(cell)
        group = cell.model.group("arm")
        home = dict(zip(group.joint_names, scene.state[group.joint_indices]))
        goal = {name: value + 0.2 for name, value in home.items()}
        result = worker.plan(scene, PlanRequest("arm", JointGoal(goal)))
        assert worker.load_time > 0
        assert np.allclose(result.path.waypoints[-1][group.joint_indices],
                           list(goal.values()), atol=1e-9)
    # Stopped and reaped by the worker's close (which also let go of its handle).
    assert not Path(f"/proc/{pid}").exists()


@pytest.mark.slow
def test_an_early_worker_on_another_cell_is_stopped(tmp_path):
    early = EarlyWorker(resolve_cell("servo_arm_table").resolve())
    assert early.take(tmp_path / "other.yaml") is None
    assert not early.process.is_alive()
    early.close()  # idempotent


def test_run_task_starts_its_worker_before_importing_the_robot_loaders():
    """What the command line imports before the early worker starts stays light."""
    import subprocess
    import sys

    code = (
        "import sys\n"
        "import taskrunner.runtime.prestart as prestart\n"
        "seen = []\n"
        "given = []\n"
        "class Stop(Exception): pass\n"
        "def early(path, options=None):\n"
        "    given.append(options)\n"
        "    seen.extend(m for m in ('taskrunner.robot.build', 'taskrunner.robot.cell',\n"
        "                            'taskrunner.tasks', 'pinocchio',\n"
        "                            'scipy', 'pydantic') if m in sys.modules)\n"
        "    raise Stop\n"
        "prestart.start_worker_early = early\n"
        "from taskrunner.cli import main\n"
        "try:\n"
        "    main(['pick_place', '--strict'])\n"
        "except Stop:\n"
        "    print('imported before:', seen, 'strict:', given[0].strict)\n"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          timeout=120)
    assert done.stdout.strip() == "imported before: [] strict: True", done.stdout + done.stderr


def test_with_other_threads_running_the_early_worker_is_spawned():
    """fork only from a process with one thread (a forked child gets no copy of the other
    threads, and whatever locks they held stay held there)."""
    import threading

    release = threading.Event()
    other = threading.Thread(target=release.wait, daemon=True)
    other.start()
    try:
        early = EarlyWorker(resolve_cell("servo_arm_table").resolve())
        try:
            assert early.start_method == "spawn"
        finally:
            early.close()
    finally:
        release.set()
        other.join()
    assert not early.process.is_alive()


@pytest.mark.slow
def test_a_forked_early_worker_ends_when_its_parent_dies(tmp_path):
    """The forked child closes its copy of the parent's end of the pipe: when run-task is
    killed outright, the worker sees the pipe close and ends instead of waiting forever."""
    import os
    import subprocess
    import sys
    import time

    code = (
        "import os, sys\n"
        "from taskrunner.resources import resolve_cell\n"
        "from taskrunner.runtime.prestart import EarlyWorker\n"
        "early = EarlyWorker(resolve_cell('servo_arm_table').resolve())\n"
        "ready = 'loaded'\n"
        "while ready == 'loaded' and early.conn.poll(120):\n"  # loaded, then warmed up
        "    ready = early.conn.recv()[0]\n"
        "print(early.start_method, early.process.pid, ready, flush=True)\n"
        "os._exit(0)\n"  # no atexit, no close(): as if killed
    )
    # The worker inherits stdout: read the one line, not to the end.
    parent = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    assert parent.stdout is not None
    with parent.stdout:
        line = parent.stdout.readline()
    assert parent.wait(timeout=180) == 0
    method, pid, ready = line.split()
    assert (method, ready) == ("fork", "ready"), line

    def alive(pid: int) -> bool:
        try:
            with open(f"/proc/{pid}/stat", encoding="ascii") as stat:
                return stat.read().rsplit(")", 1)[1].split()[0] != "Z"
        except FileNotFoundError:
            return False

    deadline = time.monotonic() + 30
    while alive(int(pid)) and time.monotonic() < deadline:
        time.sleep(0.05)
    if alive(int(pid)):
        os.kill(int(pid), 9)
        pytest.fail("the orphaned worker kept waiting on its pipe")
