"""``run-task examples``: the example tasks that ship with taskrunner."""

from __future__ import annotations

import argparse
from pathlib import Path
from typing import TYPE_CHECKING

from taskrunner.errors import TaskrunnerError
from taskrunner.kinds import ExitCode

if TYPE_CHECKING:

    pass

__all__ = ["cmd_examples"]


def cmd_examples(args: argparse.Namespace) -> int:
    """The shipped example tasks: name, cell, first line of the description."""
    from taskrunner.resources import example_tasks
    from taskrunner.yamlfile import load_yaml

    rows = []
    for name, path in example_tasks().items():
        try:
            data = load_yaml(path)
        except TaskrunnerError as exc:  # a broken shipped file is a bug: say so, go on
            rows.append((name, "?", f"unreadable: {exc}"))
            continue
        cell = Path(str(data.get("cell", "?"))).stem if isinstance(data, dict) else "?"
        lines = str(data.get("description", "")).strip().splitlines() if isinstance(
            data, dict) else []
        rows.append((name, cell, lines[0] if lines else ""))
    width = max(len(r[0]) for r in rows)
    cell_width = max(len(r[1]) for r in rows)
    for name, cell, about in rows:
        print(f"{name:<{width}}  {cell:<{cell_width}}  {about}".rstrip())
    if args.paths:
        for name, path in example_tasks().items():
            print(f"{name}: {path}")
    return ExitCode.OK
