"""The shipped tasks on the mujoco backend, grasp_mode weld, what physics reports, and
the failures physics finds (each naming the step's file:line).

Skipped where mujoco is not installed (``pip install -e '.[mujoco]'``).
"""

from __future__ import annotations

import itertools
import json
import math
from pathlib import Path

import numpy as np
import pinocchio as pin
import pytest

from taskrunner.resources import resolve_task
from taskrunner.robot.cell import load_cell
from taskrunner.shapes import Box
from taskrunner.tasks.loader import load_task

mujoco = pytest.importorskip("mujoco", reason="the mujoco backend needs: pip install "
                             "-e '.[mujoco]'")

from taskrunner.backends.physics import (  # noqa: E402
    MujocoBackend,
    MujocoOptions,
    ObjectPhysics,
    PhysicsObject,
    physics_cell,
)
from taskrunner.errors import BackendError  # noqa: E402
from taskrunner.planning.service import InProcessPlanner  # noqa: E402
from taskrunner.runtime.runner import Runner, RunOptions  # noqa: E402

ROBOTS = Path(resolve_task("pick_place_panda")).parent.parent / "robots"


def run(task: str | Path, tmp_path: Path, options: dict | None = None, cell_edit=None,
        physics_edit=None, parameters: dict | None = None):
    """Run a task on mujoco; returns (record, final object poses, backend)."""
    spec = load_task(resolve_task(task) if isinstance(task, str) else task, parameters or {})
    cell = load_cell(spec.cell)
    if cell_edit is not None:
        cell_edit(cell)
    described = physics_cell(cell)
    if physics_edit is not None:
        described = physics_edit(described)
    start = dict(zip(cell.model.joint_names, cell.start_state()))
    backend = MujocoBackend(cell.model.joint_names, described, start,
                            MujocoOptions(cache_dir=str(tmp_path / "cache"), **(options or {})))
    try:
        record = Runner(spec, cell, backend, InProcessPlanner(),
                        RunOptions(backend_name="mujoco")).run()
        return record, backend.object_poses(), backend
    finally:
        backend.close()


def rotation(xyzw) -> np.ndarray:
    x, y, z, w = xyzw
    return pin.Quaternion(w, x, y, z).normalized().toRotationMatrix()


def box_symmetries(size) -> list[np.ndarray]:
    """The rotations that map a box of ``size`` onto itself."""
    found = []
    for perm in itertools.permutations(range(3)):
        for signs in itertools.product((1, -1), repeat=3):
            m = np.zeros((3, 3))
            for row, (col, sign) in enumerate(zip(perm, signs)):
                m[row, col] = sign
            if np.linalg.det(m) > 0 and np.allclose(np.abs(m) @ np.asarray(size), size):
                found.append(m)
    return found


def box_error(pose, target_xyz, target_rpy, size) -> tuple[float, float]:
    """Distance (m) and angle (deg) from a box's pose to a target, up to the box's
    symmetries (a cube turned by 90 degrees is the same cube)."""
    distance = float(np.linalg.norm(np.subtract(pose.xyz, target_xyz)))
    goal = pin.rpy.rpyToMatrix(*target_rpy)
    actual = rotation(pose.quat)
    angle = min(np.linalg.norm(pin.log3(goal.T @ actual @ s)) for s in box_symmetries(size))
    return distance, math.degrees(float(angle))


def assert_near(pose, xyz, rpy, size, name):
    distance, angle = box_error(pose, xyz, rpy, size)
    assert distance < 0.01, f"{name} at {pose.xyz}: {1e3 * distance:.1f} mm from {xyz}"
    assert angle < 5.0, f"{name} turned {angle:.1f} deg from {rpy}"


CUBE = (0.04, 0.04, 0.04)


@pytest.mark.slow
def test_stack_on_mujoco_leaves_every_cube_within_1cm_and_5deg(tmp_path):
    record, poses, _ = run("stack", tmp_path)
    assert record.status == "succeeded", record.error
    # The task's expectation: cube_a where it started, b and c on top, 41 mm apart, yaw 0.3.
    assert_near(poses["cube_a"], (0.5, 0.0, 0.77), (0, 0, 0.3), CUBE, "cube_a")
    assert_near(poses["cube_b"], (0.5, 0.0, 0.811), (0, 0, 0.3), CUBE, "cube_b")
    assert_near(poses["cube_c"], (0.5, 0.0, 0.852), (0, 0, 0.3), CUBE, "cube_c")


@pytest.mark.parametrize("task", ["handoff", pytest.param("handoff_panda", marks=pytest.mark.slow)])
def test_handoff_on_mujoco_leaves_the_bar_within_1cm_and_5deg(task, tmp_path):
    spec = load_task(resolve_task(task), {})
    values = {k: p.value for k, p in spec.parameters.items()}
    if task == "handoff":
        xyz, rpy, size = (values["drop_x"], 0.0, 0.7635), (0, 1.5708, 0), (0.025, 0.025, 0.08)
    else:
        xyz, rpy = (values["drop_x"], values["drop_y"], 0.7635), (1.5708, 0, 0)
        size = (0.025, 0.025, 0.10)
    record, poses, backend = run(task, tmp_path)
    assert record.status == "succeeded", record.error
    assert_near(poses["bar"], xyz, rpy, size, "bar")
    # It went from one gripper to the other through the air, not along the table.
    heights = [s.objects["bar"].xyz[2] for s in backend.history()]
    assert max(heights) > 0.85


def wrong_width(cell):
    """The Panda hand's 'closed' pose leaves 6 cm between the fingers: never holds a 4 cm cube."""
    cell.model.named_states["hand"]["closed"] = {"panda_finger_joint1": 0.03}


def test_a_gripper_that_cannot_hold_carries_the_cube_with_grasp_mode_weld(tmp_path):
    # A cube as slippery as ice (friction 0.001: 0.04 N of grip for 0.4 N of weight)
    # slips at the pick; with the weld the cube is welded at the grasp, carried, released at the place and
    # left on its target. (A gripper too wide to touch it is refused before it moves.)
    def weld(cell):
        cell.grasp_modes["arm"] = "weld"

    record, poses, backend = run("pick_place_panda", tmp_path, cell_edit=weld,
                                 options={"objects": {"cube": ObjectPhysics(
                                     friction=(0.001, 0.005, 0.0001))}})
    assert record.status == "succeeded", record.error
    assert_near(poses["cube"], (0.45, -0.2, 0.771), (0, 0, 0), CUBE, "cube")
    physics = [e for e in record.events if e.kind == "physics"]
    grasps = [(e.location, g["action"], g["object"], g["link"])
              for e in physics for g in e.data["grasps"]]
    task_file = str(resolve_task("pick_place_panda"))
    assert grasps == [(f"{task_file}:14", "welded", "cube", "panda_hand_tcp"),
                      (f"{task_file}:15", "released", "cube", "panda_hand_tcp")]
    assert any("welded to 'panda_hand_tcp'" in e.message for e in physics)
    assert any("welded" in note for note in backend.notes)


def test_grasp_mode_weld_from_the_cell_file(tmp_path):
    cell_file = tmp_path / "cell.yaml"
    cell_file.write_text(f"""
name: panda_weld
robots:
  - name: panda
    robot: {ROBOTS / 'panda'}
    base: {{xyz: [0.0, 0.0, 0.75]}}
    grasp_mode: {{hand: weld}}
start: {{arm: ready, hand: open}}
objects:
  - {{name: table, shape: box, size: [1.2, 0.8, 0.75], pose: {{xyz: [0.4, 0.0, 0.375]}},
     touch_links: [panda_link0], friction: 0.8}}
""")
    cell = load_cell(cell_file)
    assert cell.grasp_modes == {"arm": "weld"}
    described = physics_cell(cell)
    assert described.grasp_modes == {"arm": "weld"}
    with MujocoBackend(cell.model.joint_names, described, None,
                       MujocoOptions(cache_dir=str(tmp_path))) as backend:
        model = backend.model
        assert model.geom("table").friction[0] == pytest.approx(0.8)
        assert not any(model.eq(i).name.startswith("grasp/") for i in range(model.neq))


def test_grasp_mode_names_an_arm_of_the_cell(tmp_path):
    cell = load_cell(load_task(resolve_task("pick_place_panda"), {}).cell)
    with pytest.raises(BackendError, match=r"'hand' is not an arm of 'panda_table' \(arms: arm\)"):
        MujocoBackend(cell.model.joint_names, physics_cell(cell), None,
                      MujocoOptions(cache_dir=str(tmp_path), grasp_mode={"hand": "weld"}))


def test_a_heavy_cube_declared_in_the_task_file_slips_at_its_pick(tmp_path):
    text = Path(resolve_task("pick_place_panda")).read_text()
    text = text.replace("cell: ../robots/cells/panda_table.yaml",
                        f"cell: {ROBOTS / 'cells' / 'panda_table.yaml'}")
    text = text.replace('0.77]}}', '0.77]}, mass: 10, friction: [0.8]}')
    task = tmp_path / "heavy.yaml"
    task.write_text(text)
    record, poses, backend = run(task, tmp_path)
    assert record.status == "failed"
    assert f"{task}:14: execution failed: object 'cube' slipped out of the gripper" in record.error
    assert backend.model.body("cube").mass[0] == pytest.approx(10.0)
    assert backend.model.geom("cube").friction[0] == pytest.approx(0.8)
    assert backend.model.geom("cube").friction[1] == pytest.approx(0.005)  # the default's
    assert poses["cube"].xyz[2] < 0.78


def test_a_cell_object_with_a_mass_is_a_free_body(tmp_path):
    cell_file = tmp_path / "cell.yaml"
    cell_file.write_text(f"""
name: panda_block
robots:
  - {{name: panda, robot: {ROBOTS / 'panda'}, base: {{xyz: [0.0, 0.0, 0.75]}}}}
objects:
  - {{name: table, shape: box, size: [1.2, 0.8, 0.75], pose: {{xyz: [0.4, 0.0, 0.375]}},
     touch_links: [panda_link0]}}
  - {{name: block, shape: box, size: [0.1, 0.1, 0.1], pose: {{xyz: [0.5, 0.3, 0.80]}},
     density: 2000}}
""")
    cell = load_cell(cell_file)
    described = physics_cell(cell)
    movable = {o.name: o.movable for o in described.objects}
    assert movable == {"table": False, "block": True}
    with MujocoBackend(cell.model.joint_names, described, None,
                       MujocoOptions(cache_dir=str(tmp_path))) as backend:
        assert backend.model.body("block").mass[0] == pytest.approx(2.0)  # 1 l at 2000 kg/m³
        assert set(backend.object_poses()) == {"block"}


def test_the_run_record_has_joints_and_objects_over_time(tmp_path):
    record, _, backend = run("pick_place_panda", tmp_path)
    assert record.status == "succeeded", record.error
    physics = [e for e in record.events if e.kind == "physics"]
    motions = [e for e in record.events if e.kind == "motion"]
    assert len(physics) == len(motions)
    assert [e.node for e in physics] == [e.node for e in motions]
    assert all(e.location and ".yaml:" in e.location for e in physics)
    times = [t for e in physics for t in e.data["t"]]
    assert times == sorted(times)
    assert times[-1] == pytest.approx(backend.sim_time, abs=0.03)
    steps = np.diff(times)
    assert float(np.median(steps)) == pytest.approx(0.04, abs=0.005)  # 25 Hz
    first = physics[0].data
    assert first["joints"] == list(backend.joint_state().names)
    assert all(len(q) == len(first["joints"]) for e in physics for q in e.data["q"])
    # The cube is lifted while carried (heights from the events alone).
    heights = [p[2] for e in physics for p in e.data["objects"]["cube"] if p is not None]
    assert max(heights) > 0.8 and heights[-1] == pytest.approx(0.771, abs=0.01)
    size = len(json.dumps([e.as_dict() for e in physics]))
    assert size < 100_000, f"{size} bytes of physics for 10 s of motion"
    # The web view's replay gets each motion's measurements.
    from taskrunner.viewer.describe import describe_replay

    replay = describe_replay(record)
    assert [m["physics"]["t"] for m in replay["motions"]] == [e.data["t"] for e in physics]


def test_an_unplanned_contact_fails_its_step_with_file_and_line(tmp_path):
    # A post physics has but the task's scene lacks, in the way of the hand going down.
    def post(described):
        return described.with_objects([*described.objects, PhysicsObject(
            "post", Box((0.1, 0.1, 0.02)), (0.5, 0.15, 0.86), (0, 0, 0, 1), movable=False)])

    record, _, _ = run("pick_place_panda", tmp_path, physics_edit=post)
    assert record.status == "failed"
    assert f"{resolve_task('pick_place_panda')}:14: execution failed: unplanned contact: " \
           "'panda_hand' pushed against 'post'" in record.error


def test_a_tracking_error_fails_its_step_with_file_and_line(tmp_path):
    record, _, _ = run("pick_place_panda", tmp_path, options={"tracking_tolerance": 0.001})
    assert record.status == "failed"
    assert f"{resolve_task('pick_place_panda')}:14: execution failed: tracking error: joint" \
        in record.error


OFF_CENTRE = """task: offcentre
cell: {cell}
parameters:
  grasp_x: {{default: 0.1, type: float, description: "grasp from the bar's centre (m)"}}
objects:
  - {{name: bar, shape: box, size: [0.24, 0.03, 0.03], pose: {{xyz: [0.5, 0.1, 0.765]}}, mass: 1.5}}
steps:
  - pick: {{arm: arm, object: bar, grasp: {{xyz: ["${{grasp_x}}", 0, 0.005], rpy: [0, 3.14159265, 0]}},
           approach: 0.08, retreat: 0.1}}
  - go: {{group: arm, to: ready}}
"""


@pytest.mark.parametrize("grasp_x", [0.1, 0.0])
def test_a_heavy_bar_grasped_far_from_its_centre_slips_at_its_pick(grasp_x, tmp_path):
    # 1.5 kg, 10 cm from the centre: 1.5 N m about the fingers' axis, more than the pads'
    # torsional friction resists. The same bar grasped at its centre is carried.
    task = tmp_path / "offcentre.yaml"
    task.write_text(OFF_CENTRE.format(cell=ROBOTS / "cells" / "panda_table.yaml"))
    record, poses, _ = run(task, tmp_path, parameters={"grasp_x": grasp_x})
    if grasp_x:
        assert record.status == "failed"
        assert f"{task}:8: execution failed: object 'bar' slipped out of the gripper" \
            in record.error
        assert poses["bar"].xyz[2] < 0.8  # back down on the table
    else:
        assert record.status == "succeeded", record.error
        assert poses["bar"].xyz[2] > 1.0  # held up at the ready pose
