"""Meshes written out from MoveIt messages go to a temporary folder during the tests."""

from __future__ import annotations

import pytest


@pytest.fixture(autouse=True, scope="session")
def _mesh_folder(tmp_path_factory: pytest.TempPathFactory):
    import os

    from taskrunner.moveit.geometry import MESH_FOLDER_ENV

    before = os.environ.get(MESH_FOLDER_ENV)
    os.environ[MESH_FOLDER_ENV] = str(tmp_path_factory.mktemp("moveit_meshes"))
    yield
    if before is None:
        os.environ.pop(MESH_FOLDER_ENV, None)
    else:
        os.environ[MESH_FOLDER_ENV] = before
