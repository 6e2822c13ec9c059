"""MoveIt PlanningScene / MotionPlanRequest files: reading, applying, planning, errors."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from taskrunner.errors import InputError, YamlError
from taskrunner.moveit import load_motion_plan_request, load_planning_scene, plan_request_file
from taskrunner.moveit.request_file import planner_name
from taskrunner.resources import resolve_cell
from taskrunner.robot.cell import load_cell_or_robot
from taskrunner.scene import scene_from_cell
from taskrunner.shapes import Box, Cylinder, Mesh, Sphere
from taskrunner.types import Pose

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures" / "moveit_scenes"
BAD = FIXTURES / "bad"


@pytest.fixture(scope="module")
def panda():
    return load_cell_or_robot(resolve_cell("panda"))


@pytest.fixture(scope="module")
def pair():
    return load_cell_or_robot(resolve_cell("panda_pair"))


def _expected(path: Path) -> tuple[int, str]:
    line, message = (path.with_suffix(".expected")).read_text().strip().split(": ", 1)
    return int(line), message


@pytest.mark.parametrize("name", sorted(p.name for p in BAD.glob("*.yaml")))
def test_bad_file_fails_with_file_line_and_field(name: str, panda) -> None:
    path = BAD / name
    line, message = _expected(path)
    with pytest.raises(InputError) as info:
        if name.endswith("_request.yaml"):
            load_motion_plan_request(path, panda.model, strict=True)
        else:
            load_planning_scene(path, panda.model, strict=True).apply(scene_from_cell(panda))
    assert info.value.path == path
    assert info.value.line == line
    assert message in info.value.reason


def test_ros1_scene_gives_every_shape_in_its_frame(panda) -> None:
    scene = scene_from_cell(panda)
    loaded = load_planning_scene(FIXTURES / "ros1_table_scene.yaml", panda.model)
    assert loaded.apply(scene) == ["table", "can", "ball", "funnel", "funnel/1"]
    assert loaded.warnings == []
    assert scene.object("can").shape == Cylinder(radius=0.033, length=0.12)
    assert scene.object("table").shape == Box((1.0, 1.2, 0.04))
    assert scene.object("ball").shape == Sphere(0.04)
    # 'ball' is given in the fixed frame table_corner at (0.3, -0.3, 0) in the world.
    assert np.allclose(scene.object_pose("ball").xyz, (0.6, -0.3, 0.04))
    assert isinstance(scene.object("funnel").shape, Mesh)  # the cone, as a covering mesh
    assert scene.collision_allowed("panda_link0", "table")
    assert not scene.collision_allowed("panda_link1", "table")
    assert np.isclose(scene.state[panda.model.joint("panda_joint4").index], -2.356194)
    assert not scene.in_collision()


def test_ros2_object_pose_places_parts_and_diff_keeps_cell_objects() -> None:
    cell = load_cell_or_robot(resolve_cell("panda_table"))
    scene = scene_from_cell(cell)
    before = set(scene.object_names)
    loaded = load_planning_scene(FIXTURES / "ros2_shelf_scene.yaml", cell.model)
    loaded.apply(scene)
    assert before < set(scene.object_names)
    # The shelf's frame is turned 90 degrees about z: its part at x = -0.3 lands at y = -0.3.
    assert np.allclose(scene.object_pose("shelf/2").xyz, (0.8, -0.3, 0.3), atol=1e-6)
    assert isinstance(scene.object("wedge").shape, Mesh)
    assert scene.object("wedge").shape.path.is_file()
    assert scene.collision_allowed("wedge", "panda_hand")  # default entry: allowed with all
    assert np.isclose(scene.state[cell.model.joint("panda_joint1").index], 0.1)


def test_full_scene_replaces_objects_unless_merged() -> None:
    cell = load_cell_or_robot(resolve_cell("panda_table"))
    loaded = load_planning_scene(FIXTURES / "ros1_table_scene.yaml", cell.model)
    replaced, merged = scene_from_cell(cell), scene_from_cell(cell)
    loaded.apply(replaced)
    loaded.apply(merged, merge=True)
    assert set(replaced.object_names) == {"table", "can", "ball", "funnel", "funnel/1"}
    assert set(cell.objects[0].name for _ in [0]) <= set(merged.object_names)


def test_attached_object_moves_with_the_hand(panda) -> None:
    scene = scene_from_cell(panda)
    load_planning_scene(FIXTURES / "attached_scene.yaml", panda.model).apply(scene)
    held = scene.object("held_box")
    assert held.attached_to == "panda_hand"
    assert set(held.touch_links) == {"panda_leftfinger", "panda_rightfinger"}
    hand = scene.link_pose("panda_hand").se3
    assert np.allclose(scene.object_pose("held_box").xyz, hand.act(np.array([0, 0, 0.11])))


def test_diff_operations_move_append_and_remove(panda, tmp_path: Path) -> None:
    scene = scene_from_cell(panda)
    load_planning_scene(FIXTURES / "ros1_table_scene.yaml", panda.model).apply(scene)
    diff = tmp_path / "diff.yaml"
    diff.write_text("""is_diff: true
world:
  collision_objects:
    - {header: {frame_id: world}, id: can, operation: 3,
       primitives: [{type: 3, dimensions: [0.12, 0.033]}],
       primitive_poses: [{position: {x: 0.3, y: 0.3, z: 0.06}, orientation: {w: 1}}]}
    - {header: {frame_id: world}, id: ball, operation: 2,
       primitives: [{type: 2, dimensions: [0.02]}],
       primitive_poses: [{position: {x: 0.6, y: 0.3, z: 0.02}, orientation: {w: 1}}]}
    - {id: funnel, operation: 1}
    - {id: ghost, operation: 1}
""")
    loaded = load_planning_scene(diff, panda.model)
    loaded.apply(scene)
    assert np.allclose(scene.object_pose("can").xyz, (0.3, 0.3, 0.06))
    assert "ball/1" in scene and "table" in scene
    assert "funnel" not in scene and "funnel/1" not in scene
    assert [w.line for w in loaded.warnings] == [11]  # REMOVE of an object that is not there
    assert "ghost" in loaded.warnings[0].message


def test_cell_prefixes_need_a_robot_when_ambiguous(pair) -> None:
    with pytest.raises(InputError, match="choose the robot"):
        load_planning_scene(FIXTURES / "ros1_table_scene.yaml", pair.model)
    scene = scene_from_cell(pair)
    load_planning_scene(FIXTURES / "attached_scene.yaml", pair.model, robot="right").apply(
        scene, merge=True)
    assert scene.object("held_box").attached_to == "right_panda_hand"
    request = load_motion_plan_request(FIXTURES / "joint_goal_request.yaml", pair.model,
                                       robot="left")
    assert request.group == "left_arm"
    assert set(request.start) >= {"left_panda_joint1", "left_panda_joint7"}


def test_pose_goal_request_is_planned_and_meets_its_constraints(panda) -> None:
    scene = scene_from_cell(panda)
    request = load_motion_plan_request(FIXTURES / "pose_goal_request.yaml", panda.model)
    assert request.options.planner == "RRTConnect" and request.velocity_scaling is None
    report = plan_request_file(scene, request, seed=1)
    assert report.success, report.message
    assert report.result is not None and report.duration > 0 and report.path_length > 0
    end = report.result.end
    tcp = scene.to_world(Pose((0, 0, 0.1034), frame="panda_hand"), end).translation
    assert np.linalg.norm(tcp - np.array([0.5, -0.2, 0.3])) <= 0.001
    z_axis = scene.to_world(Pose(frame="panda_hand"), end).rotation[:, 2]
    assert z_axis[2] < -0.999  # pointing down
    # The start state does not meet the goal: the check says so.
    assert request.goal_violations(scene, scene.state, scene.state)


def test_joint_goal_request_reads_options_and_plans(panda) -> None:
    scene = scene_from_cell(panda)
    load_planning_scene(FIXTURES / "ros1_table_scene.yaml", panda.model).apply(scene)
    request = load_motion_plan_request(FIXTURES / "joint_goal_request.yaml", panda.model)
    assert (request.velocity_scaling, request.acceleration_scaling) == (0.5, 0.5)
    assert request.options.planning_time == 5.0 and request.options.attempts == 1
    report = plan_request_file(scene, request, seed=0)
    assert report.success, report.message
    assert np.isclose(report.result.end[panda.model.joint("panda_joint1").index], 0.8)


def test_unknown_planner_is_a_warning_and_strict_makes_it_an_error(panda, tmp_path: Path) -> None:
    path = tmp_path / "r.yaml"
    path.write_text("group_name: arm\nplanner_id: CHOMP\ngoal_constraints:\n"
                    "  - joint_constraints: [{joint_name: panda_joint1, position: 0.3}]\n")
    request = load_motion_plan_request(path, panda.model, strict=False)
    assert request.options.planner == "RRTConnect"
    assert [(w.line, "'planner_id'" in w.message) for w in request.warnings] == [(2, True)]
    with pytest.raises(InputError, match=r"'planner_id'.*--strict"):
        load_motion_plan_request(path, panda.model, strict=True)


def test_planner_ids_as_moveit_writes_them() -> None:
    assert planner_name("RRTConnectkConfigDefault") == "RRTConnect"
    assert planner_name("geometric::PRMstar") == "PRMstar"
    assert planner_name("BITstar") == "BITstar"


def test_goal_in_collision_is_reported_as_a_typed_failure(panda, tmp_path: Path) -> None:
    scene = scene_from_cell(panda)
    path = tmp_path / "r.yaml"
    path.write_text("group_name: arm\ngoal_constraints:\n  - joint_constraints:\n"
                    "      - {joint_name: panda_joint4, position: -0.1}\n"
                    "      - {joint_name: panda_joint2, position: 1.7}\n"
                    "      - {joint_name: panda_joint6, position: 3.7}\n")
    blocker = tmp_path / "s.yaml"
    blocker.write_text("world:\n  collision_objects:\n    - {header: {frame_id: world}, id: wall,"
                       " primitives: [{type: 1, dimensions: [0.1, 2, 2]}],"
                       " primitive_poses: [{position: {x: 0.9, y: 0, z: 0.5}, orientation: {w: 1}}]}\n")
    load_planning_scene(blocker, panda.model).apply(scene)
    report = plan_request_file(scene, load_motion_plan_request(path, panda.model))
    assert not report.success
    assert report.error_kind in ("GoalInCollisionError", "InvalidStateError")
    assert report.message


def test_alias_bomb_is_refused_by_the_yaml_limits(panda, tmp_path: Path) -> None:
    rows = ["a: &a [x, x, x, x, x, x, x, x, x, x]"]
    for i in range(1, 8):
        rows.append(f"{'abcdefgh'[i]}: &{'abcdefgh'[i]} [" + ", ".join([f"*{'abcdefgh'[i - 1]}"] * 10) + "]")
    path = tmp_path / "bomb.yaml"
    path.write_text("\n".join(rows) + "\n")
    with pytest.raises(YamlError, match="alias"):
        load_planning_scene(path, panda.model)


def test_cone_mesh_covers_the_cone(panda, tmp_path: Path) -> None:
    from taskrunner.moveit.geometry import _cone

    vertices, triangles = _cone(0.1, 0.05)
    # Every point of the cone's base circle lies inside the polygon of the mesh's rim.
    rim = vertices[:-2, :2]
    for angle in np.linspace(0, 2 * math.pi, 97):
        point = 0.05 * np.array([math.cos(angle), math.sin(angle)])
        edges = np.roll(rim, -1, axis=0) - rim
        cross = edges[:, 0] * (point[1] - rim[:, 1]) - edges[:, 1] * (point[0] - rim[:, 0])
        assert np.all(cross >= -1e-12)
    assert triangles.shape == (64, 3)


def test_robowflex_form_of_motionbenchmaker_files_is_read(panda) -> None:
    scene = scene_from_cell(panda)
    loaded = load_planning_scene(FIXTURES / "robowflex_scene.yaml", panda.model, strict=True)
    assert loaded.is_diff
    assert loaded.apply(scene) == ["Can1", "side_cap", "rock", "shard"]
    assert np.allclose(scene.object_pose("Can1").xyz, (0.45, 0.35, 0.07))  # moved
    assert np.allclose(scene.object_pose("side_cap").xyz, (0.6, -0.3, 0.3))
    rock = scene.object("rock").shape
    assert isinstance(rock, Mesh) and rock.path == FIXTURES / "tetra.stl" and rock.scale == (0.1,) * 3
    assert isinstance(scene.object("shard").shape, Mesh)
    assert scene.collision_allowed("Can1", "panda_hand")
    request = load_motion_plan_request(FIXTURES / "robowflex_request.yaml", panda.model, strict=True)
    assert request.options.planning_time == 10 and request.velocity_scaling == 0.8
    report = plan_request_file(scene, request, seed=0)
    assert report.success, report.message


def test_a_moveit_group_name_maps_to_the_group_with_the_goals_joints(panda, tmp_path: Path) -> None:
    text = (FIXTURES / "joint_goal_request.yaml").read_text().replace("group_name: arm",
                                                                      "group_name: panda_arm")
    path = tmp_path / "r.yaml"
    path.write_text(text)
    request = load_motion_plan_request(path, panda.model, strict=False)
    assert request.group == "arm"
    assert ["'group_name'" in w.message and "'arm'" in w.message for w in request.warnings] == [True]
    with pytest.raises(InputError, match="group_name"):
        load_motion_plan_request(path, panda.model, strict=True)
