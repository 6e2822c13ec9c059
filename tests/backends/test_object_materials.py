"""Mass, density and friction of objects (cell and task files) and the cell's grasp_mode:
validated with file:line, collected for the physics backend, ignored by the others.
Needs no mujoco."""

from __future__ import annotations

from pathlib import Path

import pytest

from taskrunner.errors import TaskrunnerError
from taskrunner.materials import Material
from taskrunner.resources import resolve_task
from taskrunner.robot.cell import load_cell
from taskrunner.tasks.loader import load_task, load_task_text

ROBOTS = Path(resolve_task("pick_place_panda")).parent.parent / "robots"
CELL = ROBOTS / "cells" / "panda_table.yaml"


def task_text(objects: str, steps: str = "  - go: {group: arm, to: ready}") -> str:
    return f"task: t\ncell: {CELL}\nobjects:\n{objects}\nsteps:\n{steps}\n"


def test_task_objects_and_added_objects_give_their_materials(tmp_path):
    spec = load_task_text(task_text(
        "  - {name: a, shape: box, size: [0.04, 0.04, 0.04], pose: {xyz: [0.5, 0, 0.77]},\n"
        "     mass: 0.2, friction: [0.6, 0.01]}\n"
        "  - {name: b, shape: sphere, radius: 0.02, pose: {xyz: [0.5, 0.2, 0.77]}}",
        "  - add_object: {name: c, shape: cylinder, radius: 0.02, length: 0.1,\n"
        "                 pose: {xyz: [0.4, 0.2, 0.8]}, density: 7800}"), tmp_path / "t.yaml")
    assert spec.object_materials() == {"a": Material(0.2, None, (0.6, 0.01)),
                                       "b": Material(), "c": Material(None, 7800.0, None)}


def test_a_parameter_gives_a_mass(tmp_path):
    text = task_text("  - {name: a, shape: box, size: [0.04, 0.04, 0.04], mass: '${m}'}")
    text = text.replace("objects:", "parameters: {m: 0.5}\nobjects:")
    spec = load_task_text(text, tmp_path / "t.yaml", {"m": 2.5})
    assert spec.object_materials()["a"].mass == 2.5


@pytest.mark.parametrize(("fields", "message"), [
    ("mass: -1", "'objects[0].mass' must be a finite number > 0"),
    ("mass: .nan", "'objects[0].mass' must be a finite number"),
    ("density: 0", "'objects[0].density' must be a finite number > 0"),
    ("friction: [1, -0.1]", "'objects[0].friction[1]' must be a finite number ≥ 0"),
    ("friction: [1, 0.1, 0.1, 0.1]", "friction"),
    ("mass: 1, density: 500", "give 'mass' or 'density', not both"),
])
def test_a_bad_material_in_a_task_names_file_and_line(fields, message, tmp_path):
    path = tmp_path / "bad.yaml"
    path.write_text(task_text(f"  - {{name: a, shape: box, size: [0.04, 0.04, 0.04], {fields}}}"))
    with pytest.raises(TaskrunnerError) as caught:
        load_task(path)
    assert f"{path}:4" in str(caught.value)
    assert message in str(caught.value)


def write_cell(tmp_path: Path, robot_extra: str = "", objects: str = "") -> Path:
    path = tmp_path / "cell.yaml"
    path.write_text(f"""name: c
robots:
  - name: panda
    robot: {ROBOTS / 'panda'}
    base: {{xyz: [0, 0, 0.75]}}
{robot_extra}objects:
  - {{name: table, shape: box, size: [1.2, 0.8, 0.75], pose: {{xyz: [0.4, 0, 0.375]}}}}
{objects}""")
    return path


def test_cell_objects_carry_their_materials_and_robots_their_grasp_mode(tmp_path):
    cell = load_cell(write_cell(
        tmp_path, "    grasp_mode: weld\n",
        "  - {name: block, shape: box, size: [0.1, 0.1, 0.1], pose: {xyz: [0.5, 0.3, 0.8]},"
        " mass: 1.5, friction: 0.4}\n"))
    assert cell.object("table").material == Material()
    assert cell.object("block").material == Material(1.5, None, (0.4,))
    assert cell.grasp_modes == {"arm": "weld"}


@pytest.mark.parametrize(("robot_extra", "objects", "line", "message"), [
    ("    grasp_mode: glue\n", "", 6, "'friction' or 'weld'"),
    ("    grasp_mode: {gripper: weld}\n", "", 6,
     "'gripper' is not an arm group or end effector of robot 'panda' (known: arm, hand)"),
    ("", "  - {name: b, shape: sphere, radius: 0.02, mass: 0}\n", 8,
     "'objects[1].mass' must be a finite number > 0"),
    ("", "  - {name: b, shape: sphere, radius: 0.02, pose: {frame: panda_hand}, mass: 1}\n",
     8, "objects[1].mass: an object fixed to link 'panda_hand' does not move"),
])
def test_a_bad_cell_material_or_grasp_mode_names_file_and_line(robot_extra, objects, line,
                                                              message, tmp_path):
    path = write_cell(tmp_path, robot_extra, objects)
    with pytest.raises(TaskrunnerError) as caught:
        load_cell(path)
    assert f"{path}:{line}" in str(caught.value)
    assert message in str(caught.value)


def test_kinematic_backends_ignore_materials(tmp_path):
    # A 50 kg cube with no friction is carried on the mock backend as any other.
    from taskrunner.backends.mock import MockBackend
    from taskrunner.planning.service import InProcessPlanner
    from taskrunner.runtime.runner import Runner

    text = Path(resolve_task("pick_place_panda")).read_text()
    text = text.replace("cell: ../robots/cells/panda_table.yaml", f"cell: {CELL}")
    text = text.replace('0.77]}}', '0.77]}, mass: 50, friction: 0}')
    path = tmp_path / "heavy.yaml"
    path.write_text(text)
    spec = load_task(path)
    cell = load_cell(spec.cell)
    names = cell.model.joint_names
    record = Runner(spec, cell, MockBackend(names, dict(zip(names, cell.start_state()))),
                    InProcessPlanner()).run()
    assert record.status == "succeeded", record.error
    assert not [e for e in record.events if e.kind == "physics"]
