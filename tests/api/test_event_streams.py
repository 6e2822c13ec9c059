"""Event streams that cannot hurt the run (api.streams): one feed per run, bounded clients.

The first tests drive :class:`EventStream` as an ASGI app on an event loop of their own,
with an ``EventLog`` standing for the run and fake ``send``/``receive`` standing for the
clients, so every step is ordered by the test (no sleeps, no timing). The last one is a
real server and a real socket whose client never reads.
"""

from __future__ import annotations

import asyncio
import http.client
import json
import logging
import socket
import threading
import time
from dataclasses import dataclass, field
from typing import Any

import pytest
from apitest import AUTH, make_settings, parse_sse, served

from taskrunner.api import create_app
from taskrunner.api.serving import header_timeout_protocol
from taskrunner.api.streams import ABORT_EXTENSION, EventStream, RunStreams, StreamOptions
from taskrunner.runtime.events import EventLog


@dataclass
class FakeRun:
    events: EventLog = field(default_factory=EventLog)
    done: threading.Event = field(default_factory=threading.Event)


class FakeManager:
    def __init__(self, run: FakeRun) -> None:
        self.run = run

    def live(self, run_id: str) -> FakeRun:
        return self.run


class Client:
    """An ASGI client: collects the body; ``gate`` (if given) holds every write after
    the first until it is set; ``abort`` disconnects it as uvicorn's transport would."""

    def __init__(self, gate: asyncio.Event | None = None, hang: bool = False) -> None:
        self.body = b""
        self.writes = 0
        self.complete = False
        self.aborted = 0
        self.gate, self.hang = gate, hang
        self._gone = asyncio.Event()

    async def send(self, message: dict[str, Any]) -> None:
        if message["type"] != "http.response.body":
            return
        if self.writes and (self.hang or self.gate is not None):
            waits = [asyncio.ensure_future(self._gone.wait())]
            if self.gate is not None:
                waits.append(asyncio.ensure_future(self.gate.wait()))
            await asyncio.wait(waits, return_when=asyncio.FIRST_COMPLETED)
            for w in waits:
                w.cancel()
        if self._gone.is_set():
            return  # uvicorn: a write to a connection that is gone returns
        self.writes += 1
        self.body += message["body"]
        self.complete = not message.get("more_body", False)

    async def receive(self) -> dict[str, Any]:
        await self._gone.wait()
        return {"type": "http.disconnect"}

    def abort(self) -> None:
        self.aborted += 1
        self._gone.set()

    def scope(self) -> dict[str, Any]:
        return {"type": "http", "extensions": {ABORT_EXTENSION: {"abort": self.abort}}}

    def events(self) -> list[dict[str, str]]:
        return parse_sse(self.body.decode())


def _stream(streams: RunStreams, run: FakeRun, client: Client, after: int = 0
            ) -> asyncio.Task[None]:
    app = EventStream(streams, FakeManager(run), "r1", after)
    return asyncio.ensure_future(app(client.scope(), client.receive, client.send))


async def _until(condition: Any) -> None:
    for _ in range(100_000):
        if condition():
            return
        await asyncio.sleep(0)
    raise AssertionError("the condition never held")


def _ids(client: Client) -> list[int]:
    return [int(e["id"]) for e in client.events() if "id" in e]


class CountingLog(EventLog):
    """A run's log that counts the subscriber calls its emits make."""

    def __init__(self) -> None:
        super().__init__()
        self.calls = 0

    def subscribe(self, callback: Any) -> None:
        def counted(event: Any) -> None:
            self.calls += 1
            callback(event)

        counted.original = callback  # type: ignore[attr-defined]
        super().subscribe(counted)

    def unsubscribe(self, callback: Any) -> None:
        for counted in list(self._subscribers):
            if getattr(counted, "original", None) == callback:
                super().unsubscribe(counted)


def test_the_run_thread_makes_one_call_per_event_whatever_the_number_of_streams():
    async def follow(count: int) -> tuple[int, int]:
        """(subscriber calls, wake-ups scheduled) by the run's thread for 21 events."""
        run, streams = FakeRun(events=CountingLog()), RunStreams(StreamOptions())
        run.events.emit("run_started")
        clients = [Client() for _ in range(count)]
        tasks = [_stream(streams, run, c) for c in clients]
        await _until(lambda: all(c.writes == 1 for c in clients))
        loop = asyncio.get_running_loop()
        thread_calls = [0]
        real = loop.call_soon_threadsafe

        def counting(*args: Any, **kwargs: Any) -> Any:
            if threading.current_thread().name == "run":
                thread_calls[0] += 1
            return real(*args, **kwargs)

        loop.call_soon_threadsafe = counting  # type: ignore[method-assign]
        # One event at a time, each seen by every stream before the next: the worst case
        # (no burst to coalesce).
        for k in range(21):
            kind = "run_finished" if k == 20 else "message"
            emitter = threading.Thread(target=run.events.emit, args=(kind, f"m{k}"),
                                       name="run")
            emitter.start()
            emitter.join()
            await _until(lambda k=k: all(c.writes >= k + 2 for c in clients))
        run.done.set()
        await asyncio.gather(*tasks)
        assert all(_ids(c) == list(range(1, 23)) and c.complete for c in clients)
        assert streams.feed(run.events) is None and not run.events._subscribers
        return run.events.calls, thread_calls[0]  # (run_started came before any stream)

    one, many = asyncio.run(follow(1)), asyncio.run(follow(50))
    assert one == (21, 21)
    assert many == one  # with 50 streams as with 1: one call per event, not 50


def test_a_client_that_falls_behind_is_dropped_and_resumes_with_last_event_id():
    async def scenario() -> tuple[Client, Client, Client]:
        run, streams = FakeRun(), RunStreams(StreamOptions(max_lag=10))
        run.events.emit("run_started")
        gate = asyncio.Event()
        slow, fast = Client(gate=gate), Client()
        slow_task, fast_task = _stream(streams, run, slow), _stream(streams, run, fast)
        await _until(lambda: slow.writes == 1 and fast.writes == 1)
        run.events.emit("message", "the write the slow client is slow to take")
        await _until(lambda: len(_ids(fast)) == 2)
        for k in range(30):  # meanwhile: more than max_lag events
            run.events.emit("message", f"m{k}")
        await _until(lambda: len(_ids(fast)) == 32)  # the other stream is not held back
        assert len(_ids(slow)) == 1
        gate.set()
        await slow_task  # 30 came while it took one write (> 10): told so, stream ended
        assert slow.complete and not slow.aborted
        assert _ids(slow) == [1, 2]
        dropped = [e for e in slow.events() if e.get("event") == "dropped"]
        assert len(dropped) == 1 and json.loads(dropped[0]["data"])["last_event_id"] == 2
        assert "Last-Event-ID: 2" in slow.body.decode()
        last = 2
        again = Client()
        resumed = _stream(streams, run, again, after=last)
        await _until(lambda: again.writes >= 1)
        run.events.emit("run_finished")
        run.done.set()
        await asyncio.gather(resumed, fast_task)
        return slow, again, fast

    slow, again, fast = asyncio.run(scenario())
    assert _ids(slow) + _ids(again) == list(range(1, 34))  # every event exactly once
    assert _ids(fast) == list(range(1, 34)) and fast.complete
    assert again.events()[-1]["event"] == "run_finished" and again.complete


def test_a_client_that_takes_nothing_is_disconnected_and_the_others_go_on():
    async def scenario() -> tuple[Client, Client, RunStreams, FakeRun]:
        run = FakeRun()
        streams = RunStreams(StreamOptions(send_timeout_s=0.05, keepalive_s=0.05))
        run.events.emit("run_started")
        stuck, reader = Client(hang=True), Client()
        stuck_task, reader_task = _stream(streams, run, stuck), _stream(streams, run, reader)
        await _until(lambda: stuck.writes == 1 and reader.writes == 1)
        run.events.emit("message", "one write the stuck client never takes")
        await asyncio.wait_for(stuck_task, 30)  # the feed's tick aborts its connection
        for k in range(5):
            run.events.emit("message", f"m{k}")
        run.events.emit("run_finished")
        run.done.set()
        await asyncio.wait_for(reader_task, 30)
        return stuck, reader, streams, run

    stuck, reader, streams, run = asyncio.run(scenario())
    assert stuck.aborted == 1 and not stuck.complete
    assert _ids(reader) == list(range(1, 9)) and reader.complete
    assert streams.feed(run.events) is None and not run.events._subscribers


def test_a_burst_while_streams_wait_drops_none():
    async def scenario() -> list[Client]:
        run, streams = FakeRun(), RunStreams(StreamOptions(max_lag=10))
        run.events.emit("run_started")
        clients = [Client() for _ in range(3)]
        tasks = [_stream(streams, run, c) for c in clients]
        await _until(lambda: all(c.writes == 1 for c in clients))
        for k in range(50):  # five times max_lag, between two wake-ups
            run.events.emit("message", f"m{k}")
        run.events.emit("run_finished")
        run.done.set()
        await asyncio.gather(*tasks)
        return clients

    for client in asyncio.run(scenario()):
        assert _ids(client) == list(range(1, 53)) and client.complete
        assert not any(e.get("event") == "dropped" for e in client.events())


def test_stream_options_are_checked():
    with pytest.raises(ValueError, match="'max_lag' must be an integer >= 1"):
        StreamOptions(max_lag=0)
    with pytest.raises(ValueError, match="'send_timeout_s' must be a positive number"):
        StreamOptions(send_timeout_s=0)


GO_SLOW = """\
task: go_slow
cell: ../robots/cells/servo_arm_table.yaml
steps:
  - go: {group: arm, to: Candle, velocity_scaling: 0.2}
  - go: {group: arm, to: home, velocity_scaling: 0.2}
"""


def _request(port: int, method: str, path: str, body: dict | None = None) -> dict:
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=30)
    conn.request(method, path, body=json.dumps(body).encode() if body is not None else None,
                 headers={**AUTH, "Content-Type": "application/json"})
    answer = conn.getresponse()
    data = answer.read()
    conn.close()
    assert answer.status < 300, (answer.status, data[:500])
    return json.loads(data)


def _closed_by_server(sock: socket.socket) -> bool:
    """Reads what is buffered; True once the server's end is closed (EOF or reset)."""
    sock.settimeout(30)
    try:
        while sock.recv(1 << 20):
            pass
    except ConnectionResetError:
        return True
    except TimeoutError:
        return False
    return True


def test_a_stream_that_never_reads_is_closed_and_the_run_and_a_reader_are_unaffected(
        tmp_path, caplog):
    # 2 s without taking a byte drops a client: the silent one surely (its 4 kB buffer is
    # full at once), the reader (a thread of this busy process) not for a pause under load.
    app = create_app(make_settings(tmp_path / "state", stream_send_timeout_s=2.0,
                                   stream_max_lag=100_000))
    with served(app, http=header_timeout_protocol(10.0)) as port:
        run_id = _request(port, "POST", "/runs",
                          {"yaml": GO_SLOW, "backend": "sim", "check": False})["run_id"]
        silent = socket.socket()
        silent.setsockopt(socket.SOL_SOCKET, socket.SO_RCVBUF, 4096)
        silent.connect(("127.0.0.1", port))
        silent.sendall(f"GET /runs/{run_id}/events HTTP/1.1\r\nHost: test\r\n"
                       f"Authorization: {AUTH['Authorization']}\r\n\r\n".encode())
        reader = http.client.HTTPConnection("127.0.0.1", port, timeout=60)
        reader.request("GET", f"/runs/{run_id}/events", headers=AUTH)
        answer = reader.getresponse()
        live = app.state.manager.live(run_id)
        # Far more than the socket buffers hold: 400 events of 40 kB in the run's log.
        blob = "x" * 40_000
        for k in range(400):
            live.events.emit("message", f"bulk {k}", blob=blob)
        body = answer.read().decode()  # to the end of the run
        reader.close()
        ids = [int(e["id"]) for e in parse_sse(body) if "id" in e]
        assert ids == list(range(1, len(ids) + 1))  # every event once, in order
        assert parse_sse(body)[-1]["event"] == "run_finished"
        assert live.record.status == "succeeded"
        assert len(ids) == len(live.events)
        # The silent client is dropped by the send timeout, 2 s after its write began
        # waiting: the run may end before. Read nothing of it until then (reading drains
        # its socket, and it is a silent client no more).
        def drops() -> list[logging.LogRecord]:
            return [r for r in caplog.records if "dropped an event stream" in r.getMessage()]
        deadline = time.monotonic() + 60
        while not drops() and time.monotonic() < deadline:
            time.sleep(0.05)
        assert len(drops()) == 1  # that one client, not the reader
        assert _closed_by_server(silent)  # the server let it go
        silent.close()
        assert app.state.streams.feed(live.events) is None
