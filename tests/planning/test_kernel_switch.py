"""A planner whose compiled kernels are not in the cache plans with coal alone while they
compile in the background, and with them once they are in: the same plans either way."""

from __future__ import annotations

import numpy as np
import pytest
from plan_helpers import dense_states

from taskrunner.planning import JointGoal, MotionPlanner, PlanRequest
from taskrunner.planning.timing import TimingOptions
from taskrunner.planning.warmup import CompiledKernels

# Reached around the shelf by a search (the straight line is blocked).
GOAL = JointGoal({"panda_joint1": 1.038, "panda_joint2": 1.305, "panda_joint3": -1.58,
                  "panda_joint4": -0.384, "panda_joint5": 2.157, "panda_joint6": 0.052,
                  "panda_joint7": 1.202})


def _request() -> PlanRequest:
    return PlanRequest("arm", GOAL, timing=TimingOptions())


def test_plans_use_coal_while_the_kernels_compile_and_the_kernels_after(shelf_scene, monkeypatch):
    compiled_in = [False]
    started: list[str] = []
    kernels = CompiledKernels(ready=lambda: compiled_in[0],
                              start=lambda: started.append("compile") or None)
    planner = MotionPlanner(shelf_scene)
    expected = MotionPlanner(shelf_scene.copy()).plan(_request())  # kernels from the start
    assert not expected.direct and expected.searches >= 1

    assert kernels.prepare(planner) is False
    assert started == ["compile"] and planner.compiled is False
    # While they compile, nothing of the compiled checks is touched.
    with monkeypatch.context() as patch:
        for name in ("path_verifier", "state_screen"):
            patch.setattr(type(shelf_scene), name, _refuse(name))
        assert kernels.update(planner) is False
        on_coal = planner.plan(_request())
    assert on_coal.compiled is False and on_coal.verify_queries > 0
    # Exactly verified: free at every state along it, as the checker says.
    assert shelf_scene.checker.first_in_collision(
        shelf_scene.robot.to_pin(dense_states(shelf_scene, on_coal))) == -1

    compiled_in[0] = True
    assert kernels.update(planner) is True and planner.compiled is True
    after = planner.plan(_request())
    assert after.compiled is True and started == ["compile"]
    # The same search verdicts on both: the same path and trajectory, bit for bit.
    for result in (on_coal, after):
        assert np.array_equal(result.path.waypoints, expected.path.waypoints)
        assert result.trajectory is not None and expected.trajectory is not None
        assert np.array_equal(result.trajectory.positions, expected.trajectory.positions)
        assert np.array_equal(result.trajectory.times, expected.trajectory.times)


def test_a_planner_loads_kernels_that_are_compiled_and_starts_no_compilation(shelf_scene):
    started: list[str] = []
    kernels = CompiledKernels(ready=lambda: True, start=lambda: started.append("x") or None)
    planner = MotionPlanner(shelf_scene, compiled=False)
    assert kernels.prepare(planner) is True and planner.compiled is True and started == []
    assert kernels.process is None


def _refuse(name: str):  # type: ignore[no-untyped-def]
    def refuse(*args: object, **kwargs: object) -> None:
        pytest.fail(f"Scene.{name} (compiled kernels) used while they compile")

    return refuse


def test_a_failed_background_compilation_is_logged_and_planning_goes_on_with_coal(
        shelf_scene, caplog):
    import subprocess
    import sys

    failing = subprocess.Popen([sys.executable, "-c", "raise SystemExit(3)"])
    kernels = CompiledKernels(ready=lambda: False, start=lambda: failing)
    planner = MotionPlanner(shelf_scene)
    assert kernels.prepare(planner) is False
    failing.wait()
    with caplog.at_level("WARNING", logger="taskrunner.planning.warmup"):
        assert kernels.update(planner) is False
        assert kernels.update(planner) is False  # said once
    said = [r.getMessage() for r in caplog.records if "background compilation" in r.getMessage()]
    assert len(said) == 1 and "exit code 3" in said[0]
    assert planner.compiled is False and kernels.process is None


def test_one_compilation_per_cache_its_process_found_by_its_lock(tmp_path, monkeypatch):
    import subprocess
    import sys

    from taskrunner.planning.warmup import compile_in_background, compiling_pid

    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path))
    assert compiling_pid() is None
    # A process holding the cache's lock as the background compilation does.
    holder = subprocess.Popen(
        [sys.executable, "-c",
         "import fcntl, os, sys\n"
         "handle = open(sys.argv[1], 'a+b')\n"
         "fcntl.flock(handle, fcntl.LOCK_EX)\n"
         "handle.truncate(0); handle.write(str(os.getpid()).encode()); handle.flush()\n"
         "print('held', flush=True)\n"
         "sys.stdin.read()\n",
         str(tmp_path / "compiling.lock")],
        stdin=subprocess.PIPE, stdout=subprocess.PIPE, text=True)
    try:
        assert holder.stdout is not None and holder.stdout.readline().strip() == "held"
        assert compiling_pid() == holder.pid
        assert compile_in_background() is None  # no second compilation into this cache
    finally:
        holder.communicate("", timeout=10)
    assert compiling_pid() is None
