"""Live event streams of runs (Server-Sent Events) that cannot slow the run.

A run's events fan out from one buffer per run, a :class:`RunFeed`, on the event loop:

* The run's thread does O(1) work per event whatever the number of streams: the feed is
  the run's only stream subscriber, and it schedules one wake-up on the loop per burst
  of events (one ``call_soon_threadsafe``, none while one is pending; the streams are
  woken at most every ``batch_s``). It never waits on a client.
* The loop encodes each event once (SSE bytes), into the feed's list; every stream of
  the run sends from that list by index (no copy of an event per client).
* A stream sends what it has not sent in one write. If more than ``max_lag`` events
  came while the client took that write (a client slower than the run), or a write does
  not complete within ``send_timeout_s`` (a client that stops reading fills the
  socket's buffers, then a write waits forever), the client is dropped. A burst of
  events while a stream waits, or the history a late client asks for, is no lag. A client that
  is still reading gets a last ``dropped`` event naming the ``Last-Event-ID`` to resume
  from; one that is not is disconnected (the transport aborted, its buffered bytes
  discarded). Other clients and the run go on.
* A stream ends after ``run_finished`` (or, should a run end without one, once it is
  caught up with the ended run).

The abort needs the server's transport: :func:`api.serving.header_timeout_protocol`
offers it to the app as the ASGI scope extension ``taskrunner.abort``. Without it (the
test client, another server), a stuck stream is abandoned and the server closes the
connection as it closes any response the app did not complete.
"""

from __future__ import annotations

import asyncio
import json
import logging
import threading
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

from starlette.concurrency import run_in_threadpool
from starlette.responses import Response

from taskrunner.errors import ArgumentError
from taskrunner.runtime.events import EventLog, RunEvent

__all__ = ["ABORT_EXTENSION", "EventStream", "RunFeed", "RunStreams", "StreamOptions",
           "encode_event"]

log = logging.getLogger(__name__)

ABORT_EXTENSION = "taskrunner.abort"
_PING = b": ping\n\n"
_BATCH = 256  # events a single write carries at most (a late client's history)


@dataclass(frozen=True)
class StreamOptions:
    """Bounds of each client's stream.

    Attributes:
        max_lag: events that may come while a client takes one write; one more and the
            client is dropped (it is that far behind the run).
        send_timeout_s: longest a write to a client may wait (s); past it the client is
            disconnected.
        keepalive_s: an idle stream sends a comment this often (s), so that proxies
            keep it open.
        batch_s: streams are woken at most this often (s); events that come faster
            reach each client together, in one write (a run of fast motions emits
            hundreds a second). 0: at every event.
    """

    max_lag: int = 1000
    send_timeout_s: float = 10.0
    keepalive_s: float = 15.0
    batch_s: float = 0.1

    def __post_init__(self) -> None:
        if isinstance(self.max_lag, bool) or not isinstance(self.max_lag, int) \
                or self.max_lag < 1:
            raise ArgumentError(f"'max_lag' must be an integer >= 1 (got {self.max_lag!r})")
        for name in ("send_timeout_s", "keepalive_s"):
            value = getattr(self, name)
            if isinstance(value, bool) or not isinstance(value, int | float) or not value > 0:
                raise ArgumentError(f"'{name}' must be a positive number of seconds "
                                 f"(got {value!r})")
        if isinstance(self.batch_s, bool) or not isinstance(self.batch_s, int | float) \
                or not self.batch_s >= 0:
            raise ArgumentError(f"'batch_s' must be a number of seconds >= 0 "
                             f"(got {self.batch_s!r})")


def encode_event(event: RunEvent) -> bytes:
    """The SSE frame of ``event``: ``event`` = its kind, ``data`` = its JSON, ``id`` = its
    seq."""
    data = json.dumps(event.as_dict())
    return f"event: {event.kind}\ndata: {data}\nid: {event.seq}\n\n".encode()


def _dropped_frame(run_id: str, last: int, reason: str) -> bytes:
    data = json.dumps({"reason": reason, "last_event_id": last,
                       "resume": f"GET /runs/{run_id}/events with the header "
                                 f"'Last-Event-ID: {last}' (or ?after={last})"})
    return (f": dropped ({reason}); resume with Last-Event-ID: {last}\n"
            f"event: dropped\ndata: {data}\n\n").encode()


class _Stream:
    """One client's place in a feed."""

    __slots__ = ("abort", "dropped", "sending_since")

    def __init__(self, abort: Callable[[], None]) -> None:
        self.abort = abort
        self.dropped = False
        self.sending_since: float | None = None


class RunFeed:
    """One run's events as SSE frames, shared by all the run's streams (lives on the loop).

    Attributes:
        frames: the encoded events; ``frames[i]`` is the event of seq ``i + 1``.
        final: how many frames there are once ``run_finished`` is among them, else None.
        ended: the run has ended (``done`` is set) and every event it emitted is framed.
        changed: set (and replaced) whenever frames are added or the feed ticks.
    """

    def __init__(self, events: EventLog, done: threading.Event, options: StreamOptions,
                 loop: asyncio.AbstractEventLoop) -> None:
        self.frames: list[bytes] = []
        self.final: int | None = None
        self.ended = False
        self.changed = asyncio.Event()
        self._events, self._done, self._options, self._loop = events, done, options, loop
        self._streams: set[_Stream] = set()
        self._pending = False
        self._woken = -float("inf")
        self._tick: asyncio.TimerHandle | None = None

    # ----------------------------------------------------------------- run's thread
    def _arrived(self, _: RunEvent) -> None:
        # In the run's thread: one wake-up per burst, whatever the number of streams.
        if self._pending:
            return
        self._pending = True
        try:
            self._loop.call_soon_threadsafe(self._wake_soon)
        except RuntimeError:  # the loop has closed: no stream is left to wake
            pass

    # ----------------------------------------------------------------- loop
    def _wake_soon(self) -> None:
        """Wake the streams now, or at ``batch_s`` after the last wake-up: events that
        come faster go out together (one write per stream for all of them)."""
        due = self._woken + self._options.batch_s
        now = self._loop.time()
        if now >= due:
            self._wake()
        else:
            self._loop.call_at(due, self._wake)

    def _wake(self) -> None:
        self._pending = False  # before reading: an event appended after it wakes again
        self._woken = self._loop.time()
        self._catch_up()
        changed, self.changed = self.changed, asyncio.Event()
        changed.set()

    def _catch_up(self) -> None:
        done = self._done.is_set()  # before reading: all it emitted is then in the log
        for event in self._events.events(len(self.frames)):
            self.frames.append(encode_event(event))
            if event.kind == "run_finished":
                self.final = len(self.frames)
        self.ended = done

    def _on_tick(self) -> None:
        """Every ``min(keepalive, send timeout / 4, 1 s)``: note a run that ended without
        ``run_finished``, disconnect clients whose write has waited past the timeout and
        let idle streams send a keep-alive."""
        now = self._loop.time()
        for stream in list(self._streams):
            since = stream.sending_since
            if since is not None and now - since > self._options.send_timeout_s:
                stream.sending_since = None
                stream.abort()
        self._wake()
        self._tick = self._loop.call_later(self._interval(), self._on_tick)

    def _interval(self) -> float:
        options = self._options
        return min(options.keepalive_s, options.send_timeout_s / 4, 1.0)

    def _open(self) -> None:
        self._events.subscribe(self._arrived)
        self._catch_up()
        self._tick = self._loop.call_later(self._interval(), self._on_tick)

    def _close(self) -> None:
        self._events.unsubscribe(self._arrived)
        if self._tick is not None:
            self._tick.cancel()
            self._tick = None

    def __len__(self) -> int:
        """How many streams follow the run."""
        return len(self._streams)


class RunStreams:
    """The feeds of the runs that have streams (one feed per run, made by the first
    stream and closed with the last)."""

    def __init__(self, options: StreamOptions | None = None) -> None:
        self.options = options or StreamOptions()
        self._feeds: dict[EventLog, RunFeed] = {}

    def feed(self, events: EventLog) -> RunFeed | None:
        """The feed of the run whose log is ``events``, if it has streams."""
        return self._feeds.get(events)

    def _join(self, events: EventLog, done: threading.Event, stream: _Stream) -> RunFeed:
        feed = self._feeds.get(events)
        if feed is None:
            feed = RunFeed(events, done, self.options, asyncio.get_running_loop())
            feed._open()
            self._feeds[events] = feed
        feed._streams.add(stream)
        return feed

    def _leave(self, events: EventLog, feed: RunFeed, stream: _Stream) -> None:
        feed._streams.discard(stream)
        if not feed._streams:
            feed._close()
            if self._feeds.get(events) is feed:
                del self._feeds[events]


class EventStream(Response):
    """The ASGI response of ``GET /runs/{id}/events``: a run's events as SSE after seq
    ``after``, to the run's end (see the module)."""

    media_type = "text/event-stream"

    def __init__(self, streams: RunStreams, manager: Any, run_id: str, after: int) -> None:
        self.status_code = 200
        self.background = None
        self.init_headers({"Cache-Control": "no-cache", "X-Accel-Buffering": "no"})
        self._streams, self._manager, self._run_id, self._after = (streams, manager, run_id,
                                                                   after)

    async def __call__(self, scope: Any, receive: Any, send: Any) -> None:
        await send({"type": "http.response.start", "status": self.status_code,
                    "headers": self.raw_headers})
        transport_abort = (scope.get("extensions") or {}).get(ABORT_EXTENSION, {}) \
            .get("abort")
        pump = asyncio.ensure_future(self._pump(send, transport_abort))
        gone = asyncio.ensure_future(_disconnected(receive))
        try:
            await asyncio.wait({pump, gone}, return_when=asyncio.FIRST_COMPLETED)
        finally:
            for task in (pump, gone):
                if not task.done():
                    task.cancel()
            await asyncio.gather(pump, gone, return_exceptions=True)
        if pump.done() and not pump.cancelled() and pump.exception() is not None:
            exc = pump.exception()
            if not isinstance(exc, OSError):  # a client gone mid-write is no error
                raise exc  # type: ignore[misc]

    async def _pump(self, send: Any, transport_abort: Callable[[], None] | None) -> None:
        live = self._manager.live(self._run_id)
        stream = _Stream(lambda: None)
        task = asyncio.current_task()

        def abort() -> None:  # the client took no bytes within the send timeout
            log.warning("run %s: dropped an event stream whose client took nothing for "
                        "%.0f s", self._run_id, self._streams.options.send_timeout_s)
            stream.dropped = True
            if transport_abort is not None:
                transport_abort()  # the pending write returns (uvicorn: disconnected)
            elif task is not None:
                task.cancel()  # abandoned: the server closes what the app left open

        stream.abort = abort
        if live is None:
            await self._pump_recorded(send, stream)
            return
        feed = self._streams._join(live.events, live.done, stream)
        try:
            await self._pump_live(send, feed, stream)
        finally:
            self._streams._leave(live.events, feed, stream)

    async def _pump_live(self, send: Any, feed: RunFeed, stream: _Stream) -> None:
        loop = asyncio.get_running_loop()
        options = self._streams.options
        sent = self._after
        # `seen`: the frames there were when the stream last started a write or woke.
        # Those that came since are what the client's last write held back: its lag.
        seen = joined = len(feed.frames)
        quiet_since = loop.time()
        while not stream.dropped:
            end = len(feed.frames)
            behind = end - max(sent, seen)
            if behind > options.max_lag:
                await _write(send, stream, _dropped_frame(
                    self._run_id, sent, f"{behind} events came while it took one write, "
                                        f"more than {options.max_lag}"), more=False)
                return
            if sent < end:
                # The history before the stream joined in batches; since, all at once
                # (at most max_lag + what came while it was idle).
                upto = min(end, sent + _BATCH) if sent < joined else end
                body = feed.frames[sent] if upto == sent + 1 else \
                    b"".join(feed.frames[sent:upto])
                seen = end
                await _write(send, stream, body)
                sent, quiet_since = upto, loop.time()
                continue
            if (feed.final is not None and sent >= feed.final) or feed.ended:
                await _write(send, stream, b"", more=False)
                return
            changed = feed.changed
            await changed.wait()
            seen = len(feed.frames)  # what came while it waited is no lag
            if seen == end and loop.time() - quiet_since >= options.keepalive_s:
                await _write(send, stream, _PING)
                quiet_since = loop.time()

    async def _pump_recorded(self, send: Any, stream: _Stream) -> None:
        """A run this server no longer holds: its recorded events, then the end (each
        write within the send timeout, as in a feed)."""
        events, _ = await run_in_threadpool(self._manager.events_after, self._run_id,
                                            self._after)
        loop = asyncio.get_running_loop()
        timer = loop.call_later(self._streams.options.send_timeout_s, stream.abort)
        try:
            for start in range(0, len(events), _BATCH):
                body = b"".join(encode_event(e) for e in events[start:start + _BATCH])
                await _write(send, stream, body)
                if stream.dropped:
                    return
                timer.cancel()
                timer = loop.call_later(self._streams.options.send_timeout_s, stream.abort)
            await _write(send, stream, b"", more=False)
        finally:
            timer.cancel()


async def _write(send: Any, stream: _Stream, body: bytes, more: bool = True) -> None:
    stream.sending_since = asyncio.get_running_loop().time()
    try:
        await send({"type": "http.response.body", "body": body, "more_body": more})
    finally:
        stream.sending_since = None


async def _disconnected(receive: Any) -> None:
    while (await receive())["type"] != "http.disconnect":
        pass
