"""Kinds and codes defined once, as enums: what a command line, the REST API and a run
record say with the same values.

An :class:`~enum.IntEnum` is an ``int`` and a :class:`~enum.StrEnum` a ``str``: each
compares equal to, hashes as, and encodes to JSON as its value, so that records and API
answers keep the bytes they had when these were plain constants.
"""

from __future__ import annotations

from enum import IntEnum

__all__ = ["ExitCode"]


class ExitCode(IntEnum):
    """``run-task``'s exit codes, by outcome."""

    OK = 0
    """Success (a run that succeeded, a check that found no problem)."""
    INVALID = 2
    """An invalid task, file or argument."""
    PLANNING = 3
    """No motion could be planned."""
    EXECUTION = 4
    """A backend failed or refused a motion, or an expectation was missed."""
    CANCELLED = 130
    """Cancelled (Ctrl-C: 128 + SIGINT)."""
    TERMINATED = 143
    """Cancelled by SIGTERM (128 + 15)."""
