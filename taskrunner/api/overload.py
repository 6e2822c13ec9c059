"""A bound on the requests the server answers at once, control requests exempt.

Every request is parsed, routed and answered on the one event loop. When a hundred
clients send back to back, each request's turn on the loop (middleware, routing,
validation, the answer) comes after every other client's, and a cancel waits its turn
like the rest: about a millisecond per request in flight. :class:`RequestLimit` keeps
that queue short: at most ``limit`` ordinary requests are being answered at once, and
one more is answered at once with 503 and ``Retry-After`` (a few bytes, no routing, no
body read), so a flood costs the loop little per request and a cancel gets its turn.

Exempt, never counted nor refused:

* control: ``POST /runs/{id}/cancel``, ``GET /runs/{id}`` (the state of a run), and
  ``/health``;
* event streams (``GET /runs/{id}/events``): they stay open for a run's length and are
  bounded by their own rules (:mod:`taskrunner.api.streams`).

Heavy work (plans, previews, checks) is bounded besides, by kind
(:class:`~taskrunner.api.admission.Admission`).
"""

from __future__ import annotations

import json
import re
from collections.abc import Awaitable, Callable, MutableMapping
from typing import Any

from taskrunner.errors import ArgumentError

__all__ = ["RequestLimit", "is_control"]

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]

CANCEL_PATH = re.compile(r"^/runs/[^/]+/cancel$")
RUN_PATH = re.compile(r"^/runs/[^/]+$")
_EVENTS_PATH = re.compile(r"^/runs/[^/]+/events$")
RETRY_AFTER_S = 1


def is_control(method: str, path: str) -> bool:
    """A cancel, the state of one run, or the health check: what must always get through."""
    return ((method == "POST" and CANCEL_PATH.match(path) is not None) or
            (method == "GET" and (RUN_PATH.match(path) is not None or path == "/health")))


class RequestLimit:
    """ASGI middleware: at most ``limit`` ordinary requests answered at once (see module).

    Args:
        app: the application.
        limit: how many ordinary requests may be in progress at once (>= 1); one more is
            answered 503 with ``Retry-After`` without being read.
    """

    def __init__(self, app: Callable[[Scope, Receive, Send], Awaitable[None]],
                 limit: int) -> None:
        if limit < 1:
            raise ArgumentError(f"'limit' must be >= 1 (got {limit})")
        self.app = app
        self.limit = limit
        self.in_flight = 0
        self.refused = 0  # requests answered 503 here (for stats and tests)
        self._body = json.dumps({"detail": (
            f"the server is busy: {limit} requests are being answered (server setting "
            "'max_requests'); try again later. Cancels and run states are always "
            "answered.")}).encode()

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] != "http" or self._exempt(scope["method"], scope["path"]):
            await self.app(scope, receive, send)
            return
        if self.in_flight >= self.limit:
            self.refused += 1
            await send({"type": "http.response.start", "status": 503, "headers": [
                (b"content-type", b"application/json"),
                (b"content-length", str(len(self._body)).encode()),
                (b"retry-after", str(RETRY_AFTER_S).encode())]})
            await send({"type": "http.response.body", "body": self._body})
            return
        self.in_flight += 1
        try:
            await self.app(scope, receive, send)
        finally:
            self.in_flight -= 1

    @staticmethod
    def _exempt(method: str, path: str) -> bool:
        return is_control(method, path) or (method == "GET" and
                                            _EVENTS_PATH.match(path) is not None)
