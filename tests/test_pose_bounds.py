"""Absurd pose numbers (``1e308``) are refused by the one pose model with the field's
name, in a task file, a cell file, a REST request and the Python API, before any
arithmetic on them could overflow: every check here turns warnings into errors."""

from __future__ import annotations

import warnings
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path

import pytest

import taskrunner
from taskrunner import resources
from taskrunner.errors import TaskSpecError, YamlError
from taskrunner.posespec import PoseFields
from taskrunner.robot.cell import load_cell
from taskrunner.tasks import load_task

HUGE_POSES = [
    ({"xyz": [1e308, 0.0, 0.8]}, "xyz", "must be a finite number within ±1000 m (got 1e+308)"),
    ({"xyz": [0.1, -1e4, 0.8]}, "xyz", "must be a finite number within ±1000 m (got -10000.0)"),
    ({"xyz": [0.1, 0.0, 0.8], "rpy": [0.0, 1e308, 0.0]}, "rpy",
     "must be a finite number within ±100 rad (got 1e+308)"),
    ({"xyz": [0.1, 0.0, 0.8], "quat": [1e308, 0.0, 0.0, 0.0]}, "quat",
     "must be a unit quaternion [x, y, z, w] (got norm 1e+308)"),
    ({"xyz": [0.1, 0.0, 0.8], "quat": [1e200, 1e200, 1e200, 1e200]}, "quat",
     "must be a unit quaternion [x, y, z, w] (got norm 2e+200)"),
]
IDS = ["xyz", "xyz-far", "rpy", "quat", "quat-all"]


@contextmanager
def no_warnings() -> Iterator[None]:
    """As ``-W error`` for the block: a warning (numpy's overflow) fails the test."""
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        yield


def _flow(pose: dict[str, list[float]]) -> str:
    return "{" + ", ".join(f"{k}: [{', '.join(repr(v) for v in vs)}]"
                           for k, vs in pose.items()) + "}"


@pytest.mark.parametrize(("pose", "field", "message"), HUGE_POSES, ids=IDS)
def test_the_pose_model_refuses_huge_numbers_naming_the_field(pose, field, message):
    with no_warnings(), pytest.raises(ValueError) as caught:
        PoseFields.model_validate(pose)
    assert field in str(caught.value) and message in str(caught.value)


@pytest.mark.parametrize(("pose", "field", "message"), HUGE_POSES, ids=IDS)
def test_a_task_file_with_a_huge_pose_is_refused_at_its_line(tmp_path: Path, pose, field,
                                                             message):
    task = tmp_path / "far.yaml"
    task.write_text(f"task: far\ncell: {resources.cells_dir() / 'servo_arm_table.yaml'}\n"
                    "steps:\n"
                    "  - go: {group: arm, to: home}\n"
                    f"  - move: {{group: arm, pose: {_flow(pose)}}}\n")
    with no_warnings(), pytest.raises(TaskSpecError) as caught:
        load_task(task)
    text = str(caught.value)
    assert f"{task}:5:" in text and f"pose.{field}" in text and message in text, text


@pytest.mark.parametrize(("pose", "field", "message"), HUGE_POSES, ids=IDS)
def test_a_cell_file_with_a_huge_object_pose_is_refused_at_its_line(tmp_path: Path, pose,
                                                                    field, message):
    cell = tmp_path / "far_cell.yaml"
    cell.write_text("name: far_cell\nrobots:\n"
                    f"  - {{name: arm, robot: {resources.robots_dir() / 'servo_arm'}}}\n"
                    "objects:\n"
                    f"  - {{name: box, shape: box, size: [0.1, 0.1, 0.1], pose: {_flow(pose)}}}\n")
    with no_warnings(), pytest.raises(YamlError) as caught:
        load_cell(cell)
    text = str(caught.value)
    assert f"{cell}:5:" in text and f"objects[0].pose.{field}" in text and message in text, text


def test_the_python_api_refuses_a_huge_pose_mapping():
    with taskrunner.load_workcell("servo_arm_table") as cell:
        for pose, field, message in HUGE_POSES:
            with no_warnings(), pytest.raises(TaskSpecError) as caught:
                cell.plan("arm", pose=pose)
            assert f"'pose.{field}" in str(caught.value) and message in str(caught.value)
