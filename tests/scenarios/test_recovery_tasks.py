"""Scenario test of a task that recovers from a failed step (tasks/fallback_place.yaml)."""

from __future__ import annotations

import numpy as np
from scenario import (
    TASKS,
    assert_held_by_one_gripper,
    assert_no_executed_motion_collides,
    assert_record_complete,
    group_at,
    object_pose,
    run_scenario,
)


def line_of(path, text: str) -> int:
    """1-based line of the first line of ``path`` containing ``text``."""
    lines = path.read_text(encoding="utf-8").splitlines()
    return next(i for i, line in enumerate(lines, 1) if text in line)


def test_fallback_place_reports_the_blocked_spot_and_uses_the_spare_one(tmp_path):
    runner = run_scenario("fallback_place.yaml", tmp_path)
    assert_record_complete(runner)
    path = TASKS / "fallback_place.yaml"
    where = f"{path}:{line_of(path, 'place on the first spot')}"
    # The first branch failed: its target is occupied by the crate, found before the arm
    # moved (as run-task check finds it), at the file:line of that place step.
    failed = [e for e in runner.record.events
              if e.kind == "node_finished" and e.status == "FAILURE"]
    assert len(failed) == 1
    assert failed[0].node == "place on the first spot: target free"
    assert failed[0].location == where
    assert failed[0].message.startswith(f"{where}: target occupied by 'crate'")
    assert not [m for m in runner.ctx.executed if "first spot" in m.node]
    # The second branch put the cube on the spare spot; the run succeeded.
    assert runner.record.status == "succeeded" and runner.record.error is None
    cube = object_pose(runner, "cube")
    assert np.linalg.norm(cube.translation - np.array([0.5, -0.28, 0.771])) < 0.002
    assert_held_by_one_gripper(runner, "cube", ["panda_hand_tcp"])
    assert group_at(runner, "arm", "ready")
    assert assert_no_executed_motion_collides(runner) > 300
