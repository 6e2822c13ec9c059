"""Serving the app with uvicorn, with a time limit on request headers, and optionally a
control listener of its own.

uvicorn times out a connection only while it is idle between requests
(``timeout_keep_alive``); a client that opens a connection and trickles its request
headers a byte at a time holds the connection (and its slot) forever. The protocol
here, uvicorn's httptools protocol with one timer more, closes a connection whose
request headers are not complete within ``header_timeout_s`` of the connection's start
or of the request's first byte (with ``408 Request Timeout``), and one whose request body
is not complete within ``body_timeout_s`` of its headers (a client that declares
``Content-Length: 1000`` and sends a byte a second held its connection and the app's
task for as long as it liked). The body's timer runs whatever the app does with the
body: it reads it, waits, or has answered without it (a 401 before the body); a request
without a body completes with its headers. The answer is ``408`` when the app has not
started its own, else the connection is just closed.

A server can also listen on a **control port** (``control_port``): a second uvicorn on
its own thread and event loop that answers only ``POST /runs/{id}/cancel``,
``GET /runs/{id}`` and ``GET /health`` (:class:`ControlOnly`). Requests on the main port,
however many, share the main event loop with each other but never with this one, so an
operator's stop is answered in milliseconds even while clients flood the main port (the
benchmark ``benchmarks/api_control.py`` measures both).
"""

from __future__ import annotations

import asyncio
import json
import threading
from typing import Any

from uvicorn.protocols.http.httptools_impl import HttpToolsProtocol

from taskrunner.api.overload import is_control
from taskrunner.api.settings import Settings
from taskrunner.api.streams import ABORT_EXTENSION
from taskrunner.errors import ArgumentError

__all__ = ["ControlOnly", "header_timeout_protocol", "serve"]



def _timeout_answer(what: str) -> bytes:
    body = f"request {what} not received in time\n".encode()
    return (b"HTTP/1.1 408 Request Timeout\r\ncontent-type: text/plain\r\n"
            b"content-length: %d\r\nconnection: close\r\n\r\n%s" % (len(body), body))


_HEADERS_TOO_SLOW = _timeout_answer("headers")
_BODY_TOO_SLOW = _timeout_answer("body")


def header_timeout_protocol(header_timeout_s: float,
                            body_timeout_s: float | None = None) -> type[asyncio.Protocol]:
    """uvicorn's httptools HTTP protocol, closing connections whose request headers take
    longer than ``header_timeout_s`` (s) to arrive, or whose request body takes longer
    than ``body_timeout_s`` (s) after its headers (None: no limit on the body)."""
    if not header_timeout_s > 0:
        raise ArgumentError(f"'header_timeout_s' must be a positive number (got {header_timeout_s!r})")
    if body_timeout_s is not None and not body_timeout_s > 0:
        raise ArgumentError(f"'body_timeout_s' must be a positive number (got {body_timeout_s!r})")

    class HeaderTimeoutProtocol(HttpToolsProtocol):
        _header_timer: asyncio.TimerHandle | None = None
        _body_timer: asyncio.TimerHandle | None = None

        def _arm_header_timer(self) -> None:
            self._disarm_header_timer()
            self._header_timer = self.loop.call_later(header_timeout_s, self._headers_too_slow)

        def _disarm_header_timer(self) -> None:
            if self._header_timer is not None:
                self._header_timer.cancel()
                self._header_timer = None

        def _headers_too_slow(self) -> None:
            self._header_timer = None
            if not self.transport.is_closing():
                self.transport.write(_HEADERS_TOO_SLOW)
                self.transport.close()

        def _disarm_body_timer(self) -> None:
            if self._body_timer is not None:
                self._body_timer.cancel()
                self._body_timer = None

        def _body_too_slow(self) -> None:
            self._body_timer = None
            if self.transport.is_closing():
                return
            if self.pipeline:  # an earlier request still runs: reading waits for it
                assert body_timeout_s is not None
                self._body_timer = self.loop.call_later(body_timeout_s, self._body_too_slow)
                return
            if self.cycle is not None and not self.cycle.response_started:
                # The app has not answered: it gets http.disconnect from its receive()
                # once the connection is lost, and whatever it sends then is dropped.
                self.cycle.keep_alive = False
                self.transport.write(_BODY_TOO_SLOW)
            self.transport.close()

        def connection_made(self, transport: asyncio.Transport) -> None:  # type: ignore[override]
            super().connection_made(transport)
            self._arm_header_timer()

        def connection_lost(self, exc: Exception | None) -> None:
            self._disarm_header_timer()
            self._disarm_body_timer()
            super().connection_lost(exc)

        def on_message_complete(self) -> None:
            self._disarm_body_timer()
            super().on_message_complete()

        def on_message_begin(self) -> None:
            super().on_message_begin()
            self._arm_header_timer()

        def on_headers_complete(self) -> None:
            self._disarm_header_timer()
            if body_timeout_s is not None:  # disarmed at once if there is no body
                self._disarm_body_timer()
                self._body_timer = self.loop.call_later(body_timeout_s, self._body_too_slow)
            super().on_headers_complete()
            # The app may drop a connection whose client stopped reading (api.streams):
            # a close would wait for the unread bytes to be sent, forever.
            self.scope.setdefault("extensions", {})[ABORT_EXTENSION] = {  # type: ignore[typeddict-item]
                "abort": self.transport.abort}

    return HeaderTimeoutProtocol


_ELSEWHERE = json.dumps({"detail": "the control port serves only POST /runs/{id}/cancel, "
                                   "GET /runs/{id} and GET /health; the rest of the API is "
                                   "on the main port"}).encode()
_STARTING = json.dumps({"detail": "the server is starting"}).encode()


class ControlOnly:
    """ASGI: pass ``app`` only the control requests (a run's cancel and state, and
    ``/health``); anything else is 404 here. The app's own rules (token, errors) apply."""

    def __init__(self, app: Any) -> None:
        self.app = app

    async def __call__(self, scope: Any, receive: Any, send: Any) -> None:
        if scope["type"] != "http":  # no lifespan here: the main server runs it
            return
        method, path = scope["method"], scope["path"]
        if not is_control(method, path):
            await _answer(send, 404, _ELSEWHERE)
            return
        if getattr(self.app.state, "manager", None) is None:
            await _answer(send, 503, _STARTING)
            return
        await self.app(scope, receive, send)


async def _answer(send: Any, code: int, body: bytes) -> None:
    await send({"type": "http.response.start", "status": code,
                "headers": [(b"content-type", b"application/json"),
                            (b"content-length", str(len(body)).encode())]})
    await send({"type": "http.response.body", "body": body})


def serve(app: Any, settings: Settings, host: str, port: int, log_level: str = "info",
          control_port: int | None = None) -> None:
    """Run ``app`` with uvicorn on ``host:port`` until it is stopped (Ctrl-C), and, with
    ``control_port``, its control listener on ``host:control_port`` (see the module)."""
    import uvicorn

    protocol = header_timeout_protocol(settings.header_timeout_s, settings.body_timeout_s)
    options: dict[str, Any] = {
        "host": host, "port": port, "log_level": log_level, "http": protocol,
        "timeout_keep_alive": 5,
        "timeout_graceful_shutdown": int(settings.shutdown_timeout_s) + 1}
    if control_port is None:
        uvicorn.run(app, **options)
        return
    main = uvicorn.Server(uvicorn.Config(app, **options))
    control = uvicorn.Server(uvicorn.Config(
        ControlOnly(app), host=host, port=control_port, log_level=log_level, http=protocol,
        lifespan="off", timeout_keep_alive=5, timeout_graceful_shutdown=1))
    thread = threading.Thread(target=control.run, name="taskrunner-control-listener",
                              daemon=True)
    thread.start()
    try:
        main.run()
    finally:
        control.should_exit = True
        thread.join(5.0)
