"""The mujoco (physics) backend: objects really grasped, carried and released.

Skipped where mujoco is not installed (``pip install -e '.[mujoco]'``), except the
test that taskrunner says how to get it.
"""

from __future__ import annotations

import math

import numpy as np
import pytest

from taskrunner.resources import resolve_task
from taskrunner.robot.cell import load_cell
from taskrunner.tasks.loader import load_task

mujoco = pytest.importorskip("mujoco", reason="the mujoco backend needs: pip install "
                             "-e '.[mujoco]'")

from taskrunner.backends.physics import (  # noqa: E402
    MujocoBackend,
    MujocoOptions,
    ObjectPhysics,
    physics_cell,
)
from taskrunner.planning.service import InProcessPlanner  # noqa: E402
from taskrunner.runtime.runner import Runner, RunOptions  # noqa: E402


def run_on_mujoco(task: str, options: MujocoOptions | None = None, tmp_path=None):
    spec = load_task(resolve_task(task), {})
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state()))
    cache = None if tmp_path is None else str(tmp_path)
    options = options or MujocoOptions(cache_dir=cache)
    backend = MujocoBackend(cell.model.joint_names, physics_cell(cell), start, options)
    try:
        runner = Runner(spec, cell, backend, InProcessPlanner(),
                        RunOptions(backend_name="mujoco"))
        record = runner.run()
        return record, backend.object_poses(), backend
    finally:
        backend.close()


def tilt_deg(quat) -> float:
    """Angle between the object's z axis and the world's (deg)."""
    x, y, z, w = quat
    zz = 1 - 2 * (x * x + y * y)
    return math.degrees(math.acos(max(-1.0, min(1.0, zz))))


@pytest.mark.parametrize(("task", "target"), [
    ("pick_place", (0.14, -0.12, 0.7635)),        # the servo arm, 2.5 cm cube
    ("pick_place_panda", (0.45, -0.2, 0.771)),    # the Panda, 4 cm cube
])
def test_pick_place_on_mujoco_leaves_the_cube_within_1cm_and_5deg(task, target, tmp_path):
    record, poses, backend = run_on_mujoco(task, tmp_path=tmp_path)
    assert record.status == "succeeded", record.error
    cube = poses["cube"]
    error = np.linalg.norm(np.subtract(cube.xyz, target))
    assert error < 0.01, f"cube at {cube.xyz}, {1e3 * error:.1f} mm from {target}"
    assert tilt_deg(cube.quat) < 5.0
    # It was really carried: lifted well above where it started, and ended on the table.
    heights = [s.objects["cube"].xyz[2] for s in backend.history()]
    assert max(heights) > target[2] + 0.03
    assert backend.sim_time > 5.0


def test_a_cube_too_heavy_to_hold_slips_out_at_the_pick_with_file_and_line(tmp_path):
    # 10 kg between fingers squeezing with 20 N each at friction 1: it cannot be lifted.
    options = MujocoOptions(cache_dir=str(tmp_path),
                            objects={"cube": ObjectPhysics(mass=10.0)})
    record, poses, _ = run_on_mujoco("pick_place_panda", options)
    assert record.status == "failed"
    assert "pick_place_panda.yaml:14" in record.error  # the pick step
    assert "slipped out of the gripper" in record.error
    assert poses["cube"].xyz[2] < 0.78  # still on the table


def test_a_gripper_closed_to_the_wrong_width_fails_its_pick_before_moving(tmp_path):
    # Fingers that stop 1 cm short of the cube on each side never hold it: the pick
    # refuses the grasp before the arm moves to it (as check does), not at the lift.
    options = MujocoOptions(cache_dir=str(tmp_path),
                            objects={"cube": ObjectPhysics(mass=0.05)})
    spec = load_task(resolve_task("pick_place_panda"), {})
    cell = load_cell(spec.cell)
    start = dict(zip(cell.model.joint_names, cell.start_state()))
    backend = MujocoBackend(cell.model.joint_names, physics_cell(cell), start, options)
    # The 'closed' pose of this hand, for this test only, leaves 6 cm between the fingers.
    cell.model.named_states["hand"]["closed"] = {"panda_finger_joint1": 0.03}
    try:
        record = Runner(spec, cell, backend, InProcessPlanner()).run()
    finally:
        backend.close()
    assert record.status == "failed"
    assert "pick_place_panda.yaml:14" in record.error
    assert "the fingers close to 60 mm" in record.error
    assert "stays 10.0 mm from 'cube' at closed width" in record.error


def test_the_same_run_gives_the_same_physics(tmp_path):
    first = run_on_mujoco("pick_place", tmp_path=tmp_path)
    second = run_on_mujoco("pick_place", tmp_path=tmp_path)
    assert first[0].status == second[0].status == "succeeded"
    assert first[2].sim_time == pytest.approx(second[2].sim_time, abs=1e-9)
    assert first[1]["cube"].xyz == pytest.approx(second[1]["cube"].xyz, abs=1e-9)


def test_the_compiled_model_is_cached_by_content(tmp_path):
    cell = load_cell(load_task(resolve_task("pick_place_panda"), {}).cell)
    options = MujocoOptions(cache_dir=str(tmp_path))
    with MujocoBackend(cell.model.joint_names, physics_cell(cell), None, options) as first:
        assert not first.cache_hit
    with MujocoBackend(cell.model.joint_names, physics_cell(cell), None, options) as again:
        assert again.cache_hit
    assert len(list(tmp_path.glob("*.mjb"))) == 1
