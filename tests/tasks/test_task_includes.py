"""include: another task file's steps, its parameters bound, its lines kept."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from taskrunner.errors import TaskSpecError
from taskrunner.tasks import GripperStep, IncludeStep, Location, PlaceStep, load_task


def problems_of(path: Path) -> list[tuple[Path | None, int | None, str]]:
    with pytest.raises(TaskSpecError) as caught:
        load_task(path)
    return [(p.path, p.line, p.message) for p in caught.value.problems]


def test_included_steps_are_bound_and_point_into_their_file(fixtures: Path):
    spec = load_task(fixtures / "include_twice.yaml")
    first, second = spec.steps[1], spec.steps[3]
    part = fixtures / "parts" / "place_part.yaml"
    assert isinstance(first, IncludeStep) and isinstance(second, IncludeStep)
    assert first.loc == Location(fixtures / "include_twice.yaml", 8)
    assert (first.path, first.task) == (part, "place_part")
    assert first.parameters == {"object": "cube", "y": -0.1}
    assert second.parameters == {"object": "cube", "y": 0.1}  # "0.1" parsed as a float
    assert second.label == "put it back"
    place = first.steps[0]
    assert isinstance(place, PlaceStep) and place.object == "cube"
    assert place.at is not None and place.at.xyz == (0.15, -0.1, 0.7625)
    assert second.steps[0].at.xyz == (0.15, 0.1, 0.7625)
    assert place.loc == Location(part, 10)
    assert place.at.loc == Location(part, 10)


def test_nested_includes_resolve_from_the_including_file(fixtures: Path):
    spec = load_task(fixtures / "include_twice.yaml")
    nested = spec.steps[1].steps[1]
    assert isinstance(nested, IncludeStep) and nested.path == fixtures / "open_part.yaml"
    gripper = nested.steps[0]
    assert isinstance(gripper, GripperStep)
    assert gripper.loc == Location(fixtures / "open_part.yaml", 3)


def test_included_objects_are_added_once(fixtures: Path):
    spec = load_task(fixtures / "include_twice.yaml")
    assert [o.name for o in spec.objects] == ["cube", "marker"]
    assert spec.objects[1].loc == Location(fixtures / "parts" / "place_part.yaml", 8)


def test_defaults_of_the_included_file_come_before_the_includers(fixtures: Path):
    spec = load_task(fixtures / "dual_arm.yaml")
    include = spec.steps[3]
    assert isinstance(include, IncludeStep)
    gripper = include.steps[0]
    # pick_part.yaml: velocity 0.3, planning time 1.0; dual_arm.yaml: planner, planning time 2.0
    assert (gripper.velocity_scaling, gripper.planning_time, gripper.planner) == (
        0.3, 1.0, "RRTConnect")
    assert spec.steps[1].planning_time == 2.0 and spec.steps[1].velocity_scaling is None
    # The includer's defaults reach steps nested in included files too.
    nested = load_task(fixtures / "include_twice.yaml").steps[1].steps[1].steps[0]
    assert (nested.velocity_scaling, nested.acceleration_scaling) == (0.5, 0.5)


def test_an_include_cycle_is_an_error_naming_the_chain(fixtures: Path):
    assert problems_of(fixtures / "cycle_a.yaml") == [
        (fixtures / "cycle_b.yaml", 4,
         "include cycle: cycle_a.yaml → cycle_b.yaml → cycle_a.yaml")]


def test_a_file_including_itself_is_a_cycle(tmp_path: Path, robots_dir: Path):
    path = tmp_path / "self.yaml"
    path.write_text(f"task: self\ncell: {robots_dir / 'cells' / 'servo_arm_table.yaml'}\n"
                    "steps:\n  - include: {file: self.yaml}\n")
    assert problems_of(path) == [(path, 4, "include cycle: self.yaml → self.yaml")]


def test_an_included_task_for_another_cell_is_an_error(fixtures: Path):
    assert problems_of(fixtures / "include_other_cell.yaml") == [
        (fixtures / "include_other_cell.yaml", 4,
         "'panda_part.yaml' is a task for cell '../../../taskrunner/data/robots/cells/panda_table.yaml', "
         "not this task's cell '../../../taskrunner/data/robots/cells/servo_arm_table.yaml'")]


def test_include_problems_point_at_the_include_or_into_the_included_file(fixtures: Path):
    here = fixtures / "include_errors.yaml"
    assert problems_of(here) == [
        (here, 8, "'y' must be <= 0.2 (got 0.5)"),
        (here, 9, "'speed' is not a parameter of task 'place_part' (its parameters: "
                  "'object', 'y')"),
        (here, 10, "parameter 'object' of task 'place_part' has no default and is not "
                   "given in the include"),
        (here, 11, "'height' must be a float (got 'tall')"),
        (here, 12, "included file not found: no_such_part.yaml"),
        (fixtures / "broken_part.yaml", 6, "'pik' is not a step verb; did you mean 'pick'?"),
    ]


def test_two_different_objects_of_one_name_are_an_error(tmp_path: Path, robots_dir: Path):
    cell = robots_dir / "cells" / "servo_arm_table.yaml"
    (tmp_path / "part.yaml").write_text(textwrap.dedent("""\
        task: part
        objects:
          - {name: cube, shape: box, size: [0.03, 0.03, 0.03]}
        steps:
          - wait: {seconds: 0}
        """))
    main = tmp_path / "main.yaml"
    main.write_text(textwrap.dedent(f"""\
        task: main
        cell: {cell}
        objects:
          - {{name: cube, shape: box, size: [0.02, 0.02, 0.02]}}
        steps:
          - include: {{file: part.yaml}}
        """))
    assert problems_of(main) == [
        (tmp_path / "part.yaml", 3,
         f"object 'cube' is declared twice (first at {main}:4)")]
