"""Public MoveIt config packages loaded from a clone of their repository as they are, with
no manifest and no flag: moveit_resources' Panda in its ROS 2 layout (``.setup_assistant``
naming ``urdf/panda.urdf``, whose meshes are ``file://$(find …)``) and in its ROS 1 layout
(``launch/planning_context.launch`` running xacro on ``panda_arm_hand.urdf.xacro``), each
with its description a sibling package of the workspace (``fixtures/public``, origin and
licence in its README). The mesh files are binary and not in the fixture: the tests copy
the same Franka meshes from example-robot-data to the paths the URDFs name."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

import taskrunner
from taskrunner.cli import main
from taskrunner.errors import MissingMeshError
from taskrunner.robot import load_robot
from taskrunner.robot.packages import example_robot_data_dir

PUBLIC = Path(__file__).parent / "fixtures" / "public"
_SHARE = example_robot_data_dir()
assert _SHARE is not None, "example-robot-data (a dependency) is not installed"
MESHES = _SHARE / "robots" / "panda_description" / "meshes"
ARM = tuple(f"panda_joint{i}" for i in range(1, 8))
READY = dict(zip(ARM, (0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785), strict=True))
# The URDF read: ROS 2, the Setup Assistant's config/panda.urdf.xacro (what the package's
# launch files and MoveItConfigsBuilder read; it includes the description's
# urdf/panda.urdf.xacro); ROS 1, what planning_context.launch runs xacro on.
LAYOUTS = {"ros2": ("ros2_ws", "ROS 2 config package (.setup_assistant)",
                    "panda_moveit_config/config/panda.urdf.xacro"),
           "ros1": ("ros1_ws", "ROS 1 config package (launch/planning_context.launch)",
                    "panda_description/urdf/panda_arm_hand.urdf.xacro")}


@pytest.fixture(autouse=True)
def _no_environment_packages(monkeypatch: pytest.MonkeyPatch) -> None:
    """Only the workspace provides the description package."""
    for name in ("ROS_PACKAGE_PATH", "AMENT_PREFIX_PATH", "TASKRUNNER_PACKAGE_PATH",
                 "TASKRUNNER_ALLOW_MISSING_MESHES", "TASKRUNNER_STRICT"):
        monkeypatch.delenv(name, raising=False)


def clone(tmp_path: Path, layout: str, meshes: bool = True) -> Path:
    """The repository's clone in ``ws/src``; its config package."""
    src = tmp_path / "ws" / "src"
    shutil.copytree(PUBLIC / LAYOUTS[layout][0] / "src", src)
    description = src / "moveit_resources" / "panda_description"
    if meshes:
        shutil.copytree(MESHES, description / "meshes")
    return src / "moveit_resources" / "panda_moveit_config"


def assert_path_verified(cell: taskrunner.Workcell, plan: taskrunner.Plan) -> None:
    """Every state of the timed path, interpolated at 0.01 rad, within limits and free."""
    model, scene = cell.model, cell.scene
    start = np.asarray(plan.start.positions)
    columns = model.indices(plan.trajectory.names)
    rows = np.asarray(plan.trajectory.positions)
    checked = 0
    for a, b in zip(rows[:-1], rows[1:], strict=True):
        for t in np.linspace(0.0, 1.0, max(2, int(np.ceil(np.max(np.abs(b - a)) / 0.01)) + 1)):
            q = start.copy()
            q[columns] = a + (b - a) * t
            q = model.apply_mimic(q)
            assert model.within_limits(q), model.limit_violations(q)
            assert not scene.collisions(q), scene.collisions(q)
            checked += 1
    assert checked > 10


@pytest.mark.parametrize("layout", sorted(LAYOUTS))
def test_run_task_info_loads_the_clone_with_no_manifest_and_no_flag(tmp_path, capsys, layout):
    config = clone(tmp_path, layout)
    assert main(["info", str(config)]) == 0
    out = capsys.readouterr().out
    _, loaded_as, urdf = LAYOUTS[layout]
    assert f"loaded as: {loaded_as}" in out
    assert f"urdf: {config.parent / urdf}" in out
    assert "panda_arm: 7 joints, tip panda_link8; poses: extended, ready, transport" in out
    assert "hand: group hand on panda_link8 (arm panda_arm)" in out


@pytest.mark.parametrize("layout", sorted(LAYOUTS))
def test_workcell_loads_the_clone_and_plans_a_verified_motion(tmp_path, layout):
    config = clone(tmp_path, layout)
    cell = taskrunner.load_workcell(config)
    model = cell.model
    assert model.group("panda_arm").joint_names == ARM
    # Every link with a mesh got its collision geometry from the workspace's meshes.
    assert model.collision_model.ngeoms == 11
    assert model.joint("panda_joint1").max_velocity == pytest.approx(2.175)  # joint_limits.yaml
    plan = cell.plan("panda_arm", start=READY,
                     joints={"panda_joint1": 0.9, "panda_joint4": -1.9, "panda_joint6": 2.0})
    end = dict(zip(plan.end.names, plan.end.positions, strict=True))
    assert end["panda_joint1"] == pytest.approx(0.9, abs=1e-6)
    assert end["panda_joint4"] == pytest.approx(-1.9, abs=1e-6)
    assert plan.duration > 0
    assert_path_verified(cell, plan)


@pytest.mark.parametrize("layout", sorted(LAYOUTS))
def test_a_clone_without_its_meshes_is_refused_naming_the_folders_searched(tmp_path, layout):
    config = clone(tmp_path, layout, meshes=False)
    with pytest.raises(MissingMeshError) as info:
        load_robot(config)
    message = str(info.value)
    description = config.parent / "panda_description"
    assert "mesh file(s) of robot 'moveit_resources_panda' cannot be found" in message
    assert f"looked at {description / 'meshes' / 'collision' / 'link0.stl'}" in message
    assert "--allow-missing-meshes" in message


def test_the_setup_assistant_urdf_entry_is_read_through_xacro_as_moveit_reads_it(tmp_path):
    """Without config/panda.urdf.xacro, MoveItConfigsBuilder reads the .setup_assistant's
    URDF entry, urdf/panda.urdf, through xacro whatever its extension: its meshes are
    'file://$(find moveit_resources_panda_description)/meshes/...', found here too."""
    config = clone(tmp_path, "ros2")
    (config / "config" / "panda.urdf.xacro").unlink()
    model = load_robot(config)
    files = dict(model.instances[0].files)
    assert files["urdf"] == config.parent / "panda_description" / "urdf" / "panda.urdf"
    assert model.collision_model.ngeoms == 11
    assert model.group("panda_arm").joint_names == ARM
