"""Starting worker processes (the planning worker, the one started early by run-task).

Standard library only: ``run-task`` starts its planning worker before its own heavy
imports, through this module.
"""

from __future__ import annotations

import os
import signal
import sys
import threading
from collections.abc import Callable
from typing import Any

__all__ = ["cpu_seconds", "ending_with_parent", "start_ignoring_sigint"]

_PR_SET_PDEATHSIG = 1  # linux/prctl.h
_CLOCK_TICKS = os.sysconf("SC_CLK_TCK") if hasattr(os, "sysconf") else 100


def cpu_seconds(pid: int | None) -> float | None:
    """CPU time (user + system, s) process ``pid`` has used, or None where /proc does
    not tell (not Linux, or the process is gone): then a caller counts wall-clock time."""
    if pid is None:
        return None
    try:
        with open(f"/proc/{pid}/stat", "rb") as stat:
            fields = stat.read().rsplit(b")", 1)[1].split()
    except OSError:
        return None
    # After the command's closing parenthesis: state is field 3, utime 14, stime 15.
    return (int(fields[11]) + int(fields[12])) / _CLOCK_TICKS


def ending_with_parent(signum: int = signal.SIGTERM) -> Callable[[], None] | None:
    """A ``preexec_fn`` for :class:`subprocess.Popen` after which the child is sent
    ``signum`` when the process that started it ends, however it ends (SIGKILL
    included): Linux's ``PR_SET_PDEATHSIG``. None where the platform has no such thing.

    The C library is looked up here, in the parent: the function run between fork and
    exec calls it and nothing else. A parent that ended before the call (the child then
    belongs to another process) ends the child at once."""
    if not sys.platform.startswith("linux"):
        return None
    import ctypes

    try:
        prctl = ctypes.CDLL(None, use_errno=True).prctl
    except (OSError, AttributeError):
        return None
    parent = os.getpid()

    def preexec() -> None:
        prctl(_PR_SET_PDEATHSIG, signum, 0, 0, 0)
        if os.getppid() != parent:
            os.kill(os.getpid(), signum)

    return preexec


def start_ignoring_sigint(process: Any) -> None:
    """Start a worker ``process`` with SIGINT ignored. An ignored signal stays ignored
    across exec (and Python then installs no KeyboardInterrupt handler): a Ctrl-C while
    the child imports cannot end it with a traceback; its parent decides what Ctrl-C
    means. Only the main thread may set handlers; a SIGINT in the few ms of start() is
    lost for the parent too."""
    main = threading.current_thread() is threading.main_thread()
    previous = signal.signal(signal.SIGINT, signal.SIG_IGN) if main else None
    try:
        process.start()
    finally:
        if main:
            signal.signal(signal.SIGINT, previous)
