"""Teaching right after a run: once the run's record says it ended (what GET /runs/{id}
shows), the cell counts as still, even while the run's thread is saving its record."""

from __future__ import annotations

from pathlib import Path
from types import SimpleNamespace

from taskrunner.api.runs import LiveRun, RunManager
from taskrunner.api.store import RunStore
from taskrunner.runtime.events import EventLog
from taskrunner.runtime.records import RunRecord


def _live(session: object, run_id: str, status: str) -> LiveRun:
    record = RunRecord(run_id, "t", "t.yaml", "cell", "mock", {}, status=status)
    runner = SimpleNamespace(record=record, events=EventLog())
    return LiveRun(runner, session, frozenset({"j1"}))  # type: ignore[arg-type]


def test_a_run_whose_record_has_ended_no_longer_holds_its_cell_still(tmp_path: Path):
    store = RunStore(tmp_path / "runs.db")
    try:
        manager = RunManager(None, store)  # type: ignore[arg-type]  # no run is started here
        cell, other = object(), object()
        for live in (_live(cell, "moving", "running"), _live(cell, "saving", "succeeded"),
                     _live(other, "elsewhere", "running")):
            manager._runs[live.run_id] = live  # none has set done: threads still at work
        assert [r.run_id for r in manager.moving_on(cell)] == ["moving"]
        assert [r.run_id for r in manager.running_on(cell)] == ["moving", "saving"]
        manager._runs["moving"].record.status = "cancelled"
        assert manager.moving_on(cell) == []
    finally:
        store.close()
