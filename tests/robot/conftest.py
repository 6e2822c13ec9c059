"""Fixtures of the robot-loading tests: the tiny "mini" arm and its bad variants.

``fixtures/ws/src`` is a ROS-style workspace as the MoveIt Setup Assistant leaves it:
``mini_description`` (package.xml, ``urdf/mini.urdf.xacro`` + macros, one STL) and
``mini_moveit_config`` (``.setup_assistant``, SRDF, kinematics.yaml, joint_limits.yaml).

Bad files are not committed one by one: :func:`make_mini` writes the mini robot as a
``robot.yaml`` manifest plus a *plain* URDF (the expanded xacro, so that errors carry
line numbers) into ``tmp_path`` with the requested edits applied.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from pathlib import Path

import pytest

from taskrunner.errors import InputError, TaskrunnerError
from taskrunner.robot import PackageMap, RobotModel, load_robot
from taskrunner.robot.urdf import expand_xacro

FIXTURES = Path(__file__).resolve().parent / "fixtures"
WS_SRC = FIXTURES / "ws" / "src"
MINI_DESCRIPTION = WS_SRC / "mini_description"
MINI_CONFIG = WS_SRC / "mini_moveit_config"

MINI_MANIFEST = """\
name: mini
urdf: mini.urdf
srdf: mini.srdf
kinematics: kinematics.yaml
joint_limits: joint_limits.yaml
"""

# An edit: the new text, (old, new) to replace once (old must be present), or a function.
Edit = str | tuple[str, str] | Callable[[str], str]


def apply_edit(text: str, edit: Edit) -> str:
    if callable(edit):
        return edit(text)
    if isinstance(edit, tuple):
        old, new = edit
        assert old in text, f"fixture drifted: {old!r} not found"
        return text.replace(old, new, 1)
    return edit


def line_in(text: str, needle: str, after: str | None = None) -> int:
    """1-based number of the first line holding ``needle`` (below the line holding ``after``)."""
    lines = text.splitlines()
    start = 0
    if after is not None:
        start = next(i for i, line in enumerate(lines) if after in line) + 1
    for i in range(start, len(lines)):
        if needle in lines[i]:
            return i + 1
    raise AssertionError(f"{needle!r} not found")


def assert_located(error: BaseException, path: Path, line: int | None = None) -> str:
    """Check that ``error`` is ours and its message starts with ``path:line:``; return it."""
    assert isinstance(error, TaskrunnerError), f"not a taskrunner error: {error!r}"
    assert isinstance(error, InputError)
    message = str(error)
    where = f"{path}:{line}: " if line is not None else f"{path}: "
    assert message.startswith(where), f"{message!r} does not start with {where!r}"
    assert error.path == path and error.line == line
    return message


@dataclass
class MiniRobot:
    """A mini robot written to a folder: robot.yaml, mini.urdf, mini.srdf and the YAML."""

    folder: Path
    packages: PackageMap

    def path(self, name: str) -> Path:
        return self.folder / name

    def text(self, name: str) -> str:
        return self.path(name).read_text()

    def line(self, name: str, needle: str, after: str | None = None) -> int:
        return line_in(self.text(name), needle, after)

    def load(self, strict: bool | None = None,
             allow_missing_meshes: bool | None = None) -> RobotModel:
        return load_robot(self.folder, self.packages, strict=strict,
                          allow_missing_meshes=allow_missing_meshes)

    def error(self, kind: type[TaskrunnerError] = InputError,
              strict: bool | None = None) -> TaskrunnerError:
        """The error that loading raises (fails the test unless it is a ``kind``)."""
        with pytest.raises(TaskrunnerError) as info:
            self.load(strict)
        assert isinstance(info.value, kind), f"expected {kind.__name__}, got {info.value!r}"
        return info.value


@pytest.fixture(scope="session")
def mini_config_dir() -> Path:
    """The MoveIt config package of the mini arm (load it with ``load_robot(folder)``)."""
    return MINI_CONFIG


@pytest.fixture(scope="session")
def mini_description_dir() -> Path:
    return MINI_DESCRIPTION


@pytest.fixture(scope="session")
def mini_model() -> RobotModel:
    """The mini arm loaded from its MoveIt config package (read-only: it is shared)."""
    return load_robot(MINI_CONFIG)


@pytest.fixture(scope="session")
def mini_texts() -> dict[str, str]:
    """The mini robot's files as text; the URDF is the expanded xacro."""
    urdf = expand_xacro(
        MINI_DESCRIPTION / "urdf" / "mini.urdf.xacro",
        PackageMap({"mini_description": MINI_DESCRIPTION}),
    )
    return {
        "robot.yaml": MINI_MANIFEST,
        "mini.urdf": urdf,
        "mini.srdf": (MINI_CONFIG / "config" / "mini.srdf").read_text(),
        "kinematics.yaml": (MINI_CONFIG / "config" / "kinematics.yaml").read_text(),
        "joint_limits.yaml": (MINI_CONFIG / "config" / "joint_limits.yaml").read_text(),
    }


@pytest.fixture
def make_mini(tmp_path: Path, mini_texts: dict[str, str]) -> Callable[..., MiniRobot]:
    """``make_mini({"mini.srdf": ("old", "new")})`` → a :class:`MiniRobot` in tmp_path.

    The folder sits one level below tmp_path, so the default package search (the
    manifest's folder and the one above) never walks into other tests' folders; tmp_path
    carries a workspace marker, so the last-resort search of the folders above a robot
    (tier 7) stops there too, and never finds a same-named package in another test's (or
    another test run's) folder under the shared pytest temporary root.
    """

    def make(edits: Mapping[str, Edit] | None = None) -> MiniRobot:
        (tmp_path / ".catkin_workspace").touch()
        folder = (tmp_path / "mini").resolve()
        folder.mkdir(exist_ok=True)
        for name, text in mini_texts.items():
            edit = (edits or {}).get(name)
            (folder / name).write_text(apply_edit(text, edit) if edit is not None else text)
        unknown = set(edits or {}) - set(mini_texts)
        assert not unknown, f"no such mini file: {unknown}"
        return MiniRobot(folder, PackageMap({"mini_description": MINI_DESCRIPTION}))

    return make


@pytest.fixture
def located() -> Callable[..., str]:
    """:func:`assert_located`, for test modules (they cannot import conftest)."""
    return assert_located
