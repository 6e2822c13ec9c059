"""Serving the app with uvicorn, with a time limit on request headers.

uvicorn times out a connection only while it is idle between requests
(``timeout_keep_alive``); a client that opens a connection and trickles its request
headers a byte at a time holds the connection (and its slot) forever. The protocol
here, uvicorn's httptools protocol with one timer more, closes a connection whose
request headers are not complete within ``header_timeout_s`` of the connection's start
or of the request's first byte (with ``408 Request Timeout``).
"""

from __future__ import annotations

import asyncio
from typing import Any

from uvicorn.protocols.http.httptools_impl import HttpToolsProtocol

from taskrunner.api.settings import Settings

__all__ = ["header_timeout_protocol", "serve"]

_TIMEOUT_BODY = b"request headers not received in time\n"
_TIMEOUT_ANSWER = (b"HTTP/1.1 408 Request Timeout\r\ncontent-type: text/plain\r\n"
                   b"content-length: %d\r\nconnection: close\r\n\r\n%s"
                   % (len(_TIMEOUT_BODY), _TIMEOUT_BODY))


def header_timeout_protocol(header_timeout_s: float) -> type[asyncio.Protocol]:
    """uvicorn's httptools HTTP protocol, closing connections whose request headers take
    longer than ``header_timeout_s`` (s) to arrive."""
    if not header_timeout_s > 0:
        raise ValueError(f"'header_timeout_s' must be a positive number (got {header_timeout_s!r})")

    class HeaderTimeoutProtocol(HttpToolsProtocol):
        _header_timer: asyncio.TimerHandle | None = None

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
                self.transport.write(_TIMEOUT_ANSWER)
                self.transport.close()

        def connection_made(self, transport: asyncio.Transport) -> None:  # type: ignore[override]
            super().connection_made(transport)
            self._arm_header_timer()

        def connection_lost(self, exc: Exception | None) -> None:
            self._disarm_header_timer()
            super().connection_lost(exc)

        def on_message_begin(self) -> None:
            super().on_message_begin()
            self._arm_header_timer()

        def on_headers_complete(self) -> None:
            self._disarm_header_timer()
            super().on_headers_complete()

    return HeaderTimeoutProtocol


def serve(app: Any, settings: Settings, host: str, port: int, log_level: str = "info") -> None:
    """Run ``app`` with uvicorn on ``host:port`` until it is stopped (Ctrl-C)."""
    import uvicorn

    uvicorn.run(app, host=host, port=port, log_level=log_level,
                http=header_timeout_protocol(settings.header_timeout_s),
                timeout_keep_alive=5, timeout_graceful_shutdown=int(
                    settings.shutdown_timeout_s) + 1)
