"""The OpenAPI page ``/docs`` works offline: every URL it references is the server's own
and answers (Swagger UI's files come from the package, copied there by the view's build),
without a token; the schema it loads lists the endpoints."""

from __future__ import annotations

import re

from apitest import NO_TOKEN
from fastapi.testclient import TestClient

from taskrunner.viewer import STATIC_DIR

_URL = re.compile(r"""(?:href|src)=["']([^"']+)["']|url:\s*['"]([^'"]+)['"]""")


def test_the_docs_page_references_only_local_urls_that_answer_without_a_token(
        client: TestClient) -> None:
    page = client.get("/docs", headers=NO_TOKEN)
    assert page.status_code == 200
    urls = [a or b for a, b in _URL.findall(page.text)]
    assert "/viewer/static/swagger-ui-bundle.js" in urls
    assert "/viewer/static/swagger-ui.css" in urls
    assert "/openapi.json" in urls
    assert "http://" not in page.text and "https://" not in page.text, page.text
    for url in urls:
        assert url.startswith("/"), url
        answer = client.get(url, headers=NO_TOKEN)
        assert answer.status_code == 200, (url, answer.status_code)
        assert answer.content, url
    assert client.get("/viewer/static/swagger-ui-bundle.js").text.count("SwaggerUIBundle") > 0
    assert "/runs" in client.get("/openapi.json", headers=NO_TOKEN).json()["paths"]


def test_redoc_is_not_served_from_a_cdn(client: TestClient) -> None:
    assert client.get("/redoc", headers=NO_TOKEN).status_code == 404


def test_swagger_uis_licence_ships_beside_its_files() -> None:
    notices = (STATIC_DIR / "THIRD_PARTY_LICENSES.txt").read_text()
    assert "swagger-ui-dist 5." in notices and "licence Apache-2.0" in notices
    assert "SmartBear" in notices  # its NOTICE
    assert (STATIC_DIR / "swagger-ui-bundle.js.LICENSE.txt").is_file()
