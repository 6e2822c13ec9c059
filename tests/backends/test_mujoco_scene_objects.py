"""A MoveIt PlanningScene's world objects on the mujoco backend: fixed, as in MoveIt,
unless the task takes hold of them.

Skipped where mujoco is not installed (``pip install -e '.[mujoco]'``).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, RunOptions
from taskrunner.tasks.loader import load_task
from taskrunner.tree.check import check_task

mujoco = pytest.importorskip("mujoco", reason="the mujoco backend needs: pip install "
                             "-e '.[mujoco]'")

from taskrunner.backends.mock import MockBackend  # noqa: E402
from taskrunner.backends.physics import MujocoBackend, MujocoOptions, physics_cell  # noqa: E402
from taskrunner.planning.service import InProcessPlanner  # noqa: E402

TASK = Path(__file__).parents[1] / "fixtures" / "moveit_scenes" / "task" / "pick_from_shelf.yaml"
SHELF_Z = 0.75 + 0.1  # the scene file's shelf, in the world (panda_link0 is 0.75 m up)


def test_a_scene_files_shelf_stays_put_and_check_mock_and_mujoco_agree(tmp_path):
    report = check_task(TASK)
    spec = load_task(TASK)
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state()))
    mock = Runner(spec, cell, MockBackend(cell.model.joint_names, start), InProcessPlanner(),
                  RunOptions(backend_name="mock")).run()
    backend = MujocoBackend(cell.model.joint_names, physics_cell(cell), start,
                            MujocoOptions(cache_dir=str(tmp_path / "cache")))
    try:
        record = Runner(spec, cell, backend, InProcessPlanner(),
                        RunOptions(backend_name="mujoco")).run()
        model, data = backend.model, backend._data
        shelf = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_GEOM, "shelf")
        assert shelf >= 0
        assert model.geom_bodyid[shelf] == 0  # a world geom: no free joint
        assert abs(float(data.geom_xpos[shelf][2]) - SHELF_Z) < 1e-3
        assert "shelf" not in backend.object_poses()
        cube = backend.object_poses()["cube"]  # the picked cube is a free body
    finally:
        backend.close()
    assert report.ok, report.problems
    assert (mock.status, record.status) == ("succeeded", "succeeded"), record.error
    assert abs(cube.xyz[2] - 0.771) < 5e-3


def test_an_object_attached_without_a_touch_was_never_touched_not_slipped(tmp_path):
    # 'attach' carries the cube in the scene though the hand is far from it: physics
    # sees it stay on the table, and says that no finger ever touched it.
    path = tmp_path / "attach.yaml"
    path.write_text(
        f"task: attach\ncell: {load_task(TASK).cell}\n"
        "objects:\n"
        "  - {name: cube, shape: box, size: [0.04, 0.04, 0.04], pose: {xyz: [0.5, 0.15, 0.77]}}\n"
        "steps:\n"
        "  - go: {group: arm, to: ready}\n"
        "  - attach: {arm: arm, object: cube}\n"
        "  - move: {group: arm, by: {xyz: [0, 0, 0.05]}}\n", encoding="utf-8")
    spec = load_task(path)
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state()))
    backend = MujocoBackend(cell.model.joint_names, physics_cell(cell), start,
                            MujocoOptions(cache_dir=str(tmp_path / "cache")))
    try:
        record = Runner(spec, cell, backend, InProcessPlanner(),
                        RunOptions(backend_name="mujoco")).run()
    finally:
        backend.close()
    assert record.status == "failed"
    assert f"{path}:8" in record.error  # the move
    assert "'cube' was never touched by the gripper" in record.error


def test_an_object_attached_to_a_link_is_welded_and_lifts_off_the_table(tmp_path):
    # A suction-like hold: the open hand around the cube, the cube attached to the hand
    # link (no arm's grasp frame): it lifts off its table in the plan and in physics.
    path = tmp_path / "suction.yaml"
    path.write_text(
        f"task: suction\ncell: {load_task(TASK).cell}\n"
        "objects:\n"
        "  - {name: cube, shape: box, size: [0.04, 0.04, 0.04], pose: {xyz: [0.5, 0.15, 0.77]}}\n"
        "steps:\n"
        "  - gripper: {arm: arm, action: open}\n"
        "  - go: {group: arm, to: ready}\n"
        "  - move: {group: arm, link: panda_hand_tcp,\n"
        "           pose: {xyz: [0.5, 0.15, 0.78], rpy: [3.141592653589793, 0, 0]}}\n"
        "  - attach: {link: panda_hand, object: cube,\n"
        "             touch_links: [panda_hand_tcp, panda_leftfinger, panda_rightfinger]}\n"
        "  - move: {group: arm, by: {xyz: [0, 0, 0.1], frame: world}}\n", encoding="utf-8")
    assert check_task(path).ok, check_task(path).problems
    spec = load_task(path)
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state()))
    backend = MujocoBackend(cell.model.joint_names, physics_cell(cell), start,
                            MujocoOptions(cache_dir=str(tmp_path / "cache")))
    try:
        record = Runner(spec, cell, backend, InProcessPlanner(),
                        RunOptions(backend_name="mujoco")).run()
        cube = backend.object_poses()["cube"]
        notes = list(backend.notes)
    finally:
        backend.close()
    assert record.status == "succeeded", record.error
    assert cube.xyz[2] > 0.77 + 0.09  # lifted with the hand
    assert any("'cube' welded to 'panda_hand'" in n for n in notes)
