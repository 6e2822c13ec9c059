"""Running compiled tasks: the runner, run events and run records."""

from __future__ import annotations

from taskrunner.runtime.events import EventLog, RunEvent
from taskrunner.runtime.records import RunRecord, load_record, new_run_id, save_record

__all__ = ["EventLog", "RunEvent", "RunRecord", "load_record", "new_run_id", "save_record"]
