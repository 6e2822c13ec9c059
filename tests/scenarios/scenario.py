"""Running an example task on the mock backend and checking what it did.

``run_scenario`` runs a task file to the end (planning in-process, motions replayed
instantly by the mock backend) and returns the runner; the ``assert_*`` helpers check the
promises every scenario keeps: no executed trajectory collides (every sample re-checked
in the scene as it was when that motion started), every joint stayed within its limits,
the run record is complete, objects end where the task put them, and a carried object is
held by exactly one gripper at every moment.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pinocchio as pin

from taskrunner.backends.mock import MockBackend
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.records import load_record
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.scene import Scene
from taskrunner.tasks import load_task

TASKS = DATA_ROOT / "tasks"


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


def object_pose(runner: Runner, name: str) -> pin.SE3:
    """World pose of object ``name`` at the end of the run."""
    return runner.scene.object_pose(name).se3


def holders(runner: Runner, name: str) -> list[str | None]:
    """The link object ``name`` was attached to when each executed motion started (None:
    lying in the world), from the scene snapshots of the run's executed motions."""
    out = []
    for motion in runner.ctx.executed:
        entries = [o for o in motion.scene.objects if o.name == name]
        assert len(entries) == 1, f"{motion.node}: {len(entries)} objects named {name!r}"
        out.append(entries[0].attached_to)
    return out


def assert_held_by_one_gripper(runner: Runner, name: str, grippers: list[str]) -> list[str]:
    """Object ``name`` lies in the world before it is picked and after it is put down, and
    is attached to exactly one of ``grippers`` (grasp frames) at every moment in between,
    passed from one to the next in that order. Returns the grippers that held it in turn."""
    held = holders(runner, name)
    first = next(i for i, h in enumerate(held) if h is not None)
    last = max(i for i, h in enumerate(held) if h is not None)
    assert all(h is None for h in held[:first]) and all(h is None for h in held[last + 1:])
    between = held[first:last + 1]
    assert None not in between, (
        f"{name!r} was let go between motions {first} and {last}: {between}")
    turns = [h for i, h in enumerate(between) if i == 0 or h != between[i - 1]]
    assert turns == grippers, f"{name!r} was held by {turns}, expected {grippers}"
    return turns


def group_at(runner: Runner, group: str, pose: str) -> bool:
    """Whether ``group`` ends the run at its named pose (within 1e-6 rad)."""
    model = runner.scene.robot
    target = model.named_state(group, pose)
    return bool(np.allclose(runner.scene.state[model.indices(target.names)], target.positions,
                            atol=1e-6))
