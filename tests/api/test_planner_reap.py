"""A cell's idle planning workers closed by the reaper while a request needs one: the
new worker starts once the old ones have ended, so that the processes never outnumber
the workers in use and idle (a burst at load 6 counted 3 processes for ``max_planners``
2)."""

from __future__ import annotations

import threading
import time
from pathlib import Path

import pytest

import taskrunner.planning.worker as worker_module
from taskrunner.api.cells import CellSession


class _SlowToClose:
    """A worker whose close waits for ``release`` (a process slow to end under load)."""

    def __init__(self) -> None:
        self.closing = threading.Event()
        self.release = threading.Event()

    def close(self) -> None:
        self.closing.set()
        assert self.release.wait(30.0)


def _reaping() -> tuple[CellSession, _SlowToClose, threading.Thread]:
    """A cell session whose one idle worker the reaper is closing now (until released)."""
    session = CellSession(Path("cell.yaml"), None, {}, "worker")  # type: ignore[arg-type]
    old = _SlowToClose()
    session.idle_planners.append((old, time.monotonic() - 10.0))
    reaper = threading.Thread(target=session.reap_planners, args=(1.0,))
    reaper.start()
    assert old.closing.wait(30.0)
    return session, old, reaper


def test_a_new_worker_starts_only_once_the_reaped_ones_have_ended(monkeypatch) -> None:
    started: list[float] = []

    class NewWorker:
        def __init__(self, *args: object, **kwargs: object) -> None:
            started.append(time.monotonic())

    monkeypatch.setattr(worker_module, "PlanningWorker", NewWorker)
    session, old, reaper = _reaping()
    taken: list[object] = []
    taker = threading.Thread(target=lambda: taken.append(session.take_planner()))
    try:
        taker.start()
        taker.join(0.3)
        assert taker.is_alive() and not started  # waits: the old worker is still ending
        ended = time.monotonic()
    finally:
        old.release.set()
        reaper.join(30.0)
        taker.join(30.0)
    assert len(started) == 1 and started[0] >= ended
    assert isinstance(taken[0], NewWorker) and session.closing == 0


def test_an_idle_worker_given_back_meanwhile_is_taken_instead(monkeypatch) -> None:
    monkeypatch.setattr(worker_module, "PlanningWorker",
                        lambda *a, **k: pytest.fail("no new worker while one is idle"))
    session, old, reaper = _reaping()
    taken: list[object] = []
    taker = threading.Thread(target=lambda: taken.append(session.take_planner()))
    taker.start()
    back = _SlowToClose()  # a worker a request has just given back
    try:
        session.give_planner(back)
        taker.join(30.0)
        assert taken == [back]
    finally:
        old.release.set()
        reaper.join(30.0)
