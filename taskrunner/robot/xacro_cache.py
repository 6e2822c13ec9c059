"""A cache of xacro expansions, checked against everything the expansion read.

Expanding a xacro robot takes 50-100 ms (a forked child process, xacro itself), and
``run-task`` loads its cell's robots twice (the check before the run, then the run) and
once more in its planning worker. :func:`lookup` and :func:`store` keep each
expansion in memory and on disk (``user_cache_dir()/xacro``, one JSON file per xacro
file and argument set) with what it depended on:

* every file xacro read (the xacro file, its includes, ``load_yaml`` files), by SHA-256
  of its content;
* every environment variable read by ``$(env)`` / ``$(optenv)`` (its value, or unset);
* every package ``$(find)`` resolved, and the folder it resolved to.

An expansion that includes files by a glob pattern is not cached (which files match
may change without any file it read changing).

A cached expansion is used only when all of these still hold (the files are read and
hashed again, the variables and packages looked up again): an edit to any included
file, a changed variable or a package found elsewhere expands again. Python
expressions inside xacro (``${...}``) see none of the outside world but these.

At most ``MAX_FILES`` expansions stay on disk. The cache is skipped when
``TASKRUNNER_XACRO_CACHE=0``; a cache folder that cannot be
written is not an error (the expansion is simply not kept on disk).
"""

from __future__ import annotations

import hashlib
import json
import os
import tempfile
import threading
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from taskrunner.textfile import file_problem

__all__ = ["XacroInputs", "cache_enabled", "lookup", "store"]

_FORMAT = 1
MAX_FILES = 200
"""Expansions kept on disk; the least recently written go first (one per xacro file and
argument set, 10-100 kB each)."""
_MEMORY: dict[str, tuple[str, dict[str, Any]]] = {}
_LOCK = threading.Lock()


@dataclass
class XacroInputs:
    """What one expansion read (filled while it runs)."""

    files: dict[str, str] = field(default_factory=dict)  # resolved path → SHA-256
    env: dict[str, str | None] = field(default_factory=dict)  # name → value (None: unset)
    finds: dict[str, str] = field(default_factory=dict)  # package → folder
    cacheable: bool = True  # False: it depends on something not tracked (a glob include)

    def read_file(self, path: str | Path, data: bytes) -> None:
        self.files[str(Path(path).resolve())] = hashlib.sha256(data).hexdigest()

    def as_dict(self) -> dict[str, Any]:
        return {"files": self.files, "env": self.env, "finds": self.finds}


def cache_enabled() -> bool:
    """False when ``TASKRUNNER_XACRO_CACHE`` is ``0`` (or ``false``, ``no``, ``off``)."""
    return os.environ.get("TASKRUNNER_XACRO_CACHE", "1").strip().lower() not in (
        "0", "false", "no", "off")


def _key(path: Path, mappings: dict[str, str] | None) -> str:
    import xacro

    what = {"format": _FORMAT, "path": str(path.resolve()),
            "mappings": sorted((mappings or {}).items()),
            "xacro": getattr(xacro, "__version__", "")}
    return hashlib.sha256(json.dumps(what, sort_keys=True).encode()).hexdigest()


def _folder() -> Path:
    from taskrunner.resources import user_cache_dir

    return user_cache_dir() / "xacro"


def _still_valid(inputs: dict[str, Any], find: Callable[[str], str]) -> bool:
    for name, value in inputs.get("env", {}).items():
        if os.environ.get(name) != value:
            return False
    for package, folder in inputs.get("finds", {}).items():
        try:
            if find(package) != folder:
                return False
        except Exception:  # not found any more: expand again, and let xacro report it
            return False
    for name, digest in inputs.get("files", {}).items():
        if file_problem(name) is not None:  # gone, or no longer a regular file
            return False
        try:
            data = Path(name).read_bytes()
        except OSError:
            return False
        if hashlib.sha256(data).hexdigest() != digest:
            return False
    return bool(inputs.get("files"))


def lookup(path: Path, mappings: dict[str, str] | None,
           find: Callable[[str], str]) -> str | None:
    """The cached expansion of ``path`` with ``mappings`` if everything it read is
    unchanged (``find`` resolves a package as the expansion would), else None."""
    if not cache_enabled():
        return None
    key = _key(path, mappings)
    with _LOCK:
        entry = _MEMORY.get(key)
    if entry is None:
        try:
            data = json.loads((_folder() / f"{key}.json").read_text(encoding="utf-8"))
            if data.get("format") != _FORMAT or not isinstance(data.get("text"), str):
                return None
            entry = (data["text"], data["inputs"])
        except (OSError, ValueError, KeyError, TypeError):
            return None
    text, inputs = entry
    if not _still_valid(inputs, find):
        return None
    with _LOCK:
        _MEMORY[key] = entry
    return text


def store(path: Path, mappings: dict[str, str] | None, text: str, inputs: XacroInputs) -> None:
    """Keep an expansion and what it read (in memory, and on disk when possible)."""
    if not cache_enabled() or not inputs.files or not inputs.cacheable:
        return
    key = _key(path, mappings)
    entry = (text, inputs.as_dict())
    with _LOCK:
        _MEMORY[key] = entry
    folder = _folder()
    try:
        folder.mkdir(parents=True, exist_ok=True)
        with tempfile.NamedTemporaryFile("w", encoding="utf-8", dir=folder, suffix=".tmp",
                                         delete=False) as handle:
            json.dump({"format": _FORMAT, "source": str(path), "text": text,
                       "inputs": entry[1]}, handle)
        os.replace(handle.name, folder / f"{key}.json")
    except OSError:
        try:
            os.unlink(handle.name)
        except (OSError, UnboundLocalError):
            pass
        return
    _prune(folder)


def _prune(folder: Path) -> None:
    """Keep the folder to ``MAX_FILES`` entries: drop the least recently written."""
    try:
        entries = [(entry.stat().st_mtime_ns, entry) for entry in folder.glob("*.json")]
    except OSError:
        return
    if len(entries) <= MAX_FILES:
        return
    entries.sort()
    for _, entry in entries[:len(entries) - MAX_FILES]:
        try:
            entry.unlink()
        except OSError:
            pass


def clear_memory() -> None:
    """Forget the in-memory entries (tests; the disk cache stays)."""
    with _LOCK:
        _MEMORY.clear()
