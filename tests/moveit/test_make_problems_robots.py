"""benchmarks/make_problems.py for robots other than the Panda (its RobotSpec), and the
Panda's files unchanged by the generalization."""

from __future__ import annotations

import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
import yaml

from taskrunner.moveit import load_motion_plan_request, load_planning_scene
from taskrunner.robot import load_robot
from taskrunner.scene import Scene

ROOT = Path(__file__).resolve().parents[2]
PROBLEMS = ROOT / "tests" / "fixtures" / "moveit_scenes" / "problems"
ROBOTS = ROOT / "benchmarks" / "robots"


@pytest.fixture(scope="module")
def make_problems():
    sys.path.insert(0, str(ROOT / "benchmarks"))
    try:
        import make_problems
    finally:
        sys.path.remove(str(ROOT / "benchmarks"))
    return make_problems


def test_panda_files_are_byte_identical_to_the_committed_ones(make_problems, tmp_path: Path
                                                               ) -> None:
    make_problems.generate(tmp_path, count=1, seed=0, classes=["table_pick", "box"])
    for name in ("table_pick", "box"):
        for stem in ("0001_scene.yaml", "0001_request.yaml", "0001_pose_request.yaml"):
            assert (tmp_path / name / stem).read_bytes() == (PROBLEMS / name / stem).read_bytes()


@pytest.mark.parametrize(("robot", "group", "frame"), [
    ("ur5_robotiq", "manipulator", "world"), ("tiago", "arm_torso", "base_footprint")])
def test_robot_sets_are_written_for_the_robots_group_and_read_back_valid(
        make_problems, tmp_path: Path, robot: str, group: str, frame: str) -> None:
    classes = ["table_pick", "table_under_pick", "cage"]
    make_problems.generate(tmp_path, count=1, seed=0, classes=classes, check=True,
                           robot_name=robot)
    model = load_robot(ROBOTS / robot)
    for name in classes:
        scene_msg = yaml.safe_load((tmp_path / name / "0001_scene.yaml").read_text())
        assert scene_msg["fixed_frame_transforms"][0]["child_frame_id"] == frame
        request = load_motion_plan_request(tmp_path / name / "0001_request.yaml", model,
                                           strict=True)
        assert request.group == group
        scene = Scene(model)
        load_planning_scene(tmp_path / name / "0001_scene.yaml", model, strict=True).apply(scene)
        start = model.state_with(scene.state, request.start)
        goal = model.state_with(start, {c.joint: c.position for c in request.joint_goals[0]})
        assert not scene.in_collision(start) and not scene.in_collision(goal)
        assert not np.allclose(start, goal)


def test_mobile_base_stands_clear_of_the_table_and_without_a_pedestal(make_problems) -> None:
    spec = make_problems.ROBOTS["tiago"]
    objects, allowed, _, _ = make_problems.class_layout("table_under_pick", spec)
    assert "pedestal" not in {n for n, _, _ in objects} and allowed == []
    objects, allowed, _, _ = make_problems.class_layout("table_pick", spec)
    table = next((s, p) for n, s, p in objects if n == "table")
    near_x = table[1].xyz[0] - table[0].size[0] / 2
    assert near_x == pytest.approx(spec.table_near_x) and allowed == []
    panda = make_problems.class_layout("table_pick")[1]
    assert panda == [("panda_link0", "table")]


def test_ur5_gripper_collides_with_its_meshes(make_problems) -> None:
    urdf = ET.parse(ROBOTS / "ur5_robotiq" / "ur5_robotiq.urdf").getroot()
    meshes = {link.get("name"): [m.get("filename") for m in link.iter("mesh")]
              for link in urdf.findall("link") if str(link.get("name")).startswith("robotiq_85")}
    with_mesh = {name: files for name, files in meshes.items() if files}
    assert len(with_mesh) == 9  # base, and knuckle, finger, inner knuckle, tip on each side
    for files in with_mesh.values():
        rel = files[0].removeprefix("package://ur5_robotiq/")
        assert (ROBOTS / "ur5_robotiq" / rel).stat().st_size > 1000


def test_unknown_robot_is_named_in_the_error(make_problems, tmp_path: Path) -> None:
    with pytest.raises(SystemExit, match="unknown robot 'fetch'; known: panda, ur5_robotiq, tiago"):
        make_problems.generate(tmp_path, count=1, robot_name="fetch")


def test_a_state_at_a_joint_limit_stays_within_it_when_written(make_problems) -> None:
    """TIAGo's arm_2_joint stops at -1.57079632679: to the nearest 9 decimals that is
    -1.570796327, past the limit for a strict reader; it is written -1.570796326."""
    model = load_robot(ROBOTS / "tiago")
    i = model.joint_names.index("arm_2_joint")
    q = model.default_state()
    q[i] = model.lower[i]
    written = make_problems._joint_state(model, q)["position"][i]
    assert model.lower[i] <= written <= model.lower[i] + 1e-9
    q[i] = 0.1234567894
    assert make_problems._joint_state(model, q)["position"][i] == 0.123456789
