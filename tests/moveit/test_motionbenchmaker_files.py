"""MotionBenchMaker-style scene and request files, loaded as MoveIt loads them: joint states
naming joints the model does not move, start states a little outside their bounds."""

from __future__ import annotations

import json
import logging
from pathlib import Path

import numpy as np
import pytest

import taskrunner
from taskrunner.cli import EXIT_INVALID, EXIT_OK, EXIT_PLANNING, main
from taskrunner.errors import InputError, InvalidStateError, SceneError
from taskrunner.moveit import load_motion_plan_request, load_planning_scene, plan_files
from taskrunner.moveit.start_bounds import fix_start_bounds
from taskrunner.resources import resolve_cell
from taskrunner.robot.cell import load_cell_or_robot
from taskrunner.scene import Scene, scene_from_cell
from taskrunner.shapes import Box
from taskrunner.types import Pose

MBM = Path(__file__).resolve().parents[1] / "fixtures" / "motionbenchmaker"
UR5_ROBOTIQ = MBM / "ur5_robotiq"
KNUCKLES = ("robotiq_85_left_inner_knuckle_joint", "robotiq_85_left_finger_tip_joint",
            "robotiq_85_left_knuckle_joint", "robotiq_85_right_inner_knuckle_joint",
            "robotiq_85_right_finger_tip_joint", "robotiq_85_right_knuckle_joint")


@pytest.fixture(autouse=True)
def _not_strict(monkeypatch: pytest.MonkeyPatch) -> None:
    # `run-task --strict` sets TASKRUNNER_STRICT for its workers; undo it after each test.
    monkeypatch.setenv("TASKRUNNER_STRICT", "")


@pytest.fixture(scope="module")
def panda():
    return load_cell_or_robot(resolve_cell("panda"))


@pytest.fixture(scope="module")
def ur5():
    return load_cell_or_robot(resolve_cell("ur5"))


@pytest.fixture(scope="module")
def ur5_robotiq():
    return load_cell_or_robot(UR5_ROBOTIQ)


def assert_path_verified(scene: Scene, start: np.ndarray, names: tuple[str, ...],
                         rows: np.ndarray, step: float = 0.01) -> None:
    """Every state of the path, interpolated at ``step`` rad, within limits and free."""
    model = scene.robot
    columns = model.indices(names)
    states = []
    for a, b in zip(rows[:-1], rows[1:]):
        count = max(2, int(np.ceil(np.max(np.abs(b - a)) / step)) + 1)
        states += [a + (b - a) * t for t in np.linspace(0.0, 1.0, count)]
    assert states, "a path of at least two points"
    for row in states:
        q = np.array(start, dtype=float)
        q[columns] = row
        q = model.apply_mimic(q)
        assert model.within_limits(q, 1e-9), model.limit_violations(q)
        assert not scene.collisions(q), scene.collisions(q)


# ----------------------------------------------------------------------------- item 1: names
def test_a_joint_fixed_in_the_model_is_ignored_without_a_warning(ur5_robotiq) -> None:
    scene_file = load_planning_scene(MBM / "ur5_table_scene.yaml", ur5_robotiq.model, strict=True)
    request = load_motion_plan_request(MBM / "ur5_table_request.yaml", ur5_robotiq.model,
                                       strict=True)
    assert set(scene_file.state) == set(ur5_robotiq.model.joint_names)
    assert scene_file.state["elbow_joint"] == pytest.approx(1.5707)
    assert not any("knuckle" in str(w) for w in scene_file.warnings + request.warnings)


def test_joints_the_model_lacks_are_one_warning_naming_file_field_and_joints(ur5) -> None:
    scene_file = load_planning_scene(MBM / "ur5_table_scene.yaml", ur5.model)
    about = [w for w in scene_file.warnings if "does not have" in w.message]
    assert len(about) == 1
    warning = about[0]
    assert warning.path == MBM / "ur5_table_scene.yaml" and warning.line == 11
    assert "'robot_state.joint_state.name'" in warning.message
    assert all(repr(k) in warning.message for k in KNUCKLES)
    assert set(scene_file.state) == set(ur5.model.joint_names)


def test_strict_makes_joints_the_model_lacks_an_error(ur5) -> None:
    with pytest.raises(InputError) as info:
        load_motion_plan_request(MBM / "ur5_table_request.yaml", ur5.model, strict=True)
    assert info.value.path == MBM / "ur5_table_request.yaml" and info.value.line == 17
    assert "'start_state.joint_state.name'" in info.value.reason
    assert "'robotiq_85_left_knuckle_joint'" in info.value.reason


def test_a_mimic_joint_value_is_ignored_when_consistent_and_warned_when_not(
        panda, tmp_path: Path) -> None:
    consistent = tmp_path / "consistent.yaml"
    consistent.write_text("robot_state:\n  joint_state:\n    name: [panda_finger_joint1, "
                          "panda_finger_joint2]\n    position: [0.03, 0.03]\n")
    loaded = load_planning_scene(consistent, panda.model, strict=True)
    assert loaded.state == {"panda_finger_joint1": 0.03}
    inconsistent = tmp_path / "inconsistent.yaml"
    inconsistent.write_text("robot_state:\n  joint_state:\n    name: [panda_finger_joint1, "
                            "panda_finger_joint2]\n    position: [0.03, 0.01]\n")
    loaded = load_planning_scene(inconsistent, panda.model)
    (warning,) = loaded.warnings
    assert "'panda_finger_joint2' = 0.01, not 0.03" in warning.message and warning.line == 4
    scene = scene_from_cell(panda)
    loaded.apply(scene)
    assert scene.state[panda.model.joint("panda_finger_joint2").index] == pytest.approx(0.03)


def test_a_goal_on_a_joint_the_model_lacks_or_has_fixed_stays_an_error(ur5, ur5_robotiq,
                                                                      tmp_path: Path) -> None:
    text = (MBM / "ur5_table_request.yaml").read_text()
    bad = tmp_path / "request.yaml"
    bad.write_text(text.replace("- {joint_name: wrist_3_joint",
                                "- {joint_name: robotiq_85_left_knuckle_joint"))
    with pytest.raises(InputError, match="fixed in the model"):
        load_motion_plan_request(bad, ur5_robotiq.model)
    with pytest.raises(InputError, match="unknown joint 'robotiq_85_left_knuckle_joint'"):
        load_motion_plan_request(bad, ur5.model)


@pytest.mark.parametrize("robot", ["ur5", "ur5_robotiq"])
def test_run_task_plan_loads_the_files_unchanged_and_the_path_is_verified(robot: str,
                                                                          capsys) -> None:
    where = str(UR5_ROBOTIQ) if robot == "ur5_robotiq" else robot
    args = ["plan", where, "--scene", str(MBM / "ur5_table_scene.yaml"),
            "--request", str(MBM / "ur5_table_request.yaml")]
    assert main([*args, "--json"]) == EXIT_OK
    out = json.loads(capsys.readouterr().out)
    assert out["success"] is True and out["waypoints"] >= 2
    assert any("does not have" in w for w in out["warnings"]) == (robot == "ur5")
    cell = load_cell_or_robot(UR5_ROBOTIQ if robot == "ur5_robotiq" else resolve_cell("ur5"))
    report, _ = plan_files(cell, MBM / "ur5_table_request.yaml", MBM / "ur5_table_scene.yaml")
    assert report.success and report.result is not None and report.result.trajectory is not None
    scene = scene_from_cell(cell)
    load_planning_scene(MBM / "ur5_table_scene.yaml", cell.model).apply(scene)
    result = report.result
    assert_path_verified(scene, result.start, result.path.names, np.asarray(result.path.waypoints))
    assert_path_verified(scene, result.start, result.trajectory.names,
                         np.asarray(result.trajectory.positions))


def test_run_task_plan_strict_refuses_joints_the_model_lacks(monkeypatch, capsys) -> None:
    code = main(["plan", "ur5", "--strict", "--request", str(MBM / "ur5_table_request.yaml")])
    assert code == EXIT_INVALID
    assert "ur5_table_request.yaml:17: 'start_state.joint_state.name'" in capsys.readouterr().err


def test_workcell_plan_request_loads_the_files_unchanged_and_the_path_is_verified() -> None:
    cell = taskrunner.load_workcell(str(UR5_ROBOTIQ))
    plan = cell.plan_request(MBM / "ur5_table_request.yaml", scene=MBM / "ur5_table_scene.yaml",
                             strict=True)
    assert plan.group == "manipulator" and plan.duration > 0
    end = np.asarray(plan.end.positions)
    goal = [1.0, -1.2, 1.3, -1.7, -1.5707, 0.5]
    assert np.allclose(end[cell.model.indices(plan.path.names)], goal, atol=1e-3)
    start = np.asarray(plan.start.positions)
    assert_path_verified(cell.scene, start, plan.trajectory.names,
                         np.asarray(plan.trajectory.positions))


# ----------------------------------------------------------------------------- item 2: bounds
def test_a_start_just_outside_its_bound_is_moved_onto_it_as_moveit_does(panda, caplog) -> None:
    """MotionBenchMaker's Panda files: fingers at 0.065 m against a 0.04 m limit (0.025 m
    over, inside MoveIt's default 0.05); panda_joint7 2.6e-6 rad over (rounding: silent)."""
    cell = taskrunner.load_workcell("panda")
    with caplog.at_level(logging.WARNING, logger="taskrunner.moveit"):
        plan = cell.plan_request(MBM / "panda_fingers_request.yaml",
                                 scene=MBM / "panda_fingers_scene.yaml")
    moved = [r.getMessage() for r in caplog.records if "moved to the bound" in r.getMessage()]
    assert len(moved) == 1
    assert ("'panda_finger_joint1' = 0.065 is above its upper bound 0.04 by 0.025 m" in moved[0])
    start = np.asarray(plan.start.positions)
    model = cell.model
    assert start[model.joint("panda_finger_joint1").index] == pytest.approx(0.04)
    assert start[model.joint("panda_joint7").index] == pytest.approx(model.joint("panda_joint7").upper)
    assert_path_verified(cell.scene, start, plan.trajectory.names,
                         np.asarray(plan.trajectory.positions))


def test_a_start_beyond_the_allowance_is_refused_with_value_bound_and_excess(
        panda, tmp_path: Path, capsys) -> None:
    request = tmp_path / "request.yaml"
    request.write_text((MBM / "panda_fingers_request.yaml").read_text()
                       + "start_state_max_bounds_error: 0.01\n")
    code = main(["plan", "panda", "--scene", str(MBM / "panda_fingers_scene.yaml"),
                 "--request", str(request), "--json"])
    out = json.loads(capsys.readouterr().out)
    assert code == EXIT_PLANNING and out["success"] is False
    assert out["error_kind"] == "InvalidStateError"
    assert ("'panda_finger_joint1' = 0.065 is above its upper bound 0.04 by 0.025 m"
            in out["message"])
    assert "start_state_max_bounds_error (0.01" in out["message"]
    cell = taskrunner.load_workcell("panda")
    with pytest.raises(InvalidStateError, match="by 0.025 m"):
        cell.plan_request(MBM / "panda_fingers_request.yaml",
                          scene=MBM / "panda_fingers_scene.yaml", start_state_max_bounds_error=0.02)
    with pytest.raises(InvalidStateError, match=r"start_state_max_bounds_error \(0.01"):
        # the file's own allowance wins over the caller's
        cell.plan_request(request, scene=MBM / "panda_fingers_scene.yaml",
                          start_state_max_bounds_error=0.05)


def test_a_tiny_excess_is_accepted_even_with_no_allowance(panda) -> None:
    model = panda.model
    q = model.default_state()
    j7 = model.joint("panda_joint7")
    q[j7.index] = j7.upper + 2.6e-6
    fixed, moved = fix_start_bounds(model, q, 0.0)
    assert fixed[j7.index] == j7.upper and moved == []
    q[j7.index] = j7.upper + 2e-3
    with pytest.raises(InvalidStateError) as info:
        fix_start_bounds(model, q, 0.0)
    assert f"bound {j7.upper:.10g} by 0.002 rad" in str(info.value)


def test_a_joint_goal_just_outside_its_bound_aims_at_the_bound(panda) -> None:
    request = load_motion_plan_request(MBM / "panda_fingers_request.yaml", panda.model)
    scene = scene_from_cell(panda)
    plan_request = request.plan_request(scene)
    goal = plan_request.goal
    values = dict(goal.values)  # type: ignore[union-attr]
    assert values["panda_joint7"] == panda.model.joint("panda_joint7").upper


# ----------------------------------------------------------------------------- item 3: ids
def test_an_object_named_like_a_robot_frame_loads_and_plans(ur5) -> None:
    """'base' is a geometry-free frame of the UR5; object ids are their own namespace."""
    scene = scene_from_cell(ur5)
    loaded = load_planning_scene(MBM / "ur5_base_object_scene.yaml", ur5.model, strict=True)
    loaded.apply(scene)
    assert "base" in scene.object_names
    # 'header.frame_id: base' is the robot's frame (MoveIt looks robot frames up first).
    expected = scene.to_world(Pose(xyz=(0.5, 0.0, 0.5), frame="base")).translation
    assert np.allclose(scene.object_pose("marker").xyz, expected)
    assert np.allclose(expected, (-0.5, 0.0, 0.5), atol=1e-9)
    # The ACM entry 'base' covers the object (the link has no geometry to allow).
    assert scene.collision_allowed("base", "table")
    report, _ = plan_files(ur5, MBM / "ur5_table_request.yaml", MBM / "ur5_base_object_scene.yaml")
    assert report.success and report.result is not None and report.result.trajectory is not None
    assert_path_verified(scene, report.result.start, report.result.trajectory.names,
                         np.asarray(report.result.trajectory.positions))


def test_an_object_may_not_take_the_name_of_a_link_with_geometry(ur5) -> None:
    scene = scene_from_cell(ur5)
    with pytest.raises(SceneError, match="'shoulder_link' is a link of the robot with collision"):
        scene.add_object("shoulder_link", Box((0.1, 0.1, 0.1)), Pose(xyz=(1.0, 0.0, 0.0)))
    scene.add_object("tool0", Box((0.1, 0.1, 0.1)), Pose(xyz=(1.0, 0.0, 0.0)))
    assert not scene.collisions()


# ----------------------------------------------------------------------------- item 4: --json
def test_plan_json_prints_an_invalid_file_as_json_with_file_line_and_exit_code(capsys) -> None:
    bad = Path(__file__).resolve().parents[1] / "fixtures" / "moveit_scenes" / "bad"
    code = main(["plan", "panda", "--scene", str(bad / "cylinder_dims.yaml"), "--request",
                 str(MBM / "panda_fingers_request.yaml"), "--json"])
    out = json.loads(capsys.readouterr().out)
    assert code == EXIT_INVALID == out["exit_code"]
    assert out["success"] is False and out["error_kind"] == "InputError"
    assert out["file"] == str(bad / "cylinder_dims.yaml") and out["line"] == 7
    assert "'world.collision_objects[0].primitives[0].dimensions'" in out["message"]


def test_plan_json_prints_strict_and_usage_errors_as_json(capsys) -> None:
    code = main(["plan", "ur5", "--strict", "--request", str(MBM / "ur5_table_request.yaml"),
                 "--json"])
    out = json.loads(capsys.readouterr().out)
    assert code == EXIT_INVALID and out["line"] == 17 and "does not have" in out["message"]
    code = main(["plan", "ur5", "--json"])
    out = json.loads(capsys.readouterr().out)
    assert code == 2 and out["error_kind"] == "UsageError" and "--request" in out["message"]
