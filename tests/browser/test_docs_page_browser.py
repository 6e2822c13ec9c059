"""The OpenAPI page ``/docs`` in a real browser with every request to anything but the
server refused (as offline): Swagger UI loads from the package and lists every endpoint
of the schema; nothing is fetched from elsewhere."""

from __future__ import annotations

from typing import Any
from urllib.parse import urlsplit

from .test_viewer_browser import shot


def test_the_swagger_page_renders_every_endpoint_with_the_network_closed(page, screenshots):
    refused: list[str] = []

    def local_only(route: Any) -> None:
        if urlsplit(route.request.url).hostname in ("127.0.0.1", "localhost"):
            route.continue_()
        else:
            refused.append(route.request.url)
            route.abort()

    page.context.route("**/*", local_only)
    page.goto(page.server.url + "/docs")
    page.wait_for_selector(".opblock-summary-path", timeout=20_000)
    page.wait_for_timeout(200)
    shown = set(page.eval_on_selector_all(
        ".opblock-summary-path", "els => els.map(e => e.dataset.path || e.textContent.trim())"))
    expected = set(page.server.api("/openapi.json")["paths"])
    assert expected and "/runs" in expected
    assert shown == expected, (sorted(expected - shown), sorted(shown - expected))
    assert page.title() == "taskrunner - API"
    shot(page, screenshots, "api_docs_page")
    assert refused == [], f"the page tried to reach other hosts: {refused}"
