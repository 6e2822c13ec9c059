"""``run-task plan``: MoveIt request and scene files from the command line."""

from __future__ import annotations

import json
from pathlib import Path

from taskrunner.cli import EXIT_INVALID, EXIT_OK, EXIT_PLANNING, main

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures" / "moveit_scenes"


def test_plan_command_reports_success_as_json(capsys) -> None:
    code = main(["plan", "panda", "--scene", str(FIXTURES / "ros1_table_scene.yaml"),
                 "--request", str(FIXTURES / "joint_goal_request.yaml"), "--json"])
    out = json.loads(capsys.readouterr().out)
    assert code == EXIT_OK
    assert out["success"] is True and out["planner"] == "RRTConnect" and out["group"] == "arm"
    assert out["duration"] > 0 and out["path_length"] > 0 and out["warnings"] == []


def test_plan_command_names_file_line_and_field_of_a_bad_scene(capsys) -> None:
    code = main(["plan", "panda", "--scene", str(FIXTURES / "bad" / "cylinder_dims.yaml"),
                 "--request", str(FIXTURES / "joint_goal_request.yaml")])
    err = capsys.readouterr().err
    assert code == EXIT_INVALID
    assert "cylinder_dims.yaml:7: 'world.collision_objects[0].primitives[0].dimensions'" in err


def test_plan_command_fails_with_the_planning_code_when_the_goal_collides(tmp_path: Path,
                                                                           capsys) -> None:
    scene = tmp_path / "scene.yaml"
    scene.write_text("world:\n  collision_objects:\n    - {header: {frame_id: world}, id: block,"
                     " primitives: [{type: 1, dimensions: [0.3, 0.3, 0.3]}],"
                     " primitive_poses: [{position: {x: 0.5, y: -0.2, z: 0.3}, orientation: {w: 1}}]}\n")
    code = main(["plan", "panda", "--scene", str(scene), "--request",
                 str(FIXTURES / "pose_goal_request.yaml")])
    out = capsys.readouterr().out
    assert code == EXIT_PLANNING
    assert "failed (" in out


def test_workcell_loads_a_scene_file_and_plans_a_request_file() -> None:
    import taskrunner

    cell = taskrunner.load_workcell("panda")
    added = cell.load_planning_scene(FIXTURES / "attached_scene.yaml")
    assert added == ["post", "held_box"] and cell.scene.object("held_box").attached
    plan = cell.plan_request(FIXTURES / "pose_goal_request.yaml",
                             scene=FIXTURES / "ros1_table_scene.yaml", seed=2)
    assert plan.group == "arm" and plan.duration > 0
    assert "held_box" not in cell.scene  # the full scene replaced the objects


def test_the_moveit_file_api_is_pinned() -> None:
    import taskrunner.moveit

    assert sorted(taskrunner.moveit.__all__) == [
        "MotionPlanRequestFile", "NameMap", "ObjectEdit", "PlanReport", "PlanningSceneFile",
        "apply_scene_file", "load_motion_plan_request", "load_planning_scene", "plan_files", "plan_request_file",
        "planner_name"]
