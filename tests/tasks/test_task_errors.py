"""load_task errors: every problem at once, each readable and at its file:line."""

from __future__ import annotations

import textwrap
from collections.abc import Callable
from pathlib import Path

import pytest

from taskrunner.errors import InputError, TaskSpecError
from taskrunner.tasks import Problem, load_task, load_task_text, problems_error

Expected = Callable[[Path], list[tuple[int, str]]]


def load_problems(path: Path) -> list[tuple[int | None, str]]:
    with pytest.raises(TaskSpecError) as caught:
        load_task(path)
    assert all(p.path == path for p in caught.value.problems)
    return [(p.line, p.message) for p in caught.value.problems]


def write(tmp_path: Path, text: str, name: str = "task.yaml") -> Path:
    path = tmp_path / name
    path.write_text(textwrap.dedent(text))
    return path


HEADER = """\
    task: t
    cell: {cell}
    steps:
"""


@pytest.fixture
def task_file(tmp_path: Path, robots_dir: Path) -> Callable[[str], Path]:
    """``task_file(steps)``: a task on servo_arm_table whose steps start on line 4."""
    cell = robots_dir / "cells" / "servo_arm_table.yaml"

    def make(steps: str) -> Path:
        return write(tmp_path, HEADER.format(cell=cell) + textwrap.indent(
            textwrap.dedent(steps), "    "))

    return make


@pytest.mark.parametrize("name", ["bad_steps.yaml", "bad_parameters.yaml"])
def test_every_problem_of_a_file_is_reported_with_its_line(fixtures: Path,
                                                          expected_problems: Expected, name: str):
    path = fixtures / name
    assert sorted(load_problems(path)) == sorted(expected_problems(path))


def test_the_error_lists_every_problem_and_is_located_at_the_first(fixtures: Path):
    path = fixtures / "bad_steps.yaml"
    with pytest.raises(TaskSpecError) as caught:
        load_task(path)
    error = caught.value
    first = error.problems[0]
    assert (error.path, error.line) == (path, first.line) == (path, 5)
    lines = str(error).splitlines()
    assert lines[0] == f"{path}:5: {len(error.problems)} problems:"
    assert lines[1:] == [f"  {path}:{p.line}: {p.message}" for p in error.problems]
    assert [p.line for p in error.problems] == sorted(p.line for p in error.problems)
    assert isinstance(error, InputError)


def test_a_single_problem_is_the_whole_message(task_file: Callable[[str], Path]):
    path = task_file("- pik: {arm: arm, object: cube}\n")
    with pytest.raises(TaskSpecError) as caught:
        load_task(path)
    assert str(caught.value) == f"{path}:4: 'pik' is not a step verb; did you mean 'pick'?"
    assert caught.value.reason == "'pik' is not a step verb; did you mean 'pick'?"


def test_an_unknown_verb_far_from_any_lists_the_verbs(task_file: Callable[[str], Path]):
    path = task_file("- fly: {to: moon}\n")
    [(line, message)] = load_problems(path)
    assert line == 4
    assert message.startswith("'fly' is not a step verb; verbs: 'add_object', 'attach', ")


def test_several_errors_in_several_steps_are_reported_together(task_file: Callable[[str], Path]):
    path = task_file("""\
        - go: {group: arm, to: home}
        - pick: {arm: arm}
        - sequence:
            - wait: {seconds: 1, unit: s}
            - move: {group: arm}
        - gripper: {arm: arm, group: gripper, action: open}
        """)
    assert load_problems(path) == [
        (5, "'pick' needs 'object'"),
        (7, "'unit' is not a field of 'wait'; fields: 'name', 'seconds', 'wait_for'"),
        (8, "'move' needs one of 'pose' or 'by'"),
        (9, "'gripper' takes only one of 'arm' or 'group' (got 'arm' and 'group')"),
    ]


def test_a_repeated_yaml_key_is_a_task_error_at_its_second_line(fixtures: Path):
    path = fixtures / "duplicate_key.yaml"
    with pytest.raises(TaskSpecError) as caught:
        load_task(path)
    assert (caught.value.path, caught.value.line) == (path, 8)
    assert caught.value.reason == "duplicate key 'arm' (first defined on line 6)"


@pytest.mark.parametrize(("text", "line", "message"), [
    ("", None, "a task file must be a mapping with 'task', 'cell' and 'steps' "
               "(got an empty file)"),
    ("- go: {}\n", 1, "a task file must be a mapping with 'task', 'cell' and 'steps' "
                      "(got a list)"),
    ("task: t\nsteps: [{wait: {seconds: 0}}]\n", 1,
     "a task file needs 'cell' (the cell file it runs in)"),
    ("cell: c.yaml\nsteps: [{wait: {seconds: 0}}]\n", 1, "a task file needs 'task'"),
    ("task: t\ncell: c.yaml\n", 1, "a task file needs 'steps'"),
    ("task: t\ncell: c.yaml\nsteps: []\n", 3, "'steps' must have at least 1 item (got 0)"),
    ("task: [t]\ncell: c.yaml\nsteps: [{wait: {seconds: 0}}]\n", 1,
     "'task' must be a string (got ['t'])"),
    ("task: t\ncell: c.yaml\nsteps: [{wait: {seconds: 0}}]\nobjects: {}\n", 4,
     "'objects' must be a list (got {})"),
    ("task: t\ncell: c.yaml\nsteps: [[go]]\n", 3,
     "a step must be a mapping 'verb: body', e.g. 'go: {group: arm, to: home}' (got ['go'])"),
    ("task: t\ncell: c.yaml\nsteps: [{go: {group: arm, to: home}, pick: {}}]\n", 3,
     "a step has one verb (got 'go' and 'pick')"),
])
def test_the_shape_of_a_file_is_checked(tmp_path: Path, text: str, line: int | None,
                                        message: str):
    (tmp_path / "c.yaml").write_text("name: c\n")
    path = write(tmp_path, text)
    problems = load_problems(path)
    assert (line, message) in problems


def test_a_cell_that_does_not_exist_is_reported_at_its_line(tmp_path: Path):
    path = write(tmp_path, "task: t\ncell: cells/none.yaml\nsteps: [{wait: {seconds: 0}}]\n")
    assert load_problems(path) == [(2, "cell file not found: cells/none.yaml")]


def test_a_file_that_does_not_exist_is_a_task_error(tmp_path: Path):
    with pytest.raises(TaskSpecError, match="missing.yaml: file not found"):
        load_task(tmp_path / "missing.yaml")


def test_bad_yaml_is_reported_at_its_line(tmp_path: Path):
    with pytest.raises(TaskSpecError) as caught:
        load_task_text("task: t\nsteps:\n  - go: {group: arm\n", tmp_path / "t.yaml")
    assert caught.value.reason.startswith("invalid YAML")
    assert caught.value.line is not None


def test_problems_error_keeps_the_problems():
    problems = [Problem(Path("/a.yaml"), 3, "one"), Problem(None, None, "two")]
    error = problems_error(problems)
    assert error.problems == tuple(problems)
    assert str(error) == "/a.yaml:3: 2 problems:\n  /a.yaml:3: one\n  two"
    assert str(problems_error(problems[:1])) == "/a.yaml:3: one"
