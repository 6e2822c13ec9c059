"""Fixtures shared by every test folder.

The loaded models are session-scoped (loading the meshes of example-robot-data takes
time): treat them as read-only. A test that needs to change a model, or uses
``model.data`` in a way that could leak into another test, makes its own
``model.model.createData()`` or loads a fresh copy with ``load_robot``.
"""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path

import pytest

from taskrunner.resources import DATA_ROOT
from taskrunner.robot import RobotModel, load_robot
from taskrunner.robot.packages import example_robot_data_dir

REPO_ROOT = Path(__file__).resolve().parents[1]


@pytest.fixture(scope="session", autouse=True)
def _verifier_kernels_compiled() -> None:
    """The path verifier's and the search screen's kernels, compiled (or loaded from numba's disk cache) before
    the first test: on a fresh machine the first plan compiles them (10-15 s of CPU,
    minutes on a busy machine), which would otherwise fall inside whichever test plans
    first, in this process or in a planning worker, and past its deadlines."""
    from taskrunner.scene import Scene
    from taskrunner.scene.screen import warm_kernels

    scene = Scene(load_robot(DATA_ROOT / "robots" / "servo_arm"))
    warm_kernels(scene.path_verifier(), scene.state)


# What `run-task`'s robot options set for its workers (os.environ): a test that calls the
# CLI in-process must not leave them to the tests after it.
_CLI_ENV = ("TASKRUNNER_STRICT", "TASKRUNNER_PACKAGE_PATH", "TASKRUNNER_COLLISION",
            "TASKRUNNER_ALLOW_MISSING_MESHES")


@pytest.fixture(autouse=True)
def _cli_environment_restored() -> Iterator[None]:
    before = {name: os.environ.get(name) for name in _CLI_ENV}
    yield
    for name, value in before.items():
        if value is None:
            os.environ.pop(name, None)
        else:
            os.environ[name] = value


@pytest.fixture(scope="session")
def repo_root() -> Path:
    """The repository's top folder (holds ``taskrunner/``, ``robots/``, ``tests/``)."""
    return REPO_ROOT


@pytest.fixture(scope="session")
def robots_dir(repo_root: Path) -> Path:
    """``robots/``: the robot folders (servo_arm, panda, ur5) and ``cells/``."""
    return DATA_ROOT / "robots"


@pytest.fixture(scope="session")
def example_robot_data() -> Path:
    """The share folder of the example-robot-data wheel (its ``robots/`` holds the URDFs)."""
    folder = example_robot_data_dir()
    if folder is None:
        pytest.skip("example-robot-data is not installed (pip install -e .[test])")
    return folder


@pytest.fixture(scope="session")
def servo_arm_model(robots_dir: Path) -> RobotModel:
    """robots/servo_arm: 5-DOF hobby-servo arm + 2 finger joints, groups arm / gripper."""
    return load_robot(robots_dir / "servo_arm")


@pytest.fixture(scope="session")
def panda_model(robots_dir: Path, example_robot_data: Path) -> RobotModel:
    """robots/panda: Franka Panda (groups arm / hand / arm_and_hand, mimic finger)."""
    return load_robot(robots_dir / "panda")


@pytest.fixture(scope="session")
def ur5_model(robots_dir: Path, example_robot_data: Path) -> RobotModel:
    """robots/ur5: UR5 (group manipulator, base_link → tool0, pose home)."""
    return load_robot(robots_dir / "ur5")
