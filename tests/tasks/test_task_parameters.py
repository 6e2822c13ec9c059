"""Task parameters: typed substitution, overrides from a command line or an API."""

from __future__ import annotations

import textwrap
from pathlib import Path

import pytest

from taskrunner.errors import TaskSpecError
from taskrunner.tasks import GoStep, WaitStep, load_task, load_task_text
from taskrunner.tasks.parameters import coerce_parameter


def problems_of(path: Path, parameters: dict[str, object]) -> list[tuple[int | None, str]]:
    with pytest.raises(TaskSpecError) as caught:
        load_task(path, parameters)
    return [(p.line, p.message) for p in caught.value.problems]


@pytest.fixture
def typed(tmp_path: Path, robots_dir: Path) -> Path:
    path = tmp_path / "typed.yaml"
    path.write_text(textwrap.dedent(f"""\
        task: typed
        cell: {robots_dir / "cells" / "servo_arm_table.yaml"}
        parameters:
          pause: 0.5
          times: 2
          careful: true
          pose: home
          group: {{type: str}}
        steps:
          - repeat:
              times: "${{times}}"
              do:
                - wait: {{seconds: "${{pause}}", name: "wait ${{pause}} s (careful: ${{careful}})"}}
          - go: {{group: "${{group}}", to: "${{pose}}", name: "$${{literal}} and $$x"}}
        """))
    return path


def test_a_whole_reference_keeps_the_parameters_type(typed: Path):
    spec = load_task(typed, {"group": "arm"})
    repeat, go = spec.steps
    wait = repeat.do[0]
    assert repeat.times == 2 and isinstance(repeat.times, int)
    assert isinstance(wait, WaitStep) and wait.seconds == 0.5
    assert isinstance(go, GoStep) and (go.group, go.to) == ("arm", "home")


def test_a_reference_inside_text_is_interpolated(typed: Path):
    spec = load_task(typed, {"group": "arm"})
    assert spec.steps[0].do[0].name == "wait 0.5 s (careful: true)"
    assert spec.steps[1].name == "${literal} and $$x"


def test_command_line_strings_are_parsed_to_the_declared_types(typed: Path):
    spec = load_task(typed, {"pause": "1.25", "times": "4", "careful": "no", "group": "arm",
                             "pose": "PickUp"})
    repeat, go = spec.steps
    assert repeat.times == 4 and repeat.do[0].seconds == 1.25
    assert repeat.do[0].name == "wait 1.25 s (careful: false)"
    assert go.to == "PickUp"
    values = {name: p.value for name, p in spec.parameters.items()}
    assert values == {"pause": 1.25, "times": 4, "careful": False, "pose": "PickUp",
                      "group": "arm"}
    assert spec.parameters["pause"].default == 0.5 and spec.parameters["pause"].type == "float"
    assert spec.parameters["group"].default is None and spec.parameters["group"].type == "str"


def test_api_values_of_the_right_type_are_taken_as_they_are(typed: Path):
    spec = load_task(typed, {"pause": 2, "times": 3, "careful": False, "group": "arm"})
    assert spec.steps[0].times == 3 and spec.steps[0].do[0].seconds == 2.0


def test_overrides_are_checked_against_the_declaration(fixtures: Path):
    path = fixtures / "pick_place.yaml"
    assert problems_of(path, {"place_y": "abc"}) == [(7, "'place_y' must be a float (got 'abc')")]
    assert problems_of(path, {"place_y": "0.5"}) == [(7, "'place_y' must be <= 0.2 (got 0.5)")]
    assert problems_of(path, {"slow": "maybe"}) == [
        (8, "'slow' must be a bool (true or false) (got 'maybe')")]
    assert problems_of(path, {"slow": 1}) == [
        (8, "'slow' must be a bool (true or false) (got 1)")]
    assert problems_of(path, {"cube_x": True}) == [(6, "'cube_x' must be a float (got True)")]


def test_an_undeclared_override_names_the_declared_parameters(fixtures: Path):
    path = fixtures / "pick_place.yaml"
    assert problems_of(path, {"speed": "1"}) == [
        (5, "'speed' is not a parameter of task 'pick_place' (its parameters: 'cube_x', "
            "'place_y', 'slow', 'label')")]
    assert problems_of(path, {"cube_y": "1"}) == [
        (5, "'cube_y' is not a parameter of task 'pick_place' (its parameters: 'cube_x', "
            "'place_y', 'slow', 'label'); did you mean 'cube_x'?")]


def test_overriding_a_task_without_parameters_says_so(fixtures: Path):
    assert problems_of(fixtures / "panda_part.yaml", {"x": "1"}) == [
        (2, "'x' is not a parameter of task 'panda_part' (it has no parameters)")]


def test_a_parameter_without_default_must_be_given(typed: Path):
    assert problems_of(typed, {}) == [
        (8, "parameter 'group' has no default and is not given (--param)")]


def test_a_bad_override_is_reported_with_the_files_other_problems(typed: Path):
    text = typed.read_text().replace("to: ", "too: ")
    with pytest.raises(TaskSpecError) as caught:
        load_task_text(text, typed, {"times": "many", "group": "arm"})
    assert [(p.line, p.message) for p in caught.value.problems] == [
        (5, "'times' must be an int (got 'many')"),
        (14, "'too' is not a field of 'go'; did you mean 'to'?"),
    ]


@pytest.mark.parametrize(("type_", "value", "expected"), [
    ("float", "0.25", 0.25), ("float", " -1e-3 ", -0.001), ("float", 3, 3.0),
    ("int", "7", 7), ("int", 7.0, 7), ("bool", "Yes", True), ("bool", "off", False),
    ("bool", True, True), ("str", "cube", "cube"),
])
def test_values_are_coerced_to_the_parameter_type(type_: str, value: object, expected: object):
    result = coerce_parameter("p", type_, value)
    assert result == expected and type(result) is type(expected)


@pytest.mark.parametrize(("type_", "value", "message"), [
    ("float", "abc", "'p' must be a float (got 'abc')"),
    ("float", "nan", "'p' must be a float (got 'nan')"),
    ("float", False, "'p' must be a float (got False)"),
    ("int", "1.5", "'p' must be an int (got '1.5')"),
    ("int", 1.5, "'p' must be an int (got 1.5)"),
    ("bool", "2", "'p' must be a bool (true or false) (got '2')"),
    ("str", 3, "'p' must be a string (got 3)"),
])
def test_bad_values_name_the_parameter(type_: str, value: object, message: str):
    with pytest.raises(ValueError) as caught:
        coerce_parameter("p", type_, value)
    assert str(caught.value) == message
