"""Warnings of the robot loader, and the strict mode that turns them into errors.

MoveIt loads configuration files that are a little wrong: it skips what it cannot use
and logs a line. taskrunner does the same, but never silently: every skipped element is
a :class:`LoadWarning` naming the file, the line and the element. In strict mode
(``strict=True`` in Python, ``LoadOptions(strict=True)``, ``--strict`` on the command
line) the first warning is raised as a :class:`~taskrunner.errors.RobotDescriptionError` instead.
"""

from __future__ import annotations

from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from taskrunner.errors import RobotDescriptionError

__all__ = ["LoadWarning", "raise_if_strict", "resolve_strict"]


@dataclass(frozen=True)
class LoadWarning:
    """Something a robot file got wrong that loading skipped.

    Attributes:
        message: what was skipped and why, naming the element.
        path: the file, if any.
        line: 1-based line in that file, if known.
    """

    message: str
    path: Path | None = None
    line: int | None = None

    def __str__(self) -> str:
        if self.path is None:
            return self.message
        where = f"{self.path}:{self.line}" if self.line is not None else str(self.path)
        return f"{where}: {self.message}"

    def error(self) -> RobotDescriptionError:
        return RobotDescriptionError(self.message, self.path, self.line)


def resolve_strict(strict: bool | None) -> bool:
    """``strict`` itself; None (not given) is not strict. The environment is not read:
    the caller passes what its options say (:class:`~taskrunner.robot.options.LoadOptions`)."""
    return bool(strict)


def raise_if_strict(warnings: Iterable[LoadWarning], strict: bool | None) -> None:
    """Raise the first warning as an error in strict mode (the others are appended).

    Raises:
        RobotDescriptionError: strict mode and at least one warning.
    """
    found = list(dict.fromkeys(warnings))
    if not found or not resolve_strict(strict):
        return
    first = found[0]
    reason = first.message
    if len(found) > 1:
        reason += f" (strict mode; {len(found) - 1} more: " + "; ".join(
            str(w) for w in found[1:]) + ")"
    raise RobotDescriptionError(reason, first.path, first.line)
