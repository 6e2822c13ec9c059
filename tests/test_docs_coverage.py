"""The command line and the REST API, checked against what a reader sees: every
subcommand's ``--help`` is plain text (no reStructuredText markup), every option of every
subcommand is named in the docs (``docs/*.md`` or README.md), and every route of the API
app is in the endpoint table ``docs/rest-api.md`` is built with."""

from __future__ import annotations

import argparse
import contextlib
import importlib.util
import io
import re
from pathlib import Path

import pytest

from taskrunner.cli import _parser, main

ROOT = Path(__file__).resolve().parents[1]
DOCS = ROOT / "docs"
_RST = re.compile(r"``|:[a-z]+:`|`[^`\n]+`_")
_OPTION = re.compile(r"(?<![\w-])(--[a-z][a-z0-9-]*|-[a-zA-Z])\b")


def _commands() -> dict[str, argparse.ArgumentParser]:
    parser = _parser()
    (sub,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    return dict(sub.choices)


def _help(*argv: str) -> str:
    out = io.StringIO()
    with contextlib.redirect_stdout(out), pytest.raises(SystemExit) as done:
        main([*argv, "--help"])
    assert done.value.code == 0
    return out.getvalue()


def _options(command: str, parser: argparse.ArgumentParser) -> set[str]:
    """Every option string of ``command`` (long forms; a short one only if it is alone)."""
    if command == "collision-matrix":  # its own parser (taskrunner.scene.acm), run as is
        text = _help(command).split("options:", 1)[1]
        return {m for m in _OPTION.findall(text) if m.startswith("--")} - {"--help"}
    found = set()
    for action in parser._actions:
        if action.help == argparse.SUPPRESS or isinstance(action, argparse._HelpAction):
            continue
        longs = [o for o in action.option_strings if o.startswith("--")]
        found.update(longs or action.option_strings)
    return found


def _pages() -> dict[str, str]:
    pages = [p for p in sorted(DOCS.glob("*.md")) if p.name != "benchmarks.md"]
    return {p.name: p.read_text() for p in [*pages, ROOT / "README.md"]}


def test_every_commands_help_is_plain_text():
    commands = _commands()
    assert {"run", "check", "serve", "view", "collision-matrix"} <= set(commands)
    for argv in [(), *((c,) for c in commands)]:
        text = _help(*argv)
        assert "usage: run-task" in text, argv
        assert not _RST.search(text), (argv, _RST.search(text), text)


def test_every_commands_options_are_in_the_docs():
    """Each option is named on a page that names its command (``run-task serve``; for
    ``run``, ``run-task FILE`` too)."""
    pages = _pages()
    missing = []
    for command, parser in _commands().items():
        mention = re.compile(rf"run-task (?:{re.escape(command)}\b"
                             + (r"|[\w./<>-]+\.yaml|pick_place|FILE|TASK)" if command == "run"
                                else ")"))
        where = [text for text in pages.values() if mention.search(text)]
        assert where, f"no page names run-task {command}"
        for option in sorted(_options(command, parser)):
            named = re.compile(rf"(?<![\w-]){re.escape(option)}(?![\w-])")
            if not any(named.search(text) for text in where):
                missing.append(f"run-task {command} {option}")
    assert not missing, f"options not on a page that names their command: {missing}"


def test_every_backend_choice_of_run_is_documented():
    run = _commands()["run"]
    (backend,) = [a for a in run._actions if "--backend" in a.option_strings]
    assert backend.choices
    started = (DOCS / "getting-started.md").read_text()
    for kind in backend.choices:
        assert f"`{kind}`" in started, f"getting-started.md does not name backend {kind!r}"


def _endpoint_hook():
    spec = importlib.util.spec_from_file_location("api_endpoints", DOCS / "_hooks" /
                                                  "api_endpoints.py")
    assert spec and spec.loader
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def test_every_api_route_is_in_the_rest_api_page():
    from fastapi.routing import APIRoute
    from starlette.routing import Route

    from taskrunner.api import create_app

    page = (DOCS / "rest-api.md").read_text()
    hook = _endpoint_hook()
    assert hook.MARKER in page, "rest-api.md lost the endpoint table's marker"
    table = hook.endpoint_table()
    assert table.count("\n| `") >= 10
    viewer_page = (DOCS / "viewer.md").read_text()
    unlisted = []
    for route in create_app().routes:
        if not isinstance(route, Route):
            continue
        methods = sorted((route.methods or set()) - {"HEAD", "OPTIONS"})
        if isinstance(route, APIRoute) and route.include_in_schema:
            for method in methods:
                if f"| `{method}` | `{route.path}` |" not in table:
                    unlisted.append(f"{method} {route.path} (not in the generated table)")
        else:
            # the page, its data and the docs themselves: described in prose
            shown = re.sub(r"\{[^}]+\}", "{", route.path)
            prose = re.sub(r"\{[^}]+\}", "{", page + viewer_page)
            if f"`{shown}`" not in prose and f"`{shown}…`" not in prose:
                unlisted.append(f"{'/'.join(methods)} {route.path} (not in the prose)")
    assert not unlisted, unlisted


def test_the_run_body_table_has_every_field_and_backend_of_the_server():
    from typing import get_args

    from taskrunner.api.schemas import Backend, RunCreate

    page = (DOCS / "rest-api.md").read_text()
    body = page.split("The body of `POST /runs`:", 1)[1].split("\n\n", 2)[1]
    rows = {line.split("|")[1].strip().strip("`"): line for line in body.splitlines()
            if line.startswith("| `")}
    assert set(rows) == set(RunCreate.model_fields), sorted(rows)
    for kind in get_args(Backend):
        assert f"`{kind}`" in rows["backend"], kind


def test_every_picture_the_docs_show_is_committed():
    shown = {m for text in _pages().values()
             for m in re.findall(r"!\[[^\]]*\]\((images/[^)]+)\)", text)}
    assert {"images/first-task-runs.png", "images/first-task-replay.png",
            "images/first-task-preview.png"} <= shown
    for image in sorted(shown):
        path = DOCS / image
        assert path.is_file() and path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", image
