"""check_names: what a task names that its cell does not have, at the right line."""

from __future__ import annotations

import textwrap
from collections.abc import Callable
from pathlib import Path

import pytest

from taskrunner.errors import YamlError
from taskrunner.robot.cell import Cell
from taskrunner.tasks import (
    arm_groups,
    check_names,
    gripper_group_of,
    load_and_check,
    load_task,
    load_task_text,
)
from taskrunner.tasks.names import moved_groups

Expected = Callable[[Path], list[tuple[int, str]]]
Cells = Callable[[str], Cell]


@pytest.mark.parametrize(("name", "cell"), [
    ("bad_names_table.yaml", "servo_arm_table"),
    ("bad_names_pair.yaml", "servo_arm_pair"),
])
def test_unknown_names_are_reported_at_their_lines(fixtures: Path, expected_problems: Expected,
                                                   cells: Cells, name: str, cell: str):
    path = fixtures / name
    problems = check_names(load_task(path), cells(cell))
    assert all(p.path == path for p in problems)
    assert sorted((p.line, p.message) for p in problems) == sorted(expected_problems(path))


@pytest.mark.parametrize(("name", "cell"), [
    ("pick_place.yaml", "servo_arm_table"),
    ("dual_arm.yaml", "servo_arm_pair"),
    ("include_twice.yaml", "servo_arm_table"),
])
def test_valid_tasks_have_no_name_problems(fixtures: Path, cells: Cells, name: str, cell: str):
    assert check_names(load_task(fixtures / name), cells(cell)) == []


def test_problems_in_an_included_file_point_into_it(fixtures: Path, cells: Cells):
    text = textwrap.dedent("""\
        task: t
        cell: ../../../taskrunner/data/robots/cells/servo_arm_table.yaml
        steps:
          - include: {file: parts/place_part.yaml, parameters: {object: ghost}}
        """)
    problems = check_names(load_task_text(text, fixtures / "t.yaml"), cells("servo_arm_table"))
    assert [(p.path, p.line, p.message) for p in problems] == [
        (fixtures / "parts" / "place_part.yaml", 10,
         "object 'ghost' is not in the scene; objects: 'marker', 'table', 'tray'")]


def test_arms_and_their_grippers_are_found_from_the_end_effectors(cells: Cells):
    table = cells("servo_arm_table").model
    assert arm_groups(table) == ["arm"]
    assert gripper_group_of(table, "arm") == "gripper"
    assert gripper_group_of(table, "gripper") is None
    pair = cells("servo_arm_pair").model
    assert arm_groups(pair) == ["left_arm", "right_arm"]
    assert gripper_group_of(pair, "right_arm") == "right_gripper"


def test_a_panda_arm_opens_its_hand(cells: Cells, example_robot_data: Path):
    model = cells("panda_table").model
    assert "arm" in arm_groups(model)
    assert gripper_group_of(model, "arm") == "hand"


def test_a_panda_task_is_checked_against_its_cell(tmp_path: Path, cells: Cells,
                                                  example_robot_data: Path, robots_dir: Path):
    text = textwrap.dedent(f"""\
        task: panda
        cell: {robots_dir / "cells" / "panda_table.yaml"}
        steps:
          - gripper: {{arm: arm, to: open}}
          - go: {{group: arm, to: extended}}
          - go: {{group: arm, joints: {{panda_joint8: 0.1}}}}
        """)
    problems = check_names(load_task_text(text, tmp_path / "t.yaml"), cells("panda_table"))
    assert [(p.line, p.message) for p in problems] == [
        (6, "joint 'panda_joint8' is not a joint of group 'arm' (its joints: 'panda_joint1', "
            "'panda_joint2', 'panda_joint3', 'panda_joint4', 'panda_joint5', 'panda_joint6', "
            "'panda_joint7')")]


def test_groups_moved_by_a_subtree_include_the_grippers(fixtures: Path, cells: Cells):
    model = cells("servo_arm_pair").model
    spec = load_task(fixtures / "dual_arm.yaml")
    assert moved_groups(spec.steps[0], model) == ["left_arm", "right_arm"]
    handoff = spec.steps[4]
    assert moved_groups(handoff, model) == ["left_arm", "left_gripper", "right_arm",
                                            "right_gripper"]
    assert moved_groups(spec.steps[7], model) == []  # repeat: wait


def test_a_missing_mesh_is_a_problem(tmp_path: Path, cells: Cells, robots_dir: Path):
    text = textwrap.dedent(f"""\
        task: mesh
        cell: {robots_dir / "cells" / "servo_arm_table.yaml"}
        objects:
          - {{name: part, shape: mesh, file: part.stl}}
        steps:
          - wait: {{seconds: 0}}
        """)
    problems = check_names(load_task_text(text, tmp_path / "t.yaml"), cells("servo_arm_table"))
    assert [(p.line, p.message) for p in problems] == [
        (4, "mesh file not found: part.stl")]


def test_load_and_check_loads_the_cell_named_by_the_task(fixtures: Path):
    spec, cell, problems = load_and_check(fixtures / "bad_names_pair.yaml")
    assert cell.name == "servo_arm_pair" and cell.path == spec.cell
    assert len(problems) == 7


def test_load_and_check_passes_cell_errors_through(tmp_path: Path):
    (tmp_path / "cell.yaml").write_text("name: broken\nrobots: []\n")
    (tmp_path / "t.yaml").write_text("task: t\ncell: cell.yaml\nsteps: [{wait: {seconds: 0}}]\n")
    with pytest.raises(YamlError, match="cell.yaml:2: robots"):
        load_and_check(tmp_path / "t.yaml")
