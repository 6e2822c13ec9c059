"""MkDocs hook: the REST API page's endpoint table, generated from the app itself.

A page holding the line ``<!-- api-endpoints -->`` gets, in its place, one row per
operation of ``taskrunner.api.create_app()``'s OpenAPI schema (method, path, the first
paragraph of its description, request body, success status), so the page cannot drift
from the code. Nothing is served and no file is written: building the schema does not
start the app's lifespan.
"""

from __future__ import annotations

import re
from typing import Any

MARKER = "<!-- api-endpoints -->"
_METHODS = ("get", "post", "put", "patch", "delete")


def _first_paragraph(text: str | None) -> str:
    paragraph = (text or "").strip().split("\n\n")[0]
    paragraph = " ".join(paragraph.split())
    return re.sub(r"``([^`]+)``", r"`\1`", paragraph).replace("|", "\\|")


def _body(operation: dict[str, Any]) -> str:
    content = operation.get("requestBody", {}).get("content", {})
    schema = content.get("application/json", {}).get("schema", {})
    ref = schema.get("$ref", "")
    return f"`{ref.rsplit('/', 1)[-1]}`" if ref else ""


def _success(operation: dict[str, Any]) -> str:
    codes = sorted(c for c in operation.get("responses", {}) if c.startswith("2"))
    return ", ".join(codes)


def endpoint_table() -> str:
    """The Markdown table of every operation of the API."""
    from taskrunner.api import create_app

    schema = create_app().openapi()
    rows = ["| method | path | what it does | body | success |",
            "| --- | --- | --- | --- | --- |"]
    for path, operations in schema["paths"].items():
        for method in _METHODS:
            operation = operations.get(method)
            if operation is None:
                continue
            summary = _first_paragraph(operation.get("description")) or operation.get(
                "summary", "")
            rows.append(f"| `{method.upper()}` | `{path}` | {summary} | {_body(operation)} "
                        f"| {_success(operation)} |")
    return "\n".join(rows)


def on_page_markdown(markdown: str, page: Any, config: Any, files: Any) -> str:
    if MARKER not in markdown:
        return markdown
    return markdown.replace(MARKER, endpoint_table())
