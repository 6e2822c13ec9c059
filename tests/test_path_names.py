"""Names checked before the file system sees them (textfile.path_problem / resolve_path), and
the early worker's reading of a task's cell (runtime/prestart.task_cell) on such names."""

from __future__ import annotations

import os
from pathlib import Path

import pytest

from taskrunner.errors import InputError, TaskSpecError
from taskrunner.runtime.prestart import task_cell
from taskrunner.textfile import file_problem, path_problem, resolve_path


@pytest.mark.parametrize("name,problem", [
    ("a\0b.yaml", "it holds a NUL character"),
    ("a\ud800b.yaml", "it holds a lone surrogate character (no file name can)"),
    ("m" * 256 + ".stl", "a name of 260 bytes (file and folder names end at 255 bytes)"),
    ("é" * 128, "a name of 256 bytes (file and folder names end at 255 bytes)"),
    ("d/" * 2048, "4096 bytes long (paths end at 4095 bytes)"),
])
def test_a_name_the_file_system_would_refuse_is_named_before_any_call(name, problem):
    assert path_problem(name) == problem
    assert file_problem(name) == f"invalid path: {problem}"


@pytest.mark.parametrize("name", ["m" * 255, "é" * 127 + "x", "a/" * 2000, "\udcff.yaml"])
def test_names_within_the_limits_pass(name):
    # "\udcff" is how Python decodes a non-UTF-8 byte of a real file name: a file may have it.
    assert path_problem(name) is None


def test_resolve_path_names_the_path_as_written_not_resolved(tmp_path: Path):
    (tmp_path / "loop").symlink_to(tmp_path / "loop")
    task = tmp_path / "task.yaml"
    with pytest.raises(TaskSpecError) as caught:
        resolve_path(tmp_path / "loop", TaskSpecError, task, 3, written="loop")
    assert str(caught.value) == (f"{task}:3: 'loop': symlink loop (too many levels of "
                                 "symbolic links)")
    with pytest.raises(InputError) as caught:
        resolve_path(tmp_path / ("x" * 300), InputError, task, 4, written="x" * 300)
    assert caught.value.line == 4 and caught.value.reason.startswith(f"invalid path '{'x' * 300}'")
    assert str(tmp_path) not in caught.value.reason


@pytest.mark.parametrize("cell", ['"a\\0b.yaml"', "c" * 300 + ".yaml", "loop.yaml",
                                  '"\\udcff.yaml"'])
def test_the_early_worker_starts_no_process_for_a_cell_it_cannot_resolve(tmp_path, cell):
    os.symlink(tmp_path / "loop.yaml", tmp_path / "loop.yaml")
    task = tmp_path / "task.yaml"
    task.write_text(f"task: t\ncell: {cell}\nsteps:\n  - wait: {{seconds: 0}}\n")
    assert task_cell(task) is None  # the loader reports it, at its line


def test_the_early_worker_reads_a_plain_cell(tmp_path: Path):
    (tmp_path / "cell.yaml").write_text("name: c\n")
    task = tmp_path / "task.yaml"
    task.write_text("task: t\ncell: cell.yaml\nsteps:\n  - wait: {seconds: 0}\n")
    assert task_cell(task) == (tmp_path / "cell.yaml").resolve()
