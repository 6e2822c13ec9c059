"""Pre-serialised bodies of ``GET /runs/{id}`` and ``GET /runs``.

Serialising a whole run (every event plus the behaviour-tree text) on every request
made polling cost O(events) per request. Instead:

* :class:`RunDetailCache` (one per live run) keeps each event's JSON, encoded once, and
  the whole body, rebuilt only when something it shows changes: the event count, the
  status, exit code, error or end time, the node running now, whether the run is done,
  or the tree text. The tree text (it has no change counter) is rendered at once when
  the status changes or the run ends, and otherwise at most every ``tree_period_s``, by
  one request after it has answered: the others meanwhile get the body with the tree
  as it was rendered last, so no request waits for a render that only the clock asked.
* :class:`StoredDetails` keeps the bodies of recorded runs (not live on this server),
  each valid for as long as its database row (record and final tree) is unchanged.
* :class:`RunListCache` keeps ``GET /runs`` bodies per query until the store is written.

A body holds a page of the run's events: those with ``seq > since``, at most ``limit``
(``DEFAULT_LIMIT`` unless asked), and says in ``events_more`` whether more follow. So a
body's cost is bounded whatever the run's length: the default body of a live run stops
changing with its events once it holds ``DEFAULT_LIMIT`` of them, and a page is sliced
from the events encoded once each (live) or read by primary key (recorded).

The bytes are exactly what FastAPI would produce from the response model (pydantic's
compact JSON of :class:`~api.schemas.RunDetail` / ``list[RunSummary]``).
"""

from __future__ import annotations

import json
import threading
import time
from collections import OrderedDict
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from pydantic import TypeAdapter

from taskrunner.api.schemas import EventOut, RunDetail, RunSummary
from taskrunner.errors import ArgumentError
from taskrunner.runtime.records import RunRecord

if TYPE_CHECKING:
    from taskrunner.api.runs import LiveRun
    from taskrunner.api.store import RunStore

__all__ = ["DEFAULT_LIMIT", "MAX_LIMIT", "RunDetailCache", "RunListCache", "StoredDetails",
           "detail_body"]

DEFAULT_LIMIT = 1000  # events in a GET /runs/{id} body unless ?limit= asks otherwise
MAX_LIMIT = 10000

_DETAIL = TypeAdapter(RunDetail)
_EVENT = TypeAdapter(EventOut)
_SUMMARIES = TypeAdapter(list[RunSummary])
_NO_EVENTS = b'"events":[]}'
_CLAIM_S = 1.0  # s; see RunDetailCache._claimed_at


def _event_json(event_dict: dict[str, Any]) -> bytes:
    return _EVENT.dump_json(EventOut(**event_dict))


def _head(record: RunRecord, current: tuple[str, str | None] | None,
          tree: str | None, more: bool = False) -> bytes:
    """The body without its events: ends with ``"events":[`` ready for them."""
    model = RunDetail(
        run_id=record.run_id, status=record.status, task=record.task,  # type: ignore[arg-type]
        cell=record.cell, backend=record.backend, started=record.started,
        finished=record.finished, exit_code=record.exit_code, error=record.error,
        task_file=record.task_file, parameters=dict(record.parameters),
        current=None if current is None else {"node": current[0],  # type: ignore[arg-type]
                                              "location": current[1]},
        tree=tree, events_more=more, events=[])
    text = _DETAIL.dump_json(model)
    if not text.endswith(_NO_EVENTS):  # events is the model's last field
        raise AssertionError("RunDetail must end with its events")
    return text[:-2]


def detail_body(record: RunRecord, current: tuple[str, str | None] | None = None,
                tree: str | None = None, events: list[bytes] | None = None,
                more: bool = False) -> bytes:
    """The JSON body of ``GET /runs/{id}`` for ``record``.

    Args:
        record: the run.
        current: the node running now and its ``file:line``, if any.
        tree: the behaviour tree as text (live runs only).
        events: the events to show, already encoded (one JSON object each); encoded
            here from ``record.events`` if not given.
        more: whether more events follow the last one shown (``events_more``).
    """
    if events is None:
        events = [_event_json(e.as_dict()) for e in list(record.events)]
    return b"".join((_head(record, current, tree, more), b",".join(events), b"]}"))


def _check_page(since: int, limit: int) -> None:
    if since < 0:
        raise ArgumentError(f"'since' must be >= 0 (got {since})")
    if not 1 <= limit <= MAX_LIMIT:
        raise ArgumentError(f"'limit' must be 1..{MAX_LIMIT} (got {limit})")


class RunDetailCache:
    """The ``GET /runs/{id}`` body of one live run, rebuilt only when it changes.

    :meth:`fresh` is cheap (no serialising) and safe on the event loop; :meth:`body`
    may render the tree and re-join the events (milliseconds), so call it off the loop.
    Both are safe from any thread.

    Args:
        live: the run.
        tree_period_s: render the tree text at most this often while the status stays
            the same, in seconds.
        clock: monotonic time in seconds (tests pass their own).
    """

    def __init__(self, live: LiveRun, tree_period_s: float = 0.05,
                 clock: Callable[[], float] = time.monotonic) -> None:
        if tree_period_s < 0:
            raise ArgumentError(f"'tree_period_s' must be >= 0 (got {tree_period_s})")
        self.live = live
        self.tree_period_s = tree_period_s
        self._clock = clock
        self._lock = threading.Lock()
        self._claim = threading.Lock()
        # When a caller was last told to refresh the tree (None: since rendered). A claim
        # older than _CLAIM_S is given again: its caller may have gone without refreshing.
        self._claimed_at: float | None = None
        self._events: list[bytes] = []
        self._tree: str | None = None
        self._tree_key: tuple[str, bool] | None = None  # (status, done) it was rendered at
        self._tree_time = float("-inf")
        # (key, body), swapped as one object so a reader never pairs a key with another body
        self._cached: tuple[tuple[Any, ...], bytes] | None = None
        self.builds = 0  # how many times the body was serialised (for tests and stats)

    def _state(self) -> tuple[Any, ...]:
        """What the body shows, besides the tree, in a cheap comparable form."""
        live, record = self.live, self.live.record
        done = live.done.is_set()
        # Past DEFAULT_LIMIT events the default body shows the same events: its count
        # stops there (one more: to say that more follow).
        return (min(len(record.events), DEFAULT_LIMIT + 1), record.status, record.exit_code,
                record.error, record.finished, done, None if done else live.current())

    def _tree_stale(self, state: tuple[Any, ...]) -> bool:
        return (self._tree_key != (state[1], state[5])
                or (not state[5] and self._clock() - self._tree_time >= self.tree_period_s))

    def fresh(self) -> tuple[bytes | None, bool]:
        """The cached body if it still shows the run as it is (its tree text may be one
        period old), else None; and whether the caller should refresh the tree (call
        :meth:`body` soon, e.g. after answering; only one caller at a time is told so).

        Cheap and non-blocking: fit for the event loop.
        """
        state = self._state()
        cached = self._cached
        if cached is None or cached[0][:-1] != state or self._tree_key != (state[1], state[5]):
            return None, False
        if state[5] or self._clock() - self._tree_time < self.tree_period_s:
            return cached[1], False
        now = self._clock()
        with self._claim:
            claimed = self._claimed_at is None or now - self._claimed_at > _CLAIM_S
            if claimed:
                self._claimed_at = now
        return cached[1], claimed

    def body(self) -> bytes:
        """The body, rebuilt if anything it shows has changed."""
        with self._lock:
            state = self._state()
            if self._tree_stale(state):
                done = state[5]
                tree = self.live.tree()
                self._tree_key, self._tree_time = (state[1], done), self._clock()
                with self._claim:
                    self._claimed_at = None
                if tree != self._tree:
                    self._tree = tree
            key = (*state, self._tree)
            if self._cached is not None and self._cached[0] == key:
                return self._cached[1]
            count = state[0]
            shown = self._encoded(0, min(count, DEFAULT_LIMIT))
            body = detail_body(self.live.record, state[6], self._tree, shown,
                               more=count > DEFAULT_LIMIT)
            self._cached = (key, body)
            self.builds += 1
            return body

    def page(self, since: int, limit: int) -> bytes:
        """The body with the events of ``seq > since``, at most ``limit`` of them (not
        cached: its cost is that of ``limit`` events, whatever the run's length)."""
        _check_page(since, limit)
        self.body()  # the tree and the head as they are now
        with self._lock:
            record = self.live.record
            count = len(record.events)  # appended only: a length read once is consistent
            shown = self._encoded(since, min(count, since + limit))
            current = None if self.live.done.is_set() else self.live.current()
            return detail_body(record, current, self._tree, shown, more=count > since + limit)

    def _encoded(self, start: int, stop: int) -> list[bytes]:
        """Events ``start`` to ``stop`` (0-based, as in the record) as JSON, each encoded
        once (events only ever get appended). Call with the lock held."""
        if stop > len(self._events):
            self._events += [_event_json(e.as_dict())
                             for e in self.live.record.events[len(self._events):stop]]
        return self._events[start:stop]

    def refresh(self) -> None:
        """Render the tree again and rebuild the body if it changed (what a caller told to
        refresh by :meth:`fresh` runs, off the event loop)."""
        self.body()


class StoredDetails:
    """Bodies of recorded runs, each kept while its database row is unchanged.

    Args:
        store: the run database.
        size: how many bodies (a run's page each) to keep, least recently asked for
            dropped first.
    """

    def __init__(self, store: RunStore, size: int = 64) -> None:
        if size < 1:
            raise ArgumentError(f"'size' must be >= 1 (got {size})")
        self.store = store
        self.size = size
        self._lock = threading.Lock()
        self._cache: OrderedDict[tuple[str, int, int],
                                 tuple[tuple[str, str | None, int], bytes]] = OrderedDict()

    def body(self, run_id: str, since: int = 0, limit: int = DEFAULT_LIMIT) -> bytes | None:
        """The body of recorded run ``run_id`` with its events of ``seq > since`` (at most
        ``limit``), or None if there is no such run."""
        _check_page(since, limit)
        row = self.store.load_row(run_id)
        if row is None:
            return None
        version = (*row, self.store.last_seq(run_id))
        page = (run_id, since, limit)
        with self._lock:
            hit = self._cache.get(page)
            if hit is not None and hit[0] == version:
                self._cache.move_to_end(page)
                return hit[1]
        text, tree = row
        events, more = self.store.events(run_id, since, limit)
        body = detail_body(RunRecord.from_dict(json.loads(text)), tree=tree,
                           events=[_event_json(e.as_dict()) for e in events], more=more)
        with self._lock:
            self._cache[page] = (version, body)
            self._cache.move_to_end(page)
            while len(self._cache) > self.size:
                self._cache.popitem(last=False)
        return body


class RunListCache:
    """``GET /runs`` bodies per (status, limit), dropped whenever the store is written."""

    def __init__(self, store: RunStore, size: int = 32) -> None:
        self.store = store
        self.size = size
        self._lock = threading.Lock()
        self._version = -1
        self._cache: dict[tuple[str | None, int], bytes] = {}

    def fresh(self, status: str | None, limit: int) -> bytes | None:
        """The cached body if no run was written since it was built, else None."""
        with self._lock:
            if self._version != self.store.version:
                return None
            return self._cache.get((status, limit))

    def body(self, status: str | None, limit: int) -> bytes:
        """The body, from the database if the store was written since it was cached."""
        version = self.store.version  # read first: a write during the query makes it stale
        hit = self.fresh(status, limit)
        if hit is not None:
            return hit
        rows = self.store.summaries(status, limit)
        body = _SUMMARIES.dump_json([RunSummary(**row) for row in rows])  # type: ignore[arg-type]
        with self._lock:
            if self._version != version:
                self._cache.clear()
                self._version = version
            if len(self._cache) < self.size:
                self._cache[(status, limit)] = body
        return body
