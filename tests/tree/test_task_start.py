"""A task's ``scene:`` file's ``robot_state`` is where both ``run-task check`` and the run
start (:mod:`taskrunner.tree.start`)."""

from __future__ import annotations

import io
from pathlib import Path

import numpy as np
import pytest

from taskrunner.errors import InputError
from taskrunner.planning.service import InProcessPlanner
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import Runner, task_scene
from taskrunner.runtime.session import make_backend, run_task_file
from taskrunner.tasks.loader import load_task
from taskrunner.tree.check import check_task
from taskrunner.tree.start import task_start

CELL = Path(__file__).resolve().parents[2] / "taskrunner" / "data" / "robots" / "cells" / "panda_table.yaml"
READY = {"panda_joint1": 0.0, "panda_joint2": -0.785398, "panda_joint3": 0.0,
         "panda_joint4": -2.356194, "panda_joint5": 0.0, "panda_joint6": 1.570796,
         "panda_joint7": 0.785398}
TURNED = {**READY, "panda_joint1": 1.0, "panda_joint4": -2.0}


def _robot_state(values: dict[str, float]) -> str:
    names = ", ".join(values)
    positions = ", ".join(repr(v) for v in values.values())
    return f"robot_state:\n  joint_state:\n    name: [{names}]\n    position: [{positions}]\n"


def _task(folder: Path, scene_text: str) -> Path:
    (folder / "scene.yaml").write_text("is_diff: true\n" + scene_text)
    task = folder / "task.yaml"
    task.write_text(f"task: from_the_scene_state\ncell: {CELL}\nscene: scene.yaml\n"
                    "steps:\n  - go: {group: arm, to: ready}\n")
    return task


def _box_around_hand(values: dict[str, float]) -> str:
    """A world box where the hand is at ``values`` (in the cell's world frame)."""
    spec_cell = load_cell(CELL)
    from taskrunner.scene import scene_from_cell

    scene = scene_from_cell(spec_cell)
    scene.set_state(values)
    x, y, z = scene.link_pose("panda_hand").xyz
    return ("world:\n  collision_objects:\n    - {header: {frame_id: world}, id: block, "
            "primitives: [{type: 1, dimensions: [0.12, 0.12, 0.12]}], primitive_poses: "
            f"[{{position: {{x: {x}, y: {y}, z: {z}}}, orientation: {{w: 1}}}}]}}\n")


def _run(task: Path) -> tuple[int, str]:
    out = io.StringIO()
    code = run_task_file(task, backend="mock", worker=False, check=False, out=out)
    return code, out.getvalue()


def test_check_and_mock_run_both_start_from_the_scene_files_robot_state(tmp_path: Path) -> None:
    task = _task(tmp_path, _robot_state(TURNED))
    spec, cell = load_task(task), load_cell(CELL)
    start = task_start(spec, cell)
    assert not np.allclose(start.q, cell.start_state())  # the file moves the robot
    for name, value in TURNED.items():
        assert start.q[cell.model.joint(name).index] == pytest.approx(value)
    assert check_task(task).problems == []
    backend = make_backend("mock", cell, None, start=start.q)
    runner = Runner(spec, cell, backend, InProcessPlanner())
    assert np.allclose(runner.scene.state, start.q)  # the run's start is the check's
    record = runner.run()
    assert record.exit_code == 0
    assert _run(task)[0] == 0


def test_a_start_in_collision_fails_check_and_mock_run_alike(tmp_path: Path) -> None:
    """Before, the check started from the file's state (in collision: refused) and the run
    from the cell's (free: succeeded)."""
    task = _task(tmp_path, _robot_state(TURNED) + _box_around_hand(TURNED))
    problems = check_task(task).problems
    assert any("start state in collision (block–panda_hand" in p.message for p in problems), problems
    code, out = _run(task)
    assert code == 3, out
    assert "start state of group 'arm' is in collision: block–panda_hand" in out


def test_a_controller_elsewhere_refuses_to_start_the_run(tmp_path: Path) -> None:
    task = _task(tmp_path, _robot_state(TURNED))
    spec, cell = load_task(task), load_cell(CELL)
    backend = make_backend("mock", cell, None)  # at the cell's start, not the file's
    runner = Runner(spec, cell, backend, InProcessPlanner())
    with pytest.raises(InputError, match="'panda_joint1' at 0, the file's 1"):
        runner.run()
    assert backend.joint_state().positions[0] == 0.0  # nothing moved


def test_the_start_moves_a_state_just_outside_its_bounds_onto_them(tmp_path: Path) -> None:
    fingers = {**READY, "panda_finger_joint1": 0.065, "panda_finger_joint2": 0.065}
    task = _task(tmp_path, _robot_state(fingers))
    spec, cell = load_task(task), load_cell(CELL)
    start = task_start(spec, cell)
    assert start.q[cell.model.joint("panda_finger_joint1").index] == pytest.approx(0.04)
    assert np.allclose(task_scene(spec, cell).state[:7], start.q[:7])
    assert check_task(task).problems == []
    assert _run(task)[0] == 0
