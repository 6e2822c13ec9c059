"""Load options passed, not looked up (issue 24, item 7): ``LoadOptions`` reach the robot
loaders and the planning workers as arguments; the environment is read only where a
program starts (the command line)."""

from __future__ import annotations

import os
import threading
from pathlib import Path

import pytest

from taskrunner.errors import ArgumentError, MissingMeshError, TaskrunnerError
from taskrunner.robot import LoadOptions
from taskrunner.robot.cell import Cell, load_cell_or_robot

WS_SRC = Path(__file__).resolve().parent / "fixtures" / "ws" / "src"
VARIABLES = ("TASKRUNNER_STRICT", "TASKRUNNER_PACKAGE_PATH", "TASKRUNNER_ALLOW_MISSING_MESHES",
             "TASKRUNNER_COLLISION")


@pytest.fixture
def mini_folder(make_mini, monkeypatch: pytest.MonkeyPatch) -> Path:
    """The mini arm as a robot folder whose meshes are in package ``mini_description``,
    which nothing near the folder has: found only through a package path."""
    for name in VARIABLES:
        monkeypatch.delenv(name, raising=False)
    return make_mini().folder


def test_two_cells_loaded_at_once_in_one_process_each_follow_their_own_options(mini_folder):
    found = LoadOptions(strict=True, package_path=(WS_SRC,), collision="convex")
    lossy = LoadOptions(allow_missing_meshes=True)
    loaded: dict[str, Cell | BaseException] = {}

    def load(name: str, options: LoadOptions) -> None:
        try:
            loaded[name] = load_cell_or_robot(mini_folder, options=options)
        except TaskrunnerError as exc:
            loaded[name] = exc

    threads = [threading.Thread(target=load, args=(name, options))
               for name, options in (("found", found), ("lossy", lossy), ("plain", LoadOptions()))]
    for thread in threads:
        thread.start()
    for thread in threads:
        thread.join()
    strict_cell, lossy_cell = loaded["found"], loaded["lossy"]
    assert isinstance(strict_cell, Cell) and isinstance(lossy_cell, Cell), loaded
    # The strict one found every mesh through its package path, and took its geometry.
    assert strict_cell.model.warnings == []
    assert strict_cell.model.instances[0].collision == "convex"
    assert "link2" not in strict_cell.model.links_without_collision_geometry()
    # The other had no package path: loaded without the meshes, as it allowed, with the
    # robot's own collision choice.
    assert len(lossy_cell.model.warnings) == 1
    assert "loaded WITHOUT 3 mesh file(s)" in lossy_cell.model.warnings[0]
    assert lossy_cell.model.instances[0].collision == "auto"
    assert "link2" in lossy_cell.model.links_without_collision_geometry()
    # Neither's options leaked into a load that gave none.
    assert isinstance(loaded["plain"], MissingMeshError)
    assert "package 'mini_description' not found" in str(loaded["plain"])


def test_the_environment_is_read_only_by_from_env(mini_folder, monkeypatch):
    monkeypatch.setenv("TASKRUNNER_PACKAGE_PATH", str(WS_SRC))
    monkeypatch.setenv("TASKRUNNER_STRICT", "1")
    with pytest.raises(MissingMeshError):
        load_cell_or_robot(mini_folder)  # the loader does not look at the variables
    options = LoadOptions.from_env()
    assert options == LoadOptions(strict=True, package_path=(WS_SRC,))
    assert load_cell_or_robot(mini_folder, options=options).model.warnings == []
    assert LoadOptions.from_env({}) == LoadOptions()
    with pytest.raises(ArgumentError, match="'TASKRUNNER_STRICT' must be 1 or 0 .got 'maybe'"):
        LoadOptions.from_env({"TASKRUNNER_STRICT": "maybe"})
    with pytest.raises(ArgumentError, match="'strict' must be a bool .got 'yes'"):
        LoadOptions(strict="yes")  # type: ignore[arg-type]
    with pytest.raises(ArgumentError, match="'package_path' must be a sequence of folders"):
        LoadOptions(package_path="/opt/ws")  # type: ignore[arg-type]


def test_a_planning_worker_loads_with_the_options_it_is_started_with(mini_folder):
    import numpy as np

    from taskrunner.planning import JointGoal, PlanRequest
    from taskrunner.planning.worker import PlanningWorker
    from taskrunner.scene import scene_from_cell

    options = LoadOptions(package_path=(WS_SRC,), collision="exact")
    here = load_cell_or_robot(mini_folder, options=options)
    group = here.model.group("arm")
    goal = here.model.named_state("arm", "home").as_dict()  # the SRDF's pose
    # No variable is set (the fixture removed them): the worker has only its argument.
    assert not any(name in os.environ for name in VARIABLES)
    with PlanningWorker(mini_folder, options=options) as worker:
        result = worker.plan(scene_from_cell(here), PlanRequest(group.name, JointGoal(goal)))
    assert np.allclose(result.path.waypoints[-1][group.joint_indices], list(goal.values()),
                       atol=1e-9)
    # Without them the same worker cannot load the robot: its meshes are not found.
    with pytest.raises(MissingMeshError, match="mini_description"):
        PlanningWorker(mini_folder).close()


def test_the_cli_flags_reach_the_loader_without_touching_the_environment(mini_folder, capsys):
    from taskrunner.cli import main

    before = dict(os.environ)
    assert main(["info", str(mini_folder)]) == 2
    assert "package 'mini_description' not found" in capsys.readouterr().err
    assert main(["info", str(mini_folder), "--strict", "--package-path", str(WS_SRC),
                 "--collision", "convex"]) == 0
    out = capsys.readouterr().out
    assert "collision geometry (mini convex):" in out and "warning:" not in out
    assert main(["info", str(mini_folder), "--allow-missing-meshes"]) == 0
    assert "loaded WITHOUT 3 mesh file(s)" in capsys.readouterr().out
    assert dict(os.environ) == before


def test_options_kept_as_data_come_back_the_same_and_bad_data_is_refused(tmp_path):
    options = LoadOptions(strict=True, package_path=(tmp_path,), allow_missing_meshes=True,
                          collision="exact")
    data = options.as_data()
    assert data == {"strict": True, "package_path": [str(tmp_path.resolve())],
                    "allow_missing_meshes": True, "collision": "exact"}
    assert LoadOptions.from_data(data) == options
    assert LoadOptions.from_data(LoadOptions().as_data()) == LoadOptions()
    for bad, said in (({"strict": "yes"}, "must be bools"), ({"collision": "mesh"},
                      "one of exact, convex, auto"), ({"package_path": "/opt"}, "a list"),
                      ({"colision": "exact"}, "unknown field 'colision'")):
        with pytest.raises(ArgumentError, match=said):
            LoadOptions.from_data(bad)


def test_the_server_finds_packages_on_its_package_path_setting(mini_folder, tmp_path):
    from fastapi.testclient import TestClient

    from taskrunner.api import Settings, create_app

    cells = tmp_path / "cells"
    cells.mkdir()
    (cells / "mini_cell.yaml").write_text(
        f"name: mini_cell\nrobots:\n  - {{name: arm, robot: {mini_folder}}}\n")
    with pytest.raises(ArgumentError, match="TASKRUNNER_PACKAGE_PATH: .*must be folders "
                                            "\\(not found: /no/such/folder\\)"):
        Settings.from_env({"TASKRUNNER_PACKAGE_PATH": f"{WS_SRC}{os.pathsep}/no/such/folder"})
    for package_path, status in (((), 422), ((WS_SRC,), 200)):
        settings = Settings.from_env(
            {}, token="t" * 32, data_dir=tmp_path / f"state{len(package_path)}",
            cells_dir=cells, robots_dirs=(mini_folder.parent,), planner="inprocess",
            package_path=package_path or None)
        assert settings.load_options().package_path == tuple(p.resolve() for p in package_path)
        with TestClient(create_app(settings), headers={"Authorization": "Bearer " + "t" * 32}
                        ) as client:
            answer = client.get("/cells/mini_cell")
        assert answer.status_code == status, answer.text
        if status == 422:
            assert "package 'mini_description' not found" in answer.text
