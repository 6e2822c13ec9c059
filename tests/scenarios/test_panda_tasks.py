"""Scenario tests of the Panda's example tasks (tasks/pick_place_panda.yaml, stack.yaml)."""

from __future__ import annotations

import math

import numpy as np
import pytest
from scenario import (
    assert_held_by_one_gripper,
    assert_no_executed_motion_collides,
    assert_record_complete,
    group_at,
    object_pose,
    run_scenario,
)

# The Panda plans full poses: objects land within this of their target (m).
TOLERANCE = 0.002


def yaw_mod(rotation: np.ndarray, period: float) -> float:
    """The yaw of an upright object's x axis, modulo ``period`` (rad), in [0, period)."""
    return math.atan2(rotation[1, 0], rotation[0, 0]) % period


@pytest.mark.parametrize("params", [{}, {"pick_y": "-0.1", "place_x": "0.6", "place_y": "0.2"}])
def test_pick_place_panda_moves_the_cube_upright_and_returns_to_ready(tmp_path, params):
    runner = run_scenario("pick_place_panda.yaml", tmp_path, params)
    assert_record_complete(runner)
    values = {k: p.value for k, p in runner.spec.parameters.items()}
    cube = object_pose(runner, "cube")
    target = np.array([values["place_x"], values["place_y"], 0.771])
    assert np.linalg.norm(cube.translation - target) < TOLERANCE, cube.translation
    # Top grasp and top release: the cube is still upright (its z axis vertical).
    assert cube.rotation[2, 2] == pytest.approx(1.0, abs=1e-4)
    assert runner.scene.object("cube").attached_to is None
    assert_held_by_one_gripper(runner, "cube", ["panda_hand_tcp"])
    assert group_at(runner, "arm", "ready")
    assert assert_no_executed_motion_collides(runner) > 300


def test_stack_puts_three_cubes_in_an_aligned_tower(tmp_path):
    runner = run_scenario("stack.yaml", tmp_path)
    assert_record_complete(runner)
    a, b, c = (object_pose(runner, n) for n in ("cube_a", "cube_b", "cube_c"))
    # Each cube sits centred on the one below, 1 mm above it (the release clearance),
    # upright and turned like it (faces flush, modulo the cube's quarter-turn symmetry).
    for below, above in ((a, b), (b, c)):
        assert np.linalg.norm(above.translation[:2] - below.translation[:2]) < TOLERANCE
        assert above.translation[2] - below.translation[2] == pytest.approx(0.041, abs=TOLERANCE)
        assert above.rotation[2, 2] == pytest.approx(1.0, abs=1e-4)
        turn = yaw_mod(above.rotation, math.pi / 2) - yaw_mod(below.rotation, math.pi / 2)
        assert min(abs(turn), math.pi / 2 - abs(turn)) < 1e-3
    for name in ("cube_b", "cube_c"):
        assert_held_by_one_gripper(runner, name, ["panda_hand_tcp"])
    assert group_at(runner, "arm", "ready")
    assert assert_no_executed_motion_collides(runner) > 600
