"""Running an example task on the mock backend and checking what it did.

``run_scenario`` runs a task file to the end (planning in-process, motions replayed
instantly by the mock backend) and returns the runner; the ``assert_*`` helpers check the
promises every scenario keeps: no executed trajectory collides (every sample re-checked
in the scene as it was when that motion started), every joint stayed within its limits,
the run record is complete, and objects end where the task put them.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from taskrunner.backends.mock import MockBackend
from taskrunner.planning.service import InProcessPlanner
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.records import load_record
from taskrunner.runtime.runner import RunOptions, Runner
from taskrunner.scene import Scene
from taskrunner.tasks import load_task

TASKS = Path(__file__).resolve().parents[2] / "tasks"


def run_scenario(name: str, tmp_path: Path, parameters: dict | None = None,
                 seed: int = 0) -> Runner:
    spec = load_task(TASKS / name, parameters or {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = MockBackend(names, dict(zip(names, cell.start_state())))
    runner = Runner(spec, cell, backend, InProcessPlanner(),
                    RunOptions(seed=seed, runs_dir=tmp_path / "runs"))
    runner.run()
    return runner


def assert_no_executed_motion_collides(runner: Runner) -> int:
    """Re-check every sample of every executed trajectory; returns the samples checked."""
    model = runner.scene.robot
    scene = Scene(model)
    checked = 0
    for motion in runner.ctx.executed:
        scene.restore(motion.scene)
        base = scene.state
        idx = model.indices(motion.trajectory.names)
        for t, values in zip(motion.trajectory.times, motion.trajectory.positions):
            q = base.copy()
            q[idx] = values
            model.apply_mimic(q)
            assert model.within_limits(q, 1e-6), (
                f"{motion.location} ({motion.node}) at t={t:.2f}s: "
                + "; ".join(model.limit_violations(q, 1e-6)))
            if scene.in_collision(q):
                pairs = ", ".join(f"{c.a}–{c.b}" for c in scene.collisions(q))
                raise AssertionError(f"{motion.location} ({motion.node}) collides at "
                                     f"t={t:.2f}s: {pairs}")
            checked += 1
    return checked


def assert_record_complete(runner: Runner, status: str = "succeeded") -> None:
    record = runner.record
    assert record.status == status, record.error
    kinds = [e.kind for e in record.events]
    assert kinds[0] == "run_started" and kinds[-1] == "run_finished"
    started = [e.node for e in record.events if e.kind == "node_started"]
    finished = [e.node for e in record.events if e.kind == "node_finished"]
    assert sorted(started) == sorted(finished)
    assert all(e.location for e in record.events if e.kind == "node_started")
    assert [e.seq for e in record.events] == list(range(1, len(record.events) + 1))
    on_disk = load_record(runner.options.runs_dir / f"{record.run_id}.json")
    assert on_disk.as_dict() == record.as_dict()
    assert on_disk.task_text.startswith("#") or on_disk.task_text.startswith("task:")


def object_position(runner: Runner, name: str) -> np.ndarray:
    return np.array(runner.scene.object_pose(name).xyz)
