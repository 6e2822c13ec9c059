"""``GET /runs/{id}`` of a live run, answered before FastAPI's routing.

Polling one run is what dashboards, PLCs and test rigs do most, and the body is
already serialised (:class:`~api.detail.RunDetailCache`). What a poll cost was then
almost all framework: route matching, solving the endpoint's dependencies, building a
``Response``; about 300 µs of the event loop's time per request, which set the latency
of 50 polling clients. :class:`RunDetailFastPath` answers a poll whose body is cached and
current straight from the cache (headers and bytes identical to the route's answer).
When the run has changed (an event, its status, the node running), one rebuild runs off
the event loop for all the polls that came meanwhile, instead of one per poll in the
thread pool. Every other request goes, unchanged, to the app:

* another method or path, or a trailing slash;
* a query string (a page of events, ``?since=`` / ``?limit=``: not the cached body);
* a run not live on this server (recorded runs are read from the database off the loop);
* a token the app must check and answer 401 for (missing or wrong).

A poll told to refresh the tree text (at most one per ``tree_period_s``) refreshes it
after answering, off the event loop, as the route does.
"""

from __future__ import annotations

import asyncio
from collections.abc import Awaitable, Callable, MutableMapping
from typing import Any

from taskrunner.api.auth import token_matches

__all__ = ["RunDetailFastPath"]

Scope = MutableMapping[str, Any]
Message = MutableMapping[str, Any]
Receive = Callable[[], Awaitable[Message]]
Send = Callable[[Message], Awaitable[None]]

_PREFIX = "/runs/"


class RunDetailFastPath:
    """ASGI middleware: serve cached ``GET /runs/{id}`` bodies of live runs (see module).

    It reads the run manager, the token and the settings from the app's state
    (``scope["app"].state``) at each request, so it works with whatever the lifespan set.
    """

    def __init__(self, app: Callable[[Scope, Receive, Send], Awaitable[None]]) -> None:
        self.app = app
        self.served = 0  # requests answered here (for tests and stats)
        self._building: dict[str, asyncio.Future[bytes]] = {}  # rebuilds in flight, by run

    async def __call__(self, scope: Scope, receive: Receive, send: Send) -> None:
        if scope["type"] == "http" and scope["method"] == "GET":
            path: str = scope["path"]
            if path.startswith(_PREFIX) and "/" not in path[len(_PREFIX):] \
                    and not scope.get("query_string"):
                run_id = path[len(_PREFIX):]
                if run_id and await self._answer(scope, run_id, send):
                    return
        await self.app(scope, receive, send)

    async def _answer(self, scope: Scope, run_id: str, send: Send) -> bool:
        """Answer from the cache and return True, or return False to let the app answer."""
        state = scope["app"].state
        manager = getattr(state, "manager", None)
        if manager is None or not _authorised(state, scope):
            return False
        live = manager.live(run_id)
        if live is None:
            return False
        body, refresh = live.detail.fresh()
        rounds = 0
        while body is None:  # it changed: rebuild (a build begun after this poll came will do)
            built = await self._rebuilt(live, scope)
            rounds += 1
            body, refresh = live.detail.fresh()
            if body is None and rounds == 2:
                body = built
        await send({"type": "http.response.start", "status": 200,
                    "headers": [(b"content-length", str(len(body)).encode()),
                                (b"content-type", b"application/json")]})
        await send({"type": "http.response.body", "body": body})
        self.served += 1
        if refresh:
            await _control(scope).run(live.detail.refresh)
        return True

    async def _rebuilt(self, live: Any, scope: Scope) -> bytes:
        """Rebuild the run's body off the event loop, once for all the polls waiting for
        it (each then checks it is current: a poll that came during a rebuild may need
        the next one)."""
        building = self._building.get(live.run_id)
        if building is None or building.get_loop() is not asyncio.get_running_loop():
            # On the control threads: a moving run's state is never queued behind other
            # requests' work in the shared pool.
            building = asyncio.ensure_future(_control(scope).run(live.detail.body))
            self._building[live.run_id] = building
            building.add_done_callback(lambda done: self._built(live.run_id, done))
        return await asyncio.shield(building)

    def _built(self, run_id: str, done: asyncio.Future[bytes]) -> None:
        if self._building.get(run_id) is done:
            del self._building[run_id]


def _control(scope: Scope) -> Any:
    """The app's :class:`~api.admission.ControlExecutor`."""
    return scope["app"].state.control


def _authorised(state: Any, scope: Scope) -> bool:
    """Whether a read may be answered without the app's own check: the server runs open,
    reads need no token, or the request carries the right one. False means: let the app
    check it (and answer 401)."""
    token: str | None = state.token
    if token is None or state.settings.open_reads:
        return True
    for name, value in scope["headers"]:
        if name == b"authorization":
            scheme, _, given = value.partition(b" ")
            return scheme.lower() == b"bearer" and token_matches(given.strip(), token)
    return False
