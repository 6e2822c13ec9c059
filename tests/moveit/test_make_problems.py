"""benchmarks/make_problems.py: seeded MotionBenchMaker-style problems, as MoveIt YAML."""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from taskrunner.moveit import load_motion_plan_request, load_planning_scene, plan_request_file
from taskrunner.resources import resolve_cell
from taskrunner.robot.cell import load_cell_or_robot
from taskrunner.scene import scene_from_cell

ROOT = Path(__file__).resolve().parents[2]
PROBLEMS = ROOT / "tests" / "fixtures" / "moveit_scenes" / "problems"


@pytest.fixture(scope="module")
def make_problems():
    sys.path.insert(0, str(ROOT / "benchmarks"))
    try:
        import make_problems
    finally:
        sys.path.remove(str(ROOT / "benchmarks"))
    return make_problems


def test_every_class_writes_problems_that_read_back_valid(make_problems, tmp_path: Path) -> None:
    summary = make_problems.generate(tmp_path, count=1, seed=3, check=True)
    assert set(summary["classes"]) == set(make_problems.CLASSES)
    for name in make_problems.CLASSES:
        assert sorted(p.name for p in (tmp_path / name).iterdir()) == [
            "0001_pose_request.yaml", "0001_request.yaml", "0001_scene.yaml"]


def test_problems_depend_only_on_seed_class_and_index(make_problems, tmp_path: Path) -> None:
    cell = load_cell_or_robot(resolve_cell("panda"))
    make_problems.generate(tmp_path, count=1, seed=0, classes=["table_pick", "box"])
    for name in ("table_pick", "box"):
        fresh = load_motion_plan_request(tmp_path / name / "0001_request.yaml", cell.model)
        kept = load_motion_plan_request(PROBLEMS / name / "0001_request.yaml", cell.model)
        goals = [np.array([c.position for c in r.joint_goals[0]]) for r in (fresh, kept)]
        assert np.allclose(goals[0], goals[1], atol=1e-6)


@pytest.mark.parametrize("name", ["table_pick", "bookshelf_small", "box"])
def test_committed_example_problems_plan(name: str) -> None:
    cell = load_cell_or_robot(resolve_cell("panda"))
    scene = scene_from_cell(cell)
    load_planning_scene(PROBLEMS / name / "0001_scene.yaml", cell.model, strict=True).apply(scene)
    for request_file in ("0001_request.yaml", "0001_pose_request.yaml"):
        request = load_motion_plan_request(PROBLEMS / name / request_file, cell.model, strict=True)
        report = plan_request_file(scene, request, seed=0)
        assert report.success, f"{name}/{request_file}: {report.message}"
