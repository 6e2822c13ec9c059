"""Cells by name through the API: ``GET /cells`` lists cells only, and a task sent to
``POST /runs`` names its cell by name within the server's cells folder."""

from __future__ import annotations

import shutil
from pathlib import Path

from apitest import AUTH, make_settings, wait_until_done
from fastapi.testclient import TestClient

from taskrunner import resources
from taskrunner.api import create_app

BY_NAME = "task: go_home_by_name\ncell: servo_arm_table\nsteps:\n  - go: {group: arm, to: home}\n"


def test_the_cell_list_holds_no_hardware_file(client):
    ids = [c["id"] for c in client.get("/cells").json()]
    assert ids == sorted(resources.cell_files(resources.cells_dir()))
    assert "servo_arm_pair" in ids and not [i for i in ids if "." in i]
    assert client.get("/cells/servo_arm_pair.hardware").status_code == 404


def test_an_inline_task_naming_a_cell_by_name_runs(client):
    answer = client.post("/runs", json={"yaml": BY_NAME, "backend": "mock"}, headers=AUTH)
    assert answer.status_code == 202, answer.text
    run = wait_until_done(client, answer.json()["run_id"])
    assert run["status"] == "succeeded" and run["cell"] == "servo_arm_table"


def test_a_cell_name_is_looked_up_in_the_servers_cells_folder_only(tmp_path: Path):
    cells = tmp_path / "cells"
    cells.mkdir()
    shutil.copy(resources.cells_dir() / "panda_table.yaml", cells / "panda_table.yaml")
    settings = make_settings(tmp_path / "state", cells_dir=cells)
    with TestClient(create_app(settings), headers=AUTH) as client:
        answer = client.post("/runs", json={"yaml": BY_NAME, "backend": "mock"})
        assert answer.status_code == 422, answer.text
        detail = answer.json()["detail"]
        assert "inline.yaml:2" in detail
        assert "'servo_arm_table': no such file or cell (known cells: panda_table)" in detail
