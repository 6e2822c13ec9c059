"""The bound on requests answered at once (api.overload): ordinary requests past the
limit get 503 and Retry-After without being read; control requests and event streams
always reach the app."""

from __future__ import annotations

import asyncio
import json

import pytest

from taskrunner.api.overload import RequestLimit, is_control
from taskrunner.api.settings import Settings
from taskrunner.errors import ArgumentError


class _HeldApp:
    """An ASGI app whose answers wait until released; counts the requests it sees."""

    def __init__(self) -> None:
        self.release = asyncio.Event()
        self.seen: list[str] = []

    async def __call__(self, scope, receive, send) -> None:
        self.seen.append(f"{scope['method']} {scope['path']}")
        await self.release.wait()
        await send({"type": "http.response.start", "status": 200, "headers": []})
        await send({"type": "http.response.body", "body": b"ok"})


async def _request(app, method: str, path: str) -> tuple[int, dict[bytes, bytes], bytes]:
    sent: list[dict] = []
    body_read = False

    async def receive():
        nonlocal body_read
        body_read = True
        return {"type": "http.request", "body": b"", "more_body": False}

    async def send(message):
        sent.append(message)

    scope = {"type": "http", "method": method, "path": path, "headers": [],
             "query_string": b""}
    await app(scope, receive, send)
    start, body = sent[0], sent[1]
    return start["status"], dict(start["headers"]), body["body"]


def test_past_the_limit_ordinary_requests_get_503_control_requests_get_through():
    async def scenario():
        held = _HeldApp()
        limit = RequestLimit(held, limit=2)
        first = [asyncio.create_task(_request(limit, "GET", "/cells")),
                 asyncio.create_task(_request(limit, "POST", "/plan"))]
        await asyncio.sleep(0)
        assert limit.in_flight == 2
        status, headers, body = await _request(limit, "POST", "/tasks/check")
        assert status == 503
        assert headers[b"retry-after"] == b"1"
        assert "max_requests" in json.loads(body)["detail"]
        assert limit.refused == 1
        assert "POST /tasks/check" not in held.seen  # refused before the app
        # A cancel, a run's state, /health and an event stream are never refused.
        exempt = [asyncio.create_task(_request(limit, m, p)) for m, p in (
            ("POST", "/runs/abc/cancel"), ("GET", "/runs/abc"), ("GET", "/health"),
            ("GET", "/runs/abc/events"))]
        await asyncio.sleep(0)
        assert {"POST /runs/abc/cancel", "GET /runs/abc", "GET /health",
                "GET /runs/abc/events"} <= set(held.seen)
        assert limit.in_flight == 2  # not counted
        held.release.set()
        answers = await asyncio.gather(*first, *exempt)
        assert [a[0] for a in answers] == [200] * 6
        assert limit.in_flight == 0
        # Room again once the first ones are answered.
        assert (await _request(limit, "POST", "/tasks/check"))[0] == 200

    asyncio.run(scenario())


def test_a_failing_app_gives_its_slot_back():
    async def boom(scope, receive, send):
        raise RuntimeError("app failed")

    async def scenario():
        limit = RequestLimit(boom, limit=1)
        for _ in range(3):
            with pytest.raises(RuntimeError):
                await _request(limit, "GET", "/cells")
        assert limit.in_flight == 0 and limit.refused == 0

    asyncio.run(scenario())


@pytest.mark.parametrize(("method", "path", "control"), [
    ("POST", "/runs/r1/cancel", True), ("GET", "/runs/r1", True), ("GET", "/health", True),
    ("GET", "/runs/r1/cancel", False), ("POST", "/runs/r1", False), ("GET", "/runs", False),
    ("GET", "/runs/r1/events", False), ("POST", "/runs/a/b/cancel", False),
])
def test_control_requests(method, path, control):
    assert is_control(method, path) is control


def test_the_setting_is_checked():
    assert Settings(auth=False).max_requests == 16
    with pytest.raises(ArgumentError):
        RequestLimit(_HeldApp(), limit=0)
    for bad in (0, -1, True, "many", 2.5):
        with pytest.raises(ValueError, match="max_requests"):
            Settings(auth=False, max_requests=bad)
