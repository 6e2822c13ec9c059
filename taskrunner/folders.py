"""Folder containment: which files a caller may have taskrunner load.

The command line loads whatever file it is given (the user owns the machine). A server
answering requests from the network must not: a request naming ``cell: /etc/passwd``
would have its first lines quoted back in an error, and a robot given as xacro runs
Python expressions in the server. A :class:`FolderPolicy` lists the folders a caller may
load each kind of file from; the task loader and the cell loader check every path they
are about to open against it, after resolving it (symlinks followed), and refuse
anything outside with :class:`PathNotAllowedError` before the file is read or even
tested for existence.

The policy is passed down explicitly, by every function between the caller and the
loaders (``load_task(..., policy=)``, ``load_cell(..., policy=)``, ``check_task(...,
policy=)``): nothing is looked up from the thread or the process, so a load can never
run under another request's policy, or none. No policy: no containment.

A policy can also hold files that exist only in memory (an inline task sent with a
request): the task loader reads such a path's text from the policy instead of the disk,
so no other request, and no file on disk, can ever include it.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from enum import StrEnum
from pathlib import Path

from taskrunner.errors import InputError

__all__ = ["FileKind", "FolderPolicy", "PathNotAllowedError"]


class FileKind(StrEnum):
    """What a path is loaded as (each kind has its own folders)."""

    TASK = "task"
    CELL = "cell"
    ROBOT = "robot"
    MESH = "mesh"


class PathNotAllowedError(InputError):
    """A path outside the folders the policy allows for its kind of file.

    The message names the path as it was written and the kind, never anything read
    from the file (it is not opened).
    """

    def __init__(self, message: str, path: str | Path | None = None,
                 line: int | None = None) -> None:
        super().__init__(message, path, line)


def _resolved(path: Path) -> Path | None:
    """``path`` made absolute with every symlink followed; None if it cannot be (a
    symlink loop)."""
    try:
        return path.resolve()
    except (OSError, RuntimeError):
        return None


@dataclass(frozen=True)
class FolderPolicy:
    """The folders each kind of file may be loaded from.

    Attributes:
        tasks: task files and the files they include.
        cells: cell files.
        robots: robot folders, manifests, URDF and xacro files (xacro runs code:
            only the operator's robots).
        meshes: extra folders for mesh files a task declares (tasks, cells and robots
            folders are always allowed for meshes).
        memory: files held in memory, by resolved path, and their text: read instead
            of the disk (an inline task).
    """

    tasks: tuple[Path, ...] = ()
    cells: tuple[Path, ...] = ()
    robots: tuple[Path, ...] = ()
    meshes: tuple[Path, ...] = ()
    memory: Mapping[Path, str] = field(default_factory=dict)

    def __post_init__(self) -> None:
        for name in ("tasks", "cells", "robots", "meshes"):
            folders = tuple(f for f in (_resolved(Path(p)) for p in getattr(self, name))
                            if f is not None)
            object.__setattr__(self, name, folders)

    def folders(self, kind: FileKind) -> tuple[Path, ...]:
        """The folders ``kind`` may be loaded from."""
        if kind is FileKind.TASK:
            return self.tasks
        if kind is FileKind.CELL:
            return self.cells
        if kind is FileKind.ROBOT:
            return self.robots
        return self.meshes + self.tasks + self.cells + self.robots

    def allows(self, path: str | Path, kind: FileKind) -> bool:
        """Whether ``path`` (resolved, symlinks followed) lies inside a folder of
        ``kind``. A file held in memory is allowed as a task."""
        resolved = _resolved(Path(path))
        if resolved is None:
            return False
        if kind is FileKind.TASK and resolved in self.memory:
            return True
        return any(resolved.is_relative_to(folder) for folder in self.folders(kind))

    def check(self, path: str | Path, kind: FileKind, written: str | None = None) -> Path:
        """``path`` resolved, if the policy allows it.

        Args:
            path: the path about to be loaded.
            kind: what it is loaded as.
            written: the path as the file or request wrote it (for the message).

        Raises:
            PathNotAllowedError: outside every folder of ``kind`` (the message does not
                say whether the file exists).
        """
        if not self.allows(path, kind):
            shown = written if written is not None else str(path)
            raise PathNotAllowedError(
                f"{kind.value} {shown!r} is outside the folders this server loads "
                f"{'meshes' if kind is FileKind.MESH else kind.value + 's'} from")
        resolved = _resolved(Path(path))
        assert resolved is not None
        return resolved

    def text_of(self, path: Path) -> str | None:
        """The in-memory text of ``path`` (resolved), or None if it is a real file."""
        resolved = _resolved(path)
        return None if resolved is None else self.memory.get(resolved)

    def with_memory(self, files: Mapping[Path, str]) -> FolderPolicy:
        """This policy plus in-memory ``files`` (paths are resolved here)."""
        held = dict(self.memory)
        for path, text in files.items():
            resolved = _resolved(Path(path))
            if resolved is not None:
                held[resolved] = text
        return FolderPolicy(self.tasks, self.cells, self.robots, self.meshes, held)
