"""What a MoveIt config says about planning: each group's default planner
(ompl_planning.yaml) is the planner of a request that names none; the Cartesian limits
(pilz_cartesian_limits.yaml) are read, checked and reported."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from taskrunner.errors import YamlError
from taskrunner.planning.planner import MotionPlanner
from taskrunner.planning.request import JointGoal, NamedGoal, PlannerOptions, PlanRequest, group_planner
from taskrunner.robot import load_robot
from taskrunner.robot.cell import load_cell_or_robot
from taskrunner.robot.moveit_yaml import (
    OmplGroupSettings,
    ompl_planner_name,
    read_pilz_cartesian_limits_yaml,
)
from taskrunner.scene import scene_from_cell

CONFIG = Path(__file__).resolve().parent / "fixtures" / "moveit" / "src" / "arm3_ros2_moveit_config"


@pytest.fixture(autouse=True)
def _no_ros_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    for name in ("TASKRUNNER_PACKAGE_PATH", "ROS_PACKAGE_PATH", "AMENT_PREFIX_PATH",
                 "TASKRUNNER_STRICT", "TASKRUNNER_COLLISION"):
        monkeypatch.delenv(name, raising=False)


def _copy(tmp_path: Path) -> Path:
    """The ROS 2 config next to its description package (found as a sibling)."""
    shutil.copytree(CONFIG.parent / "arm3_description", tmp_path / "arm3_description")
    return Path(shutil.copytree(CONFIG, tmp_path / CONFIG.name))


@pytest.mark.parametrize(("written", "name"), [
    ("geometric::RRTConnect", "RRTConnect"), ("RRTConnectkConfigDefault", "RRTConnect"),
    ("PRMkConfigDefault", "PRM"), ("geometric::BITstar", "BITstar"), ("KPIECE1", "KPIECE1"),
    ("BiTRRTkConfigDefault", "BiTRRT"),
])
def test_moveit_planner_ids_map_to_planner_names(written: str, name: str):
    assert ompl_planner_name(written) == name


def test_a_request_naming_no_planner_uses_the_groups_default_from_ompl_planning_yaml():
    cell = load_cell_or_robot(CONFIG)
    model = cell.model
    assert group_planner(model.group("hand")) == "PRM"  # its first planner_configs entry
    assert group_planner(model.group("arm")) == "RRTConnect"  # its default_planner_config
    planner = MotionPlanner(scene_from_cell(cell))
    hand = planner.plan(PlanRequest("hand", NamedGoal("open"), options=PlannerOptions(seed=1)))
    assert hand.planner == "PRM"
    arm = planner.plan(PlanRequest("arm", NamedGoal("ready")))
    assert arm.planner == "RRTConnect"
    # A planner named in the request wins.
    chosen = planner.plan(PlanRequest("hand", JointGoal({"finger_joint1": 0.01}),
                                      options=PlannerOptions(planner="RRT")))
    assert chosen.planner == "RRT"


def test_a_default_planner_the_bindings_lack_is_a_warning_and_rrtconnect_plans(tmp_path: Path):
    config = _copy(tmp_path)
    ompl = config / "config" / "ompl_planning.yaml"
    text = ompl.read_text().replace("PRMkConfigDefault:\n    type: geometric::PRM",
                                    "PRMkConfigDefault:\n    type: geometric::BiTRRT")
    ompl.write_text(text)
    model = load_robot(config)
    line = text.splitlines().index("hand:") + 1
    assert (f"{ompl}:{line}: group 'hand': default planner 'geometric::BiTRRT' is not available "
            "(available: RRTConnect, RRT,") in "\n".join(model.warnings)
    assert model.group("hand").planner is not None and model.group("hand").planner.planner is None
    assert group_planner(model.group("hand")) == "RRTConnect"


def test_group_settings_without_a_planner_fall_back_to_rrtconnect():
    settings = OmplGroupSettings(None, None, {}, {}, None)
    assert settings.planner is None


# ----------------------------------------------------------------- pilz_cartesian_limits.yaml
PILZ = """cartesian_limits:
  max_trans_vel: 1.0
  max_trans_acc: 2.25
  max_trans_dec: -5.0
  max_rot_vel: 1.57
"""


def test_cartesian_limits_are_read_and_reported(tmp_path: Path):
    config = _copy(tmp_path)
    (config / "config" / "pilz_cartesian_limits.yaml").write_text(PILZ)
    cell = load_cell_or_robot(config)
    [inst] = cell.model.instances
    lines = inst.describe_files()
    assert f"pilz_cartesian_limits: {config / 'config' / 'pilz_cartesian_limits.yaml'}" in lines
    assert ("note: Cartesian limits: translation 1 m/s, 2.25 m/s² up, 5 m/s² down; rotation "
            "1.57 rad/s (straight moves of the tool are slowed to them)") in lines
    assert inst.cartesian_limits is not None and inst.cartesian_limits.max_trans_vel == 1.0
    assert cell.model.warnings == [w for w in cell.model.warnings if "pilz" not in w]


def test_cartesian_limits_in_ros2_parameter_form_are_read(tmp_path: Path):
    path = tmp_path / "pilz_cartesian_limits.yaml"
    path.write_text("/**:\n  ros__parameters:\n    robot_description_planning:\n" + "".join(
        "      " + line + "\n" for line in PILZ.splitlines()))
    limits = read_pilz_cartesian_limits_yaml(path)
    assert (limits.max_trans_vel, limits.max_trans_acc, limits.max_trans_dec,
            limits.max_rot_vel) == (1.0, 2.25, 5.0, 1.57)


@pytest.mark.parametrize(("edit", "message", "line"), [
    (("  max_rot_vel: 1.57\n", ""), "'max_rot_vel' is required", 2),
    (("max_trans_vel: 1.0", "max_trans_vel: fast"), "'max_trans_vel' must be a number (got 'fast')", 2),
    (("max_trans_acc: 2.25", "max_trans_acc: -2.25"), "'max_trans_acc' must be > 0 (got -2.25)", 3),
    (("max_trans_dec: -5.0", "max_trans_dec: 0"), "'max_trans_dec' must be a non-zero finite number (got 0.0)", 4),
    (("max_rot_vel", "max_rot_speed"), "unknown field 'max_rot_speed' (expected one of max_trans_vel, "
                                        "max_trans_acc, max_trans_dec, max_rot_vel)", 5),
    (("cartesian_limits:", "limits:"), "expected 'cartesian_limits: {max_trans_vel, max_trans_acc, "
                                       "max_trans_dec, max_rot_vel}'", 1),
])
def test_bad_cartesian_limits_are_errors_at_their_line(tmp_path: Path, edit, message: str, line: int):
    path = tmp_path / "pilz_cartesian_limits.yaml"
    path.write_text(PILZ.replace(*edit))
    with pytest.raises(YamlError) as info:
        read_pilz_cartesian_limits_yaml(path)
    assert str(info.value) == f"{path}:{line}: {message}"


def test_a_broken_cartesian_limits_file_is_a_warning_when_loading(tmp_path: Path):
    config = _copy(tmp_path)
    pilz = config / "config" / "pilz_cartesian_limits.yaml"
    pilz.write_text(PILZ.replace("max_trans_vel: 1.0", "max_trans_vel: -1.0"))
    model = load_robot(config)
    assert (f"{pilz}:2: 'max_trans_vel' must be > 0 (got -1.0); pilz_cartesian_limits.yaml "
            "not used") in model.warnings


def _panda_with_limits(tmp_path: Path, robots_dir: Path, limits: str | None) -> Path:
    """The shipped Panda's manifest, its files by absolute path, with a pilz file or not."""
    panda = robots_dir / "panda"
    manifest = (panda / "robot.yaml").read_text()
    for key in ("srdf", "kinematics", "joint_limits"):
        manifest = manifest.replace(f"{key}: config/", f"{key}: {panda / 'config'}/")
    if limits is not None:
        (tmp_path / "pilz_cartesian_limits.yaml").write_text(limits)
        manifest += "pilz_cartesian_limits: pilz_cartesian_limits.yaml\n"
    (tmp_path / "robot.yaml").write_text(manifest)
    return tmp_path


def test_a_straight_move_is_slowed_to_the_cartesian_limits(tmp_path: Path, robots_dir: Path,
                                                           example_robot_data):
    from taskrunner.planning.cartesian_limits import measure_cartesian_motion
    from taskrunner.workcell import load_workcell

    def straight_move(folder: Path):  # type: ignore[no-untyped-def]
        cell = load_workcell(folder)
        cell.scene.set_state(cell.model.named_state("arm", "ready"))
        plan = cell.plan_cartesian("arm", by=(0.1, 0.0, -0.1), frame="world")
        assert plan.complete
        tip = cell.model.group("arm").tip_link
        return plan, measure_cartesian_motion(cell.model, plan.trajectory, tip)

    (tmp_path / "free").mkdir()
    (tmp_path / "slow").mkdir()
    free, free_motion = straight_move(_panda_with_limits(tmp_path / "free", robots_dir, None))
    slow, slow_motion = straight_move(_panda_with_limits(tmp_path / "slow", robots_dir, PILZ.replace(
        "max_trans_vel: 1.0", "max_trans_vel: 0.05").replace("max_trans_acc: 2.25",
                                                             "max_trans_acc: 0.2")))
    assert free_motion.speed > 0.2  # the joint limits alone move the tool faster
    assert slow_motion.speed <= 0.05 * 1.02 and slow_motion.acceleration <= 0.2 * 1.02
    assert slow_motion.speed > 0.04  # slowed to the limit, not far below it
    assert slow.duration > 4 * free.duration
    np.testing.assert_allclose(slow.trajectory.positions[-1], free.trajectory.positions[-1],
                               atol=1e-9)  # the same line, only slower


def test_a_straight_move_of_a_task_is_slowed_to_the_cartesian_limits(tmp_path: Path,
                                                                      robots_dir: Path,
                                                                      example_robot_data):
    from taskrunner.workcell import run_task

    durations = {}
    for name, limits in (("free", None), ("slow", PILZ.replace("max_trans_vel: 1.0",
                                                                "max_trans_vel: 0.05"))):
        folder = tmp_path / name
        (folder / "robots" / "panda").mkdir(parents=True)
        _panda_with_limits(folder / "robots" / "panda", robots_dir, limits)
        (folder / "cells").mkdir()
        (folder / "cells" / "cell.yaml").write_text(
            "name: cell\nrobots:\n  - {name: panda, robot: robots/panda}\nstart: {arm: ready}\n")
        task = folder / "task.yaml"
        task.write_text("task: down\ncell: cells/cell.yaml\nsteps:\n"
                        "  - move: {group: arm, by: {xyz: [0, 0, -0.1], frame: world}}\n")
        result = run_task(task)
        assert result.status == "succeeded", result.error
        [planned] = [e for e in result.events if e.kind == "planned"]
        durations[name] = planned.data["duration"]
    # 10 cm at 0.05 m/s takes 2 s at least (the joint limits alone: well under a second).
    assert durations["free"] < 1.0 < 2.0 <= durations["slow"] < 6.0


def test_the_default_configurations_range_is_the_tree_step_and_zero_means_ours(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch):
    from ompl import geometric as og

    from taskrunner.planning import ompl_search
    from taskrunner.planning.request import DEFAULT_RANGE

    steps: list[float] = []
    original = og.RRTConnect.setRange

    def recorded(self, value):  # type: ignore[no-untyped-def]
        steps.append(value)
        return original(self, value)

    monkeypatch.setattr(og.RRTConnect, "setRange", recorded)
    plain = load_robot(CONFIG)  # range: 0.0, MoveIt's "the planner's default"
    assert plain.group("arm").planner is not None and plain.group("arm").planner.range == 0.0
    config = _copy(tmp_path)
    ompl = config / "config" / "ompl_planning.yaml"
    ompl.write_text(ompl.read_text().replace(
        "type: geometric::RRTConnect\n    range: 0.0", "type: geometric::RRTConnect\n    range: 0.35"))
    tuned = load_robot(config)
    assert tuned.group("arm").planner is not None and tuned.group("arm").planner.range == 0.35
    for model, expected in ((plain, DEFAULT_RANGE), (tuned, 0.35)):
        planner = MotionPlanner(scene_from_cell(load_cell_or_robot(
            CONFIG if model is plain else config)))
        planner.plan(PlanRequest("arm", NamedGoal("ready"), options=PlannerOptions(direct=False)))
        assert steps[-1] == pytest.approx(expected)
        # A range in the request wins over the file's.
        planner.plan(PlanRequest("arm", NamedGoal("ready"),
                                 options=PlannerOptions(direct=False, range=0.2)))
        assert steps[-1] == pytest.approx(0.2)
    assert ompl_search.DEFAULT_RANGE == DEFAULT_RANGE


@pytest.mark.parametrize("value", ["fast", "-1.0", "[1]"])
def test_a_bad_range_in_ompl_planning_yaml_names_its_line(tmp_path: Path, value: str):
    config = _copy(tmp_path)
    ompl = config / "config" / "ompl_planning.yaml"
    text = ompl.read_text().replace("type: geometric::RRTConnect\n    range: 0.0",
                                    f"type: geometric::RRTConnect\n    range: {value}")
    ompl.write_text(text)
    line = text.splitlines().index(f"    range: {value}") + 1
    # Like any bad ompl_planning.yaml: named with its line, and not used.
    model = load_robot(config)
    assert any(w.startswith(f"{ompl}:{line}: 'range' must be") and "not used" in w
               for w in model.warnings), model.warnings
    assert model.group("arm").planner is None


def test_a_negative_range_in_a_request_is_refused():
    with pytest.raises(ValueError, match="'range' must be a number >= 0"):
        PlannerOptions(range=-0.5)
