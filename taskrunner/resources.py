"""What ships inside the package: robots, cells, example tasks, the task schema, firmware.

Everything here is found with :mod:`importlib.resources`, so an installed wheel works with
no checkout. The shipped files are plain files on disk (pinocchio, xacro and make need real
paths); a package imported from a zip archive is refused with a clear error.

Layout of ``taskrunner/data/``::

    robots/<robot>/robot.yaml     robots (servo_arm, panda, ur5)
    robots/cells/<cell>.yaml      cells
    tasks/<task>.yaml             example tasks (each also a scenario test)
    tasks/task.schema.json        the task language's JSON Schema
    firmware/                     the ESP32 firmware sources and its host build
"""

from __future__ import annotations

import importlib.resources
import os
from pathlib import Path

from taskrunner.errors import InputError

__all__ = [
    "DATA_ROOT",
    "cells_dir",
    "example_tasks",
    "firmware_dir",
    "resolve_cell",
    "resolve_task",
    "robots_dir",
    "tasks_dir",
    "user_cache_dir",
]


def _data_root() -> Path:
    root = importlib.resources.files("taskrunner") / "data"
    path = Path(str(root))
    if not path.is_dir():
        raise ImportError(f"taskrunner's package data is not a folder on disk ({root}); "
                          "install taskrunner as a regular (unzipped) package")
    return path


DATA_ROOT: Path = _data_root()


def robots_dir() -> Path:
    """The shipped robot folders (``servo_arm``, ``panda``, ``ur5``) and ``cells/``."""
    return DATA_ROOT / "robots"


def cells_dir() -> Path:
    """The shipped cell files."""
    return DATA_ROOT / "robots" / "cells"


def tasks_dir() -> Path:
    """The shipped example tasks."""
    return DATA_ROOT / "tasks"


def firmware_dir() -> Path:
    """The ESP32 firmware sources (protocol core, sketch, host build, Makefile)."""
    return DATA_ROOT / "firmware"


def user_cache_dir() -> Path:
    """Where taskrunner builds things it needs (the host firmware): ``$XDG_CACHE_HOME``
    or ``~/.cache``, then ``taskrunner``."""
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "taskrunner"


def example_tasks() -> dict[str, Path]:
    """The shipped example tasks by name (file name without ``.yaml``), sorted."""
    return {p.stem: p for p in sorted(tasks_dir().glob("*.yaml"))}


def resolve_task(name_or_path: str | os.PathLike[str]) -> Path:
    """A task file from a path, or from the bare name of a shipped example.

    A path that exists wins (``tasks/pick_place.yaml``, ``./my_task.yaml``); a bare name
    with no separator and no such file (``pick_place``) is a shipped example.

    Raises:
        InputError: neither a file nor an example's name.
    """
    text = os.fspath(name_or_path)
    path = Path(text)
    if path.exists():
        return path
    examples = example_tasks()
    name = text[:-5] if text.endswith(".yaml") else text
    if os.sep not in text and "/" not in text and name in examples:
        return examples[name]
    hint = (f"; shipped examples: {', '.join(examples)} (run-task examples)"
            if os.sep not in text and "/" not in text else "")
    raise InputError(f"task '{text}': no such file{hint}")


def resolve_cell(name_or_path: str | os.PathLike[str]) -> Path:
    """A cell or robot path, or the bare name of a shipped cell (``servo_arm_pair``) or
    robot (``panda``).

    Raises:
        InputError: neither a file or folder nor a shipped cell's or robot's name.
    """
    text = os.fspath(name_or_path)
    path = Path(text)
    if path.exists():
        return path
    if os.sep not in text and "/" not in text:
        name = text[:-5] if text.endswith(".yaml") else text
        if (cells_dir() / f"{name}.yaml").is_file():
            return cells_dir() / f"{name}.yaml"
        if (robots_dir() / name / "robot.yaml").is_file():
            return robots_dir() / name
        cells = sorted(p.stem for p in cells_dir().glob("*.yaml"))
        robots = sorted(p.parent.name for p in robots_dir().glob("*/robot.yaml"))
        raise InputError(f"'{text}': no such file, cell or robot (shipped cells: "
                         f"{', '.join(cells)}; robots: {', '.join(robots)})")
    raise InputError(f"'{text}': no such file or folder")
