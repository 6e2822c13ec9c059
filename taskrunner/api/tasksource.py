"""Loading the task a request names: a file of the tasks folder, or inline YAML."""

from __future__ import annotations

import os
import tempfile
from collections.abc import Iterator
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from taskrunner.api.runs import resolve_task_file
from taskrunner.tasks import load_task, load_task_text
from taskrunner.tasks.spec import TaskSpec

__all__ = ["INLINE_NAME", "inline_path", "load_request_task", "task_file_for_check"]

INLINE_NAME = "inline.yaml"


def inline_path(tasks_dir: Path) -> Path:
    """The path inline YAML stands for: messages name it; relative paths start there."""
    return tasks_dir / INLINE_NAME


def load_request_task(tasks_dir: Path, task: str | None, yaml: str | None,
                      parameters: dict[str, Any]) -> tuple[TaskSpec, str, str]:
    """The task of a request: ``(spec, task_file, task_text)``.

    An inline task's spec has no path (it names no file the runner could read back).

    Raises:
        InputError: no such task file; TaskSpecError: an invalid task (file:line).
    """
    if task is not None:
        path = resolve_task_file(tasks_dir, task)
        return load_task(path, parameters), str(path), path.read_text(encoding="utf-8")
    assert yaml is not None
    spec = load_task_text(yaml, inline_path(tasks_dir), parameters)
    return spec.model_copy(update={"path": None}), str(inline_path(tasks_dir)), yaml


@contextmanager
def task_file_for_check(tasks_dir: Path, task: str | None, yaml: str | None
                        ) -> Iterator[tuple[Path, Path | None]]:
    """A task file to check, and the temporary file standing for inline YAML (None for a
    named file). The temporary file sits in the tasks folder, so relative paths resolve
    as they would for a task file there; it is removed on exit."""
    if task is not None:
        yield resolve_task_file(tasks_dir, task), None
        return
    assert yaml is not None
    fd, name = tempfile.mkstemp(dir=tasks_dir, prefix=".inline-", suffix=".yaml")
    try:
        with os.fdopen(fd, "w", encoding="utf-8") as out:
            out.write(yaml)
        yield Path(name), Path(name)
    finally:
        Path(name).unlink(missing_ok=True)
