"""The SO-101's pick-and-place on the physics backend: the moving jaw squeezes the cube
against the fixed jaw and friction alone carries it (grasp_mode friction, the default).

Skipped where mujoco is not installed (``pip install -e '.[mujoco]'``).
"""

from __future__ import annotations

import pytest

from taskrunner.resources import DATA_ROOT
from taskrunner.robot.cell import load_cell
from taskrunner.tasks.loader import load_task

mujoco = pytest.importorskip("mujoco", reason="the mujoco backend needs: pip install "
                             "-e '.[mujoco]'")

from taskrunner.backends.physics import MujocoBackend, MujocoOptions, physics_cell  # noqa: E402
from taskrunner.planning.service import InProcessPlanner  # noqa: E402
from taskrunner.runtime.runner import Runner, RunOptions  # noqa: E402


def test_so101_pick_place_carries_the_cube_by_friction_to_its_spot(tmp_path):
    spec = load_task(DATA_ROOT / "tasks" / "pick_place_so101.yaml", {})
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state()))
    backend = MujocoBackend(cell.model.joint_names, physics_cell(cell), start,
                            MujocoOptions(cache_dir=str(tmp_path / "cache"), speed=50.0))
    try:
        record = Runner(spec, cell, backend, InProcessPlanner(),
                        RunOptions(backend_name="mujoco", runs_dir=tmp_path / "runs")).run()
        cube = backend.object_poses()["cube"]
    finally:
        backend.close()
    assert record.status == "succeeded", record.error  # the task's expect: checked
    # Where physics left it: on the table (its centre 12.5 mm up), within 5 mm of the spot.
    assert cube.xyz == pytest.approx((0.22, -0.05, 0.7625), abs=0.005)
    physics = [e for e in record.events if e.kind == "physics"]
    assert physics and not any(e.data.get("grasps") for e in physics)  # no weld held it


def test_so101_pair_hands_the_bar_over_and_lays_it_down_by_friction(tmp_path):
    spec = load_task(DATA_ROOT / "tasks" / "handoff_so101.yaml", {})
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state()))
    backend = MujocoBackend(cell.model.joint_names, physics_cell(cell), start,
                            MujocoOptions(cache_dir=str(tmp_path / "cache"), speed=50.0))
    try:
        record = Runner(spec, cell, backend, InProcessPlanner(),
                        RunOptions(backend_name="mujoco", runs_dir=tmp_path / "runs")).run()
        bar = backend.object_poses()["bar"]
    finally:
        backend.close()
    assert record.status == "succeeded", record.error
    # Lying on its side (its centre 12.5 mm up) at the spot in front of the right arm.
    assert bar.xyz == pytest.approx((0.10, 0.0, 0.7625), abs=0.015)
    assert bar.xyz[2] == pytest.approx(0.7625, abs=0.002)
