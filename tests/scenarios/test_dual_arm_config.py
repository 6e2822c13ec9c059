"""A one-URDF dual-arm robot given as its MoveIt config package, unedited (the duo fixture:
two six-joint arms on one torso, chains ending at their flanges, no tool0, gripper poses
``open``/``close``, a mimic finger): pick/place and hand-over tasks check, run on the mock
and sim backends, and leave the objects where they were asked to be."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest
from scenario import (
    assert_held_by_one_gripper,
    assert_no_executed_motion_collides,
    assert_record_complete,
    group_at,
    object_pose,
)

from taskrunner.backends.mock import MockBackend
from taskrunner.backends.sim import SimBackend, SimOptions
from taskrunner.planning.service import InProcessPlanner
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks import load_task
from taskrunner.tree.check import check_task
from taskrunner.tree.grasps import symmetries

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures"
DUO = FIXTURES / "duo"
PACKAGE = FIXTURES / "moveit" / "src" / "duo_moveit_config"


def run(name: str, backend: str, tmp_path: Path) -> Runner:
    spec = load_task(DUO / name, {})
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    start = dict(zip(names, cell.start_state()))
    driver = (MockBackend(names, start) if backend == "mock"
              else SimBackend(names, start, SimOptions(speed=200.0, keep_history=False)))
    runner = Runner(spec, cell, driver, InProcessPlanner(),
                    RunOptions(seed=0, runs_dir=tmp_path / "runs"))
    runner.run()
    return runner


def near(runner: Runner, name: str, xyz, rpy, mm: float = 5.0, degrees: float = 5.0) -> None:
    """Object ``name`` ends at ``xyz``, ``rpy`` (world), up to its symmetries."""
    pose = object_pose(runner, name)
    wanted = pin.SE3(pin.rpy.rpyToMatrix(*rpy), np.array(xyz, dtype=float))
    assert np.linalg.norm(pose.translation - wanted.translation) < mm / 1e3, pose.translation
    turn = min(np.degrees(np.linalg.norm(pin.log3((wanted.rotation @ s).T @ pose.rotation)))
               for s in symmetries(runner.scene.object(name).shape))
    assert turn < degrees, f"{turn:.1f}° from the wanted orientation"


def test_the_package_is_a_setup_assistant_package_with_no_taskrunner_file():
    # Run as it is: nothing added for the task runner (the cell declares one hand's TCP).
    assert (PACKAGE / ".setup_assistant").is_file()
    assert not (PACKAGE / "robot.yaml").exists()
    assert (PACKAGE / "config" / "duo.srdf").is_file()


@pytest.mark.parametrize("name", ["pick_place.yaml", "handoff.yaml"])
def test_duo_tasks_pass_the_check(name):
    report = check_task(DUO / name)
    assert report.ok, [str(p) for p in report.problems]
    assert report.cell == "duo_table" and report.steps >= 4


@pytest.mark.parametrize("backend", ["mock", "sim"])
def test_duo_left_arm_moves_the_cube(backend, tmp_path):
    runner = run("pick_place.yaml", backend, tmp_path)
    assert_record_complete(runner)
    near(runner, "cube", [0.30, 0.05, 0.7705], [0, 0, 0.5])
    assert runner.scene.object("cube").attached_to is None
    assert group_at(runner, "left_arm", "home")
    # Held by the link the declared tool frame is fixed to.
    assert assert_held_by_one_gripper(runner, "cube", ["left_flange"]) == ["left_flange"]
    assert assert_no_executed_motion_collides(runner) > 0


@pytest.mark.parametrize("backend", ["mock", "sim"])
def test_duo_hands_the_bar_from_left_to_right_and_lays_it_down(backend, tmp_path):
    runner = run("handoff.yaml", backend, tmp_path)
    assert_record_complete(runner)
    near(runner, "bar", [0.30, -0.20, 0.766], [1.5708, 0, 0])
    assert runner.scene.object("bar").attached_to is None
    assert group_at(runner, "left_arm", "home") and group_at(runner, "right_arm", "home")
    assert_held_by_one_gripper(runner, "bar", ["left_flange", "right_flange"])
    assert assert_no_executed_motion_collides(runner) > 0
    # The gripper closed on the SRDF's own 'close' pose.
    closes = [m for m in runner.ctx.executed if m.node.endswith("closes")]
    assert closes and np.allclose(closes[0].trajectory.positions[-1], 0.0)


def test_duo_receiver_takes_the_bar_at_an_explicit_grasp_pose(tmp_path):
    runner = run("handoff_grasp.yaml", "mock", tmp_path)
    assert_record_complete(runner)
    near(runner, "bar", [0.30, -0.20, 0.766], [1.5708, 0, 0])
    # While the right arm held the bar, its tool frame was at the grasp pose written in
    # the task, in the bar's frame (within the approach's straight-line tolerance).
    wanted = pin.SE3(pin.rpy.rpyToMatrix(-1.5708, -1.5708, 0), np.array([0, -0.006, -0.03]))
    arm = runner.ctx.arm("right_arm")
    held = [o for m in runner.ctx.executed if m.node.endswith("right_arm backs off")
            for o in m.scene.objects if o.name == "bar"]
    assert held and held[0].attached_to == "right_flange"
    tool_in_bar = arm.grip(held[0].pose.se3).inverse()
    assert np.linalg.norm(tool_in_bar.translation - wanted.translation) < 1e-3
    assert np.linalg.norm(pin.log3(wanted.rotation.T @ tool_in_bar.rotation)) < 1e-2
