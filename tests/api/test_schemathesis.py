"""schemathesis over the app's own OpenAPI schema: no input it generates makes a 5xx.

Every operation gets seeded, generated requests (bodies, paths, queries) with the bearer
token, against the app with its lifespan running (TestClient), planning in-process and
tasks checked in a thread, so nothing waits on a process start. The check is the one the
issue asks for: no server error, whatever the input. A second test pins that every
route of the app is in the schema (so every endpoint is exercised), and a third that the
generated requests carried the token and most got past it.
"""

from __future__ import annotations

from collections import Counter

import pytest
from apitest import AUTH, make_settings
from fastapi.routing import APIRoute
from fastapi.testclient import TestClient
from hypothesis import HealthCheck, given, settings

schemathesis = pytest.importorskip("schemathesis")

from taskrunner.api import create_app  # noqa: E402

EXAMPLES = 40  # per operation; about 0.5 s each on two cores
_SEEN: Counter[tuple[str, str, int]] = Counter()


def _schema():
    import tempfile
    from pathlib import Path

    app = create_app(make_settings(Path(tempfile.mkdtemp(prefix="schemathesis-")) / "state",
                                   check_timeout_s=5.0, plan_timeout_s=5.0))
    return schemathesis.openapi.from_dict(app.openapi()), app


SCHEMA, APP = _schema()


@pytest.fixture(scope="module")
def client():
    # Server exceptions are raised here, with their traceback, instead of becoming a 500.
    with TestClient(APP, raise_server_exceptions=True) as c:
        yield c


# One test per operation, parametrized here rather than by SCHEMA.parametrize(): under
# pytest-xdist (the README's test command) that gave one test that reached one operation.
OPERATIONS = [result.ok() for result in SCHEMA.get_all_operations()]


@pytest.mark.parametrize("operation", OPERATIONS, ids=[op.label for op in OPERATIONS])
def test_no_generated_request_gets_a_server_error(operation, client):
    @given(case=operation.as_strategy())
    @settings(max_examples=EXAMPLES, deadline=None, derandomize=True,
              suppress_health_check=list(HealthCheck))
    def generated(case):
        kwargs = case.as_transport_kwargs(base_url="")
        kwargs["headers"] = {**(kwargs.get("headers") or {}), **AUTH}
        kwargs.pop("base_url", None)
        method, url = kwargs.pop("method"), kwargs.pop("url")
        if not kwargs.get("cookies"):
            kwargs.pop("cookies", None)  # the API reads no cookies; per-request ones are deprecated
        if isinstance(kwargs.get("data"), (bytes, str)):
            kwargs["content"] = kwargs.pop("data")  # raw bodies: httpx's name for them
        response = client.request(method, url, **kwargs)
        _SEEN[(case.operation.method.upper(), case.operation.path, response.status_code)] += 1
        assert response.status_code < 500, (
            f"{method} {url} -> {response.status_code}: {response.text[:500]}")

    generated()


def test_every_route_of_the_app_is_in_the_schema():
    from taskrunner.api.routers import cells, health, plan, runs, tasks, viewer, viewer_goal

    routes = {(method, route.path.replace(":path}", "}"))  # OpenAPI has no path converters
              for module in (cells, health, plan, runs, tasks, viewer, viewer_goal)
              for route in module.router.routes if isinstance(route, APIRoute)
              and route.include_in_schema for method in route.methods}
    assert len(routes) == 24  # 13 + the web view's 11 data endpoints (its page is not an API)
    operations = {(op.method.upper(), op.path) for op in
                  (result.ok() for result in SCHEMA.get_all_operations())}
    assert routes == operations


def test_the_generated_requests_were_authenticated_and_reached_every_operation():
    if not _SEEN:
        pytest.skip("run with the generated tests (same module)")
    reached = {(method, path) for method, path, _ in _SEEN}
    assert len(reached) == len(list(SCHEMA.get_all_operations()))
    assert not any(code == 401 for _, _, code in _SEEN)  # the token went with every one
    print(f"schemathesis: {sum(_SEEN.values())} requests over {len(reached)} operations")
