"""The search's state and edge checks give the scene checker's verdicts (the compiled
segment scan included, also before the fractions' table has the rows it needs)."""

from __future__ import annotations

import numpy as np
import pytest

from taskrunner.planning import edge_order
from taskrunner.planning.edge_order import bisection_order
from taskrunner.planning.planner import MotionPlanner


@pytest.mark.parametrize("fresh_table", [True, False])
def test_state_and_edge_checks_are_the_checkers(shelf_scene, monkeypatch, fresh_table) -> None:
    if fresh_table:  # as in a new process: no row filled yet
        monkeypatch.setattr(edge_order, "FRACTIONS", np.zeros_like(edge_order.FRACTIONS))
    scene = shelf_scene
    robot = scene.robot
    group = robot.group("arm")
    idx = group.joint_indices
    start = scene.state.copy()
    planner = MotionPlanner(scene)
    resolution = 0.05
    state_valid, edge_valid, count = planner._checks(group, start, resolution)
    rng = np.random.default_rng(4)
    verdicts = {True: 0, False: 0}
    for _ in range(150):
        q = robot.random_state(rng, "arm", base=start)
        want = not scene.in_collision(q)
        assert state_valid(q[idx]) == want
        verdicts[want] += 1
    assert min(verdicts.values()) > 10
    edges = {True: 0, False: 0}
    for _ in range(60):
        a = robot.random_state(rng, "arm", base=start)
        if scene.in_collision(a):
            continue
        b = a.copy()
        b[idx] = a[idx] + rng.uniform(-1.0, 1.0, len(idx))
        b = np.clip(b, robot.lower, robot.upper)
        steps = max(1, int(np.ceil(np.max(np.abs(b[idx] - a[idx])) / resolution)))
        fractions = np.concatenate([[1.0], bisection_order(steps) / steps])
        states = [b if f == 1.0 else a + f * (b - a) for f in fractions]
        want = not any(scene.in_collision(q) for q in states)
        before = count[0]
        assert edge_valid(a[idx], b[idx]) == want
        assert count[0] > before
        edges[want] += 1
    assert min(edges.values()) > 5
