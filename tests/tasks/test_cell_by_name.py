"""A task file's ``cell:`` by name: the same resolution as ``run-task info``,
``load_workcell`` and the REST API (``taskrunner.resources.resolve_cell``)."""

from __future__ import annotations

import shutil
import textwrap
from pathlib import Path

import pytest

from taskrunner import resources
from taskrunner.errors import InputError, TaskSpecError
from taskrunner.folders import FolderPolicy
from taskrunner.tasks import load_task

SHIPPED_TABLE = resources.cells_dir() / "servo_arm_table.yaml"


def write_task(folder: Path, cell: str, name: str = "t.yaml") -> Path:
    path = folder / name
    path.write_text(textwrap.dedent(f"""\
        task: t
        cell: {cell}
        steps:
          - go: {{group: arm, to: home}}
        """))
    return path


@pytest.fixture(autouse=True)
def _no_cells_folder(monkeypatch):
    monkeypatch.delenv("TASKRUNNER_CELLS_DIR", raising=False)


def test_a_task_in_an_empty_folder_names_a_shipped_cell(tmp_path):
    spec = load_task(write_task(tmp_path, "servo_arm_table"))
    assert spec.cell.resolve() == SHIPPED_TABLE.resolve()
    assert spec.cell.resolve() == resources.resolve_cell("servo_arm_table").resolve()


def test_a_cell_name_with_yaml_suffix_is_the_same_cell(tmp_path):
    spec = load_task(write_task(tmp_path, "servo_arm_table.yaml"))
    assert spec.cell.resolve() == SHIPPED_TABLE.resolve()


def test_a_file_next_to_the_task_wins_over_a_shipped_cell_of_that_name(tmp_path):
    local = tmp_path / "servo_arm_table.yaml"
    shutil.copy(SHIPPED_TABLE, local)
    spec = load_task(write_task(tmp_path, "servo_arm_table.yaml"))
    assert spec.cell.resolve() == local.resolve()


def test_an_unknown_cell_name_says_where_and_what_is_close(tmp_path):
    task = write_task(tmp_path, "servo_arm_tabel")
    with pytest.raises(TaskSpecError) as caught:
        load_task(task)
    message = str(caught.value)
    assert f"{task}:2" in message
    assert "did you mean 'servo_arm_table'?" in message
    assert "known cells: panda_pair, panda_table" in message


def test_an_unknown_cell_name_lists_the_cells_but_no_hardware_file(tmp_path):
    with pytest.raises(TaskSpecError) as caught:
        load_task(write_task(tmp_path, "atlantis"))
    message = str(caught.value)
    assert "'atlantis': no such file or cell" in message
    assert "servo_arm_pair, servo_arm_table" in message
    assert "hardware" not in message and "did you mean" not in message


def test_a_cells_hardware_file_is_not_a_cell_by_name(tmp_path):
    with pytest.raises(TaskSpecError, match="'servo_arm_pair.hardware': no such file or cell"):
        load_task(write_task(tmp_path, "servo_arm_pair.hardware"))
    assert "servo_arm_pair.hardware" not in resources.cell_files(resources.cells_dir())


def test_a_robot_name_is_not_a_tasks_cell_but_is_a_workcell(tmp_path):
    with pytest.raises(TaskSpecError, match="'panda': no such file or cell"):
        load_task(write_task(tmp_path, "panda"))
    assert resources.resolve_cell("panda") == resources.robots_dir() / "panda"


def test_the_cells_folder_is_looked_up_first_by_every_caller(tmp_path, monkeypatch):
    folder = tmp_path / "cells"
    folder.mkdir()
    mine = folder / "servo_arm_table.yaml"
    shutil.copy(SHIPPED_TABLE, mine)
    text = mine.read_text().replace("name: servo_arm_table", "name: my_cell")
    (folder / "my_cell.yaml").write_text(text)
    monkeypatch.setenv("TASKRUNNER_CELLS_DIR", str(folder))
    tasks = tmp_path / "tasks"
    tasks.mkdir()
    assert load_task(write_task(tasks, "servo_arm_table")).cell.resolve() == mine.resolve()
    assert resources.resolve_cell("servo_arm_table") == mine
    assert load_task(write_task(tasks, "my_cell")).cell.resolve() == (folder / "my_cell.yaml").resolve()
    # the shipped cells are still there by name after the cells folder's
    assert resources.resolve_cell("panda_table") == resources.cells_dir() / "panda_table.yaml"


def test_a_server_task_finds_cells_by_name_only_in_its_cells_folder(tmp_path):
    other = tmp_path / "cells"
    other.mkdir()
    tasks = tmp_path / "tasks"
    tasks.mkdir()
    task = write_task(tasks, "servo_arm_table")
    allowed = FolderPolicy(tasks=(tasks,), cells=(resources.cells_dir(),))
    assert load_task(task, policy=allowed).cell.resolve() == SHIPPED_TABLE.resolve()
    # a server whose cells folder holds no such cell does not reach the shipped ones
    elsewhere = FolderPolicy(tasks=(tasks,), cells=(other,))
    with pytest.raises(TaskSpecError, match=r"'servo_arm_table': no such file or cell "
                                            r"\(known cells: none\)"):
        load_task(task, policy=elsewhere)


def test_resolve_cell_tells_a_missing_path_from_an_unknown_name(tmp_path):
    with pytest.raises(InputError, match="no such file or folder"):
        resources.resolve_cell(str(tmp_path / "nope.yaml"))
    with pytest.raises(InputError, match=r"did you mean 'panda_table'\?"):
        resources.resolve_cell("panda_tabel")
    with pytest.raises(InputError, match="no such file, cell or robot"):
        resources.resolve_cell("nul\0name")
