"""Scenario tests of the Sawyer's example task (tasks/pick_place_sawyer.yaml): on the mock
backend in-process, and through ``run-task`` on the sim backend."""

from __future__ import annotations

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

from taskrunner.cli import main
from taskrunner.runtime.records import load_record

TOLERANCE = 0.002
PLACE_Z = 0.771  # the table top (0.75) + half the 4 cm block + 1 mm release clearance


@pytest.mark.parametrize("params", [{}, {"pick_y": "-0.1", "place_x": "0.75", "place_y": "0.3"}])
def test_pick_place_sawyer_moves_the_block_and_returns_to_neutral(tmp_path, params):
    runner = run_scenario("pick_place_sawyer.yaml", tmp_path, params)
    assert_record_complete(runner)
    values = {k: p.value for k, p in runner.spec.parameters.items()}
    block = object_pose(runner, "block")
    target = np.array([values["place_x"], values["place_y"], PLACE_Z])
    assert np.linalg.norm(block.translation - target) < TOLERANCE, block.translation
    assert block.rotation[2, 2] == pytest.approx(1.0, abs=1e-4)
    assert runner.scene.object("block").attached_to is None
    # Held by the gripper's tip frame (the tool the cell declares) from pick to place.
    assert_held_by_one_gripper(runner, "block", ["right_gripper_tip"])
    assert group_at(runner, "right_arm", "neutral")
    assert group_at(runner, "right_gripper", "open")
    # The head never moved from its start pose.
    assert group_at(runner, "head", "neutral")
    assert assert_no_executed_motion_collides(runner) > 200


@pytest.mark.slow
def test_run_task_pick_place_sawyer_on_the_sim_backend(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    code = main(["pick_place_sawyer", "--backend", "sim", "--speed", "50", "--plain",
                 "--param", "place_y=0.3"])
    out = capsys.readouterr().out
    assert code == 0, out
    assert "expectations met" in out
    (path,) = (tmp_path / "runs").glob("*.json")
    record = load_record(path)
    assert record.status == "succeeded" and record.backend == "sim"
    final = record.events[-1].data["scene"]
    (block,) = [o for o in final["objects"] if o["name"] == "block"]
    assert block["attached_to"] is None and block["pose"]["frame"] == "world"
    assert block["pose"]["xyz"] == pytest.approx([0.55, 0.3, PLACE_Z], abs=TOLERANCE)
    neutral = [0.0, -1.18, 0.0, 2.18, 0.0, 0.57, 3.3161]
    assert [final["joints"][f"right_j{i}"] for i in range(7)] == pytest.approx(neutral, abs=1e-4)
