"""Scenario tests of the servo arm's example tasks (tasks/go_home.yaml, pick_place.yaml)."""

from __future__ import annotations

import numpy as np
import pytest
from scenario import (
    assert_no_executed_motion_collides,
    assert_record_complete,
    object_position,
    run_scenario,
)


def test_go_home_opens_stands_up_and_returns_home(tmp_path):
    runner = run_scenario("go_home.yaml", tmp_path)
    assert_record_complete(runner)
    model = runner.scene.robot
    home = model.named_state("arm", "home")
    assert runner.scene.state[model.indices(home.names)] == pytest.approx(home.positions)
    assert assert_no_executed_motion_collides(runner) > 100


@pytest.mark.parametrize("params", [{}, {"pick_y": "-0.02", "place_x": "0.19", "place_y": "-0.10"}])
def test_pick_place_moves_the_cube_and_nothing_collides(tmp_path, params):
    runner = run_scenario("pick_place.yaml", tmp_path, params)
    assert_record_complete(runner)
    spec = runner.spec
    target = np.array([spec.parameters["place_x"].value, spec.parameters["place_y"].value, 0.7635])
    cube = object_position(runner, "cube")
    # Position-only arm: the cube's centre lands within a few millimetres of the target.
    assert np.linalg.norm(cube - target) < 0.006, cube
    assert runner.scene.object("cube").attached_to is None
    assert assert_no_executed_motion_collides(runner) > 100
    planned = [e for e in runner.record.events if e.kind == "planned"]
    assert len(planned) >= 10
