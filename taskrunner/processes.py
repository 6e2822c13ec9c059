"""Starting worker processes (the planning worker, the one started early by run-task).

Standard library only: ``run-task`` starts its planning worker before its own heavy
imports, through this module.
"""

from __future__ import annotations

import signal
import threading
from typing import Any

__all__ = ["start_ignoring_sigint"]


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
