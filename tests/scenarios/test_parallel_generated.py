"""Generated two-arm tasks on servo_arm_pair (issue 25): each arm picks a cube near the
table's middle and places it elsewhere on its own side, both branches of one
``parallel``, the workspaces overlapping. Every run that reports success must pass the
independent space-time verifier over its record (0 contacts between the arms); a run
may instead fail cleanly (a step refused by the schedule, a place out of reach)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from taskrunner.backends.mock import MockBackend
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks import load_task
from taskrunner.tree.expect import arm_conflicts

CELL = DATA_ROOT / "robots" / "cells" / "servo_arm_pair.yaml"
QUICK = 20   # cases in every run of the suite
SLOW = 60    # more behind the slow marker


def generated_task(seed: int) -> str:
    """A two-arm task, its cubes and drop spots drawn with ``seed``: the cubes 2-7 cm
    from the table's middle, the drop spots 8-12 cm out on each arm's side."""
    rng = np.random.default_rng(seed)
    lx, rx = -rng.uniform(0.02, 0.07), rng.uniform(0.02, 0.07)
    ly, ry = rng.uniform(-0.05, 0.05, size=2)
    dlx, drx = -rng.uniform(0.08, 0.12), rng.uniform(0.08, 0.12)
    dly, dry = rng.uniform(-0.06, 0.06, size=2)
    order = rng.permutation(2)  # which branch comes first in the file
    branches = [
        f"""      - sequence:
          - pick: {{arm: left_arm, object: lc, grasp: top, approach: 0.04, retreat: 0.04}}
          - place: {{arm: left_arm, object: lc, at: {{xyz: [{dlx:.4f}, {dly:.4f}, 0.7635]}}, orientation: yaw, approach: 0.04, retreat: 0.04}}
""",
        f"""      - sequence:
          - pick: {{arm: right_arm, object: rc, grasp: top, approach: 0.04, retreat: 0.04}}
          - place: {{arm: right_arm, object: rc, at: {{xyz: [{drx:.4f}, {dry:.4f}, 0.7635]}}, orientation: yaw, approach: 0.04, retreat: 0.04}}
"""]
    return f"""task: generated_{seed}
cell: {CELL}
objects:
  - {{name: lc, shape: box, size: [0.025, 0.025, 0.025], pose: {{xyz: [{lx:.4f}, {ly:.4f}, 0.7625]}}}}
  - {{name: rc, shape: box, size: [0.025, 0.025, 0.025], pose: {{xyz: [{rx:.4f}, {ry:.4f}, 0.7625]}}}}
steps:
  - parallel:
{branches[order[0]]}{branches[order[1]]}expect:
  collision_free: true
"""


def run_generated(seed: int, tmp_path: Path, replans: bool = True) -> Runner:
    """Generated task ``seed`` on the mock backend (``replans``: the schedule's)."""
    path = tmp_path / f"generated_{seed}.yaml"
    path.write_text(generated_task(seed), encoding="utf-8")
    spec = load_task(path, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = MockBackend(names, dict(zip(names, cell.start_state())))
    runner = Runner(spec, cell, backend, InProcessPlanner(), RunOptions(seed=seed))
    runner.ctx.schedule.replans = replans
    runner.run()
    return runner


def assert_no_contact_when_succeeded(runner: Runner) -> None:
    record = runner.record
    motions = [e for e in record.events if e.kind == "motion"]
    assert all(e.data.get("lane") for e in motions)  # every motion is of a branch
    misses = arm_conflicts(runner.scene.robot, record.events)
    if record.status == "succeeded":
        assert not misses, misses
    else:  # failed cleanly, at a step's file:line
        assert record.error and ".yaml:" in record.error, record.error


@pytest.mark.parametrize("seed", range(QUICK))
def test_generated_two_arm_task_never_succeeds_with_the_arms_touching(seed, tmp_path):
    assert_no_contact_when_succeeded(run_generated(seed, tmp_path))


@pytest.mark.slow
@pytest.mark.parametrize("seed", range(QUICK, QUICK + SLOW))
def test_more_generated_two_arm_tasks(seed, tmp_path):
    assert_no_contact_when_succeeded(run_generated(seed, tmp_path))


def test_most_generated_tasks_succeed_and_some_wait(tmp_path):
    """The suite is not vacuous: most runs succeed, and the arms do meet (waits)."""
    runners = [run_generated(seed, tmp_path) for seed in range(6)]
    succeeded = [r for r in runners if r.record.status == "succeeded"]
    assert len(succeeded) >= 4, [r.record.error for r in runners]
    assert any(e.kind == "wait" for r in succeeded for e in r.record.events)
