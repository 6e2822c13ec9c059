"""schemathesis over the app's own OpenAPI schema: no input it generates makes a 5xx.

Every operation gets seeded, generated requests (bodies, paths, queries) with the bearer
token, against the app with its lifespan running (TestClient), planning in-process and a
mock backend so nothing waits on motion. The check is the one the issue asks for: no
server error, whatever the input.
"""

from __future__ import annotations

import pytest
from apitest import AUTH, make_settings
from fastapi.testclient import TestClient
from hypothesis import HealthCheck, settings

schemathesis = pytest.importorskip("schemathesis")

from taskrunner.api import create_app  # noqa: E402

_APP_SETTINGS = None


def _schema():
    import tempfile
    from pathlib import Path

    global _APP_SETTINGS
    _APP_SETTINGS = make_settings(Path(tempfile.mkdtemp(prefix="schemathesis-")) / "state")
    app = create_app(_APP_SETTINGS)
    return schemathesis.openapi.from_dict(app.openapi()), app


SCHEMA, APP = _schema()


@pytest.fixture(scope="module")
def client():
    # Server exceptions are raised here, with their traceback, instead of becoming a 500.
    with TestClient(APP, raise_server_exceptions=True) as c:
        yield c


@SCHEMA.parametrize()
@settings(max_examples=25, deadline=None, derandomize=True,
          suppress_health_check=list(HealthCheck))
def test_no_generated_request_gets_a_server_error(case, client):
    kwargs = case.as_transport_kwargs(base_url="")
    kwargs["headers"] = {**(kwargs.get("headers") or {}), **AUTH}
    kwargs.pop("base_url", None)
    method, url = kwargs.pop("method"), kwargs.pop("url")
    if not kwargs.get("cookies"):
        kwargs.pop("cookies", None)  # the API reads no cookies; per-request ones are deprecated
    if isinstance(kwargs.get("data"), (bytes, str)):
        kwargs["content"] = kwargs.pop("data")  # raw bodies: httpx's name for them
    response = client.request(method, url, **kwargs)
    assert response.status_code < 500, (
        f"{method} {url} -> {response.status_code}: {response.text[:500]}")
