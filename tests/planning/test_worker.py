"""The planning worker process: same plans as in-process, scene updates, cancel, crashes."""

from __future__ import annotations

import json
import os
import signal
import time

import numpy as np
import pytest
from plan_helpers import READY, dense_states

from taskrunner.errors import PlanningCancelledError, UnknownNameError
from taskrunner.kinematics import frame_pose
from taskrunner.planning import JointGoal, MotionPlanner, PlannerOptions, PlanRequest
from taskrunner.planning.timing import TimingOptions, parameterize_path
from taskrunner.planning.worker import PlanningWorker, WorkerDiedError
from taskrunner.shapes import Box
from taskrunner.types import Pose

GOAL = JointGoal({**READY, "panda_joint1": 1.2, "panda_joint2": 0.2, "panda_joint4": -1.8})


@pytest.fixture(scope="module")
def worker(robots_dir, example_robot_data):
    with PlanningWorker(robots_dir / "panda") as w:
        yield w


@pytest.fixture
def scene(shelf_scene):
    return shelf_scene  # the Panda at 'ready' before a table and a shelf (conftest)


def test_worker_plans_the_same_path_as_in_process(worker, scene):
    expected = MotionPlanner(scene).plan(PlanRequest("arm", GOAL))
    result = worker.plan(scene, PlanRequest("arm", GOAL))
    assert np.array_equal(result.path.waypoints, expected.path.waypoints)
    assert worker.model_name == "panda"


def test_the_worker_times_the_path_when_asked_as_toppra_would_here(worker, scene):
    timing = TimingOptions(velocity_scaling=0.5)
    result = worker.plan(scene, PlanRequest("arm", GOAL, timing=timing))
    assert worker.plan(scene, PlanRequest("arm", GOAL)).trajectory is None
    expected = parameterize_path(scene.robot, result.path, timing)
    assert result.trajectory is not None
    assert result.trajectory.names == expected.names
    assert np.array_equal(result.trajectory.times, expected.times)
    assert np.array_equal(result.trajectory.positions, expected.positions)
    assert np.array_equal(result.trajectory.velocities, expected.velocities)
    encoded = worker.plan(scene, PlanRequest("arm", GOAL, timing=timing,
                                             trajectory_json=True)).trajectory_json
    assert encoded is not None and result.trajectory_json is None
    decoded = json.loads(encoded)
    assert np.array_equal(decoded["times"], expected.times)
    assert np.array_equal(decoded["positions"], expected.positions)  # exact round trip
    assert np.array_equal(decoded["velocities"], expected.velocities)


def test_scene_edits_reach_the_worker(worker, scene):
    first = worker.plan(scene, PlanRequest("arm", GOAL))
    # A post right on the first path's midpoint: the next plan must go around it.
    along = dense_states(scene, first)
    q = along[len(along) // 2]
    hand = frame_pose(scene.robot, q, "panda_hand").translation
    scene.add_object("post", Box((0.06, 0.06, 0.06)), Pose(tuple(hand)))
    assert scene.in_collision(q) and not scene.in_collision()
    second = worker.plan(scene, PlanRequest("arm", GOAL))
    assert not any(scene.in_collision(s) for s in dense_states(scene, second))


def test_a_scene_made_where_a_freed_one_was_reaches_the_worker(worker, panda_model):
    # The worker is sent a scene's objects when they differ from those it holds: by
    # content, not by the scene's id() and revision, which a new scene made at a freed
    # one's address, edited as often, shares.
    import gc

    from taskrunner.scene import Scene

    first = Scene(panda_model)
    first.set_state(READY)
    first.add_object("post", Box((0.06, 0.06, 0.06)), Pose((1.5, 1.5, 0.0)))  # far away
    path = worker.plan(first, PlanRequest("arm", GOAL))
    along = dense_states(first, path)
    q = along[len(along) // 2]
    hand = tuple(frame_pose(first.robot, q, "panda_hand").translation)
    address, revision = id(first), first.revision
    del first
    gc.collect()
    held = []  # allocated until one lands where the first scene was
    for _ in range(100_000):
        held.append(Scene.__new__(Scene))
        if id(held[-1]) == address:
            break
    second = held.pop()
    assert id(second) == address, "no scene was made at the freed one's address"
    second.__init__(panda_model)  # type: ignore[misc]
    second.set_state(READY)
    second.add_object("post", Box((0.06, 0.06, 0.06)), Pose(hand))  # on the first path
    assert second.revision == revision and second.in_collision(q)
    around = worker.plan(second, PlanRequest("arm", GOAL))
    assert not any(second.in_collision(s) for s in dense_states(second, around))


def test_submit_returns_at_once_and_the_caller_keeps_running(worker, scene):
    request = PlanRequest("arm", GOAL, options=PlannerOptions(
        planner="RRTstar", refine=True, planning_time=0.6, direct=False))
    started = time.perf_counter()
    handle = worker.submit(scene, request)
    assert time.perf_counter() - started < 0.2
    assert not handle.done()
    ticks = 0
    while not handle.done():
        ticks += 1
        time.sleep(0.01)
    assert ticks > 20  # this thread ran all along
    assert handle.result().planner == "RRTstar"


def test_cancel_stops_an_in_flight_plan_quickly(worker, scene):
    request = PlanRequest("arm", GOAL, options=PlannerOptions(
        planner="RRTstar", refine=True, planning_time=30.0, direct=False))
    handle = worker.submit(scene, request)
    time.sleep(0.2)
    cancelled_at = time.perf_counter()
    handle.cancel()
    with pytest.raises(PlanningCancelledError):
        handle.result(timeout=10.0)
    assert time.perf_counter() - cancelled_at < 1.0
    # The worker serves the next request normally.
    assert worker.plan(scene, PlanRequest("arm", GOAL)).path.names[0] == "panda_joint1"


def test_errors_come_back_with_their_class_and_message(worker, scene):
    with pytest.raises(UnknownNameError, match="unknown group 'amr'"):
        worker.plan(scene, PlanRequest("amr", GOAL))


def test_a_killed_worker_is_reported_and_restarted(robots_dir, scene, example_robot_data):
    with PlanningWorker(robots_dir / "panda") as worker:
        handle = worker.submit(scene, PlanRequest("arm", GOAL, options=PlannerOptions(
            planner="RRTstar", refine=True, planning_time=30.0, direct=False)))
        time.sleep(0.2)
        os.kill(worker._process.pid, signal.SIGKILL)
        with pytest.raises(WorkerDiedError, match="died"):
            handle.result(timeout=10.0)
        assert worker.plan(scene, PlanRequest("arm", GOAL)).path.names[0] == "panda_joint1"


def test_a_worker_on_a_bad_file_fails_to_start_with_the_files_error(tmp_path):
    bad = tmp_path / "cell.yaml"
    bad.write_text("name: x\nrobots: []\n")
    with pytest.raises(Exception, match=r"cell.yaml:2: robots"):
        PlanningWorker(bad)


@pytest.mark.skipif(not hasattr(os, "getpriority"), reason="Unix priorities")
def test_a_worker_can_run_at_a_lower_cpu_priority(robots_dir, example_robot_data):
    own = os.getpriority(os.PRIO_PROCESS, 0)
    with PlanningWorker(robots_dir / "panda", nice=5) as worker:
        assert os.getpriority(os.PRIO_PROCESS, worker._process.pid) == min(own + 5, 19)
        assert worker.nice == 5


@pytest.mark.parametrize("nice", [-1, 20, 1.5, True])
def test_a_workers_niceness_must_be_an_integer_from_0_to_19(tmp_path, nice):
    with pytest.raises(ValueError, match="'nice' must be an integer from 0 to 19"):
        PlanningWorker(tmp_path / "never-loaded", nice=nice)


class _Process:
    """Stands in for a worker process that another thread speaks for."""

    exitcode = None
    pid = None  # no /proc entry to read: wall-clock time counts

    def is_alive(self) -> bool:
        return True

    def kill(self) -> None:
        self.killed = True

    def join(self, timeout: float | None = None) -> None:
        pass


@pytest.mark.parametrize("warm_up", [0.0, 0.6])
def test_a_loaded_worker_may_take_longer_to_warm_up_than_to_load(warm_up: float):
    # The start timeout bounds the load; a worker that reported "loaded" is compiling
    # its verifier's kernels (once per machine) and is waited for.
    import multiprocessing as mp
    import threading

    from taskrunner.planning import worker as worker_module

    ours, theirs = mp.Pipe()

    def speak() -> None:
        theirs.send(("loaded", "panda", 0.1))
        time.sleep(warm_up)
        theirs.send(("ready", "panda", 0.1 + warm_up))

    threading.Thread(target=speak, daemon=True).start()
    worker = worker_module.PlanningWorker.__new__(worker_module.PlanningWorker)
    worker.source, worker._process, worker._conn, worker._ready = "panda", _Process(), ours, False
    worker._await_ready(0.3)
    assert worker._ready and worker.model_name == "panda"


def test_a_worker_that_never_loads_is_reported():
    import multiprocessing as mp

    from taskrunner.planning import worker as worker_module

    ours, _theirs = mp.Pipe()
    worker = worker_module.PlanningWorker.__new__(worker_module.PlanningWorker)
    worker.source, worker._process, worker._conn, worker._ready = "panda", _Process(), ours, False
    with pytest.raises(WorkerDiedError, match=r"did not load for panda: no answer in 0.2 s"):
        worker._await_ready(0.2)
    assert worker._process.killed


_SPIN = "import time\nwhile True:\n    t = time.process_time() + {busy}\n" \
        "    while time.process_time() < t: pass\n    time.sleep({idle})\n"


@pytest.mark.parametrize(("busy", "idle", "said"), [
    (0.0, 60.0, r"it used no CPU time for 0.3 s \(stuck\?\)"),  # asleep: stuck
    (60.0, 0.0, r"it used 0.3 s of CPU time"),                    # a runaway load
])
def test_a_starting_worker_is_judged_by_its_cpu_time(busy: float, idle: float, said: str):
    import multiprocessing as mp
    import subprocess
    import sys

    from taskrunner.planning import worker as worker_module

    ours, _theirs = mp.Pipe()
    process = subprocess.Popen([sys.executable, "-c", _SPIN.format(busy=busy, idle=idle)])
    worker = worker_module.PlanningWorker.__new__(worker_module.PlanningWorker)
    worker.source, worker._process, worker._conn, worker._ready = "panda", process, ours, False
    try:
        with pytest.raises(WorkerDiedError, match="did not load for panda: " + said):
            worker._await_ready(0.3)
    finally:
        process.kill()
        process.wait()


def test_a_starved_worker_that_keeps_working_is_waited_for():
    # It uses a tenth of a core at most (as at nice 10 beside busy processes) and answers
    # after 3 times its limit of wall time, having used less than its limit of CPU time.
    import multiprocessing as mp
    import subprocess
    import sys
    import threading

    from taskrunner.planning import worker as worker_module

    ours, theirs = mp.Pipe()
    process = subprocess.Popen([sys.executable, "-c", _SPIN.format(busy=0.01, idle=0.09)])

    def speak() -> None:
        time.sleep(3.0)
        theirs.send(("ready", "panda", 3.0))

    threading.Thread(target=speak, daemon=True).start()
    worker = worker_module.PlanningWorker.__new__(worker_module.PlanningWorker)
    worker.source, worker._process, worker._conn, worker._ready = "panda", process, ours, False
    try:
        worker._await_ready(1.0)
    finally:
        process.kill()
        process.wait()
    assert worker._ready and worker.model_name == "panda"


def _open_fds() -> dict[int, str]:
    """This process's open descriptors and what each is (the listing's own left out)."""
    found = {}
    for name in os.listdir("/proc/self/fd"):
        try:
            found[int(name)] = os.readlink(f"/proc/self/fd/{name}")
        except FileNotFoundError:  # the listing's own descriptor, closed since
            pass
    return found


def test_a_closed_worker_keeps_no_descriptor_and_starts_again_when_asked(
        robots_dir, scene, example_robot_data):
    # multiprocessing's shared-memory arena and resource tracker are made once per process
    # (the first worker's cancel flag): open them first, then count.
    PlanningWorker(robots_dir / "panda", wait_ready=False).close()
    before = _open_fds()
    worker = PlanningWorker(robots_dir / "panda")
    worker.plan(scene, PlanRequest("arm", GOAL))
    assert len(_open_fds()) > len(before)  # its pipe and its process's sentinel
    worker.close()
    worker.close()  # idempotent
    # The object is still referenced: nothing of its process is left open all the same.
    assert _open_fds().items() <= before.items()
    assert worker.plan(scene, PlanRequest("arm", GOAL)).path.names[0] == "panda_joint1"
    worker.close()
    assert _open_fds().items() <= before.items()
