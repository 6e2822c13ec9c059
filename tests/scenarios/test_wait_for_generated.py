"""Generated two-arm tasks with ``wait_for`` on servo_arm_pair (issue 25): each arm picks
a cube near the table's middle and places it on its own side, both branches of one
``parallel``; a step of one branch (drawn: which arm, which step) waits for a step of the
other. Every run that succeeds keeps the order on the schedule's clock (the waiting
step's first motion starts when the named step's last motion has ended) and passes the
independent space-time verifier over its record; a run may instead fail cleanly, at a
step's file:line."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from taskrunner.backends.mock import MockBackend
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks import load_task
from taskrunner.tree.expect import arm_conflicts

CELL = DATA_ROOT / "robots" / "cells" / "servo_arm_pair.yaml"
CASES = 5  # every run of the suite: about 0.5 s each on mock


def generated_task(seed: int) -> tuple[str, int, int]:
    """A task drawn with ``seed``, and the lines of its waiting step and the step it
    waits for."""
    rng = np.random.default_rng(seed)
    lx, rx = -rng.uniform(0.03, 0.07), rng.uniform(0.03, 0.07)
    ly, ry = rng.uniform(-0.05, 0.05, size=2)
    dlx, drx = -rng.uniform(0.09, 0.12), rng.uniform(0.09, 0.12)
    dly, dry = rng.uniform(-0.06, 0.06, size=2)
    waiter_side = int(rng.integers(2))  # 0: the left arm's step waits, 1: the right's
    waiter_step, named_step = int(rng.integers(2)), int(rng.integers(2))  # 0 pick, 1 place
    sides = [("left_arm", "lc", dlx, dly), ("right_arm", "rc", drx, dry)]
    lines = {}
    body = []
    line = 8  # the first branch's 'sequence'
    for side, (arm, obj, x, y) in enumerate(sides):
        steps = [f"pick: {{arm: {arm}, object: {obj}, grasp: top, approach: 0.04, "
                 f"retreat: 0.04",
                 f"place: {{arm: {arm}, object: {obj}, at: {{xyz: [{x:.4f}, {y:.4f}, 0.7635]}}, "
                 f"orientation: yaw, approach: 0.04, retreat: 0.04"]
        body.append("      - sequence:\n")
        for index, text in enumerate(steps):
            line += 1
            if side == waiter_side and index == waiter_step:
                text += f", wait_for: {{step: s{1 - side}{named_step}}}"
                lines["waiter"] = line
            if side != waiter_side and index == named_step:
                lines["named"] = line
            body.append(f"          - {text}, name: s{side}{index}}}\n")
        line += 1
    task = (f"task: generated_{seed}\ncell: {CELL}\nobjects:\n"
            f"  - {{name: lc, shape: box, size: [0.025, 0.025, 0.025], "
            f"pose: {{xyz: [{lx:.4f}, {ly:.4f}, 0.7625]}}}}\n"
            f"  - {{name: rc, shape: box, size: [0.025, 0.025, 0.025], "
            f"pose: {{xyz: [{rx:.4f}, {ry:.4f}, 0.7625]}}}}\n"
            "steps:\n  - parallel:\n" + "".join(body) + "expect:\n  collision_free: true\n")
    return task, lines["waiter"], lines["named"]


def run_generated(seed: int, tmp_path: Path) -> tuple[Runner, Path, int, int]:
    text, waiter, named = generated_task(seed)
    path = tmp_path / f"generated_{seed}.yaml"
    path.write_text(text, encoding="utf-8")
    spec = load_task(path, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    backend = MockBackend(names, dict(zip(names, cell.start_state())))
    runner = Runner(spec, cell, backend, InProcessPlanner(), RunOptions(seed=seed))
    runner.run()
    return runner, path, waiter, named


def test_the_generator_writes_the_lines_it_says():
    text, waiter, named = generated_task(3)
    lines = text.splitlines()
    assert "wait_for" in lines[waiter - 1] and "wait_for" not in lines[named - 1]
    name = lines[waiter - 1].split("wait_for: {step: ")[1].split("}")[0]
    assert f"name: {name}}}" in lines[named - 1]


def assert_kept_in_order_and_apart(runner: Runner, path: Path, waiter: int, named: int
                                   ) -> None:
    record = runner.record
    if record.status != "succeeded":  # failed cleanly, at a step's file:line
        assert record.error and ".yaml:" in record.error, record.error
        return
    assert arm_conflicts(runner.scene.robot, record.events) == []
    motions = [e for e in record.events if e.kind == "motion"]
    ends = [e.data["start"] + e.data["trajectory"]["duration"] for e in motions
            if e.location == f"{path}:{named}"]
    starts = [e.data["start"] for e in motions if e.location == f"{path}:{waiter}"]
    assert ends and starts
    assert min(starts) >= max(ends) - 1e-4  # (a record rounds durations to 0.1 ms)


def test_generated_wait_for_is_kept_on_the_clock_and_the_arms_never_touch(tmp_path):
    # One test over the seeds (one warm-up): most runs succeed, so it is not vacuous.
    statuses = []
    for seed in range(CASES):
        runner, path, waiter, named = run_generated(seed, tmp_path)
        assert_kept_in_order_and_apart(runner, path, waiter, named)
        statuses.append(runner.record.status)
    assert statuses.count("succeeded") >= CASES - 1, statuses
