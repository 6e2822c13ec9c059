"""No ambient state: taught poses and folder policies reach the loaders as arguments,
never from the thread or the process (issue 24, item 7)."""

from __future__ import annotations

import re
import threading
from pathlib import Path

import pytest

from taskrunner import resources
from taskrunner.folders import FolderPolicy
from taskrunner.robot.cell import Cell, load_cell
from taskrunner.robot.model import RobotModel
from taskrunner.taught import TaughtPose, TaughtPoses
from taskrunner.tree.check import check_task

PACKAGE = Path(__file__).resolve().parents[1] / "taskrunner"


def _cell_file(folder: Path, name: str) -> Path:
    """The shipped servo arm table as ``folder/name.yaml`` (its robot by absolute path)."""
    text = (resources.cells_dir() / "servo_arm_table.yaml").read_text()
    text = text.replace("robot: servo_arm", f"robot: {resources.robots_dir() / 'servo_arm'}")
    folder.mkdir(parents=True, exist_ok=True)
    path = folder / f"{name}.yaml"
    path.write_text(text.replace("name: servo_arm_table", f"name: {name}"))
    return path


def _pose(model: RobotModel, name: str, turn: float) -> TaughtPose:
    joints = dict(model.named_state("arm", "Candle").as_dict())
    joints["Revolute 1"] += turn
    return TaughtPose("arm", name, joints)


def test_two_cells_loaded_in_one_process_each_get_their_own_taught_poses(tmp_path: Path):
    a, b = _cell_file(tmp_path, "cell_a"), _cell_file(tmp_path, "cell_b")
    plain = load_cell(a)
    assert "bench" not in plain.model.named_states["arm"]
    taught_a = TaughtPoses({a.resolve(): (_pose(plain.model, "bench", 0.3),)})
    taught_b = TaughtPoses({b.resolve(): (_pose(plain.model, "bench", -0.4),
                                          _pose(plain.model, "shelf", 0.1))})
    loaded: dict[str, Cell] = {}

    def load(name: str, path: Path, taught: TaughtPoses) -> None:
        loaded[name] = load_cell(path, taught=taught)

    # Side by side, in two threads, each with its own set.
    threads = [threading.Thread(target=load, args=("a", a, taught_a)),
               threading.Thread(target=load, args=("b", b, taught_b))]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    cell_a, cell_b = loaded["a"], loaded["b"]
    poses_a, poses_b = cell_a.model.named_states["arm"], cell_b.model.named_states["arm"]
    assert poses_a["bench"]["Revolute 1"] == pytest.approx(
        taught_a.of(a)[0].joints["Revolute 1"])
    assert poses_b["bench"]["Revolute 1"] == pytest.approx(
        taught_b.of(b)[0].joints["Revolute 1"])
    assert "shelf" not in poses_a and "shelf" in poses_b
    # A set given to cell b's load says nothing about cell a's; nothing stays behind.
    assert "bench" not in load_cell(a, taught=taught_b).model.named_states["arm"]
    assert "bench" not in load_cell(b).model.named_states["arm"]


def test_check_task_sees_only_the_taught_poses_and_policy_it_is_given(tmp_path: Path):
    cell = _cell_file(tmp_path / "cells", "bench_table")
    task = tmp_path / "tasks" / "go_bench.yaml"
    task.parent.mkdir()
    task.write_text(f"task: go_bench\ncell: {cell}\n"
                    "steps:\n  - go: {group: arm, to: bench}\n")
    model = load_cell(cell).model
    taught = TaughtPoses({cell.resolve(): (_pose(model, "bench", 0.3),)})
    assert not check_task(task).ok
    assert check_task(task, taught=taught).ok
    assert not check_task(task).ok  # the set given before is not kept anywhere
    # The policy given is the one obeyed: the cell's folder is not among its cells.
    narrow = FolderPolicy(tasks=(task.parent,), cells=(tmp_path / "elsewhere",),
                          robots=(resources.robots_dir(),))
    refused = check_task(task, policy=narrow, taught=taught)
    assert not refused.ok
    assert any("outside the folders" in p.message for p in refused.problems), refused.problems
    wide = FolderPolicy(tasks=(task.parent,), cells=(cell.parent,),
                        robots=(resources.robots_dir(),))
    assert check_task(task, policy=wide, taught=taught).ok


def test_no_module_keeps_a_context_variable_for_loads():
    # A loader's inputs come as arguments; a context variable read deep down is how a
    # load ran under another caller's policy or poses. The settings' environment, read
    # only while one Settings is built in the same call, is the one left.
    allowed = {"api/settings.py"}
    found = sorted(str(p.relative_to(PACKAGE)) for p in PACKAGE.rglob("*.py")
                   if re.search(r"\bContextVar\s*\(", p.read_text(encoding="utf-8")))
    assert set(found) <= allowed, found
