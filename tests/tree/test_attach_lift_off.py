"""An ``attach`` step lets the object touch what it rests on so that it can be lifted off,
and, as a pick's allowance ends after its retreat, that allowance ends with the first
motion that starts with the object clear of its support: check and run alike."""

from __future__ import annotations

from pathlib import Path

from taskrunner.backends.mock import MockBackend
from taskrunner.planning.service import InProcessPlanner
from taskrunner.resources import resolve_task
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.scene import scene_from_cell
from taskrunner.shapes import Box
from taskrunner.tasks.loader import load_task
from taskrunner.tree.check import check_task
from taskrunner.tree.grasps import LIFT_OFF, allow_lift_off, end_lift_offs_left
from taskrunner.types import Pose

CELL = Path(resolve_task("pick_place_panda")).parent.parent / "robots" / "cells" / "panda_table.yaml"


def suction_task(tmp_path: Path, after: str) -> Path:
    """The open hand around a cube on the table, the cube attached to the hand link (a
    suction cup), lifted 10 cm, then ``after``."""
    path = tmp_path / "suction.yaml"
    path.write_text(
        f"task: suction\ncell: {CELL}\n"
        "objects:\n"
        "  - {name: cube, shape: box, size: [0.04, 0.04, 0.04], pose: {xyz: [0.5, 0.15, 0.77]}}\n"
        "steps:\n"
        "  - gripper: {arm: arm, action: open}\n"
        "  - go: {group: arm, to: ready}\n"
        "  - move: {group: arm, link: panda_hand_tcp,\n"
        "           pose: {xyz: [0.5, 0.15, 0.78], rpy: [3.141592653589793, 0, 0]}}\n"
        "  - attach: {link: panda_hand, object: cube,\n"
        "             touch_links: [panda_hand_tcp, panda_leftfinger, panda_rightfinger]}\n"
        "  - move: {group: arm, by: {xyz: [0, 0, 0.1], frame: world}}\n"
        f"  - {after}\n", encoding="utf-8")
    return path


def run_on_mock(path: Path):
    spec = load_task(path)
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state(), strict=True))
    return Runner(spec, cell, MockBackend(cell.model.joint_names, start), InProcessPlanner(),
                  RunOptions(backend_name="mock")).run()


def test_the_lift_is_allowed_and_the_support_is_an_obstacle_again_after_it(tmp_path):
    # Back down 12 cm: the cube would end 2 cm into the table it was lifted off.
    path = suction_task(tmp_path, "move: {group: arm, by: {xyz: [0, 0, -0.12], frame: world}}")
    report = check_task(path)
    assert len(report.problems) == 1, report.problems
    problem = report.problems[0]
    assert problem.line == 13  # the move down, not the lift (line 12)
    assert "cube" in problem.message and "table" in problem.message
    record = run_on_mock(path)
    assert record.status == "failed"
    assert f"{path}:13" in record.error
    assert "cube" in record.error and "table" in record.error


def test_a_motion_that_keeps_clear_of_the_old_support_passes(tmp_path):
    path = suction_task(tmp_path, "move: {group: arm, by: {xyz: [0, 0, -0.05], frame: world}}")
    report = check_task(path)
    assert report.ok, report.problems
    record = run_on_mock(path)
    assert record.status == "succeeded", record.error


def test_an_allowance_whose_pair_still_touches_is_kept():
    cell = load_cell(CELL)
    scene = scene_from_cell(cell)
    scene.add_object("cube", Box((0.04, 0.04, 0.04)), Pose((0.5, 0.15, 0.7695)))  # 0.5 mm in
    scene.attach_object("cube", "panda_hand")  # where it is: the hand holds it on the table
    pairs = allow_lift_off(scene, "cube")
    assert [sorted(p) for p in pairs] == [["cube", "table"]]
    pair = frozenset(("cube", "table"))
    assert end_lift_offs_left(scene) == []  # still touching: kept
    assert scene.allowed_collisions()[pair] == LIFT_OFF
    lifted = scene.state.copy()
    lifted[scene.robot.joint("panda_joint2").index] -= 0.3  # the arm raises the hand
    scene.set_state(lifted)
    assert scene.object_pose("cube").xyz[2] > 0.78
    assert end_lift_offs_left(scene) == [("cube", "table")]
    assert pair not in scene.allowed_collisions()
    assert end_lift_offs_left(scene) == []
