"""A cell file's poses and objects are the task file's: one pose model (``rpy`` or ``quat``),
one object model (the same fields and checks)."""

from __future__ import annotations

import math
import os
from pathlib import Path

import numpy as np
import pytest

from taskrunner.errors import YamlError
from taskrunner.objectspec import ObjectFields
from taskrunner.posespec import PoseFields
from taskrunner.robot.cell import ObjectSpec as CellObject
from taskrunner.robot.cell import PoseSpec as CellPose
from taskrunner.robot.cell import load_cell
from taskrunner.tasks.nodes import ObjectSpec as TaskObject
from taskrunner.tasks.nodes import PoseSpec as TaskPose


def _cell(tmp_path: Path, robots_dir: Path, old: str, new: str) -> Path:
    text = (robots_dir / "cells" / "servo_arm_table.yaml").read_text()
    assert old in text
    (tmp_path / "cells").mkdir(exist_ok=True)
    if not (tmp_path / "servo_arm").exists():
        os.symlink(robots_dir / "servo_arm", tmp_path / "servo_arm")
    path = tmp_path / "cells" / "cell.yaml"
    path.write_text(text.replace(old, new))
    return path


def test_cell_and_task_poses_are_one_model():
    assert issubclass(CellPose, PoseFields) and issubclass(TaskPose, PoseFields)
    assert list(CellPose.model_fields) == list(TaskPose.model_fields) == [
        "xyz", "rpy", "quat", "frame"]


def test_a_cell_object_placed_by_quat_is_where_the_same_rpy_puts_it(tmp_path, robots_dir):
    half = math.sqrt(0.5)  # 90 degrees about z
    by_quat = load_cell(_cell(tmp_path, robots_dir, "pose: {xyz: [0.15, 0.0, 0.375]}",
                              f"pose: {{xyz: [0.15, 0.0, 0.375], quat: [0, 0, {half}, {half}]}}"))
    by_rpy = load_cell(_cell(tmp_path, robots_dir, "pose: {xyz: [0.15, 0.0, 0.375]}",
                             f"pose: {{xyz: [0.15, 0.0, 0.375], rpy: [0, 0, {math.pi / 2}]}}"))
    a, b = by_quat.objects[0].pose, by_rpy.objects[0].pose
    np.testing.assert_allclose(a.rotation, b.rotation, atol=1e-12)
    np.testing.assert_allclose(a.translation, b.translation)
    assert not np.allclose(a.rotation, np.eye(3))


def test_a_cell_pose_with_rpy_and_quat_is_refused_at_its_line(tmp_path, robots_dir):
    path = _cell(tmp_path, robots_dir, "base: {xyz: [0.0, 0.0, 0.75]}",
                 "base: {xyz: [0.0, 0.0, 0.75], rpy: [0, 0, 0], quat: [0, 0, 0, 1]}")
    with pytest.raises(YamlError, match=r"cell.yaml:7: .*takes only one of 'rpy' or 'quat'"):
        load_cell(path)
    path = _cell(tmp_path, robots_dir, "base: {xyz: [0.0, 0.0, 0.75]}",
                 "base: {xyz: [0.0, 0.0, 0.75], quat: [0, 0, 0, 2]}")
    with pytest.raises(YamlError, match=r"'robots\[0\].base.quat' must be a unit quaternion"):
        load_cell(path)


def test_cell_and_task_objects_are_one_model():
    assert issubclass(CellObject, ObjectFields) and issubclass(TaskObject, ObjectFields)
    assert list(CellObject.model_fields) == list(TaskObject.model_fields)
    mesh = {"name": "m", "shape": "mesh", "file": "part.stl"}
    assert CellObject.model_validate(mesh).scale is TaskObject.model_validate(mesh).scale is None


def test_a_cell_object_with_a_field_its_shape_does_not_take_is_refused(tmp_path, robots_dir):
    # Was ignored in cell files (a box with a radius), refused in task files: now both.
    path = _cell(tmp_path, robots_dir, "pose: {xyz: [0.15, 0.0, 0.375]}",
                 "pose: {xyz: [0.15, 0.0, 0.375]}\n    radius: 0.1")
    with pytest.raises(YamlError, match="has 'radius', which a box does not take"):
        load_cell(path)
