"""Run events: what happened during a run, in order, with the task file:line of each.

Events are plain frozen data (JSON-ready through :meth:`RunEvent.as_dict`). An
:class:`EventLog` numbers them, keeps them, and hands each to its subscribers (the CLI's
display, a run record, the API's live stream). It is safe to append from several threads.
"""

from __future__ import annotations

import threading
import time
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from taskrunner.errors import ArgumentError
from taskrunner.kinds import EventKind

__all__ = ["EventLog", "RunEvent"]

# The kinds of event a run emits, each with its data: taskrunner.kinds.EventKind.
KINDS = tuple(kind.value for kind in EventKind)


@dataclass(frozen=True)
class RunEvent:
    """One event of a run.

    Attributes:
        seq: 1-based position in the run's event list.
        time: seconds since the run started.
        kind: one of ``KINDS``.
        node: the tree node's name, if the event is about one.
        location: ``file:line`` of the task node, if known.
        status: the node's or the run's status, where it has one.
        message: a human-readable line.
        data: extra figures (planning time in s, trajectory duration in s, …).
    """

    seq: int
    time: float
    kind: str
    node: str | None = None
    location: str | None = None
    status: str | None = None
    message: str = ""
    data: dict[str, Any] = field(default_factory=dict)

    def as_dict(self) -> dict[str, Any]:
        return {
            "seq": self.seq, "time": round(self.time, 6), "kind": self.kind, "node": self.node,
            "location": self.location, "status": self.status, "message": self.message,
            "data": dict(self.data),
        }

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> RunEvent:
        fields: dict[str, Any] = {k: data.get(k) for k in ("seq", "time", "kind", "node",
                                                           "location", "status")}
        return cls(**fields, message=data.get("message", ""), data=dict(data.get("data") or {}))


class EventLog:
    """An append-only, numbered list of run events with subscribers."""

    def __init__(self, clock: Callable[[], float] = time.monotonic) -> None:
        self._clock = clock
        self._start = clock()
        self._events: list[RunEvent] = []
        self._subscribers: list[Callable[[RunEvent], None]] = []
        self._journal: Callable[[RunEvent], None] | None = None
        self._lock = threading.Lock()

    def set_journal(self, journal: Callable[[RunEvent], None] | None) -> list[RunEvent]:
        """Call ``journal`` with every event appended from now on, before the event is
        kept (before :meth:`events` returns it or any subscriber gets it), in the appending
        thread and in seq order: a durable journal then holds every event anyone saw.
        Returns the events appended before (for the caller to journal). An exception
        from ``journal`` propagates from :meth:`emit`, the event not kept."""
        with self._lock:
            self._journal = journal
            return list(self._events)

    def subscribe(self, callback: Callable[[RunEvent], None]) -> None:
        """Call ``callback`` with every event appended from now on (in the appending thread:
        the run's, which it must not hold up; the API's streams subscribe one waker per
        run, not one callback per client)."""
        with self._lock:
            self._subscribers.append(callback)

    def unsubscribe(self, callback: Callable[[RunEvent], None]) -> None:
        """Stop calling ``callback`` (no error if it was not subscribed)."""
        with self._lock:
            if callback in self._subscribers:
                self._subscribers.remove(callback)

    def emit(self, kind: str, message: str = "", *, node: str | None = None,
             location: str | None = None, status: str | None = None,
             **data: Any) -> RunEvent:
        """Append an event and pass it to the subscribers."""
        if kind not in KINDS:
            raise ArgumentError(f"'kind' must be one of {', '.join(KINDS)} (got {kind!r})")
        with self._lock:
            event = RunEvent(len(self._events) + 1, self._clock() - self._start, kind, node,
                             location, status, message, data)
            if self._journal is not None:
                self._journal(event)
            self._events.append(event)
            subscribers = list(self._subscribers)
        for callback in subscribers:
            callback(event)
        return event

    def events(self, after: int = 0) -> list[RunEvent]:
        """The events with ``seq > after``.

        Never waits for an ``emit`` in progress (its journal write may take a disk's
        flush): the list is only appended to, and a slice of it is taken whole (CPython's
        GIL), so the answer is the events kept so far, in order, without gaps.
        """
        return self._events[after:]

    def __len__(self) -> int:
        return len(self._events)
