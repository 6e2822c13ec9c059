"""A run that does not stop within the server's shutdown timeout: recorded as interrupted at
shutdown, and when it ends later (its database closed) it says loudly that its end is not
recorded, and lets go of its joints, instead of dying in its thread with a sqlite error."""

from __future__ import annotations

import logging
import threading
from pathlib import Path
from types import SimpleNamespace

from taskrunner.api.runs import LiveRun, RunManager
from taskrunner.api.store import RunStore
from taskrunner.runtime.events import EventLog
from taskrunner.runtime.records import RunRecord


class StuckRunner:
    """A runner whose run ignores its cancel until released (as a plan being compiled does)."""

    def __init__(self) -> None:
        self.record = RunRecord("r1", "t", "t.yaml", "cell", "mock", {})
        self.events = EventLog()
        self.scene = None
        self.cancels: list[str] = []
        self.release = threading.Event()

    def run(self) -> RunRecord:
        self.release.wait(30)
        self.record.status = "cancelled"
        return self.record

    def cancel(self, reason: str = "", exit_code: int = 130) -> None:
        self.cancels.append(reason)

    def snapshot(self) -> str:
        return "[-] t"


def test_a_run_outliving_the_shutdown_is_recorded_interrupted_and_reports_its_lost_end(
        tmp_path: Path, caplog):
    store = RunStore(tmp_path / "runs.db")
    manager = RunManager(None, store)  # type: ignore[arg-type]  # no run is started here
    runner = StuckRunner()
    session = SimpleNamespace(last_scene=None, give_planner=lambda planner: None)
    live = LiveRun(runner, session, frozenset({"j1"}))  # type: ignore[arg-type]
    manager._runs[live.run_id] = live
    manager._claims[id(live)] = (session, live.joints, live.run_id)  # type: ignore[assignment]
    store.save(live.record)
    live.thread = threading.Thread(target=manager._run, args=(live,), daemon=True)
    live.thread.start()
    with caplog.at_level(logging.ERROR, logger="taskrunner.api.runs"):
        manager.shutdown(0.05)  # the run ignores its cancel: shutdown stops waiting
        assert runner.cancels and not live.done.is_set()
        assert "did not stop within 0.1 s" in caplog.text
        store.close()  # as the server's lifespan does next
        runner.release.set()
        live.thread.join(10)
    assert not live.thread.is_alive() and live.done.is_set()
    assert manager._claims == {}  # the joints are free again
    assert "run r1 ended interrupted but its final record was not written" in caplog.text
    assert "shutdown timeout" in caplog.text
    reopened = RunStore(tmp_path / "runs.db")
    try:
        stored = reopened.load("r1")
        assert stored is not None and stored.status == "interrupted"
        assert stored.exit_code == 143
    finally:
        reopened.close()
