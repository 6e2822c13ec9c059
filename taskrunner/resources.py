"""What ships inside the package: robots, cells, example tasks, the task schema, firmware.

Everything here is found with :mod:`importlib.resources`, so an installed wheel works with
no checkout. The shipped files are plain files on disk (pinocchio, xacro and make need real
paths); a package imported from a zip archive is refused with a clear error.

Layout of ``taskrunner/data/``::

    robots/<robot>/robot.yaml     robots (servo_arm, panda, ur5)
    robots/cells/<cell>.yaml      cells (a <cell>.hardware.yaml beside one is its servo board)
    tasks/<task>.yaml             example tasks (each also a scenario test)
    tasks/task.schema.json        the task language's JSON Schema
    firmware/                     the ESP32 firmware sources and its host build
"""

from __future__ import annotations

import functools
import hashlib
import importlib.resources
import json
import os
import tempfile
from collections.abc import Mapping, Sequence
from pathlib import Path

from taskrunner.errors import InputError, did_you_mean

__all__ = ["merge_json_cache",
    "DATA_ROOT",
    "cell_files",
    "cells_dir",
    "cells_folders",
    "example_tasks",
    "firmware_dir",
    "is_bare_name",
    "KERNEL_PACKAGES",
    "kernel_cache_dir",
    "kernel_sources_digest",
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
    """Where taskrunner builds things it needs (the planner's compiled kernels, expanded
    xacro files, the host firmware …): ``$XDG_CACHE_HOME`` or ``~/.cache``, then
    ``taskrunner``."""
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "taskrunner"



def merge_json_cache(path: Path, entries: Mapping[str, object], prefix: str) -> None:
    """Merge ``entries`` into the JSON object cached at ``path``, replacing the file
    atomically (a temporary file named ``prefix…`` beside it, then a rename), so readers
    in other processes see the old file or the new one, never half of one. A missing or
    unreadable file starts empty.

    Raises:
        OSError: the folder or the file could not be written (a cache's caller ignores it:
            it only costs a measurement next time).
    """
    path.parent.mkdir(parents=True, exist_ok=True)
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
        if not isinstance(data, dict):
            data = {}
    except (OSError, ValueError):
        data = {}
    data.update(entries)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=prefix, suffix=".json")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            json.dump(data, out)
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


# The packages whose sources the compiled kernels are made of: the kernels themselves, the
# helpers they call across modules, and the constants and record layouts they freeze in.
KERNEL_PACKAGES = ("collision", "scene")


def kernel_sources_digest(root: Path | None = None) -> str:
    """A hash of the compiled kernels' sources (every module of :data:`KERNEL_PACKAGES`
    under ``root``, by default this package, whose hash is computed once): what
    :func:`kernel_cache_dir` is named by.

    numba checks a cached kernel against its own source file only: a kernel whose helper
    (in another module) changed would be loaded from the cache as it was, silently. A
    folder per version of the sources cannot be stale."""
    return _package_digest() if root is None else _sources_digest(root)


@functools.cache
def _package_digest() -> str:
    return _sources_digest(Path(__file__).parent)


def _sources_digest(root: Path) -> str:
    digest = hashlib.sha256()
    for package in KERNEL_PACKAGES:
        for path in sorted((root / package).glob("*.py")):
            digest.update(f"{package}/{path.name}\0".encode())
            digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


def kernel_cache_dir() -> Path:
    """Where numba keeps the planner's compiled kernels: ``$NUMBA_CACHE_DIR`` when set
    (numba's own setting: then clear it after changing taskrunner's sources), else
    ``numba/kernels-HASH`` in :func:`user_cache_dir` (an installed package's own folder
    may be read-only), one folder per version of the kernels' sources
    (:func:`kernel_sources_digest`); older folders may be removed at any time."""
    configured = os.environ.get("NUMBA_CACHE_DIR")
    if configured:
        return Path(configured)
    return user_cache_dir() / "numba" / f"kernels-{kernel_sources_digest()}"


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
    from taskrunner.textfile import file_problem

    text = os.fspath(name_or_path)
    path = Path(text)
    problem = file_problem(path)  # never raises: a NUL, a name too long, a loop are problems
    if problem is None or problem.startswith("not a regular file"):
        return path  # the loader says what else it is (a folder, a FIFO)
    if problem != "file not found":
        raise InputError(f"task {text!r}: {problem}")
    examples = example_tasks()
    name = text[:-5] if text.endswith(".yaml") else text
    if os.sep not in text and "/" not in text and name in examples:
        return examples[name]
    hint = (f"; shipped examples: {', '.join(examples)} (run-task examples)"
            if os.sep not in text and "/" not in text else "")
    raise InputError(f"task '{text}': no such file{hint}")


def cell_files(folder: str | os.PathLike[str]) -> dict[str, Path]:
    """The cell files of ``folder`` by name, sorted: each ``<name>.yaml`` whose name holds
    no dot. A file ``<cell>.<what>.yaml`` belongs to a cell and is not one
    (``servo_arm_pair.hardware.yaml``: the servo board of ``servo_arm_pair``)."""
    return {p.stem: p for p in sorted(Path(folder).glob("*.yaml"))
            if "." not in p.stem and p.is_file()}


def cells_folders() -> tuple[Path, ...]:
    """Where a cell's bare name is looked up, in order: the cells folder
    ``TASKRUNNER_CELLS_DIR`` (the one ``run-task serve`` serves), if set, then the
    shipped cells."""
    folders = [cells_dir()]
    if os.environ.get("TASKRUNNER_CELLS_DIR"):
        folders.insert(0, Path(os.environ["TASKRUNNER_CELLS_DIR"]))
    return tuple(folders)


def is_bare_name(text: str) -> bool:
    """Whether ``text`` is a name (``servo_arm_table``), not a path: no separator, not
    ``.`` or ``..``."""
    return bool(text) and os.sep not in text and "/" not in text and text not in (".", "..")


def resolve_cell(name_or_path: str | os.PathLike[str], *, relative_to: Path | None = None,
                 folders: Sequence[Path] | None = None, robots: bool = True) -> Path:
    """A cell or robot path, or the bare name of a cell (``servo_arm_pair``) or of a
    shipped robot (``panda``).

    The one resolution of cell names: the command line (``run-task info``),
    :func:`~taskrunner.workcell.load_workcell`, task files' ``cell:`` and the REST API's
    tasks use it. A path (relative to ``relative_to``, if given) that exists wins; a bare
    name is then a cell file ``<name>.yaml`` of ``folders`` (see :func:`cell_files`),
    first folder first, then (``robots``) a shipped robot's folder.

    Args:
        name_or_path: what the user wrote.
        relative_to: the folder a relative path is taken from (a task file's folder;
            default: the working directory).
        folders: where names are looked up (default: :func:`cells_folders`).
        robots: whether a shipped robot's name is accepted too.

    Raises:
        InputError: neither a file or folder nor a known name; the message lists the
            known cells (and says which is close, if one is).
    """
    text = os.fspath(name_or_path)
    path = Path(text) if relative_to is None else Path(relative_to) / text
    try:  # a link that leads nowhere is there too: its reader says what is wrong
        exists = os.path.lexists(path)
    except (OSError, ValueError):  # a NUL character: no such file
        exists = False
    if exists:
        return path
    if not is_bare_name(text):
        raise InputError(f"'{text}': no such file or folder")
    name = text[:-5] if text.endswith(".yaml") else text
    cells: dict[str, Path] = {}
    for folder in cells_folders() if folders is None else folders:
        for cell, file in cell_files(folder).items():
            cells.setdefault(cell, file)
    if name in cells:
        return cells[name]
    shipped_robots = (sorted(p.parent.name for p in robots_dir().glob("*/robot.yaml"))
                      if robots else [])
    if name in shipped_robots:
        return robots_dir() / name
    hint = did_you_mean(name, [*cells, *shipped_robots])
    known = f"known cells: {', '.join(cells) or 'none'}"
    if robots:
        known += f"; robots: {', '.join(shipped_robots)}"
    where = "no such file, cell or robot" if robots else "no such file or cell"
    raise InputError(f"'{text}': {where} ({known}){hint}")
