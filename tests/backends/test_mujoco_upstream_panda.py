"""Tasks on moveit_resources' Panda as its ROS 1 config package has it (a clone of the
public repository, ``tests/robot/fixtures/public``: no ``<inertial>`` on any link) pass on
the mujoco backend without edits: its links are weighed from their collision geometry.
Before that they weighed 1 g each and the fingers shoved the object away.

Skipped where mujoco is not installed (``pip install -e '.[mujoco]'``).
"""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from taskrunner.robot.cell import load_cell
from taskrunner.robot.packages import example_robot_data_dir
from taskrunner.tasks.loader import load_task

mujoco = pytest.importorskip("mujoco", reason="the mujoco backend needs: pip install "
                             "-e '.[mujoco]'")

from taskrunner.backends.physics import MujocoBackend, MujocoOptions, physics_cell  # noqa: E402
from taskrunner.planning.service import InProcessPlanner  # noqa: E402
from taskrunner.runtime.runner import Runner, RunOptions  # noqa: E402

TESTS = Path(__file__).parents[1]
WORKSPACE = TESTS / "robot" / "fixtures" / "public" / "ros1_ws"
FIXTURE = Path(__file__).parent / "fixtures" / "upstream_panda"


@pytest.fixture(autouse=True)
def _no_environment_packages(monkeypatch: pytest.MonkeyPatch) -> None:
    for name in ("ROS_PACKAGE_PATH", "AMENT_PREFIX_PATH", "TASKRUNNER_PACKAGE_PATH",
                 "TASKRUNNER_ALLOW_MISSING_MESHES"):
        monkeypatch.delenv(name, raising=False)


@pytest.fixture()
def upstream(tmp_path: Path) -> Path:
    """The clone in ``ws/src`` with its meshes (the same Franka meshes, from
    example-robot-data), and the cells and tasks beside it."""
    shutil.copytree(WORKSPACE, tmp_path / "ws")
    share = example_robot_data_dir()
    assert share is not None
    shutil.copytree(share / "robots" / "panda_description" / "meshes",
                    tmp_path / "ws" / "src" / "moveit_resources" / "panda_description" / "meshes")
    shutil.copytree(FIXTURE, tmp_path / "upstream")
    return tmp_path / "upstream"


@pytest.mark.parametrize(("task", "obj", "target", "allowed"), [
    ("pick_place", "cube", (0.45, -0.2, 0.771), 0.003),
    ("handoff", "bar", (0.25, -0.1, 0.7635), 0.006),
])
def test_upstream_panda_tasks_pass_on_mujoco_without_edits(upstream, tmp_path, caplog, task,
                                                          obj, target, allowed):
    spec = load_task(upstream / "tasks" / f"{task}.yaml")
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state(), strict=True))
    backend = MujocoBackend(cell.model.joint_names, physics_cell(cell), start,
                            MujocoOptions(cache_dir=str(tmp_path / "cache")))
    try:
        record = Runner(spec, cell, backend, InProcessPlanner(),
                        RunOptions(backend_name="mujoco")).run()
        poses = backend.object_poses()
    finally:
        backend.close()
    assert record.status == "succeeded", record.error
    assert record.exit_code == 0
    reached = np.asarray(poses[obj].xyz)
    assert np.linalg.norm(reached - np.asarray(target)) < allowed, reached
    weighed = [r.getMessage() for r in caplog.records if "without <inertial>" in r.getMessage()]
    assert weighed and "panda_leftfinger" in weighed[0] and "panda_link1" in weighed[0]
