"""Without mujoco installed, taskrunner works and says how to get the physics backend."""

from __future__ import annotations

import sys

import pytest

from taskrunner.errors import InputError
from taskrunner.resources import resolve_task
from taskrunner.robot.cell import load_cell
from taskrunner.runtime.session import make_backend
from taskrunner.tasks.loader import load_task


def test_make_backend_without_mujoco_says_how_to_install_it(monkeypatch):
    monkeypatch.setitem(sys.modules, "mujoco", None)  # import mujoco -> ImportError
    for name in [m for m in sys.modules if m.startswith("taskrunner.backends.physics")]:
        monkeypatch.delitem(sys.modules, name)
    cell = load_cell(load_task(resolve_task("pick_place"), {}).cell)
    with pytest.raises(InputError, match=r"pip install 'mujoco>=3.2,<4' 'trimesh"):
        make_backend("mujoco", cell, None)
