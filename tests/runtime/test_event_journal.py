"""An EventLog's journal: called with each event before anyone can see it."""

from __future__ import annotations

import pytest

from taskrunner.runtime.events import EventLog, RunEvent


def test_the_journal_has_each_event_before_readers_and_subscribers_see_it():
    log = EventLog()
    log.emit("message", "before the journal")
    journaled: list[int] = []
    seen_by_journal: list[int] = []

    def journal(event: RunEvent) -> None:
        journaled.append(event.seq)
        seen_by_journal.append(len(log._events))  # what a reader could see meanwhile

    earlier = log.set_journal(journal)
    assert [e.seq for e in earlier] == [1]
    at_subscriber: list[list[int]] = []
    log.subscribe(lambda event: at_subscriber.append(list(journaled)))
    log.emit("run_started")
    log.emit("node_started", node="a")
    assert journaled == [2, 3]
    assert seen_by_journal == [1, 2]  # not yet kept when journaled
    assert at_subscriber == [[2], [2, 3]]


def test_an_event_the_journal_refuses_is_not_kept():
    log = EventLog()

    def journal(event: RunEvent) -> None:
        raise OSError("disk full")

    log.set_journal(journal)
    with pytest.raises(OSError):
        log.emit("message", "lost")
    assert log.events() == []
    log.set_journal(None)
    assert log.emit("message", "kept").seq == 1
