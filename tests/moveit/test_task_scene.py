"""A task's ``scene:``: a MoveIt PlanningScene file whose objects join the cell's world."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from taskrunner.errors import TaskSpecError
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.runner import task_scene
from taskrunner.tasks.loader import load_task, load_task_text
from taskrunner.tasks.names import check_names
from taskrunner.tree.check import check_task

TASK = Path(__file__).resolve().parents[1] / "fixtures" / "moveit_scenes" / "task" / "pick_from_scene.yaml"


def test_task_scene_file_adds_its_objects_after_the_cells() -> None:
    spec = load_task(TASK)
    assert spec.scene == TASK.parent / "cube_scene.yaml"
    cell = load_cell(spec.cell)
    scene = task_scene(spec, cell)
    assert list(scene.object_names) == ["table", "cube", "post"]
    # panda_link0 stands on the table top (0.75 m): the cube rests on the table.
    assert np.allclose(scene.object_pose("cube").xyz, (0.5, 0.15, 0.77))
    assert scene.collision_allowed("cube", "table")
    assert check_names(spec, cell) == []
    assert check_task(TASK).problems == []


def test_task_document_keeps_the_scene_file() -> None:
    spec = load_task(TASK)
    document = spec.to_document()
    assert document["scene"] == str(TASK.parent / "cube_scene.yaml")


def test_missing_scene_file_is_a_task_problem_at_its_line(tmp_path: Path) -> None:
    text = TASK.read_text().replace("cube_scene.yaml", "nowhere.yaml")
    with pytest.raises(TaskSpecError) as info:
        load_task_text(text, TASK.parent / "copy.yaml")
    assert "copy.yaml:4: scene file not found" in str(info.value)


def test_bad_scene_file_is_reported_by_the_check_with_its_line(tmp_path: Path) -> None:
    (tmp_path / "scene.yaml").write_text(
        "world:\n  collision_objects:\n    - {header: {frame_id: shelf_top}, id: cube,"
        " primitives: [{type: 1, dimensions: [0.04, 0.04, 0.04]}],"
        " primitive_poses: [{position: {x: 0.5, y: 0, z: 0.02}, orientation: {w: 1}}]}\n")
    task = tmp_path / "task.yaml"
    cell = TASK.parent.parents[3] / "taskrunner" / "data" / "robots" / "cells" / "panda_table.yaml"
    task.write_text(f"task: t\ncell: {cell}\nscene: scene.yaml\nsteps:\n  - go: {{group: arm, to: ready}}\n")
    problems = check_task(task).problems
    assert any(p.line == 3 and "unknown frame 'shelf_top'" in p.message for p in problems), problems
