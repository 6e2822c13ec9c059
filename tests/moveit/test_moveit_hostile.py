"""Mutated MoveIt files end in our own errors (file, line, field), never a traceback."""

from __future__ import annotations

import json
import math
from pathlib import Path
from typing import Any

import numpy as np
import pytest

from taskrunner.errors import TaskrunnerError
from taskrunner.moveit import load_motion_plan_request, load_planning_scene
from taskrunner.resources import resolve_cell
from taskrunner.robot.cell import load_cell_or_robot
from taskrunner.scene import scene_from_cell
from taskrunner.yamlfile import load_yaml

FIXTURES = Path(__file__).resolve().parents[1] / "fixtures" / "moveit_scenes"
SCENES = ["ros1_table_scene.yaml", "ros2_shelf_scene.yaml", "attached_scene.yaml",
          "robowflex_scene.yaml"]
REQUESTS = ["joint_goal_request.yaml", "pose_goal_request.yaml", "robowflex_request.yaml"]
ODD_VALUES: list[Any] = [None, "", "x", -1, 0, 1e308, -1e-9, math.inf, True, [], {}, [1, 2],
                         {"x": "y"}, "b'\\x09'", 99, [[]], "package://nope/x.stl"]


def _plain(node: Any) -> Any:
    if isinstance(node, dict):
        return {k: _plain(v) for k, v in node.items()}
    if isinstance(node, list):
        return [_plain(v) for v in node]
    return node


def _paths(node: Any, at: tuple = ()) -> list[tuple]:
    out = [at]
    if isinstance(node, dict):
        for key, value in node.items():
            out += _paths(value, (*at, key))
    elif isinstance(node, list):
        for index, value in enumerate(node):
            out += _paths(value, (*at, index))
    return out


def _mutated(tree: Any, rng: np.random.Generator) -> Any:
    tree = json.loads(json.dumps(tree))
    paths = [p for p in _paths(tree) if p]
    path = paths[int(rng.integers(len(paths)))]
    parent = tree
    for key in path[:-1]:
        parent = parent[key]
    choice = int(rng.integers(len(ODD_VALUES) + 1))
    if choice == len(ODD_VALUES):
        del parent[path[-1]]
    else:
        parent[path[-1]] = ODD_VALUES[choice]
    return tree


@pytest.fixture(scope="module")
def panda():
    return load_cell_or_robot(resolve_cell("panda"))


@pytest.mark.parametrize("name", SCENES + REQUESTS)
def test_mutated_files_fail_only_with_our_errors(name: str, panda, tmp_path: Path) -> None:
    tree = _plain(load_yaml(FIXTURES / name))
    rng = np.random.default_rng(list(name.encode()))
    path = tmp_path / name
    for _ in range(60):
        path.write_text(json.dumps(_mutated(tree, rng), allow_nan=True).replace("Infinity", ".inf"))
        scene = scene_from_cell(panda)
        try:
            if name in SCENES:
                load_planning_scene(path, panda.model, strict=False).apply(scene)
            else:
                load_motion_plan_request(path, panda.model, strict=False).plan_request(scene)
        except TaskrunnerError as exc:
            assert str(path) in str(exc) or "unknown" in str(exc), exc
