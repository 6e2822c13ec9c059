"""GET /runs/{id} of live runs answered before routing (api.fastpath): the same answer as
the route, the same auth, one rebuild for many polls, everything else left to the app."""

from __future__ import annotations

import asyncio
import gc
import json
from pathlib import Path
from types import SimpleNamespace
from typing import Any

import pytest
from apitest import AUTH, NO_TOKEN, TOKEN, make_settings, wait_until_done
from fastapi.testclient import TestClient
from test_detail_cache import FakeClock, FakeRun, reference

from taskrunner.api import create_app
from taskrunner.api.admission import ControlExecutor
from taskrunner.api.detail import RunDetailCache
from taskrunner.api.fastpath import RunDetailFastPath


def fastpath_of(app: Any) -> RunDetailFastPath:
    """The app's fast-path middleware (the stack is built at the first request)."""
    layer = app.middleware_stack
    while not isinstance(layer, RunDetailFastPath):
        layer = layer.app
    return layer


def finished_run(client: TestClient) -> str:
    run_id = client.post("/runs", json={"task": "go_home", "backend": "mock"},
                         headers=AUTH).json()["run_id"]
    wait_until_done(client, run_id)
    return str(run_id)


def test_a_live_runs_poll_is_answered_before_routing_exactly_as_the_route_answers(
        client, monkeypatch):
    run_id = finished_run(client)
    fast = fastpath_of(client.app)
    served = fast.served
    quick = client.get(f"/runs/{run_id}")
    assert fast.served == served + 1

    async def decline(self: Any, scope: Any, run: str, send: Any) -> bool:
        return False

    monkeypatch.setattr(RunDetailFastPath, "_answer", decline)
    routed = client.get(f"/runs/{run_id}")
    assert fast.served == served + 1
    assert (quick.status_code, quick.content) == (routed.status_code, routed.content)
    assert quick.headers == routed.headers
    assert json.loads(quick.content)["status"] == "succeeded"


@pytest.mark.parametrize("path", ["/runs/no-such-run", "/runs/{id}/", "/runs/{id}/events",
                                  "/runs"])
def test_other_paths_and_unknown_runs_go_to_the_app(client, path):
    run_id = finished_run(client)
    fast = fastpath_of(client.app)
    served = fast.served
    answer = client.get(path.format(id=run_id), follow_redirects=False)
    assert fast.served == served
    if path == "/runs/no-such-run":
        assert answer.status_code == 404 and "no-such-run" in answer.json()["detail"]
    else:
        assert answer.status_code in (200, 307, 404)


def test_other_methods_go_to_the_app(client):
    run_id = finished_run(client)
    fast = fastpath_of(client.app)
    served = fast.served
    assert client.head(f"/runs/{run_id}").status_code == 405
    assert client.delete(f"/runs/{run_id}").status_code == 405
    assert fast.served == served


def test_a_recorded_run_not_live_on_this_server_is_read_by_the_route(tmp_path: Path):
    settings = make_settings(tmp_path / "state")
    with TestClient(headers=AUTH, app=create_app(settings)) as first:
        run_id = finished_run(first)
        expected = first.get(f"/runs/{run_id}").json()
    with TestClient(headers=AUTH, app=create_app(settings)) as second:
        answer = second.get(f"/runs/{run_id}")
        fast = fastpath_of(second.app)
        assert answer.status_code == 200 and fast.served == 0
        body = answer.json()
        assert body["status"] == expected["status"] == "succeeded"
        assert body["events"] == expected["events"]


@pytest.mark.parametrize(("header", "code"), [
    (None, 401), ("Bearer wrong-token-000", 401), (f"Basic {TOKEN}", 401),
    (f"Bearer  {TOKEN}", 200), (f"Bearer {TOKEN}", 200), (f"bearer {TOKEN}", 200)])
def test_when_reads_need_the_token_the_answer_is_the_apps(tmp_path: Path, header, code):
    settings = make_settings(tmp_path / "state", open_reads=False)
    with TestClient(headers=AUTH, app=create_app(settings)) as client:
        run_id = finished_run(client)
        fast = fastpath_of(client.app)
        served = fast.served
        answer = client.get(f"/runs/{run_id}",
                            headers=NO_TOKEN if header is None else {"Authorization": header})
        assert answer.status_code == code
        assert fast.served == served + (code == 200)
        if code == 401:
            assert answer.headers["www-authenticate"] == "Bearer"
            assert "token" in answer.json()["detail"]


def test_with_reads_open_no_token_is_needed(tmp_path: Path):
    settings = make_settings(tmp_path / "state", open_reads=True)
    with TestClient(headers=AUTH, app=create_app(settings)) as client:
        _no_token_needed(client)


def _no_token_needed(client: TestClient) -> None:
    run_id = finished_run(client)
    assert client.get(f"/runs/{run_id}", headers=NO_TOKEN).status_code == 200
    assert client.get(f"/runs/{run_id}", headers={"Authorization": "Bearer x"}).status_code \
        == 200


# ---------------------------------------------------------------- at the ASGI level
def _app_with(run: SimpleNamespace, token: str | None = None,
              open_reads: bool = True) -> SimpleNamespace:
    manager = SimpleNamespace(live=lambda run_id: run if run_id == run.run_id else None)
    settings = SimpleNamespace(open_reads=open_reads)
    return SimpleNamespace(state=SimpleNamespace(manager=manager, token=token,
                                                 settings=settings,
                                                 control=ControlExecutor()))


async def _get(fast: RunDetailFastPath, app: Any, path: str) -> tuple[int, bytes]:
    sent: list[dict[str, Any]] = []

    async def send(message: dict[str, Any]) -> None:
        sent.append(message)

    async def receive() -> dict[str, Any]:
        return {"type": "http.request", "body": b""}

    scope = {"type": "http", "method": "GET", "path": path, "headers": [], "app": app}
    await fast(scope, receive, send)
    body = b"".join(m.get("body", b"") for m in sent if m["type"] == "http.response.body")
    return sent[0]["status"], body


async def _not_found_app(scope: Any, receive: Any, send: Any) -> None:
    await send({"type": "http.response.start", "status": 404, "headers": []})
    await send({"type": "http.response.body", "body": b"from the app"})


def test_many_polls_of_a_changed_run_share_one_rebuild():
    fake = FakeRun()
    cache = RunDetailCache(fake, tree_period_s=0.05, clock=FakeClock())
    run = SimpleNamespace(run_id="r1", detail=cache)
    app = _app_with(run)
    fast = RunDetailFastPath(_not_found_app)

    async def burst() -> list[tuple[int, bytes]]:
        return await asyncio.gather(*(_get(fast, app, "/runs/r1") for _ in range(20)))

    answers = asyncio.run(burst())
    assert cache.builds == 1
    assert {a for a in answers} == {(200, reference(fake))}
    fake.events.emit("node_started", "go", node="go")
    answers = asyncio.run(burst())
    assert cache.builds == 2
    assert {a for a in answers} == {(200, reference(fake))}
    assert json.loads(answers[0][1])["events"][-1]["kind"] == "node_started"
    assert fast.served == 40
    assert asyncio.run(_get(fast, app, "/runs/other")) == (404, b"from the app")


def test_the_tree_is_refreshed_once_per_period_after_answering():
    fake = FakeRun()
    clock = FakeClock()
    cache = RunDetailCache(fake, tree_period_s=0.05, clock=clock)
    app = _app_with(SimpleNamespace(run_id="r1", detail=cache))
    fast = RunDetailFastPath(_not_found_app)

    async def polls(n: int) -> list[tuple[int, bytes]]:
        return [await _get(fast, app, "/runs/r1") for _ in range(n)]

    asyncio.run(polls(5))
    assert fake.trees_rendered == 1
    fake.tree_text = "-> root [*] (later)"
    clock.now += 0.06
    first, *rest = asyncio.run(polls(5))
    assert b"(later)" not in first[1]  # the poll answered first, then refreshed the tree
    assert fake.trees_rendered == 2
    assert all(b"(later)" in body for _, body in rest)


def test_the_token_is_checked_by_the_fast_path_too():
    fake = FakeRun()
    app = _app_with(SimpleNamespace(run_id="r1", detail=RunDetailCache(fake)),
                    token=TOKEN, open_reads=False)
    fast = RunDetailFastPath(_not_found_app)
    assert asyncio.run(_get(fast, app, "/runs/r1")) == (404, b"from the app")
    assert fast.served == 0


# ---------------------------------------------------------------- the heap
def test_the_server_freezes_its_long_lived_objects_and_thaws_them_at_shutdown(settings):
    with TestClient(headers=AUTH, app=create_app(settings)) as client:
        assert gc.get_freeze_count() > 10_000
        finished_run(client)  # loads a cell: frozen too
        assert gc.get_freeze_count() > 10_000
    assert gc.get_freeze_count() == 0
