"""Hostile task files end in a TaskSpecError naming the file (and line), quickly:
deep nesting, include diamonds, symlink loops, bad tags, non-finite numbers."""

from __future__ import annotations

import os
import time
from pathlib import Path

import pytest

from taskrunner.errors import TaskSpecError
from taskrunner.tasks import load_task, load_task_text
from taskrunner.tasks.loader import MAX_INCLUDES, MAX_STEP_DEPTH


@pytest.fixture
def cell(robots_dir: Path) -> Path:
    return robots_dir / "cells" / "servo_arm_table.yaml"


def task_text(cell: Path, steps: str) -> str:
    return f"task: t\ncell: {cell}\nsteps:\n{steps}"


def problems_of(path: Path, text: str | None = None) -> list[tuple[Path | None, int | None, str]]:
    with pytest.raises(TaskSpecError) as caught:
        if text is None:
            load_task(path)
        else:
            load_task_text(text, path)
    return [(p.path, p.line, p.message) for p in caught.value.problems]


def nested_sequences(depth: int) -> str:
    # Flow style keeps a deep file small: [{sequence: [{sequence: [...]}]}]
    return "  - " + "{sequence: [" * depth + "{wait: {seconds: 0.1}}" + "]}" * depth + "\n"


@pytest.mark.parametrize("depth", [40, 200, 100_000])
def test_deeply_nested_steps_are_refused_without_recursion(tmp_path, cell, depth):
    path = tmp_path / "deep.yaml"
    start = time.perf_counter()
    problems = problems_of(path, task_text(cell, nested_sequences(depth)))
    assert time.perf_counter() - start < 5
    assert len(problems) == 1
    file, line, message = problems[0]
    assert file == path and line == 4
    assert ("YAML nested deeper than 64 levels" in message
            or f"steps nested deeper than {MAX_STEP_DEPTH} levels" in message)


def test_steps_nested_through_includes_are_limited(tmp_path, cell):
    # Each file nests 10 steps deep and includes the next: 6 files, 60 levels in all.
    for i in range(6):
        inner = f"{{include: {{file: part{i + 1}.yaml}}}}" if i < 5 else "{wait: {seconds: 0.1}}"
        body = "{sequence: [" * 10 + inner + "]}" * 10
        (tmp_path / f"part{i}.yaml").write_text(task_text(cell, f"  - {body}\n"))
    problems = problems_of(tmp_path / "part0.yaml")
    assert [m for _, _, m in problems] == [
        f"steps nested deeper than {MAX_STEP_DEPTH} levels (composites and includes together)"]
    assert problems[0][0] == tmp_path / "part3.yaml"


def test_an_include_diamond_is_refused_by_the_include_limit(tmp_path, cell):
    # 8 files, each including the next one 8 times: 8^7 includes if expanded.
    for i in range(8):
        steps = ("  - {wait: {seconds: 0.1}}\n" if i == 7 else
                 f"  - {{include: {{file: d{i + 1}.yaml}}}}\n" * 8)
        (tmp_path / f"d{i}.yaml").write_text(task_text(cell, steps))
    start = time.perf_counter()
    problems = problems_of(tmp_path / "d0.yaml")
    assert time.perf_counter() - start < 2
    assert [m for _, _, m in problems] == [
        f"more than {MAX_INCLUDES} includes in one task (a file included many times over?)"]
    assert problems[0][0] is not None and problems[0][1] is not None


def test_a_task_file_that_is_a_symlink_loop_is_refused(tmp_path):
    loop = tmp_path / "loop.yaml"
    os.symlink(loop, loop)
    with pytest.raises(TaskSpecError) as caught:
        load_task(loop)
    assert str(caught.value) == f"{loop}: symlink loop (too many levels of symbolic links)"


def test_an_include_and_a_cell_that_are_symlink_loops_are_refused(tmp_path, cell):
    loop = tmp_path / "loop.yaml"
    os.symlink(loop, loop)
    path = tmp_path / "task.yaml"
    path.write_text("task: t\ncell: loop.yaml\nsteps:\n  - include: {file: loop.yaml}\n")
    problems = problems_of(path)
    # Named as the file wrote them, not resolved.
    expected = "'loop.yaml': symlink loop (too many levels of symbolic links)"
    assert problems == [(path, 2, expected), (path, 4, expected)]


def test_an_explicit_int_tag_on_text_is_refused_with_its_line(tmp_path, cell):
    path = tmp_path / "tag.yaml"
    text = task_text(cell, '  - wait: !!int "abc"\n')
    assert problems_of(path, text) == [(path, 4, "invalid YAML: 'abc' is not a valid !!int")]


def test_a_python_tag_is_refused(tmp_path, cell):
    path = tmp_path / "tag.yaml"
    text = task_text(cell, "  - wait: !!python/object/apply:os.system ['true']\n")
    ((file, line, message),) = problems_of(path, text)
    assert (file, line) == (path, 4)
    assert message.startswith("invalid YAML: tag '!!python/object/apply:os.system' is not "
                              "supported")


def test_a_path_with_a_nul_character_is_refused(tmp_path, cell):
    path = tmp_path / "task.yaml"
    path.write_text(task_text(cell, '  - include: {file: "a\\0b.yaml"}\n'))
    ((file, line, message),) = problems_of(path)
    assert (file, line) == (path, 4)
    assert "holds a NUL character" in message


@pytest.mark.parametrize(
    ("value", "message"),
    [
        ("{xyz: [.inf, 0, 0.8]}", "'objects[0].pose.xyz[0]' must be a finite number (got inf)"),
        ("{xyz: [1e400, 0, 0.8]}", "'objects[0].pose.xyz[0]' must be a finite number (got inf)"),
        ("{xyz: [0, .nan, 0.8]}", "'objects[0].pose.xyz[1]' must be a finite number (got nan)"),
        ("{xyz: [-1e308, 0, 0.8]}",
         "'objects[0].pose.xyz[0]' must be a finite number within ±1000 m (got -1e+308)"),
        ("{xyz: [0, 0, 0.8], rpy: [0, 1e308, 0]}",
         "'objects[0].pose.rpy[1]' must be a finite number within ±100 rad (got 1e+308)"),
    ],
    ids=["inf", "overflow", "nan", "-1e308", "huge rpy"],
)
def test_pose_numbers_must_be_finite_and_bounded(tmp_path, cell, value, message):
    path = tmp_path / "t.yaml"
    text = (f"task: t\ncell: {cell}\nobjects:\n"
            f"  - {{name: cube, shape: box, size: [0.02, 0.02, 0.02], pose: {value}}}\n"
            "steps:\n  - wait: {seconds: 1}\n")
    assert problems_of(path, text) == [(path, 4, message)]


@pytest.mark.parametrize(
    ("shape", "message"),
    [
        ("shape: box, size: [0.02, -0.02, 0.02]",
         "'objects[0].size[1]' must be a finite number > 0 and ≤ 1000 m (got -0.02)"),
        ("shape: sphere, radius: .nan",
         "'objects[0].radius' must be a finite number (got nan)"),
        ("shape: cylinder, radius: 0.01, length: 0",
         "'objects[0].length' must be a finite number > 0 and ≤ 1000 m (got 0.0)"),
    ],
    ids=["negative size", "nan radius", "zero length"],
)
def test_object_sizes_must_be_positive(tmp_path, cell, shape, message):
    path = tmp_path / "t.yaml"
    text = (f"task: t\ncell: {cell}\nobjects:\n  - {{name: o, {shape}}}\n"
            "steps:\n  - wait: {seconds: 1}\n")
    assert problems_of(path, text) == [(path, 4, message)]


def test_a_place_at_infinity_is_refused(tmp_path, cell):
    path = tmp_path / "t.yaml"
    text = task_text(cell, "  - place: {arm: arm, object: cube, at: {xyz: [0.1, .inf, 0.8]}}\n")
    assert problems_of(path, text) == [
        (path, 4, "'place.at.xyz[1]' must be a finite number (got inf)")]


def test_an_approach_of_1e308_is_refused(tmp_path, cell):
    path = tmp_path / "t.yaml"
    text = task_text(cell, "  - pick: {arm: arm, object: cube, approach: 1e308}\n")
    assert problems_of(path, text) == [
        (path, 4, "'pick.approach' must be <= 1000 (got 1e+308)")]
